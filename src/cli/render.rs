//! `nrgdb render`: a model as a picture (PNG or SVG): spaces by kind over
//! the occupancy map, the graph, labels, a route, a diff, a legend and a
//! scale bar.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use miette::{IntoDiagnostic, WrapErr};
use nrgdb::diff::{DiffOptions, compare};
use nrgdb::format::PictureFormat;
use nrgdb::grid::{LoadOptions, OccupancyGrid, load_map};
use nrgdb::model::{Nrg, SpaceId};
use nrgdb::query::LoadedRevision;
use nrgdb::render::{
    Drawing, LabelMode, RenderOptions, RouteOverlay, Scene, diff_by_level, diff_overlay,
    drawing_svg, layout, route_by_level,
};
use nrgdb::route::{Budget, NavMesh, Route, RouteRequest, shortest_route};

use super::db::{DbArg, parse_map_rev};
use super::diff::load_file;

/// Draw a model as a picture: each space filled by its kind over the
/// occupancy map, the graph with labels, optionally a route or the changes
/// between two revisions, with a legend and a scale bar in metres.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// NAME[@REV] of a map in the database, or a model file (.gml, .json,
    /// .geojson, or a .yaml occupancy map, extracted first and drawn behind).
    pub model: String,
    /// The picture to write; the extension picks the format (.png or .svg).
    #[arg(long, value_name = "FILE.png|FILE.svg")]
    pub out: PathBuf,
    /// An occupancy map (ROS map YAML) to draw behind the model.
    #[arg(long, value_name = "MAP.yaml")]
    pub map: Option<PathBuf>,
    /// Draw the shortest route between two spaces (ids or names).
    #[arg(long, num_args = 2, value_names = ["FROM", "TO"])]
    pub route: Option<Vec<String>>,
    /// Draw what changed from A to B (revision numbers of the map, NAME@REV,
    /// or model files); the picture shows B with the change set of `nrgdb diff A B`.
    #[arg(long, num_args = 2, value_names = ["A", "B"])]
    pub diff: Option<Vec<String>>,
    /// Pixels per metre [default: the longer side about 1200 px].
    #[arg(long, value_name = "PX_PER_M")]
    pub scale: Option<f64>,
    /// How spaces are labelled: names (name or id; doors unlabelled), ids, none.
    #[arg(long, default_value = "names")]
    pub labels: LabelMode,
    /// Leave out the legend and the scale bar.
    #[arg(long)]
    pub no_legend: bool,
    /// Leave out the graph (nodes and edges).
    #[arg(long)]
    pub no_graph: bool,
    /// The level drawn, in a building with levels (each level is a picture of its own).
    #[arg(long, value_name = "LEVEL")]
    pub level: Option<String>,
    #[command(flatten)]
    pub db: DbArg,
}

