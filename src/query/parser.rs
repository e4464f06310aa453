//! Parsing: tokens from [`lex`] to [`Statement`]s by recursive descent.
//! Errors point at the offending token, list what was expected and suggest
//! the keyword it most likely meant.

use super::ast::{
    CompareOp, Condition, EditStatement, Field, OrderKey, SpaceRef, Statement, Value, WalkOptions,
};
use super::error::{QueryError, Span};
use super::lexer::{Token, TokenKind, lex};
use super::suggest::suggest;
use crate::model::{SpaceId, SpaceKind};
use crate::route::MAX_ALTERNATIVES;

/// Words that start a statement.
pub const STATEMENT_KEYWORDS: [&str; 17] = [
    "ROUTE",
    "NEIGHBOURS",
    "NEIGHBORS",
    "FIND",
    "LOCATE",
    "REACHABLE",
    "SHOW",
    "USE",
    "NAME",
    "DIFF",
    "EXPLAIN",
    "MERGE",
    "SPLIT",
    "ADD",
    "REMOVE",
    "SET",
    "UNSET",
];

/// Every keyword of the language (for completion and highlighting).
pub const KEYWORDS: [&str; 53] = [
    "ROUTE",
    "NEIGHBOURS",
    "NEIGHBORS",
    "FIND",
    "LOCATE",
    "REACHABLE",
    "SHOW",
    "USE",
    "NAME",
    "DIFF",
    "EXPLAIN",
    "FROM",
    "TO",
    "VIA",
    "AVOID",
    "ALTERNATIVES",
    "OF",
    "DEPTH",
    "WHERE",
    "ORDER",
    "BY",
    "ASC",
    "DESC",
    "LIMIT",
    "WITHIN",
    "WITH",
    "CLEARANCE",
    "MIN_DOOR_WIDTH",
    "SPEED",
    "MAPS",
    "REVISIONS",
    "AT",
    "REVISION",
    "AS",
    "AND",
    "OR",
    "NOT",
    "LIKE",
    "TRUE",
    "FALSE",
    "NULL",
    "MERGE",
    "SPLIT",
    "ALONG",
    "ADD",
    "DOOR",
    "BETWEEN",
    "REMOVE",
    "SET",
    "UNSET",
    "KIND",
    "ATTRIBUTE",
    "WIDTH",
];

const FIELDS: [&str; 7] = ["id", "kind", "name", "area", "degree", "width", "attr"];
const TARGETS: [&str; 5] = ["rooms", "corridors", "doors", "others", "spaces"];

/// Parses `;`-separated statements (empty ones are skipped).
///
/// ```
/// let s = nrgdb::query::parse("find ROOMS where area > 10; -- big rooms\n").unwrap();
/// assert_eq!(s[0].to_string(), "FIND rooms WHERE area > 10.0");
/// ```
pub fn parse(text: &str) -> Result<Vec<Statement>, QueryError> {
    let mut p = Parser {
        tokens: lex(text)?,
        pos: 0,
        depth: 0,
        terms: 0,
        tried: Vec::new(),
        tried_at: 0,
    };
    let mut out = Vec::new();
    loop {
        while p.eat_punct(";") {}
        if p.peek().kind == TokenKind::Eof {
            return Ok(out);
        }
        if out.len() == MAX_STATEMENTS {
            return Err(p.refused(format!(
                "at most {MAX_STATEMENTS} statements a request or file"
            )));
        }
        out.push(p.statement()?);
        if p.peek().kind != TokenKind::Eof && !p.eat_punct(";") {
            return Err(p.expected(&["';'", "end of input"]));
        }
    }
}

/// Parses a condition of the `FIND … WHERE` language on its own
/// (`attr.restricted = TRUE`), as `AVOID WHERE` and HTTP `avoid_where=`
/// take it.
pub fn parse_condition(text: &str) -> Result<Condition, QueryError> {
    match parse_statement(&format!("FIND spaces WHERE {text}"))? {
        Statement::Find {
            filter: Some(cond),
            order,
            limit: None,
            ..
        } if order.is_empty() => Ok(cond),
        _ => Err(QueryError::Syntax {
            span: Span::default(),
            message: format!("'{text}' is not a condition (e.g. attr.restricted = TRUE)"),
        }),
    }
}

