//! Planning: a [`Statement`] with its references resolved against the
//! current revision, as the operators the executor runs. `EXPLAIN` prints it.

use std::fmt;

use super::ast::{Condition, EditStatement, OrderKey, SpaceRef, Statement, Value, WalkOptions};
use super::error::QueryError;
use super::index::IndexedRevision;
use crate::model::{Point, SpaceId, SpaceKind};
use crate::route::{Endpoint, Profile, RouteRequest};

/// What the executor will do.
#[derive(Debug, Clone, PartialEq)]
pub enum Plan {
    /// A* over the navigation layer per leg, or door-distinct alternatives.
    Route(RouteRequest),
    /// Breadth-first search over navigable connections.
    Neighbours {
        /// Centre.
        of: SpaceId,
        /// Hops.
        depth: u32,
    },
    /// Scan → filter → sort → limit.
    Find {
        /// Kind filter from the target.
        kind: Option<SpaceKind>,
        /// WHERE.
        filter: Option<Condition>,
        /// ORDER BY.
        order: Vec<OrderKey>,
        /// LIMIT.
        limit: Option<u64>,
    },
    /// R*-tree then point-in-polygon.
    Locate(Point, Option<String>),
    /// Distance-bounded Dijkstra over the navigation layer.
    Reachable {
        /// Start.
        from: Endpoint,
        /// Bound in metres walked.
        within_m: f64,
        /// The walker.
        profile: Profile,
    },
    /// List maps.
    ShowMaps,
    /// List revisions of a map.
    ShowRevisions(String),
    /// Select a map and revision (latest when `None`).
    Use(String, Option<u64>),
    /// Rename a space, writing a revision.
    Name(SpaceId, String),
    /// A correction (spaces resolved), writing a revision, and the
    /// statement as written.
    Edit(crate::edit::Edit, String),
    /// Compare two revisions of the selected map (`crate::diff::compare`).
    Diff(u64, u64),
    /// Print the inner plan instead of running it.
    Explain(Box<Plan>),
}

/// Plans `statement`. `current` is the selected revision (needed by
/// statements that read a model); `current_map` names the selected map.
pub fn plan(
    statement: &Statement,
    current: Option<&IndexedRevision>,
    current_map: Option<&str>,
) -> Result<Plan, QueryError> {
    let model = || current.ok_or(QueryError::NoMapSelected);
    Ok(match statement {
        Statement::Route {
            from,
            to,
            via,
            avoid,
            avoid_where,
            alternatives,
            with,
        } => {
            let m = model()?;
            let (from, to) = (endpoint(m, from)?, endpoint(m, to)?);
            let mut avoid: Vec<SpaceId> = avoid
                .iter()
                .map(|r| m.resolve(r))
                .collect::<Result<_, _>>()?;
            if let Some(cond) = avoid_where {
                // The route's own ends are never avoided.
                let ends: Vec<SpaceId> = [&from, &to]
                    .into_iter()
                    .filter_map(Endpoint::space)
                    .collect();
                avoid.extend(super::filter::matching_spaces(cond, m, &ends)?);
            }
            let ends = |refs: &[SpaceRef]| -> Result<Vec<Endpoint>, QueryError> {
                refs.iter().map(|r| endpoint(m, r)).collect()
            };
            Plan::Route(RouteRequest {
                from,
                to,
                via: ends(via)?,
                avoid,
                alternatives: alternatives.unwrap_or(1).max(1) as usize,
                profile: profile(with)?,
            })
        }
        Statement::Neighbours { of, depth } => Plan::Neighbours {
            of: model()?.resolve(of)?,
            depth: depth.unwrap_or(1),
        },
        Statement::Find {
            kind,
            filter,
            order,
            limit,
        } => {
            model()?;
            Plan::Find {
                kind: *kind,
                filter: filter.clone(),
                order: order.clone(),
                limit: *limit,
            }
        }
        Statement::Locate { point, level } => {
            model()?;
            Plan::Locate(*point, level.clone())
        }
        Statement::Reachable {
            from,
            within_m,
            with,
        } => Plan::Reachable {
            from: endpoint(model()?, from)?,
            within_m: *within_m,
            profile: profile(with)?,
        },
        Statement::ShowMaps => Plan::ShowMaps,
        Statement::ShowRevisions { map } => match map.as_deref().or(current_map) {
            Some(m) => Plan::ShowRevisions(m.to_string()),
            None => return Err(QueryError::NoMapSelected),
        },
        Statement::Use { map, revision } => Plan::Use(map.clone(), *revision),
        Statement::Name { space, name } => Plan::Name(model()?.resolve(space)?, name.clone()),
        Statement::Diff { from, to } => Plan::Diff(*from, *to),
        Statement::Edit(e) => Plan::Edit(resolve_edit(model()?, e)?, e.to_string()),
        Statement::Explain(inner) => Plan::Explain(Box::new(plan(inner, current, current_map)?)),
    })
}

