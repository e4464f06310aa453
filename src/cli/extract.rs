//! `nrgdb extract`: occupancy grid map → NRG (graph JSON, label PNG, timings).

use nrgdb::wording::count;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use miette::{IntoDiagnostic, WrapErr};
use nrgdb::extract::{ExtractParams, Extraction, Method, extract};
use nrgdb::format::{FileKind, ModelFormat, PictureFormat};
use nrgdb::grid::{LoadOptions, OccupancyGrid, load_image, load_map};
use nrgdb::render::{RenderOptions, Scene};
use nrgdb::route::{WalkedModel, walked_model};

use super::progress;
use super::render::write_picture;

/// Map input options shared by `extract` and `eval`.
#[derive(Debug, clap::Args)]
pub struct MapArgs {
    /// The map(s): ROS map_server YAMLs, bare PGM/PNG images with --resolution,
    /// or folders (every .yaml in them).
    #[arg(required_unless_present = "print_params", value_name = "MAP")]
    pub maps: Vec<PathBuf>,
    /// Metres per pixel for a bare image (ignored for a YAML).
    #[arg(long)]
    pub resolution: Option<f64>,
    /// A pixel is free iff its grey (after negate) is at least this.
    #[arg(long, default_value_t = 250)]
    pub free_min_grey: u8,
    /// Refuse images with more pixels than this.
    #[arg(long, default_value_t = 64 * 1024 * 1024)]
    pub max_pixels: u64,
    /// Parameters file (TOML: `[building]`, `[output]` and `[internals]`
    /// tables of ExtractParams, or their keys on their own; flags below
    /// override it).
    #[arg(long)]
    pub params: Option<PathBuf>,
    /// Segmentation method: watershed (paper Exp. II, default) or ccl (Exp. I).
    #[arg(long)]
    pub method: Option<Method>,
    /// Passages narrower than twice this (m) separate spaces.
    #[arg(long)]
    pub core_radius: Option<f64>,
    /// Widest doorway (m); wider borders are open connections.
    #[arg(long)]
    pub door_width_max: Option<f64>,
    /// Free space narrower than twice this (m) is noise (LiDAR rays).
    #[arg(long)]
    pub noise_radius: Option<f64>,
    /// Spaces smaller than this (m²) merge into a neighbour.
    #[arg(long)]
    pub min_room_area: Option<f64>,
    /// Any parameter of ExtractParams as KEY=VALUE (a TOML value), KEY
    /// as `group.key` or the bare key, e.g. `--set furniture_max_m=0`,
    /// `--set internals.door_constriction=0.8` or `--set
    /// working_resolution_m=0.1`; repeatable, applied last, checked together.
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// Print the parameters in effect (defaults, --params, flags, --set)
    /// as a parameters file and stop; no map is needed.
    #[arg(long)]
    pub print_params: bool,
}

impl MapArgs {
    /// The input maps: each file given, and every `.yaml` of each folder
    /// given (sorted by name).
    pub fn inputs(&self) -> miette::Result<Vec<PathBuf>> {
        let mut out = Vec::new();
        for path in &self.maps {
            if !path.is_dir() {
                out.push(path.clone());
                continue;
            }
            let entries = std::fs::read_dir(path)
                .into_diagnostic()
                .wrap_err_with(|| format!("{}: cannot list the folder", path.display()))?;
            let mut found: Vec<PathBuf> = entries
                .filter_map(Result::ok)
                .map(|e| e.path())
                .filter(|p| is_yaml(p))
                .collect();
            if found.is_empty() {
                miette::bail!("{}: no .yaml map in this folder", path.display());
            }
            found.sort();
            out.extend(found);
        }
        Ok(out)
    }

    /// Loads one map and resolves the parameters.
    pub fn load(&self, map: &Path) -> miette::Result<(OccupancyGrid, ExtractParams)> {
        let opts = LoadOptions {
            free_min_grey: self.free_min_grey,
            max_pixels: self.max_pixels,
        };
        let grid = if is_yaml(map) {
            load_map(map, &opts).into_diagnostic()?
        } else {
            let res = self.resolution.ok_or_else(|| {
                miette::miette!(
                    "{}: a bare image needs --resolution (metres per pixel)",
                    map.display()
                )
            })?;
            load_image(map, res, &opts).into_diagnostic()?
        };
        Ok((grid, self.params()?))
    }

