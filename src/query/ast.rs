//! The abstract syntax of the query language. `Display` prints canonical
//! text: upper-case keywords, `;`-free, and `parse(ast.to_string()) == ast`.

use std::fmt;

use crate::model::{SpaceId, SpaceKind};

/// One statement.
#[derive(Debug, Clone, PartialEq)]
pub enum Statement {
    /// `ROUTE FROM a TO b [VIA c, …] [AVOID d, …] [ALTERNATIVES k]
    /// [WITH CLEARANCE r, MIN_DOOR_WIDTH w, SPEED v]`. A point end is the
    /// point itself; a space end is its anchor.
    Route {
        /// Start.
        from: SpaceRef,
        /// Goal.
        to: SpaceRef,
        /// Ordered waypoints.
        via: Vec<SpaceRef>,
        /// Excluded spaces.
        avoid: Vec<SpaceRef>,
        /// `AVOID WHERE …`: spaces excluded by a condition (e.g. an
        /// attribute a correction set: `attr.restricted = TRUE`).
        avoid_where: Option<Condition>,
        /// Number of routes, if given.
        alternatives: Option<u32>,
        /// `WITH …` options of the walker.
        with: WalkOptions,
    },
    /// `NEIGHBOURS OF a [DEPTH n]`.
    Neighbours {
        /// The centre.
        of: SpaceRef,
        /// Hops (default 1).
        depth: Option<u32>,
    },
    /// `FIND rooms|corridors|doors|spaces [WHERE …] [ORDER BY …] [LIMIT n]`.
    Find {
        /// `None` means every kind (`spaces`).
        kind: Option<SpaceKind>,
        /// Filter.
        filter: Option<Condition>,
        /// Sort keys.
        order: Vec<OrderKey>,
        /// Row limit.
        limit: Option<u64>,
    },
    /// `LOCATE (x, y) [ON LEVEL l]`.
    Locate {
        /// The point in metres.
        point: [f64; 2],
        /// The level searched (every level when None).
        level: Option<String>,
    },
    /// `REACHABLE FROM a WITHIN d [WITH …]` (metres walked).
    Reachable {
        /// Start.
        from: SpaceRef,
        /// Distance bound in metres.
        within_m: f64,
        /// `WITH …` options of the walker.
        with: WalkOptions,
    },
    /// `SHOW MAPS`.
    ShowMaps,
    /// `SHOW REVISIONS [OF m]`.
    ShowRevisions {
        /// The map, or the current one.
        map: Option<String>,
    },
    /// `USE m [AT REVISION n]`.
    Use {
        /// The map.
        map: String,
        /// The revision, or the latest.
        revision: Option<u64>,
    },
    /// `NAME a AS "Kitchen"`.
    Name {
        /// The space to name.
        space: SpaceRef,
        /// The new name.
        name: String,
    },
    /// `DIFF r1 r2`: the changes from revision r1 to r2 of the selected map.
    Diff {
        /// Old revision.
        from: u64,
        /// New revision.
        to: u64,
    },
    /// A correction: `MERGE`, `SPLIT`, `ADD DOOR`, `REMOVE DOOR`, `SET`,
    /// `UNSET` (a new revision, kept as a rule for later imports).
    Edit(EditStatement),
    /// `EXPLAIN <statement>`.
    Explain(Box<Statement>),
}

/// A correction as written (spaces not yet resolved); see [`crate::edit::Edit`].
#[derive(Debug, Clone, PartialEq)]
pub enum EditStatement {
    /// `MERGE a, b [, …] [AS "Lobby"]`.
    Merge {
        /// The spaces.
        spaces: Vec<SpaceRef>,
        /// The merged space's name.
        name: Option<String>,
    },
    /// `SPLIT a ALONG (x1, y1) TO (x2, y2) [WITH DOOR (x, y) [WIDTH w]]`.
    Split {
        /// The space.
        space: SpaceRef,
        /// The line's ends.
        line: [[f64; 2]; 2],
        /// A doorway on it: its position and width.
        door: Option<([f64; 2], Option<f64>)>,
    },
    /// `ADD DOOR BETWEEN a AND b AT (x, y) [WIDTH w]`.
    AddDoor {
        /// One side.
        a: SpaceRef,
        /// The other side.
        b: SpaceRef,
        /// Where.
        at: [f64; 2],
        /// How wide.
        width: Option<f64>,
    },
    /// `REMOVE DOOR d`.
    RemoveDoor(SpaceRef),
    /// `SET a KIND corridor`.
    SetKind(SpaceRef, SpaceKind),
    /// `SET a ATTRIBUTE key = value`.
    SetAttribute(SpaceRef, String, Value),
    /// `UNSET a ATTRIBUTE key`.
    UnsetAttribute(SpaceRef, String),
}