/// Runs `nrgdb render`.
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let format = PictureFormat::of(&args.out).into_diagnostic()?;
    let base = resolve(&args.model, None, &args.db)?;
    let background = match &args.map {
        Some(path) => Some(load_grid(path)?),
        None => base.map_grid.clone(),
    };
    let (nrg, title, diff, old, changed) = match &args.diff {
        Some(pair) => {
            let (Some(a), Some(b)) = (pair.first(), pair.get(1)) else {
                miette::bail!("--diff needs two revisions: --diff A B");
            };
            let old = resolve(a, Some(&base), &args.db)?;
            let new = resolve(b, Some(&base), &args.db)?;
            // The change set of `nrgdb diff A B`, drawn over B.
            let done = compare(old.rev.side(), new.rev.side(), &DiffOptions::default())
                .into_diagnostic()
                .wrap_err_with(|| {
                    format!("--diff: comparing {} with {}", old.rev.label, new.rev.label)
                })?;
            let overlay = diff_overlay(&done.changes, &old.rev.nrg, &new.rev.nrg);
            let title = format!("{} -> {}", old.rev.label, new.rev.label);
            let changed = done.changes.changed_levels();
            (
                new.rev.nrg,
                title,
                Some(overlay),
                Some(old.rev.nrg),
                changed,
            )
        }
        None => (base.rev.nrg, base.rev.label, None, None, Vec::new()),
    };
    // The route over the whole building (across its levels).
    let route = match &args.route {
        Some(pair) => {
            let (Some(from), Some(to)) = (pair.first(), pair.get(1)) else {
                miette::bail!("--route needs two spaces: --route FROM TO");
            };
            match shortest(&nrg, from, to)? {
                Some(r) => Some(r),
                None => {
                    writeln!(out, "no route from {from} to {to}").into_diagnostic()?;
                    return Ok(ExitCode::from(1));
                }
            }
        }
        None => None,
    };
    let options = RenderOptions {
        px_per_m: args.scale,
        labels: args.labels,
        legend: !args.no_legend,
        graph: !args.no_graph,
        title: Some(title.clone()),
        ..RenderOptions::default()
    };
    let route_said = |r: &Route| format!(", route {:.1} m", r.length_m);
    let levels = nrg.levels();
    let names: Vec<&str> = levels.iter().map(|l| l.name.as_str()).collect();
    let (floor, overlay, diff, level) = match (&args.level, levels.is_empty(), &route) {
        (Some(l), true, _) => miette::bail!("--level {l}: this map has no levels"),
        (None, true, _) => (
            nrg.clone(),
            route.as_ref().map(|r| RouteOverlay::of_route(&nrg, r)),
            diff,
            None,
        ),
        (None, false, Some(r)) => {
            if diff.is_some() {
                miette::bail!(
                    "this map has levels {}: draw a route or a diff, or give --level",
                    names.join(", ")
                );
            }
            // One panel for each level the route is on.
            let drawing = route_by_level(&nrg, r, &options)
                .into_diagnostic()
                .wrap_err_with(|| format!("{}: cannot draw the picture", args.out.display()))?;
            write_drawing(&args.out, format, &drawing)?;
            let on: Vec<&str> = r.levels.iter().map(|s| s.level.as_str()).collect();
            writeln!(
                out,
                "wrote {} (levels {}{})",
                args.out.display(),
                on.join(" -> "),
                route_said(r)
            )
            .into_diagnostic()?;
            return Ok(ExitCode::SUCCESS);
        }
        (None, false, None) => {
            let (Some(d), Some(old)) = (&diff, &old) else {
                miette::bail!(
                    "this map has levels {}: draw one with --level",
                    names.join(", ")
                );
            };
            if changed.is_empty() {
                writeln!(out, "no level changed: nothing drawn").into_diagnostic()?;
                return Ok(ExitCode::SUCCESS);
            }
            // One panel for each level that changed.
            let drawing = diff_by_level(old, &nrg, d, &changed, &options)
                .into_diagnostic()
                .wrap_err_with(|| format!("{}: cannot draw the picture", args.out.display()))?;
            write_drawing(&args.out, format, &drawing)?;
            writeln!(
                out,
                "wrote {} (changed levels {}: {} added, {} removed, {} changed)",
                args.out.display(),
                changed.join(", "),
                d.added.len(),
                d.removed.len(),
                d.changed.len()
            )
            .into_diagnostic()?;
            return Ok(ExitCode::SUCCESS);
        }
        (Some(l), false, _) => {
            let Some(floor) = nrg.level_model(l) else {
                miette::bail!(
                    "--level {l}: no such level (the map has {})",
                    names.join(", ")
                );
            };
            let overlay = route
                .as_ref()
                .and_then(|r| RouteOverlay::on_level(&nrg, r, l));
            if route.is_some() && overlay.is_none() {
                writeln!(out, "the route does not pass level {l}").into_diagnostic()?;
            }
            let diff = match (diff, &old) {
                (Some(d), Some(old)) => Some(d.on_level(old, &nrg, l)),
                _ => None,
            };
            (floor, overlay, diff, Some(l.clone()))
        }
    };
    let options = RenderOptions {
        title: Some(match &level {
            Some(l) => format!("{title} level {l}"),
            None => title,
        }),
        ..options
    };
    let scene = Scene {
        nrg: &floor,
        map: background.as_ref(),
        route: overlay.as_ref(),
        diff: diff.as_ref(),
        options: &options,
    };
    write_picture(&args.out, format, &scene)?;
    writeln!(
        out,
        "wrote {} ({} spaces{}{})",
        args.out.display(),
        floor.spaces().len(),
        route.as_ref().map(route_said).unwrap_or_default(),
        diff.as_ref()
            .map(|d| format!(
                ", {} added, {} removed, {} changed",
                d.added.len(),
                d.removed.len(),
                d.changed.len()
            ))
            .unwrap_or_default()
    )
    .into_diagnostic()?;
    Ok(ExitCode::SUCCESS)
}

/// Renders `scene` and writes it atomically to `path` as `format`.
pub fn write_picture(path: &Path, format: PictureFormat, scene: &Scene<'_>) -> miette::Result<()> {
    let drawing = layout(scene)
        .into_diagnostic()
        .wrap_err_with(|| format!("{}: cannot draw the picture", path.display()))?;
    write_drawing(path, format, &drawing)
}

