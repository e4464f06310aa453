//! `nrgdb repl`: an interactive query shell. Reedline glue only: the
//! language, planning and rendering live in `nrgdb::query::Session`.

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::{Arc, Mutex};
use std::time::Instant;

use miette::IntoDiagnostic;
use nrgdb::query::{
    Format, HELP, KEYWORDS, ShellCommand, TokenKind, Vocabulary, format_message, lex,
};
use nu_ansi_term::{Color, Style};
use reedline::{
    ColumnarMenu, Completer, CompletionResult, DefaultHinter, DefaultPrompt, DefaultPromptSegment,
    Emacs, FileBackedHistory, Highlighter, KeyCode, KeyModifiers, MenuBuilder, Reedline,
    ReedlineEvent, ReedlineMenu, Signal, Span, StyledText, Suggestion, ValidationResult, Validator,
    default_emacs_keybindings,
};

use super::query::{SourceArgs, open_session, query_report};

/// Start an interactive query shell: statements end with ';' (Enter on an
/// unfinished statement continues it on the next line), Tab completes
/// keywords and space names and ids, `\help` lists the commands.
#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(flatten)]
    pub source: SourceArgs,
    /// History file (default: $XDG_DATA_HOME/nrgdb/history, else
    /// ~/.nrgdb_history; none when neither is known).
    #[arg(long, value_name = "FILE")]
    pub history: Option<PathBuf>,
}

/// The history file: the argument, the data dir, or ~/.nrgdb_history.
fn history_path(arg: Option<PathBuf>) -> Option<PathBuf> {
    if arg.is_some() {
        return arg;
    }
    let nonempty = |k: &str| {
        std::env::var_os(k)
            .filter(|v| !v.is_empty())
            .map(PathBuf::from)
    };
    if let Some(data) = nonempty("XDG_DATA_HOME") {
        let dir = data.join("nrgdb");
        if std::fs::create_dir_all(&dir).is_ok() {
            return Some(dir.join("history"));
        }
    }
    nonempty("HOME").map(|h| h.join(".nrgdb_history"))
}

/// Offers what [`Vocabulary::complete`] finds (map names after `USE`).
struct QueryCompleter {
    words: Arc<Mutex<Vocabulary>>,
}

impl Completer for QueryCompleter {
    fn complete(&mut self, line: &str, pos: usize) -> CompletionResult {
        let vocabulary = self.words.lock().map(|w| w.clone()).unwrap_or_default();
        let (start, words) = vocabulary.complete(line, pos);
        let end = pos.min(line.len()).max(start);
        let out: Vec<Suggestion> = words
            .into_iter()
            .map(|value| Suggestion {
                value,
                span: Span::new(start, end),
                append_whitespace: true,
                ..Suggestion::default()
            })
            .collect();
        CompletionResult::fresh(out)
    }
}

/// Colours keywords, numbers, strings and comments.
struct QueryHighlighter;

impl Highlighter for QueryHighlighter {
    fn highlight(&self, line: &str, _cursor: usize) -> StyledText {
        let mut styled = StyledText::new();
        let Ok(tokens) = lex(line) else {
            styled.push((Style::new(), line.to_string()));
            return styled;
        };
        let mut at = 0;
        for t in tokens {
            let (start, end) = (t.span.offset, t.span.offset + t.span.len);
            if start > at {
                let gap = &line[at..start];
                let style = if gap.contains("--") {
                    Style::new().fg(Color::DarkGray)
                } else {
                    Style::new()
                };
                styled.push((style, gap.to_string()));
            }
            let style = match &t.kind {
                TokenKind::Word if KEYWORDS.iter().any(|k| k.eq_ignore_ascii_case(&t.text)) => {
                    Style::new().bold().fg(Color::LightBlue)
                }
                TokenKind::Number => Style::new().fg(Color::Magenta),
                TokenKind::Str(_) => Style::new().fg(Color::Green),
                _ => Style::new(),
            };
            styled.push((style, line.get(start..end).unwrap_or_default().to_string()));
            at = end;
        }
        if at < line.len() {
            styled.push((Style::new().fg(Color::DarkGray), line[at..].to_string()));
        }
        styled
    }
}