    /// The parameters in effect: the defaults, the `--params` file, the
    /// flags and `--set`, in that order, checked together.
    pub fn params(&self) -> miette::Result<ExtractParams> {
        let mut params = match &self.params {
            Some(p) => {
                let text = std::fs::read_to_string(p)
                    .into_diagnostic()
                    .wrap_err_with(|| {
                        format!("{}: cannot read the parameters file", p.display())
                    })?;
                ExtractParams::from_toml(&text)
                    .into_diagnostic()
                    .wrap_err_with(|| format!("{}: invalid parameters", p.display()))?
            }
            None => ExtractParams::default(),
        };
        if let Some(m) = self.method {
            params.method = m;
        }
        if let Some(v) = self.core_radius {
            params.internals.core_radius_m = v;
        }
        if let Some(v) = self.door_width_max {
            params.building.door_width_max_m = v;
        }
        if let Some(v) = self.noise_radius {
            params.building.noise_radius_m = v;
        }
        if let Some(v) = self.min_room_area {
            params.building.min_room_area_m2 = v;
        }
        apply_sets(params, &self.set)
    }
}

/// Whether a path names a ROS map YAML (by its extension: a folder's
/// maps are listed without reading every file; `nrgdb::format` decides).
pub fn is_yaml(path: &Path) -> bool {
    FileKind::by_extension(&path.to_string_lossy()) == Some(FileKind::MapYaml)
}

/// Applies `--set KEY=VALUE` overrides to `params` in order (see
/// [`ExtractParams::set`]: `group.key` or the bare key; unknown keys are
/// refused with the list of known ones).
pub(crate) fn apply_sets(
    mut params: ExtractParams,
    sets: &[String],
) -> miette::Result<ExtractParams> {
    for set in sets {
        let Some((key, value)) = set.split_once('=') else {
            miette::bail!("--set {set}: expected KEY=VALUE, e.g. --set furniture_max_m=0");
        };
        params
            .set(key.trim(), value)
            .into_diagnostic()
            .wrap_err_with(|| format!("--set {set}"))?;
    }
    params.validate().into_diagnostic()?;
    Ok(params)
}

/// `params` as a TOML parameters file, its groups explained.
pub(crate) fn params_file(params: &ExtractParams) -> miette::Result<String> {
    let body = toml::to_string_pretty(params).into_diagnostic()?;
    Ok(format!(
        "# nrgdb extraction parameters (lengths in metres, areas in m²).\n\
         # [building]: what the building and its sensor are like; change these for a building.\n\
         # [output]: how the spaces are drawn.\n\
         # [internals]: thresholds of the method's rules; change them to study the method.\n\
         {body}"
    ))
}

/// Extracts an IndoorGML NRG (rooms, corridors, doors, connections) from an occupancy grid map.
///
/// With several maps (or a folder), give `--out-dir DIR`: each map's outputs
/// are written there as `<stem>.<format>` for each of `--formats`.
#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(flatten)]
    pub map: MapArgs,
    /// Write the NRG in the format its extension names: .gml IndoorGML 1.0.3
    /// (schema-valid, thick doors), .json the model, .geojson GeoJSON,
    /// .indoor.json IndoorJSON2 (a draft).
    #[arg(long, value_name = "FILE.gml")]
    pub out: Option<PathBuf>,
    /// Write the graph as JSON (the model's form plus each space's pixel_centroid [col,row]).
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Write a 16-bit grey PNG of the map's size: each pixel its space id, 0 elsewhere.
    #[arg(long)]
    pub labels: Option<PathBuf>,
    /// Write a picture of the NRG over its map (.png or .svg; see `nrgdb render`).
    #[arg(long, value_name = "FILE.png|FILE.svg")]
    pub png: Option<PathBuf>,
    /// Folder for the outputs of several maps (created if missing).
    #[arg(long, value_name = "DIR")]
    pub out_dir: Option<PathBuf>,
    /// What to write per map into --out-dir: gml, json, labels (`<stem>_labels.png`), png, svg.
    #[arg(
        long,
        value_delimiter = ',',
        default_value = "gml,json",
        value_name = "LIST"
    )]
    pub formats: Vec<OutputFormat>,
    /// Print each stage's time.
    #[arg(long)]
    pub timings: bool,
    /// Write the model even when it stays geometrically invalid after
    /// repair (`nrgdb check` would report it); refused by default.
    #[arg(long)]
    pub allow_invalid: bool,
}

