//! IndoorGML 1.0.1 / 1.0.2 / 1.0.3 / 1.1 → [`Document`], namespace-aware (any
//! prefix), tolerant of what real files do (hrefs with or without `#`,
//! 1.0.1's geometry without `cellSpaceGeometry`, extension elements) and
//! strict about structure: an element that does not belong is refused with
//! its line.

use super::document::*;
use super::dom::{Element, Ns};
use super::gml_read::{GeometryReader, first_gml_child, parse_number};
use super::{IndoorGmlError, IndoorGmlVersion};

/// Reads a document from its text.
pub fn read_document(text: &str) -> Result<Document, IndoorGmlError> {
    let root = super::dom::parse(text)?;
    document(&root)
}

/// Reads a document from a parsed element tree.
pub fn document(root: &Element) -> Result<Document, IndoorGmlError> {
    check_root(root)?;
    let geo = GeometryReader::for_document(root);
    let mut doc = Document {
        info: info(root),
        version: IndoorGmlVersion::of_schema_location(
            root.attr(&Ns::Xsi, "schemaLocation").unwrap_or_default(),
        ),
        ..Document::default()
    };
    for child in &root.children {
        match (&child.ns, &*child.name) {
            (Ns::Core, "primalSpaceFeatures") => {
                if let Some(p) = only_child(child, "PrimalSpaceFeatures")? {
                    doc.primal = Some(primal(p, &geo)?);
                }
            }
            (Ns::Core, "PrimalSpaceFeatures") => doc.primal = Some(primal(child, &geo)?),
            (Ns::Core, "multiLayeredGraph") => {
                if let Some(g) = only_child(child, "MultiLayeredGraph")? {
                    doc.graph = Some(graph(g, &geo, &mut doc.warnings)?);
                }
            }
            (Ns::Core, "MultiLayeredGraph") => {
                doc.graph = Some(graph(child, &geo, &mut doc.warnings)?)
            }
            (Ns::Core, _) => {
                return Err(unexpected(
                    child,
                    root,
                    "core:primalSpaceFeatures or core:multiLayeredGraph",
                ));
            }
            _ => {}
        }
    }
    doc.srs_name = geo.srs_name();
    Ok(doc)
}

fn check_root(root: &Element) -> Result<(), IndoorGmlError> {
    if root.is(&Ns::Core, "IndoorFeatures") {
        return Ok(());
    }
    let hint = match &root.ns {
        Ns::Other(uri) if uri.contains("indoorgml/2.0") => {
            "; this is the IndoorGML 2.0 draft XML encoding, which nrgdb does not read (it reads 1.0.x and 1.1 XML, and the 2.0 draft's JSON, IndoorJSON2, as .indoor.json)".to_string()
        }
        Ns::None if &*root.name == "IndoorFeatures" => {
            "; the element has no namespace: declare xmlns=\"http://www.opengis.net/indoorgml/1.0/core\"".to_string()
        }
        Ns::Navi => "; a navigation-module fragment (e.g. a Route) is not a complete IndoorGML document".to_string(),
        _ => String::new(),
    };
    Err(IndoorGmlError::UnknownRoot {
        line: root.line,
        found: root.qualified_name(),
        hint,
    })
}

/// The single IndoorGML child of a property element (`None` if empty).
fn only_child<'e, 'a>(
    prop: &'e Element<'a>,
    name: &str,
) -> Result<Option<&'e Element<'a>>, IndoorGmlError> {
    for child in &prop.children {
        if child.is(&Ns::Core, name) {
            return Ok(Some(child));
        }
        if child.ns != Ns::Gml {
            return Err(unexpected(child, prop, &format!("core:{name}")));
        }
    }
    Ok(None)
}

fn info(el: &Element) -> FeatureInfo {
    let mut info = FeatureInfo {
        id: el.gml_id().unwrap_or_default().to_string(),
        line: el.line,
        ..FeatureInfo::default()
    };
    for child in &el.children {
        if child.is(&Ns::Gml, "name") {
            info.names.push(child.trimmed_text().to_string());
        } else if child.is(&Ns::Gml, "description") {
            info.description = Some(child.trimmed_text().to_string());
        }
    }
    info
}

