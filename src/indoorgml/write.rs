//! [`Document`] → IndoorGML 1.0.3 (or 1.1) XML (core + navigation modules), in the
//! element order the OGC schemas require. Deterministic: the same document
//! always gives the same bytes.

use std::fmt::Write as _;
use std::io::{self, Write};

use super::IndoorGmlVersion;
use super::document::*;
use super::dom::{NS_CORE, NS_GML, NS_NAVI, NS_XLINK, NS_XSI};
use super::xml_out::XmlOut;

/// Writes `doc` as IndoorGML `version` (the same elements; 1.1 names the
/// 1.1 schemas, see [`IndoorGmlVersion`]).
pub fn write_document_as<W: Write>(
    doc: &Document,
    version: IndoorGmlVersion,
    out: W,
) -> io::Result<W> {
    let mut w = DocWriter {
        x: XmlOut::new(out),
        srs: doc.srs_name.as_deref(),
        buf: String::new(),
    };
    w.x.declaration()?;
    let mut attrs = vec![
        ("xmlns:core", NS_CORE),
        ("xmlns:navi", NS_NAVI),
        ("xmlns:gml", NS_GML),
        ("xmlns:xlink", NS_XLINK),
        ("xmlns:xsi", NS_XSI),
        ("xsi:schemaLocation", version.schema_location()),
    ];
    if !doc.info.id.is_empty() {
        attrs.push(("gml:id", &doc.info.id));
    }
    w.x.start("core:IndoorFeatures", &attrs)?;
    w.info(&doc.info)?;
    if let Some(p) = &doc.primal {
        w.x.start("core:primalSpaceFeatures", &[])?;
        w.primal(p)?;
        w.x.end("core:primalSpaceFeatures")?;
    }
    if let Some(g) = &doc.graph {
        w.x.start("core:multiLayeredGraph", &[])?;
        w.graph(g)?;
        w.x.end("core:multiLayeredGraph")?;
    }
    w.x.end("core:IndoorFeatures")?;
    w.x.finish()
}

struct DocWriter<'a, W: Write> {
    x: XmlOut<W>,
    srs: Option<&'a str>,
    buf: String,
}