/// One output of a batch extraction.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum OutputFormat {
    /// IndoorGML 1.0.3, `<stem>.gml`.
    Gml,
    /// The graph as JSON, `<stem>.json`.
    Json,
    /// The label image, `<stem>_labels.png`.
    Labels,
    /// A picture, `<stem>.png`.
    Png,
    /// A picture, `<stem>.svg`.
    Svg,
}

/// Runs `nrgdb extract`.
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    if args.map.print_params {
        write!(out, "{}", params_file(&args.map.params()?)?).into_diagnostic()?;
        return Ok(ExitCode::SUCCESS);
    }
    let inputs = args.map.inputs()?;
    if inputs.len() > 1 || args.out_dir.is_some() {
        return run_batch(&args, &inputs, out);
    }
    let Some(map) = inputs.first() else {
        miette::bail!("no map given (nrgdb extract MAP.yaml)");
    };
    // A wrong output name fails before the work.
    let out_format = args
        .out
        .as_deref()
        .map(ModelFormat::of)
        .transpose()
        .into_diagnostic()?;
    let spinner = progress::spinner(format!("extracting {}", map.display()));
    let (grid, params) = args.map.load(map)?;
    let (x, walked) = extract_walked(&grid, &params, map, args.allow_invalid)?;
    spinner.finish_and_clear();
    // Encode everything before writing anything, so a failure leaves no half output.
    let gml = out_format.map(|f| nrgdb::format::render(&walked, f));
    let json = args.json.as_ref().map(|_| x.to_json());
    let png = match &args.labels {
        Some(_) => Some(
            x.labels_png()
                .into_diagnostic()
                .wrap_err("cannot encode the label image")?,
        ),
        None => None,
    };
    let picture_format = args
        .png
        .as_deref()
        .map(PictureFormat::of)
        .transpose()
        .into_diagnostic()?;
    if let (Some(path), Some(gml)) = (&args.out, gml) {
        write_out(path, gml.as_bytes())?;
    }
    if let (Some(path), Some(json)) = (&args.json, json) {
        write_out(path, json.as_bytes())?;
    }
    if let (Some(path), Some(png)) = (&args.labels, png) {
        write_out(path, &png)?;
    }
    if let (Some(path), Some(format)) = (&args.png, picture_format) {
        picture(path, format, &x, &grid, map)?;
    }
    summary(&x, out).into_diagnostic()?;
    if args.timings {
        let mut total = std::time::Duration::ZERO;
        for (stage, t) in &x.timings {
            writeln!(out, "{stage:>10}  {:8.2} ms", t.as_secs_f64() * 1e3).into_diagnostic()?;
            total += *t;
        }
        writeln!(out, "{:>10}  {:8.2} ms", "total", total.as_secs_f64() * 1e3).into_diagnostic()?;
    }
    Ok(ExitCode::SUCCESS)
}

/// Extracts `grid`, passes its model through the geometric gate (repairs
/// are said on stderr; a model still invalid is refused unless
/// `allow_invalid`) and gives it walked connection lengths, with the
/// walked paths for the IndoorGML output.
fn extract_walked(
    grid: &OccupancyGrid,
    params: &ExtractParams,
    map: &Path,
    allow_invalid: bool,
) -> miette::Result<(Extraction, WalkedModel)> {
    let mut x = extract(grid, params)
        .into_diagnostic()
        .wrap_err_with(|| format!("{}: extraction failed", map.display()))?;
    let label = map.display().to_string();
    let valid = nrgdb::ingest::validate(x.nrg, &label, allow_invalid).into_diagnostic()?;
    super::report_repairs(&label, &valid.repairs, &valid.kept);
    let walked = walked_model(&valid.nrg);
    x.nrg = walked.nrg.clone();
    Ok((x, walked))
}

/// Draws the extraction over its map.
fn picture(
    path: &Path,
    format: PictureFormat,
    x: &Extraction,
    grid: &OccupancyGrid,
    map: &Path,
) -> miette::Result<()> {
    let options = RenderOptions {
        title: map.file_name().map(|n| n.to_string_lossy().into_owned()),
        ..RenderOptions::default()
    };
    let scene = Scene {
        nrg: &x.nrg,
        map: Some(grid),
        route: None,
        diff: None,
        options: &options,
    };
    write_picture(path, format, &scene)
}

