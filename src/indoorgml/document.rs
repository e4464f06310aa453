//! The IndoorGML document as data: what nrgdb reads from and writes to
//! IndoorGML 1.0.x, faithful enough that import → export → import keeps
//! ids, counts, duality, `connects`, names and coordinates.
//!
//! References (`xlink:href`) are stored as the target's `gml:id`, without
//! the leading `#`. Line numbers are 1-based positions in the source file
//! (0 for elements that were not read from a file).

use std::collections::HashMap;

/// An `IndoorFeatures` document.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Document {
    /// `gml:id`, names and description of the root.
    pub info: FeatureInfo,
    /// The `srsName` of the geometries, when the source declared one.
    pub srs_name: Option<String>,
    /// `PrimalSpaceFeatures`: the cells and their boundaries.
    pub primal: Option<PrimalSpace>,
    /// `MultiLayeredGraph`: the dual graph(s).
    pub graph: Option<LayeredGraph>,
    /// The version the root's `xsi:schemaLocation` names (1.0.3 when it
    /// names none); the version a copy is written in unless asked.
    pub version: super::IndoorGmlVersion,
    /// What the reader accepted although the schema does not (a misspelt
    /// element that real files share, as browsers accept sloppy HTML),
    /// each with its line; empty for a schema-valid file. Never written.
    pub warnings: Vec<String>,
}

/// The common properties of every GML feature nrgdb keeps.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct FeatureInfo {
    /// `gml:id`.
    pub id: String,
    /// `gml:name`s, trimmed.
    pub names: Vec<String>,
    /// `gml:description`, trimmed.
    pub description: Option<String>,
    /// Line of the element in the source file.
    pub line: usize,
}

impl FeatureInfo {
    /// A feature with this id and nothing else.
    pub fn new(id: impl Into<String>) -> FeatureInfo {
        FeatureInfo {
            id: id.into(),
            ..FeatureInfo::default()
        }
    }
}

/// `PrimalSpaceFeatures`.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PrimalSpace {
    /// Id, names, description.
    pub info: FeatureInfo,
    /// `cellSpaceMember`s, in document order.
    pub cells: Vec<Cell>,
    /// `cellSpaceBoundaryMember`s, in document order.
    pub boundaries: Vec<Boundary>,
}

/// The element type of a cell.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum CellClass {
    /// `core:CellSpace`.
    CellSpace,
    /// `navi:NavigableSpace`.
    NavigableSpace,
    /// `navi:GeneralSpace` (rooms).
    GeneralSpace,
    /// `navi:TransferSpace`.
    TransferSpace,
    /// `navi:TransitionSpace` (corridors).
    TransitionSpace,
    /// `navi:ConnectionSpace` (doors, thick-door model).
    ConnectionSpace,
    /// `navi:AnchorSpace`.
    AnchorSpace,
    /// An element from an extension schema, by its qualified source name;
    /// written back as `core:CellSpace`.
    Extension(String),
}

impl CellClass {
    /// The local element name written for this class.
    pub fn element_name(&self) -> &'static str {
        match self {
            CellClass::CellSpace | CellClass::Extension(_) => "CellSpace",
            CellClass::NavigableSpace => "NavigableSpace",
            CellClass::GeneralSpace => "GeneralSpace",
            CellClass::TransferSpace => "TransferSpace",
            CellClass::TransitionSpace => "TransitionSpace",
            CellClass::ConnectionSpace => "ConnectionSpace",
            CellClass::AnchorSpace => "AnchorSpace",
        }
    }

    /// Whether the element is in the navigation module's namespace.
    pub fn is_navi(&self) -> bool {
        !matches!(self, CellClass::CellSpace | CellClass::Extension(_))
    }

    /// The class of a navigation-module element, by local name.
    pub fn from_navi_name(local: &str) -> Option<CellClass> {
        Some(match local {
            "NavigableSpace" => CellClass::NavigableSpace,
            "GeneralSpace" => CellClass::GeneralSpace,
            "TransferSpace" => CellClass::TransferSpace,
            "TransitionSpace" => CellClass::TransitionSpace,
            "ConnectionSpace" => CellClass::ConnectionSpace,
            "AnchorSpace" => CellClass::AnchorSpace,
            _ => return None,
        })
    }
}

/// The `navi:class`, `navi:function` and `navi:usage` codes of a navigable space.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct NaviCodes {
    /// `navi:class`.
    pub class: String,
    /// `navi:function`.
    pub function: String,
    /// `navi:usage`.
    pub usage: String,
}

/// A `CellSpace` or one of its navigation-module subtypes.
#[derive(Debug, Clone, PartialEq)]
pub struct Cell {
    /// Id, names, description, line.
    pub info: FeatureInfo,
    /// Element type.
    pub class: CellClass,
    /// Navigation codes (written for navigation-module classes).
    pub navi: NaviCodes,
    /// `cellSpaceGeometry` (2D surface or 3D solid).
    pub geometry: Option<CellGeometry>,
    /// `duality` → a State.
    pub duality: Option<String>,
    /// `externalReference`s.
    pub external: Vec<ExternalReference>,
    /// `partialboundedBy` → CellSpaceBoundaries.
    pub bounded_by: Vec<String>,
}

