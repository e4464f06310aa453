//! The interactive shell's language-side parts: its help text, its
//! backslash commands (apart from the query language) and Tab completion.
//! Uses [`Session`] and [`Source`]; the terminal glue (reedline) lives in
//! the binary.

use super::ast::quote;
use super::parser::KEYWORDS;
use super::result::Format;
use super::session::Session;
use super::source::Source;

/// What `\help` prints: every statement of the language and the commands.
pub const HELP: &str = "\
statements end with ';' and may span lines; -- starts a comment
  ROUTE FROM a TO b [VIA c, ...] [AVOID d, ...] [ALTERNATIVES k]
        [WITH CLEARANCE r, MIN_DOOR_WIDTH w, SPEED v]
  NEIGHBOURS OF a [DEPTH n]
  FIND rooms|corridors|doors|others|spaces [WHERE ...] [ORDER BY ...] [LIMIT n]
  LOCATE (x, y)            REACHABLE FROM a WITHIN metres [WITH ...]
  SHOW MAPS                SHOW REVISIONS [OF m]
  USE m [AT REVISION n]    NAME a AS \"Kitchen\"
  DIFF r1 r2               (what changed from revision r1 to r2 of the map)
  EXPLAIN <statement>
corrections (each a new revision, kept and re-applied when the map is re-imported):
  MERGE a, b [, ...] [AS \"Lobby\"]
  SPLIT a ALONG (x1, y1) TO (x2, y2) [WITH DOOR (x, y) [WIDTH w]]
  ADD DOOR BETWEEN a AND b AT (x, y) [WIDTH w]    REMOVE DOOR d
  SET a KIND room|corridor|other    SET a ATTRIBUTE key = value    UNSET a ATTRIBUTE key
a reference is an id (12, room 12), a \"name\" or a point (x, y) in metres
commands: \\help  \\timing (toggle)  \\json  \\csv  \\table  \\quit";

/// A backslash command of the shell.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ShellCommand {
    /// `\help`, `\h`, `\?`.
    Help,
    /// `\quit`, `\q`, `\exit`.
    Quit,
    /// `\timing`: toggle printing how long each statement took.
    Timing,
    /// `\json`, `\csv`, `\table`: the format of the answers.
    Format(Format),
}

impl ShellCommand {
    /// The command `line` names, `None` for an unknown one.
    pub fn parse(line: &str) -> Option<ShellCommand> {
        Some(match line.trim() {
            "\\help" | "\\h" | "\\?" => ShellCommand::Help,
            "\\q" | "\\quit" | "\\exit" => ShellCommand::Quit,
            "\\timing" => ShellCommand::Timing,
            "\\json" => ShellCommand::Format(Format::Json),
            "\\csv" => ShellCommand::Format(Format::Csv),
            "\\table" => ShellCommand::Format(Format::Table),
            _ => return None,
        })
    }
}

/// What a format switch says it did.
pub fn format_message(format: Format) -> &'static str {
    match format {
        Format::Json => "answers as JSON (\\table to switch back)",
        Format::Csv => "answers as CSV (\\table to switch back)",
        Format::Table => "answers as tables",
    }
}

/// The words Tab may offer: keywords, the maps, and the selected
/// revision's space names (quoted) and ids. A snapshot, refreshed after
/// each statement.
#[derive(Debug, Clone, Default)]
pub struct Vocabulary {
    /// Map names.
    pub maps: Vec<String>,
    /// Space names (quoted) and ids of the selected revision.
    pub spaces: Vec<String>,
}

impl Vocabulary {
    /// The vocabulary of a session now.
    pub fn of<S: Source>(session: &Session<S>) -> Vocabulary {
        let maps = session
            .source()
            .maps()
            .map(|m| m.into_iter().map(|m| m.name).collect())
            .unwrap_or_default();
        let mut spaces = Vec::new();
        if let Some(rev) = session.current() {
            let all = rev.nrg.spaces();
            spaces.extend(all.iter().filter_map(|s| s.name.as_deref().map(quote)));
            spaces.extend(all.iter().map(|s| s.id.to_string()));
        }
        Vocabulary { maps, spaces }
    }

    /// Completions of the word ending at byte `pos` of `line`: its start
    /// and the candidates. After `USE` or `REVISIONS OF` only map names
    /// are offered (all of them when nothing is typed yet).
    ///
    /// ```
    /// use nrgdb::query::Vocabulary;
    /// let v = Vocabulary { maps: vec!["office_g".into()], spaces: vec!["3".into()] };
    /// assert_eq!(v.complete("USE of", 6), (4, vec!["office_g".to_string()]));
    /// assert_eq!(v.complete("USE ", 4), (4, vec!["office_g".to_string()]));
    /// assert!(v.complete("rou", 3).1.contains(&"ROUTE".to_string()));
    /// ```
    pub fn complete(&self, line: &str, pos: usize) -> (usize, Vec<String>) {
        let mut pos = pos.min(line.len());
        while !line.is_char_boundary(pos) {
            pos -= 1;
        }
        let start = line[..pos]
            .rfind(|c: char| c.is_whitespace() || c == ',' || c == '(' || c == ';')
            .map_or(0, |i| i + 1);
        let prefix = line[start..pos].trim_start_matches('"').to_lowercase();
        let before: Vec<String> = line[..start]
            .split_whitespace()
            .rev()
            .take(2)
            .map(str::to_uppercase)
            .collect();
        let wants_map = match before.as_slice() {
            [w, ..] if w == "USE" => true,
            [of, revisions, ..] => of == "OF" && revisions == "REVISIONS",
            _ => false,
        };
        let words: Vec<&String> = if wants_map {
            self.maps.iter().collect()
        } else if prefix.is_empty() {
            Vec::new()
        } else {
            self.spaces.iter().collect()
        };
        let keywords = KEYWORDS.iter().map(|k| k.to_string());
        // Inside quotes only names complete, not keywords.
        let quoted = line[start..pos].starts_with('"');
        let candidates = if wants_map || quoted {
            words.into_iter().cloned().collect::<Vec<_>>()
        } else {
            keywords.chain(words.into_iter().cloned()).collect()
        };
        let out = candidates
            .into_iter()
            .filter(|w| w.trim_matches('"').to_lowercase().starts_with(&prefix))
            .filter(|_| wants_map || !prefix.is_empty())
            .collect();
        (start, out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::query::{MemorySource, demo};

    #[test]
    fn use_completes_map_names_and_help_lists_every_statement() {
        let mut source = MemorySource::new();
        source.insert_with_note("office_g", demo::building(2), "demo");
        let session = Session::with_default_map(source).unwrap();
        let v = Vocabulary::of(&session);
        assert_eq!(v.complete("use OF", 6).1, ["office_g"]);
        assert_eq!(v.complete("SHOW REVISIONS OF ", 18).1, ["office_g"]);
        assert!(v.complete("FIND rooms WHERE name = \"Ki", 27).1[0].contains("Kitchen"));
        for keyword in crate::query::STATEMENT_KEYWORDS {
            assert!(
                HELP.contains(keyword) || keyword == "NEIGHBORS",
                "{keyword}"
            );
        }
        assert_eq!(
            ShellCommand::parse("\\json"),
            Some(ShellCommand::Format(Format::Json))
        );
    }
}
