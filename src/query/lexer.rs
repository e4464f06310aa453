//! Lexing with nom 8 over a `nom_locate` span: words, numbers, strings and
//! punctuation, each with its byte span, line and column. `--` starts a
//! comment to the end of the line. Keywords are plain words here; the
//! parser compares them case-insensitively.

use nom::branch::alt;
use nom::bytes::complete::{tag, take_while, take_while1};
use nom::character::complete::{char, digit1, multispace1, one_of};
use nom::combinator::{opt, recognize};
use nom::{IResult, Parser};
use nom_locate::LocatedSpan;

use super::error::{QueryError, Span};

type Input<'a> = LocatedSpan<&'a str>;

/// What a token is.
#[derive(Debug, Clone, PartialEq)]
pub enum TokenKind {
    /// An identifier or keyword (letters, digits, `_`, inner `-`).
    Word,
    /// A number (`12`, `-3.5`, `1e3`).
    Number,
    /// A quoted string, unescaped.
    Str(String),
    /// Punctuation: `( ) , ; . = != <> < <= > >=`.
    Punct,
    /// End of input.
    Eof,
}

/// One token with its text (as written) and position.
#[derive(Debug, Clone, PartialEq)]
pub struct Token {
    /// What it is.
    pub kind: TokenKind,
    /// The text as written.
    pub text: String,
    /// Where it is.
    pub span: Span,
}

fn span_of(start: &Input<'_>, len: usize) -> Span {
    Span {
        offset: start.location_offset(),
        len,
        line: start.location_line(),
        column: start.get_utf8_column(),
    }
}

/// Columns of tokens met in order, counted incrementally: nom_locate's
/// `get_utf8_column` scans back to the line start on every call, which made
/// lexing a long one-line query quadratic.
struct Columns<'a> {
    text: &'a str,
    /// Byte offset and 1-based column of the last token.
    offset: usize,
    column: usize,
    /// Bytes looked at so far (at most the text's length: linear).
    scanned: usize,
}

