//! The query language: text → tokens ([`lex`], nom + nom_locate) →
//! [`Statement`]s ([`parse`]) → [`Plan`] (references resolved) → execution
//! over a [`Source`] → [`QueryResult`] rendered as a table, JSON or CSV.
//! [`Session`] ties these together (line in, text out).
//!
//! Owns the AST, the parser, the planner, the executor, the [`Source`]
//! trait and [`MemorySource`]. Uses `model`, `route` and `diff` (`DIFF`
//! compares revisions loaded with their grids: [`compare_revisions`]).
//! Must not use `store` (it implements [`Source`]), the server or the
//! terminal.
//!
//! Statements: `ROUTE FROM a TO b [VIA c, …] [AVOID d, …] [ALTERNATIVES k]`,
//! `NEIGHBOURS OF a [DEPTH n]`, `FIND rooms|corridors|doors|others|spaces
//! [WHERE …] [ORDER BY …] [LIMIT n]`, `LOCATE (x, y)`, `REACHABLE FROM a
//! WITHIN d`, `SHOW MAPS`, `SHOW REVISIONS [OF m]`, `USE m [AT REVISION n]`,
//! `NAME a AS "…"`, `DIFF r1 r2` (changes between two revisions), `EXPLAIN <statement>`.
//! A reference is an id (`12`, `space 12`, `room 12`), a name
//! (`"Kitchen"`, case-insensitive) or a point (`(3.5, 7.25)`, metres).
//!
//! WHERE fields: `id`, `kind`, `name` (the label when unnamed), `area` (m²),
//! `degree` (navigable connections), `width` (a door's width in metres,
//! [`model::doorway`](crate::model::doorway()): the doorway line's length
//! unless a `width_m` attribute declares it; none for other kinds) and
//! `attr.key`; operators `= != < <= > >=
//! LIKE`, combined with `AND`, `OR`, `NOT` and parentheses.

pub mod demo;

mod ast;
mod compare_revisions;
mod error;
mod exec;
mod filter;
mod index;
mod lexer;
mod parser;
mod plan;
mod result;
mod script;
mod session;
mod shell;
mod source;
mod suggest;

pub use ast::{
    CompareOp, Condition, EditStatement, Field, OrderKey, SpaceRef, Statement, Value, WalkOptions,
    is_identifier, quote,
};
pub use compare_revisions::{LoadedRevision, RevisionComparison, compare_revisions};
pub use error::{QueryError, SourceError, Span};
pub use exec::{Limits, execute};
pub use filter::{like, matching_spaces};
pub use index::IndexedRevision;
pub use lexer::{Token, TokenKind, lex};
pub use parser::{KEYWORDS, STATEMENT_KEYWORDS, parse, parse_condition, parse_statement};
pub use plan::{Plan, plan};
pub use result::{Cell, Format, QueryResult, Table};
pub use script::{OnError, ScriptStep, StatementText, split_statements};
pub use session::Session;
pub use shell::{HELP, ShellCommand, Vocabulary, format_message};
pub use source::{EditDone, MapInfo, MemorySource, RevisionInfo, Source};
pub use suggest::{edit_distance, suggest};
