//! A query session: a [`Source`], the selected map revision (indexed) and
//! limits. Text in, results or rendered text out; the REPL, the CLI and the
//! golden tests all drive this.

use super::ast::Statement;
use super::compare_revisions::compare_revisions;
use super::error::QueryError;
use super::exec::{Limits, execute};
use super::index::IndexedRevision;
use super::parser::parse;
use super::plan::{Plan, plan};
use super::result::{Cell, Format, QueryResult, Table};
use super::source::Source;
use crate::diff::{ChangeSet, DiffOptions};

/// A session over a source.
///
/// ```
/// use nrgdb::query::{Format, MemorySource, Session, demo};
/// let mut source = MemorySource::new();
/// source.insert("demo", demo::building(3));
/// let mut session = Session::with_default_map(source).unwrap();
/// let text = session.run("ROUTE FROM \"Kitchen\" TO \"Library\";", Format::Table).unwrap();
/// assert!(text.starts_with("route 1: "));
/// ```
pub struct Session<S: Source> {
    source: S,
    current: Option<std::sync::Arc<IndexedRevision>>,
    limits: Limits,
    /// Who the corrections this session writes are recorded as made by.
    author: String,
}

impl<S: Source> Session<S> {
    /// A session with no map selected and default limits.
    pub fn new(source: S) -> Session<S> {
        Session {
            source,
            current: None,
            limits: Limits::default(),
            author: "nrgdb query".to_string(),
        }
    }

    /// Records the corrections this session writes as made by `author`
    /// (default "nrgdb query").
    pub fn set_author(&mut self, author: impl Into<String>) {
        self.author = author.into();
    }

    /// A session on the latest revision of the first map (by name), if any.
    pub fn with_default_map(source: S) -> Result<Session<S>, QueryError> {
        let mut session = Session::new(source);
        session.use_default_map()?;
        Ok(session)
    }

    /// Selects the latest revision of the first map (by name), if any.
    pub fn use_default_map(&mut self) -> Result<(), QueryError> {
        if let Some(first) = self.source.maps()?.into_iter().next() {
            self.use_map(&first.name, None)?;
        }
        Ok(())
    }

    /// Replaces the limits.
    pub fn set_limits(&mut self, limits: Limits) {
        self.limits = limits;
    }

    /// The limits in force.
    pub fn limits(&self) -> Limits {
        self.limits
    }

    /// The source.
    pub fn source(&self) -> &S {
        &self.source
    }

    /// The selected revision, indexed.
    pub fn current(&self) -> Option<&IndexedRevision> {
        self.current.as_deref()
    }

    /// Selects `map` at `revision` (latest when `None`); returns a message.
    pub fn use_map(&mut self, map: &str, revision: Option<u64>) -> Result<String, QueryError> {
        if self.limits.past_deadline() {
            return Err(self.limits.timeout_error());
        }
        let revision = match revision {
            Some(r) => r,
            None => self.source.revisions(map)?.last().map_or(1, |r| r.revision),
        };
        let rev = self.source.indexed(map, revision)?;
        let message = format!(
            "using map '{map}' at revision {revision} ({}, {})",
            crate::wording::count(rev.nrg.spaces().len(), "space", "spaces"),
            crate::wording::count(rev.nrg.connections().len(), "connection", "connections")
        );
        self.current = Some(rev);
        Ok(message)
    }

    /// Plans a statement against the selected revision.
    pub fn plan(&self, statement: &Statement) -> Result<Plan, QueryError> {
        plan(
            statement,
            self.current.as_deref(),
            self.current.as_deref().map(|c| c.map.as_str()),
        )
    }

    /// Plans and runs one statement; past the deadline of the limits it
    /// fails with [`QueryError::Timeout`] without doing any work.
    pub fn execute_statement(&mut self, statement: &Statement) -> Result<QueryResult, QueryError> {
        if self.limits.past_deadline() {
            return Err(self.limits.timeout_error());
        }
        let planned = self.plan(statement)?;
        self.execute_plan(&planned)
    }

