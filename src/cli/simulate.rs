//! `nrgdb simulate`: generate a building, drive a simulated LiDAR robot
//! through it, map it, and write the map with its ground truth.

use nrgdb::wording::count;
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use miette::{IntoDiagnostic, WrapErr};
use nrgdb::sim::{SimParams, simulate, write_simulation};

/// Simulate a building and a robot with a 2D LiDAR mapping it (log-odds,
/// known poses). Writes map.yaml + map.pgm (ROS), map_gt.png (room ground
/// truth in the IPA format) and truth.json (the true spaces and doors).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Seed of the building and the sensor noise; the same seed gives the
    /// same files.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Output directory (created if missing).
    #[arg(long, default_value = "sim")]
    pub out: PathBuf,
    /// Map resolution in metres per cell.
    #[arg(long, default_value_t = 0.05)]
    pub resolution: f64,
    /// Put furniture boxes into rooms (clutter).
    #[arg(long)]
    pub furniture: bool,
    /// Add diagonal building wings (non-Manhattan walls).
    #[arg(long)]
    pub non_manhattan: bool,
    /// Put what real robot maps show into rooms: rows of shelves with
    /// door-wide aisles, desk clusters with chairs, a counter and a table.
    #[arg(long)]
    pub clutter: bool,
    /// A furnished house instead of an office floor: an open-plan living
    /// area (sofa, kitchen counter, dining table) with bedrooms and
    /// bathrooms opening off it. A house has one living area, so no wings
    /// to turn: `--non-manhattan` is refused with it.
    #[arg(long, conflicts_with = "non_manhattan")]
    pub house: bool,
    /// Turn the whole building by this many degrees (counter-clockwise):
    /// a robot's map seldom lies square to the walls.
    #[arg(
        long,
        value_name = "DEG",
        default_value_t = 0.0,
        allow_negative_numbers = true
    )]
    pub heading: f64,
    /// A building of this many levels (2 to 50): the same plan on each, one robot run per
    /// level, written to `OUT/levelK/` with `OUT/building.toml` for `nrgdb import`.
    #[arg(long, value_name = "N")]
    pub levels: Option<usize>,
}

/// Runs the subcommand.
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let mut params = SimParams::new(args.seed);
    params.resolution_m = args.resolution;
    if args.house {
        params.plan = nrgdb::sim::FloorPlanParams::house(args.seed);
    }
    params.plan.furniture = args.furniture || args.house;
    params.plan.non_manhattan = args.non_manhattan;
    params.plan.clutter = args.clutter;
    params.plan.heading_deg = args.heading;
    if let Some(levels) = args.levels {
        let files = nrgdb::sim::write_storeys(&args.out, &params, levels)
            .into_diagnostic()
            .wrap_err_with(|| {
                format!(
                    "cannot simulate {levels} levels into {}",
                    args.out.display()
                )
            })?;
        writeln!(
            out,
            "simulated seed {}: {levels} levels, stairs at ({:.2}, {:.2}), Lift A at ({:.2}, {:.2})\nwrote building manifest: {}",
            args.seed,
            files.stairs_at[0],
            files.stairs_at[1],
            files.lift_at[0],
            files.lift_at[1],
            files.manifest.display()
        )
        .into_diagnostic()?;
        return Ok(ExitCode::SUCCESS);
    }
    let sim = simulate(&params)
        .into_diagnostic()
        .wrap_err("cannot simulate")?;
    let files = write_simulation(&args.out, &sim)
        .into_diagnostic()
        .wrap_err_with(|| format!("cannot write the simulation to {}", args.out.display()))?;
    let m = &sim.map;
    let p = &sim.plan;
    writeln!(
        out,
        "simulated seed {}: {}, {}, {}, {}",
        args.seed,
        if p.open_plan {
            count(p.corridors.len(), "living area", "living areas")
        } else {
            count(p.corridors.len(), "corridor", "corridors")
        },
        count(p.rooms.len(), "room", "rooms"),
        count(p.doors.len(), "door", "doors"),
        count(p.furniture.len(), "furniture box", "furniture boxes")
    )
    .into_diagnostic()?;
    writeln!(
        out,
        "map {} x {} px at {} m/px ({:.1} m x {:.1} m, origin [{:.3}, {:.3}]) from {} scans, {} beams",
        m.width,
        m.height,
        m.resolution_m,
        f64::from(m.width) * m.resolution_m,
        f64::from(m.height) * m.resolution_m,
        m.origin_m[0],
        m.origin_m[1],
        sim.scans,
        sim.beams
    )
    .into_diagnostic()?;
    for (what, path) in [
        ("map yaml", &files.yaml),
        ("map image", &files.pgm),
        ("ground truth", &files.gt_png),
        ("true NRG", &files.truth_json),
    ] {
        writeln!(out, "wrote {what}: {}", path.display()).into_diagnostic()?;
    }
    Ok(ExitCode::SUCCESS)
}