/// Parses exactly one statement (a trailing `;` is allowed).
pub fn parse_statement(text: &str) -> Result<Statement, QueryError> {
    let mut all = parse(text)?;
    match all.len() {
        1 => Ok(all.remove(0)),
        n => {
            let p = Parser {
                tokens: lex(text)?,
                pos: 0,
                depth: 0,
                terms: 0,
                tried: Vec::new(),
                tried_at: 0,
            };
            let mut e = p.expected(&["one statement"]);
            if let QueryError::Syntax { message, .. } = &mut e {
                *message = format!("expected one statement, found {n}");
            }
            Err(e)
        }
    }
}

/// Deepest nesting of brackets, NOT and EXPLAIN the parser accepts: the
/// parser, the planner and the evaluator all recurse on it, so an
/// unbounded depth would overflow a thread's stack (a 4 KB query of
/// brackets crashed the server).
pub const MAX_NESTING: usize = 64;

/// Most statements one text may hold (issue 21, defect 7: a 1 MB request
/// of statements ran long past its time bound).
pub const MAX_STATEMENTS: usize = 1_000;

/// Most comparisons one condition may hold (an OR of 50 000 terms is a
/// tree that deep).
pub const MAX_TERMS: usize = 256;

struct Parser {
    tokens: Vec<Token>,
    pos: usize,
    /// Current nesting of brackets, NOT and EXPLAIN.
    depth: usize,
    /// Comparisons in the condition being parsed.
    terms: usize,
    /// Optional keywords tried (and absent) at `tried_at`, for messages.
    tried: Vec<&'static str>,
    tried_at: usize,
}

impl Parser {
    fn peek(&self) -> &Token {
        // `lex` always ends with Eof, and `pos` never passes it.
        &self.tokens[self.pos.min(self.tokens.len() - 1)]
    }

    fn bump(&mut self) -> Token {
        let t = self.peek().clone();
        if t.kind != TokenKind::Eof {
            self.pos += 1;
        }
        t
    }

    fn at_word(&self, kw: &str) -> bool {
        let t = self.peek();
        t.kind == TokenKind::Word && t.text.eq_ignore_ascii_case(kw)
    }

    fn eat_word(&mut self, kw: &'static str) -> bool {
        let yes = self.at_word(kw);
        if yes {
            self.pos += 1;
        } else {
            if self.tried_at != self.pos {
                self.tried.clear();
                self.tried_at = self.pos;
            }
            if !self.tried.contains(&kw) {
                self.tried.push(kw);
            }
        }
        yes
    }

    fn eat_punct(&mut self, p: &str) -> bool {
        let t = self.peek();
        let yes = t.kind == TokenKind::Punct && t.text == p;
        if yes {
            self.pos += 1;
        }
        yes
    }

    fn expect_word(&mut self, kw: &'static str) -> Result<(), QueryError> {
        if self.eat_word(kw) {
            Ok(())
        } else {
            Err(self.expected(&[kw]))
        }
    }

    fn expect_punct(&mut self, p: &'static str) -> Result<(), QueryError> {
        if self.eat_punct(p) {
            Ok(())
        } else {
            Err(self.expected(&[p]))
        }
    }

    /// "expected A, B or C, found 'x' (did you mean A?)" at the next token.
    fn expected(&self, what: &[&str]) -> QueryError {
        let mut all: Vec<&str> = Vec::new();
        if self.tried_at == self.pos {
            // Optional keywords that could also have come here.
            all.extend(self.tried.iter());
        }
        for w in what {
            if !all.contains(w) {
                all.push(w);
            }
        }
        let what = all.as_slice();
        let t = self.peek();
        let found = match t.kind {
            TokenKind::Eof => "end of input".to_string(),
            _ => format!("'{}'", t.text),
        };
        let list = match what {
            [] => String::new(),
            [one] => (*one).to_string(),
            [init @ .., last] => format!("{} or {last}", init.join(", ")),
        };
        let mut message = format!("expected {list}, found {found}");
        if t.kind == TokenKind::Word {
            let words = what.iter().map(|w| w.trim_matches('\''));
            let words = words.filter(|w| w.chars().all(|c| c.is_alphabetic()));
            if let Some(s) = suggest(&t.text, words) {
                message.push_str(&format!(" (did you mean {s}?)"));
            }
        }
        QueryError::Syntax {
            span: t.span,
            message,
        }
    }