fn primal(el: &Element, geo: &GeometryReader) -> Result<PrimalSpace, IndoorGmlError> {
    let mut out = PrimalSpace {
        info: info(el),
        ..PrimalSpace::default()
    };
    for member in &el.children {
        match (&member.ns, &*member.name) {
            (Ns::Core, "cellSpaceMember") => {
                for c in member.children.iter().filter(|c| c.ns != Ns::Gml) {
                    out.cells.push(cell(c, geo)?);
                }
            }
            (Ns::Core, "cellSpaceBoundaryMember") => {
                for b in member.children.iter().filter(|c| c.ns != Ns::Gml) {
                    out.boundaries.push(boundary(b, geo)?);
                }
            }
            (Ns::Core, _) => {
                return Err(unexpected(
                    member,
                    el,
                    "core:cellSpaceMember or core:cellSpaceBoundaryMember",
                ));
            }
            _ => {}
        }
    }
    Ok(out)
}

fn cell(el: &Element, geo: &GeometryReader) -> Result<Cell, IndoorGmlError> {
    let class = match &el.ns {
        Ns::Core if &*el.name == "CellSpace" => CellClass::CellSpace,
        Ns::Navi => CellClass::from_navi_name(&el.name).ok_or_else(|| {
            unexpected_in(el, "core:cellSpaceMember", "core:CellSpace or a navi space")
        })?,
        Ns::Other(_) => CellClass::Extension(el.qualified_name()),
        _ => {
            return Err(unexpected_in(
                el,
                "core:cellSpaceMember",
                "core:CellSpace or a navi space",
            ));
        }
    };
    let mut cell = Cell {
        info: require_id(el)?,
        class,
        navi: NaviCodes::default(),
        geometry: None,
        duality: None,
        external: Vec::new(),
        bounded_by: Vec::new(),
    };
    for child in &el.children {
        match (&child.ns, &*child.name) {
            (Ns::Core, "cellSpaceGeometry") => {
                for g in child.children.iter() {
                    cell.geometry = Some(cell_geometry(g, geo)?);
                }
            }
            (Ns::Core, "Geometry2D" | "Geometry3D") => {
                cell.geometry = Some(cell_geometry(child, geo)?)
            }
            (Ns::Core, "duality") => cell.duality = href(child)?,
            (Ns::Core, "partialboundedBy") => cell.bounded_by.extend(href(child)?),
            (Ns::Core, "externalReference") => cell.external.push(external(child)),
            (Ns::Navi, "class") => cell.navi.class = child.trimmed_text().to_string(),
            (Ns::Navi, "function") => cell.navi.function = child.trimmed_text().to_string(),
            (Ns::Navi, "usage") => cell.navi.usage = child.trimmed_text().to_string(),
            _ => {}
        }
    }
    Ok(cell)
}

fn cell_geometry(el: &Element, geo: &GeometryReader) -> Result<CellGeometry, IndoorGmlError> {
    let shape = first_gml_child(el);
    match (&el.ns, &*el.name, shape) {
        (Ns::Core, "Geometry3D", Some(s)) if &*s.name == "Solid" => {
            Ok(CellGeometry::Solid(geo.solid(s)?))
        }
        (Ns::Core, "Geometry2D", Some(s)) if &*s.name == "Polygon" => {
            Ok(CellGeometry::Surface(geo.polygon(s, None)?))
        }
        (Ns::Core, "Geometry3D" | "Geometry2D", Some(s)) => Err(unexpected(
            s,
            el,
            if &*el.name == "Geometry3D" {
                "gml:Solid"
            } else {
                "gml:Polygon"
            },
        )),
        (Ns::Core, "Geometry3D" | "Geometry2D", None) => Err(IndoorGmlError::Missing {
            line: el.line,
            element: el.qualified_name(),
            missing: "geometry".into(),
        }),
        _ => Err(unexpected_in(
            el,
            "core:cellSpaceGeometry",
            "core:Geometry2D or core:Geometry3D",
        )),
    }
}

