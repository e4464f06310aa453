//! `nrgdb extract`: occupancy grid map → NRG (graph JSON, label PNG, timings).

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use miette::{IntoDiagnostic, WrapErr};
use nrgdb::extract::{ExtractParams, Extraction, Method, extract};
use nrgdb::grid::{LoadOptions, OccupancyGrid, load_image, load_map};

/// Map input options shared by `extract` and `eval`.
#[derive(Debug, clap::Args)]
pub struct MapArgs {
    /// The map: a ROS map_server YAML, or a bare PGM/PNG with --resolution.
    pub map: PathBuf,
    /// Metres per pixel for a bare image (ignored for a YAML).
    #[arg(long)]
    pub resolution: Option<f64>,
    /// A pixel is free iff its grey (after negate) is at least this.
    #[arg(long, default_value_t = 250)]
    pub free_min_grey: u8,
    /// Refuse images with more pixels than this.
    #[arg(long, default_value_t = 64 * 1024 * 1024)]
    pub max_pixels: u64,
    /// Parameters file (TOML, keys of ExtractParams; flags below override it).
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
}

impl MapArgs {
    /// Loads the map and resolves the parameters.
    pub fn load(&self) -> miette::Result<(OccupancyGrid, ExtractParams)> {
        let opts = LoadOptions {
            free_min_grey: self.free_min_grey,
            max_pixels: self.max_pixels,
        };
        let is_yaml = self
            .map
            .extension()
            .and_then(|e| e.to_str())
            .is_some_and(|e| e.eq_ignore_ascii_case("yaml") || e.eq_ignore_ascii_case("yml"));
        let grid = if is_yaml {
            load_map(&self.map, &opts).into_diagnostic()?
        } else {
            let res = self.resolution.ok_or_else(|| {
                miette::miette!(
                    "{}: a bare image needs --resolution (metres per pixel)",
                    self.map.display()
                )
            })?;
            load_image(&self.map, res, &opts).into_diagnostic()?
        };
        let mut params = match &self.params {
            Some(p) => {
                let text = std::fs::read_to_string(p)
                    .into_diagnostic()
                    .wrap_err_with(|| {
                        format!("{}: cannot read the parameters file", p.display())
                    })?;
                toml::from_str::<ExtractParams>(&text)
                    .into_diagnostic()
                    .wrap_err_with(|| format!("{}: invalid parameters", p.display()))?
            }
            None => ExtractParams::default(),
        };
        if let Some(m) = self.method {
            params.method = m;
        }
        if let Some(v) = self.core_radius {
            params.core_radius_m = v;
        }
        if let Some(v) = self.door_width_max {
            params.door_width_max_m = v;
        }
        if let Some(v) = self.noise_radius {
            params.noise_radius_m = v;
        }
        if let Some(v) = self.min_room_area {
            params.min_room_area_m2 = v;
        }
        Ok((grid, params))
    }
}

/// Extracts an IndoorGML NRG (rooms, corridors, doors, connections) from an occupancy grid map.
#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(flatten)]
    pub map: MapArgs,
    /// Write the NRG as IndoorGML 1.0.3 (schema-valid, thick doors).
    #[arg(long, value_name = "FILE.gml")]
    pub out: Option<PathBuf>,
    /// Write the graph as JSON (the model's form plus each space's pixel_centroid [col,row]).
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Write a 16-bit grey PNG of the map's size: each pixel its space id, 0 elsewhere.
    #[arg(long)]
    pub labels: Option<PathBuf>,
    /// Print each stage's time.
    #[arg(long)]
    pub timings: bool,
}

/// Runs `nrgdb extract`.
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let (grid, params) = args.map.load()?;
    let x = extract(&grid, &params)
        .into_diagnostic()
        .wrap_err_with(|| format!("{}: extraction failed", args.map.map.display()))?;
    // Encode everything before writing anything, so a failure leaves no half output.
    let gml = args
        .out
        .as_ref()
        .map(|_| nrgdb::indoorgml::write_string(&nrgdb::indoorgml::from_nrg(&x.nrg)));
    let json = args.json.as_ref().map(|_| x.to_json());
    let png = match &args.labels {
        Some(_) => Some(
            x.labels_png()
                .into_diagnostic()
                .wrap_err("cannot encode the label image")?,
        ),
        None => None,
    };
    if let (Some(path), Some(gml)) = (&args.out, gml) {
        write_out(path, gml.as_bytes())?;
    }
    if let (Some(path), Some(json)) = (&args.json, json) {
        write_out(path, json.as_bytes())?;
    }
    if let (Some(path), Some(png)) = (&args.labels, png) {
        write_out(path, &png)?;
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

fn write_out(path: &Path, bytes: &[u8]) -> miette::Result<()> {
    nrgdb::atomic::write(path, bytes)
        .into_diagnostic()
        .wrap_err_with(|| format!("{}: cannot write", path.display()))
}

fn summary(x: &Extraction, out: &mut dyn Write) -> std::io::Result<()> {
    let count = |k: &str| {
        x.nrg
            .spaces()
            .iter()
            .filter(|s| s.kind.as_str() == k)
            .count()
    };
    writeln!(
        out,
        "{} spaces: {} rooms, {} corridors, {} doors; {} connections",
        x.nrg.spaces().len(),
        count("room"),
        count("corridor"),
        count("door"),
        x.nrg.connections().len()
    )
}
