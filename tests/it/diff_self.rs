//! Issue 19: `nrgdb diff M.yaml M.yaml` on every shared map
//! (`$NRGDB_SHARED/maps`, skipped without it): each map has walls to align
//! on, shares a frame with itself, and aligned by force lands on the
//! identity with nothing changed. Clean drawn maps (office_g: anti-aliased
//! black walls) once had "0 wall pixels".

use std::time::Instant;

use nrgdb::diff::{AlignMode, DiffOptions, Revision, compare, wall_points};
use nrgdb::grid::{LoadOptions, load_map};

use super::diff_support::extracted;
use super::support::shared_dir;

#[test]
fn issue_19_self_diff_of_every_shared_map_aligns_to_the_identity() {
    let Some(dir) = shared_dir("maps/office_g.yaml") else {
        return;
    };
    let mut maps: Vec<_> = std::fs::read_dir(dir.join("maps"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "yaml"))
        .collect();
    maps.sort();
    assert!(maps.len() >= 30, "{} maps", maps.len());
    for path in &maps {
        let name = path.file_name().unwrap().to_string_lossy();
        let started = Instant::now();
        let grid = load_map(path, &LoadOptions::default()).unwrap();
        let walls = wall_points(&grid).len();
        assert!(walls >= 500, "{name}: {walls} wall pixels");
        let nrg = extracted(&grid);
        let side = Revision::new(&nrg).with_grid(Some(&grid)).with_label(&name);
        for mode in [AlignMode::Auto, AlignMode::Always] {
            let options = DiffOptions {
                align: mode,
                ..DiffOptions::default()
            };
            let done =
                compare(side, side, &options).unwrap_or_else(|e| panic!("{name} ({mode:?}): {e}"));
            assert!(done.changes.is_empty(), "{name}: {}", done.changes.table());
            match (mode, done.alignment) {
                (AlignMode::Auto, None) => {
                    assert_eq!(done.identity_inliers, Some(1.0), "{name}");
                }
                (AlignMode::Always, Some(al)) => {
                    let t = al.transform;
                    assert!(
                        t.rotation_deg().abs() < 0.1 && t.tx_m.hypot(t.ty_m) < 0.05,
                        "{name}: {t:?}"
                    );
                    assert!(al.inliers > 0.99, "{name}: {al:?}");
                }
                (mode, al) => panic!("{name}: {mode:?} gave {al:?}"),
            }
        }
        eprintln!(
            "{name}: {walls} wall pixels, {} spaces, {:.1} s",
            nrg.spaces().len(),
            started.elapsed().as_secs_f64()
        );
    }
}
