//! The extraction pipeline: clean → distance → segment → merge (small
//! regions, open joins) → doors → graph → polygons → [`Nrg`].

use std::collections::{BTreeMap, HashMap, HashSet};
use std::time::{Duration, Instant};

use super::ccl::segment_ccl;
use super::clean::clean_free;
use super::doors::{Border, borders, cut_doors};
use super::doorway::SpanLimits;
use super::filled::filled_diameters;
use super::graph::topology;
use super::interior::{claim_enclosed_unknown, fill_specks};
use super::joins::{JoinLimits, open_joins};
use super::merge::{merge_pairs, merge_small};
use super::passages::give_passages_to_narrow_side;
use super::polygon::outlines;
use super::resample::{coarsen, pixel_centroids, refine};
use super::segment::segment_basins;
use super::skeleton_doors::skeleton_doorways;
use super::stubs::{StubLimits, compared_width, passage_labels, split_off_passages};
use super::tidy::tidy_labels;
use super::wall_gaps::{GapLimits, WallGap, close_gaps, reopen_gaps, wall_gaps};
use super::{DoorRule, ExtractError, ExtractParams, Method};
use crate::grid::{Cell, OccupancyGrid};
use crate::imaging::{Labels, distance_to_background, max_distance};
use crate::model::{Connection, Nrg, Space, SpaceId, SpaceKind, point_in_ring};

/// A border is a door under `DoorRule::Skeleton` if it passes this close
/// (pixels) to a doorway point: the watershed border and the skeletons'
/// crossing need not share a pixel.
const SKELETON_NEAR_PX: f64 = 2.0;

/// How far (m) from a door border's centre, across it, its doorway's
/// narrowest chord is sought.
const SPAN_SEARCH_M: f64 = 0.25;

/// The thickest wall (m) a door spans from face to face: an opening of
/// even width that runs on further is a passage (a corridor piece), and
/// its door stays thin. The IPA maps' drawn walls are up to 0.65 m with
/// their anti-aliased edges; built walls are thinner.
const SPAN_MAX_DEPTH_M: f64 = 0.7;

/// How much (m) an opening may widen at either end and still be inside its
/// wall (anti-aliased and ragged jambs).
const SPAN_SLACK_M: f64 = 0.05;

/// Unlabelled specks smaller than this (m²) inside one space join it.
const MIN_HOLE_M2: f64 = 0.25;

/// Unknown pockets no thicker than this (m) bordered mostly by obstacles
/// are the insides of walls, not of furniture: they stay out of spaces.
const WALL_MAX_M: f64 = 0.3;