/// A cell's geometry.
#[derive(Debug, Clone, PartialEq)]
pub enum CellGeometry {
    /// `Geometry2D`: a surface (polygon).
    Surface(Polygon),
    /// `Geometry3D`: a solid.
    Solid(Solid),
}

/// An `externalReference` of a cell or boundary.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ExternalReference {
    /// `informationSystem` URI.
    pub information_system: Option<String>,
    /// `externalObject/name`.
    pub name: Option<String>,
    /// `externalObject/uri`.
    pub uri: Option<String>,
}

/// The element type of a cell boundary.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum BoundaryClass {
    /// `core:CellSpaceBoundary`.
    CellSpaceBoundary,
    /// `navi:NavigableBoundary`.
    NavigableBoundary,
    /// `navi:TransferBoundary`.
    TransferBoundary,
    /// `navi:ConnectionBoundary` (thin-door model).
    ConnectionBoundary,
    /// `navi:AnchorBoundary`.
    AnchorBoundary,
    /// An extension element, by qualified source name; written back as
    /// `core:CellSpaceBoundary`.
    Extension(String),
}

impl BoundaryClass {
    /// The local element name written for this class.
    pub fn element_name(&self) -> &'static str {
        match self {
            BoundaryClass::CellSpaceBoundary | BoundaryClass::Extension(_) => "CellSpaceBoundary",
            BoundaryClass::NavigableBoundary => "NavigableBoundary",
            BoundaryClass::TransferBoundary => "TransferBoundary",
            BoundaryClass::ConnectionBoundary => "ConnectionBoundary",
            BoundaryClass::AnchorBoundary => "AnchorBoundary",
        }
    }

    /// Whether the element is in the navigation module's namespace.
    pub fn is_navi(&self) -> bool {
        !matches!(
            self,
            BoundaryClass::CellSpaceBoundary | BoundaryClass::Extension(_)
        )
    }

    /// The class of a navigation-module element, by local name.
    pub fn from_navi_name(local: &str) -> Option<BoundaryClass> {
        Some(match local {
            "NavigableBoundary" => BoundaryClass::NavigableBoundary,
            "TransferBoundary" => BoundaryClass::TransferBoundary,
            "ConnectionBoundary" => BoundaryClass::ConnectionBoundary,
            "AnchorBoundary" => BoundaryClass::AnchorBoundary,
            _ => return None,
        })
    }
}

/// A `CellSpaceBoundary` or one of its subtypes.
#[derive(Debug, Clone, PartialEq)]
pub struct Boundary {
    /// Id, names, description, line.
    pub info: FeatureInfo,
    /// Element type.
    pub class: BoundaryClass,
    /// `duality` → a Transition.
    pub duality: Option<String>,
    /// `cellSpaceBoundaryGeometry`.
    pub geometry: Option<BoundaryGeometry>,
    /// `externalReference`s.
    pub external: Vec<ExternalReference>,
}

/// A boundary's geometry.
#[derive(Debug, Clone, PartialEq)]
pub enum BoundaryGeometry {
    /// `geometry2D`: a curve.
    Curve(LineString),
    /// `geometry3D`: a surface.
    Surface(Polygon),
}

/// `MultiLayeredGraph`.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LayeredGraph {
    /// Id, names, description.
    pub info: FeatureInfo,
    /// `spaceLayers` groups, each with its layers.
    pub layer_groups: Vec<LayerGroup>,
    /// `interEdges` groups.
    pub inter_edges: Vec<InterEdges>,
}

impl LayeredGraph {
    /// Every layer of every group.
    pub fn layers(&self) -> impl Iterator<Item = &Layer> {
        self.layer_groups.iter().flat_map(|g| g.layers.iter())
    }
}

/// A `spaceLayers` element.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LayerGroup {
    /// `gml:id` of the group.
    pub id: String,
    /// Its `SpaceLayer`s.
    pub layers: Vec<Layer>,
}

/// A `SpaceLayer` with its States and Transitions.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Layer {
    /// Id, names, description.
    pub info: FeatureInfo,
    /// `class` (TOPOGRAPHIC, SENSOR, …), when given.
    pub class: Option<String>,
    /// `gml:id` of the `nodes` element.
    pub nodes_id: String,
    /// `gml:id` of the `edges` element.
    pub edges_id: String,
    /// `stateMember`s.
    pub states: Vec<State>,
    /// `transitionMember`s.
    pub transitions: Vec<Transition>,
}

/// A `State`: a node of the dual graph.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct State {
    /// Id, names, description, line.
    pub info: FeatureInfo,
    /// `duality` → a cell.
    pub duality: Option<String>,
    /// `connects` → Transitions.
    pub connects: Vec<String>,
    /// `geometry`: the node's point.
    pub point: Option<GmlPoint>,
}

