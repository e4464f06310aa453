//! Route fidelity over the shared maps and simulated buildings: routes
//! `--pairs` random room pairs per model anchor to anchor with the router
//! of [`router`] and measures each route against the free-space geodesic
//! (`nrgdb::eval::route_fidelity`): length ratio, share of the route outside
//! every space, and pairs only one side could connect. Prints a row per
//! model and the figures per group; `--json` prints everything as JSON.
//!
//! ```text
//! cargo run --release --example route_fidelity [-- MAPS_DIR --pairs 25 --sims 10 --cell 0.025 --gap-px 0 --seed 1 --json]
//! ```
//! Extracted spaces tile the free space exactly (outlines along pixel
//! edges), so `--gap-px 0`, the exact union of the spaces, is the honest
//! setting; `--gap-px N` lets the geodesic bridge gaps of up to `2N` pixels
//! and counts samples within `N` pixels of a space as inside (for models
//! whose spaces do not touch).
//! MAPS_DIR defaults to `$NRGDB_SHARED/maps` (NRGDB_SHARED defaults to
//! `../shared`); every `*.yaml` in it is extracted with the default
//! parameters. Simulated buildings (seeds 1..=`--sims`) are measured twice:
//! the extracted model (`sim<seed>`) and the true plan (`sim<seed>/truth`).

use std::path::{Path, PathBuf};
use std::time::Instant;

use nrgdb::eval::{FidelityReport, FidelitySummary, PairFidelity, route_fidelity_with_gap};
use nrgdb::extract::{ExtractParams, extract};
use nrgdb::grid::{LoadOptions, load_map};
use nrgdb::model::{Nrg, Point};
use nrgdb::route::{Budget, Endpoint, NavMesh, Profile, RouteRequest, shortest_route};
use nrgdb::sim::{SimParams, simulate, write_simulation};
use serde::Serialize;

/// The router under test: the navigation layer at zero clearance, from
/// point to point (the free-space geodesic it should match).
fn router(nrg: &Nrg) -> impl Fn(Point, Point) -> Option<(f64, Vec<Point>)> {
    let nav = NavMesh::new(std::sync::Arc::new(nrg.clone()));
    move |from, to| {
        let mut request = RouteRequest::between(Endpoint::Point(from), Endpoint::Point(to));
        request.profile = Profile::exact();
        let routes = shortest_route(&nav, &request, &Budget::unlimited()).ok()?;
        let route = routes.into_iter().next()?;
        Some((route.length_m, route.waypoints))
    }
}

struct Args {
    dir: PathBuf,
    pairs: usize,
    sims: u64,
    cell_m: f64,
    gap_px: f64,
    seed: u64,
    json: bool,
}

fn parse_args() -> Result<Args, Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let mut dir = None;
    let (mut pairs, mut sims, mut cell_m, mut seed, mut json) = (25, 10, 0.025, 1, false);
    let mut gap_px = 0.0;
    while let Some(a) = args.next() {
        let mut value = || args.next().ok_or(format!("{a} needs a value"));
        match a.as_str() {
            "--pairs" => pairs = value()?.parse()?,
            "--sims" => sims = value()?.parse()?,
            "--cell" => cell_m = value()?.parse()?,
            "--seed" => seed = value()?.parse()?,
            "--gap-px" => gap_px = value()?.parse()?,
            "--json" => json = true,
            s if s.starts_with("--") => return Err(format!("unknown argument {s:?}").into()),
            _ => dir = Some(PathBuf::from(a)),
        }
    }
    let dir = dir.unwrap_or_else(|| {
        let shared = std::env::var("NRGDB_SHARED").unwrap_or_else(|_| "../shared".into());
        Path::new(&shared).join("maps")
    });
    Ok(Args {
        dir,
        pairs,
        sims,
        cell_m,
        gap_px,
        seed,
        json,
    })
}

/// One model's measurement.
#[derive(Serialize)]
struct Row {
    name: String,
    group: &'static str,
    spaces: usize,
    ms: f64,
    report: FidelityReport,
}

