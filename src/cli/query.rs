//! `nrgdb query`: run query statements against a model and print the answers.

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Duration;

use miette::{IntoDiagnostic, LabeledSpan, NamedSource, WrapErr, miette};
use nrgdb::query::{
    Format, Limits, MemorySource, OnError, QueryError, QueryResult, Session, Source, demo,
};

/// Where the model comes from, shared by `query` and `repl`.
#[derive(Debug, Clone, clap::Args)]
pub struct SourceArgs {
    /// Database of map revisions, an SQLite file or a PostgreSQL URL
    /// (`nrgdb import` fills it; default `$NRGDB_DB`, else ./nrgdb.sqlite
    /// when it exists).
    #[arg(long, value_name = "DB")]
    pub db: Option<String>,
    /// A model file (.json, .gml or .geojson), queried in memory as map
    /// `model` (or the name given with --map).
    #[arg(long, value_name = "FILE", conflicts_with = "db")]
    pub model: Option<PathBuf>,
    /// Use the built-in demo building (rooms along a corridor, named
    /// Kitchen, Library, Lounge, Office, Printer Room) with this many
    /// corridor segments, as map `demo`.
    #[arg(long, value_name = "SEGMENTS", conflicts_with_all = ["db", "model"])]
    pub demo: Option<usize>,
    /// The map to query (default: the first map).
    #[arg(long, value_name = "M")]
    pub map: Option<String>,
    /// The revision to query (default: the latest).
    #[arg(long, value_name = "N", requires = "map")]
    pub rev: Option<u64>,
    /// Time bound per statement, in milliseconds.
    #[arg(long, value_name = "MS", default_value_t = 5000)]
    pub timeout_ms: u64,
    /// Most rows a statement may return.
    #[arg(long, value_name = "N", default_value_t = 10_000)]
    pub max_rows: usize,
    /// Who corrections (MERGE, SPLIT, …) are recorded as made by
    /// [default: $USER].
    #[arg(long, env = "NRGDB_AUTHOR")]
    pub author: Option<String>,
}

/// Run query statements (ROUTE, FIND, NEIGHBOURS, LOCATE, REACHABLE, SHOW,
/// USE, NAME, EXPLAIN) and print the answers. Exit code 1 when every answer
/// is empty (no rows, no route).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The statements, separated by ';' (e.g. 'ROUTE FROM "Kitchen" TO room 13').
    #[arg(required_unless_present = "file", conflicts_with = "file")]
    pub query: Option<String>,
    /// `nrgdb query MODEL QUERY`: a model file before the statements is
    /// read as `--model MODEL` (what a user coming from `extract --out`
    /// types first).
    #[arg(hide = true)]
    pub then: Option<String>,
    /// Read the statements from a file (e.g. queries/*.nrgq; lines starting
    /// with '#' are ignored).
    #[arg(short = 'f', long = "file", value_name = "FILE.nrgq")]
    pub file: Option<PathBuf>,
    #[command(flatten)]
    pub source: SourceArgs,
    /// Print JSON (one document per statement).
    #[arg(long, conflicts_with = "csv")]
    pub json: bool,
    /// Print CSV with a header row.
    #[arg(long)]
    pub csv: bool,
    /// Run every statement even when some fail (each error is reported
    /// with its file:line; the exit status is still 2). By default the
    /// first failed statement stops the run, like psql's ON_ERROR_STOP.
    #[arg(long)]
    pub keep_going: bool,
}

/// Builds the source the arguments name. The one place that knows which
/// storage backs a session.
pub fn open_source(args: &SourceArgs) -> miette::Result<Box<dyn Source>> {
    // $NRGDB_DB is read here rather than by clap, so that a set variable
    // does not conflict with --model or --demo (only --db does).
    let chosen = args.model.is_some() || args.demo.is_some();
    let from_env = std::env::var("NRGDB_DB").ok().filter(|v| !v.is_empty());
    let default_db = "nrgdb.sqlite";
    let db = args.db.clone().or_else(|| {
        if chosen {
            None
        } else {
            from_env.or_else(|| {
                std::path::Path::new(default_db)
                    .exists()
                    .then(|| default_db.to_string())
            })
        }
    });
    if let Some(db) = db {
        let store = nrgdb::store::Store::open_existing_db(&db).into_diagnostic()?;
        return Ok(Box::new(store));
    }
    let mut source = MemorySource::new();
    if let Some(path) = &args.model {
        let nrg = nrgdb::format::read_model(path, nrgdb::indoorgml::DEFAULT_MAX_BYTES)
            .into_diagnostic()?;
        let name = args.map.clone().unwrap_or_else(|| "model".to_string());
        source.insert_with_note(&name, nrg, &format!("loaded from {}", path.display()));
    } else if let Some(segments) = args.demo {
        source.insert_with_note("demo", demo::building(segments), "built-in demo building");
    }
    Ok(Box::new(source))
}