/// The edit `e` names, its spaces resolved in `m`.
fn resolve_edit(m: &IndexedRevision, e: &EditStatement) -> Result<crate::edit::Edit, QueryError> {
    use crate::edit::{Edit, NewDoor};
    Ok(match e {
        EditStatement::Merge { spaces, name } => Edit::Merge {
            spaces: spaces
                .iter()
                .map(|r| m.resolve(r))
                .collect::<Result<_, _>>()?,
            name: name.clone(),
        },
        EditStatement::Split { space, line, door } => Edit::Split {
            space: m.resolve(space)?,
            line: *line,
            door: door.map(|(at, width_m)| NewDoor { at, width_m }),
        },
        EditStatement::AddDoor { a, b, at, width } => Edit::AddDoor {
            a: m.resolve(a)?,
            b: m.resolve(b)?,
            at: *at,
            width_m: *width,
        },
        EditStatement::RemoveDoor(d) => Edit::RemoveDoor {
            door: m.resolve(d)?,
        },
        EditStatement::SetKind(s, kind) => Edit::SetKind {
            space: m.resolve(s)?,
            kind: *kind,
        },
        EditStatement::SetAttribute(s, key, value) => Edit::SetAttribute {
            space: m.resolve(s)?,
            key: key.clone(),
            value: match value {
                Value::Number(x) => serde_json::Number::from_f64(*x)
                    .map_or(serde_json::Value::Null, serde_json::Value::Number),
                Value::Text(t) => serde_json::Value::String(t.clone()),
                Value::Bool(b) => serde_json::Value::Bool(*b),
                Value::Null => serde_json::Value::Null,
            },
        },
        EditStatement::UnsetAttribute(s, key) => Edit::UnsetAttribute {
            space: m.resolve(s)?,
            key: key.clone(),
        },
    })
}

/// A route end: a point stays a point (checked to lie in a space, with
/// the nearest space named otherwise); anything else is a space.
fn endpoint(m: &IndexedRevision, r: &SpaceRef) -> Result<Endpoint, QueryError> {
    match r {
        SpaceRef::Point(p) => {
            m.nav
                .locate(*p)
                .ok_or_else(|| QueryError::Route(m.outside(*p)))?;
            Ok(Endpoint::Point(*p))
        }
        SpaceRef::PointOn { at, level } => m.point_on(*at, level),
        other => Ok(Endpoint::Space(m.resolve(other)?)),
    }
}

/// The walker of `WITH …` over the default profile.
fn profile(with: &WalkOptions) -> Result<Profile, QueryError> {
    let d = Profile::default();
    let p = Profile {
        clearance_m: with.clearance_m.unwrap_or(d.clearance_m),
        min_door_width_m: with.min_door_width_m.unwrap_or(d.min_door_width_m),
        speed_m_s: with.speed_m_s.unwrap_or(d.speed_m_s),
        no_stairs: with.no_stairs,
        no_elevator: with.no_elevator,
    };
    p.validate().map_err(QueryError::Route)?;
    Ok(p)
}

fn endpoints(list: &[Endpoint]) -> String {
    let v: Vec<String> = list.iter().map(endpoint_text).collect();
    v.join(", ")
}

