//! `ROUTE` after its first keyword, and the walker options (`WITH …`)
//! that `ROUTE` and `REACHABLE` share.

use super::Parser;
use crate::query::ast::{Statement, WalkOptions};
use crate::query::error::QueryError;
use crate::route::MAX_ALTERNATIVES;

impl Parser {
    /// `ROUTE FROM … TO … [VIA …] [AVOID …] [ALTERNATIVES n] [WITH …]`
    /// after its first keyword.
    pub(super) fn route(&mut self) -> Result<Statement, QueryError> {
        self.expect_word("FROM")?;
        let from = self.space_ref()?;
        self.expect_word("TO")?;
        let to = self.space_ref()?;
        let via = if self.eat_word("VIA") {
            self.ref_list()?
        } else {
            Vec::new()
        };
        let (mut avoid, mut avoid_where) = (Vec::new(), None);
        if self.eat_word("AVOID") {
            if !self.at_word("WHERE") {
                avoid = self.ref_list()?;
            }
            if self.eat_word("WHERE") {
                avoid_where = Some(self.or()?);
            }
        }
        let alternatives = if self.eat_word("ALTERNATIVES") {
            let span = self.peek().span;
            let k = self.integer()?;
            if !(1..=MAX_ALTERNATIVES as u32).contains(&k) {
                return Err(QueryError::Syntax {
                    span,
                    message: format!("ALTERNATIVES takes 1 to {MAX_ALTERNATIVES} routes, not {k}"),
                });
            }
            Some(k)
        } else {
            None
        };
        let with = self.walk_options()?;
        Ok(Statement::Route {
            from,
            to,
            via,
            avoid,
            avoid_where,
            alternatives,
            with,
        })
    }

    /// `[WITH CLEARANCE r [,] MIN_DOOR_WIDTH w [,] SPEED v [,] NO STAIRS
    /// [,] NO ELEVATOR]`, any order, each at most once.
    pub(super) fn walk_options(&mut self) -> Result<WalkOptions, QueryError> {
        let mut with = WalkOptions::default();
        if !self.eat_word("WITH") {
            return Ok(with);
        }
        const OPTIONS: [&str; 4] = ["CLEARANCE", "MIN_DOOR_WIDTH", "SPEED", "NO"];
        loop {
            if self.eat_word("NO") {
                let flag = if self.eat_word("STAIRS") {
                    &mut with.no_stairs
                } else if self.eat_word("ELEVATOR") {
                    &mut with.no_elevator
                } else {
                    return Err(self.expected(&["STAIRS", "ELEVATOR"]));
                };
                if *flag {
                    return Err(self.expected(&["each WITH option once"]));
                }
                *flag = true;
                self.eat_punct(",");
                if !OPTIONS.iter().any(|o| self.at_word(o)) {
                    return Ok(with);
                }
                continue;
            }
            let slot = if self.eat_word("CLEARANCE") {
                &mut with.clearance_m
            } else if self.eat_word("MIN_DOOR_WIDTH") {
                &mut with.min_door_width_m
            } else if self.eat_word("SPEED") {
                &mut with.speed_m_s
            } else {
                return Err(self.expected(&OPTIONS));
            };
            if slot.is_some() {
                return Err(self.expected(&["each WITH option once"]));
            }
            *slot = Some(self.number()?);
            self.eat_punct(",");
            if !OPTIONS.iter().any(|o| self.at_word(o)) {
                return Ok(with);
            }
        }
    }
}
