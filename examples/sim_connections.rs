//! Lists, for one simulated building, the ground truth's room pairs joined
//! by a doorway line and the pairs the extraction joins through a detected
//! door (each space mapped to its best-overlap GT room), naming GT rooms by
//! the plan's spaces, and writes the evaluation picture.
//!
//! ```text
//! cargo run --release --example sim_connections -- SEED [--furnished] [--picture P.png]
//! ```

use std::collections::HashMap;

use nrgdb::eval::{connection_pairs, connection_scores, evaluation_picture, load_ground_truth};
use nrgdb::extract::{ExtractParams, extract};
use nrgdb::grid::{LoadOptions, load_map};
use nrgdb::model::{SpaceKind, point_in_ring};
use nrgdb::sim::{SimParams, simulate, write_simulation};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let mut seed = 1u64;
    let mut furnished = false;
    let mut picture = None;
    while let Some(a) = args.next() {
        match a.as_str() {
            "--furnished" => furnished = true,
            "--picture" => picture = args.next(),
            s => seed = s.parse()?,
        }
    }
    let mut sim = SimParams::new(seed);
    sim.plan.furniture = furnished;
    let b = simulate(&sim)?;
    let dir = tempfile::tempdir()?;
    let files = write_simulation(dir.path(), &b)?;
    let grid = load_map(&files.yaml, &LoadOptions::default())?;
    let gt = load_ground_truth(&files.gt_png, &grid)?;
    let x = extract(&grid, &ExtractParams::default())?;
    let truth = b.plan.truth()?;
    // Name each GT label by the plan space holding most of its pixels.
    let (w, h) = (grid.width, grid.height);
    let r = grid.resolution;
    let mut votes: HashMap<u32, HashMap<String, usize>> = HashMap::new();
    for (i, &l) in gt.rooms.data.iter().enumerate() {
        if l == 0 {
            continue;
        }
        let (c, row) = (i as u32 % w, i as u32 / w);
        let p = [
            grid.origin[0] + (f64::from(c) + 0.5) * r,
            grid.origin[1] + (f64::from(h - 1 - row) + 0.5) * r,
        ];
        let name = truth
            .spaces()
            .iter()
            .filter(|s| s.kind != SpaceKind::Door)
            .find(|s| point_in_ring(p, &s.polygon))
            .map_or("-".to_string(), |s| s.label());
        *votes.entry(l).or_default().entry(name).or_insert(0) += 1;
    }
    let name = |l: u32| -> String {
        votes.get(&l).map_or("?".into(), |v| {
            let mut v: Vec<_> = v.iter().collect();
            v.sort_by(|a, b| b.1.cmp(a.1));
            v.iter()
                .take(2)
                .map(|(n, c)| format!("{n}:{c}"))
                .collect::<Vec<_>>()
                .join(",")
        })
    };
    println!("GT labels: {}", gt.rooms.count);
    for l in 1..=gt.rooms.count {
        println!("  gt {l}: {}", name(l));
    }
    println!("GT doorway lines: {}", gt.doors.len());
    for d in &gt.doors {
        let p = d.pixels[0];
        println!(
            "  line {} px at ({},{}) rooms {:?}",
            d.pixels.len(),
            p % w,
            p / w,
            d.rooms
        );
    }
    println!(
        "plan: {} corridors, {} rooms, {} doors, {} openings",
        b.plan.corridors.len(),
        b.plan.rooms.len(),
        b.plan.doors.len(),
        b.plan.openings.len()
    );
    let pairs = connection_pairs(&gt, &x);
    println!("extracted spaces:");
    for s in x.nrg.spaces() {
        println!(
            "  {} {} -> gt {:?} conns {:?}",
            s.id,
            s.kind,
            pairs.best_room.get(s.id.0 as usize),
            x.nrg
                .connections_of(s.id)
                .map(|c| (c.other(s.id).map(|o| o.0), c.kind.to_string()))
                .collect::<Vec<_>>()
        );
    }
    println!("GT pairs not detected:");
    for p in pairs.gt.difference(&pairs.detected) {
        println!("  {p:?} {} <-> {}", name(p.0), name(p.1));
    }
    println!("detected pairs not in GT:");
    for p in pairs.detected.difference(&pairs.gt) {
        println!("  {p:?} {} <-> {}", name(p.0), name(p.1));
    }
    let c = connection_scores(&gt, &x);
    println!(
        "connections R {:.3} P {:.3} gt {} det {}",
        c.recall, c.precision, c.gt, c.detected
    );
    if let Some(p) = picture {
        evaluation_picture(&grid, &gt, &x).save(p)?;
    }
    Ok(())
}
