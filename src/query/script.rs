//! Scripts: a text of `;`-separated statements (an `.nrgq` file, `nrgdb
//! query -f`) split and parsed one statement at a time, so a syntax error
//! in one statement does not stop the statements before it from running.
//! Uses the parser and [`Session`]; knows nothing of files or terminals.

use super::error::{QueryError, Span};
use super::parser::{MAX_STATEMENTS, parse};
use super::result::QueryResult;
use super::session::Session;
use super::source::Source;

/// One statement of a script, as text, with where it starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StatementText<'a> {
    /// The statement, without its terminating `;`.
    pub text: &'a str,
    /// Byte offset of its first character in the script.
    pub offset: usize,
    /// 1-based line of its first non-blank character.
    pub line: u32,
    /// 1-based column (in characters) of `offset`.
    pub column: usize,
}

/// What to do after a statement fails (psql's `ON_ERROR_STOP`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum OnError {
    /// Stop at the first failed statement (the default).
    #[default]
    Stop,
    /// Report the error and run the remaining statements.
    KeepGoing,
}

/// One statement run by [`Session::run_script`]: where it starts and what
/// it gave. Syntax errors carry spans in the whole script's coordinates.
#[derive(Debug)]
pub struct ScriptStep {
    /// 1-based line where the statement starts.
    pub line: u32,
    /// Its answer or its error.
    pub result: Result<QueryResult, QueryError>,
}

/// Splits a script at the `;`s outside strings and `--` comments, skipping
/// statements that hold only blanks and comments. Linear in the text.
///
/// ```
/// let s = nrgdb::query::split_statements("SHOW MAPS;\n-- x;\nFIND rooms WHERE name = ';'");
/// assert_eq!(s.len(), 2);
/// assert_eq!((s[1].line, s[1].text.trim()), (3, "FIND rooms WHERE name = ';'"));
/// ```
pub fn split_statements(text: &str) -> Vec<StatementText<'_>> {
    let mut out = Vec::new();
    let (mut line, mut column) = (1u32, 1usize);
    // Where the current statement's first non-blank character is.
    let mut first: Option<(usize, u32, usize)> = None;
    let mut quote: Option<char> = None;
    let (mut escaped, mut comment) = (false, false);
    let mut chars = text.char_indices().peekable();
    let mut push = |end: usize, first: &mut Option<(usize, u32, usize)>| {
        if let Some((offset, line, column)) = first.take() {
            out.push(StatementText {
                text: &text[offset..end],
                offset,
                line,
                column,
            });
        }
    };
    while let Some((i, c)) = chars.next() {
        if comment {
            comment = c != '\n';
        } else if let Some(q) = quote {
            if escaped {
                escaped = false;
            } else if c == '\\' {
                escaped = true;
            } else if c == q {
                quote = None;
            }
        } else if c == ';' {
            push(i, &mut first);
        } else if c == '-' && chars.peek().is_some_and(|(_, n)| *n == '-') {
            comment = true;
        } else if !c.is_whitespace() {
            first.get_or_insert((i, line, column));
            if c == '"' || c == '\'' {
                quote = Some(c);
            }
        }
        if c == '\n' {
            line = line.saturating_add(1);
            column = 1;
        } else {
            column += 1;
        }
    }
    push(text.len(), &mut first);
    out
}

/// Moves a syntax error's span from a statement's own coordinates to the
/// script's.
fn shift(error: QueryError, at: &StatementText<'_>) -> QueryError {
    match error {
        QueryError::Syntax { span, message } => QueryError::Syntax {
            span: Span {
                offset: span.offset + at.offset,
                len: span.len,
                line: span.line.saturating_add(at.line - 1),
                column: if span.line == 1 {
                    span.column + at.column - 1
                } else {
                    span.column
                },
            },
            message,
        },
        other => other,
    }
}

impl<S: Source> Session<S> {
    /// Runs a script statement by statement, handing each result to `step`
    /// as soon as it is known. With [`OnError::Stop`] the first failed
    /// statement (a syntax error included) ends the run; with
    /// [`OnError::KeepGoing`] every statement runs. Returns how many
    /// statements failed.
    pub fn run_script(
        &mut self,
        text: &str,
        on_error: OnError,
        mut step: impl FnMut(ScriptStep),
    ) -> usize {
        let mut failed = 0;
        for (n, statement) in split_statements(text).iter().enumerate() {
            let result = if n == MAX_STATEMENTS {
                Err(QueryError::Syntax {
                    span: Span {
                        offset: statement.offset,
                        len: statement.text.len().max(1),
                        line: statement.line,
                        column: statement.column,
                    },
                    message: format!("at most {MAX_STATEMENTS} statements a request or file"),
                })
            } else {
                self.run_statement_text(statement)
            };
            let stop = result.is_err() && (on_error == OnError::Stop || n >= MAX_STATEMENTS);
            failed += usize::from(result.is_err());
            step(ScriptStep {
                line: statement.line,
                result,
            });
            if stop {
                break;
            }
        }
        failed
    }

    fn run_statement_text(
        &mut self,
        statement: &StatementText<'_>,
    ) -> Result<QueryResult, QueryError> {
        let parsed = parse(statement.text).map_err(|e| shift(e, statement))?;
        match parsed.as_slice() {
            [one] => self.execute_statement(one),
            _ => Err(QueryError::Syntax {
                span: Span {
                    offset: statement.offset,
                    len: statement.text.len().max(1),
                    line: statement.line,
                    column: statement.column,
                },
                message: "expected one statement".into(),
            }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::query::{MemorySource, demo};

    #[test]
    fn splits_outside_strings_and_comments() {
        let s = split_statements("A 'x;y'; -- c;\n  B \"\\\";\" ;\n\n;  ");
        let texts: Vec<_> = s.iter().map(|s| s.text.trim()).collect();
        assert_eq!(texts, ["A 'x;y'", "B \"\\\";\""]);
        assert_eq!((s[1].line, s[1].column), (2, 3));
    }

    #[test]
    fn syntax_error_spans_are_in_script_coordinates() {
        let mut source = MemorySource::new();
        source.insert_with_note("demo", demo::building(2), "demo");
        let mut session = Session::with_default_map(source).unwrap();
        let text = "SHOW MAPS;\n\nFIND rooms ORDRE BY area;\nSHOW MAPS;";
        let mut steps = Vec::new();
        let failed = session.run_script(text, OnError::KeepGoing, |s| steps.push(s));
        assert_eq!((failed, steps.len()), (1, 3));
        let e = steps[1].result.as_ref().unwrap_err();
        assert!(e.to_string().starts_with("3:12: "), "{e}");
        assert_eq!(e.span().unwrap().offset, text.find("ORDRE").unwrap());
        let mut steps = 0;
        assert_eq!(session.run_script(text, OnError::Stop, |_| steps += 1), 1);
        assert_eq!(steps, 2);
    }
}
