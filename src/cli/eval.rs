//! `nrgdb eval`: extraction scored against a ground-truth room image, for
//! one map or a folder of maps (with a progress bar on a terminal).

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use miette::{IntoDiagnostic, WrapErr};
use nrgdb::diff::{AlignParams, Alignment, align_grids, alignment_quality};
use nrgdb::eval::{
    DoorReport, Evaluation, GroundTruth, door_report, evaluate, evaluation_picture,
    load_ground_truth, transfer_ground_truth,
};
use nrgdb::extract::extract;
use nrgdb::grid::OccupancyGrid;

use super::extract::MapArgs;
use super::progress;

/// Scores an extraction against a ground truth (IPA room-segmentation recall/precision,
/// doors, connections).
///
/// Several maps or a folder: each map's ground truth is `<stem>_gt.png` beside
/// it; maps without one are skipped. Prints one row per map and the means.
#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(flatten)]
    pub map: MapArgs,
    /// Ground-truth image: rooms white (> 250), doorways closed by dark lines (IPA style)
    /// [default: `<stem>_gt.png` beside the map].
    #[arg(long)]
    pub gt: Option<PathBuf>,
    /// The map the ground truth was drawn on, when it is another map of the
    /// same building (one map only; e.g. MAP built by `nrgdb map-log` from a
    /// robot log): MAP is aligned onto it as `nrgdb diff` aligns revisions,
    /// and the GT's rooms and doorway lines are carried onto MAP's pixels
    /// (rooms only where MAP is free). The GT defaults to `<stem>_gt.png`
    /// beside this map.
    #[arg(long, value_name = "REF.yaml")]
    pub gt_map: Option<PathBuf>,
    /// Print JSON instead of a table.
    #[arg(long)]
    pub json: bool,
    /// Also write a picture of where extraction and ground truth disagree (one map only):
    /// spaces in pale colours and door spaces orange over the map; GT doorway lines green
    /// where a door was found, magenta where none was; each detected door ringed, blue when
    /// it matched a line, red when it matched none.
    #[arg(long, value_name = "FILE.png")]
    pub picture: Option<PathBuf>,
    /// Also list the doors item by item (one map only): each GT doorway line no door
    /// was found at, each detected door that matches no line, and each matched door's
    /// width against its line's length, worst first; places in metres in the map frame.
    /// With --json: under "door_report".
    #[arg(long)]
    pub doors: bool,
    /// Judge a parameter's values leave-one-building-out over the maps
    /// (`--loo door_width_max_m=1.2,1.5,1.8`): each building (a map and its
    /// `_furnitures` copy) gets the value that scores best on the other
    /// buildings, and its score under that value is reported beside the
    /// score of every value (score: the mean F1 of rooms, doors and
    /// connections).
    #[arg(long, value_name = "KEY=V1,V2,...")]
    pub loo: Option<String>,
}

/// Runs `nrgdb eval`.
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    if args.map.print_params {
        let text = super::extract::params_file(&args.map.params()?)?;
        write!(out, "{text}").into_diagnostic()?;
        return Ok(ExitCode::SUCCESS);
    }
    let inputs = args.map.inputs()?;
    if let Some(spec) = &args.loo {
        if args.gt.is_some() || args.gt_map.is_some() || args.picture.is_some() || args.doors {
            miette::bail!(
                "--loo scores every map against the <stem>_gt.png beside it and draws nothing: \
                 leave out --gt, --gt-map, --picture and --doors"
            );
        }
        return super::eval_loo::run(&args.map, spec, args.json, &inputs, out);
    }
    match inputs.as_slice() {
        [map] if !args.map.maps.iter().any(|p| p.is_dir()) => {
            let drawn_on = args.gt_map.as_deref().unwrap_or(map);
            let gt = match &args.gt {
                Some(gt) => gt.clone(),
                None => sibling_gt(drawn_on).ok_or_else(|| {
                    miette::miette!(
                        "{}: no ground truth given and no {} beside it (use --gt GT.png)",
                        drawn_on.display(),
                        gt_name(drawn_on)
                    )
                })?,
            };
            let source = GtSource {
                image: &gt,
                drawn_on: args.gt_map.as_deref(),
            };
            let (e, report, alignment) =
                evaluate_one(&args.map, map, source, args.picture.as_deref(), args.doors)?;
            if let (Some(a), false) = (alignment, args.json) {
                print_alignment(&a, drawn_on, out).into_diagnostic()?;
            }
            print_one(&e, report.as_ref(), alignment.as_ref(), args.json, out).into_diagnostic()?;
            Ok(ExitCode::SUCCESS)
        }
        _ => run_many(&args, &inputs, out),
    }
}