fn endpoint_text(e: &Endpoint) -> String {
    match e {
        Endpoint::Space(id) => id.to_string(),
        Endpoint::Point(p) => format!("({}, {})", p[0], p[1]),
        Endpoint::PointIn(p, id) => format!("({}, {}) in {id}", p[0], p[1]),
    }
}

fn ids(list: &[SpaceId]) -> String {
    let v: Vec<String> = list.iter().map(ToString::to_string).collect();
    v.join(", ")
}

impl fmt::Display for Plan {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Plan::Route(r) => {
                let (from, to) = (endpoint_text(&r.from), endpoint_text(&r.to));
                if r.alternatives > 1 {
                    writeln!(
                        f,
                        "DoorDistinct k={} routes {from} -> {to} (Yen over doors)",
                        r.alternatives
                    )?;
                } else {
                    writeln!(
                        f,
                        "AStar {} {from} -> {to}",
                        crate::wording::count(r.via.len() + 1, "leg", "legs")
                    )?;
                }
                if !r.via.is_empty() {
                    writeln!(f, "  via [{}]", endpoints(&r.via))?;
                }
                if !r.avoid.is_empty() {
                    writeln!(f, "  avoid [{}]", ids(&r.avoid))?;
                }
                writeln!(
                    f,
                    "  over gates of the navigation layer (clearance {} m, min door width {} m)",
                    r.profile.clearance_m, r.profile.min_door_width_m
                )?;
                write!(f, "  Funnel through the triangle channel (walked metres)")
            }
            Plan::Neighbours { of, depth } => {
                write!(
                    f,
                    "BreadthFirst from {of} depth {depth} over navigable connections"
                )
            }
            Plan::Find {
                kind,
                filter,
                order,
                limit,
            } => {
                let mut lines = Vec::new();
                if let Some(n) = limit {
                    lines.push(format!("Limit {n}"));
                }
                if !order.is_empty() {
                    let keys: Vec<String> = order
                        .iter()
                        .map(|k| format!("{}{}", k.field, if k.descending { " DESC" } else { "" }))
                        .collect();
                    lines.push(format!("Sort {}", keys.join(", ")));
                }
                if let Some(c) = filter {
                    lines.push(format!("Filter {c}"));
                }
                lines.push(match kind {
                    Some(k) => format!("Scan spaces kind = {k}"),
                    None => "Scan spaces".to_string(),
                });
                for (depth, line) in lines.iter().enumerate() {
                    if depth > 0 {
                        writeln!(f)?;
                    }
                    write!(f, "{}{line}", "  ".repeat(depth))?;
                }
                Ok(())
            }
            Plan::Locate(p, level) => write!(
                f,
                "RTreeEnvelopes at ({}, {})\n  PointInPolygon, smallest area wins{}",
                p[0],
                p[1],
                match level {
                    Some(l) => format!(" on level {l}"),
                    None => " on each level".to_string(),
                }
            ),
            Plan::Reachable {
                from,
                within_m,
                profile,
            } => write!(
                f,
                "BoundedDijkstra over gates from {} within {within_m} m walked (clearance {} m)",
                endpoint_text(from),
                profile.clearance_m
            ),
            Plan::ShowMaps => write!(f, "SourceMaps"),
            Plan::ShowRevisions(m) => write!(f, "SourceRevisions of '{m}'"),
            Plan::Use(m, r) => match r {
                Some(r) => write!(f, "Select map '{m}' revision {r}"),
                None => write!(f, "Select map '{m}' latest revision"),
            },
            Plan::Name(id, name) => write!(f, "RenameSpace {id} to '{name}' (new revision)"),
            Plan::Edit(_, statement) => write!(
                f,
                "Correct: {statement}\n  ApplyAndCheck (the checks of `nrgdb check`)\n  CommitRevision with the correction kept as a rule"
            ),
            Plan::Diff(a, b) => write!(
                f,
                "Diff revision {a} -> {b}\n  AlignIfFramesDiffer (walls of the stored grids, else of the space polygons)\n  \
                 MatchSpaces IoU, Kuhn-Munkres; split/merge by overlap shares"
            ),
            Plan::Explain(inner) => write!(f, "Explain\n  {inner}"),
        }
    }
}