    fn statement(&mut self) -> Result<Statement, QueryError> {
        self.terms = 0;
        let t = self.peek().clone();
        let kw = if t.kind == TokenKind::Word {
            t.text.to_ascii_uppercase()
        } else {
            String::new()
        };
        if !STATEMENT_KEYWORDS.contains(&kw.as_str()) {
            return Err(self.expected(&STATEMENT_KEYWORDS));
        }
        self.pos += 1;
        match kw.as_str() {
            "ROUTE" => self.route(),
            "NEIGHBOURS" | "NEIGHBORS" => {
                self.expect_word("OF")?;
                let of = self.space_ref()?;
                let depth = if self.eat_word("DEPTH") {
                    Some(self.integer()?)
                } else {
                    None
                };
                Ok(Statement::Neighbours { of, depth })
            }
            "FIND" => self.find(),
            "LOCATE" => Ok(Statement::Locate {
                point: self.point()?,
            }),
            "REACHABLE" => {
                self.expect_word("FROM")?;
                let from = self.space_ref()?;
                self.expect_word("WITHIN")?;
                let within_m = self.number()?;
                let with = self.walk_options()?;
                Ok(Statement::Reachable {
                    from,
                    within_m,
                    with,
                })
            }
            "SHOW" => {
                if self.eat_word("MAPS") {
                    Ok(Statement::ShowMaps)
                } else if self.eat_word("REVISIONS") {
                    let map = if self.eat_word("OF") {
                        Some(self.map_name()?)
                    } else {
                        None
                    };
                    Ok(Statement::ShowRevisions { map })
                } else {
                    Err(self.expected(&["MAPS", "REVISIONS"]))
                }
            }
            "USE" => {
                let map = self.map_name()?;
                let revision = if self.eat_word("AT") {
                    self.expect_word("REVISION")?;
                    Some(self.integer()?)
                } else {
                    None
                };
                Ok(Statement::Use { map, revision })
            }
            "NAME" => {
                let space = self.space_ref()?;
                self.expect_word("AS")?;
                let span = self.peek().span;
                let name = self.string()?;
                if name.trim().is_empty() {
                    return Err(QueryError::Syntax {
                        span,
                        message: "a space's name cannot be empty".into(),
                    });
                }
                Ok(Statement::Name { space, name })
            }
            "DIFF" => Ok(Statement::Diff {
                from: self.integer()?,
                to: self.integer()?,
            }),
            "MERGE" | "SPLIT" | "ADD" | "REMOVE" | "SET" | "UNSET" => {
                Ok(Statement::Edit(self.edit(&kw)?))
            }
            _ => {
                self.enter()?;
                let inner = self.statement();
                self.depth -= 1;
                Ok(Statement::Explain(Box::new(inner?)))
            }
        }
    }

