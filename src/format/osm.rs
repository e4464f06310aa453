//! The model as an OpenStreetMap XML file (`.osm`, OSM XML 0.6) tagged by
//! Simple Indoor Tagging (<https://wiki.openstreetmap.org/wiki/Simple_Indoor_Tagging>),
//! for JOSM: [`to_osm_xml`].
//!
//! - A room, corridor or other space is a closed way tagged
//!   `indoor=room | corridor | area`, `level` (the georeference's),
//!   `ref` and `nrgdb:id` (its id), and `name` when it has one; a space with
//!   holes is a `type=multipolygon` relation carrying those tags, its
//!   rings untagged `outer` and `inner` member ways.
//! - A door is not a way (SIT has no `indoor=door`): it is a node tagged
//!   `door=yes`, `width` (metres, to the centimetre), `level`, `ref`,
//!   `nrgdb:id` (and `name`), at the middle of its doorway line
//!   ([`doorway`]), and a vertex of the outline of every space it joins
//!   (its connections), which dips to it in a small notch (see
//!   `osm/notch.rs`).
//! - Coordinates come from the [`Georef`], to 7 decimals (OSM's
//!   precision); points equal at that precision are one node, so
//!   neighbouring outlines share their common corners.
//! - Every id is negative (new objects) and unique across nodes, ways and
//!   relations; there is no `version` or `changeset`, and the file says
//!   `upload="never"` so JOSM refuses to upload it.

mod notch;

use std::collections::HashMap;
use std::fmt::Write as _;

use quick_xml::escape::escape;

use crate::model::{Georef, Nrg, Point, Space, SpaceId, SpaceKind, doorway};
use notch::Notch;

/// A model as the text of an OSM XML file tagged by Simple Indoor Tagging
/// (see the module doc), placed on the Earth by `georef`. A model without
/// spaces gives a valid file without objects.
///
/// ```
/// use nrgdb::format::osm::to_osm_xml;
/// use nrgdb::model::Georef;
/// let nrg = nrgdb::fixtures::corridor_building(2);
/// let georef = Georef::new(52.5, 13.4, 0.0, "1").unwrap();
/// let osm = to_osm_xml(&nrg, &georef);
/// assert!(osm.contains(r#"<osm version="0.6" generator="nrgdb" upload="never">"#));
/// assert!(osm.contains(r#"<tag k="indoor" v="corridor"/>"#));
/// assert_eq!(osm.matches(r#"<tag k="door" v="yes"/>"#).count(), 2);
/// ```
pub fn to_osm_xml(nrg: &Nrg, georef: &Georef) -> String {
    let mut osm = Osm::new(georef);
    let notches = door_notches(nrg);
    for space in nrg.spaces() {
        if let Some(indoor) = indoor_value(space.kind) {
            let mine = notches.get(&space.id).map_or(&[][..], Vec::as_slice);
            osm.add_space(space, indoor, mine);
        }
    }
    for space in nrg.spaces() {
        if let Some(d) = doorway(space) {
            osm.add_door(space, d.middle(), d.width_m);
        }
    }
    osm.into_xml()
}

/// SIT's `indoor` value for a kind; `None` for doors (nodes, not areas).
fn indoor_value(kind: SpaceKind) -> Option<&'static str> {
    match kind {
        SpaceKind::Room => Some("room"),
        SpaceKind::Corridor => Some("corridor"),
        // SIT maps stairwells and lift shafts as indoor=area (with
        // stairs=yes / highway=elevator added by `kind_tags`).
        SpaceKind::Stairs | SpaceKind::Elevator | SpaceKind::Other => Some("area"),
        SpaceKind::Door => None,
    }
}

/// For each space written as an area, the doors put into its rings: the
/// ring's index (0 the exterior, then the holes) and the notch.
fn door_notches(nrg: &Nrg) -> HashMap<SpaceId, Vec<(usize, Notch)>> {
    let mut out: HashMap<SpaceId, Vec<(usize, Notch)>> = HashMap::new();
    for door in nrg.spaces() {
        let Some(d) = doorway(door) else { continue };
        let mut sides: Vec<SpaceId> = nrg
            .connections_of(door.id)
            .map(|c| if c.a == door.id { c.b } else { c.a })
            .collect();
        sides.sort();
        sides.dedup();
        for side in sides {
            let Some(space) = nrg.space(side) else {
                continue;
            };
            if indoor_value(space.kind).is_none() {
                continue;
            }
            let rings: Vec<&[Point]> = std::iter::once(space.polygon.as_slice())
                .chain(space.holes.iter().map(Vec::as_slice))
                .collect();
            if let Some(found) = notch::nearest(&rings, d.middle()) {
                out.entry(side).or_default().push(found);
            }
        }
    }
    out
}

