//! The NRG: spaces and the connections between them, with their invariants.

use std::collections::{BTreeMap, HashMap, HashSet};

use serde::{Deserialize, Serialize};

use super::{Connection, ConnectionKind, Level, ModelError, Space, SpaceId, level_name};

/// A Node-Relation Graph: the spaces of one floor and how they connect.
///
/// Invariants (checked by [`Nrg::new`]): space ids are unique, every
/// connection names two distinct existing spaces, a pair is connected at
/// most once, coordinates and lengths are finite. Spaces are kept sorted by
/// id and connections by `(a, b)` with `a < b`, so equal models serialise to
/// equal bytes.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Nrg {
    spaces: Vec<Space>,
    connections: Vec<Connection>,
}

#[derive(Deserialize)]
struct RawNrg {
    spaces: Vec<Space>,
    #[serde(default)]
    connections: Vec<Connection>,
}

impl<'de> Deserialize<'de> for Nrg {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let raw = RawNrg::deserialize(d)?;
        Nrg::new(raw.spaces, raw.connections).map_err(serde::de::Error::custom)
    }
}

/// How far from the origin of the map frame a coordinate may lie, metres
/// (100 000 km: room for projected frames such as UTM or web Mercator, far
/// from where areas and grid cell counts overflow). Issue 21: a coordinate
/// at 1e308 made later imports into the map loop or exhaust memory.
pub const MAX_COORD_M: f64 = 1.0e8;

/// The longest space name a model holds, in characters (issue 21: a
/// 70 000-character name was stored and broke every listing).
pub const MAX_NAME_CHARS: usize = 1_000;

impl Nrg {
    /// Builds a model, checking its invariants and normalising order,
    /// connection direction and areas.
    pub fn new(
        mut spaces: Vec<Space>,
        mut connections: Vec<Connection>,
    ) -> Result<Nrg, ModelError> {
        spaces.sort_by_key(|s| s.id);
        for pair in spaces.windows(2) {
            if pair[0].id == pair[1].id {
                return Err(ModelError::DuplicateSpace(pair[0].id));
            }
        }
        for space in &mut spaces {
            check_space(space)?;
            space.update_area();
            space.update_doorway();
        }
        let ids: HashSet<SpaceId> = spaces.iter().map(|s| s.id).collect();
        let mut seen = HashSet::new();
        for c in &mut connections {
            if c.a == c.b {
                return Err(ModelError::SelfLoop(c.a));
            }
            for end in [c.a, c.b] {
                if !ids.contains(&end) {
                    return Err(ModelError::UnknownSpace {
                        a: c.a,
                        b: c.b,
                        missing: end,
                    });
                }
            }
            if !c.length_m.is_finite() || c.length_m < 0.0 {
                return Err(ModelError::BadLength {
                    a: c.a,
                    b: c.b,
                    length_m: c.length_m,
                });
            }
            let (a, b) = c.key();
            c.a = a;
            c.b = b;
            if !seen.insert((a, b)) {
                return Err(ModelError::DuplicateConnection { a, b });
            }
        }
        connections.sort_by_key(|c| c.key());
        check_levels(&spaces, &connections)?;
        Ok(Nrg {
            spaces,
            connections,
        })
    }

    /// The spaces on level `name` and the connections among them (vertical
    /// ones leave), as a model of its own; None when no space is on it.
    pub fn level_model(&self, name: &str) -> Option<Nrg> {
        self.levels_model(&[name])
    }

    /// The spaces on the levels named and the connections among them (a
    /// vertical connection stays when both its levels are named), as a
    /// model of its own; None when no space is on them.
    pub fn levels_model(&self, names: &[&str]) -> Option<Nrg> {
        let on = |id: SpaceId| {
            self.space(id)
                .and_then(|s| s.level.as_ref())
                .is_some_and(|l| names.contains(&l.name.as_str()))
        };
        let spaces: Vec<Space> = self.spaces.iter().filter(|s| on(s.id)).cloned().collect();
        if spaces.is_empty() {
            return None;
        }
        let connections = self
            .connections
            .iter()
            .filter(|c| on(c.a) && on(c.b))
            .cloned()
            .collect();
        Nrg::new(spaces, connections).ok()
    }

    /// The extent of every space's outline, metres: x min, y min, x max,
    /// y max (all levels together); None without spaces.
    pub fn extent(&self) -> Option<[f64; 4]> {
        super::geometry::bounds(self.spaces.iter().flat_map(|s| &s.polygon))
    }