    /// The rest of a correction statement after its first keyword `kw`.
    fn edit(&mut self, kw: &str) -> Result<EditStatement, QueryError> {
        Ok(match kw {
            "MERGE" => {
                let spaces = self.ref_list()?;
                let name = if self.eat_word("AS") {
                    let span = self.peek().span;
                    let name = self.string()?;
                    if name.trim().is_empty() {
                        return Err(QueryError::Syntax {
                            span,
                            message: "a space's name cannot be empty".into(),
                        });
                    }
                    Some(name)
                } else {
                    None
                };
                EditStatement::Merge { spaces, name }
            }
            "SPLIT" => {
                let space = self.space_ref()?;
                self.expect_word("ALONG")?;
                let from = self.point()?;
                self.expect_word("TO")?;
                let to = self.point()?;
                let door = if self.eat_word("WITH") {
                    self.expect_word("DOOR")?;
                    let at = self.point()?;
                    Some((at, self.door_width()?))
                } else {
                    None
                };
                EditStatement::Split {
                    space,
                    line: [from, to],
                    door,
                }
            }
            "ADD" => {
                self.expect_word("DOOR")?;
                self.expect_word("BETWEEN")?;
                let a = self.space_ref()?;
                self.expect_word("AND")?;
                let b = self.space_ref()?;
                self.expect_word("AT")?;
                let at = self.point()?;
                let width = self.door_width()?;
                EditStatement::AddDoor { a, b, at, width }
            }
            "REMOVE" => {
                self.expect_word("DOOR")?;
                EditStatement::RemoveDoor(self.space_ref()?)
            }
            "SET" => {
                let space = self.space_ref()?;
                if self.eat_word("KIND") {
                    let t = self.peek().clone();
                    let kind =
                        t.text
                            .parse::<SpaceKind>()
                            .map_err(|message| QueryError::Syntax {
                                span: t.span,
                                message,
                            })?;
                    self.pos += 1;
                    EditStatement::SetKind(space, kind)
                } else {
                    self.expect_word("ATTRIBUTE")?;
                    let key = self.attribute_key()?;
                    self.expect_punct("=")?;
                    let span = self.peek().span;
                    let value = self.value()?;
                    if value == Value::Null {
                        return Err(QueryError::Syntax {
                            span,
                            message: "an attribute cannot be set to NULL: UNSET it".into(),
                        });
                    }
                    EditStatement::SetAttribute(space, key, value)
                }
            }
            _ => {
                let space = self.space_ref()?;
                self.expect_word("ATTRIBUTE")?;
                EditStatement::UnsetAttribute(space, self.attribute_key()?)
            }
        })
    }

    /// `[WIDTH w]`.
    fn door_width(&mut self) -> Result<Option<f64>, QueryError> {
        if self.eat_word("WIDTH") {
            Ok(Some(self.number()?))
        } else {
            Ok(None)
        }
    }

    /// An attribute's name: a bare word or a "string".
    fn attribute_key(&mut self) -> Result<String, QueryError> {
        let t = self.peek().clone();
        match t.kind {
            TokenKind::Word => {
                self.pos += 1;
                Ok(t.text)
            }
            TokenKind::Str(s) => {
                self.pos += 1;
                Ok(s)
            }
            _ => Err(self.expected(&["an attribute name"])),
        }
    }

