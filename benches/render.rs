//! Rendering the generated corridor building (200 rooms, 401 spaces, 800 m
//! × 7 m) with a route and labels at 4 px/m (a 3 200 × 28 px map area plus
//! legend), as SVG and as PNG.
//! No target in issue 8; recorded so regressions show.
#![allow(clippy::unwrap_used)]

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use nrgdb::model::SpaceId;
use nrgdb::render::{RenderOptions, RouteOverlay, Scene, render_png, render_svg};

fn render(c: &mut Criterion) {
    let nrg = nrgdb::fixtures::corridor_building(200);
    let anchor = |id: u32| nrg.space(SpaceId(id)).unwrap().anchor;
    let route = RouteOverlay {
        waypoints: vec![
            anchor(10),
            anchor(10_000),
            anchor(1),
            anchor(10_199),
            anchor(209),
        ],
        doors: vec![anchor(10_000), anchor(10_199)],
        length_m: 800.0,
        ..RouteOverlay::default()
    };
    let options = RenderOptions {
        px_per_m: Some(4.0),
        ..RenderOptions::default()
    };
    let scene = Scene {
        nrg: &nrg,
        map: None,
        route: Some(&route),
        diff: None,
        options: &options,
    };
    c.bench_function("render/svg/corridor_building_200", |b| {
        b.iter(|| render_svg(black_box(&scene)).unwrap())
    });
    c.bench_function("render/png/corridor_building_200", |b| {
        b.iter(|| render_png(black_box(&scene)).unwrap())
    });
}

criterion_group!(benches, render);
criterion_main!(benches);
