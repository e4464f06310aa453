//! Reading GML 3.2 geometry (Point, LineString, Polygon, Solid) from the
//! element tree, with `pos`/`posList` in 2 or 3 dimensions.

use super::IndoorGmlError;
use super::document::{Coords, GmlPoint, LineString, Polygon, Solid};
use super::dom::{Element, Ns};

/// Reads geometry with a default dimension for coordinates that declare none.
pub struct GeometryReader {
    /// Dimension used when neither the element nor an ancestor says.
    pub default_dim: usize,
    /// The first `srsName` seen on a geometry read so far.
    srs_name: std::cell::RefCell<Option<String>>,
}

impl GeometryReader {
    /// Chooses the default dimension of a document: 3 if any position in
    /// it declares or has three numbers, else 2.
    pub fn for_document(root: &Element) -> GeometryReader {
        GeometryReader {
            default_dim: if has_3d(root) { 3 } else { 2 },
            srs_name: std::cell::RefCell::new(None),
        }
    }

    /// The first `srsName` on any geometry read.
    pub fn srs_name(&self) -> Option<String> {
        self.srs_name.borrow().clone()
    }

    fn note_srs(&self, el: &Element) {
        if let Some(srs) = el.attr(&Ns::None, "srsName") {
            let mut seen = self.srs_name.borrow_mut();
            if seen.is_none() {
                *seen = Some(srs.to_string());
            }
        }
    }

    /// A `gml:Point`.
    pub fn point(&self, el: &Element) -> Result<GmlPoint, IndoorGmlError> {
        expect(el, "Point")?;
        self.note_srs(el);
        let dim = self.dim_of(el, None);
        let pos = el
            .child(&Ns::Gml, "pos")
            .ok_or_else(|| missing(el, "gml:pos"))?;
        let coords = self.positions(std::slice::from_ref(pos), dim)?;
        if coords.len() != 1 {
            return Err(missing(el, "exactly one position"));
        }
        Ok(GmlPoint {
            id: id_of(el),
            coords,
        })
    }

    /// A `gml:LineString`.
    pub fn line_string(&self, el: &Element) -> Result<LineString, IndoorGmlError> {
        expect(el, "LineString")?;
        self.note_srs(el);
        let dim = self.dim_of(el, None);
        let coords = self.positions(&el.children, dim)?;
        if coords.len() < 2 {
            return Err(missing(el, "two positions"));
        }
        Ok(LineString {
            id: id_of(el),
            coords,
        })
    }

    /// A `gml:Polygon`; `dim` is an ancestor's `srsDimension`, if any.
    pub fn polygon(&self, el: &Element, dim: Option<usize>) -> Result<Polygon, IndoorGmlError> {
        expect(el, "Polygon")?;
        self.note_srs(el);
        let dim = self.dim_of(el, dim);
        let mut exterior = None;
        let mut interiors = Vec::new();
        for child in &el.children {
            if child.is(&Ns::Gml, "exterior") {
                exterior = Some(self.ring(child, dim)?);
            } else if child.is(&Ns::Gml, "interior") {
                interiors.push(self.ring(child, dim)?);
            }
        }
        let exterior = exterior.ok_or_else(|| missing(el, "gml:exterior"))?;
        Ok(Polygon {
            id: id_of(el),
            exterior,
            interiors,
        })
    }

    /// A `gml:Solid` made of Polygon surface members.
    pub fn solid(&self, el: &Element) -> Result<Solid, IndoorGmlError> {
        expect(el, "Solid")?;
        self.note_srs(el);
        let dim = Some(self.dim_of(el, None));
        let mut exterior = None;
        let mut interiors = Vec::new();
        for child in &el.children {
            let is_ext = child.is(&Ns::Gml, "exterior");
            if !is_ext && !child.is(&Ns::Gml, "interior") {
                continue;
            }
            let shell = first_gml_child(child).ok_or_else(|| missing(child, "gml:Shell"))?;
            let mut polygons = Vec::new();
            for member in shell.children_named(&Ns::Gml, "surfaceMember") {
                let poly = first_gml_child(member)
                    .ok_or_else(|| missing(member, "an inline gml:Polygon"))?;
                polygons.push(self.polygon(poly, dim)?);
            }
            if is_ext {
                exterior = Some(polygons);
            } else {
                interiors.push(polygons);
            }
        }
        let exterior = exterior.ok_or_else(|| missing(el, "gml:exterior"))?;
        Ok(Solid {
            id: id_of(el),
            exterior,
            interiors,
        })
    }