impl fmt::Display for EditStatement {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let point = |p: &[f64; 2]| format!("({}, {})", number(p[0]), number(p[1]));
        let key = |k: &str| {
            if is_identifier(k) {
                k.to_string()
            } else {
                quote(k)
            }
        };
        let width =
            |w: &Option<f64>| w.map_or_else(String::new, |w| format!(" WIDTH {}", number(w)));
        match self {
            EditStatement::Merge { spaces, name } => {
                let list: Vec<String> = spaces.iter().map(ToString::to_string).collect();
                write!(f, "MERGE {}", list.join(", "))?;
                if let Some(n) = name {
                    write!(f, " AS {}", quote(n))?;
                }
                Ok(())
            }
            EditStatement::Split { space, line, door } => {
                write!(
                    f,
                    "SPLIT {space} ALONG {} TO {}",
                    point(&line[0]),
                    point(&line[1])
                )?;
                if let Some((at, w)) = door {
                    write!(f, " WITH DOOR {}{}", point(at), width(w))?;
                }
                Ok(())
            }
            EditStatement::AddDoor { a, b, at, width: w } => {
                write!(
                    f,
                    "ADD DOOR BETWEEN {a} AND {b} AT {}{}",
                    point(at),
                    width(w)
                )
            }
            EditStatement::RemoveDoor(d) => write!(f, "REMOVE DOOR {d}"),
            EditStatement::SetKind(s, k) => write!(f, "SET {s} KIND {k}"),
            EditStatement::SetAttribute(s, k, v) => write!(f, "SET {s} ATTRIBUTE {} = {v}", key(k)),
            EditStatement::UnsetAttribute(s, k) => write!(f, "UNSET {s} ATTRIBUTE {}", key(k)),
        }
    }
}

impl Statement {
    /// Whether running it writes a revision (`NAME` and the corrections);
    /// `EXPLAIN` only plans.
    pub fn writes(&self) -> bool {
        matches!(self, Statement::Name { .. } | Statement::Edit(_))
    }
}

/// A reference to a space.
#[derive(Debug, Clone, PartialEq)]
pub enum SpaceRef {
    /// `12`, `space 12`, or `room 12` (kind checked when given).
    Id {
        /// The kind named before the id, if any (`space` means none).
        kind: Option<SpaceKind>,
        /// The id.
        id: SpaceId,
    },
    /// `"Kitchen"`: the space with this name (case-insensitive).
    Name(String),
    /// `(3.5, 7.25)`: the space containing the point.
    Point([f64; 2]),
    /// `(3.5, 7.25) ON LEVEL 2`: the point on a level of a building (a
    /// route's stop there), or the space containing it on that level.
    PointOn {
        /// The point, metres.
        at: [f64; 2],
        /// The level's name.
        level: String,
    },
}

/// A WHERE condition.
#[derive(Debug, Clone, PartialEq)]
pub enum Condition {
    /// `a AND b`.
    And(Box<Condition>, Box<Condition>),
    /// `a OR b`.
    Or(Box<Condition>, Box<Condition>),
    /// `NOT a`.
    Not(Box<Condition>),
    /// `field op value`.
    Compare {
        /// Left side.
        field: Field,
        /// Operator.
        op: CompareOp,
        /// Right side.
        value: Value,
    },
}

