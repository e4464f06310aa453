//! Test support: the shared reference data, a generated building, and
//! running the `nrgdb` binary.

use std::path::PathBuf;
use std::process::{Command, Output};

use nrgdb::model::Nrg;

/// `$NRGDB_SHARED` (default `../shared`) as an absolute path, so that
/// commands run in a temporary folder find it too, or `None` with a
/// printed notice when it is missing; panics when `NRGDB_REQUIRE_SHARED=1`
/// demands it.
pub fn shared_dir(what: &str) -> Option<PathBuf> {
    let dir =
        std::env::var_os("NRGDB_SHARED").map_or_else(|| PathBuf::from("../shared"), PathBuf::from);
    if dir.join(what).exists() {
        return Some(std::fs::canonicalize(&dir).unwrap_or(dir));
    }
    if std::env::var("NRGDB_REQUIRE_SHARED").as_deref() == Ok("1") {
        panic!(
            "NRGDB_REQUIRE_SHARED=1 but {} is missing",
            dir.join(what).display()
        );
    }
    eprintln!(
        "notice: skipping, {} not found (set NRGDB_SHARED)",
        dir.join(what).display()
    );
    None
}

/// Whether xmllint (for schema validation) can run here.
pub fn have_xmllint() -> bool {
    Command::new("xmllint").arg("--version").output().is_ok()
}

/// Asserts that `path` validates against the OGC IndoorGML schema with
/// the shared `validate.sh`, where xmllint and the shared data are here.
pub fn schema_valid_if_shared(path: &std::path::Path) {
    if have_xmllint()
        && let Some(shared) = shared_dir("indoorgml/validate.sh")
    {
        let v = Command::new(shared.join("indoorgml/validate.sh"))
            .arg(path)
            .output()
            .unwrap();
        assert!(
            v.status.success(),
            "{}: {}",
            path.display(),
            String::from_utf8_lossy(&v.stderr)
        );
    }
}

/// Flags for headless Chromium on this closed network (no background
/// connections, no sandbox as root), shared by the viewer tests.
pub const HEADLESS_CHROMIUM: &[&str] = &[
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-dev-shm-usage",
];

/// Runs the nrgdb binary with `args` in `dir`.
pub fn nrgdb(dir: &std::path::Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_nrgdb"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("run nrgdb")
}

/// Runs the nrgdb binary with `args` in `dir`, asserting that it succeeds
/// (its stderr in the message when not).
pub fn nrgdb_ok(dir: &std::path::Path, args: &[&str]) -> Output {
    let out = nrgdb(dir, args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

/// The generated corridor building of `nrgdb::fixtures`.
pub fn building(rooms: usize) -> Nrg {
    nrgdb::fixtures::corridor_building(rooms)
}

/// `nrg` as a fresh extraction of the same building would give it: every
/// id shifted by `id_shift`, names and attributes gone, every outline,
/// anchor and doorway moved by `offset` metres.
pub fn remapped(nrg: &Nrg, offset: [f64; 2], id_shift: u32) -> Nrg {
    let (spaces, connections) = nrg.clone().into_parts();
    let shift = |s: nrgdb::model::SpaceId| nrgdb::model::SpaceId(s.0 + id_shift);
    let spaces = spaces
        .into_iter()
        .map(|mut s| {
            s.id = shift(s.id);
            s.name = None;
            s.attributes.clear();
            let moved = std::iter::once(&mut s.anchor)
                .chain(s.polygon.iter_mut())
                .chain(s.doorway.iter_mut().flatten());
            for p in moved {
                p[0] += offset[0];
                p[1] += offset[1];
            }
            s
        })
        .collect();
    let connections = connections
        .into_iter()
        .map(|mut c| {
            c.a = shift(c.a);
            c.b = shift(c.b);
            c
        })
        .collect();
    Nrg::new(spaces, connections).unwrap()
}
