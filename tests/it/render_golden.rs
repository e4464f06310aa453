//! Golden pictures: a generated building over a hand-made grid, with a
//! route and a diff, rendered to PNG and SVG and compared with the stored
//! pictures in tests/golden/ (PNG with a small per-pixel tolerance, SVG
//! exactly). `NRGDB_UPDATE_GOLDEN=1` rewrites them; review the change.

use std::path::{Path, PathBuf};

use nrgdb::grid::{Cell, OccupancyGrid};
use nrgdb::model::{Nrg, Space, SpaceId, SpaceKind};
use nrgdb::render::{
    DiffOverlay, LabelMode, OverlaySpace, RenderOptions, RouteOverlay, Scene, render_png,
    render_svg,
};

/// A 0.5 m grid under the corridor building of 3 rooms (12 m × 7 m):
/// walls around, free inside, an unknown corner.
fn grid() -> OccupancyGrid {
    let (w, h) = (26u32, 16u32);
    let mut cells = Vec::new();
    for row in 0..h {
        for col in 0..w {
            cells.push(if col == 0 || row == 0 || col == w - 1 || row == h - 1 {
                Cell::Occupied
            } else if col > 20 && row < 4 {
                Cell::Unknown
            } else {
                Cell::Free
            });
        }
    }
    OccupancyGrid::from_cells(w, h, 0.5, [-0.5, -0.5, 0.0], cells)
}

fn overlays(nrg: &Nrg) -> (RouteOverlay, DiffOverlay) {
    let anchor = |id: u32| nrg.space(SpaceId(id)).map(|s| s.anchor).unwrap();
    let route = RouteOverlay {
        waypoints: [10, 10_000, 1, 10_002, 12].map(anchor).to_vec(),
        doors: [10_000, 10_002].map(anchor).to_vec(),
        length_m: 13.2,
        ..RouteOverlay::default()
    };
    let gone = Space::new(
        SpaceId(7),
        SpaceKind::Room,
        [6.0, 9.0],
        vec![[4.5, 7.5], [7.5, 7.5], [7.5, 10.0], [4.5, 10.0]],
    );
    let diff = DiffOverlay {
        added: vec![OverlaySpace::of(nrg.space(SpaceId(12)).unwrap())],
        removed: vec![OverlaySpace::of(&gone)],
        changed: vec![OverlaySpace::of(nrg.space(SpaceId(11)).unwrap())],
        ..DiffOverlay::default()
    };
    (route, diff)
}

fn golden(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/golden")
        .join(name)
}

fn update() -> bool {
    std::env::var("NRGDB_UPDATE_GOLDEN").as_deref() == Ok("1")
}

/// Writes the actual picture to a temp folder and returns its path.
fn keep_actual(name: &str, bytes: &[u8]) -> PathBuf {
    let dir = std::env::temp_dir().join("nrgdb-golden");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

/// Pixels whose channels differ by more than `tol` between two PNGs, or
/// `None` when the sizes differ.
fn differing_pixels(a: &[u8], b: &[u8], tol: u8) -> Option<usize> {
    let a = image::load_from_memory(a).unwrap().to_rgba8();
    let b = image::load_from_memory(b).unwrap().to_rgba8();
    if a.dimensions() != b.dimensions() {
        return None;
    }
    Some(
        a.pixels()
            .zip(b.pixels())
            .filter(|(p, q)| p.0.iter().zip(q.0).any(|(x, y)| x.abs_diff(y) > tol))
            .count(),
    )
}

fn check_png(name: &str, actual: &[u8]) {
    let path = golden(name);
    if update() {
        std::fs::write(&path, actual).unwrap();
        return;
    }
    let expected = std::fs::read(&path)
        .unwrap_or_else(|e| panic!("{}: {e} (run with NRGDB_UPDATE_GOLDEN=1)", path.display()));
    let (w, h) = image::load_from_memory(actual)
        .unwrap()
        .to_rgba8()
        .dimensions();
    // Anti-aliasing may differ a little between CPUs (SIMD paths): allow
    // small differences on a few pixels, never a changed picture.
    let allowed = (w * h) as usize / 1000;
    match differing_pixels(&expected, actual, 24) {
        Some(n) if n <= allowed => {}
        found => {
            let kept = keep_actual(name, actual);
            panic!(
                "{name}: {} (allowed {allowed}); actual picture written to {}; \
                 NRGDB_UPDATE_GOLDEN=1 accepts it",
                found.map_or("the size differs".to_string(), |n| format!(
                    "{n} pixels differ"
                )),
                kept.display()
            );
        }
    }
}

fn check_svg(name: &str, actual: &str) {
    let path = golden(name);
    if update() {
        std::fs::write(&path, actual).unwrap();
        return;
    }
    let expected = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("{}: {e} (run with NRGDB_UPDATE_GOLDEN=1)", path.display()));
    if expected != actual {
        let kept = keep_actual(name, actual.as_bytes());
        panic!(
            "{name}: the SVG differs; actual written to {} (diff it; NRGDB_UPDATE_GOLDEN=1 accepts it)",
            kept.display()
        );
    }
}

fn options() -> RenderOptions {
    RenderOptions {
        px_per_m: Some(30.0),
        title: Some("corridor_building(3)".into()),
        ..RenderOptions::default()
    }
}

#[test]
fn render_golden_png_with_map_route_and_labels() {
    let nrg = nrgdb::fixtures::corridor_building(3);
    let map = grid();
    let (route, _) = overlays(&nrg);
    let options = options();
    let scene = Scene {
        nrg: &nrg,
        map: Some(&map),
        route: Some(&route),
        diff: None,
        options: &options,
    };
    check_png("render_route.png", &render_png(&scene).unwrap());
}

#[test]
fn render_golden_png_with_diff_and_ids() {
    let nrg = nrgdb::fixtures::corridor_building(3);
    let (_, diff) = overlays(&nrg);
    let options = RenderOptions {
        labels: LabelMode::Ids,
        ..options()
    };
    let scene = Scene {
        nrg: &nrg,
        map: None,
        route: None,
        diff: Some(&diff),
        options: &options,
    };
    check_png("render_diff.png", &render_png(&scene).unwrap());
}

#[test]
fn render_golden_svg_with_everything() {
    let nrg = nrgdb::fixtures::corridor_building(3);
    let map = grid();
    let (route, diff) = overlays(&nrg);
    let options = options();
    let scene = Scene {
        nrg: &nrg,
        map: Some(&map),
        route: Some(&route),
        diff: Some(&diff),
        options: &options,
    };
    check_svg("render_all.svg", &render_svg(&scene).unwrap());
}

#[test]
fn render_golden_comparison_catches_a_changed_picture() {
    let nrg = nrgdb::fixtures::corridor_building(3);
    let options = options();
    let a = render_png(&Scene {
        nrg: &nrg,
        map: None,
        route: None,
        diff: None,
        options: &options,
    })
    .unwrap();
    let (route, _) = overlays(&nrg);
    let b = render_png(&Scene {
        nrg: &nrg,
        map: None,
        route: Some(&route),
        diff: None,
        options: &options,
    })
    .unwrap();
    assert_eq!(differing_pixels(&a, &a, 0), Some(0));
    assert!(differing_pixels(&a, &b, 24).unwrap() > 500);
}