/// Writes a laid-out drawing atomically to `path` as `format`.
fn write_drawing(path: &Path, format: PictureFormat, drawing: &Drawing) -> miette::Result<()> {
    let bytes = match format {
        PictureFormat::Svg => drawing_svg(drawing).map(String::into_bytes),
        #[cfg(feature = "render")]
        PictureFormat::Png => nrgdb::render::drawing_png(drawing),
        #[cfg(not(feature = "render"))]
        PictureFormat::Png => miette::bail!(
            "{}: this nrgdb was built without the `render` feature, so it cannot write PNG (write .svg)",
            path.display()
        ),
    }
    .into_diagnostic()
    .wrap_err_with(|| format!("{}: cannot draw the picture", path.display()))?;
    nrgdb::atomic::write(path, &bytes)
        .into_diagnostic()
        .wrap_err_with(|| format!("{}: cannot write", path.display()))
}

/// A model to draw (labelled with where it came from, with the grid it
/// was extracted from when known), and its map when it is one.
struct Resolved {
    rev: LoadedRevision,
    /// The map's name in the database (for `--diff 1 3`).
    map_name: Option<String>,
    /// The grid of the .yaml occupancy map the model was extracted from.
    map_grid: Option<OccupancyGrid>,
}

/// `spec` is a model file, NAME[@REV], or (with `base` a stored map) a bare
/// revision number of that map.
fn resolve(spec: &str, base: Option<&Resolved>, db: &DbArg) -> miette::Result<Resolved> {
    let path = Path::new(spec);
    if path.is_file() {
        let rev = load_file(path)?;
        return Ok(Resolved {
            map_grid: rev.grid.clone(),
            rev,
            map_name: None,
        });
    }
    let (name, rev) = match (spec.parse::<u32>(), base.and_then(|b| b.map_name.clone())) {
        (Ok(n), Some(name)) => (name, Some(n)),
        (Ok(_), None) => miette::bail!(
            "'{spec}' is a bare revision number but the model is not a stored map \
             (give NAME@REV or a model file)"
        ),
        (Err(_), _) => parse_map_rev(spec)?,
    };
    if !nrgdb::store::is_postgres_url(&db.db) && !std::path::Path::new(&db.db).exists() {
        miette::bail!(
            "'{spec}' is not a file, and there is no database {} to find a map in \
             (give a model file, or --db DB / NRGDB_DB)",
            db.shown()
        );
    }
    let store = db.open_existing()?;
    let info = store
        .revision(&name, rev)
        .into_diagnostic()
        .wrap_err_with(|| {
            format!(
                "'{spec}' is neither a file nor a revision in {}",
                db.shown()
            )
        })?;
    let rev = LoadedRevision::load(&store, &name, u64::from(info.seq))
        .into_diagnostic()
        .wrap_err_with(|| format!("loading {name}@{}", info.seq))?;
    Ok(Resolved {
        rev,
        map_name: Some(name),
        map_grid: None,
    })
}

fn load_grid(path: &Path) -> miette::Result<OccupancyGrid> {
    load_map(path, &LoadOptions::default())
        .into_diagnostic()
        .wrap_err_with(|| format!("{}: cannot load the map to draw behind", path.display()))
}

/// A space by id, or by name (case-insensitive) or label.
fn find_space(nrg: &Nrg, text: &str) -> miette::Result<SpaceId> {
    if let Ok(n) = text.parse::<u32>()
        && nrg.space(SpaceId(n)).is_some()
    {
        return Ok(SpaceId(n));
    }
    nrg.spaces()
        .iter()
        .find(|s| {
            s.name
                .as_deref()
                .is_some_and(|n| n.eq_ignore_ascii_case(text))
                || s.label().eq_ignore_ascii_case(text)
        })
        .map(|s| s.id)
        .ok_or_else(|| {
            miette::miette!(
                "--route: no space '{text}' (give a space id or name; see `nrgdb query`)"
            )
        })
}

/// The shortest route between two spaces (across levels in a building);
/// `None` when there is none.
fn shortest(nrg: &Nrg, from: &str, to: &str) -> miette::Result<Option<Route>> {
    let request = RouteRequest::new(find_space(nrg, from)?, find_space(nrg, to)?);
    let nav = NavMesh::new(std::sync::Arc::new(nrg.clone()));
    let routes = shortest_route(&nav, &request, &Budget::unlimited())
        .into_diagnostic()
        .wrap_err_with(|| format!("--route {from} {to}"))?;
    Ok(routes.into_iter().next())
}
