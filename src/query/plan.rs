//! Planning: a [`Statement`] with its references resolved against the
//! current revision, as the operators the executor runs. `EXPLAIN` prints it.

use std::fmt;

use super::ast::{Condition, OrderKey, Statement};
use super::error::QueryError;
use super::index::IndexedRevision;
use crate::model::{Point, SpaceId, SpaceKind};
use crate::route::RouteRequest;

/// What the executor will do.
#[derive(Debug, Clone, PartialEq)]
pub enum Plan {
    /// Dijkstra per leg, or Yen for alternatives.
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
    Locate(Point),
    /// Distance-bounded Dijkstra.
    Reachable {
        /// Start.
        from: SpaceId,
        /// Bound in metres.
        within_m: f64,
    },
    /// List maps.
    ShowMaps,
    /// List revisions of a map.
    ShowRevisions(String),
    /// Select a map and revision (latest when `None`).
    Use(String, Option<u64>),
    /// Rename a space, writing a revision.
    Name(SpaceId, String),
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
            alternatives,
        } => {
            let m = model()?;
            let resolve = |refs: &[super::ast::SpaceRef]| -> Result<Vec<SpaceId>, QueryError> {
                refs.iter().map(|r| m.resolve(r)).collect()
            };
            Plan::Route(RouteRequest {
                from: m.resolve(from)?,
                to: m.resolve(to)?,
                via: resolve(via)?,
                avoid: resolve(avoid)?,
                alternatives: alternatives.unwrap_or(1).max(1) as usize,
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
        Statement::Locate { point } => {
            model()?;
            Plan::Locate(*point)
        }
        Statement::Reachable { from, within_m } => Plan::Reachable {
            from: model()?.resolve(from)?,
            within_m: *within_m,
        },
        Statement::ShowMaps => Plan::ShowMaps,
        Statement::ShowRevisions { map } => match map.as_deref().or(current_map) {
            Some(m) => Plan::ShowRevisions(m.to_string()),
            None => return Err(QueryError::NoMapSelected),
        },
        Statement::Use { map, revision } => Plan::Use(map.clone(), *revision),
        Statement::Name { space, name } => Plan::Name(model()?.resolve(space)?, name.clone()),
        Statement::Diff { from, to } => Plan::Diff(*from, *to),
        Statement::Explain(inner) => Plan::Explain(Box::new(plan(inner, current, current_map)?)),
    })
}

fn ids(list: &[SpaceId]) -> String {
    let v: Vec<String> = list.iter().map(ToString::to_string).collect();
    v.join(", ")
}

impl fmt::Display for Plan {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Plan::Route(r) => {
                if r.alternatives > 1 {
                    writeln!(
                        f,
                        "Yen k={} loopless routes {} -> {}",
                        r.alternatives, r.from, r.to
                    )?;
                } else {
                    writeln!(
                        f,
                        "Dijkstra {} leg(s) {} -> {}",
                        r.via.len() + 1,
                        r.from,
                        r.to
                    )?;
                }
                if !r.via.is_empty() {
                    writeln!(f, "  via [{}]", ids(&r.via))?;
                }
                if !r.avoid.is_empty() {
                    writeln!(f, "  avoid [{}]", ids(&r.avoid))?;
                }
                write!(f, "  over navigable graph (lengths in metres)")
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
            Plan::Locate(p) => write!(
                f,
                "RTreeEnvelopes at ({}, {})\n  PointInPolygon, smallest area wins",
                p[0], p[1]
            ),
            Plan::Reachable { from, within_m } => {
                write!(f, "BoundedDijkstra from {from} within {within_m} m")
            }
            Plan::ShowMaps => write!(f, "SourceMaps"),
            Plan::ShowRevisions(m) => write!(f, "SourceRevisions of '{m}'"),
            Plan::Use(m, r) => match r {
                Some(r) => write!(f, "Select map '{m}' revision {r}"),
                None => write!(f, "Select map '{m}' latest revision"),
            },
            Plan::Name(id, name) => write!(f, "RenameSpace {id} to '{name}' (new revision)"),
            Plan::Diff(a, b) => write!(
                f,
                "Diff revision {a} -> {b}\n  AlignIfFramesDiffer (walls of the space polygons)\n  \
                 MatchSpaces IoU, Kuhn-Munkres; split/merge by overlap shares"
            ),
            Plan::Explain(inner) => write!(f, "Explain\n  {inner}"),
        }
    }
}
