//! The correction statements (`MERGE`, `SPLIT`, `ADD DOOR`, `REMOVE
//! DOOR`, `SET`, `UNSET`) after their first keyword.

use super::Parser;
use crate::model::SpaceKind;
use crate::query::ast::{EditStatement, Value};
use crate::query::error::QueryError;
use crate::query::lexer::TokenKind;

impl Parser {
    /// The rest of a correction statement after its first keyword `kw`.
    pub(super) fn edit(&mut self, kw: &str) -> Result<EditStatement, QueryError> {
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
}