/// A property of a space usable in WHERE and ORDER BY.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Field {
    /// `id`.
    Id,
    /// `kind`.
    Kind,
    /// `name` (the label when unnamed).
    Name,
    /// `area` in m².
    Area,
    /// `degree`: navigable connections.
    Degree,
    /// `width` in metres (door width, see `exec`).
    Width,
    /// `level`: the name of the space's level (null without levels).
    Level,
    /// `attr.key`.
    Attr(String),
}

/// A comparison operator.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CompareOp {
    /// `=`
    Eq,
    /// `!=`
    Ne,
    /// `<`
    Lt,
    /// `<=`
    Le,
    /// `>`
    Gt,
    /// `>=`
    Ge,
    /// `LIKE` (`%` any run, `_` one character, case-insensitive).
    Like,
}

/// A literal.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// A number.
    Number(f64),
    /// A string (also a bare word such as `room`).
    Text(String),
    /// `TRUE` / `FALSE`.
    Bool(bool),
    /// `NULL` (matches a missing attribute).
    Null,
}

/// One ORDER BY key.
#[derive(Debug, Clone, PartialEq)]
pub struct OrderKey {
    /// What to sort by.
    pub field: Field,
    /// Descending?
    pub descending: bool,
}

/// Quotes a string literal, escaping `"` and `\`.
pub fn quote(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        if c == '"' || c == '\\' {
            out.push('\\');
        }
        out.push(c);
    }
    out.push('"');
    out
}

/// Whether `s` can be written as a bare identifier.
pub fn is_identifier(s: &str) -> bool {
    let mut chars = s.chars();
    chars
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

fn name_or_quoted(s: &str) -> String {
    if is_identifier(s) {
        s.to_string()
    } else {
        quote(s)
    }
}

fn number(x: f64) -> String {
    format!("{x:?}")
}

/// The walker options of `WITH CLEARANCE r, MIN_DOOR_WIDTH w, SPEED v`;
/// `None` keeps the default.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct WalkOptions {
    /// Clearance from walls, metres.
    pub clearance_m: Option<f64>,
    /// Narrowest door passed, metres.
    pub min_door_width_m: Option<f64>,
    /// Walking speed, metres per second.
    pub speed_m_s: Option<f64>,
    /// `NO STAIRS`: never take stairs between levels.
    pub no_stairs: bool,
    /// `NO ELEVATOR`: never take a lift between levels.
    pub no_elevator: bool,
}

impl fmt::Display for WalkOptions {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut parts: Vec<String> = [
            ("CLEARANCE", self.clearance_m),
            ("MIN_DOOR_WIDTH", self.min_door_width_m),
            ("SPEED", self.speed_m_s),
        ]
        .iter()
        .filter_map(|(k, v)| v.map(|v| format!("{k} {}", number(v))))
        .collect();
        if self.no_stairs {
            parts.push("NO STAIRS".into());
        }
        if self.no_elevator {
            parts.push("NO ELEVATOR".into());
        }
        if !parts.is_empty() {
            write!(f, " WITH {}", parts.join(", "))?;
        }
        Ok(())
    }
}

fn list(refs: &[SpaceRef]) -> String {
    refs.iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(", ")
}

