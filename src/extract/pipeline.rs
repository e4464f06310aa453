//! The extraction pipeline, as named stages over one [`Regions`]:
//! `clean` → `wall gaps` → `distance` → `segment` → `merge` → `passages`
//! → `joins` → `doors` (choice, then spans) → `tidy` → `graph` →
//! `polygons` → [`Nrg`]. The parameters are turned into pixels once
//! ([`PixelConfig`]); every stage takes them from there.

use std::collections::BTreeMap;
use std::time::{Duration, Instant};

use super::build::{DoorLines, build};
use super::ccl::segment_ccl;
use super::chord_pixels::{Pixel, outside_pixels};
use super::clean::{FreeSpace, clean_free};
use super::door_choice::{DoorCues, choose_doors};
use super::doors::{Border, cut_doors};
use super::filled::filled_diameters;
use super::furniture::{Islands, islands};
use super::geodesic::geodesic_lengths;
use super::graph::{SpaceShape, topology};
use super::interior::{claim_enclosed_unknown, fill_specks};
use super::merge::merge_small;
use super::pixel_config::{PixelConfig, Segmentation};
use super::regions::Regions;
use super::resample::{coarsen, pixel_centroids, refine};
use super::seen_walls::ends_on_seen_walls;
use super::segment::segment_basins;
use super::skeleton_doors::skeleton_doorways;
use super::stub_openings::stub_openings;
use super::tidy::tidy_labels;
use super::wall_gaps::{
    GapIndex, GapLimits, WallGap, close_gaps, near_lines, reopen_gaps, wall_gaps,
};
use super::wall_support::WallSupport;
use super::{ExtractError, ExtractParams};
use crate::grid::OccupancyGrid;
use crate::imaging::{
    Labels, Mask, distance_to_background, dominant_orientation, further_wall_directions,
};
use crate::model::{Nrg, SpaceId};

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
    let px = PixelConfig::new(params, grid.resolution);
    let clock = Clock {
        last: Instant::now(),
        timings: Vec::new(),
    };
    // The obstacles standing free, labelled once for the furniture filter,
    // the clutter the wall support rule knows and the doorway chords.
    let islands = islands(grid);
    // The doorway chords' pixel classes (see `chord_pixels::Pixel`) need
    // only the map and its obstacles: they are worked out on another core
    // while the free space is cleaned and segmented.
    std::thread::scope(|scope| {
        let outside =
            scope.spawn(|| outside_pixels(grid, &islands, px.chord_speck_max, px.obstacle_min));
        let outside = || {
            outside
                .join()
                .unwrap_or_else(|panic| std::panic::resume_unwind(panic))
        };
        stages(grid, params, &px, &islands, clock, outside)
    })
}

