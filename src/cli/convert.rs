//! `nrgdb convert IN OUT`: between IndoorGML, model JSON and GeoJSON.

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use miette::{IntoDiagnostic, WrapErr};
use nrgdb::format::{self, Declared, FileKind, ModelFormat};
use nrgdb::{indoorgml, ingest};

/// Arguments of `nrgdb convert`.
#[derive(Debug, clap::Args)]
#[command(
    after_help = "Formats by extension (the input's also by its content): .gml/.xml IndoorGML 1.0.3 (1.1 with --indoorgml-version 1.1; 1.0.x and 1.1 read), \
.indoor.json IndoorJSON2 (the IndoorGML 2.0 draft's JSON encoding, draft 0.1), \
.json the model's JSON form, .geojson a GeoJSON FeatureCollection (metres in the map frame).\n\
IndoorGML to IndoorGML keeps the whole document (3D geometry, every layer, inter-layer connections); \
any other conversion goes through the 2D model, written with walked connection lengths \
(IndoorGML Transitions and GeoJSON connection lines are the walked paths through the doorways)."
)]
pub struct Args {
    /// The file to read.
    pub input: PathBuf,
    /// The file to write (replaced atomically).
    pub output: PathBuf,
    /// Refuse input files larger than this many bytes.
    #[arg(long, default_value_t = indoorgml::DEFAULT_MAX_BYTES)]
    pub max_bytes: u64,
    /// Write the output even when the model (or document) stays invalid
    /// for `nrgdb check`; refused by default.
    #[arg(long)]
    pub allow_invalid: bool,
    /// IndoorGML version of a .gml/.xml output: 1.0.3 or 1.1 (default:
    /// the input's version for IndoorGML to IndoorGML, else 1.0.3).
    #[arg(long, value_name = "VERSION")]
    pub indoorgml_version: Option<indoorgml::IndoorGmlVersion>,
}

/// Runs `nrgdb convert`.
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let to = ModelFormat::of(&args.output).into_diagnostic()?;
    let bytes = format::read_bytes(&args.input, args.max_bytes).into_diagnostic()?;
    let name = args.input.to_string_lossy();
    let from = format::detect_model(&Declared::name(&name), &bytes).into_diagnostic()?;
    if from == ModelFormat::IndoorGml && to == ModelFormat::IndoorGml {
        let kind = FileKind::Model(from);
        let doc = format::utf8_text(&bytes, &args.input, kind)
            .into_diagnostic()
            .and_then(|text| indoorgml::read_str(text).into_diagnostic())
            .wrap_err_with(|| format!("cannot read {}", args.input.display()))?;
        refuse_findings(&args, &indoorgml::check(&doc))?;
        let version = args.indoorgml_version.unwrap_or(doc.version);
        indoorgml::write_file_as(&doc, version, &args.output).into_diagnostic()?;
        writeln!(
            out,
            "wrote {} ({} cells, {} boundaries, {} layers)",
            args.output.display(),
            doc.cells().len(),
            doc.boundaries().len(),
            doc.layers().len()
        )
        .into_diagnostic()?;
        return Ok(ExitCode::SUCCESS);
    }
    let (nrg, fixes) = format::model_from_bytes(&bytes, from, &args.input).into_diagnostic()?;
    let label = args.input.display().to_string();
    let valid = ingest::validate(nrg, &label, args.allow_invalid).into_diagnostic()?;
    super::report_repairs(&label, &valid.repairs, &valid.kept);
    let nrg = valid.nrg;
    let version = args.indoorgml_version.unwrap_or_default();
    format::write_model_as(&nrg, &args.output, version).into_diagnostic()?;
    super::report_fixes(&fixes, out)?;
    writeln!(
        out,
        "wrote {} ({} spaces, {} connections)",
        args.output.display(),
        nrg.spaces().len(),
        nrg.connections().len()
    )
    .into_diagnostic()?;
    Ok(ExitCode::SUCCESS)
}

/// IndoorGML to IndoorGML copies the document as it is (3D geometry and
/// all), so findings cannot be repaired there: refused unless
/// `--allow-invalid`, which copies them along with a warning.
fn refuse_findings(args: &Args, findings: &[indoorgml::Finding]) -> miette::Result<()> {
    let Some(first) = findings.first() else {
        return Ok(());
    };
    let input = args.input.display();
    if args.allow_invalid {
        eprintln!(
            "warning: {input}: copied with {} of `nrgdb check` (--allow-invalid); the first: {first}",
            nrgdb::wording::count(findings.len(), "finding", "findings")
        );
        return Ok(());
    }
    miette::bail!(
        help = "`nrgdb check {input}` lists them; convert to .json for a repaired 2D model, \
                or give --allow-invalid to copy the document as it is",
        "{input}: {} of `nrgdb check`, the first: {first}; not written",
        nrgdb::wording::count(findings.len(), "finding", "findings")
    )
}