impl<'a> Columns<'a> {
    fn new(text: &'a str) -> Columns<'a> {
        Columns {
            text,
            offset: 0,
            column: 1,
            scanned: 0,
        }
    }

    /// The span of `len` bytes at `start` (at or after the last one).
    fn span(&mut self, start: &Input<'_>, len: usize) -> Span {
        let offset = start.location_offset();
        let between = self.text.get(self.offset..offset).unwrap_or("");
        self.scanned += between.len();
        self.column = match between.rfind('\n') {
            Some(nl) => between[nl + 1..].chars().count() + 1,
            None => self.column + between.chars().count(),
        };
        self.offset = offset;
        Span {
            offset,
            len,
            line: start.location_line(),
            column: self.column,
        }
    }
}

fn skip(i: Input<'_>) -> IResult<Input<'_>, ()> {
    let (mut i, _) = opt(multispace1).parse(i)?;
    loop {
        let (rest, comment) = opt(recognize((tag("--"), take_while(|c| c != '\n')))).parse(i)?;
        let (rest, _) = opt(multispace1).parse(rest)?;
        if comment.is_none() {
            return Ok((rest, ()));
        }
        i = rest;
    }
}

fn word(i: Input<'_>) -> IResult<Input<'_>, Input<'_>> {
    recognize((
        take_while1(|c: char| c.is_alphabetic() || c == '_'),
        take_while(|c: char| c.is_alphanumeric() || c == '_' || c == '-'),
    ))
    .parse(i)
}

fn number(i: Input<'_>) -> IResult<Input<'_>, Input<'_>> {
    recognize((
        opt(char('-')),
        digit1,
        opt((char('.'), digit1)),
        opt((one_of("eE"), opt(one_of("+-")), digit1)),
    ))
    .parse(i)
}

fn punct(i: Input<'_>) -> IResult<Input<'_>, Input<'_>> {
    alt((
        tag("!="),
        tag("<>"),
        tag("<="),
        tag(">="),
        recognize(one_of("(),;.=<>")),
    ))
    .parse(i)
}

/// A quoted string ('…' or "…", `\` escapes the next character).
/// `Ok(None)` at an unterminated string.
fn string(i: Input<'_>) -> IResult<Input<'_>, Option<(String, usize)>> {
    let (rest, quote) = one_of("\"'").parse(i)?;
    let mut value = String::new();
    let mut chars = rest.fragment().char_indices();
    while let Some((at, c)) = chars.next() {
        if c == quote {
            let len = 1 + at + 1;
            // `at` is a byte offset: nom's `take` counts characters, and
            // cut strings holding "ü" one character too far.
            let (rest, _) = nom::Input::take_split(&rest, at + 1);
            return Ok((rest, Some((value, len))));
        }
        if c == '\\' {
            match chars.next() {
                Some((_, e)) => value.push(e),
                None => break,
            }
        } else {
            value.push(c);
        }
    }
    Ok((i, None))
}

/// Splits `text` into tokens, ending with an `Eof` token.
///
/// ```
/// let tokens = nrgdb::query::lex("FIND rooms -- all\nLIMIT 3;").unwrap();
/// let texts: Vec<_> = tokens.iter().map(|t| t.text.as_str()).collect();
/// assert_eq!(texts, ["FIND", "rooms", "LIMIT", "3", ";", ""]);
/// ```
pub fn lex(text: &str) -> Result<Vec<Token>, QueryError> {
    lex_counting(text).map(|(tokens, _)| tokens)
}

/// [`lex`], also giving the bytes scanned to count columns (the tests
/// check it stays within the text's length).
fn lex_counting(text: &str) -> Result<(Vec<Token>, usize), QueryError> {
    let mut tokens = Vec::new();
    let mut input = Input::new(text);
    let mut columns = Columns::new(text);
    loop {
        let Ok((rest, ())) = skip(input) else {
            return Err(bad_char(&input));
        };
        input = rest;
        if input.fragment().is_empty() {
            tokens.push(Token {
                kind: TokenKind::Eof,
                text: String::new(),
                span: columns.span(&input, 0),
            });
            return Ok((tokens, columns.scanned));
        }
        let start = input;
        let (rest, kind, text) = if let Ok((rest, t)) = number(input) {
            (rest, TokenKind::Number, t.fragment().to_string())
        } else if let Ok((rest, t)) = word(input) {
            (rest, TokenKind::Word, t.fragment().to_string())
        } else if let Ok((rest, t)) = punct(input) {
            (rest, TokenKind::Punct, t.fragment().to_string())
        } else if let Ok((rest, s)) = string(input) {
            let Some((value, len)) = s else {
                return Err(QueryError::Syntax {
                    span: span_of(&start, start.fragment().len()),
                    message: "unterminated string (close it with the same quote)".into(),
                });
            };
            (
                rest,
                TokenKind::Str(value),
                start.fragment()[..len].to_string(),
            )
        } else {
            return Err(bad_char(&input));
        };
        tokens.push(Token {
            kind,
            span: columns.span(&start, text.len()),
            text,
        });
        input = rest;
    }
}

fn bad_char(input: &Input<'_>) -> QueryError {
    let c = input.fragment().chars().next().unwrap_or(' ');
    QueryError::Syntax {
        span: span_of(input, c.len_utf8()),
        message: format!(
            "unexpected character '{c}' (strings need quotes, statements end with ';')"
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn positions_and_strings() {
        let t = lex("use 'a\\'b'\n  (1.5, -2e3)").unwrap();
        assert_eq!(t[1].kind, TokenKind::Str("a'b".into()));
        assert_eq!(t[2].span.line, 2);
        assert_eq!(t[2].span.column, 3);
        assert_eq!(t[5].text, "-2e3");
    }

    /// Columns counted incrementally are the characters since the line
    /// start, plus one, for every token (multi-byte text, several lines).
    #[test]
    fn columns_count_characters_from_the_line_start() {
        let text =
            "FIND rooms WHERE name = 'Küche' AND x = 1\n  AND area > 1; -- é\n\nNAME 3 AS \"Büro\"";
        for t in lex(text).unwrap() {
            let before = &text[..t.span.offset];
            let line_start = before.rfind('\n').map_or(0, |i| i + 1);
            assert_eq!(
                t.span.column,
                text[line_start..t.span.offset].chars().count() + 1,
                "{t:?}"
            );
            assert_eq!(t.span.line as usize, before.matches('\n').count() + 1);
        }
    }

    /// Issue 21, defect 7: splitting 1 M `;` took over 15 s (columns were
    /// counted by scanning back to the line start for every token). Every
    /// byte is now looked at once however the text is laid out: the work
    /// is counted, not timed.
    #[test]
    fn issue_21_defect_7_splitting_statements_is_linear() {
        let one_line = ";".repeat(1_000_000);
        let many_lines = "FIND rooms; -- x\n".repeat(20_000);
        let wide = format!("{}\n{}", "; ".repeat(200_000), "SHOW MAPS;".repeat(10));
        for text in [one_line.as_str(), many_lines.as_str(), wide.as_str()] {
            let (tokens, scanned) = lex_counting(text).unwrap();
            assert!(scanned <= text.len(), "{scanned} > {}", text.len());
            assert!(tokens.len() > 20_000);
        }
    }

    #[test]
    fn errors_point_at_the_character() {
        let e = lex("FIND rooms WHERE name = \"x").unwrap_err();
        assert_eq!(e.span().unwrap().offset, 24);
        let e = lex("FIND @").unwrap_err();
        assert_eq!(e.span().unwrap().column, 6);
    }
}