/// The stages of [`extract_at`] after the obstacles are labelled;
/// `outside` gives the doorway chords' pixel classes when the doors are
/// cut.
fn stages(
    grid: &OccupancyGrid,
    params: &ExtractParams,
    px: &PixelConfig,
    islands: &Islands,
    mut clock: Clock,
    outside: impl FnOnce() -> Vec<Pixel>,
) -> Result<Extraction, ExtractError> {
    let mut free = clean(grid, islands, params, px)?;
    // The building's two directions, from the free space without noise.
    let deg = dominant_orientation(&free.clean);
    // Those of wings built at other angles.
    let further = further_wall_directions(&free.clean, deg);
    let support = WallSupport::new(grid, islands, deg, &further, px.support);
    let mut gaps = match &px.gaps {
        Some(limits) => doorway_gaps(&free.clean, deg, &further, *limits, &support),
        None => Vec::new(),
    };
    let openings = openings(grid, &free, deg, &support, px, &gaps);
    gaps.extend(openings.iter().cloned());
    // A gap between pieces of clutter is no doorway in a wall.
    gaps.retain(|g| !support.lacks_gap(&g.line));
    clock.lap("clean");
    // The paper's doorway points (Tab. 2), taken before the gaps close.
    let skeleton = px
        .skeleton
        .map(|s| skeleton_doorways(&free.clean, s.erode, s.open, s.near));
    if skeleton.is_some() {
        clock.lap("skeleton");
    }
    close_gaps(&mut free.clean, &mut free.reachable, &gaps);
    let dist = distance_to_background(&free.clean);
    clock.lap("distance");
    let mut labels = segment(&free, &dist, px);
    clock.lap("segment");
    merge_small(&mut labels, px.min_room_area);
    reopen_gaps(&mut labels, &gaps);
    let mut regions = Regions::new(labels, dist);
    clock.lap("merge");
    regions.split_passages(px);
    clock.lap("passages");
    regions.join_open(&gaps, &support, px);
    clock.lap("joins");
    let cues = DoorCues {
        gaps: &gaps,
        skeleton: skeleton.as_deref(),
    };
    let chosen = choose_doors(&mut regions, &cues, px);
    let doors: Vec<&Border> = chosen.iter().map(|&k| &regions.borders[k]).collect();
    let door_pairs: Vec<(u32, u32)> = doors.iter().map(|b| b.pair).collect();
    let n_regions = regions.labels.count;
    let outside = outside();
    let (mut labels, mut door_lines) = span_doors(grid, &outside, &regions, &doors, px);
    // An opening's door is as wide as the opening, jamb to jamb.
    let crossed = GapIndex::new(&openings, grid.width);
    for (line, door) in door_lines.iter_mut().zip(&doors) {
        if let Some(o) = crossed.crossed(&door.pixels) {
            *line = o.ends(grid.width).or(*line);
        }
    }
    clock.lap("doors");
    // One simple polygon per space: before the graph, so that it and the
    // polygons see the same labels.
    tidy_labels(&mut labels);
    clock.lap("tidy");
    // A corridor by its shape: its widest part with the clutter standing
    // in it filled (see `filled`) and its length along the longest walk
    // inside it (see `geodesic`).
    let mut shape: Vec<SpaceShape> = labels
        .areas()
        .into_iter()
        .zip(filled_diameters(&labels, n_regions, px.clutter_max_width))
        .map(|(area, diameter)| SpaceShape {
            area,
            diameter,
            length: 0.0,
        })
        .collect();
    // Only a region long for its widest part can be a corridor: the
    // others' walks are not measured.
    let lengths = geodesic_lengths(&labels, n_regions, |l| {
        shape[l as usize].elongation() >= px.corridor.min_elongation
    });
    for (s, length) in shape.iter_mut().zip(lengths) {
        s.length = length;
    }
    let topo = topology(
        &labels,
        n_regions,
        &door_pairs,
        &shape,
        px.corridor,
        px.open_min,
    );
    clock.lap("graph");
    let (labels, nrg, pixel_centroids) = build(
        grid,
        labels,
        &regions.dist,
        &topo.kinds,
        &topo.edges,
        px.simplify_m,
        &DoorLines {
            first: n_regions + 1,
            lines: &door_lines,
        },
    )?;
    clock.lap("polygons");
    Ok(Extraction {
        nrg,
        labels,
        pixel_centroids,
        timings: clock.timings,
    })
}

/// Stage `clean`: the free space without noise, rays and furniture
/// islands; an error when nothing is left.
fn clean(
    grid: &OccupancyGrid,
    islands: &Islands,
    params: &ExtractParams,
    px: &PixelConfig,
) -> Result<FreeSpace, ExtractError> {
    let free = clean_free(
        grid,
        islands,
        px.noise_radius,
        px.min_free_area,
        &px.islands,
    );
    if free.clean.iter().all(|&p| p == 0) {
        return Err(ExtractError::NoSpace {
            noise_m: params.building.noise_radius_m,
            min_area_m2: params.internals.min_free_area_m2,
        });
    }
    Ok(free)
}

/// Doorway gaps (`wall_gaps`) along the building's dominant directions
/// `deg`, then along the further directions of wings built at other
/// angles (`imaging::further_wall_directions`) where they pass no gap
/// already found within the jamb length. In a building with such wings
/// every gap needs wall support along its own direction
/// (`WallSupport::backs_gap`): elsewhere the rule abstains on a line
/// along one pair of directions drawn in a wing of another (across a
/// slanted corridor, between the ends of its partitions).
fn doorway_gaps(
    free: &Mask,
    deg: f64,
    further: &[f64],
    limits: GapLimits,
    support: &WallSupport,
) -> Vec<WallGap> {
    let mut gaps = wall_gaps(free, deg, limits);
    if !further.is_empty() {
        gaps.retain(|g| support.backs_gap(&g.line));
    }
    for &further in further {
        let near = near_lines(gaps.iter(), free.width(), limits.jamb);
        let found = wall_gaps(free, further, limits);
        gaps.extend(
            found
                .into_iter()
                .filter(|g| !g.line.iter().any(|p| near.contains(p)) && support.backs_gap(&g.line)),
        );
    }
    gaps
}