/// The result of [`extract`].
#[derive(Debug, Clone)]
pub struct Extraction {
    /// The NRG, in metres in the map frame.
    pub nrg: Nrg,
    /// Space id per pixel (0 = in no space), the map's size, row 0 at the top.
    pub labels: Labels,
    /// Mean `[col, row]` of each space's pixels.
    pub pixel_centroids: BTreeMap<SpaceId, [f64; 2]>,
    /// Wall-clock time of each stage, in order.
    pub timings: Vec<(&'static str, Duration)>,
}

struct Clock {
    last: Instant,
    timings: Vec<(&'static str, Duration)>,
}

impl Clock {
    fn lap(&mut self, stage: &'static str) {
        let now = Instant::now();
        self.timings.push((stage, now - self.last));
        self.last = now;
    }
}

/// Extracts the NRG of rooms, corridors and doors from an occupancy grid.
///
/// ```
/// use nrgdb::extract::{ExtractParams, extract};
/// use nrgdb::grid::OccupancyGrid;
/// // Two 2 m rooms joined by a 0.8 m doorway, at 0.1 m/px.
/// let mut rows = vec!["#".repeat(45)];
/// for y in 0..20 {
///     let door = (6..14).contains(&y);
///     rows.push(format!("#{}{}{}#", ".".repeat(20), if door { ".." } else { "##" }, ".".repeat(21)));
/// }
/// rows.push("#".repeat(45));
/// let grid = OccupancyGrid::from_ascii(&rows.join("\n"), 0.1);
/// let x = extract(&grid, &ExtractParams::default()).unwrap();
/// let doors = x.nrg.spaces().iter().filter(|s| s.kind.as_str() == "door").count();
/// assert_eq!((x.nrg.spaces().len(), doors), (3, 1));
/// ```
pub fn extract(grid: &OccupancyGrid, params: &ExtractParams) -> Result<Extraction, ExtractError> {
    params.validate()?;
    let k = (params.working_resolution_m / grid.resolution + 1e-9).floor();
    if !(2.0..=64.0).contains(&k) {
        return extract_at(grid, params);
    }
    let k = k as u32;
    let started = Instant::now();
    let coarse = coarsen(grid, k);
    let coarsen_time = started.elapsed();
    let mut x = extract_at(&coarse, params)?;
    let started = Instant::now();
    x.labels = refine(&x.labels, grid, k);
    x.pixel_centroids = pixel_centroids(&x.labels);
    x.timings.insert(0, ("coarsen", coarsen_time));
    x.timings.push(("refine", started.elapsed()));
    Ok(x)
}

/// [`extract`] at the grid's own resolution.
fn extract_at(grid: &OccupancyGrid, params: &ExtractParams) -> Result<Extraction, ExtractError> {
    let res = grid.resolution;
    let mut clock = Clock {
        last: Instant::now(),
        timings: Vec::new(),
    };
    let mut free = clean_free(
        grid,
        params.noise_radius_m,
        params.min_free_area_m2,
        params.furniture_max_m,
        params.wall_gap_width_max_m,
    );
    if free.clean.iter().all(|&p| p == 0) {
        return Err(ExtractError::NoSpace {
            noise_m: params.noise_radius_m,
            min_area_m2: params.min_free_area_m2,
        });
    }
    let gaps = match params.method {
        Method::Watershed if params.wall_jamb_m > 0.0 => {
            let px = |m: f64| (m / res).round() as usize;
            wall_gaps(
                &free.clean,
                GapLimits {
                    width: (px(params.door_width_min_m), px(params.wall_gap_width_max_m)),
                    jamb: px(params.wall_jamb_m).max(1),
                    depth: px(params.wall_thickness_max_m).max(1),
                },
            )
        }
        _ => Vec::new(),
    };
    clock.lap("clean");
    // The paper's doorway points (Tab. 2), taken before the gaps close.
    let skeleton = (params.method == Method::Watershed && params.door_rule == DoorRule::Skeleton)
        .then(|| {
            skeleton_doorways(
                &free.clean,
                params.skeleton_erode_m / res,
                params.skeleton_open_m / res,
                SKELETON_NEAR_PX,
            )
        });
    if skeleton.is_some() {
        clock.lap("skeleton");
    }
    close_gaps(&mut free.clean, &mut free.reachable, &gaps);
    let dist = distance_to_background(&free.clean);
    clock.lap("distance");
    let min_free_px = (params.min_free_area_m2 / (res * res)).ceil() as usize;
    let mut regions = match params.method {
        Method::Watershed => segment_basins(
            &free.clean,
            &free.reachable,
            &dist,
            params.core_radius_m / res,
            min_free_px,
            (params.split_min_core_m2 / (res * res)).ceil() as usize,
        ),
        Method::Ccl => segment_ccl(
            &free.clean,
            &free.reachable,
            params.ccl_erode_m / res,
            params.ccl_open_m / res,
            min_free_px,
        ),
    };
    clock.lap("segment");
    merge_small(
        &mut regions,
        (params.min_room_area_m2 / (res * res)).ceil() as usize,
    );
    reopen_gaps(&mut regions, &gaps);
    clock.lap("merge");
    let join_px = (params.door_join_m / res).round() as i64;
    let mut widest = widest_passages(&regions, &dist);
    let mut in_passage = Vec::new();
    if params.passage_min_length_m > 0.0 {
        let stub = StubLimits {
            radius_px: (params.door_width_max_m / res / 2.0) as f32,
            width_min_px: (params.door_width_min_m / res) as f32,
            length_min_px: (params.passage_min_length_m / res) as f32,
            constriction: params.door_constriction,
        };
        in_passage = split_off_passages(&mut regions, &dist, &widest, &stub);
        if !in_passage.is_empty() {
            merge_small(
                &mut regions,
                (params.min_room_area_m2 / (res * res)).ceil() as usize,
            );
            widest = widest_passages(&regions, &dist);
        }
    }
    let passages_of = |regions: &Labels| {
        if in_passage.is_empty() {
            vec![false; regions.count as usize + 1]
        } else {
            passage_labels(regions, &in_passage)
        }
    };
    let mut is_passage = passages_of(&regions);
    clock.lap("passages");
    let mut all = borders(&regions, &dist, join_px);
    let gap_px: HashSet<u32> = gaps.iter().flat_map(|g| g.line.iter().copied()).collect();
    let limits = JoinLimits {
        door_min_px: params.door_width_min_m / res,
        door_max_px: params.door_width_max_m / res,
        constriction: params.door_constriction,
        fraction: params.open_join_fraction,
    };
    let joins = open_joins(&all, &widest, &is_passage, &gap_px, &limits);
    if !joins.is_empty() {
        merge_pairs(&mut regions, &joins);
        all = borders(&regions, &dist, join_px);
        widest = widest_passages(&regions, &dist);
        is_passage = passages_of(&regions);
    }
    clock.lap("joins");
    let rule = DoorCues {
        gaps: &gaps,
        skeleton: skeleton.as_deref(),
    };
    let first = select_doors(&all, &widest, &is_passage, &rule, params, res);
    // Doors found mid-passage move to the passage's mouth; the borders and
    // doors are found again only if one did.
    let window_px = (2.0 * params.door_width_max_m / res).ceil() as usize;
    let first_doors: Vec<&Border> = first.iter().map(|&k| &all[k]).collect();
    let moved = give_passages_to_narrow_side(&mut regions, &dist, &first_doors, &widest, window_px);
    let (all, chosen) = if moved {
        let all = borders(&regions, &dist, join_px);
        let chosen = select_doors(
            &all,
            &widest_passages(&regions, &dist),
            &is_passage,
            &rule,
            params,
            res,
        );
        (all, chosen)
    } else {
        (all, first)
    };
    let doors: Vec<&Border> = chosen.iter().map(|&k| &all[k]).collect();
    let door_pairs: Vec<(u32, u32)> = doors.iter().map(|b| b.pair).collect();
    let n_regions = regions.count;
    let span_limits = SpanLimits {
        max_width: 1.15 * params.door_width_max_m.max(params.wall_gap_width_max_m) / res,
        search: (SPAN_SEARCH_M / res).max(2.0),
        min_depth: (params.door_depth_m / res).max(1.0),
        max_depth: (params.wall_thickness_max_m.min(SPAN_MAX_DEPTH_M) / res).max(1.0),
        slack: (SPAN_SLACK_M / res).max(1.5),
    };
    // Doorway chords end at the map's walls; other pixels outside the
    // regions may be noise they cross (see `doorway::Pixel`).
    let walls = wall_pixels(grid);
    let (mut labels, door_lines) = cut_doors(&regions, Some(&walls), &doors, &dist, &span_limits);
    claim_enclosed_unknown(
        &mut labels,
        grid,
        (params.unknown_pocket_max_m2 / (res * res)).floor() as usize,
        (WALL_MAX_M / res).ceil() as usize,
        n_regions + 1,
    );
    fill_specks(&mut labels, (MIN_HOLE_M2 / (res * res)).floor() as usize);
    clock.lap("doors");
    // One simple polygon per space: before the graph, so that it and the
    // polygons see the same labels.
    tidy_labels(&mut labels);
    clock.lap("tidy");
    // A corridor by its outline: the clutter standing in a space is filled
    // before its width is taken (see `filled`).
    let shape: Vec<(usize, f64)> = region_shapes(&labels, &dist)
        .into_iter()
        .zip(filled_diameters(&labels, n_regions))
        .map(|((area, _), diameter)| (area, diameter))
        .collect();
    let topo = topology(
        &labels,
        n_regions,
        &door_pairs,
        &shape,
        params.corridor_min_elongation,
        (params.door_width_max_m / res).ceil() as usize,
    );
    clock.lap("graph");
    let out = build(
        grid,
        labels,
        &dist,
        &topo.kinds,
        &topo.edges,
        params.simplify_m,
        &DoorLines {
            first: n_regions + 1,
            lines: &door_lines,
        },
    )?;
    clock.lap("polygons");
    let (labels, nrg, pixel_centroids) = out;
    Ok(Extraction {
        nrg,
        labels,
        pixel_centroids,
        timings: clock.timings,
    })
}

/// Pixels that are surely walls: occupied cells, and cells next to one
/// (8-neighbours: the uncertain halo of a scanned wall, a blurred drawn
/// wall). A 3 × 3 dilation, by rows then by columns.
fn wall_pixels(grid: &OccupancyGrid) -> Vec<bool> {
    let w = grid.width as usize;
    let occupied: Vec<bool> = grid.cells.iter().map(|c| *c == Cell::Occupied).collect();
    let mut rows = occupied.clone();
    for (row, out) in occupied.chunks(w.max(1)).zip(rows.chunks_mut(w.max(1))) {
        for x in 0..row.len() {
            out[x] = row[x.saturating_sub(1)..(x + 2).min(row.len())].contains(&true);
        }
    }
    (0..rows.len())
        .map(|i| rows[i] || (i >= w && rows[i - w]) || rows.get(i + w).is_some_and(|&r| r))
        .collect()
}

/// The indices of the borders of `all` that are doors. With the skeleton
/// cue (`DoorRule::Skeleton`), those touching a doorway point. Otherwise
/// those along a doorway gap's line, and those between `door_width_min_m`
/// and `door_width_max_m` wide that are a constriction of the narrower
/// region (`widest`: each region's widest inscribed diameter, px; see
/// `compared_width` for passages) and whose regions do not also meet wider
/// than any door.
fn select_doors(
    all: &[Border],
    widest: &[f64],
    is_passage: &[bool],
    cues: &DoorCues,
    params: &ExtractParams,
    res: f64,
) -> Vec<usize> {
    if let Some(skeleton) = cues.skeleton {
        return (0..all.len())
            .filter(|&k| all[k].pixels.iter().any(|&p| skeleton[p as usize]))
            .collect();
    }
    let gaps = cues.gaps;
    let door_px = params.door_width_max_m / res;
    let door_min_px = params.door_width_min_m / res;
    let constriction =
        |b: &Border| params.door_constriction * compared_width(b.pair, widest, is_passage);
    let gap_at: HashMap<u32, usize> = gaps
        .iter()
        .enumerate()
        .flat_map(|(k, g)| g.line.iter().map(move |&p| (p, k)))
        .collect();
    let crosses_gap = |b: &Border| {
        let mut hits: HashMap<usize, usize> = HashMap::new();
        for k in b.pixels.iter().filter_map(|p| gap_at.get(p)) {
            *hits.entry(*k).or_default() += 1;
        }
        hits.iter().any(|(&k, &n)| 2 * n >= gaps[k].line.len())
    };
    // Pairs of regions that also meet wider than any door: openly joined,
    // so a narrow stretch between them elsewhere (a nook between furniture
    // and a wall) is no doorway.
    let open_pairs: HashSet<(u32, u32)> = all
        .iter()
        .filter(|b| b.width_px > door_px)
        .map(|b| b.pair)
        .collect();
    (0..all.len())
        .filter(|&k| {
            let b = &all[k];
            // A doorway in a wall is a door whatever the widths around it.
            crosses_gap(b)
                || (b.width_px >= door_min_px
                    && b.width_px <= door_px
                    && b.pixels.len() as f64 >= door_min_px
                    && b.width_px <= constriction(b)
                    && !open_pairs.contains(&b.pair))
        })
        .collect()
}

/// What marks a doorway besides the borders' widths.
struct DoorCues<'a> {
    /// Doorway gaps in walls.
    gaps: &'a [WallGap],
    /// With `DoorRule::Skeleton`: per pixel, near a doorway point of the
    /// paper's Tab. 2; a border is a door iff it touches one.
    skeleton: Option<&'a [bool]>,
}

/// The widest inscribed diameter (px) of every label.
fn widest_passages(labels: &Labels, dist: &[f32]) -> Vec<f64> {
    region_shapes(labels, dist)
        .into_iter()
        .map(|s| s.1)
        .collect()
}

/// (area in px, widest inscribed diameter in px) of every label.
fn region_shapes(labels: &Labels, dist: &[f32]) -> Vec<(usize, f64)> {
    let mut s = vec![(0usize, 0.0f32); labels.count as usize + 1];
    // A run of one label updates it once (no store-to-load chain per pixel).
    let mut i = 0;
    while i < labels.data.len() {
        let l = labels.data[i];
        let run = labels.data[i..].iter().position(|&m| m != l);
        let end = run.map_or(labels.data.len(), |r| i + r);
        let e = &mut s[l as usize];
        e.0 += end - i;
        e.1 = e.1.max(max_distance(&dist[i..end]));
        i = end;
    }
    s.into_iter()
        .map(|(a, d)| (a, 2.0 * f64::from(d)))
        .collect()
}

type Built = (Labels, Nrg, BTreeMap<SpaceId, [f64; 2]>);

/// The doorway lines of the door labels (pixel coordinates): label
/// `first + k` has `lines[k]`.
struct DoorLines<'a> {
    first: u32,
    lines: &'a [Option<[[f64; 2]; 2]>],
}

