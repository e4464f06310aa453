//! Execution of the plans that read one revision: ROUTE, NEIGHBOURS, FIND,
//! LOCATE and REACHABLE, within the time and size bounds of [`Limits`].

use std::collections::VecDeque;
use std::time::{Duration, Instant};

use super::error::QueryError;
use super::filter::{field_value, matches, order_values};
use super::index::IndexedRevision;
use super::plan::Plan;
use super::result::{Cell, QueryResult, Table};
use crate::model::{Doorway, Space, SpaceId, SpaceKind, doorway};
use crate::route::{Budget, RouteError, no_route_reason, reachable_within, shortest_route};

/// Bounds on the work of statements: wall-clock time per statement, a
/// deadline for all of them, and rows returned.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limits {
    /// Time bound per statement (default 5 s).
    pub timeout: Duration,
    /// Most rows (or routes) a statement may return (default 10 000).
    pub max_rows: usize,
    /// Most rows all statements of one [`execute`](super::Session::execute)
    /// may return together (default 100 000): a request of 1 000
    /// statements of 10 000 rows each would otherwise hold 10 M rows
    /// (issue 21). Statements after the bound is reached fail without
    /// running.
    pub max_total_rows: usize,
    /// When all work stops (default none): statements not yet started
    /// fail with [`QueryError::Timeout`] without running, and running ones
    /// stop at their next check (a server request's deadline; issue 21,
    /// defect 7: a request kept computing 24 s past its 503).
    pub deadline: Option<Instant>,
}

impl Default for Limits {
    fn default() -> Limits {
        Limits {
            timeout: Duration::from_secs(5),
            max_rows: 10_000,
            max_total_rows: 100_000,
            deadline: None,
        }
    }
}

impl Limits {
    /// Whether the deadline has passed.
    pub fn past_deadline(&self) -> bool {
        self.deadline.is_some_and(|d| Instant::now() >= d)
    }

    /// When a statement starting now must stop: its own time bound or the
    /// deadline, whichever comes first.
    pub fn statement_deadline(&self) -> Option<Instant> {
        Budget::stop_at(self.timeout, self.deadline)
    }

    /// The time-bound error of these limits.
    pub fn timeout_error(&self) -> QueryError {
        QueryError::Timeout(self.timeout.as_millis())
    }
}

fn space_cells(s: &Space) -> Vec<Cell> {
    vec![
        Cell::Int(s.id.0.into()),
        Cell::Text(s.kind.to_string()),
        s.name.clone().map_or(Cell::Null, Cell::Text),
    ]
}

/// A doorway line as text: `(x1, y1)-(x2, y2)`, metres with 2 decimals.
fn line_text(d: &Doorway) -> String {
    let [a, b] = d.line;
    format!("({:.2}, {:.2})-({:.2}, {:.2})", a[0], a[1], b[0], b[1])
}

fn columns(names: &[&str]) -> Vec<String> {
    names.iter().map(|s| (*s).to_string()).collect()
}

fn timeout(budget: &Budget) -> QueryError {
    QueryError::Timeout(budget.limit_ms())
}

fn bounded(result: QueryResult, limits: &Limits) -> Result<QueryResult, QueryError> {
    if result.row_count() > limits.max_rows {
        return Err(QueryError::TooManyRows(limits.max_rows));
    }
    Ok(result)
}