/// Openings in walls wider than doorway gaps (see `opening_width_max_m`)
/// with wall support like the doorway gaps, and none across a passage
/// (`WallSupport::crosses_passage`); then the openings from wall stubs'
/// ends (`wall_stubs.rs`) with wall support that pass no opening or
/// doorway gap (in `doorways`) within `WallStubLimits::tolerance`, the
/// openings counting as wall: a stub's line may end on an opening, which
/// is then cut in two there (`stub_openings.rs`). The
/// openings are scanned on the free space with its corners (see
/// `FreeSpace::with_corners`): a rounded corner widens the gap by a pixel
/// a line, and the stack never sees the wall's face. One into a room
/// hardly wider than its front (`WallGap::narrow_faces`) must end on walls
/// the sensor saw at both ends, not on the unseen shadow of furniture.
fn openings(
    grid: &OccupancyGrid,
    free: &FreeSpace,
    deg: f64,
    support: &WallSupport,
    px: &PixelConfig,
    doorways: &[WallGap],
) -> Vec<WallGap> {
    let Some(limits) = &px.openings else {
        return Vec::new();
    };
    let mut found = wall_gaps(&free.with_corners(), deg, *limits);
    found.retain(|o| {
        !support.crosses_passage(&o.line, o.corner_ends)
            && !support.lacks_gap(&o.line)
            && (!o.narrow_faces || ends_on_seen_walls(grid, &o.line, px.seen_wall_reach))
    });
    if let Some(stub_limits) = &px.wall_stubs {
        let stubs = stub_openings(&free.clean, deg, stub_limits, &mut found, doorways, |s| {
            !support.lacks_gap(&s.line)
        });
        found.extend(stubs);
    }
    found
}

/// Stage `segment`: the free space cut into regions, by the watershed of
/// its distance transform or by the paper's CCL.
fn segment(free: &FreeSpace, dist: &[f32], px: &PixelConfig) -> Labels {
    match px.segmentation {
        Segmentation::Watershed {
            core,
            split_min_core,
        } => segment_basins(
            &free.clean,
            &free.reachable,
            dist,
            core,
            px.min_free_area,
            split_min_core,
        ),
        Segmentation::Ccl { erode, open } => {
            segment_ccl(&free.clean, &free.reachable, erode, open, px.min_free_area)
        }
    }
}