impl fmt::Display for Statement {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Statement::Route {
                from,
                to,
                via,
                avoid,
                avoid_where,
                alternatives,
                with,
            } => {
                write!(f, "ROUTE FROM {from} TO {to}")?;
                if !via.is_empty() {
                    write!(f, " VIA {}", list(via))?;
                }
                if !avoid.is_empty() || avoid_where.is_some() {
                    f.write_str(" AVOID")?;
                }
                if !avoid.is_empty() {
                    write!(f, " {}", list(avoid))?;
                }
                if let Some(c) = avoid_where {
                    write!(f, " WHERE {c}")?;
                }
                if let Some(k) = alternatives {
                    write!(f, " ALTERNATIVES {k}")?;
                }
                write!(f, "{with}")
            }
            Statement::Neighbours { of, depth } => {
                write!(f, "NEIGHBOURS OF {of}")?;
                if let Some(d) = depth {
                    write!(f, " DEPTH {d}")?;
                }
                Ok(())
            }
            Statement::Find {
                kind,
                filter,
                order,
                limit,
            } => {
                let target = match kind {
                    None => "spaces".to_string(),
                    Some(SpaceKind::Stairs) => "stairs".to_string(),
                    Some(k) => format!("{k}s"),
                };
                write!(f, "FIND {target}")?;
                if let Some(c) = filter {
                    write!(f, " WHERE {c}")?;
                }
                if !order.is_empty() {
                    let keys: Vec<String> = order
                        .iter()
                        .map(|k| format!("{}{}", k.field, if k.descending { " DESC" } else { "" }))
                        .collect();
                    write!(f, " ORDER BY {}", keys.join(", "))?;
                }
                if let Some(n) = limit {
                    write!(f, " LIMIT {n}")?;
                }
                Ok(())
            }
            Statement::Locate { point, level } => {
                write!(f, "LOCATE ({}, {})", number(point[0]), number(point[1]))?;
                if let Some(l) = level {
                    write!(f, " ON LEVEL {}", quote(l))?;
                }
                Ok(())
            }
            Statement::Reachable {
                from,
                within_m,
                with,
            } => {
                write!(
                    f,
                    "REACHABLE FROM {from} WITHIN {}{with}",
                    number(*within_m)
                )
            }
            Statement::ShowMaps => f.write_str("SHOW MAPS"),
            Statement::ShowRevisions { map: None } => f.write_str("SHOW REVISIONS"),
            Statement::ShowRevisions { map: Some(m) } => {
                write!(f, "SHOW REVISIONS OF {}", name_or_quoted(m))
            }
            Statement::Use { map, revision } => {
                write!(f, "USE {}", name_or_quoted(map))?;
                if let Some(r) = revision {
                    write!(f, " AT REVISION {r}")?;
                }
                Ok(())
            }
            Statement::Name { space, name } => write!(f, "NAME {space} AS {}", quote(name)),
            Statement::Diff { from, to } => write!(f, "DIFF {from} {to}"),
            Statement::Edit(e) => write!(f, "{e}"),
            Statement::Explain(inner) => write!(f, "EXPLAIN {inner}"),
        }
    }
}

impl fmt::Display for SpaceRef {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SpaceRef::Id { kind: None, id } => write!(f, "space {id}"),
            SpaceRef::Id { kind: Some(k), id } => write!(f, "{k} {id}"),
            SpaceRef::Name(n) => f.write_str(&quote(n)),
            SpaceRef::Point(p) => write!(f, "({}, {})", number(p[0]), number(p[1])),
            SpaceRef::PointOn { at, level } => write!(
                f,
                "({}, {}) ON LEVEL {}",
                number(at[0]),
                number(at[1]),
                quote(level)
            ),
        }
    }
}

impl fmt::Display for Condition {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // Fully parenthesised binary nodes keep the printed text unambiguous.
        match self {
            Condition::And(a, b) => write!(f, "({a} AND {b})"),
            Condition::Or(a, b) => write!(f, "({a} OR {b})"),
            Condition::Not(a) => write!(f, "NOT {a}"),
            Condition::Compare { field, op, value } => write!(f, "{field} {op} {value}"),
        }
    }
}

impl fmt::Display for Field {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Field::Id => f.write_str("id"),
            Field::Kind => f.write_str("kind"),
            Field::Name => f.write_str("name"),
            Field::Area => f.write_str("area"),
            Field::Degree => f.write_str("degree"),
            Field::Width => f.write_str("width"),
            Field::Level => f.write_str("level"),
            Field::Attr(k) => write!(f, "attr.{}", name_or_quoted(k)),
        }
    }
}

impl fmt::Display for CompareOp {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            CompareOp::Eq => "=",
            CompareOp::Ne => "!=",
            CompareOp::Lt => "<",
            CompareOp::Le => "<=",
            CompareOp::Gt => ">",
            CompareOp::Ge => ">=",
            CompareOp::Like => "LIKE",
        })
    }
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Number(x) => f.write_str(&number(*x)),
            Value::Text(s) => f.write_str(&quote(s)),
            Value::Bool(b) => f.write_str(if *b { "TRUE" } else { "FALSE" }),
            Value::Null => f.write_str("NULL"),
        }
    }
}
