//! IndoorGML import and export throughput (MB/s) and peak memory, on the
//! largest importable dev sample (when `NRGDB_SHARED` has it) and on a
//! generated 2 000-room building. Peak heap is measured with a counting
//! allocator and printed once per input.
#![allow(clippy::unwrap_used, clippy::expect_used, unsafe_code)]

use std::alloc::{GlobalAlloc, Layout, System};
use std::hint::black_box;
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use nrgdb::indoorgml::{from_nrg, read_str, write_string};

struct Counting;
static CURRENT: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

// SAFETY: delegates to the system allocator and only counts bytes.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let now = CURRENT.fetch_add(layout.size(), Ordering::Relaxed) + layout.size();
        PEAK.fetch_max(now, Ordering::Relaxed);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        CURRENT.fetch_sub(layout.size(), Ordering::Relaxed);
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Peak heap growth while running `f`, in bytes.
fn peak_during(f: impl FnOnce()) -> usize {
    let base = CURRENT.load(Ordering::Relaxed);
    PEAK.store(base, Ordering::Relaxed);
    f();
    PEAK.load(Ordering::Relaxed) - base
}

fn inputs() -> Vec<(String, String)> {
    let mut out = Vec::new();
    let shared =
        std::env::var_os("NRGDB_SHARED").map_or_else(|| PathBuf::from("../shared"), PathBuf::from);
    let sample = shared.join("indoorgml/samples/201-2019-05-24-corrected.gml");
    if let Ok(text) = std::fs::read_to_string(&sample) {
        out.push(("sample-201".to_string(), text));
    } else {
        eprintln!(
            "notice: {} not found; benchmarking the generated building only",
            sample.display()
        );
    }
    out.push((
        "generated-2000-rooms".to_string(),
        write_string(&from_nrg(&nrgdb::fixtures::corridor_building(2000))),
    ));
    out
}

fn indoorgml(c: &mut Criterion) {
    for (name, text) in inputs() {
        let doc = read_str(&text).unwrap();
        let bytes = text.len();
        let import_peak = peak_during(|| drop(black_box(read_str(&text).unwrap())));
        let export_peak = peak_during(|| drop(black_box(write_string(&doc))));
        println!(
            "{name}: {bytes} bytes; peak heap import {import_peak} B ({:.2}x file), export {export_peak} B ({:.2}x file)",
            import_peak as f64 / bytes as f64,
            export_peak as f64 / bytes as f64
        );
        let mut group = c.benchmark_group(format!("indoorgml/{name}"));
        group.throughput(Throughput::Bytes(bytes as u64));
        group.bench_function("import", |b| b.iter(|| read_str(black_box(&text)).unwrap()));
        group.bench_function("export", |b| b.iter(|| write_string(black_box(&doc))));
        group.finish();
    }
}

criterion_group!(benches, indoorgml);
criterion_main!(benches);