    fn route(&mut self) -> Result<Statement, QueryError> {
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

    /// `[WITH CLEARANCE r [,] MIN_DOOR_WIDTH w [,] SPEED v]`, any order,
    /// each at most once.
    fn walk_options(&mut self) -> Result<WalkOptions, QueryError> {
        let mut with = WalkOptions::default();
        if !self.eat_word("WITH") {
            return Ok(with);
        }
        const OPTIONS: [&str; 3] = ["CLEARANCE", "MIN_DOOR_WIDTH", "SPEED"];
        loop {
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

    fn ref_list(&mut self) -> Result<Vec<SpaceRef>, QueryError> {
        let mut refs = vec![self.space_ref()?];
        while self.eat_punct(",") {
            refs.push(self.space_ref()?);
        }
        Ok(refs)
    }

    fn find(&mut self) -> Result<Statement, QueryError> {
        let t = self.peek().clone();
        let target = t.text.to_ascii_lowercase();
        let kind = match target.trim_end_matches('s') {
            "space" if t.kind == TokenKind::Word => None,
            k if t.kind == TokenKind::Word && k.parse::<SpaceKind>().is_ok() => k.parse().ok(),
            _ => return Err(self.expected(&TARGETS)),
        };
        self.pos += 1;
        let filter = if self.eat_word("WHERE") {
            Some(self.or()?)
        } else {
            None
        };
        let mut order = Vec::new();
        if self.eat_word("ORDER") {
            self.expect_word("BY")?;
            loop {
                let field = self.field()?;
                let descending = if self.eat_word("DESC") {
                    true
                } else {
                    self.eat_word("ASC");
                    false
                };
                order.push(OrderKey { field, descending });
                if !self.eat_punct(",") {
                    break;
                }
            }
        }
        let limit = if self.eat_word("LIMIT") {
            Some(self.integer()?)
        } else {
            None
        };
        Ok(Statement::Find {
            kind,
            filter,
            order,
            limit,
        })
    }

    /// One level deeper, or an error past [`MAX_NESTING`].
    fn enter(&mut self) -> Result<(), QueryError> {
        self.depth += 1;
        if self.depth > MAX_NESTING {
            self.depth -= 1;
            return Err(self.refused(format!(
                "brackets, NOT and EXPLAIN nest at most {MAX_NESTING} deep"
            )));
        }
        Ok(())
    }

    /// A syntax error with `message` at the next token.
    fn refused(&self, message: String) -> QueryError {
        QueryError::Syntax {
            span: self.peek().span,
            message,
        }
    }

    fn or(&mut self) -> Result<Condition, QueryError> {
        let mut left = self.and()?;
        while self.eat_word("OR") {
            left = Condition::Or(Box::new(left), Box::new(self.and()?));
        }
        Ok(left)
    }

    fn and(&mut self) -> Result<Condition, QueryError> {
        let mut left = self.not()?;
        while self.eat_word("AND") {
            left = Condition::And(Box::new(left), Box::new(self.not()?));
        }
        Ok(left)
    }

    fn not(&mut self) -> Result<Condition, QueryError> {
        if self.eat_word("NOT") {
            self.enter()?;
            let inner = self.not();
            self.depth -= 1;
            return Ok(Condition::Not(Box::new(inner?)));
        }
        if self.eat_punct("(") {
            self.enter()?;
            let c = self.or();
            self.depth -= 1;
            let c = c?;
            self.expect_punct(")")?;
            return Ok(c);
        }
        self.terms += 1;
        if self.terms > MAX_TERMS {
            return Err(self.refused(format!(
                "a condition may hold at most {MAX_TERMS} comparisons"
            )));
        }
        let field = self.field()?;
        let t = self.bump();
        let op = match (
            t.kind == TokenKind::Punct,
            t.text.to_ascii_uppercase().as_str(),
        ) {
            (true, "=") => CompareOp::Eq,
            (true, "!=" | "<>") => CompareOp::Ne,
            (true, "<") => CompareOp::Lt,
            (true, "<=") => CompareOp::Le,
            (true, ">") => CompareOp::Gt,
            (true, ">=") => CompareOp::Ge,
            (false, "LIKE") if t.kind == TokenKind::Word => CompareOp::Like,
            _ => {
                self.pos -= 1;
                return Err(self.expected(&["=", "!=", "<", "<=", ">", ">=", "LIKE"]));
            }
        };
        Ok(Condition::Compare {
            field,
            op,
            value: self.value()?,
        })
    }

    fn field(&mut self) -> Result<Field, QueryError> {
        let t = self.peek().clone();
        let word = if t.kind == TokenKind::Word {
            t.text.to_ascii_lowercase()
        } else {
            String::new()
        };
        let field = match word.as_str() {
            "id" => Field::Id,
            "kind" => Field::Kind,
            "name" => Field::Name,
            "area" => Field::Area,
            "degree" => Field::Degree,
            "width" => Field::Width,
            "attr" => {
                self.pos += 1;
                self.expect_punct(".")?;
                let key = self.bump();
                return match key.kind {
                    TokenKind::Word => Ok(Field::Attr(key.text)),
                    TokenKind::Str(s) => Ok(Field::Attr(s)),
                    _ => {
                        self.pos -= 1;
                        Err(self.expected(&["an attribute name"]))
                    }
                };
            }
            _ => return Err(self.expected(&FIELDS)),
        };
        self.pos += 1;
        Ok(field)
    }

    fn value(&mut self) -> Result<Value, QueryError> {
        let t = self.peek().clone();
        let v = match &t.kind {
            TokenKind::Number => Value::Number(self.number()?),
            TokenKind::Str(s) => {
                self.pos += 1;
                Value::Text(s.clone())
            }
            TokenKind::Word => {
                self.pos += 1;
                match t.text.to_ascii_uppercase().as_str() {
                    "TRUE" => Value::Bool(true),
                    "FALSE" => Value::Bool(false),
                    "NULL" => Value::Null,
                    _ => Value::Text(t.text.clone()),
                }
            }
            _ => return Err(self.expected(&["a number", "a \"string\"", "TRUE", "FALSE", "NULL"])),
        };
        Ok(v)
    }

    fn space_ref(&mut self) -> Result<SpaceRef, QueryError> {
        let t = self.peek().clone();
        match &t.kind {
            TokenKind::Number => Ok(SpaceRef::Id {
                kind: None,
                id: SpaceId(self.integer()?),
            }),
            TokenKind::Str(s) => {
                self.pos += 1;
                Ok(SpaceRef::Name(s.clone()))
            }
            TokenKind::Punct if t.text == "(" => Ok(SpaceRef::Point(self.point()?)),
            TokenKind::Word => {
                let w = t.text.to_ascii_lowercase();
                let kind = if w == "space" {
                    None
                } else {
                    w.parse::<SpaceKind>().ok()
                };
                if w != "space" && kind.is_none() {
                    let hint = suggest(&w, ["room", "space", "door", "corridor"]);
                    let mut e = self.expected(&["an id", "a \"name\"", "a point (x, y)"]);
                    if let (QueryError::Syntax { message, .. }, Some(h)) = (&mut e, hint) {
                        message.push_str(&format!(" (did you mean {h}?)"));
                    } else if let QueryError::Syntax { message, .. } = &mut e {
                        message.push_str(" (names need quotes: \"Kitchen\")");
                    }
                    return Err(e);
                }
                self.pos += 1;
                Ok(SpaceRef::Id {
                    kind,
                    id: SpaceId(self.integer()?),
                })
            }
            _ => Err(self.expected(&["an id", "a \"name\"", "a point (x, y)"])),
        }
    }

    fn point(&mut self) -> Result<[f64; 2], QueryError> {
        self.expect_punct("(")?;
        let x = self.number()?;
        self.expect_punct(",")?;
        let y = self.number()?;
        self.expect_punct(")")?;
        Ok([x, y])
    }

    fn number(&mut self) -> Result<f64, QueryError> {
        let t = self.peek();
        match (t.kind == TokenKind::Number, t.text.parse::<f64>()) {
            (true, Ok(x)) if x.is_finite() => {
                self.pos += 1;
                Ok(x)
            }
            _ => Err(self.expected(&["a number"])),
        }
    }

    fn integer<T: std::str::FromStr>(&mut self) -> Result<T, QueryError> {
        let t = self.peek();
        match (t.kind == TokenKind::Number, t.text.parse::<T>()) {
            (true, Ok(x)) => {
                self.pos += 1;
                Ok(x)
            }
            _ => Err(self.expected(&["a whole number"])),
        }
    }

    fn string(&mut self) -> Result<String, QueryError> {
        if let TokenKind::Str(s) = &self.peek().kind {
            let s = s.clone();
            self.pos += 1;
            return Ok(s);
        }
        Err(self.expected(&["a \"string\""]))
    }

    fn map_name(&mut self) -> Result<String, QueryError> {
        let t = self.peek().clone();
        match t.kind {
            TokenKind::Word => {
                self.pos += 1;
                Ok(t.text)
            }
            TokenKind::Str(s) => {
                self.pos += 1;
                Ok(s)
            }
            _ => Err(self.expected(&["a map name"])),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 21, defect 1: nested brackets, NOTs and EXPLAINs and long OR
    /// chains crashed the server by overflowing a worker's stack. Now
    /// each is a syntax error naming the limit, at any size.
    #[test]
    fn deeply_nested_query_is_refused_not_a_crash() {
        let brackets = |n: usize| {
            format!(
                "FIND rooms WHERE {}area > 1{}",
                "(".repeat(n),
                ")".repeat(n)
            )
        };
        assert!(parse(&brackets(MAX_NESTING)).is_ok());
        for text in [
            brackets(MAX_NESTING + 1),
            brackets(20_000),
            format!("FIND rooms WHERE {}area > 1", "NOT ".repeat(5_000)),
            format!("{}FIND rooms", "EXPLAIN ".repeat(100_000)),
        ] {
            let e = parse(&text).unwrap_err().to_string();
            assert!(e.contains("nest at most 64 deep"), "{e}");
        }
        let terms = |n: usize| {
            let ors = vec!["area > 1"; n].join(" OR ");
            format!("FIND rooms WHERE {ors}; FIND rooms WHERE {ors}")
        };
        assert!(parse(&terms(MAX_TERMS)).is_ok());
        let e = parse(&terms(50_000)).unwrap_err().to_string();
        assert!(e.contains("at most 256 comparisons"), "{e}");
    }

    /// Issue 21 paper cuts: `ALTERNATIVES 0` answered "no route" and
    /// `NAME 3 AS ""` was accepted; both are errors at the value.
    #[test]
    fn empty_names_and_zero_alternatives_are_refused() {
        let e = parse("ROUTE FROM 1 TO 2 ALTERNATIVES 0")
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("ALTERNATIVES takes 1 to 10 routes, not 0"),
            "{e}"
        );
        assert!(parse("ROUTE FROM 1 TO 2 ALTERNATIVES 3").is_ok());
        let e = parse("NAME 3 AS \"  \"").unwrap_err().to_string();
        assert!(e.contains("name cannot be empty"), "{e}");
    }

    /// Issue 21, defect 7: a megabyte of statements is refused at once;
    /// empty statements (`;;;`) cost nothing and are not counted.
    #[test]
    fn too_many_statements_are_refused() {
        assert_eq!(parse(&";".repeat(1_000_000)).unwrap().len(), 0);
        assert_eq!(
            parse(&"SHOW MAPS;".repeat(MAX_STATEMENTS)).unwrap().len(),
            MAX_STATEMENTS
        );
        let e = parse(&"SHOW MAPS;".repeat(100_000))
            .unwrap_err()
            .to_string();
        assert!(e.contains("at most 1000 statements"), "{e}");
    }

    #[test]
    fn typo_gets_a_suggestion_and_a_span() {
        let e = parse("FIND rooms;\n  ROUET FROM 1 TO 2").unwrap_err();
        let s = e.to_string();
        assert!(s.contains("found 'ROUET' (did you mean ROUTE?)"), "{s}");
        let span = e.span().unwrap();
        assert_eq!(
            (span.line, span.column, span.offset, span.len),
            (2, 3, 14, 5)
        );
    }

    #[test]
    fn statements_round_trip() {
        let text = "ROUTE FROM room 3 TO \"Lounge\" VIA (1.5, 2.0), 7 AVOID door 4 ALTERNATIVES 2;\
            ROUTE FROM 1 TO 2 AVOID WHERE attr.restricted = TRUE; ROUTE FROM 1 TO 2 AVOID 5 WHERE kind = door;\
            NEIGHBORS OF space 1 DEPTH 2; FIND doors WHERE NOT (width < 1 OR attr.\"a b\" = NULL) \
            AND name LIKE 'K%' ORDER BY area DESC, id LIMIT 3; LOCATE (1, -2); \
            REACHABLE FROM 1 WITHIN 10; SHOW MAPS; SHOW REVISIONS OF \"willow-full\"; \
            USE demo AT REVISION 2; NAME 3 AS \"Big \\\"Room\\\"\"; DIFF 1 2; EXPLAIN FIND spaces; \
            MERGE 3, \"Hall\", (1, 2) AS \"Lobby\"; SPLIT 4 ALONG (0, 1.5) TO (9, 1.5) WITH DOOR (3, 1.5) WIDTH 0.9; \
            SPLIT corridor 2 ALONG (0, 0) TO (1, 1); ADD DOOR BETWEEN 3 AND \"Hall\" AT (4, 4) WIDTH 1.2; \
            ADD DOOR BETWEEN 3 AND 5 AT (4, 4); REMOVE DOOR door 31; SET 3 KIND corridor; \
            SET \"Hall\" ATTRIBUTE restricted = TRUE; SET 3 ATTRIBUTE \"opening hours\" = \"8-18\"; \
            SET 3 ATTRIBUTE capacity = 12; UNSET 3 ATTRIBUTE restricted";
        let parsed = parse(text).unwrap();
        assert_eq!(parsed.len(), 24);
        for s in &parsed {
            assert_eq!(&parse_statement(&s.to_string()).unwrap(), s, "{s}");
        }
    }

    #[test]
    fn errors_name_what_was_expected() {
        let e = parse("ROUTE FROM kitchen TO 2").unwrap_err().to_string();
        assert!(e.contains("names need quotes"), "{e}");
        let e = parse("FIND rooms WHERE aera > 3").unwrap_err().to_string();
        assert!(e.contains("did you mean area?"), "{e}");
        let e = parse("FIND rooms LIMIT").unwrap_err().to_string();
        assert!(e.contains("found end of input"), "{e}");
    }
}