    fn execute_plan(&mut self, planned: &Plan) -> Result<QueryResult, QueryError> {
        match planned {
            Plan::Explain(inner) => Ok(QueryResult::Plan(inner.to_string())),
            Plan::ShowMaps => {
                let rows = self
                    .source
                    .maps()?
                    .into_iter()
                    .map(|m| {
                        vec![
                            Cell::Text(m.name),
                            Cell::Int(m.revisions as i64),
                            Cell::Int(m.latest as i64),
                        ]
                    })
                    .collect();
                Ok(table(&["map", "revisions", "latest"], rows))
            }
            Plan::ShowRevisions(map) => {
                let rows = self
                    .source
                    .revisions(map)?
                    .into_iter()
                    .map(|r| {
                        vec![
                            Cell::Int(r.revision as i64),
                            Cell::Int(r.spaces as i64),
                            Cell::Int(r.connections as i64),
                            Cell::Text(r.note),
                        ]
                    })
                    .collect();
                Ok(table(&["revision", "spaces", "connections", "note"], rows))
            }
            Plan::Use(map, revision) => Ok(QueryResult::Message(self.use_map(map, *revision)?)),
            Plan::Name(id, name) => {
                let current = self.current.as_ref().ok_or(QueryError::NoMapSelected)?;
                let (map, old) = (current.map.clone(), current.revision);
                let revision = self.source.rename_space(&map, old, *id, name)?;
                self.use_map(&map, Some(revision))?;
                Ok(QueryResult::Message(format!(
                    "named space {id} '{name}' in map '{map}': revision {revision} (was {old})"
                )))
            }
            Plan::Edit(edit, statement) => {
                let current = self.current.as_ref().ok_or(QueryError::NoMapSelected)?;
                let (map, old) = (current.map.clone(), current.revision);
                let before = std::sync::Arc::clone(&current.nrg);
                let done = self.source.edit(&map, old, edit, statement, &self.author)?;
                self.use_map(&map, Some(done.revision))?;
                let what = edit.describe(&before);
                let kept = done.correction.map_or_else(String::new, |c| {
                    format!("; kept as correction {c}, re-applied at every import")
                });
                let made = if done.created.is_empty() {
                    String::new()
                } else {
                    let ids: Vec<String> = done.created.iter().map(ToString::to_string).collect();
                    format!("; new space {}", ids.join(", "))
                };
                Ok(QueryResult::Message(format!(
                    "{what} in map '{map}': revision {} (was {old}){made}{kept}",
                    done.revision
                )))
            }
            Plan::Diff(from, to) => {
                let current = self.current.as_ref().ok_or(QueryError::NoMapSelected)?;
                let map = current.map.clone();
                let options = DiffOptions {
                    deadline: self.limits.statement_deadline(),
                    ..DiffOptions::default()
                };
                let done = compare_revisions(&self.source, &map, *from, *to, &options).map_err(
                    |e| match e {
                        QueryError::Diff(crate::diff::DiffError::TimedOut) => {
                            self.limits.timeout_error()
                        }
                        other => other,
                    },
                )?;
                Ok(diff_result(&done.comparison.changes))
            }
            data => {
                let current = self.current.as_ref().ok_or(QueryError::NoMapSelected)?;
                execute(data, current, &self.limits)
            }
        }
    }

    /// Parses `text` and runs each statement in order. A syntax error fails
    /// the whole text (nothing runs); a statement's own error is kept in
    /// its slot and the following statements still run. Once the deadline
    /// of the limits has passed, the remaining slots hold
    /// [`QueryError::Timeout`] and nothing more runs.
    pub fn execute(
        &mut self,
        text: &str,
    ) -> Result<Vec<Result<QueryResult, QueryError>>, QueryError> {
        let statements = parse(text)?;
        let mut total = 0usize;
        Ok(statements
            .iter()
            .map(|s| {
                if total >= self.limits.max_total_rows {
                    return Err(QueryError::TooManyRowsInAll(total));
                }
                let result = self.execute_statement(s);
                if let Ok(r) = &result {
                    total = total.saturating_add(r.row_count());
                }
                result
            })
            .collect())
    }

