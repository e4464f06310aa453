//! `nrgdb check FILE.gml`: a conformance report for an IndoorGML file.

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use miette::IntoDiagnostic;
use nrgdb::indoorgml::check::schema::{self, SchemaVerdict};
use nrgdb::indoorgml::{self, Finding};

/// Arguments of `nrgdb check`.
#[derive(Debug, clap::Args)]
#[command(
    after_help = "Checks: dangling or mistyped xlink:hrefs, duality that does not point back, \
connects that are not mutual or name non-States, inter-layer connections (OGC ETS Req 4), \
unclosed / self-intersecting / wrongly oriented polygons, solids without surfaces (Req 1), \
cells overlapping inside one layer (Req 2), thick and thin doors mixed (Req 5-7), and \
XSD validity when the OGC schema validator (validate.sh, NRGDB_SHARED) is available.\n\n\
Exit status: 0 clean, 1 findings, 2 the file could not be checked."
)]
pub struct Args {
    /// The IndoorGML file (1.0.1, 1.0.2 or 1.0.3; 2D or 3D).
    pub file: PathBuf,
    /// Print the findings as JSON.
    #[arg(long)]
    pub json: bool,
    /// Skip XSD validation.
    #[arg(long)]
    pub no_schema: bool,
    /// Refuse files larger than this many bytes.
    #[arg(long, default_value_t = indoorgml::DEFAULT_MAX_BYTES)]
    pub max_bytes: u64,
}

/// Runs `nrgdb check`.
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let mut findings: Vec<Finding> = Vec::new();
    let mut notes = Vec::new();
    match indoorgml::read_file(&args.file, args.max_bytes) {
        Ok(doc) => findings.extend(indoorgml::check(&doc)),
        Err(
            e @ (indoorgml::IndoorGmlError::Io { .. } | indoorgml::IndoorGmlError::TooLarge { .. }),
        ) => {
            return Err(e).into_diagnostic();
        }
        Err(e) => findings.push(Finding {
            code: "unreadable",
            element: String::new(),
            line: 0,
            message: e.to_string(),
        }),
    }
    if !args.no_schema {
        match schema::validate(&args.file) {
            SchemaVerdict::Valid => {
                notes.push("schema: valid against IndoorGML 1.0.3 (OGC XSD)".to_string())
            }
            SchemaVerdict::Invalid(errors) => findings.extend(errors),
            SchemaVerdict::Unavailable(why) => notes.push(format!("schema: not checked: {why}")),
        }
    }
    let findings = indoorgml::tidy(findings);
    if args.json {
        let report = serde_json::json!({
            "file": args.file,
            "clean": findings.is_empty(),
            "findings": findings,
            "notes": notes,
        });
        writeln!(
            out,
            "{}",
            serde_json::to_string_pretty(&report).into_diagnostic()?
        )
        .into_diagnostic()?;
    } else {
        for f in &findings {
            writeln!(out, "{}: {f}", args.file.display()).into_diagnostic()?;
        }
        for n in &notes {
            writeln!(out, "{n}").into_diagnostic()?;
        }
        let verdict = if findings.is_empty() {
            "clean".to_string()
        } else {
            nrgdb::wording::count(findings.len(), "finding", "findings")
        };
        writeln!(out, "{}: {verdict}", args.file.display()).into_diagnostic()?;
    }
    Ok(if findings.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}