#[derive(Serialize)]
struct Output {
    cell_m: f64,
    pairs_per_model: usize,
    seed: u64,
    skipped: Vec<(String, String)>,
    rows: Vec<Row>,
    groups: Vec<(&'static str, FidelitySummary)>,
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args = parse_args()?;
    // (name, group, model, gap to bridge in metres)
    let mut models: Vec<(String, &'static str, Nrg, f64)> = Vec::new();
    let mut skipped = Vec::new();
    let mut names: Vec<PathBuf> = std::fs::read_dir(&args.dir)?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "yaml"))
        .collect();
    names.sort();
    for path in &names {
        let name = path.file_stem().map(|s| s.to_string_lossy().into_owned());
        let name = name.unwrap_or_default();
        let loaded = load_map(path, &LoadOptions::default())
            .map_err(|e| e.to_string())
            .and_then(|g| {
                let x = extract(&g, &ExtractParams::default()).map_err(|e| e.to_string())?;
                Ok((x.nrg, args.gap_px * g.resolution))
            });
        match loaded {
            Ok((nrg, gap_m)) => models.push((name, "shared maps", nrg, gap_m)),
            Err(e) => skipped.push((name, e)),
        }
    }
    let scratch = tempfile::tempdir()?;
    for seed in 1..=args.sims {
        let sim = simulate(&SimParams::new(seed))?;
        let files = write_simulation(scratch.path(), &sim)?;
        let grid = load_map(&files.yaml, &LoadOptions::default())?;
        let x = extract(&grid, &ExtractParams::default())?;
        let gap_m = args.gap_px * grid.resolution;
        models.push((format!("sim{seed}"), "simulated, extracted", x.nrg, gap_m));
        let truth = sim.plan.truth()?;
        models.push((format!("sim{seed}/truth"), "simulated, truth", truth, 0.0));
    }
    if !args.json {
        print_header();
    }
    let mut rows = Vec::new();
    for (name, group, nrg, gap_m) in models {
        let route = router(&nrg);
        let t = Instant::now();
        let (pairs, seed, cell_m) = (args.pairs, args.seed, args.cell_m);
        let report = route_fidelity_with_gap(&nrg, pairs, seed, cell_m, gap_m, &route);
        let row = Row {
            name,
            group,
            spaces: nrg.spaces().len(),
            ms: t.elapsed().as_secs_f64() * 1e3,
            report,
        };
        if !args.json {
            print_row(&row.name, &row.report.summary, row.ms);
            if let Some(e) = &row.report.raster_error {
                println!("    geodesic refused: {e}");
            }
        }
        rows.push(row);
    }
    let mut groups = Vec::new();
    for group in [
        "shared maps",
        "simulated, extracted",
        "simulated, truth",
        "all",
    ] {
        let pairs: Vec<PairFidelity> = rows
            .iter()
            .filter(|r| group == "all" || r.group == group)
            .flat_map(|r| r.report.pairs.iter().cloned())
            .collect();
        groups.push((group, FidelitySummary::of(&pairs)));
    }
    if args.json {
        let out = Output {
            cell_m: args.cell_m,
            pairs_per_model: args.pairs,
            seed: args.seed,
            skipped,
            rows,
            groups,
        };
        println!("{}", serde_json::to_string_pretty(&out)?);
        return Ok(());
    }
    println!();
    for (group, summary) in &groups {
        print_row(group, summary, f64::NAN);
    }
    for (name, e) in &skipped {
        println!("skipped {name}: {e}");
    }
    Ok(())
}

fn print_header() {
    println!(
        "{:<32} {:>5} {:>5} {:>7} {:>7} {:>7} {:>8} {:>8} {:>6} {:>6} {:>8}",
        "model", "pairs", "n", "median", "p90", "max", "outside", "max_out", "1side", "len!=", "ms"
    );
}

fn print_row(name: &str, s: &FidelitySummary, ms: f64) {
    let r = |x: Option<f64>| x.map_or("-".to_string(), |v| format!("{v:.3}"));
    println!(
        "{:<32} {:>5} {:>5} {:>7} {:>7} {:>7} {:>8} {:>8.3} {:>6} {:>6} {:>8.0}",
        name,
        s.pairs,
        s.n,
        r(s.median_ratio),
        r(s.p90_ratio),
        r(s.max_ratio),
        format!("{}/{}", s.routes_outside, s.routes),
        s.max_outside_fraction,
        s.one_sided,
        s.length_mismatches,
        ms
    );
}