/// Runs a plan that reads `rev`. Session-level plans (SHOW, USE, NAME,
/// DIFF, EXPLAIN) are handled by [`super::Session`]; given here they yield
/// a message saying so.
pub fn execute(
    plan: &Plan,
    rev: &IndexedRevision,
    limits: &Limits,
) -> Result<QueryResult, QueryError> {
    let budget = Budget::within(limits.timeout, limits.deadline);
    let result = match plan {
        Plan::Route(request) => {
            let routes = shortest_route(&rev.nav, request, &budget).map_err(|e| match e {
                RouteError::Timeout(ms) => QueryError::Timeout(ms),
                other => QueryError::Route(other),
            })?;
            if routes.is_empty() {
                QueryResult::Message(no_route_reason(&rev.nav, request))
            } else {
                QueryResult::Routes(routes)
            }
        }
        Plan::Neighbours { of, depth } => neighbours(rev, *of, *depth, &budget)?,
        Plan::Find {
            kind,
            filter,
            order,
            limit,
        } => {
            let mut found: Vec<&Space> = Vec::new();
            for s in rev
                .nrg
                .spaces()
                .iter()
                .filter(|s| kind.is_none_or(|k| s.kind == k))
            {
                if budget.check() {
                    return Err(timeout(&budget));
                }
                if filter.as_ref().map_or(Ok(true), |c| matches(c, s, rev))? {
                    found.push(s);
                }
            }
            if !order.is_empty() {
                found.sort_by(|a, b| {
                    order
                        .iter()
                        .map(|k| {
                            let o = order_values(
                                &field_value(&k.field, a, rev),
                                &field_value(&k.field, b, rev),
                            );
                            if k.descending { o.reverse() } else { o }
                        })
                        .find(|o| o.is_ne())
                        .unwrap_or(std::cmp::Ordering::Equal)
                });
            }
            if let Some(n) = limit {
                found.truncate(usize::try_from(*n).unwrap_or(usize::MAX));
            }
            let doors = *kind == Some(SpaceKind::Door);
            let mut names = vec!["id", "kind", "name", "area_m2", "degree"];
            if doors {
                names.extend(["width_m", "doorway"]);
            }
            let rows = found
                .into_iter()
                .map(|s| {
                    let mut row = space_cells(s);
                    row.push(Cell::Float(s.area_m2));
                    row.push(Cell::Int(rev.graph.degree(s.id) as i64));
                    if doors {
                        let d = doorway(s);
                        row.push(d.map_or(Cell::Null, |d| Cell::Float(d.width_m)));
                        row.push(d.map_or(Cell::Null, |d| Cell::Text(line_text(&d))));
                    }
                    row
                })
                .collect();
            QueryResult::Table(Table {
                columns: columns(&names),
                rows,
            })
        }
        Plan::Locate(p, level) => {
            let leveled = rev.nrg.has_levels();
            let rows = rev
                .locate_on(*p, level.as_deref())
                .into_iter()
                .map(|s| {
                    let mut row = space_cells(s);
                    row.push(Cell::Float(s.area_m2));
                    if leveled {
                        row.push(Cell::Text(
                            s.level.as_ref().map_or(String::new(), |l| l.name.clone()),
                        ));
                    }
                    row
                })
                .collect();
            let names: &[&str] = if leveled {
                &["id", "kind", "name", "area_m2", "level"]
            } else {
                &["id", "kind", "name", "area_m2"]
            };
            QueryResult::Table(Table {
                columns: columns(names),
                rows,
            })
        }
        Plan::Reachable {
            from,
            within_m,
            profile,
        } => {
            let reach = reachable_within(&rev.nav, from, *within_m, profile, &budget).map_err(
                |e| match e {
                    RouteError::Timeout(ms) => QueryError::Timeout(ms),
                    other => QueryError::Route(other),
                },
            )?;
            let rows = reach
                .into_iter()
                .filter_map(|(id, d)| rev.nrg.space(id).map(|s| (s, d)))
                .map(|(s, d)| {
                    let mut row = space_cells(s);
                    row.push(Cell::Float(d));
                    row
                })
                .collect();
            QueryResult::Table(Table {
                columns: columns(&["id", "kind", "name", "distance_m"]),
                rows,
            })
        }
        other => QueryResult::Message(format!("{other} is run by the session")),
    };
    bounded(result, limits)
}

/// Spaces within `depth` hops of `of` (breadth first), without `of` itself,
/// with their hop count and, for doors, their width.
fn neighbours(
    rev: &IndexedRevision,
    of: SpaceId,
    depth: u32,
    budget: &Budget,
) -> Result<QueryResult, QueryError> {
    let start = rev.graph.node(of).ok_or(RouteError::NotNavigable(of))?;
    let mut seen = vec![u32::MAX; rev.graph.len()];
    seen[start as usize] = 0;
    let mut queue = VecDeque::from([start]);
    let mut found = Vec::new();
    while let Some(n) = queue.pop_front() {
        if budget.check() {
            return Err(timeout(budget));
        }
        let d = seen[n as usize];
        if d >= depth {
            continue;
        }
        for &(m, _) in rev.graph.edges(n) {
            if seen[m as usize] == u32::MAX {
                seen[m as usize] = d + 1;
                found.push((d + 1, rev.graph.space(m)));
                queue.push_back(m);
            }
        }
    }
    found.sort();
    let rows = found
        .into_iter()
        .filter_map(|(d, id)| rev.nrg.space(id).map(|s| (d, s)))
        .map(|(d, s)| {
            let mut row = space_cells(s);
            row.push(Cell::Int(d.into()));
            row.push(doorway(s).map_or(Cell::Null, |d| Cell::Float(d.width_m)));
            row
        })
        .collect();
    Ok(QueryResult::Table(Table {
        columns: columns(&["id", "kind", "name", "depth", "width_m"]),
        rows,
    }))
}