/// One node: its id, coordinates in 1e-7 degrees and tags.
struct Node {
    id: i64,
    lat: i64,
    lon: i64,
    tags: Vec<(&'static str, String)>,
}

/// One way: its id, node ids (closed) and tags.
struct Way {
    id: i64,
    nodes: Vec<i64>,
    tags: Vec<(&'static str, String)>,
}

/// One multipolygon relation: its id, member way ids with roles, tags.
struct Relation {
    id: i64,
    members: Vec<(i64, &'static str)>,
    tags: Vec<(&'static str, String)>,
}

/// The file being built.
struct Osm<'g> {
    georef: &'g Georef,
    next_id: i64,
    nodes: Vec<Node>,
    by_position: HashMap<(i64, i64), usize>,
    ways: Vec<Way>,
    relations: Vec<Relation>,
}

impl<'g> Osm<'g> {
    fn new(georef: &'g Georef) -> Osm<'g> {
        Osm {
            georef,
            next_id: -1,
            nodes: Vec::new(),
            by_position: HashMap::new(),
            ways: Vec::new(),
            relations: Vec::new(),
        }
    }

    fn new_id(&mut self) -> i64 {
        let id = self.next_id;
        self.next_id -= 1;
        id
    }

    /// The index of the node at map point `p` (made when new).
    fn node(&mut self, p: Point) -> usize {
        let [lon, lat] = self.georef.to_lon_lat(p);
        // Finite coordinates within ±180°: the cast cannot saturate.
        let key = ((lat * 1e7).round() as i64, (lon * 1e7).round() as i64);
        if let Some(&i) = self.by_position.get(&key) {
            return i;
        }
        let id = self.new_id();
        self.nodes.push(Node {
            id,
            lat: key.0,
            lon: key.1,
            tags: Vec::new(),
        });
        let i = self.nodes.len() - 1;
        self.by_position.insert(key, i);
        i
    }

    /// A closed way of the ring's nodes, or `None` when fewer than three
    /// distinct nodes remain at OSM's precision.
    fn ring_way(&mut self, ring: &[Point], tags: Vec<(&'static str, String)>) -> Option<i64> {
        let mut nodes: Vec<i64> = Vec::with_capacity(ring.len() + 1);
        for &p in ring {
            let i = self.node(p);
            let id = self.nodes.get(i).map_or(0, |n| n.id);
            if nodes.last() != Some(&id) {
                nodes.push(id);
            }
        }
        while nodes.len() > 1 && nodes.first() == nodes.last() {
            nodes.pop();
        }
        if nodes.len() < 3 {
            return None;
        }
        nodes.push(nodes.first().copied().unwrap_or_default());
        let id = self.new_id();
        self.ways.push(Way { id, nodes, tags });
        Some(id)
    }

    /// A room, corridor or other space: a way, or a multipolygon when it
    /// has holes; the doors' notches put into its rings.
    fn add_space(&mut self, space: &Space, indoor: &'static str, notches: &[(usize, Notch)]) {
        let mut tags = vec![("indoor", indoor.to_string())];
        tags.extend(common_tags(space, self.georef));
        let rings: Vec<Vec<Point>> = std::iter::once(&space.polygon)
            .chain(&space.holes)
            .enumerate()
            .map(|(r, ring)| {
                let mine: Vec<Notch> = notches
                    .iter()
                    .filter(|(on, _)| *on == r)
                    .map(|(_, n)| *n)
                    .collect();
                notch::with_notches(ring, &mine)
            })
            .collect();
        let Some((outer, holes)) = rings.split_first() else {
            return;
        };
        if holes.is_empty() {
            self.ring_way(outer, tags);
            return;
        }
        let Some(outer_id) = self.ring_way(outer, Vec::new()) else {
            return;
        };
        let mut members = vec![(outer_id, "outer")];
        for hole in holes {
            if let Some(id) = self.ring_way(hole, Vec::new()) {
                members.push((id, "inner"));
            }
        }
        tags.insert(0, ("type", "multipolygon".to_string()));
        let id = self.new_id();
        self.relations.push(Relation { id, members, tags });
    }

    /// A door: its node at the doorway's middle, tagged.
    fn add_door(&mut self, door: &Space, middle: Point, width_m: f64) {
        let i = self.node(middle);
        let mut tags = vec![("door", "yes".to_string())];
        if width_m.is_finite() && width_m > 0.0 {
            tags.push(("width", metres(width_m)));
        }
        tags.extend(common_tags(door, self.georef));
        if let Some(node) = self.nodes.get_mut(i) {
            node.tags.extend(tags);
        }
    }

    fn into_xml(self) -> String {
        let mut out = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        out.push_str("<osm version=\"0.6\" generator=\"nrgdb\" upload=\"never\">\n");
        let lats = self.nodes.iter().map(|n| n.lat);
        let lons = self.nodes.iter().map(|n| n.lon);
        if let (Some(minlat), Some(maxlat), Some(minlon), Some(maxlon)) = (
            lats.clone().min(),
            lats.max(),
            lons.clone().min(),
            lons.max(),
        ) {
            let _ = writeln!(
                out,
                "  <bounds minlat=\"{}\" minlon=\"{}\" maxlat=\"{}\" maxlon=\"{}\"/>",
                degrees(minlat),
                degrees(minlon),
                degrees(maxlat),
                degrees(maxlon)
            );
        }
        for n in &self.nodes {
            let _ = write!(
                out,
                "  <node id=\"{}\" lat=\"{}\" lon=\"{}\"",
                n.id,
                degrees(n.lat),
                degrees(n.lon)
            );
            if n.tags.is_empty() {
                out.push_str("/>\n");
            } else {
                out.push_str(">\n");
                write_tags(&mut out, &n.tags);
                out.push_str("  </node>\n");
            }
        }
        for w in &self.ways {
            let _ = writeln!(out, "  <way id=\"{}\">", w.id);
            for id in &w.nodes {
                let _ = writeln!(out, "    <nd ref=\"{id}\"/>");
            }
            write_tags(&mut out, &w.tags);
            out.push_str("  </way>\n");
        }
        for r in &self.relations {
            let _ = writeln!(out, "  <relation id=\"{}\">", r.id);
            for (id, role) in &r.members {
                let _ = writeln!(
                    out,
                    "    <member type=\"way\" ref=\"{id}\" role=\"{role}\"/>"
                );
            }
            write_tags(&mut out, &r.tags);
            out.push_str("  </relation>\n");
        }
        out.push_str("</osm>\n");
        out
    }
}

/// The tags every written space carries: `level` (the space's, else the
/// georeference's), `ref`, `nrgdb:id`, `name` when it has one, and
/// `stairs=yes` or `highway=elevator` on stairs and lifts (SIT).
fn common_tags(space: &Space, georef: &Georef) -> Vec<(&'static str, String)> {
    let level = space
        .level
        .as_ref()
        .map_or_else(|| georef.level.clone(), |l| l.name.clone());
    let mut tags = vec![
        ("level", level),
        ("ref", space.id.to_string()),
        ("nrgdb:id", space.id.to_string()),
    ];
    match space.kind {
        SpaceKind::Stairs => tags.push(("stairs", "yes".into())),
        SpaceKind::Elevator => tags.push(("highway", "elevator".into())),
        _ => {}
    }
    if let Some(name) = space.name.as_deref().filter(|n| !n.trim().is_empty()) {
        tags.push(("name", name.to_string()));
    }
    tags
}

fn write_tags(out: &mut String, tags: &[(&'static str, String)]) {
    for (k, v) in tags {
        let _ = writeln!(
            out,
            "    <tag k=\"{}\" v=\"{}\"/>",
            escape(*k),
            escape(xml_chars(v))
        );
    }
}

/// The text without the characters XML 1.0 cannot hold (controls below
/// U+0020 other than tab, line feed and carriage return; U+FFFE, U+FFFF).
fn xml_chars(s: &str) -> String {
    s.chars()
        .filter(|&c| {
            (c >= ' ' || matches!(c, '\t' | '\n' | '\r')) && !matches!(c, '\u{fffe}' | '\u{ffff}')
        })
        .collect()
}

/// 1e-7 degrees as a decimal with 7 places, exactly.
fn degrees(e7: i64) -> String {
    let sign = if e7 < 0 { "-" } else { "" };
    let abs = e7.unsigned_abs();
    format!("{sign}{}.{:07}", abs / 10_000_000, abs % 10_000_000)
}

/// Metres to the centimetre without trailing zeros ("0.9", "1.25", "1").
fn metres(m: f64) -> String {
    let s = format!("{m:.2}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_written_exactly() {
        assert_eq!(degrees(525_000_000), "52.5000000");
        assert_eq!(degrees(-1), "-0.0000001");
        assert_eq!(degrees(-1_234_567_891), "-123.4567891");
        assert_eq!(metres(0.9), "0.9");
        assert_eq!(metres(1.0), "1");
        assert_eq!(metres(1.254_9), "1.25");
    }

    #[test]
    fn control_characters_are_left_out() {
        assert_eq!(xml_chars("a\u{1}b\tc\u{ffff}d é"), "ab\tcd é");
    }

    #[test]
    fn an_empty_model_is_an_empty_file() {
        let georef = Georef::new(0.0, 0.0, 0.0, "0").unwrap();
        let osm = to_osm_xml(&Nrg::default(), &georef);
        assert!(osm.ends_with("upload=\"never\">\n</osm>\n"), "{osm}");
    }
}