/// Extracts several maps into `--out-dir`, with a progress bar on a
/// terminal. A map that fails is reported and skipped; the exit code is 2
/// when any failed.
fn run_batch(args: &Args, inputs: &[PathBuf], out: &mut dyn Write) -> miette::Result<ExitCode> {
    if args.out.is_some() || args.json.is_some() || args.labels.is_some() || args.png.is_some() {
        miette::bail!(
            "--out, --json, --labels and --png name one file each: with several maps use \
             --out-dir DIR --formats gml,json,labels,png,svg"
        );
    }
    let Some(dir) = &args.out_dir else {
        miette::bail!(
            "{} maps given: say where their outputs go with --out-dir DIR (and --formats)",
            inputs.len()
        );
    };
    let stems: Vec<String> = inputs
        .iter()
        .map(|p| {
            p.file_stem()
                .map_or_else(|| "map".to_string(), |s| s.to_string_lossy().into_owned())
        })
        .collect();
    for (i, s) in stems.iter().enumerate() {
        if let Some(j) = stems[..i].iter().position(|t| t == s) {
            miette::bail!(
                "{} and {} would both write {s}.*: give maps with different file names",
                inputs[j].display(),
                inputs[i].display()
            );
        }
    }
    std::fs::create_dir_all(dir)
        .into_diagnostic()
        .wrap_err_with(|| format!("{}: cannot create the output folder", dir.display()))?;
    let bar = progress::bar(inputs.len() as u64, "extract");
    let mut failed = 0usize;
    for (map, stem) in inputs.iter().zip(&stems) {
        bar.set_message(stem.clone());
        match extract_into(args, map, dir, stem) {
            Ok(x) => {
                let mut line = Vec::new();
                write!(line, "{stem}: ").into_diagnostic()?;
                summary(&x, &mut line).into_diagnostic()?;
                bar.suspend(|| out.write_all(&line)).into_diagnostic()?;
            }
            Err(e) => {
                failed += 1;
                bar.suspend(|| eprintln!("{stem}: {e:?}"));
            }
        }
        bar.inc(1);
    }
    bar.finish_and_clear();
    writeln!(
        out,
        "{} of {} maps extracted into {}",
        inputs.len() - failed,
        inputs.len(),
        dir.display()
    )
    .into_diagnostic()?;
    Ok(if failed == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(2)
    })
}

/// Extracts one map of a batch and writes its outputs.
fn extract_into(args: &Args, map: &Path, dir: &Path, stem: &str) -> miette::Result<Extraction> {
    let (grid, params) = args.map.load(map)?;
    let (x, walked) = extract_walked(&grid, &params, map, args.allow_invalid)?;
    for format in &args.formats {
        match format {
            OutputFormat::Gml => write_out(
                &dir.join(format!("{stem}.gml")),
                nrgdb::format::render(&walked, ModelFormat::IndoorGml).as_bytes(),
            )?,
            OutputFormat::Json => {
                write_out(&dir.join(format!("{stem}.json")), x.to_json().as_bytes())?
            }
            OutputFormat::Labels => {
                let png = x
                    .labels_png()
                    .into_diagnostic()
                    .wrap_err("cannot encode the label image")?;
                write_out(&dir.join(format!("{stem}_labels.png")), &png)?;
            }
            OutputFormat::Png => picture(
                &dir.join(format!("{stem}.png")),
                PictureFormat::Png,
                &x,
                &grid,
                map,
            )?,
            OutputFormat::Svg => picture(
                &dir.join(format!("{stem}.svg")),
                PictureFormat::Svg,
                &x,
                &grid,
                map,
            )?,
        }
    }
    Ok(x)
}

fn write_out(path: &Path, bytes: &[u8]) -> miette::Result<()> {
    nrgdb::atomic::write(path, bytes)
        .into_diagnostic()
        .wrap_err_with(|| format!("{}: cannot write", path.display()))
}

fn summary(x: &Extraction, out: &mut dyn Write) -> std::io::Result<()> {
    let of = |k: &str| {
        x.nrg
            .spaces()
            .iter()
            .filter(|s| s.kind.as_str() == k)
            .count()
    };
    writeln!(
        out,
        "{}: {}, {}, {}; {}",
        count(x.nrg.spaces().len(), "space", "spaces"),
        count(of("room"), "room", "rooms"),
        count(of("corridor"), "corridor", "corridors"),
        count(of("door"), "door", "doors"),
        count(x.nrg.connections().len(), "connection", "connections")
    )
}
