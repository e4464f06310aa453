//! [`PixelConfig`]: the parameters of one extraction in the pixels of the
//! grid it runs on, converted once, with the method's fixed constants
//! (kept in metres here, so no stage holds a length in pixels that would
//! mean something else at another resolution).

use super::clutter::LineLimits;
use super::doorway::SpanLimits;
use super::furniture::IslandLimits;
use super::graph::CorridorShape;
use super::joins::JoinLimits;
use super::params::{DoorRule, ExtractParams, Method};
use super::passages::PassageLimits;
use super::stubs::StubLimits;
use super::wall_gaps::{GapKind, GapLimits};
use super::wall_stubs::WallStubLimits;
use super::wall_support::SupportLimits;

/// A border is a door under `DoorRule::Skeleton` if it passes this close
/// (m) to a doorway point: the watershed border and the skeletons'
/// crossing need not share a pixel. 2 px on the 0.05 m/px maps the rule
/// was measured on.
const SKELETON_NEAR_M: f64 = 0.1;

/// The wall lines of the clutter rule (`clutter.rs`) and of doorway gaps'
/// jambs (`wall_support.rs`): the shortest straight run of wall face that
/// makes one, the longest break bridged in it (a ragged scan, at least a
/// pixel) and how far from it an island's outline may lie and be on it.
const WALL_LINE_MIN_M: f64 = 2.5;
const WALL_LINE_GAP_M: f64 = 0.1;
const WALL_LINE_TOLERANCE_M: f64 = 0.1;
/// A wall line may also stand in pieces of at least this much wall (m),
/// each at most `wall_gap_width_max_m` (a doorway gap) from the next,
/// adding up to `WALL_LINE_MIN_M`: a room front whose wall stands free
/// between doorways. Simulated house 20's T of walls, cut off by a doorway
/// on each side, lies on such a line and is no clutter (four doorways
/// found); no shared map changes. Pieces of 0.3–0.5 m (scan specks and
/// desks in a row) cost freiburg_building101 two false doors and umic one to
/// three (benches/README.md, "A wall line in pieces").
const WALL_LINE_PIECE_MIN_M: f64 = 0.75;

/// The wall support rule (`wall_support.rs`), in metres: a run of wall
/// face this long supports a doorway by itself; in-line runs this long at
/// both ends support it as a pair; runs may lie this far across the
/// doorway's line from an end and end this far along it; a long run this
/// near a doorway's middle shows that the walls there follow the dominant
/// directions. Measured on the 19 development buildings (benches/README.md,
/// "Wall support"): no IPA map changes; door precision rises on three of
/// the six ROSE² maps and falls on none. A pair run of 0.8 m loses most of
/// that gain; 1.2 m loses office_e_furnitures a door (its 0.95 m wall
/// stubs between diagonal walls).
const SUPPORT_RUN_M: f64 = 1.5;
const SUPPORT_PAIR_RUN_M: f64 = 1.0;
const SUPPORT_TOLERANCE_M: f64 = 0.5;
const SUPPORT_REACH_M: f64 = 0.6;
const SUPPORT_NEAR_M: f64 = 2.0;
/// How far apart across (m) the walls past an opening's end on its two
/// faces may lie and be one passage's side wall (`wall_support.rs`,
/// `crosses_passage`): a pixel at 0.05 m/px, besides the pixel each side a
/// run's own line takes in (`wall_runs.rs`). Measured on the 19
/// development buildings and 400 simulated ones (benches/README.md, "A
/// passage's side is one wall line"): 0 and 1 px measure the same on the
/// shared maps; at 2 px rose2_intel_map loses the doorway it gains, and
/// with no limit (before) NLB's 3.4 m room front is taken for a passage
/// too.
const PASSAGE_SIDE_LINE_M: f64 = 0.05;

/// Clutter is no jamb (`wall_support.rs`, `furniture::clutter_pixels`): a
/// door-wide border with an end on an obstacle island at most this wide
/// (m) that is less than [`WALL_PIECE_ELONGATION`] times as long as thick,
/// and on nothing else within [`BORDER_END_REACH_M`], joins its regions;
/// a doorway gap so ending is dropped unless the island lies on the
/// building's wall lines (`wall_support::JAMB_ON_LINE_MIN_FRACTION`).
/// It is ROSE²'s idea that rooms are bounded by the building's walls.
/// Measured on the 19 development buildings (benches/README.md, "Clutter
/// is no jamb"): no IPA map changes at 1.5 or 2 m; at 3 m office_e loses
/// doors whose jambs are its round wall's pieces. Without the elongation
/// test, lab_intel loses the doorways on either side of a free-standing
/// diagonal wall piece. Ends looked at within 0.1 m lose umic a doorway
/// whose jamb's speckled halo makes it look like a blob; 0.15 and 0.2 m
/// measure the same.
const CLUTTER_JAMB_MAX_M: f64 = 2.0;
const WALL_PIECE_ELONGATION: f64 = 3.0;
const BORDER_END_REACH_M: f64 = 0.15;