/// A statement is complete when it ends with ';' (or is a `\` command).
struct StatementValidator;

impl Validator for StatementValidator {
    fn validate(&self, line: &str) -> ValidationResult {
        let t = line.trim();
        if t.is_empty() || t.starts_with('\\') || t.ends_with(';') {
            ValidationResult::Complete
        } else {
            ValidationResult::Incomplete
        }
    }
}

/// Runs `nrgdb repl`.
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let mut session = open_session(&args.source)?;
    let words = Arc::new(Mutex::new(Vocabulary::of(&session)));
    let mut keybindings = default_emacs_keybindings();
    keybindings.add_binding(
        KeyModifiers::NONE,
        KeyCode::Tab,
        ReedlineEvent::UntilFound(vec![
            ReedlineEvent::Menu("completion_menu".to_string()),
            ReedlineEvent::MenuNext,
        ]),
    );
    let mut editor = Reedline::create()
        .with_completer(Box::new(QueryCompleter {
            words: Arc::clone(&words),
        }))
        .with_menu(ReedlineMenu::EngineCompleter(Box::new(
            ColumnarMenu::default().with_name("completion_menu"),
        )))
        .with_edit_mode(Box::new(Emacs::new(keybindings)))
        .with_highlighter(Box::new(QueryHighlighter))
        .with_hinter(Box::new(
            DefaultHinter::default().with_style(Style::new().italic().fg(Color::DarkGray)),
        ))
        .with_validator(Box::new(StatementValidator));
    if let Some(path) = history_path(args.history) {
        match FileBackedHistory::with_file(1000, path.clone()) {
            Ok(history) => editor = editor.with_history(Box::new(history)),
            Err(e) => eprintln!("note: no history file ({}): {e}", path.display()),
        }
    }
    let prompt = DefaultPrompt::new(
        DefaultPromptSegment::Basic("nrgdb".to_string()),
        DefaultPromptSegment::Empty,
    );
    writeln!(out, "nrgdb query shell; \\help for help, \\quit to leave").into_diagnostic()?;
    if let Some(rev) = session.current() {
        writeln!(out, "map '{}' revision {}", rev.map, rev.revision).into_diagnostic()?;
    }
    let (mut timing, mut format) = (false, Format::Table);
    loop {
        let line = match editor.read_line(&prompt).into_diagnostic()? {
            Signal::Success(line) => line,
            Signal::CtrlC => continue,
            _ => break,
        };
        let text = line.trim();
        match (text, ShellCommand::parse(text)) {
            ("", _) => continue,
            (_, Some(ShellCommand::Quit)) => break,
            (_, Some(ShellCommand::Help)) => writeln!(out, "{HELP}").into_diagnostic()?,
            (_, Some(ShellCommand::Timing)) => {
                timing = !timing;
                writeln!(out, "timing {}", if timing { "on" } else { "off" }).into_diagnostic()?;
            }
            (_, Some(ShellCommand::Format(f))) => {
                format = f;
                writeln!(out, "{}", format_message(f)).into_diagnostic()?;
            }
            (t, None) if t.starts_with('\\') => {
                writeln!(out, "unknown command {t} (\\help lists them)").into_diagnostic()?;
            }
            _ => {
                let started = Instant::now();
                match session.run(text, format) {
                    Ok(answer) => out.write_all(answer.as_bytes()).into_diagnostic()?,
                    Err(e) => eprintln!("{:?}", query_report(e, "input", text)),
                }
                if timing {
                    writeln!(out, "time: {:.3} ms", started.elapsed().as_secs_f64() * 1e3)
                        .into_diagnostic()?;
                }
                if let Ok(mut w) = words.lock() {
                    *w = Vocabulary::of(&session);
                }
            }
        }
        out.flush().into_diagnostic()?;
    }
    Ok(ExitCode::SUCCESS)
}
