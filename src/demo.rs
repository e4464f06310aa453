//! The built-in demo (`nrgdb demo`): simulate a building and a robot
//! mapping it, extract the NRG, store it as a revision, shut a door on a
//! route and store the re-extracted map as a second revision, then show
//! the route in both and what changed, and write IndoorGML and a picture.
//!
//! Uses sim, grid, extract, ingest, store, query, route, format and render:
//! everything it prints comes from those modules, nothing is canned.

use crate::wording::count;
use std::collections::BTreeSet;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::extract::{ExtractParams, extract};
use crate::grid::{Cell, LoadOptions, load_map};
use crate::model::{Nrg, SpaceId, SpaceKind};
use crate::query::{Format, Session};
use crate::route::{Budget, NavMesh, RouteRequest, shortest_route};
use crate::sim::{SimParams, simulate, write_simulation};
use crate::store::{ImportMeta, Store};

/// Where the demo writes and what it simulates.
#[derive(Debug, Clone)]
pub struct DemoOptions {
    /// Folder for the map, ground truth, IndoorGML and picture.
    pub dir: PathBuf,
    /// The database: an SQLite file (created when missing) or a
    /// PostgreSQL URL.
    pub db: String,
    /// The map name in the database.
    pub map: String,
    /// Seed of the simulated building.
    pub seed: u64,
}

impl Default for DemoOptions {
    fn default() -> DemoOptions {
        DemoOptions {
            dir: PathBuf::from("nrgdb-demo"),
            db: "nrgdb.sqlite".into(),
            map: "demo".into(),
            seed: 7,
        }
    }
}