    /// Whether the spaces have levels (all do or none do, see
    /// [`Nrg::new`]): O(1), for hot paths.
    pub fn has_levels(&self) -> bool {
        self.spaces.first().is_some_and(|s| s.level.is_some())
    }

    /// The levels the spaces are on, lowest first (by elevation, then
    /// name); empty for a model without levels.
    pub fn levels(&self) -> Vec<Level> {
        let mut levels: Vec<Level> = Vec::new();
        for l in self.spaces.iter().filter_map(|s| s.level.as_ref()) {
            if !levels.iter().any(|k| k.name == l.name) {
                levels.push(l.clone());
            }
        }
        levels.sort_by(|a, b| {
            a.elevation_m
                .total_cmp(&b.elevation_m)
                .then_with(|| a.name.cmp(&b.name))
        });
        levels
    }

    /// The spaces, sorted by id.
    pub fn spaces(&self) -> &[Space] {
        &self.spaces
    }

    /// The connections, sorted by `(a, b)` with `a < b`.
    pub fn connections(&self) -> &[Connection] {
        &self.connections
    }

    /// The space with this id.
    pub fn space(&self, id: SpaceId) -> Option<&Space> {
        self.spaces
            .binary_search_by_key(&id, |s| s.id)
            .ok()
            .and_then(|i| self.spaces.get(i))
    }

    /// The connection between two spaces, in either order.
    pub fn connection(&self, a: SpaceId, b: SpaceId) -> Option<&Connection> {
        let key = if a <= b { (a, b) } else { (b, a) };
        self.connections
            .binary_search_by_key(&key, |c| c.key())
            .ok()
            .and_then(|i| self.connections.get(i))
    }

    /// Connections touching `id`.
    pub fn connections_of(&self, id: SpaceId) -> impl Iterator<Item = &Connection> {
        self.connections
            .iter()
            .filter(move |c| c.a == id || c.b == id)
    }

    /// Number of connections per space (all kinds).
    pub fn degrees(&self) -> BTreeMap<SpaceId, usize> {
        let mut deg: BTreeMap<SpaceId, usize> = self.spaces.iter().map(|s| (s.id, 0)).collect();
        for c in &self.connections {
            for end in [c.a, c.b] {
                if let Some(d) = deg.get_mut(&end) {
                    *d += 1;
                }
            }
        }
        deg
    }

    /// The smallest id not used by any space (ids start at 1).
    pub fn next_id(&self) -> SpaceId {
        SpaceId(self.spaces.last().map_or(1, |s| s.id.0.saturating_add(1)))
    }

    /// Takes the model apart.
    pub fn into_parts(self) -> (Vec<Space>, Vec<Connection>) {
        (self.spaces, self.connections)
    }

    /// The public JSON form, pretty-printed.
    pub fn to_json(&self) -> String {
        // Serialising plain data with string keys cannot fail.
        serde_json::to_string_pretty(self).unwrap_or_default()
    }

    /// Reads the public JSON form.
    pub fn from_json(text: &str) -> Result<Nrg, serde_json::Error> {
        serde_json::from_str(text)
    }
}