fn boundary(el: &Element, geo: &GeometryReader) -> Result<Boundary, IndoorGmlError> {
    let class = match &el.ns {
        Ns::Core if &*el.name == "CellSpaceBoundary" => BoundaryClass::CellSpaceBoundary,
        Ns::Navi => BoundaryClass::from_navi_name(&el.name).ok_or_else(|| {
            unexpected_in(
                el,
                "core:cellSpaceBoundaryMember",
                "core:CellSpaceBoundary or a navi boundary",
            )
        })?,
        Ns::Other(_) => BoundaryClass::Extension(el.qualified_name()),
        _ => {
            return Err(unexpected_in(
                el,
                "core:cellSpaceBoundaryMember",
                "core:CellSpaceBoundary or a navi boundary",
            ));
        }
    };
    let mut b = Boundary {
        info: require_id(el)?,
        class,
        duality: None,
        geometry: None,
        external: Vec::new(),
    };
    for child in &el.children {
        match (&child.ns, &*child.name) {
            (Ns::Core, "duality") => b.duality = href(child)?,
            (Ns::Core, "cellSpaceBoundaryGeometry") => {
                for g in &child.children {
                    b.geometry = Some(boundary_geometry(g, geo)?);
                }
            }
            (Ns::Core, "geometry2D" | "geometry3D") => {
                b.geometry = Some(boundary_geometry(child, geo)?)
            }
            (Ns::Core, "externalReference") => b.external.push(external(child)),
            _ => {}
        }
    }
    Ok(b)
}

fn boundary_geometry(
    el: &Element,
    geo: &GeometryReader,
) -> Result<BoundaryGeometry, IndoorGmlError> {
    let shape = first_gml_child(el).ok_or_else(|| IndoorGmlError::Missing {
        line: el.line,
        element: el.qualified_name(),
        missing: "geometry".into(),
    })?;
    match (&*el.name, &*shape.name) {
        ("geometry2D", "LineString") => Ok(BoundaryGeometry::Curve(geo.line_string(shape)?)),
        ("geometry3D", "Polygon") => Ok(BoundaryGeometry::Surface(geo.polygon(shape, None)?)),
        ("geometry2D", _) => Err(unexpected(shape, el, "gml:LineString")),
        ("geometry3D", _) => Err(unexpected(shape, el, "gml:Polygon")),
        _ => Err(unexpected_in(
            el,
            "core:cellSpaceBoundaryGeometry",
            "core:geometry2D or core:geometry3D",
        )),
    }
}

fn external(el: &Element) -> ExternalReference {
    let text = |parent: &Element, name: &str| {
        parent
            .child(&Ns::Core, name)
            .map(|e| e.trimmed_text().to_string())
    };
    let object = el.child(&Ns::Core, "externalObject");
    ExternalReference {
        information_system: text(el, "informationSystem"),
        name: object.and_then(|o| text(o, "name")),
        uri: object.and_then(|o| text(o, "uri")),
    }
}

