//! The model as an OpenStreetMap file in Simple Indoor Tagging (SIT), for
//! JOSM: OSM XML 0.6 with negative ids and `upload="never"` (a file to look
//! at and edit, never to send to the OSM servers by mistake).
//!
//! Rooms, corridors and other spaces are closed ways tagged
//! `indoor=room|corridor|area` with `level`, `ref` (the space id) and
//! `name`; a space with holes is a `type=multipolygon` relation with an
//! outer and inner ways. SIT has no `indoor=door`: a door is a node tagged
//! `door=yes` (`width`, `level`, `ref`) that lies on the outlines of both
//! spaces it joins. Our doors are thick (a door space fills the doorway
//! between two rooms), so each neighbour's outline takes a narrow notch
//! into the doorway to reach the door node: the doorway line's ends
//! projected onto its nearest edge, the door node between them (the
//! notch is as wide as the door and half the wall deep). Positions are
//! WGS84 from the map's georeference, to 7 decimals (OSM's precision);
//! vertices that round to the same position are one node.

use std::collections::HashMap;
use std::fmt::Write as _;

use crate::model::{Georef, Nrg, Point, Space, SpaceId, SpaceKind, doorway};

/// OSM XML of `nrg` placed by `georef` (see the module docs).
///
/// ```
/// use nrgdb::model::Georef;
/// let nrg = nrgdb::fixtures::corridor_building(2);
/// let osm = nrgdb::format::osm::to_osm(&nrg, &Georef::new(48.0, 11.0, 0.0, "1").unwrap());
/// assert!(osm.contains(r#"<tag k="indoor" v="room"/>"#) && osm.contains(r#"<tag k="door" v="yes"/>"#));
/// ```
pub fn to_osm(nrg: &Nrg, georef: &Georef) -> String {
    let mut doc = Doc {
        georef,
        nodes: Vec::new(),
        at: HashMap::new(),
        body: String::new(),
        next: -1,
    };
    // Door nodes first, and the notches they cut into their neighbours.
    let mut notches: HashMap<SpaceId, Vec<(Point, Point, Point)>> = HashMap::new();
    for d in nrg.spaces().iter().filter(|s| s.kind == SpaceKind::Door) {
        let Some(way) = doorway(d) else { continue };
        let [e1, e2] = way.line;
        let mid = [(e1[0] + e2[0]) / 2.0, (e1[1] + e2[1]) / 2.0];
        let id = doc.node(mid);
        let mut tags = vec![
            ("door", "yes".to_string()),
            ("width", format!("{:.2}", way.width_m)),
            ("level", georef.level.clone()),
            ("ref", d.id.0.to_string()),
        ];
        if let Some(name) = &d.name {
            tags.push(("name", name.clone()));
        }
        doc.tag_node(id, tags);
        for c in nrg.connections().iter().filter(|c| c.kind.is_navigable()) {
            if let Some(other) = c.other(d.id) {
                notches.entry(other).or_default().push((e1, mid, e2));
            }
        }
    }
    for s in nrg.spaces().iter().filter(|s| s.kind != SpaceKind::Door) {
        let outer = notched(&s.polygon, notches.get(&s.id).map_or(&[][..], |v| v));
        let tags = space_tags(s, georef);
        if s.holes.is_empty() {
            doc.way(&outer, &tags);
            continue;
        }
        let outer_id = doc.way(&outer, &[]);
        let inner: Vec<i64> = s.holes.iter().map(|h| doc.way(h, &[])).collect();
        let mut members = format!("    <member type=\"way\" ref=\"{outer_id}\" role=\"outer\"/>\n");
        for i in inner {
            let _ = writeln!(
                members,
                "    <member type=\"way\" ref=\"{i}\" role=\"inner\"/>"
            );
        }
        let id = doc.fresh();
        let _ = writeln!(doc.body, "  <relation id=\"{id}\" visible=\"true\">");
        doc.body.push_str(&members);
        doc.body
            .push_str(&tag_lines(&[("type", "multipolygon".to_string())]));
        doc.body.push_str(&tag_lines(&tags));
        doc.body.push_str("  </relation>\n");
    }
    let mut out = String::from(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<osm version=\"0.6\" generator=\"nrgdb\" upload=\"never\">\n",
    );
    for (id, p, tags) in &doc.nodes {
        let [lon, lat] = georef.to_lon_lat(*p);
        if tags.is_empty() {
            let _ = writeln!(
                out,
                "  <node id=\"{id}\" visible=\"true\" lat=\"{lat:.7}\" lon=\"{lon:.7}\"/>"
            );
        } else {
            let _ = writeln!(
                out,
                "  <node id=\"{id}\" visible=\"true\" lat=\"{lat:.7}\" lon=\"{lon:.7}\">"
            );
            out.push_str(&tag_lines(tags));
            out.push_str("  </node>\n");
        }
    }
    out.push_str(&doc.body);
    out.push_str("</osm>\n");
    out
}