impl<W: Write> DocWriter<'_, W> {
    fn info(&mut self, info: &FeatureInfo) -> io::Result<()> {
        if let Some(d) = &info.description {
            self.x.leaf("gml:description", &[], d)?;
        }
        for n in &info.names {
            self.x.leaf("gml:name", &[], n)?;
        }
        Ok(())
    }

    fn primal(&mut self, p: &PrimalSpace) -> io::Result<()> {
        self.x.start_id("core:PrimalSpaceFeatures", &p.info.id)?;
        self.info(&p.info)?;
        for c in &p.cells {
            self.x.start("core:cellSpaceMember", &[])?;
            self.cell(c)?;
            self.x.end("core:cellSpaceMember")?;
        }
        for b in &p.boundaries {
            self.x.start("core:cellSpaceBoundaryMember", &[])?;
            self.boundary(b)?;
            self.x.end("core:cellSpaceBoundaryMember")?;
        }
        self.x.end("core:PrimalSpaceFeatures")
    }

    fn cell(&mut self, c: &Cell) -> io::Result<()> {
        let name = format!(
            "{}:{}",
            if c.class.is_navi() { "navi" } else { "core" },
            c.class.element_name()
        );
        self.x.start_id(&name, &c.info.id)?;
        self.info(&c.info)?;
        if let Some(g) = &c.geometry {
            self.x.start("core:cellSpaceGeometry", &[])?;
            match g {
                CellGeometry::Surface(p) => {
                    self.x.start("core:Geometry2D", &[])?;
                    self.polygon(p, true)?;
                    self.x.end("core:Geometry2D")?;
                }
                CellGeometry::Solid(s) => {
                    self.x.start("core:Geometry3D", &[])?;
                    self.solid(s)?;
                    self.x.end("core:Geometry3D")?;
                }
            }
            self.x.end("core:cellSpaceGeometry")?;
        }
        if let Some(d) = &c.duality {
            self.x.href("core:duality", d)?;
        }
        self.external(&c.external)?;
        for b in &c.bounded_by {
            self.x.href("core:partialboundedBy", b)?;
        }
        if c.class.is_navi() {
            self.x.leaf("navi:class", &[], &c.navi.class)?;
            self.x.leaf("navi:function", &[], &c.navi.function)?;
            self.x.leaf("navi:usage", &[], &c.navi.usage)?;
        }
        self.x.end(&name)
    }

    fn external(&mut self, refs: &[ExternalReference]) -> io::Result<()> {
        for r in refs {
            self.x.start("core:externalReference", &[])?;
            if let Some(s) = &r.information_system {
                self.x.leaf("core:informationSystem", &[], s)?;
            }
            self.x.start("core:externalObject", &[])?;
            match (&r.uri, &r.name) {
                (Some(uri), _) => self.x.leaf("core:uri", &[], uri)?,
                (None, Some(name)) => self.x.leaf("core:name", &[], name)?,
                (None, None) => self.x.leaf("core:name", &[], "")?,
            }
            self.x.end("core:externalObject")?;
            self.x.end("core:externalReference")?;
        }
        Ok(())
    }

    fn boundary(&mut self, b: &Boundary) -> io::Result<()> {
        let name = format!(
            "{}:{}",
            if b.class.is_navi() { "navi" } else { "core" },
            b.class.element_name()
        );
        self.x.start_id(&name, &b.info.id)?;
        self.info(&b.info)?;
        if let Some(d) = &b.duality {
            self.x.href("core:duality", d)?;
        }
        if let Some(g) = &b.geometry {
            self.x.start("core:cellSpaceBoundaryGeometry", &[])?;
            match g {
                BoundaryGeometry::Curve(l) => {
                    self.x.start("core:geometry2D", &[])?;
                    self.line_string(l)?;
                    self.x.end("core:geometry2D")?;
                }
                BoundaryGeometry::Surface(p) => {
                    self.x.start("core:geometry3D", &[])?;
                    self.polygon(p, true)?;
                    self.x.end("core:geometry3D")?;
                }
            }
            self.x.end("core:cellSpaceBoundaryGeometry")?;
        }
        self.external(&b.external)?;
        self.x.end(&name)
    }

    fn graph(&mut self, g: &LayeredGraph) -> io::Result<()> {
        self.x.start_id("core:MultiLayeredGraph", &g.info.id)?;
        self.info(&g.info)?;
        for group in &g.layer_groups {
            self.x.start_id("core:spaceLayers", &group.id)?;
            for layer in &group.layers {
                self.x.start("core:spaceLayerMember", &[])?;
                self.layer(layer)?;
                self.x.end("core:spaceLayerMember")?;
            }
            self.x.end("core:spaceLayers")?;
        }
        for group in &g.inter_edges {
            self.x.start_id("core:interEdges", &group.id)?;
            for c in &group.connections {
                self.x.start("core:interLayerConnectionMember", &[])?;
                self.inter_layer_connection(c)?;
                self.x.end("core:interLayerConnectionMember")?;
            }
            self.x.end("core:interEdges")?;
        }
        self.x.end("core:MultiLayeredGraph")
    }

    fn layer(&mut self, l: &Layer) -> io::Result<()> {
        self.x.start_id("core:SpaceLayer", &l.info.id)?;
        self.info(&l.info)?;
        if let Some(c) = &l.class {
            self.x.leaf("core:class", &[], c)?;
        }
        self.x.start_id("core:nodes", &l.nodes_id)?;
        for s in &l.states {
            self.x.start("core:stateMember", &[])?;
            self.state(s)?;
            self.x.end("core:stateMember")?;
        }
        self.x.end("core:nodes")?;
        if !l.transitions.is_empty() || !l.edges_id.is_empty() {
            self.x.start_id("core:edges", &l.edges_id)?;
            for t in &l.transitions {
                self.x.start("core:transitionMember", &[])?;
                self.transition(t)?;
                self.x.end("core:transitionMember")?;
            }
            self.x.end("core:edges")?;
        }
        self.x.end("core:SpaceLayer")
    }

    fn state(&mut self, s: &State) -> io::Result<()> {
        self.x.start_id("core:State", &s.info.id)?;
        self.info(&s.info)?;
        if let Some(d) = &s.duality {
            self.x.href("core:duality", d)?;
        }
        for c in &s.connects {
            self.x.href("core:connects", c)?;
        }
        if let Some(p) = &s.point {
            self.x.start("core:geometry", &[])?;
            self.geometry_start("gml:Point", p.id.as_deref(), true)?;
            self.positions("gml:pos", &p.coords)?;
            self.x.end("gml:Point")?;
            self.x.end("core:geometry")?;
        }
        self.x.end("core:State")
    }

    fn transition(&mut self, t: &Transition) -> io::Result<()> {
        self.x.start_id("core:Transition", &t.info.id)?;
        self.info(&t.info)?;
        if let Some(w) = t.weight {
            self.buf.clear();
            let _ = write!(self.buf, "{w}");
            let text = std::mem::take(&mut self.buf);
            self.x.leaf("core:weight", &[], &text)?;
            self.buf = text;
        }
        for c in &t.connects {
            self.x.href("core:connects", c)?;
        }
        if let Some(d) = &t.duality {
            self.x.href("core:duality", d)?;
        }
        if let Some(l) = &t.geometry {
            self.x.start("core:geometry", &[])?;
            self.line_string(l)?;
            self.x.end("core:geometry")?;
        }
        self.x.end("core:Transition")
    }

    fn inter_layer_connection(&mut self, c: &InterLayerConnection) -> io::Result<()> {
        self.x.start_id("core:InterLayerConnection", &c.info.id)?;
        self.info(&c.info)?;
        if let Some(t) = &c.topo {
            self.x.leaf("core:typeOfTopoExpression", &[], t)?;
        }
        if let Some(t) = &c.comment {
            self.x.leaf("core:comment", &[], t)?;
        }
        for s in &c.inter_connects {
            self.x.href("core:interConnects", s)?;
        }
        for l in &c.connected_layers {
            self.x.href("core:ConnectedLayers", l)?;
        }
        self.x.end("core:InterLayerConnection")
    }

    /// `top`: the geometry is the top of a property, so it carries srsName.
    fn geometry_start(&mut self, name: &str, id: Option<&str>, top: bool) -> io::Result<()> {
        let mut attrs: Vec<(&str, &str)> = Vec::with_capacity(2);
        if let Some(id) = id {
            attrs.push(("gml:id", id));
        }
        if let (true, Some(srs)) = (top, self.srs) {
            attrs.push(("srsName", srs));
        }
        self.x.start(name, &attrs)
    }

    fn polygon(&mut self, p: &Polygon, top: bool) -> io::Result<()> {
        self.geometry_start("gml:Polygon", p.id.as_deref(), top)?;
        self.ring("gml:exterior", &p.exterior)?;
        for r in &p.interiors {
            self.ring("gml:interior", r)?;
        }
        self.x.end("gml:Polygon")
    }

    fn ring(&mut self, name: &str, coords: &Coords) -> io::Result<()> {
        self.x.start(name, &[])?;
        self.x.start("gml:LinearRing", &[])?;
        self.positions("gml:posList", coords)?;
        self.x.end("gml:LinearRing")?;
        self.x.end(name)
    }

    fn solid(&mut self, s: &Solid) -> io::Result<()> {
        self.geometry_start("gml:Solid", s.id.as_deref(), true)?;
        self.shell("gml:exterior", &s.exterior)?;
        for shell in &s.interiors {
            self.shell("gml:interior", shell)?;
        }
        self.x.end("gml:Solid")
    }

    fn shell(&mut self, name: &str, polygons: &[Polygon]) -> io::Result<()> {
        self.x.start(name, &[])?;
        self.x.start("gml:Shell", &[])?;
        for p in polygons {
            self.x.start("gml:surfaceMember", &[])?;
            self.polygon(p, false)?;
            self.x.end("gml:surfaceMember")?;
        }
        self.x.end("gml:Shell")?;
        self.x.end(name)
    }

    fn line_string(&mut self, l: &LineString) -> io::Result<()> {
        self.geometry_start("gml:LineString", l.id.as_deref(), true)?;
        self.positions("gml:posList", &l.coords)?;
        self.x.end("gml:LineString")
    }

    fn positions(&mut self, name: &str, coords: &Coords) -> io::Result<()> {
        self.buf.clear();
        for (i, v) in coords.values.iter().enumerate() {
            if i > 0 {
                self.buf.push(' ');
            }
            let _ = write!(self.buf, "{v}");
        }
        let dim = if coords.dim == 3 { "3" } else { "2" };
        let text = std::mem::take(&mut self.buf);
        let result = self.x.leaf(name, &[("srsDimension", dim)], &text);
        self.buf = text;
        result
    }
}