/// An opening's stack of gaps (`wall_gaps::GapKind::Opening`) ends where
/// the next line's gap steps out by at least this much (m) on a side: the
/// face of the wall, with an alcove or a narrow room behind it; and where
/// it steps in as much, from such a room into the wall (benches/README.md,
/// "Openings into rooms hardly wider than their fronts"). Measured
/// on the 19 development buildings and 400 simulated ones
/// (benches/README.md, "Openings: furniture is no passage's side"): only
/// houses change (door R +0.5); 0.15 m changes fr079 by a few hundredths;
/// a step counted from the stack's narrowest gap instead of the line
/// before loses intel_map's sloping 3.25 m opening; doorway stacks stopped
/// the same way lose doors on office_d, office_e and three ROSE² maps and
/// give NLB a false one.
const OPENING_FACE_STEP_M: f64 = 0.2;

/// How far (m) past each end of an opening into a room hardly wider than
/// its front (`wall_gaps::WallGap::narrow_faces`) a wall the sensor saw is
/// looked for along its line: its last free pixel may lie a pixel short
/// of the wall's face, and the face be ragged by one more (3 px on the
/// 0.05 m/px maps the rule was measured on, benches/README.md "Openings
/// into rooms hardly wider than their fronts").
const SEEN_WALL_REACH_M: f64 = 0.15;

/// A corridor is at least this many times as long as it is wide on
/// average (`graph::SpaceShape::length_ratio`: the length of the longest
/// walk inside it, squared, over its area), as well as long for its
/// widest part (`corridor_min_elongation`). A rectangle passes from about
/// 3.7 : 1. Measured on 400 simulated buildings (benches/README.md, "A
/// corridor is long along its walk"): rooms labelled corridor 42 → 8,
/// corridors labelled room 7 before and after; 3 leaves 12, 3.5 leaves 10,
/// 5 leaves 7. On the development maps the spaces it turns into rooms are
/// L-shaped and furnished rooms (office_g's corner room, aws_small_house's
/// bedroom, ROSE² room groups), and, wrongly, three short corridor pieces
/// (lab_d's two, 5 × 2.5 m, and fr079's, 7 × 1.9 m).
const CORRIDOR_MIN_LENGTH_RATIO: f64 = 4.0;

/// Wall-stub openings (`wall_stubs.rs`), with the openings' limits: a stub
/// is at most this thick (m), thin with free space beside it over this
/// share of its first metre (the openings' jamb, [`SUPPORT_PAIR_RUN_M`])
/// and thin all along its first `wall_jamb_m`; a piece of wall across at
/// least this long (m) within this reach (m) of its end makes a front.
/// Measured on the 19 development buildings and 150 simulated ones
/// (benches/README.md, "Wall-stub openings"): NLB gains two doorways and
/// umic one, no map or simulated building gains a false door. With a
/// front reach of 1 m lab_a_scan and lab_intel gain false doors across
/// the corridor in front of their bays; at 2.5 m NLB's two are lost.
const STUB_THICK_MAX_M: f64 = 0.4;
const STUB_THIN_SHARE: f64 = 0.7;
const STUB_FRONT_RUN_M: f64 = 0.5;
const STUB_FRONT_REACH_M: f64 = 1.5;

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

/// The longest stretch (m) of uncertain grey a doorway chord crosses when
/// free space follows it: specks inside a doorway on a compressed or
/// scanned map are no jamb, but a doorway closed by unknown cells stays
/// closed (uncertain grey touching a wall is the wall's). It was two
/// pixels (0.1 m at 0.05 m/px); 0.2 m brings umic's width error p90 from
/// 0.256 m to 0.176 m and intel_map's from 0.244 m to 0.082 m, and changes
/// no other shared map's doors (benches/README.md, "Doorway chords across
/// specks"); 0.3 and 0.4 m measure the same.
const NOISE_RUN_MAX_M: f64 = 0.2;

