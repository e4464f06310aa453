//! Reading a ROS 2 recording (issue 24): a 100 MB MCAP file with 200
//! OccupancyGrid messages (1 000 × 500 cells each, every one a little
//! different, as a robot's map grows), uncompressed and zstd-compressed,
//! through both passes of an import without the extraction: `scan` (read
//! to the end, decode, hash, choose) and `read_chosen` (read again, hand
//! out the chosen grids). Throughput is bytes of recording per second of
//! the two passes together (of message bytes: the same for both files).
//! Peak memory (VmHWM) is printed before and after reading.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::hint::black_box;

use criterion::{Criterion, Throughput};
use nrgdb::grid::{Cell, OccupancyGrid};
use nrgdb::recording::{Recording, RecordingError, RecordingOptions, read_chosen, scan};

#[path = "../tests/it/recording_support.rs"]
mod recording_support;

use recording_support::{Msg, grid_message, write_mcap};

const MAPS: usize = 200;

fn maps() -> Vec<Msg> {
    let (w, h) = (1000u32, 500u32);
    let mut cells = vec![Cell::Unknown; (w * h) as usize];
    (0..MAPS)
        .map(|k| {
            // Each map uncovers a few more rows of free space with a wall.
            let rows = (k as u32 * 2 + 2).min(h);
            for row in 0..rows {
                for col in 0..w {
                    cells[(row * w + col) as usize] = if col % 100 == 0 {
                        Cell::Occupied
                    } else {
                        Cell::Free
                    };
                }
            }
            let grid = OccupancyGrid::from_cells(w, h, 0.05, [0.0, 0.0, 0.0], cells.clone());
            let t = 1_796_292_000_000_000_000 + k as u64 * 5_000_000_000;
            Msg {
                topic: "/map",
                kind: "nav_msgs/msg/OccupancyGrid",
                time_ns: t,
                data: grid_message(&grid, t, true),
            }
        })
        .collect()
}

fn peak_rss_kib() -> u64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM:"))
                .and_then(|l| l.split_whitespace().nth(1)?.parse().ok())
        })
        .unwrap_or(0)
}

fn bench(c: &mut Criterion) {
    let dir = tempfile::tempdir().unwrap();
    let options = RecordingOptions::default();
    // Both files written first and the messages dropped, so the peak
    // memory printed at the end is the reading's.
    let messages = maps();
    let payload: u64 = messages.iter().map(|m| m.data.len() as u64).sum();
    for compress in [false, true] {
        let name = if compress { "zstd" } else { "plain" };
        write_mcap(
            &dir.path().join(format!("{name}.mcap")),
            &messages,
            compress,
        );
    }
    drop(messages);
    eprintln!(
        "peak RSS after writing the files: {} MiB (VmHWM; the bench resets nothing)",
        peak_rss_kib() / 1024
    );
    for name in ["plain", "zstd"] {
        let path = dir.path().join(format!("{name}.mcap"));
        let bytes = std::fs::metadata(&path).unwrap().len();
        eprintln!("{name}: {bytes} bytes on disk, {payload} bytes of messages");
        let recording = Recording::open(&path).unwrap();
        let mut group = c.benchmark_group("recording");
        // Per byte of messages: the zstd file is ~100 times smaller than
        // its content (these synthetic maps are very regular).
        group.throughput(Throughput::Bytes(payload));
        group.sample_size(10);
        group.bench_function(format!("read-two-passes/{name}"), |b| {
            b.iter(|| {
                let found = scan(&recording, &options).unwrap();
                assert_eq!(found.choice.chosen.len(), MAPS);
                let mut cells = 0usize;
                read_chosen::<RecordingError>(&recording, &options, &found, |_, g| {
                    cells += black_box(g.cells.len());
                    Ok(())
                })
                .unwrap();
                assert_eq!(cells, MAPS * 500_000);
            })
        });
        group.finish();
    }
    eprintln!(
        "peak RSS of the bench process: {} MiB",
        peak_rss_kib() / 1024
    );
}

fn main() {
    // `NRGDB_RECORDING_OUT=FILE cargo bench --bench recording` only writes
    // the uncompressed recording to FILE (to time or measure a whole
    // `nrgdb import` of it).
    if let Some(out) = std::env::var_os("NRGDB_RECORDING_OUT") {
        write_mcap(std::path::Path::new(&out), &maps(), false);
        return;
    }
    let mut c = Criterion::default().configure_from_args();
    bench(&mut c);
    c.final_summary();
}