/// A `Transition`: an edge of the dual graph.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Transition {
    /// Id, names, description, line.
    pub info: FeatureInfo,
    /// `weight`.
    pub weight: Option<f64>,
    /// `connects` → the two States.
    pub connects: Vec<String>,
    /// `duality` → a boundary.
    pub duality: Option<String>,
    /// `geometry`: the edge's curve.
    pub geometry: Option<LineString>,
}

/// An `interEdges` element.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct InterEdges {
    /// `gml:id` of the group.
    pub id: String,
    /// Its `InterLayerConnection`s.
    pub connections: Vec<InterLayerConnection>,
}

/// An `InterLayerConnection` between States of two layers.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct InterLayerConnection {
    /// Id, names, description, line.
    pub info: FeatureInfo,
    /// `typeOfTopoExpression` (CONTAINS, OVERLAPS, EQUALS, …).
    pub topo: Option<String>,
    /// `comment`.
    pub comment: Option<String>,
    /// `interConnects` → two States.
    pub inter_connects: Vec<String>,
    /// `ConnectedLayers` → two SpaceLayers (derived from the States when
    /// the source, e.g. IndoorGML 1.0.1, has none).
    pub connected_layers: Vec<String>,
}

/// Coordinates: `dim` values a position, flat.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Coords {
    /// 2 or 3.
    pub dim: usize,
    /// `dim` × number of positions values.
    pub values: Vec<f64>,
}

impl Coords {
    /// Number of positions.
    pub fn len(&self) -> usize {
        self.values.len().checked_div(self.dim).unwrap_or(0)
    }

    /// Whether there are no positions.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The positions' x and y.
    pub fn xy(&self) -> impl Iterator<Item = [f64; 2]> + '_ {
        self.values
            .chunks_exact(self.dim.max(1))
            .map(|p| [p[0], p.get(1).copied().unwrap_or(0.0)])
    }

    /// The positions' z (0 in 2D).
    pub fn z(&self) -> impl Iterator<Item = f64> + '_ {
        self.values
            .chunks_exact(self.dim.max(1))
            .map(|p| p.get(2).copied().unwrap_or(0.0))
    }
}

/// A `gml:Polygon`.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Polygon {
    /// `gml:id` (optional in the OGC schema set).
    pub id: Option<String>,
    /// Exterior ring, closed (last position = first) as in GML.
    pub exterior: Coords,
    /// Interior rings, closed.
    pub interiors: Vec<Coords>,
}

/// A `gml:Solid` given by its shells' surface members.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Solid {
    /// `gml:id`.
    pub id: Option<String>,
    /// Polygons of the exterior shell.
    pub exterior: Vec<Polygon>,
    /// Polygons of each interior shell.
    pub interiors: Vec<Vec<Polygon>>,
}

/// A `gml:LineString`.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LineString {
    /// `gml:id`.
    pub id: Option<String>,
    /// Its positions.
    pub coords: Coords,
}

/// A `gml:Point`.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct GmlPoint {
    /// `gml:id`.
    pub id: Option<String>,
    /// One position.
    pub coords: Coords,
}

/// What a `gml:id` names, found by [`Document::index`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Target {
    /// A cell, by index in `primal.cells`.
    Cell(usize),
    /// A boundary, by index in `primal.boundaries`.
    Boundary(usize),
    /// A state: (layer number across groups, index in the layer).
    State(usize, usize),
    /// A transition: (layer number, index in the layer).
    Transition(usize, usize),
    /// A `SpaceLayer`, by layer number.
    Layer(usize),
}

impl Document {
    /// Every layer of the document, in order.
    pub fn layers(&self) -> Vec<&Layer> {
        self.graph.iter().flat_map(|g| g.layers()).collect()
    }

    /// The cells (empty without primal space).
    pub fn cells(&self) -> &[Cell] {
        self.primal.as_ref().map_or(&[], |p| &p.cells)
    }

    /// The boundaries (empty without primal space).
    pub fn boundaries(&self) -> &[Boundary] {
        self.primal.as_ref().map_or(&[], |p| &p.boundaries)
    }

    /// Maps every feature `gml:id` to what it names. When an id is used
    /// twice the first use wins (the checker reports the duplicate).
    pub fn index(&self) -> HashMap<&str, Target> {
        let mut map = HashMap::new();
        if let Some(p) = &self.primal {
            for (i, c) in p.cells.iter().enumerate() {
                map.entry(c.info.id.as_str()).or_insert(Target::Cell(i));
            }
            for (i, b) in p.boundaries.iter().enumerate() {
                map.entry(b.info.id.as_str()).or_insert(Target::Boundary(i));
            }
        }
        for (l, layer) in self.layers().into_iter().enumerate() {
            map.entry(layer.info.id.as_str())
                .or_insert(Target::Layer(l));
            for (i, s) in layer.states.iter().enumerate() {
                map.entry(s.info.id.as_str()).or_insert(Target::State(l, i));
            }
            for (i, t) in layer.transitions.iter().enumerate() {
                map.entry(t.info.id.as_str())
                    .or_insert(Target::Transition(l, i));
            }
        }
        map
    }
}