fn graph(
    el: &Element,
    geo: &GeometryReader,
    warnings: &mut Vec<String>,
) -> Result<LayeredGraph, IndoorGmlError> {
    let mut out = LayeredGraph {
        info: info(el),
        ..LayeredGraph::default()
    };
    for child in &el.children {
        match (&child.ns, &*child.name) {
            (Ns::Core, "spaceLayers") => {
                let mut group = LayerGroup {
                    id: child.gml_id().unwrap_or_default().to_string(),
                    layers: Vec::new(),
                };
                for member in child.children.iter().filter(|c| c.ns != Ns::Gml) {
                    if !member.is(&Ns::Core, "spaceLayerMember") {
                        return Err(unexpected(member, child, "core:spaceLayerMember"));
                    }
                    if let Some(misspelt) = member
                        .children
                        .iter()
                        .find(|c| c.is(&Ns::Core, "spaceLayer"))
                    {
                        // Two independent real files (FZK-Haus among them)
                        // write the property's name for the feature's.
                        let w = format!(
                            "line {}: core:spaceLayer read as core:SpaceLayer (the schema \
                             spells the feature with a capital S)",
                            misspelt.line
                        );
                        tracing::warn!("{w}");
                        warnings.push(w);
                        group.layers.push(layer(misspelt, geo)?);
                    } else if let Some(layer_el) = only_child(member, "SpaceLayer")? {
                        group.layers.push(layer(layer_el, geo)?);
                    }
                }
                out.layer_groups.push(group);
            }
            (Ns::Core, "interEdges") => {
                let mut group = InterEdges {
                    id: child.gml_id().unwrap_or_default().to_string(),
                    connections: Vec::new(),
                };
                for member in child.children.iter().filter(|c| c.ns != Ns::Gml) {
                    if !member.is(&Ns::Core, "interLayerConnectionMember") {
                        return Err(unexpected(member, child, "core:interLayerConnectionMember"));
                    }
                    if let Some(ilc) = only_child(member, "InterLayerConnection")? {
                        group.connections.push(inter_layer_connection(ilc)?);
                    }
                }
                out.inter_edges.push(group);
            }
            (Ns::Core, _) => {
                return Err(unexpected(child, el, "core:spaceLayers or core:interEdges"));
            }
            _ => {}
        }
    }
    Ok(out)
}

fn layer(el: &Element, geo: &GeometryReader) -> Result<Layer, IndoorGmlError> {
    let mut out = Layer {
        info: require_id(el)?,
        ..Layer::default()
    };
    for child in &el.children {
        match (&child.ns, &*child.name) {
            (Ns::Core, "class") => out.class = Some(child.trimmed_text().to_string()),
            (Ns::Core, "nodes") => {
                if out.nodes_id.is_empty() {
                    out.nodes_id = child.gml_id().unwrap_or_default().to_string();
                }
                for member in child.children.iter().filter(|c| c.ns != Ns::Gml) {
                    if !member.is(&Ns::Core, "stateMember") {
                        return Err(unexpected(member, child, "core:stateMember"));
                    }
                    if let Some(s) = only_child(member, "State")? {
                        out.states.push(state(s, geo)?);
                    }
                }
            }
            (Ns::Core, "edges") => {
                if out.edges_id.is_empty() {
                    out.edges_id = child.gml_id().unwrap_or_default().to_string();
                }
                for member in child.children.iter().filter(|c| c.ns != Ns::Gml) {
                    if !member.is(&Ns::Core, "transitionMember") {
                        return Err(unexpected(member, child, "core:transitionMember"));
                    }
                    if let Some(t) = only_child(member, "Transition")? {
                        out.transitions.push(transition(t, geo)?);
                    }
                }
            }
            _ => {}
        }
    }
    Ok(out)
}

fn state(el: &Element, geo: &GeometryReader) -> Result<State, IndoorGmlError> {
    let mut s = State {
        info: require_id(el)?,
        ..State::default()
    };
    for child in &el.children {
        match (&child.ns, &*child.name) {
            (Ns::Core, "duality") => s.duality = href(child)?,
            (Ns::Core, "connects") => s.connects.extend(href(child)?),
            (Ns::Core, "geometry") => {
                if let Some(p) = first_gml_child(child) {
                    s.point = Some(geo.point(p)?);
                }
            }
            _ => {}
        }
    }
    Ok(s)
}

fn transition(el: &Element, geo: &GeometryReader) -> Result<Transition, IndoorGmlError> {
    let mut t = Transition {
        info: require_id(el)?,
        ..Transition::default()
    };
    for child in &el.children {
        match (&child.ns, &*child.name) {
            (Ns::Core, "weight") => t.weight = Some(parse_number(child)?),
            (Ns::Core, "connects") => t.connects.extend(href(child)?),
            (Ns::Core, "duality") => t.duality = href(child)?,
            (Ns::Core, "geometry") => {
                if let Some(l) = first_gml_child(child) {
                    t.geometry = Some(geo.line_string(l)?);
                }
            }
            _ => {}
        }
    }
    Ok(t)
}