pub(crate) fn gt_name(map: &Path) -> String {
    let stem = map
        .file_stem()
        .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    format!("{stem}_gt.png")
}

/// `<stem>_gt.png` beside the map, when it exists.
pub(crate) fn sibling_gt(map: &Path) -> Option<PathBuf> {
    let path = map.with_file_name(gt_name(map));
    path.is_file().then_some(path)
}

/// Where a map's ground truth comes from.
#[derive(Clone, Copy)]
struct GtSource<'a> {
    /// The GT image.
    image: &'a Path,
    /// The map it was drawn on, when not the evaluated map itself.
    drawn_on: Option<&'a Path>,
}

fn evaluate_one(
    args: &MapArgs,
    map: &Path,
    source: GtSource<'_>,
    picture: Option<&Path>,
    doors: bool,
) -> miette::Result<(Evaluation, Option<DoorReport>, Option<Carried>)> {
    let (grid, params) = args.load(map)?;
    let (gt, alignment) = match source.drawn_on {
        None => (
            load_ground_truth(source.image, &grid).into_diagnostic()?,
            None,
        ),
        Some(reference) => {
            let (gt, a) = carried_ground_truth(args, reference, source.image, map, &grid)?;
            (gt, Some(a))
        }
    };
    let x = extract(&grid, &params)
        .into_diagnostic()
        .wrap_err_with(|| format!("{}: extraction failed", map.display()))?;
    if let Some(path) = picture {
        let img = evaluation_picture(&grid, &gt, &x);
        let mut png = Vec::new();
        img.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
            .into_diagnostic()?;
        nrgdb::atomic::write(path, &png)
            .into_diagnostic()
            .wrap_err_with(|| format!("cannot write {}", path.display()))?;
    }
    Ok((
        evaluate(&gt, &x, grid.resolution),
        doors.then(|| door_report(&gt, &x, &grid)),
        alignment,
    ))
}

/// How a ground truth was carried onto the evaluated map.
#[derive(Debug, Clone, Copy, serde::Serialize)]
struct Carried {
    /// The evaluated map's frame → the GT's map's frame; its `inliers` is
    /// the share of the evaluated map's walls that lie on the GT map's.
    alignment: Alignment,
    /// The share of the GT map's walls that lie on the evaluated map's
    /// (within the same distance): walls the evaluated map has.
    walls_found: f64,
}

/// The GT `image` drawn on the map `reference`, carried onto `grid` (the
/// map `map`) by aligning `grid` onto `reference`.
fn carried_ground_truth(
    args: &MapArgs,
    reference: &Path,
    image: &Path,
    map: &Path,
    grid: &OccupancyGrid,
) -> miette::Result<(GroundTruth, Carried)> {
    let (ref_grid, _) = args.load(reference)?;
    let gt = load_ground_truth(image, &ref_grid).into_diagnostic()?;
    let a = align_grids(&ref_grid, grid, &AlignParams::default())
        .into_diagnostic()
        .wrap_err_with(|| {
            format!(
                "cannot carry the ground truth of {} onto {}",
                reference.display(),
                map.display()
            )
        })?;
    let back = a.transform.inverse();
    let found = alignment_quality(grid, &ref_grid, back, &AlignParams::default());
    let carried = transfer_ground_truth(
        &gt,
        &ref_grid,
        grid,
        |p| a.transform.apply(p),
        |p| back.apply(p),
    );
    Ok((
        carried,
        Carried {
            alignment: a,
            walls_found: found.inliers,
        },
    ))
}

/// Two lines saying how the evaluated map was aligned onto the GT's map
/// and how well their walls agree.
fn print_alignment(c: &Carried, drawn_on: &Path, out: &mut dyn Write) -> std::io::Result<()> {
    let a = &c.alignment;
    let [tx, ty] = a.transform.apply([0.0, 0.0]);
    writeln!(
        out,
        "ground truth carried from {}: turned {:.1}°, moved ({tx:.2}, {ty:.2}) m",
        drawn_on.display(),
        a.transform.rotation_deg(),
    )?;
    writeln!(
        out,
        "walls       {:.1} % of this map's lie within {:.2} m of the GT map's; {:.1} % of the \
         GT map's within {:.2} m of this map's",
        100.0 * a.inliers,
        a.tolerance_m,
        100.0 * c.walls_found,
        a.tolerance_m
    )
}