/// Stage `doors` (the spans): each door cut across its doorway, from one
/// face of the wall to the other, with its doorway line (pixels); then
/// the unknown pockets and specks inside spaces joined to them.
/// Doorway chords end at the map's walls; other pixels outside the
/// regions may be noise or specks they cross (`outside`, see
/// `chord_pixels::Pixel`).
fn span_doors(
    grid: &OccupancyGrid,
    outside: &[Pixel],
    regions: &Regions,
    doors: &[&Border],
    px: &PixelConfig,
) -> (Labels, Vec<Option<[[f64; 2]; 2]>>) {
    let (mut labels, door_lines) = cut_doors(
        &regions.labels,
        Some(outside),
        doors,
        &regions.dist,
        &px.span,
    );
    claim_enclosed_unknown(
        &mut labels,
        grid,
        px.unknown_pocket_max,
        px.wall_inside_max,
        regions.labels.count + 1,
    );
    fill_specks(&mut labels, px.speck_max);
    (labels, door_lines)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A `w` × `h` grid at `resolution` m/px, walled round, with the cells
    /// `wall(x, y)` says occupied inside.
    fn walled(
        w: usize,
        h: usize,
        resolution: f64,
        wall: impl Fn(usize, usize) -> bool,
    ) -> OccupancyGrid {
        let rows: Vec<String> = (0..h)
            .map(|y| {
                (0..w)
                    .map(|x| {
                        let outer = x == 0 || y == 0 || x == w - 1 || y == h - 1;
                        if outer || wall(x, y) { '#' } else { '.' }
                    })
                    .collect()
            })
            .collect();
        OccupancyGrid::from_ascii(&rows.join("\n"), resolution)
    }

    /// How many spaces of `x` are no doors, and the doors' widths (m).
    fn spaces_and_door_widths(x: &Extraction) -> (usize, Vec<f64>) {
        let doors: Vec<f64> = x
            .nrg
            .spaces()
            .iter()
            .filter_map(crate::model::doorway)
            .map(|d| d.width_m)
            .collect();
        (x.nrg.spaces().len() - doors.len(), doors)
    }

    #[test]
    fn a_doorway_through_a_wall_deeper_than_any_doorway_gap_is_one_door() {
        // At 0.05 m/px: two 5 x 6 m rooms either side of a wall 1.0 m
        // thick (x 100..120, deeper than `wall_thickness_max_m`), with a
        // 1.0 m doorway through it (y 50..70).
        let grid = walled(221, 121, 0.05, |x, y| {
            (100..120).contains(&x) && !(50..70).contains(&y)
        });
        let x = extract(&grid, &ExtractParams::default()).unwrap();
        let (spaces, doors) = spaces_and_door_widths(&x);
        assert_eq!((spaces, doors.len()), (2, 1), "{doors:?}");
        assert!((doors[0] - 1.0).abs() <= 0.1, "{doors:?}");
    }

    #[test]
    fn a_t_of_walls_cut_off_by_doorways_is_a_wall_not_clutter() {
        // At 0.05 m/px: a hall (y 1..100) over two rooms, behind a front
        // wall (y 100..103) standing in pieces between three 0.9 m
        // doorways: a 1.2 m piece from the west wall, a free 1.4 m bar, the
        // 1.3 m head of a free T whose stem (x 101..104) parts the rooms down
        // to a 0.8 m doorway (y 140..156) above a stub from the south wall,
        // and a 1.3 m piece from the east wall. No piece is 2.5 m long, and
        // the T is neither bar nor block: it is a wall only by lying on the
        // front's line, which stands in pieces.
        let grid = walled(160, 200, 0.05, |x, y| {
            let front = (100..103).contains(&y)
                && [(1, 25), (43, 71), (89, 115), (133, 159)]
                    .iter()
                    .any(|&(a, b)| (a..b).contains(&x));
            let stem = (101..104).contains(&x) && (103..140).contains(&y);
            let stub = (101..104).contains(&x) && y >= 156;
            front || stem || stub
        });
        let x = extract(&grid, &ExtractParams::default()).unwrap();
        let (spaces, mut doors) = spaces_and_door_widths(&x);
        doors.sort_by(f64::total_cmp);
        assert_eq!((spaces, doors.len()), (3, 4), "{doors:?}");
        for (w, want) in doors.iter().zip([0.8, 0.9, 0.9, 0.9]) {
            assert!((w - want).abs() <= 0.1, "{doors:?}");
        }
    }

    #[test]
    fn a_partition_short_of_the_wall_across_leaves_a_door_along_its_line() {
        // At 0.05 m/px: a 10 x 6 m hall (x 1..199, y 1..119) divided by a
        // 0.15 m partition (x 100..103) from the south wall to y = 70,
        // 3.45 m short of the north wall: two rooms and one opening
        // between them, drawn along the partition's line.
        let grid = walled(201, 121, 0.05, |x, y| (100..103).contains(&x) && y >= 70);
        let x = extract(&grid, &ExtractParams::default()).unwrap();
        let doors: Vec<_> = x
            .nrg
            .spaces()
            .iter()
            .filter_map(crate::model::doorway)
            .collect();
        assert_eq!(x.nrg.spaces().len() - doors.len(), 2, "{doors:?}");
        assert_eq!(doors.len(), 1, "{doors:?}");
        // From the partition's end to the north wall, along x = 5.1 m.
        assert!((doors[0].width_m - 3.45).abs() <= 0.1, "{doors:?}");
        for p in doors[0].line {
            assert!((p[0] - 5.08).abs() <= 0.1, "{doors:?}");
        }
        // Without openings the hall is one space.
        let mut params = ExtractParams::default();
        params.building.opening_width_max_m = 0.0;
        let one = extract(&grid, &params).unwrap();
        assert_eq!(one.nrg.spaces().len(), 1);
    }

    #[test]
    fn a_partition_behind_an_open_front_gives_each_room_its_opening() {
        // At 0.05 m/px: a 2 m corridor (y 1..40) along two rooms (y 43..160)
        // whose 0.15 m front wall (y 40..43) was seen only at its ends
        // (x < 80, x >= 150): a 3.5 m opening. The partition between the
        // rooms (x 114..117) runs from the south wall to y = 80, 1.85 m
        // short of the front. Each room opens onto the corridor through
        // its part of the front, cut where the partition's line meets it.
        let grid = walled(241, 161, 0.05, |x, y| {
            let front = (40..43).contains(&y) && !(80..150).contains(&x);
            let partition = (114..117).contains(&x) && y >= 80;
            front || partition
        });
        front_cut_by_the_partition(&grid, 0.1);
    }

    /// The building of `a_partition_behind_an_open_front_…` in `grid`:
    /// three spaces, and doors as wide as the two parts of the front (1.75 m
    /// each, the partition's middle to each jamb) and the partition's line
    /// (1.85 m), each within `tolerance` (m).
    fn front_cut_by_the_partition(grid: &OccupancyGrid, tolerance: f64) {
        let x = extract(grid, &ExtractParams::default()).unwrap();
        let (spaces, mut widths) = spaces_and_door_widths(&x);
        widths.sort_by(f64::total_cmp);
        assert_eq!(spaces, 3, "{widths:?}");
        assert_eq!(widths.len(), 3, "{widths:?}");
        for (w, truth) in widths.iter().zip([1.75, 1.75, 1.85]) {
            assert!((w - truth).abs() <= tolerance, "{widths:?}");
        }
    }

    #[test]
    fn a_partition_behind_an_open_front_in_a_turned_building() {
        // The building above turned by 20 degrees on a 0.05 m/px grid: the
        // scans run along its own walls, and the partition's line still
        // ends on the front and cuts it.
        let (s, c) = 20f64.to_radians().sin_cos();
        let grid = walled(300, 250, 0.05, |x, y| {
            let (dx, dy) = (x as f64 + 0.5 - 150.0, y as f64 + 0.5 - 125.0);
            let (u, v) = (dx * c + dy * s + 120.0, -dx * s + dy * c + 80.0);
            let inside = (3.0..237.0).contains(&u) && (3.0..157.0).contains(&v);
            let front = (40.0..43.0).contains(&v) && !(80.0..150.0).contains(&u);
            let partition = (114.0..117.0).contains(&u) && v >= 80.0;
            !inside || front || partition
        });
        front_cut_by_the_partition(&grid, 0.15);
    }

    #[test]
    fn a_doorway_in_a_wing_built_at_another_angle_is_found() {
        // At 0.1 m/px: a 10 x 16 m hall along the grid (x < 100) and,
        // beyond its east wall, a 12 x 5 m wing turned by 40 degrees: a
        // 1.6 m corridor and a 3.2 m room side by side, the partition
        // between them (0.2 m) open over 1.6 m in its middle. That doorway
        // is as wide as the corridor, so the distance transform shows no
        // constriction: only a doorway gap along the wing's walls
        // separates the room from the corridor.
        let (s, c) = 40f64.to_radians().sin_cos();
        let grid = walled(240, 160, 0.1, |x, y| {
            let (dx, dy) = (x as f64 + 0.5 - 170.0, y as f64 + 0.5 - 80.0);
            let (u, v) = (dx * c + dy * s, -dx * s + dy * c);
            let in_wing = u.abs() < 60.0 && v.abs() < 25.0;
            let partition = (-9.0..-7.0).contains(&v) && u.abs() >= 8.0;
            if x < 100 {
                x == 99
            } else {
                !in_wing || partition
            }
        });
        let (others, doors) =
            spaces_and_door_widths(&extract(&grid, &ExtractParams::default()).unwrap());
        assert_eq!(others, 3, "{doors:?}");
        assert_eq!(doors.len(), 1, "{doors:?}");
        assert!((doors[0] - 1.6).abs() <= 0.15, "{doors:?}");
    }

    #[test]
    fn a_room_open_to_the_corridor_gets_a_door_as_wide_as_its_opening() {
        // At 0.1 m/px: two 6 x 4 m rooms above a 3 m corridor. The left
        // room opens onto the corridor through a 3 m gap in its front wall
        // (x 15..45), wider than any doorway; the right one through a
        // 0.9 m doorway.
        let grid = walled(122, 74, 0.1, |x, y| {
            let divider = x == 60 && y < 40;
            let front = (40..42).contains(&y) && !(15..45).contains(&x) && !(85..94).contains(&x);
            divider || front
        });
        let spaces =
            |params: &ExtractParams| spaces_and_door_widths(&extract(&grid, params).unwrap());
        let (others, mut widths) = spaces(&ExtractParams::default());
        widths.sort_by(f64::total_cmp);
        assert_eq!(others, 3, "{widths:?}");
        assert_eq!(widths.len(), 2, "{widths:?}");
        assert!((widths[0] - 0.9).abs() <= 0.1, "{widths:?}");
        assert!((widths[1] - 3.0).abs() <= 0.1, "{widths:?}");
        // Without openings the room and the corridor are one space.
        let mut params = ExtractParams::default();
        params.building.opening_width_max_m = 0.0;
        let (others, widths) = spaces(&params);
        assert_eq!((others, widths.len()), (2, 1), "{widths:?}");
    }

    /// At 0.1 m/px: a 12 x 5 m living area above a 0.3 m front wall (rows
    /// 50..53) with a 2.5 m opening (x 30..55) into a room 3 m wide (x
    /// 28..58) and 4.5 m deep: the floor beyond the front goes on only
    /// 0.2 and 0.3 m past the opening's ends, less than a jamb. Elsewhere
    /// below the front is `beside` (`#` a wall seen, `?` never seen); the
    /// front's rows are `front`, top to bottom.
    fn room_behind_a_wide_front(front: [char; 3], beside: char) -> OccupancyGrid {
        let (w, h) = (122, 100);
        let rows: Vec<String> = (0..h)
            .map(|y| {
                (0..w)
                    .map(|x| match (x, y) {
                        _ if x == 0 || y == 0 || x == w - 1 || y == h - 1 => '#',
                        (_, 1..50) => '.',
                        (30..55, 50..53) => '.',
                        (_, 50..53) => front[y - 50],
                        (28..58, _) => '.',
                        _ => beside,
                    })
                    .collect()
            })
            .collect();
        OccupancyGrid::from_ascii(&rows.join("\n"), 0.1)
    }

    /// The widths (m) of the doors `extract` finds in `grid`, with how
    /// many spaces are no doors.
    fn front_doors(grid: &OccupancyGrid) -> (usize, Vec<f64>) {
        spaces_and_door_widths(&extract(grid, &ExtractParams::default()).unwrap())
    }

    #[test]
    fn an_opening_into_a_room_hardly_wider_than_its_front_is_a_door_between_walls_seen() {
        // Seen throughout; then with the front's two faces seen and its
        // core not, as in a log-odds map: the sensor saw the walls the
        // opening ends on all the same.
        for front in [['#'; 3], ['#', '?', '#']] {
            let (others, widths) = front_doors(&room_behind_a_wide_front(front, '#'));
            assert_eq!(others, 2, "{front:?}: {widths:?}");
            assert_eq!(widths.len(), 1, "{front:?}: {widths:?}");
            assert!((widths[0] - 2.5).abs() <= 0.1, "{front:?}: {widths:?}");
        }
        // The front never seen by the sensor, or from the living area
        // only: the line would end on unknown space, as on the shadow
        // behind furniture.
        for front in [['?'; 3], ['#', '?', '?']] {
            let (_, widths) = front_doors(&room_behind_a_wide_front(front, '?'));
            assert!(
                widths.iter().all(|w| (w - 2.5).abs() > 0.3),
                "{front:?}: {widths:?}"
            );
        }
    }

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
        // The 0.8 m gap in a straight wall is a doorway gap; the 2.5 m
        // opening, beside the rooms' corner with a 0.5 m piece of the wall
        // above it, an opening (a door of its own). Without gap detection
        // the gap is a narrow border stretch like a nook between furniture
        // and a wall.
        let with_gaps = extract(&grid, &ExtractParams::default()).unwrap();
        let (_, mut widths) = spaces_and_door_widths(&with_gaps);
        widths.sort_by(f64::total_cmp);
        assert_eq!(widths.len(), 2, "{widths:?}");
        assert!((widths[0] - 0.8).abs() <= 0.1, "{widths:?}");
        assert!((widths[1] - 2.5).abs() <= 0.1, "{widths:?}");
        let mut params = ExtractParams::default();
        params.building.wall_jamb_m = 0.0;
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
        let mut off = ExtractParams::default();
        off.building.passage_min_length_m = 0.0;
        assert_eq!(kinds(&extract(&grid, &off).unwrap()), ["room"]);
    }
}