fn inter_layer_connection(el: &Element) -> Result<InterLayerConnection, IndoorGmlError> {
    let mut c = InterLayerConnection {
        info: require_id(el)?,
        ..InterLayerConnection::default()
    };
    for child in &el.children {
        match (&child.ns, &*child.name) {
            (Ns::Core, "typeOfTopoExpression") => c.topo = Some(child.trimmed_text().to_string()),
            (Ns::Core, "comment") => c.comment = Some(child.trimmed_text().to_string()),
            (Ns::Core, "interConnects") => c.inter_connects.extend(href(child)?),
            (Ns::Core, "ConnectedLayers") => c.connected_layers.extend(href(child)?),
            _ => {}
        }
    }
    Ok(c)
}

/// The target of a property element: its `xlink:href`, or the `gml:id` of
/// an inline feature.
fn href(prop: &Element) -> Result<Option<String>, IndoorGmlError> {
    if let Some(h) = prop.href() {
        return Ok(Some(h.to_string()));
    }
    match prop.children.iter().find(|c| c.ns != Ns::Gml) {
        Some(inline) => Err(IndoorGmlError::Unexpected {
            line: inline.line,
            found: format!("an inline {}", inline.qualified_name()),
            parent: prop.qualified_name(),
            expected: "an xlink:href to an element defined elsewhere in the document".into(),
        }),
        None => Ok(None),
    }
}

fn require_id(el: &Element) -> Result<FeatureInfo, IndoorGmlError> {
    let info = info(el);
    if info.id.is_empty() {
        return Err(IndoorGmlError::Missing {
            line: el.line,
            element: el.qualified_name(),
            missing: "gml:id attribute".into(),
        });
    }
    Ok(info)
}

fn unexpected(el: &Element, parent: &Element, expected: &str) -> IndoorGmlError {
    unexpected_in(el, &parent.qualified_name(), expected)
}

fn unexpected_in(el: &Element, parent: &str, expected: &str) -> IndoorGmlError {
    IndoorGmlError::Unexpected {
        line: el.line,
        found: el.qualified_name(),
        parent: parent.to_string(),
        expected: expected.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn doc(prefix: &str, href: &str) -> String {
        format!(
            r#"<{prefix}:IndoorFeatures xmlns:{prefix}="http://www.opengis.net/indoorgml/1.0/core" xmlns:g="http://www.opengis.net/gml/3.2" xmlns:x="http://www.w3.org/1999/xlink">
<{prefix}:multiLayeredGraph><{prefix}:MultiLayeredGraph g:id="G"><{prefix}:spaceLayers><{prefix}:spaceLayerMember>
<{prefix}:SpaceLayer g:id="L"><{prefix}:nodes><{prefix}:stateMember><{prefix}:State g:id="S1"><{prefix}:connects x:href="{href}"/></{prefix}:State>
</{prefix}:stateMember></{prefix}:nodes></{prefix}:SpaceLayer></{prefix}:spaceLayerMember></{prefix}:spaceLayers></{prefix}:MultiLayeredGraph></{prefix}:multiLayeredGraph>
</{prefix}:IndoorFeatures>"#
        )
    }

    #[test]
    fn any_prefix_and_hrefs_with_or_without_hash() {
        let a = read_document(&doc("core", "#T1")).unwrap();
        let b = read_document(&doc("ig", "T1")).unwrap();
        assert_eq!(a.layers()[0].states[0].connects, vec!["T1".to_string()]);
        assert_eq!(
            a.layers()[0].states[0].connects,
            b.layers()[0].states[0].connects
        );
    }

    #[test]
    fn inline_features_in_references_are_refused_with_their_line() {
        let text = doc("core", "#T1").replace(
            r##"<core:connects x:href="#T1"/>"##,
            "<core:connects>\n<core:Transition g:id=\"T9\"/></core:connects>",
        );
        let err = read_document(&text).unwrap_err().to_string();
        assert!(
            err.starts_with("line 4") && err.contains("inline core:Transition"),
            "{err}"
        );
    }
}