    /// Line in, text out: runs `text` and renders every result in
    /// `format`, a statement's error as `error: …`. Syntax errors are
    /// returned so the caller can point at the token.
    pub fn run(&mut self, text: &str, format: Format) -> Result<String, QueryError> {
        let mut out = String::new();
        for result in self.execute(text)? {
            match result {
                Ok(r) => out.push_str(&r.render(format)),
                Err(e) => out.push_str(&format!("error: {e}\n")),
            }
        }
        Ok(out)
    }
}

/// `DIFF A B`: one row per reported change of `changes` (see
/// `ChangeSet::rows`), and a first row giving the alignment when the
/// frames differed.
fn diff_result(changes: &ChangeSet) -> QueryResult {
    let mut rows = Vec::new();
    if let Some(t) = changes.alignment {
        rows.push(vec![
            Cell::Text("aligned".into()),
            Cell::Null,
            Cell::Null,
            Cell::Null,
            Cell::Text(format!(
                "rotation {:.2}°, translation ({:.3}, {:.3}) m",
                t.rotation_deg(),
                t.tx_m,
                t.ty_m
            )),
        ]);
    }
    let all = changes.rows();
    // A level column in a building with levels.
    let leveled = all.iter().any(|r| !r.level.is_empty());
    for r in all {
        let mut row = vec![
            Cell::Text(r.change),
            Cell::Text(r.old),
            Cell::Text(r.new),
            Cell::Text(r.space),
            Cell::Text(r.detail),
        ];
        if leveled {
            row.push(Cell::Text(r.level));
        }
        rows.push(row);
    }
    if leveled {
        for row in rows.iter_mut().filter(|r| r.len() == 5) {
            row.push(Cell::Null);
        }
        return table(&["change", "old", "new", "space", "detail", "level"], rows);
    }
    table(&["change", "old", "new", "space", "detail"], rows)
}

fn table(names: &[&str], rows: Vec<Vec<Cell>>) -> QueryResult {
    QueryResult::Table(Table {
        columns: names.iter().map(|s| (*s).to_string()).collect(),
        rows,
    })
}

#[cfg(test)]
mod tests {
    use std::cell::Cell as Counter;
    use std::time::{Duration, Instant};

    use super::*;
    use crate::grid::OccupancyGrid;
    use crate::model::{Nrg, SpaceId};
    use crate::query::{Limits, MapInfo, MemorySource, RevisionInfo, SourceError, demo};

    /// A source counting every call that reaches it.
    struct Counting {
        inner: MemorySource,
        calls: Counter<usize>,
    }

    impl Counting {
        fn tick(&self) {
            self.calls.set(self.calls.get() + 1);
        }
    }

    impl Source for Counting {
        fn maps(&self) -> Result<Vec<MapInfo>, SourceError> {
            self.tick();
            self.inner.maps()
        }
        fn revisions(&self, map: &str) -> Result<Vec<RevisionInfo>, SourceError> {
            self.tick();
            self.inner.revisions(map)
        }
        fn load(&self, map: &str, revision: u64) -> Result<Nrg, SourceError> {
            self.tick();
            self.inner.load(map, revision)
        }
        fn grid(&self, map: &str, revision: u64) -> Result<Option<OccupancyGrid>, SourceError> {
            self.tick();
            self.inner.grid(map, revision)
        }
        fn rename_space(
            &mut self,
            map: &str,
            revision: u64,
            id: SpaceId,
            name: &str,
        ) -> Result<u64, SourceError> {
            self.tick();
            self.inner.rename_space(map, revision, id, name)
        }
        fn edit(
            &mut self,
            map: &str,
            revision: u64,
            edit: &crate::edit::Edit,
            statement: &str,
            author: &str,
        ) -> Result<crate::query::EditDone, SourceError> {
            self.tick();
            self.inner.edit(map, revision, edit, statement, author)
        }
    }

