//! `nrgdb check FILE`: a conformance report for a model file. IndoorGML is
//! checked as it is written; model JSON, GeoJSON and IndoorJSON2 are read
//! and their IndoorGML form checked (the same checks the ingest gate runs,
//! `nrgdb::ingest::findings`), without repairing anything first.

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use miette::IntoDiagnostic;
use nrgdb::format::{self, Declared, FileKind, ModelFormat};
use nrgdb::indoorgml::check::schema::{self, SchemaVerdict};
use nrgdb::indoorgml::{self, Finding};

/// Arguments of `nrgdb check`.
#[derive(Debug, clap::Args)]
#[command(
    after_help = "Checks: dangling or mistyped xlink:hrefs, duality that does not point back, \
connects that are not mutual or name non-States, inter-layer connections (OGC ETS Req 4), \
unclosed / self-intersecting / wrongly oriented polygons, solids without surfaces (Req 1), \
cells overlapping inside one layer (Req 2), thick and thin doors mixed (Req 5-7), and \
XSD validity when the OGC schema validator (validate.sh, NRGDB_SHARED) is available. \
Model JSON, GeoJSON and IndoorJSON2 files are checked in their IndoorGML form, as `import` \
and `convert` would see them before any repair (no XSD: the schema is IndoorGML's).\n\n\
Exit status: 0 clean, 1 findings, 2 the file could not be checked."
)]
pub struct Args {
    /// The model file: IndoorGML (1.0.1, 1.0.2 or 1.0.3; 2D or 3D), model
    /// JSON, GeoJSON or IndoorJSON2 (told by name and content).
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
    let bytes = format::read_bytes(&args.file, args.max_bytes).into_diagnostic()?;
    let name = args.file.to_string_lossy();
    let kind = format::detect(&Declared::name(&name), &bytes);
    match kind {
        Ok(FileKind::Model(ModelFormat::IndoorGml)) | Err(_) => {
            // Read again as a document (with line numbers): not twice in memory.
            drop(bytes);
            check_indoorgml(&args, &mut findings, &mut notes)?
        }
        Ok(FileKind::Model(model)) => {
            match format::model_from_bytes_in(&bytes, model, &args.file, None) {
                Ok(read) => {
                    findings.extend(nrgdb::ingest::findings(&read.nrg));
                    notes.push(format!(
                        "schema: not checked: the file is {}; its IndoorGML form was checked",
                        FileKind::Model(model)
                    ));
                }
                Err(e) => findings.push(unreadable(e.to_string())),
            }
        }
        Ok(other) => {
            return Err(miette::miette!(
                "{}: is {other}, not a model file; `nrgdb check` reads IndoorGML, model JSON, \
GeoJSON and IndoorJSON2 (extract a map first: `nrgdb extract MAP.yaml --out model.gml`)",
                args.file.display()
            ));
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

/// The checks of an IndoorGML file: as read, then against the OGC schema.
fn check_indoorgml(
    args: &Args,
    findings: &mut Vec<Finding>,
    notes: &mut Vec<String>,
) -> miette::Result<()> {
    match indoorgml::read_file(&args.file, args.max_bytes) {
        Ok(doc) => findings.extend(indoorgml::check(&doc)),
        Err(
            e @ (indoorgml::IndoorGmlError::Io { .. } | indoorgml::IndoorGmlError::TooLarge { .. }),
        ) => {
            return Err(e).into_diagnostic();
        }
        Err(e) => findings.push(unreadable(e.to_string())),
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
    Ok(())
}

/// The finding for a file that could not be read as what it claims to be.
fn unreadable(message: String) -> Finding {
    Finding {
        code: "unreadable",
        element: String::new(),
        line: 0,
        message,
    }
}
