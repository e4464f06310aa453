//! `nrgdb eval --loo KEY=V1,V2,...`: a parameter's values judged
//! leave-one-building-out over a folder of maps with ground truths (the
//! judgement itself is `nrgdb::eval::leave_one_out`).

use std::collections::BTreeMap;
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use miette::{IntoDiagnostic, WrapErr};
use nrgdb::eval::{building_of, evaluate, leave_one_out, load_ground_truth, score, tuned_on_all};
use nrgdb::extract::extract;
use serde::Serialize;

use super::eval::{gt_name, sibling_gt};
use super::extract::MapArgs;
use super::progress;

/// Most values one run compares (each is one extraction per map).
const MAX_VALUES: usize = 16;

#[derive(Debug, Serialize)]
struct BuildingRow {
    building: String,
    maps: Vec<String>,
    /// Score (0..=1) under each value.
    scores: Vec<f64>,
    /// The value tuned on the other buildings, and the score under it.
    held_out_value: String,
    held_out_score: f64,
    /// The value best for this building alone.
    own_best_value: String,
}

#[derive(Debug, Serialize)]
struct Report {
    key: String,
    values: Vec<String>,
    buildings: Vec<BuildingRow>,
    /// Mean over buildings of the held-out scores.
    mean_held_out: f64,
    /// Mean over buildings of each value's score.
    mean_per_value: Vec<f64>,
    /// The value with the best mean over all buildings.
    tuned_on_all: Option<String>,
    /// Maps left out (no ground truth) and values an extraction failed on.
    notes: Vec<String>,
}

/// Parses `KEY=V1,V2,...`.
fn parse(spec: &str) -> miette::Result<(String, Vec<String>)> {
    let Some((key, values)) = spec.split_once('=') else {
        miette::bail!("--loo {spec}: expected KEY=V1,V2,..., e.g. --loo door_width_max_m=1.2,1.5");
    };
    let values: Vec<String> = values
        .split(',')
        .map(|v| v.trim().to_owned())
        .filter(|v| !v.is_empty())
        .collect();
    if !(2..=MAX_VALUES).contains(&values.len()) {
        miette::bail!(
            "--loo {}: give between 2 and {MAX_VALUES} values to compare (got {})",
            key.trim(),
            values.len()
        );
    }
    Ok((key.trim().to_owned(), values))
}