fn space_tags(s: &Space, georef: &Georef) -> Tags {
    let indoor = match s.kind {
        SpaceKind::Room => "room",
        SpaceKind::Corridor => "corridor",
        _ => "area",
    };
    let mut tags = vec![
        ("indoor", indoor.to_string()),
        ("level", georef.level.clone()),
        ("ref", s.id.0.to_string()),
    ];
    if let Some(name) = &s.name {
        tags.push(("name", name.clone()));
    }
    tags
}

fn tag_lines(tags: &[(&str, String)]) -> String {
    let mut out = String::new();
    for (k, v) in tags {
        let _ = writeln!(out, "    <tag k=\"{k}\" v=\"{}\"/>", escape(v));
    }
    out
}

fn escape(v: &str) -> String {
    v.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// Tags of a node, way or relation.
type Tags = Vec<(&'static str, String)>;

/// The nodes and ways written so far.
struct Doc<'a> {
    georef: &'a Georef,
    /// Id, map-frame position and tags of every node.
    nodes: Vec<(i64, Point, Tags)>,
    /// Node id by rounded WGS84 position (1e-7°).
    at: HashMap<(i64, i64), i64>,
    /// Ways and relations.
    body: String,
    next: i64,
}

impl Doc<'_> {
    fn fresh(&mut self) -> i64 {
        let id = self.next;
        self.next -= 1;
        id
    }

    /// The node at `p` (one per position after rounding).
    fn node(&mut self, p: Point) -> i64 {
        let [lon, lat] = self.georef.to_lon_lat(p);
        let key = ((lat * 1e7).round() as i64, (lon * 1e7).round() as i64);
        if let Some(id) = self.at.get(&key) {
            return *id;
        }
        let id = self.fresh();
        self.at.insert(key, id);
        self.nodes.push((id, p, Vec::new()));
        id
    }

    fn tag_node(&mut self, id: i64, tags: Tags) {
        if let Some(n) = self.nodes.iter_mut().find(|n| n.0 == id) {
            n.2 = tags;
        }
    }

    /// A closed way along `ring`; returns its id.
    fn way(&mut self, ring: &[Point], tags: &[(&'static str, String)]) -> i64 {
        let mut refs: Vec<i64> = ring.iter().map(|p| self.node(*p)).collect();
        refs.dedup();
        if refs.len() > 1 && refs.first() == refs.last() {
            refs.pop();
        }
        let id = self.fresh();
        let _ = writeln!(self.body, "  <way id=\"{id}\" visible=\"true\">");
        for r in refs.iter().chain(refs.first()) {
            let _ = writeln!(self.body, "    <nd ref=\"{r}\"/>");
        }
        self.body.push_str(&tag_lines(tags));
        self.body.push_str("  </way>\n");
        id
    }
}

/// `ring` with a notch to each door node: on the edge nearest the door,
/// the doorway ends projected onto it with the door node between them.
fn notched(ring: &[Point], doors: &[(Point, Point, Point)]) -> Vec<Point> {
    let n = ring.len();
    let mut inserts: Vec<Vec<(f64, [Point; 3])>> = vec![Vec::new(); n];
    for (e1, mid, e2) in doors {
        let Some((i, _)) = (0..n)
            .map(|i| {
                (
                    i,
                    crate::model::segment_distance(*mid, ring[i], ring[(i + 1) % n]),
                )
            })
            .min_by(|a, b| a.1.total_cmp(&b.1))
        else {
            continue;
        };
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        let (t1, t2) = (along(a, b, *e1), along(a, b, *e2));
        let (lo, hi) = (t1.min(t2), t1.max(t2));
        let at = |t: f64| [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
        inserts[i].push((lo, [at(lo), *mid, at(hi)]));
    }
    let mut out = Vec::with_capacity(n + 3 * doors.len());
    for (i, p) in ring.iter().enumerate() {
        out.push(*p);
        let mut here = std::mem::take(&mut inserts[i]);
        here.sort_by(|x, y| x.0.total_cmp(&y.0));
        for (_, pts) in here {
            out.extend(pts);
        }
    }
    out
}

/// Where the projection of `p` onto segment `a`–`b` lies, as a fraction
/// clamped to the segment (kept a little inside its ends).
fn along(a: Point, b: Point, p: Point) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    if len2 <= 0.0 {
        return 0.5;
    }
    (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.001, 0.999)
}