/// Levels fit together: every space has one or none has; a name has one
/// elevation; a vertical connection joins two levels (usually stairs or a
/// lift, but a file may join a landing to a corridor), every other
/// connection two spaces on one level.
fn check_levels(spaces: &[Space], connections: &[Connection]) -> Result<(), ModelError> {
    let with = spaces.iter().filter(|s| s.level.is_some()).count();
    let vertical = connections
        .iter()
        .find(|c| c.kind == ConnectionKind::Vertical);
    if with == 0 {
        return match vertical {
            Some(c) => Err(ModelError::LevelConnection {
                a: c.a,
                b: c.b,
                why: "a vertical connection joins levels, and the model has none".into(),
            }),
            None => Ok(()),
        };
    }
    if let Some(s) = spaces.iter().find(|s| s.level.is_none()) {
        return Err(ModelError::Levels(format!(
            "space {} has no level while {with} others have one: give every space a level or none",
            s.id
        )));
    }
    let mut elevations: HashMap<&str, f64> = HashMap::new();
    for s in spaces {
        let Some(level) = &s.level else { continue };
        level
            .check()
            .map_err(|source| ModelError::Level { id: s.id, source })?;
        let e = *elevations
            .entry(level.name.as_str())
            .or_insert(level.elevation_m);
        if e.to_bits() != level.elevation_m.to_bits() {
            return Err(ModelError::Levels(format!(
                "level {} has two elevations, {e} m and {} m (space {})",
                level.name, level.elevation_m, s.id
            )));
        }
    }
    let by_id: HashMap<SpaceId, &Space> = spaces.iter().map(|s| (s.id, s)).collect();
    for c in connections {
        let (Some(a), Some(b)) = (by_id.get(&c.a), by_id.get(&c.b)) else {
            continue;
        };
        let same = level_name(a.level.as_ref()) == level_name(b.level.as_ref());
        let why = if c.kind == ConnectionKind::Vertical {
            same.then(|| {
                format!(
                    "a vertical connection joins two levels, and both ends are on level {}",
                    level_name(a.level.as_ref())
                )
            })
        } else if !same {
            Some(format!(
                "a {} connection joins level {} and level {}; only a vertical connection joins levels",
                c.kind,
                level_name(a.level.as_ref()),
                level_name(b.level.as_ref())
            ))
        } else {
            None
        };
        if let Some(why) = why {
            return Err(ModelError::LevelConnection {
                a: c.a,
                b: c.b,
                why,
            });
        }
    }
    Ok(())
}