/// How much longer than the widest doorway (`wall_gap_width_max_m` or
/// `door_width_max_m`) a doorway's chord may be: a chord across a
/// doorway is measured a little slanted, from one ragged jamb to the other.
const SPAN_WIDTH_SLACK: f64 = 1.15;

/// A border is judged by how wide its two regions are near it: within
/// this many widest doors (`door_width_max_m`) of it (see
/// `regions::measure_near`). On the 19 development buildings 2.5 and 3
/// give the same result (door precision up on NLB, intel_carmen and umic,
/// nothing lower anywhere); 4 is as good as not looking near; 2 and 1.5
/// cut more corridors' false doors on the ROSE² maps but lose lab_ipa a
/// door whose room is widest farther off.
const NEAR_REACH_DOORS: f64 = 2.5;

/// The disk that finds the passage a door border lies in (see `passages`)
/// is this much wider than the border, times...
const PASSAGE_DISK_SLACK: f64 = 1.15;

/// ...plus this many pixels on its radius. In pixels on purpose: it keeps
/// the rasterised disk out of a passage exactly its width, whatever the
/// resolution; it is no length in the building. As 0.05 m (a pixel where it
/// was measured) it lowered rooms R/P a little on the three shared maps not
/// at 0.05 m/px (rose2_freiburg_building101 at 0.078: 78.99 -> 78.97,
/// building79 at 0.038: 95.19 -> 95.17 P, umic at 0.044: 93.51 -> 93.43 P)
/// and raised nothing.
const PASSAGE_DISK_MARGIN_PX: f64 = 1.0;

/// Unlabelled specks smaller than this (m²) inside one space join it.
const SPECK_MAX_M2: f64 = 0.25;

/// Obstacle pieces standing free and at most this long (m) on both sides
/// are specks a doorway chord runs through (see `chord_pixels::outside_pixels`).
/// Measured on the shared maps (2026-12-05): only umic's door widths move
/// (error median 0.131 -> 0.106 m, p90 0.336 -> 0.256 m, with the free
/// cells the noise filter took passed too); no door is found or lost.
const CHORD_SPECK_MAX_M: f64 = 0.2;

/// Occupied pieces inside the spaces (obstacles the furniture filter let
/// them take in) narrow a doorway line to its clear part (see
/// `clear_width`) when they hold at least this much occupied area (m²):
/// a 10 cm square. A dot of one or two occupied cells in a grey halo is
/// scan noise. Measured on the shared maps (2026-12-06): see
/// `benches/README.md`, "A doorway's width is its clear part"; every
/// floor from 0.004 to 0.02 m² measures the same, 0.03 loses one of
/// building79's two fixed doors, and none (every occupied cell) narrows
/// umic's 1.89 m doorway to 1.14 m on a two-cell dot.
const OBSTACLE_MIN_M2: f64 = 0.01;

/// Unknown pockets no thicker than this (m) bordered mostly by obstacles
/// are the insides of walls, not of furniture: they stay out of spaces.
const WALL_INSIDE_MAX_M: f64 = 0.3;

/// The widest (m) a hole in a space may be and still be clutter standing
/// in it when the space's width is taken (see `filled`): a wider hole is a
/// block of rooms the sensor did not enter, which a corridor runs round
/// (the CARMEN ACES log: blocks 10 m and more across). Clutter is at most
/// about 3 m (two desks back to back with chairs); 3 to 5 m also made
/// office_a_furnitures' room round a lift core a corridor (its plain copy
/// has it a room), 8 m does not. Any value from 2 to 8 m gives the same
/// kinds on every other shared map and simulated building.
const CLUTTER_MAX_WIDTH_M: f64 = 8.0;

/// How regions are first found, in pixels.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Segmentation {
    /// Distance markers and a watershed.
    Watershed {
        /// `core_radius_m`.
        core: f64,
        /// `split_min_core_m2`, px².
        split_min_core: usize,
    },
    /// The paper's Experiment I.
    Ccl {
        /// `ccl_erode_m`.
        erode: f64,
        /// `ccl_open_m`.
        open: f64,
    },
}

/// The paper's skeleton door rule (`door_rule = "skeleton"`), in pixels.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SkeletonLimits {
    /// `skeleton_erode_m`.
    pub erode: f64,
    /// `skeleton_open_m`.
    pub open: f64,
    /// How near a doorway point a door's border passes.
    pub near: f64,
}