    fn ring(&self, boundary: &Element, dim: usize) -> Result<Coords, IndoorGmlError> {
        let ring = boundary
            .child(&Ns::Gml, "LinearRing")
            .ok_or_else(|| missing(boundary, "gml:LinearRing"))?;
        let coords = self.positions(&ring.children, self.dim_of(ring, Some(dim)))?;
        if coords.len() < 4 {
            return Err(missing(ring, "at least 4 positions (a closed ring)"));
        }
        Ok(coords)
    }

    fn dim_of(&self, el: &Element, inherited: Option<usize>) -> usize {
        el.attr(&Ns::None, "srsDimension")
            .and_then(|d| d.trim().parse().ok())
            .filter(|d| (2..=3).contains(d))
            .or(inherited)
            .unwrap_or(self.default_dim)
    }

    /// Coordinates of the `gml:pos` / `gml:posList` children.
    fn positions(&self, children: &[Element], dim: usize) -> Result<Coords, IndoorGmlError> {
        let mut values = Vec::new();
        let mut out_dim = None;
        for child in children {
            let is_pos = child.is(&Ns::Gml, "pos");
            if !is_pos && !child.is(&Ns::Gml, "posList") {
                continue;
            }
            let start = values.len();
            parse_numbers(child, &mut values)?;
            let count = values.len() - start;
            let declared = child
                .attr(&Ns::None, "srsDimension")
                .and_then(|d| d.trim().parse::<usize>().ok())
                .filter(|d| (2..=3).contains(d));
            let d = match (is_pos, declared) {
                (_, Some(d)) => d,
                (true, None) if (2..=3).contains(&count) => count,
                _ => dim,
            };
            if count % d != 0 || (is_pos && count != d) {
                return Err(IndoorGmlError::BadCoordinates {
                    line: child.line,
                    element: child.qualified_name(),
                    count,
                    dim: d,
                });
            }
            match out_dim {
                None => out_dim = Some(d),
                Some(prev) if prev != d => {
                    return Err(IndoorGmlError::BadCoordinates {
                        line: child.line,
                        element: child.qualified_name(),
                        count,
                        dim: prev,
                    });
                }
                Some(_) => {}
            }
        }
        Ok(Coords {
            dim: out_dim.unwrap_or(dim),
            values,
        })
    }
}

/// Parses whitespace-separated finite numbers from an element's text.
pub fn parse_numbers(el: &Element, out: &mut Vec<f64>) -> Result<(), IndoorGmlError> {
    for word in el.text.split_ascii_whitespace() {
        match word.parse::<f64>() {
            Ok(v) if v.is_finite() => out.push(v),
            _ => {
                return Err(IndoorGmlError::BadNumber {
                    line: el.line,
                    element: el.qualified_name(),
                    text: word.chars().take(40).collect(),
                });
            }
        }
    }
    Ok(())
}

/// Parses an element's text as one finite number.
pub fn parse_number(el: &Element) -> Result<f64, IndoorGmlError> {
    let text = el.trimmed_text();
    match text.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(IndoorGmlError::BadNumber {
            line: el.line,
            element: el.qualified_name(),
            text: text.chars().take(40).collect(),
        }),
    }
}

/// The first child in the GML namespace.
pub fn first_gml_child<'e, 'a>(el: &'e Element<'a>) -> Option<&'e Element<'a>> {
    el.children.iter().find(|c| c.ns == Ns::Gml)
}

fn id_of(el: &Element) -> Option<String> {
    el.gml_id().map(str::to_string)
}

fn expect(el: &Element, name: &str) -> Result<(), IndoorGmlError> {
    if el.is(&Ns::Gml, name) {
        Ok(())
    } else {
        Err(IndoorGmlError::Unexpected {
            line: el.line,
            found: el.qualified_name(),
            parent: "a geometry property".into(),
            expected: format!("gml:{name}"),
        })
    }
}

fn missing(el: &Element, what: &str) -> IndoorGmlError {
    IndoorGmlError::Missing {
        line: el.line,
        element: el.qualified_name(),
        missing: what.into(),
    }
}

fn has_3d(el: &Element) -> bool {
    if el
        .attr(&Ns::None, "srsDimension")
        .is_some_and(|d| d.trim() == "3")
    {
        return true;
    }
    if el.is(&Ns::Gml, "pos") {
        return el.text.split_ascii_whitespace().count() == 3;
    }
    el.children.iter().any(has_3d)
}