impl DoorLines<'_> {
    fn of(&self, label: usize) -> Option<[[f64; 2]; 2]> {
        let k = label.checked_sub(self.first as usize)?;
        self.lines.get(k).copied().flatten()
    }
}

/// Renumbers non-empty labels to space ids 1..=n and builds spaces and connections.
fn build(
    grid: &OccupancyGrid,
    mut labels: Labels,
    dist: &[f32],
    kinds: &[SpaceKind],
    edges: &[(u32, u32, crate::model::ConnectionKind)],
    simplify_m: f64,
    door_lines: &DoorLines<'_>,
) -> Result<Built, ExtractError> {
    let n = labels.count as usize + 1;
    let w = labels.width as usize;
    // Per label: pixel count, sum of col/row, best anchor pixel.
    let mut count = vec![0usize; n];
    let mut sum = vec![[0.0f64; 2]; n];
    let mut best = vec![(-1.0f32, 0usize); n];
    for (y, row) in labels.data.chunks_exact(w.max(1)).enumerate() {
        for (x, &l) in row.iter().enumerate() {
            if l == 0 {
                continue;
            }
            let (l, i) = (l as usize, y * w + x);
            count[l] += 1;
            sum[l][0] += x as f64;
            sum[l][1] += y as f64;
            if dist[i] > best[l].0 {
                best[l] = (dist[i], i);
            }
        }
    }
    let mut new_id = vec![0u32; n];
    let mut next = 0u32;
    for l in 1..n {
        if count[l] > 0 {
            next += 1;
            new_id[l] = next;
        }
    }
    if next > u32::from(u16::MAX) {
        return Err(ExtractError::TooManySpaces(next as usize));
    }
    for v in &mut labels.data {
        *v = new_id[*v as usize];
    }
    labels.count = next;
    // Anchor: of the pixels (nearly) farthest from a wall, the one nearest
    // the label's centroid — a corridor's middle, not its first pixel in
    // scan order, and the same pixel after a quarter turn of the map.
    let centre = |l: usize| {
        let c = count[l].max(1) as f64;
        [sum[l][0] / c, sum[l][1] / c]
    };
    let mut pick = vec![(f64::INFINITY, 0usize); n];
    for (y, row) in labels.data.chunks_exact(w.max(1)).enumerate() {
        for (x, &l) in row.iter().enumerate() {
            let (l, i) = (l as usize, y * w + x);
            if l == 0 || dist[i] < best[l].0 - 1.0 {
                continue;
            }
            let c = centre(l);
            let d2 = (x as f64 - c[0]).powi(2) + (y as f64 - c[1]).powi(2);
            if d2 < pick[l].0 {
                pick[l] = (d2, i);
            }
        }
    }
    let mut outlines = outlines(&labels, grid, simplify_m);
    let mut spaces = Vec::with_capacity(next as usize);
    let mut centroids = BTreeMap::new();
    for l in 1..n {
        let id = new_id[l];
        if id == 0 {
            continue;
        }
        let (polygon, holes) = std::mem::take(&mut outlines[id as usize]);
        let door = kinds[l] == SpaceKind::Door;
        let line = door_lines.of(l).filter(|_| door).map(|[a, b]| {
            [
                grid.pixel_to_metres(a[0], a[1]),
                grid.pixel_to_metres(b[0], b[1]),
            ]
        });
        // A door's anchor is the middle of its doorway line (else of its
        // pixels); other spaces' the pixel picked above.
        let middle = line
            .map(|[a, b]| [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0])
            .filter(|m| point_in_ring(*m, &polygon) && !holes.iter().any(|h| point_in_ring(*m, h)));
        let anchor = if let Some(m) = middle {
            m
        } else if door {
            let c = centre(l);
            grid.pixel_to_metres(c[0] + 0.5, c[1] + 0.5)
        } else {
            let i = pick[l].1;
            grid.pixel_to_metres((i % w) as f64 + 0.5, (i / w) as f64 + 0.5)
        };
        let mut space = Space::new(SpaceId(id), kinds[l], anchor, polygon);
        space.holes = holes;
        if line.is_some() {
            space.doorway = line;
        }
        space.update_area();
        space.update_doorway();
        spaces.push(space);
        let c = count[l] as f64;
        centroids.insert(SpaceId(id), [sum[l][0] / c, sum[l][1] / c]);
    }
    let anchor_of = |id: u32| spaces.get(id as usize - 1).map(|s: &Space| s.anchor);
    let mut connections = Vec::new();
    for &(a, b, kind) in edges {
        let (na, nb) = (new_id[a as usize], new_id[b as usize]);
        if na == 0 || nb == 0 || na == nb {
            continue;
        }
        let (Some(pa), Some(pb)) = (anchor_of(na), anchor_of(nb)) else {
            continue;
        };
        let length_m = ((pa[0] - pb[0]).powi(2) + (pa[1] - pb[1]).powi(2)).sqrt();
        connections.push(Connection {
            a: SpaceId(na.min(nb)),
            b: SpaceId(na.max(nb)),
            kind,
            length_m,
        });
    }
    connections.sort_by_key(|c| (c.a, c.b));
    connections.dedup_by_key(|c| (c.a, c.b));
    let nrg = Nrg::new(spaces, connections)?;
    Ok((labels, nrg, centroids))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_narrow_stretch_beside_a_wide_opening_is_no_door() {
        // Two 6 x 6 m rooms at 0.1 m/px; the wall between them has a 2.5 m
        // opening at the top and, 1.5 m further down, a 0.8 m gap.
        let mut rows = vec!["#".repeat(123)];
        for y in 0..60 {
            let open = (5..30).contains(&y) || (45..53).contains(&y);
            rows.push(format!(
                "#{}{}{}#",
                ".".repeat(60),
                if open { "." } else { "#" },
                ".".repeat(60)
            ));
        }
        rows.push("#".repeat(123));
        let grid = OccupancyGrid::from_ascii(&rows.join("\n"), 0.1);
        // The 0.8 m gap in a straight wall is a doorway gap (a door
        // whatever else joins the rooms); without gap detection it is a
        // narrow border stretch like a nook between furniture and a wall.
        let with_gaps = extract(&grid, &ExtractParams::default()).unwrap();
        let doors = |x: &Extraction| {
            x.nrg
                .spaces()
                .iter()
                .filter(|s| s.kind == SpaceKind::Door)
                .count()
        };
        assert_eq!(doors(&with_gaps), 1);
        let params = ExtractParams {
            wall_jamb_m: 0.0,
            ..ExtractParams::default()
        };
        let x = extract(&grid, &params).unwrap();
        let kinds: Vec<&str> = x.nrg.spaces().iter().map(|s| s.kind.as_str()).collect();
        assert_eq!(kinds.len(), 2, "{kinds:?}");
        assert!(!kinds.contains(&"door"), "{kinds:?}");
        assert_eq!(x.nrg.connections().len(), 1);
        assert_eq!(
            x.nrg.connections()[0].kind,
            crate::model::ConnectionKind::Open
        );
    }

    #[test]
    fn a_corridor_stub_opens_into_its_room_through_a_door() {
        // A 6 x 4 m room at 0.1 m/px with a 1.2 m wide, 4 m long stub going
        // down from its floor, flush with its left wall: no narrowing at the
        // stub's mouth, so only the passage rule puts a door there.
        let mut rows = vec!["#".repeat(62)];
        for y in 0..80 {
            let row = if y < 40 {
                format!("#{}#", ".".repeat(60))
            } else {
                format!("#{}{}", ".".repeat(12), "#".repeat(49))
            };
            rows.push(row);
        }
        rows.push("#".repeat(62));
        let grid = OccupancyGrid::from_ascii(&rows.join("\n"), 0.1);
        let kinds = |x: &Extraction| {
            let mut k: Vec<&str> = x.nrg.spaces().iter().map(|s| s.kind.as_str()).collect();
            k.sort_unstable();
            k
        };
        let x = extract(&grid, &ExtractParams::default()).unwrap();
        assert_eq!(kinds(&x), ["door", "room", "room"]);
        let off = ExtractParams {
            passage_min_length_m: 0.0,
            ..ExtractParams::default()
        };
        assert_eq!(kinds(&extract(&grid, &off).unwrap()), ["room"]);
    }
}