/// Every length of one extraction in pixels (areas in pixels²), for a grid
/// of `resolution` m/px.
#[derive(Debug, Clone)]
pub(crate) struct PixelConfig {
    /// `noise_radius_m`: the noise opening's radius.
    pub noise_radius: f64,
    /// `min_free_area_m2`: smaller free components are dropped.
    pub min_free_area: usize,
    /// `furniture_max_m` and `clutter_max_m`: the islands treated as free.
    pub islands: IslandLimits,
    /// Doorway gaps in walls; none with the CCL method or `wall_jamb_m` 0.
    pub gaps: Option<GapLimits>,
    /// `wall_thickness_max_m`: two doors between the same two spaces
    /// closer than this are the two faces of one deep doorway.
    pub wall_thickness_max: f64,
    /// Openings in walls wider than doorway gaps (`opening_width_max_m`):
    /// jambs a metre of wall in line (the wall support's pair run) or a
    /// wall across, floor for `wall_jamb_m` beyond both faces; none with
    /// the CCL method, `wall_jamb_m` 0, or no width above the gaps'.
    pub openings: Option<GapLimits>,
    /// How far past an opening's ends a wall the sensor saw is looked for
    /// (`SEEN_WALL_REACH_M`), in pixels rounded up.
    pub seen_wall_reach: i64,
    /// Openings from a wall stub's end to the wall it points at; with the
    /// openings only.
    pub wall_stubs: Option<WallStubLimits>,
    /// The skeleton door rule, when chosen (watershed only).
    pub skeleton: Option<SkeletonLimits>,
    /// How regions are found.
    pub segmentation: Segmentation,
    /// `min_room_area_m2`: smaller regions merge into a neighbour.
    pub min_room_area: usize,
    /// Narrow passages split off as spaces; none when
    /// `passage_min_length_m` is 0.
    pub passages: Option<StubLimits>,
    /// `door_join_m`: border stretches this close are one border.
    pub border_join: i64,
    /// Door widths, the constriction and the open-join fraction.
    pub doors: JoinLimits,
    /// Which door-wide constrictions the building's walls support.
    pub support: SupportLimits,
    /// How far from a border its regions' widths are measured.
    pub near_reach: f64,
    /// How far a door found mid-passage may move to the passage's mouth
    /// (twice the widest door), and the disk that finds the passage.
    pub passage: PassageLimits,
    /// A door's span across its doorway.
    pub span: SpanLimits,
    /// `unknown_pocket_max_m2`: unknown pockets this small join their space.
    pub unknown_pocket_max: usize,
    /// Unknown pockets this thin and walled are the insides of walls.
    pub wall_inside_max: usize,
    /// Unlabelled specks this small join their space.
    pub speck_max: usize,
    /// Obstacle pieces this small (px across) are no jambs to a chord.
    pub chord_speck_max: f64,
    /// Occupied pieces with fewer cells than this do not narrow a doorway.
    pub obstacle_min: usize,
    /// What makes a space a corridor: `corridor_min_elongation` and
    /// [`CORRIDOR_MIN_LENGTH_RATIO`].
    pub corridor: CorridorShape,
    /// The widest hole in a space that is clutter standing in it.
    pub clutter_max_width: f64,
    /// Regions meeting wider than this are openly connected
    /// (`door_width_max_m`).
    pub open_min: usize,
    /// `simplify_m`, in metres: the polygons are simplified in the map's frame.
    pub simplify_m: f64,
}