/// Opens a session on the map and revision the arguments select.
pub fn open_session(args: &SourceArgs) -> miette::Result<Session<Box<dyn Source>>> {
    let source = open_source(args)?;
    let mut session = Session::with_default_map(source).into_diagnostic()?;
    session.set_author(super::db::author(args.author.clone()));
    if let Some(map) = &args.map {
        session.use_map(map, args.rev).into_diagnostic()?;
    }
    session.set_limits(Limits {
        timeout: Duration::from_millis(args.timeout_ms),
        max_rows: args.max_rows,
        // At least one statement's worth, whatever --max-rows says.
        max_total_rows: Limits::default().max_total_rows.max(args.max_rows),
        deadline: None,
    });
    Ok(session)
}

/// A query error as a miette report; syntax errors get the source text and
/// a caret under the offending token.
pub fn query_report(error: QueryError, name: &str, text: &str) -> miette::Report {
    match error.span() {
        Some(span) => {
            let message = match &error {
                QueryError::Syntax { message, .. } => message.clone(),
                other => other.to_string(),
            };
            let end = (span.offset + span.len.max(1)).min(text.len());
            let start = span.offset.min(end);
            miette!(
                labels = vec![LabeledSpan::at(start..end.max(start), "here")],
                "syntax error at line {}, column {}: {message}",
                span.line,
                span.column
            )
            .with_source_code(NamedSource::new(name, text.to_string()))
        }
        None => miette!("{error}"),
    }
}

/// Drops the golden-file lines (starting with '#') from an .nrgq text,
/// keeping line numbers.
pub fn strip_hash_lines(text: &str) -> String {
    text.lines()
        .map(|l| {
            if l.trim_start().starts_with('#') {
                ""
            } else {
                l
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// Runs `nrgdb query`.
pub fn run(mut args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    if let Some(statements) = args.then.take() {
        let first = args.query.take().unwrap_or_default();
        let source = &args.source;
        if source.model.is_some() || source.db.is_some() || source.demo.is_some() {
            return Err(miette!(
                "give the statements as one argument (separated by ';'): the model or database \
is already named by --model, --db or --demo, so `{first}` is not taken as one"
            ));
        }
        if !std::path::Path::new(&first).is_file() {
            return Err(miette!(
                "`{first}` is not a model file; give the statements as one argument, separated \
by ';' (e.g. nrgdb query --model lab.json 'FIND rooms; ROUTE FROM 3 TO 7')"
            ));
        }
        args.source.model = Some(first.into());
        args.query = Some(statements);
    }
    let (name, text) = match (&args.query, &args.file) {
        (Some(q), _) => ("query".to_string(), q.clone()),
        (None, Some(path)) => {
            let text = std::fs::read_to_string(path)
                .into_diagnostic()
                .wrap_err_with(|| format!("cannot read {}", path.display()))?;
            (path.display().to_string(), strip_hash_lines(&text))
        }
        (None, None) => return Err(miette!("give a query or -f FILE.nrgq")),
    };
    let format = if args.json {
        Format::Json
    } else if args.csv {
        Format::Csv
    } else {
        Format::Table
    };
    let mut session = open_session(&args.source)?;
    let on_error = if args.keep_going {
        OnError::KeepGoing
    } else {
        OnError::Stop
    };
    let (mut any, mut ran) = (false, 0usize);
    let mut written = Ok(());
    let mut first_error = None;
    let failed = session.run_script(&text, on_error, |step| {
        ran += 1;
        match step.result {
            Ok(result) => {
                any |= match &result {
                    QueryResult::Table(t) => !t.rows.is_empty(),
                    QueryResult::Routes(r) => !r.is_empty(),
                    _ => true,
                };
                if written.is_ok() {
                    written = out.write_all(result.render(format).as_bytes());
                }
            }
            Err(e) => {
                let report = query_report(e, &name, &text)
                    .wrap_err(format!("{name}:{}: statement failed", step.line));
                if args.keep_going {
                    eprintln!("{report:?}");
                } else {
                    first_error = Some(report);
                }
            }
        }
    });
    written.into_diagnostic()?;
    if let Some(report) = first_error {
        return Err(report);
    }
    if failed > 0 {
        return Err(miette!(
            "{failed} of {} failed (see above)",
            nrgdb::wording::count(ran, "statement", "statements")
        ));
    }
    Ok(if any {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}