fn check_space(space: &Space) -> Result<(), ModelError> {
    let finite = |p: &[f64; 2]| p[0].is_finite() && p[1].is_finite();
    let near = |p: &[f64; 2]| p[0].abs() <= MAX_COORD_M && p[1].abs() <= MAX_COORD_M;
    let far = |what: &'static str| ModelError::TooFar {
        id: space.id,
        what,
        limit_m: MAX_COORD_M,
    };
    if !finite(&space.anchor) {
        return Err(ModelError::NotFinite {
            id: space.id,
            what: "anchor",
        });
    }
    for ring in std::iter::once(&space.polygon).chain(&space.holes) {
        if !ring.iter().all(finite) {
            return Err(ModelError::NotFinite {
                id: space.id,
                what: "polygon",
            });
        }
        if !ring.iter().all(near) {
            return Err(far("polygon"));
        }
    }
    if !near(&space.anchor) {
        return Err(far("anchor"));
    }
    if space.polygon.len() < 3 {
        return Err(ModelError::DegeneratePolygon(space.id));
    }
    if let Some(name) = &space.name
        && name.chars().count() > MAX_NAME_CHARS
    {
        return Err(ModelError::NameTooLong {
            id: space.id,
            chars: name.chars().count(),
            limit: MAX_NAME_CHARS,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{ConnectionKind, SpaceKind};

    fn square(id: u32, x: f64) -> Space {
        let poly = vec![[x, 0.0], [x + 1.0, 0.0], [x + 1.0, 1.0], [x, 1.0]];
        Space::new(SpaceId(id), SpaceKind::Room, [x + 0.5, 0.5], poly)
    }

    fn conn(a: u32, b: u32) -> Connection {
        Connection {
            a: SpaceId(a),
            b: SpaceId(b),
            kind: ConnectionKind::Open,
            length_m: 1.0,
        }
    }

    #[test]
    fn normalises_order_and_direction() {
        let nrg = Nrg::new(vec![square(2, 1.0), square(1, 0.0)], vec![conn(2, 1)]).unwrap();
        assert_eq!(nrg.spaces()[0].id, SpaceId(1));
        assert_eq!(nrg.connections()[0].key(), (SpaceId(1), SpaceId(2)));
        assert!(nrg.connection(SpaceId(2), SpaceId(1)).is_some());
    }

    #[test]
    fn rejects_broken_models() {
        assert_eq!(
            Nrg::new(vec![square(1, 0.0), square(1, 1.0)], vec![]),
            Err(ModelError::DuplicateSpace(SpaceId(1)))
        );
        assert!(matches!(
            Nrg::new(vec![square(1, 0.0)], vec![conn(1, 9)]),
            Err(ModelError::UnknownSpace {
                missing: SpaceId(9),
                ..
            })
        ));
        assert_eq!(
            Nrg::new(vec![square(1, 0.0)], vec![conn(1, 1)]),
            Err(ModelError::SelfLoop(SpaceId(1)))
        );
        assert!(matches!(
            Nrg::new(
                vec![square(1, 0.0), square(2, 1.0)],
                vec![conn(1, 2), conn(2, 1)]
            ),
            Err(ModelError::DuplicateConnection { .. })
        ));
    }

    /// Issue 21, defects 3–5: a coordinate at 1e308 was accepted and later
    /// made matching loop, memory grow and geo's hull panic. It is refused
    /// where every model is built, with the space and the limit named.
    #[test]
    fn far_flung_coordinates_are_refused_at_the_door() {
        let mut s = square(7, 0.0);
        s.polygon[2] = [1e308, 1.0];
        let e = Nrg::new(vec![s], vec![]).unwrap_err();
        assert!(matches!(
            e,
            ModelError::TooFar {
                id: SpaceId(7),
                what: "polygon",
                ..
            }
        ));
        assert!(e.to_string().contains("space 7"), "{e}");
        let mut s = square(8, 0.0);
        s.anchor = [0.5, -2e8];
        assert!(matches!(
            Nrg::new(vec![s], vec![]),
            Err(ModelError::TooFar { what: "anchor", .. })
        ));
        let mut named = square(10, 0.0);
        named.name = Some("x".repeat(70_000));
        assert!(matches!(
            Nrg::new(vec![named], vec![]),
            Err(ModelError::NameTooLong { chars: 70_000, .. })
        ));
        let at_limit = square(9, MAX_COORD_M - 1.0);
        assert!(Nrg::new(vec![at_limit], vec![]).is_ok());
        let text = r#"{"spaces":[{"id":1,"kind":"room","anchor":[0,0],"polygon":[[0,0],[1e308,0],[0,1]]}],"connections":[]}"#;
        let err = Nrg::from_json(text).unwrap_err().to_string();
        assert!(err.contains("from the origin"), "{err}");
    }

    #[test]
    fn json_round_trip_keeps_everything() {
        let mut s = square(1, 0.0);
        s.name = Some("Kitchen".into());
        s.attributes.insert("floor".into(), serde_json::json!(2));
        let nrg = Nrg::new(vec![s, square(2, 1.0)], vec![conn(1, 2)]).unwrap();
        let text = nrg.to_json();
        assert!(text.contains("\"area_m2\": 1.0"));
        assert_eq!(Nrg::from_json(&text).unwrap(), nrg);
    }

    #[test]
    fn json_with_unknown_space_is_refused() {
        let text = r#"{"spaces":[],"connections":[{"a":1,"b":2,"kind":"door","length_m":1}]}"#;
        let err = Nrg::from_json(text).unwrap_err().to_string();
        assert!(err.contains("not in the model"), "{err}");
    }

    #[test]
    fn levels_go_through_json_and_must_fit_together() {
        let nrg = crate::fixtures::storeys(2, 2);
        let back = Nrg::from_json(&nrg.to_json()).unwrap();
        assert_eq!(back, nrg);
        let first = &back.spaces()[0];
        assert_eq!(first.level.as_ref().map(|l| l.name.as_str()), Some("0"));
        let (spaces, connections) = nrg.clone().into_parts();
        // One name, two elevations.
        let mut bad = spaces.clone();
        bad[0].level.as_mut().unwrap().elevation_m = 9.0;
        let err = Nrg::new(bad, connections.clone()).unwrap_err().to_string();
        assert!(err.contains("two elevations"), "{err}");
        // A space without a level among leveled ones.
        let mut bad = spaces.clone();
        bad[3].level = None;
        let err = Nrg::new(bad, connections.clone()).unwrap_err().to_string();
        assert!(err.contains("has no level"), "{err}");
        // A door connection across levels.
        let mut bad = connections.clone();
        let v = bad
            .iter_mut()
            .find(|c| c.kind == ConnectionKind::Vertical)
            .unwrap();
        v.kind = ConnectionKind::Door;
        let err = Nrg::new(spaces.clone(), bad).unwrap_err().to_string();
        assert!(
            err.contains("only a vertical connection joins levels"),
            "{err}"
        );
        // A vertical connection within one level.
        let mut bad = connections;
        let c = bad
            .iter_mut()
            .find(|c| c.kind == ConnectionKind::Open)
            .unwrap();
        c.kind = ConnectionKind::Vertical;
        let err = Nrg::new(spaces, bad).unwrap_err().to_string();
        assert!(err.contains("both ends are on level 0"), "{err}");
    }
}