impl PixelConfig {
    /// `params` for a grid of `resolution` m/px.
    pub(crate) fn new(params: &ExtractParams, resolution: f64) -> PixelConfig {
        let (b, o, i) = (&params.building, &params.output, &params.internals);
        let px = |m: f64| m / resolution;
        let area = |m2: f64| (m2 / (resolution * resolution)).ceil() as usize;
        let whole = |m: f64| px(m).round() as usize;
        let watershed = params.method == Method::Watershed;
        let wall_lines = LineLimits {
            min_run: px(WALL_LINE_MIN_M),
            gap: px(WALL_LINE_GAP_M).round().max(1.0) as i64,
            tolerance: px(WALL_LINE_TOLERANCE_M).round() as i64,
            piece_min: px(WALL_LINE_PIECE_MIN_M),
            piece_gap: px(b.wall_gap_width_max_m),
        };
        PixelConfig {
            noise_radius: px(b.noise_radius_m),
            min_free_area: area(i.min_free_area_m2),
            islands: IslandLimits {
                furniture: px(b.furniture_max_m),
                clutter: px(b.clutter_max_m),
                wall_piece_gap: px(b.wall_gap_width_max_m),
                wall_elongation: WALL_PIECE_ELONGATION,
                lines: wall_lines,
            },
            wall_thickness_max: px(b.wall_thickness_max_m),
            gaps: (watershed && b.wall_jamb_m > 0.0).then(|| GapLimits {
                width: (whole(b.door_width_min_m), whole(b.wall_gap_width_max_m)),
                jamb: whole(b.wall_jamb_m).max(1),
                depth: whole(b.wall_thickness_max_m).max(1),
                kind: GapKind::Doorway,
            }),
            openings: (watershed
                && b.wall_jamb_m > 0.0
                && b.opening_width_max_m > b.wall_gap_width_max_m)
                .then(|| GapLimits {
                    width: (
                        whole(b.wall_gap_width_max_m) + 1,
                        whole(b.opening_width_max_m),
                    ),
                    jamb: whole(SUPPORT_PAIR_RUN_M).max(1),
                    depth: whole(b.wall_thickness_max_m).max(1),
                    kind: GapKind::Opening {
                        face: whole(b.wall_jamb_m).max(1),
                        step: whole(OPENING_FACE_STEP_M).max(1),
                        near_margin: whole(b.wall_jamb_m).max(1),
                    },
                }),
            seen_wall_reach: (px(SEEN_WALL_REACH_M).ceil() as i64).max(1),
            wall_stubs: (watershed
                && b.wall_jamb_m > 0.0
                && b.opening_width_max_m > b.wall_gap_width_max_m)
                .then(|| WallStubLimits {
                    width: (
                        whole(b.door_width_min_m).max(1),
                        whole(b.opening_width_max_m),
                    ),
                    thick: whole(STUB_THICK_MAX_M).max(1),
                    length: whole(SUPPORT_PAIR_RUN_M).max(1),
                    thin_share: STUB_THIN_SHARE,
                    head: whole(b.wall_jamb_m).max(1),
                    face: whole(b.wall_jamb_m).max(1),
                    front_run: whole(STUB_FRONT_RUN_M).max(1),
                    front_reach: whole(STUB_FRONT_REACH_M).max(1),
                    tolerance: whole(WALL_LINE_TOLERANCE_M).max(1),
                }),
            skeleton: (watershed && params.door_rule == DoorRule::Skeleton).then(|| {
                SkeletonLimits {
                    erode: px(i.skeleton_erode_m),
                    open: px(i.skeleton_open_m),
                    near: px(SKELETON_NEAR_M),
                }
            }),
            segmentation: if watershed {
                Segmentation::Watershed {
                    core: px(i.core_radius_m),
                    split_min_core: area(i.split_min_core_m2),
                }
            } else {
                Segmentation::Ccl {
                    erode: px(i.ccl_erode_m),
                    open: px(i.ccl_open_m),
                }
            },
            min_room_area: area(b.min_room_area_m2),
            passages: (b.passage_min_length_m > 0.0).then(|| StubLimits {
                radius_px: (px(b.door_width_max_m) / 2.0) as f32,
                width_min_px: px(b.door_width_min_m) as f32,
                length_min_px: px(b.passage_min_length_m) as f32,
                constriction: i.door_constriction,
            }),
            border_join: px(i.door_join_m).round() as i64,
            doors: JoinLimits {
                door_min_px: px(b.door_width_min_m),
                door_max_px: px(b.door_width_max_m),
                constriction: i.door_constriction,
                fraction: i.open_join_fraction,
            },
            support: SupportLimits {
                long_run: px(SUPPORT_RUN_M),
                pair_run: px(SUPPORT_PAIR_RUN_M),
                tie_run: px(b.wall_jamb_m),
                gap: px(WALL_LINE_GAP_M).round().max(1.0) as i64,
                tolerance: px(SUPPORT_TOLERANCE_M).round() as i64,
                reach: px(SUPPORT_REACH_M),
                side_line: px(PASSAGE_SIDE_LINE_M).round() as i64,
                near: px(SUPPORT_NEAR_M),
                clutter_max: px(CLUTTER_JAMB_MAX_M),
                wall_elongation: WALL_PIECE_ELONGATION,
                end_reach: px(BORDER_END_REACH_M).round().max(1.0) as i64,
                lines: wall_lines,
            },
            near_reach: NEAR_REACH_DOORS * px(b.door_width_max_m),
            passage: PassageLimits {
                window: (2.0 * px(b.door_width_max_m)).ceil() as usize,
                disk_slack: PASSAGE_DISK_SLACK,
                disk_margin: PASSAGE_DISK_MARGIN_PX,
            },
            span: SpanLimits {
                max_width: SPAN_WIDTH_SLACK * b.door_width_max_m.max(b.wall_gap_width_max_m)
                    / resolution,
                search: px(SPAN_SEARCH_M).max(2.0),
                min_depth: px(o.door_depth_m).max(1.0),
                max_depth: px(b.wall_thickness_max_m.min(SPAN_MAX_DEPTH_M)).max(1.0),
                slack: px(SPAN_SLACK_M).max(1.5),
                noise_run: px(NOISE_RUN_MAX_M),
            },
            unknown_pocket_max: (b.unknown_pocket_max_m2 / (resolution * resolution)).floor()
                as usize,
            wall_inside_max: px(WALL_INSIDE_MAX_M).ceil() as usize,
            speck_max: (SPECK_MAX_M2 / (resolution * resolution)).floor() as usize,
            chord_speck_max: px(CHORD_SPECK_MAX_M),
            obstacle_min: (OBSTACLE_MIN_M2 / (resolution * resolution)).ceil() as usize,
            corridor: CorridorShape {
                min_elongation: i.corridor_min_elongation,
                // 0 keeps the paper's pure degree rule (see the field).
                min_length_ratio: if i.corridor_min_elongation > 0.0 {
                    CORRIDOR_MIN_LENGTH_RATIO
                } else {
                    0.0
                },
            },
            clutter_max_width: px(CLUTTER_MAX_WIDTH_M),
            open_min: px(b.door_width_max_m).ceil() as usize,
            simplify_m: o.simplify_m,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_set_of_metres_gives_pixels_in_proportion_to_the_resolution() {
        let p = ExtractParams::default();
        let (fine, coarse) = (PixelConfig::new(&p, 0.05), PixelConfig::new(&p, 0.1));
        assert_eq!(fine.doors.door_max_px, 36.0);
        assert_eq!(coarse.doors.door_max_px, 18.0);
        assert_eq!((fine.min_room_area, coarse.min_room_area), (400, 100));
        assert_eq!((fine.seen_wall_reach, coarse.seen_wall_reach), (3, 2));
        assert_eq!(fine.passage.window, 72);
        let gaps = fine.gaps.unwrap();
        assert_eq!((gaps.width, gaps.jamb, gaps.depth), ((6, 42), 6, 18));
        assert_eq!(
            (fine.wall_thickness_max, coarse.wall_thickness_max),
            (18.0, 9.0)
        );
        assert!((fine.span.max_width - 1.15 * 42.0).abs() < 1e-9);
        assert_eq!(fine.skeleton.map(|s| s.near), None, "constriction rule");
        let skeleton = ExtractParams {
            door_rule: DoorRule::Skeleton,
            ..ExtractParams::default()
        };
        let near = |res| PixelConfig::new(&skeleton, res).skeleton.unwrap().near;
        assert!((near(0.05) - 2.0).abs() < 1e-9 && (near(0.1) - 1.0).abs() < 1e-9);
        // The CCL method finds no wall gaps; 0 turns the passages off.
        let mut ccl = ExtractParams {
            method: Method::Ccl,
            ..ExtractParams::default()
        };
        ccl.building.passage_min_length_m = 0.0;
        let c = PixelConfig::new(&ccl, 0.05);
        assert!(c.gaps.is_none() && c.passages.is_none());
        assert!(matches!(c.segmentation, Segmentation::Ccl { open, .. } if open == 10.0));
    }

    #[test]
    fn no_least_elongation_is_the_papers_pure_degree_rule() {
        let p = ExtractParams::default();
        let corridor = PixelConfig::new(&p, 0.05).corridor;
        assert_eq!(
            (corridor.min_elongation, corridor.min_length_ratio),
            (2.5, 4.0)
        );
        let mut degree_only = ExtractParams::default();
        degree_only.internals.corridor_min_elongation = 0.0;
        let corridor = PixelConfig::new(&degree_only, 0.05).corridor;
        assert_eq!(
            (corridor.min_elongation, corridor.min_length_ratio),
            (0.0, 0.0)
        );
    }
}
