//! Parsing: tokens from [`lex`] to [`Statement`]s by recursive descent.
//! Errors point at the offending token, list what was expected and suggest
//! the keyword it most likely meant.

use super::ast::{CompareOp, Condition, Field, OrderKey, SpaceRef, Statement, Value};
use super::error::{QueryError, Span};
use super::lexer::{Token, TokenKind, lex};
use super::suggest::suggest;

mod edit;
mod route;
use crate::model::{SpaceId, SpaceKind};

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
const TARGETS: [&str; 7] = [
    "rooms",
    "corridors",
    "doors",
    "stairs",
    "elevators",
    "others",
    "spaces",
];

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
            "LOCATE" => {
                let point = self.point()?;
                let level = if self.eat_word("ON") {
                    self.expect_word("LEVEL")?;
                    Some(self.level_name()?)
                } else {
                    None
                };
                Ok(Statement::Locate { point, level })
            }
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

    /// A level's name: `"M"`, `2`, `-1` or a bare word.
    fn level_name(&mut self) -> Result<String, QueryError> {
        let t = self.bump();
        match t.kind {
            TokenKind::Str(s) => Ok(s),
            TokenKind::Word => Ok(t.text),
            TokenKind::Number => Ok(t.text),
            _ => {
                self.pos -= 1;
                Err(self.expected(&["a level name (\"0\", 1, M)"]))
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
        // Plurals: "rooms", "elevators"; "stairs" is its own plural.
        let singular = target.strip_suffix('s').unwrap_or(&target);
        let kind = match (target.as_str(), singular) {
            (_, "space") if t.kind == TokenKind::Word => None,
            ("stairs", _) if t.kind == TokenKind::Word => Some(SpaceKind::Stairs),
            (_, k) if t.kind == TokenKind::Word && k.parse::<SpaceKind>().is_ok() => k.parse().ok(),
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
            "level" => Field::Level,
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
            TokenKind::Punct if t.text == "(" => {
                let at = self.point()?;
                if self.eat_word("ON") {
                    self.expect_word("LEVEL")?;
                    let level = self.level_name()?;
                    return Ok(SpaceRef::PointOn { at, level });
                }
                Ok(SpaceRef::Point(at))
            }
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
mod tests;
