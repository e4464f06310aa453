//! `nrgdb map-log`: build an occupancy map from a CARMEN log with
//! corrected poses.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use miette::{IntoDiagnostic, WrapErr};
use nrgdb::sim::{OccupancyRule, map_carmen_log, write_map};

/// Build an occupancy map (known poses) from a CARMEN laser log
/// (FLASER or ROBOTLASER1 lines; plain or .gz) and write map.yaml + map.pgm
/// (or NAME.yaml + NAME.pgm for `--out NAME.yaml`).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The CARMEN log, e.g. intel-corrected.log.gz.
    pub log: PathBuf,
    /// Map resolution in metres per cell.
    #[arg(long, default_value_t = 0.05)]
    pub resolution: f64,
    /// Output directory (created if missing; map.yaml + map.pgm in it), or
    /// the map YAML to write (`aces.yaml`: aces.yaml + aces.pgm beside it).
    #[arg(long, default_value = "map")]
    pub out: PathBuf,
    /// Longer readings are cut here and only clear free space (metres).
    #[arg(long, default_value_t = 20.0)]
    pub max_range: f64,
    /// What makes a cell occupied: `hit-ratio` (a quarter of the beams
    /// reaching it end in it, as GMapping's maps; unknown under two beams)
    /// or `log-odds` (the paper's Eq. 3: later beams outweigh earlier ones,
    /// so walls grazed late in a log are cleared).
    #[arg(long, value_enum, default_value_t = Rule::HitRatio)]
    pub rule: Rule,
}

/// `--rule`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Rule {
    /// Occupied when at least a quarter of the beams reaching a cell end in it.
    HitRatio,
    /// Log-odds updates (the simulator's mapper).
    LogOdds,
}

/// The folder and file stem `--out` names: a `.yaml`/`.yml` path is the
/// map YAML itself, anything else a folder for `map.yaml` + `map.pgm`.
fn destination(out: &Path) -> (PathBuf, String) {
    let is_yaml = out
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("yaml") || e.eq_ignore_ascii_case("yml"));
    match (is_yaml, out.file_stem().and_then(|s| s.to_str())) {
        (true, Some(stem)) if !stem.is_empty() => (
            out.parent()
                .filter(|p| !p.as_os_str().is_empty())
                .map_or_else(|| PathBuf::from("."), Path::to_path_buf),
            stem.to_string(),
        ),
        _ => (out.to_path_buf(), "map".to_string()),
    }
}

/// Runs the subcommand.
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let rule = match args.rule {
        Rule::HitRatio => OccupancyRule::RECORDED,
        Rule::LogOdds => OccupancyRule::LogOdds,
    };
    let built = map_carmen_log(&args.log, args.resolution, args.max_range, rule)
        .into_diagnostic()
        .wrap_err_with(|| format!("cannot map {}", args.log.display()))?;
    let (dir, stem) = destination(&args.out);
    let [yaml, pgm] = write_map(&dir, &stem, &built.map)
        .into_diagnostic()
        .wrap_err_with(|| format!("cannot write the map to {}", args.out.display()))?;
    let m = &built.map;
    writeln!(
        out,
        "mapped {} scans, {} beams: {} x {} px at {} m/px ({:.1} m x {:.1} m, origin [{:.3}, {:.3}])",
        built.scans,
        built.beams,
        m.width,
        m.height,
        m.resolution_m,
        f64::from(m.width) * m.resolution_m,
        f64::from(m.height) * m.resolution_m,
        m.origin_m[0],
        m.origin_m[1]
    )
    .into_diagnostic()?;
    writeln!(out, "wrote map yaml: {}", yaml.display()).into_diagnostic()?;
    writeln!(out, "wrote map image: {}", pgm.display()).into_diagnostic()?;
    Ok(ExitCode::SUCCESS)
}
