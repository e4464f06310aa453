//! Simulator benchmarks: log-odds mapping throughput (beams per second)
//! and simulating + mapping a 50 m x 50 m building at 0.05 m/px.
#![allow(clippy::unwrap_used)]

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use nrgdb::sim::{
    FloorPlan, LidarParams, LogOddsMap, LogOddsParams, SimParams, WallIndex, sample_poses,
    simulate, simulate_scans,
};
use std::hint::black_box;

/// A building about 50 m x 50 m: three 44 m wings in a U.
fn big_building() -> SimParams {
    let mut p = SimParams::new(7);
    p.plan.wings = (3, 3);
    p.plan.corridor_length_m = (44.0, 44.0);
    p.plan.furniture = true;
    p
}

fn mapping(c: &mut Criterion) {
    let p = big_building();
    let plan = FloorPlan::generate(&p.plan).unwrap();
    let walls = WallIndex::new(plan.walls(), 1.0);
    let poses = sample_poses(&plan.route, p.pose_step_m);
    let scans = simulate_scans(
        &walls,
        &poses,
        &LidarParams {
            seed: 7,
            ..LidarParams::default()
        },
    );
    let beams: usize = scans.iter().map(|s| s.ranges_m.len()).sum();
    let cells: f64 = scans
        .iter()
        .flat_map(|s| s.ranges_m.iter())
        .map(|&r| f64::from(r).min(10.0) / 0.05)
        .sum();
    let b = plan.bounds();
    eprintln!(
        "building {:.1} m x {:.1} m, {} rooms, {} scans, {beams} beams, {:.0} cells per beam on average",
        b[2] - b[0],
        b[3] - b[1],
        plan.rooms.len(),
        scans.len(),
        cells / beams as f64
    );
    let mut g = c.benchmark_group("sim");
    g.sample_size(10);
    g.throughput(Throughput::Elements(beams as u64));
    g.bench_function("log_odds_mapping/beams", |b| {
        b.iter(|| {
            let params = LogOddsParams {
                usable_range_m: 10.0,
                ..LogOddsParams::default()
            };
            let mut m = LogOddsMap::covering(plan.bounds(), 1.0, 0.05, params).unwrap();
            for s in &scans {
                black_box(m.integrate(s));
            }
            m
        })
    });
    g.bench_function("lidar_scans/beams", |b| {
        b.iter(|| simulate_scans(&walls, black_box(&poses), &LidarParams::default()))
    });
    g.finish();
}

fn simulate_50m(c: &mut Criterion) {
    let p = big_building();
    let mut g = c.benchmark_group("sim");
    g.sample_size(10);
    g.bench_function("simulate_and_map/50x50m/0.05", |b| {
        b.iter(|| simulate(black_box(&p)).unwrap())
    });
    g.finish();
}

criterion_group!(benches, mapping, simulate_50m);
criterion_main!(benches);