fn run_many(args: &Args, inputs: &[PathBuf], out: &mut dyn Write) -> miette::Result<ExitCode> {
    if args.gt.is_some() || args.gt_map.is_some() {
        miette::bail!(
            "--gt and --gt-map name one ground truth: with several maps each uses <stem>_gt.png beside it"
        );
    }
    if args.picture.is_some() || args.doors {
        miette::bail!("--picture and --doors are for one map: give a single map");
    }
    let bar = progress::bar(inputs.len() as u64, "eval");
    let mut rows: Vec<(String, Evaluation)> = Vec::new();
    let mut failed = 0usize;
    let mut notes = Vec::new();
    for map in inputs {
        let stem = map
            .file_stem()
            .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
        bar.set_message(stem.clone());
        match sibling_gt(map) {
            None => notes.push(format!("{stem}: skipped, no {} beside it", gt_name(map))),
            Some(gt) => match evaluate_one(
                &args.map,
                map,
                GtSource {
                    image: &gt,
                    drawn_on: None,
                },
                None,
                false,
            ) {
                Ok((e, _, _)) => rows.push((stem, e)),
                Err(e) => {
                    failed += 1;
                    bar.suspend(|| eprintln!("{stem}: {e:?}"));
                }
            },
        }
        bar.inc(1);
    }
    bar.finish_and_clear();
    if args.json {
        let list: Vec<serde_json::Value> = rows
            .iter()
            .map(|(name, e)| serde_json::json!({"map": name, "evaluation": e}))
            .collect();
        let text = serde_json::to_string_pretty(&list).into_diagnostic()?;
        writeln!(out, "{text}").into_diagnostic()?;
    } else {
        print_table(&rows, out).into_diagnostic()?;
        for note in &notes {
            writeln!(out, "{note}").into_diagnostic()?;
        }
    }
    Ok(if failed > 0 {
        ExitCode::from(2)
    } else if rows.is_empty() {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

fn cells(e: &Evaluation) -> [f64; 8] {
    [
        e.rooms.recall_micro,
        e.rooms.precision_micro,
        e.rooms.recall_macro,
        e.rooms.precision_macro,
        e.doors.recall,
        e.doors.precision,
        e.connections.recall,
        e.connections.precision,
    ]
}

fn print_table(rows: &[(String, Evaluation)], out: &mut dyn Write) -> std::io::Result<()> {
    writeln!(
        out,
        "{:<28} {:>6} {:>6} {:>6} {:>6} | {:>6} {:>6} | {:>6} {:>6} | {:>5} {:>5}",
        "map (%; width error m)",
        "R",
        "P",
        "Rmac",
        "Pmac",
        "doorR",
        "doorP",
        "connR",
        "connP",
        "wMed",
        "wP90"
    )?;
    let mut sum = [0.0; 8];
    let metres = |v: Option<f64>| v.map_or_else(|| "-".to_string(), |m| format!("{m:.3}"));
    let row = |out: &mut dyn Write, name: &str, c: &[f64; 8], w: [Option<f64>; 2]| {
        writeln!(
            out,
            "{name:<28} {:>6.1} {:>6.1} {:>6.1} {:>6.1} | {:>6.1} {:>6.1} | {:>6.1} {:>6.1} | {:>5} {:>5}",
            100.0 * c[0],
            100.0 * c[1],
            100.0 * c[2],
            100.0 * c[3],
            100.0 * c[4],
            100.0 * c[5],
            100.0 * c[6],
            100.0 * c[7],
            metres(w[0]),
            metres(w[1])
        )
    };
    let mut worst: [Option<f64>; 2] = [None, None];
    for (name, e) in rows {
        let c = cells(e);
        for (s, v) in sum.iter_mut().zip(c) {
            *s += v;
        }
        let w = [e.widths.median_m, e.widths.p90_m];
        for (m, v) in worst.iter_mut().zip(w) {
            *m = match (*m, v) {
                (Some(a), Some(b)) => Some(a.max(b)),
                (a, b) => a.or(b),
            };
        }
        row(out, name, &c, w)?;
    }
    if !rows.is_empty() {
        let mean = sum.map(|s| s / rows.len() as f64);
        // Width errors: the worst map's.
        row(
            out,
            &format!("mean of {} (w: worst)", rows.len()),
            &mean,
            worst,
        )?;
    }
    Ok(())
}

fn print_one(
    e: &Evaluation,
    report: Option<&DoorReport>,
    alignment: Option<&Carried>,
    json: bool,
    out: &mut dyn Write,
) -> std::io::Result<()> {
    if json {
        let mut value = serde_json::to_value(e).map_err(std::io::Error::other)?;
        if let (Some(r), Some(object)) = (report, value.as_object_mut()) {
            let r = serde_json::to_value(r).map_err(std::io::Error::other)?;
            object.insert("door_report".into(), r);
        }
        if let (Some(a), Some(object)) = (alignment, value.as_object_mut()) {
            let a = serde_json::to_value(a).map_err(std::io::Error::other)?;
            object.insert("gt_alignment".into(), a);
        }
        let text = serde_json::to_string_pretty(&value).map_err(std::io::Error::other)?;
        return writeln!(out, "{text}");
    }
    print_summary(e, out)?;
    match report {
        Some(r) => print_report(r, out),
        None => Ok(()),
    }
}

/// The door report as text: missed lines, wrong doors, then matched doors
/// by width error, worst first.
fn print_report(r: &DoorReport, out: &mut dyn Write) -> std::io::Result<()> {
    let at = |p: [f64; 2]| format!("({:.2}, {:.2})", p[0], p[1]);
    for l in r.missed() {
        let rooms: Vec<String> = l.rooms.iter().map(u32::to_string).collect();
        writeln!(
            out,
            "missed  GT doorway line {:>3} at {:<18} {:.2} m long, between GT rooms {}",
            l.line,
            at(l.middle),
            l.length_m,
            rooms.join(", ")
        )?;
    }
    let width = |w: Option<f64>| w.map_or_else(|| "-".to_string(), |w| format!("{w:.2} m"));
    for d in r.wrong() {
        writeln!(
            out,
            "wrong   door {:>4} at {:<18} width {}, no GT doorway line within 0.5 m",
            d.door,
            at(d.middle),
            width(d.width_m)
        )?;
    }
    for (d, line, truth) in r.right_worst_first() {
        writeln!(
            out,
            "right   door {:>4} at {:<18} width {}, GT doorway line {} {:.2} m",
            d.door,
            at(d.middle),
            width(d.width_m),
            line,
            truth
        )?;
    }
    Ok(())
}

fn print_summary(e: &Evaluation, out: &mut dyn Write) -> std::io::Result<()> {
    let r = &e.rooms;
    writeln!(
        out,
        "rooms       recall {:6.2} %  precision {:6.2} %  (per-room mean, IPA \"micro\"; {} GT rooms, {} segments)",
        100.0 * r.recall_micro,
        100.0 * r.precision_micro,
        r.gt_rooms,
        r.segments
    )?;
    writeln!(
        out,
        "rooms       recall {:6.2} %  precision {:6.2} %  (pixel-weighted, IPA \"macro\")",
        100.0 * r.recall_macro,
        100.0 * r.precision_macro
    )?;
    writeln!(
        out,
        "doors       recall {:6.2} %  precision {:6.2} %  ({} GT doorway lines, {} detected)",
        100.0 * e.doors.recall,
        100.0 * e.doors.precision,
        e.doors.gt,
        e.doors.detected
    )?;
    writeln!(
        out,
        "connections recall {:6.2} %  precision {:6.2} %  ({} GT, {} detected)",
        100.0 * e.connections.recall,
        100.0 * e.connections.precision,
        e.connections.gt,
        e.connections.detected
    )?;
    let w = &e.widths;
    match (w.median_m, w.p90_m) {
        (Some(median), Some(p90)) => writeln!(
            out,
            "door widths error median {median:.3} m  p90 {p90:.3} m  ({} doors matched to GT doorway lines)",
            w.matched
        ),
        _ => writeln!(out, "door widths no door matched to a GT doorway line"),
    }
}