/// Why the demo stopped.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum DemoError {
    /// Simulation failed.
    #[error(transparent)]
    Sim(#[from] crate::sim::SimError),
    /// The simulated map could not be loaded.
    #[error(transparent)]
    Grid(#[from] crate::grid::GridError),
    /// Extraction failed.
    #[error(transparent)]
    Extract(#[from] crate::extract::ExtractError),
    /// The database failed.
    #[error(transparent)]
    Store(#[from] crate::store::StoreError),
    /// A query failed.
    #[error(transparent)]
    Query(#[from] crate::query::QueryError),
    /// The demo's correction was refused.
    #[error(transparent)]
    Correction(#[from] crate::ingest::CorrectError),
    /// Writing IndoorGML failed.
    #[error(transparent)]
    IndoorGml(#[from] crate::indoorgml::IndoorGmlError),
    /// Encoding the picture failed.
    #[error("cannot encode the picture: {0}")]
    Picture(#[from] image::ImageError),
    /// Reading or writing a file failed.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// The extracted building has no two connected rooms to route between.
    #[error("the extracted building has no route between two rooms")]
    NoRoute,
}

fn io(path: &Path) -> impl FnOnce(std::io::Error) -> DemoError + '_ {
    move |source| DemoError::Io {
        path: path.to_path_buf(),
        source,
    }
}

/// Runs the demo, telling `out` what it does and where the files are.
pub fn run(opts: &DemoOptions, out: &mut dyn Write) -> Result<(), DemoError> {
    let start = Instant::now();
    let say = |out: &mut dyn Write, text: String| {
        writeln!(out, "{text}").map_err(io(Path::new("<stdout>")))
    };
    std::fs::create_dir_all(&opts.dir).map_err(io(&opts.dir))?;

    let sim = simulate(&SimParams::new(opts.seed))?;
    let files = write_simulation(&opts.dir, &sim)?;
    say(
        out,
        format!(
            "1. simulated building (seed {}): {} scans, {} LiDAR beams mapped by log-odds into {}×{} px at {} m/px → {}",
            opts.seed,
            sim.scans,
            sim.beams,
            sim.map.width,
            sim.map.height,
            sim.map.resolution_m,
            files.yaml.display()
        ),
    )?;

    let grid = load_map(&files.yaml, &LoadOptions::default())?;
    let params = ExtractParams::default();
    let first = extract(&grid, &params)?;
    say(out, format!("2. extracted the NRG: {}", census(&first.nrg)))?;

    let mut store = Store::open_db(&opts.db)?;
    let yaml = std::fs::read(&files.yaml).map_err(io(&files.yaml))?;
    let meta = |msg: &str| {
        let mut m = ImportMeta::new(msg, "nrgdb demo").with_source("map.yaml", &yaml);
        m.params = serde_json::to_value(&params).ok();
        m
    };
    let rev_a = crate::ingest::ingest(
        &mut store,
        &opts.map,
        &first.nrg,
        meta("demo: simulated building, as mapped"),
        None,
    )?
    .imported;

    // A route across the building, and its first door.
    let (from, to, route) = longest_room_route(&first.nrg).ok_or(DemoError::NoRoute)?;
    let door = route.doors.first().copied().ok_or(DemoError::NoRoute)?;
    let stable = |id: SpaceId| rev_a.ids.get(&id).copied().unwrap_or(id);

    // A correction people make on the first revision: the destination
    // room is staff-only. It is kept as a rule and re-applied when the
    // re-mapped revision comes in below.
    let staff = crate::edit::Edit::SetAttribute {
        space: stable(to),
        key: "access".into(),
        value: serde_json::json!("staff only"),
    };
    let statement = format!("SET space {} ATTRIBUTE access = \"staff only\"", stable(to));
    let corrected = crate::ingest::edit(
        &mut store,
        &opts.map,
        &staff,
        &statement,
        meta("demo: a correction"),
    )?;

    // Shut that door in the map: its pixels become wall; re-extract.
    let mut shut = grid.clone();
    for (i, label) in first.labels.data.iter().enumerate() {
        if *label == door.0 {
            shut.cells[i] = Cell::Occupied;
            shut.grey[i] = 0;
        }
    }
    let second = extract(&shut, &params)?;
    let remapped = crate::ingest::ingest(
        &mut store,
        &opts.map,
        &second.nrg,
        meta(&format!("demo: door {} shut", stable(door))),
        None,
    )?;
    let rev_b = remapped.imported;
    let (a, b) = (rev_a.revision.seq, rev_b.revision.seq);
    let kept = store
        .load(&opts.map, Some(b))?
        .spaces()
        .iter()
        .filter(|s| s.attributes.get("access") == Some(&serde_json::json!("staff only")))
        .map(|s| s.id.to_string())
        .collect::<Vec<_>>();
    say(
        out,
        format!(
            "3. stored revisions {a} and {b} (door {} shut) of map '{}' in {}; revision {} is correction {} ({statement}), re-applied to the re-mapped revision {b}: {} re-applied, {} failed; staff-only there: space {}",
            stable(door),
            opts.map,
            opts.db,
            corrected.revision.seq,
            corrected.correction,
            remapped.corrections_applied.len(),
            remapped.corrections_failed.len(),
            kept.join(", ")
        ),
    )?;

    let mut session = Session::new(store);
    for rev in [a, b] {
        let text = format!(
            "USE {} AT REVISION {rev}; ROUTE FROM space {} TO space {};",
            opts.map,
            stable(from),
            stable(to)
        );
        say(out, format!("4. {text}"))?;
        let answer = session.run(&text, Format::Table)?;
        say(out, indent(&answer))?;
    }

    let store = session.source();
    let (old, new) = (
        store.load(&opts.map, Some(a))?,
        store.load(&opts.map, Some(b))?,
    );
    say(
        out,
        format!("5. changes from revision {a} to {b} (stable ids):"),
    )?;
    say(out, indent(&changes(&old, &new)))?;

    let gml = opts.dir.join("building.gml");
    let text = crate::format::render_model(&new, crate::format::ModelFormat::IndoorGml);
    crate::atomic::write(&gml, text.as_bytes()).map_err(io(&gml))?;
    // A picture of each revision with its route, so the shut door shows.
    let picture_a = opts.dir.join(format!("building-rev{a}.png"));
    let png = crate::render::kind_picture_png(&grid, &first.labels, &first.nrg, &route.waypoints)?;
    crate::atomic::write(&picture_a, &png).map_err(io(&picture_a))?;
    let picture_b = opts.dir.join(format!("building-rev{b}.png"));
    let in_b = |id: SpaceId| {
        let stable_id = stable(id);
        rev_b
            .ids
            .iter()
            .find(|(_, s)| **s == stable_id)
            .map(|(input, _)| *input)
    };
    let route_b = match (in_b(from), in_b(to)) {
        (Some(f), Some(t)) => route_between(&second.nrg, f, t),
        _ => None,
    };
    let waypoints_b = route_b.map(|r| r.waypoints).unwrap_or_default();
    let png = crate::render::kind_picture_png(&shut, &second.labels, &second.nrg, &waypoints_b)?;
    crate::atomic::write(&picture_b, &png).map_err(io(&picture_b))?;
    say(
        out,
        format!(
            "6. wrote {} (IndoorGML 1.0.3 of revision {b}), {} (revision {a}, as mapped) and {} (revision {b}, door {} shut); rooms blue, corridors orange, doors green, the route in red; ground truth in {} and {}",
            gml.display(),
            picture_a.display(),
            picture_b.display(),
            stable(door),
            files.gt_png.display(),
            files.truth_json.display()
        ),
    )?;
    say(
        out,
        format!(
            "done in {:.1} s. Try: nrgdb query --db {} --map {} 'FIND rooms ORDER BY area DESC LIMIT 5'",
            secs(start.elapsed()),
            opts.db,
            opts.map
        ),
    )?;
    Ok(())
}

fn secs(d: Duration) -> f64 {
    d.as_secs_f64()
}

fn indent(text: &str) -> String {
    text.trim_end()
        .lines()
        .map(|l| format!("   {l}"))
        .collect::<Vec<_>>()
        .join("\n")
}

fn census(nrg: &Nrg) -> String {
    let of = |k: SpaceKind| nrg.spaces().iter().filter(|s| s.kind == k).count();
    format!(
        "{}, {}, {}, {}",
        count(of(SpaceKind::Room), "room", "rooms"),
        count(of(SpaceKind::Corridor), "corridor", "corridors"),
        count(of(SpaceKind::Door), "door", "doors"),
        count(nrg.connections().len(), "connection", "connections")
    )
}

/// The shortest route from `from` to `to`, if there is one.
fn route_between(nrg: &Nrg, from: SpaceId, to: SpaceId) -> Option<crate::route::Route> {
    let nav = NavMesh::new(std::sync::Arc::new(nrg.clone()));
    let budget = Budget::new(Duration::from_secs(5));
    let routes = shortest_route(&nav, &RouteRequest::new(from, to), &budget).ok()?;
    routes.into_iter().next()
}

/// The route between two rooms with the most doors on it (ties: longer).
fn longest_room_route(nrg: &Nrg) -> Option<(SpaceId, SpaceId, crate::route::Route)> {
    let nav = NavMesh::new(std::sync::Arc::new(nrg.clone()));
    let rooms: Vec<SpaceId> = nrg
        .spaces()
        .iter()
        .filter(|s| s.kind == SpaceKind::Room)
        .map(|s| s.id)
        .collect();
    let from = *rooms.first()?;
    let budget = Budget::new(Duration::from_secs(5));
    rooms[1..]
        .iter()
        .filter_map(|&to| {
            let routes = shortest_route(&nav, &RouteRequest::new(from, to), &budget).ok()?;
            routes.into_iter().next().map(|r| (from, to, r))
        })
        .filter(|(_, _, r)| !r.doors.is_empty())
        .max_by(|x, y| {
            (x.2.doors.len(), x.2.length_m)
                .partial_cmp(&(y.2.doors.len(), y.2.length_m))
                .unwrap_or(std::cmp::Ordering::Equal)
        })
}

/// Spaces and connections that differ between two revisions of one map.
fn changes(old: &Nrg, new: &Nrg) -> String {
    let ids = |n: &Nrg| n.spaces().iter().map(|s| s.id).collect::<BTreeSet<_>>();
    let links = |n: &Nrg| {
        n.connections()
            .iter()
            .map(|c| (c.a, c.b, c.kind))
            .collect::<BTreeSet<_>>()
    };
    let (o, n) = (ids(old), ids(new));
    let label = |nrg: &Nrg, id: SpaceId| nrg.space(id).map_or(id.to_string(), |s| s.label());
    let mut lines = Vec::new();
    for id in o.difference(&n) {
        lines.push(format!("removed space {}", label(old, *id)));
    }
    for id in n.difference(&o) {
        lines.push(format!("added space {}", label(new, *id)));
    }
    let (lo, ln) = (links(old), links(new));
    for (a, b, k) in lo.difference(&ln) {
        lines.push(format!(
            "removed {k} connection {} – {}",
            label(old, *a),
            label(old, *b)
        ));
    }
    for (a, b, k) in ln.difference(&lo) {
        lines.push(format!(
            "added {k} connection {} – {}",
            label(new, *a),
            label(new, *b)
        ));
    }
    if lines.is_empty() {
        lines.push("no change".into());
    }
    lines.join("\n")
}