    fn session(segments: usize) -> Session<Counting> {
        let mut inner = MemorySource::new();
        inner.insert("demo", demo::building(segments));
        let source = Counting {
            inner,
            calls: Counter::new(0),
        };
        Session::with_default_map(source).unwrap()
    }

    /// Issue 21, defect 7: a request of many statements kept computing
    /// long after its deadline. Once the deadline has passed no statement
    /// starts: every slot is a time-out and the source is never asked.
    #[test]
    fn issue_21_defect_7_no_statement_starts_after_the_deadline() {
        let mut s = session(3);
        s.set_limits(Limits {
            deadline: Some(Instant::now()),
            ..Limits::default()
        });
        let before = s.source().calls.get();
        let text = "SHOW MAPS; USE demo; DIFF 1 1; NAME 3 AS \"x\"; FIND rooms; ROUTE FROM 3 TO 5;";
        let results = s.execute(text).unwrap();
        assert_eq!(results.len(), 6);
        for r in results {
            assert!(matches!(r, Err(QueryError::Timeout(5000))), "{r:?}");
        }
        assert_eq!(s.source().calls.get(), before);
        assert!(s.use_map("demo", None).is_err());
    }

    /// Issue 21, defect 7: a statement running when the deadline passes
    /// stops at its next check, even when its own bound is far away (FIND
    /// over thousands of spaces, a walk over the whole building).
    /// Issue 21: a request of many big statements is bounded in all, not
    /// only per statement; the statements after the bound do not run.
    #[test]
    fn issue_21_rows_are_bounded_per_request() {
        let mut s = session(1_000);
        s.set_limits(Limits {
            max_rows: 10_000,
            max_total_rows: 12_000,
            ..Limits::default()
        });
        let results = s.execute(&"FIND spaces;".repeat(6)).unwrap();
        let rows: Vec<usize> = results
            .iter()
            .map(|r| r.as_ref().map_or(0, QueryResult::row_count))
            .collect();
        let one = rows[0];
        assert!(
            (4_000..6_000).contains(&one),
            "{one} spaces: {:?}",
            results[0]
        );
        // 3 × one ≥ 12 000: the fourth statement and the rest fail unrun.
        assert_eq!(rows[..3], [one, one, one]);
        for r in &results[3..] {
            assert!(
                matches!(r, Err(QueryError::TooManyRowsInAll(n)) if *n == 3 * one),
                "{r:?}"
            );
        }
    }

    #[test]
    fn issue_21_defect_7_running_statements_stop_at_the_deadline() {
        let mut s = session(2_000);
        let mut limits = Limits {
            timeout: Duration::from_secs(3_600),
            max_rows: usize::MAX,
            max_total_rows: usize::MAX,
            deadline: None,
        };
        s.set_limits(limits);
        assert!(
            s.execute_statement(&parse("FIND spaces").unwrap()[0])
                .is_ok()
        );
        limits.deadline = Some(Instant::now());
        s.set_limits(limits);
        for text in [
            "FIND spaces",
            "REACHABLE FROM 3 WITHIN 100000",
            "NEIGHBOURS OF 3 DEPTH 100000",
        ] {
            let statement = parse(text).unwrap().remove(0);
            let planned = s.plan(&statement).unwrap();
            let current = s.current().unwrap();
            let e = super::super::exec::execute(&planned, current, &limits).unwrap_err();
            assert!(matches!(e, QueryError::Timeout(3_600_000)), "{text}: {e}");
        }
    }
}