/// Runs the leave-one-building-out comparison.
pub fn run(
    args: &MapArgs,
    spec: &str,
    json: bool,
    inputs: &[PathBuf],
    out: &mut dyn Write,
) -> miette::Result<ExitCode> {
    let (key, values) = parse(spec)?;
    let mut notes = Vec::new();
    let maps: Vec<(String, PathBuf, PathBuf)> = inputs
        .iter()
        .filter_map(|map| {
            let stem = map.file_stem()?.to_string_lossy().into_owned();
            match sibling_gt(map) {
                Some(gt) => Some((stem, map.clone(), gt)),
                None => {
                    notes.push(format!("{stem}: skipped, no {} beside it", gt_name(map)));
                    None
                }
            }
        })
        .collect();
    let bar = progress::bar((maps.len() * values.len()) as u64, "eval --loo");
    // Per building: its maps and, per map, the score under each value.
    let mut by_building: BTreeMap<String, Vec<(String, Vec<f64>)>> = BTreeMap::new();
    for (stem, map, gt) in &maps {
        bar.set_message(stem.clone());
        let (grid, base) = args.load(map)?;
        let truth = load_ground_truth(gt, &grid).into_diagnostic()?;
        let mut scores = Vec::with_capacity(values.len());
        for value in &values {
            // Not checked here: a value out of order with the others makes
            // extraction fail, and that value scores 0 with a note.
            let mut params = base.clone();
            params
                .set(&key, value)
                .into_diagnostic()
                .wrap_err_with(|| format!("--loo {key}={value}"))?;
            scores.push(match extract(&grid, &params) {
                Ok(x) => score(&evaluate(&truth, &x, grid.resolution)),
                Err(e) => {
                    notes.push(format!(
                        "{stem}: {key}={value}: extraction failed ({e}), scored 0"
                    ));
                    0.0
                }
            });
            bar.inc(1);
        }
        by_building
            .entry(building_of(stem).to_owned())
            .or_default()
            .push((stem.clone(), scores));
    }
    bar.finish_and_clear();
    if by_building.len() < 2 {
        miette::bail!(
            "--loo needs maps of at least two buildings with ground truths (found {})",
            by_building.len()
        );
    }
    let table: Vec<Vec<f64>> = by_building
        .values()
        .map(|maps| {
            (0..values.len())
                .map(|v| maps.iter().map(|(_, s)| s[v]).sum::<f64>() / maps.len() as f64)
                .collect()
        })
        .collect();
    let held = leave_one_out(&table);
    let n = table.len() as f64;
    let report = Report {
        key,
        buildings: by_building
            .iter()
            .zip(&table)
            .zip(&held)
            .map(|(((building, maps), scores), h)| BuildingRow {
                building: building.clone(),
                maps: maps.iter().map(|(m, _)| m.clone()).collect(),
                scores: scores.clone(),
                held_out_value: values[h.chosen].clone(),
                held_out_score: h.score,
                own_best_value: values[h.own_best].clone(),
            })
            .collect(),
        mean_held_out: held.iter().map(|h| h.score).sum::<f64>() / n,
        mean_per_value: (0..values.len())
            .map(|v| table.iter().map(|s| s[v]).sum::<f64>() / n)
            .collect(),
        tuned_on_all: tuned_on_all(&table).map(|v| values[v].clone()),
        values,
        notes,
    };
    if json {
        let text = serde_json::to_string_pretty(&report).into_diagnostic()?;
        writeln!(out, "{text}").into_diagnostic()?;
    } else {
        print(&report, out).into_diagnostic()?;
    }
    Ok(ExitCode::SUCCESS)
}

fn print(r: &Report, out: &mut dyn Write) -> std::io::Result<()> {
    writeln!(
        out,
        "{} leave-one-building-out (score: mean F1 of rooms, doors, connections, %)",
        r.key
    )?;
    write!(
        out,
        "{:<28} {:>9} {:>6} {:>9}",
        "building", "held-out", "score", "own best"
    )?;
    for v in &r.values {
        write!(out, " {:>8}", format!("={v}"))?;
    }
    writeln!(out)?;
    for b in &r.buildings {
        write!(
            out,
            "{:<28} {:>9} {:>6.1} {:>9}",
            b.building,
            b.held_out_value,
            100.0 * b.held_out_score,
            b.own_best_value
        )?;
        for s in &b.scores {
            write!(out, " {:>8.1}", 100.0 * s)?;
        }
        writeln!(out)?;
    }
    write!(
        out,
        "{:<28} {:>9} {:>6.1} {:>9}",
        format!("mean of {}", r.buildings.len()),
        "",
        100.0 * r.mean_held_out,
        ""
    )?;
    for m in &r.mean_per_value {
        write!(out, " {:>8.1}", 100.0 * m)?;
    }
    writeln!(out)?;
    if let Some(v) = &r.tuned_on_all {
        writeln!(
            out,
            "tuned on all buildings: {}={v}; held out, the buildings score {:.1} % on average",
            r.key,
            100.0 * r.mean_held_out
        )?;
    }
    for note in &r.notes {
        writeln!(out, "{note}")?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_spec_is_a_key_and_two_or_more_values() {
        let (key, values) = parse("door_width_max_m = 1.2, 1.5,1.8").unwrap();
        assert_eq!(key, "door_width_max_m");
        assert_eq!(values, ["1.2", "1.5", "1.8"]);
        assert!(parse("door_width_max_m").is_err());
        assert!(parse("door_width_max_m=1.2").is_err());
        let many = format!("k={}", vec!["1"; MAX_VALUES + 1].join(","));
        assert!(parse(&many).is_err());
    }
}
