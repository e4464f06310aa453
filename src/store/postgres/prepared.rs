//! Statements prepared once per connection: the client otherwise prepares
//! every query anew, a round trip of its own before each execution.

use std::collections::HashMap;

use postgres::types::ToSql;
use postgres::{GenericClient, Row, Statement};

use super::fault::R;

/// A connection's prepared statements, by their SQL.
#[derive(Default)]
pub(super) struct Prepared(HashMap<String, Statement>);

impl Prepared {
    fn get(&mut self, c: &mut impl GenericClient, sql: &str) -> R<Statement> {
        if let Some(s) = self.0.get(sql) {
            return Ok(s.clone());
        }
        let s = c.prepare(sql)?;
        self.0.insert(sql.to_string(), s.clone());
        Ok(s)
    }

    /// The rows of `sql`.
    pub(super) fn query(
        &mut self,
        c: &mut impl GenericClient,
        sql: &str,
        params: &[&(dyn ToSql + Sync)],
    ) -> R<Vec<Row>> {
        let s = self.get(c, sql)?;
        Ok(c.query(&s, params)?)
    }

    /// The one row of `sql`.
    pub(super) fn query_one(
        &mut self,
        c: &mut impl GenericClient,
        sql: &str,
        params: &[&(dyn ToSql + Sync)],
    ) -> R<Row> {
        let s = self.get(c, sql)?;
        Ok(c.query_one(&s, params)?)
    }

    /// The row of `sql`, if any.
    pub(super) fn query_opt(
        &mut self,
        c: &mut impl GenericClient,
        sql: &str,
        params: &[&(dyn ToSql + Sync)],
    ) -> R<Option<Row>> {
        let s = self.get(c, sql)?;
        Ok(c.query_opt(&s, params)?)
    }

    /// Runs `sql`; the number of rows it changed.
    pub(super) fn execute(
        &mut self,
        c: &mut impl GenericClient,
        sql: &str,
        params: &[&(dyn ToSql + Sync)],
    ) -> R<u64> {
        let s = self.get(c, sql)?;
        Ok(c.execute(&s, params)?)
    }
}
