//! Which borders between regions are doors: those crossing a doorway gap
//! in a wall, or door-wide constrictions of the regions they join (or,
//! under the paper's skeleton rule, those touching a doorway point); a
//! door found inside a narrow passage moves to the passage's mouth.

use std::collections::HashSet;

use super::doors::Border;
use super::joins::JoinLimits;
use super::passages::give_passages_to_narrow_side;
use super::pixel_config::PixelConfig;
use super::regions::Regions;
use super::stubs::compared_width;
use super::wall_gaps::{GapIndex, WallGap};

/// What marks a doorway besides the borders' widths.
pub(crate) struct DoorCues<'a> {
    /// Doorway gaps in walls.
    pub gaps: &'a [WallGap],
    /// With `DoorRule::Skeleton`: per pixel, near a doorway point of the
    /// paper's Tab. 2; a border is a door iff it touches one.
    pub skeleton: Option<&'a [bool]>,
}

/// Stage `doors` (the choice): the indices of `regions.borders` that are
/// doors. Doors found mid-passage move to the passage's mouth (the
/// regions' pixels move); the borders are then measured and chosen again.
pub(crate) fn choose_doors(regions: &mut Regions, cues: &DoorCues, px: &PixelConfig) -> Vec<usize> {
    let first = select_doors(
        &regions.borders,
        &regions.widest,
        &regions.is_passage,
        cues,
        &px.doors,
        regions.labels.width,
    );
    let deep = px.wall_thickness_max;
    let width = regions.labels.width;
    let first = one_door_per_doorway(&regions.borders, first, deep, width);
    let first_doors: Vec<&Border> = first.iter().map(|&k| &regions.borders[k]).collect();
    let moved = give_passages_to_narrow_side(
        &mut regions.labels,
        &regions.dist,
        &first_doors,
        &regions.widest,
        &px.passage,
    );
    if !moved {
        return first;
    }
    regions.remeasure(px);
    let again = select_doors(
        &regions.borders,
        &regions.widest,
        &regions.is_passage,
        cues,
        &px.doors,
        width,
    );
    one_door_per_doorway(&regions.borders, again, deep, width)
}

/// `chosen` (indices into `all`) without the doors that are a second face
/// of a doorway: of two chosen borders between the same two regions whose
/// pixels' centres lie within `deep` pixels (`wall_thickness_max_m`) of
/// each other, the shorter goes (of two as long, the later). The
/// watershed draws a border at each face of a doorway through a wall
/// deeper than the doorway gap scan takes (`GapLimits::depth`), and both
/// are door-wide constrictions of the same two spaces: one doorway, one
/// door. `width` is the labels' width.
fn one_door_per_doorway(all: &[Border], chosen: Vec<usize>, deep: f64, width: u32) -> Vec<usize> {
    let centre = |b: &Border| {
        let n = b.pixels.len().max(1) as f64;
        b.pixels.iter().fold([0.0, 0.0], |c, &p| {
            [
                c[0] + f64::from(p % width.max(1)) / n,
                c[1] + f64::from(p / width.max(1)) / n,
            ]
        })
    };
    let centres: Vec<[f64; 2]> = chosen.iter().map(|&k| centre(&all[k])).collect();
    // Whether door `i` of `chosen` gives way to door `j`.
    let yields = |i: usize, j: usize| {
        let (a, b) = (&all[chosen[i]], &all[chosen[j]]);
        let (ca, cb) = (centres[i], centres[j]);
        i != j
            && a.pair == b.pair
            && (ca[0] - cb[0]).hypot(ca[1] - cb[1]) <= deep
            && (b.pixels.len(), std::cmp::Reverse(chosen[j]))
                > (a.pixels.len(), std::cmp::Reverse(chosen[i]))
    };
    (0..chosen.len())
        .filter(|&i| !(0..chosen.len()).any(|j| yields(i, j)))
        .map(|i| chosen[i])
        .collect()
}

/// The indices of the borders of `all` that are doors. With the skeleton
/// cue (`DoorRule::Skeleton`), those touching a doorway point. Otherwise
/// those along a doorway gap's line, and those between the least and the
/// greatest door width that are a constriction of the narrower region
/// (`widest`: each region's widest inscribed diameter, px; see
/// `compared_width` for passages) and whose regions do not also meet wider
/// than any door.
fn select_doors(
    all: &[Border],
    widest: &[f64],
    is_passage: &[bool],
    cues: &DoorCues,
    limits: &JoinLimits,
    width: u32,
) -> Vec<usize> {
    if let Some(skeleton) = cues.skeleton {
        return (0..all.len())
            .filter(|&k| all[k].pixels.iter().any(|&p| skeleton[p as usize]))
            .collect();
    }
    let (door_min_px, door_px) = (limits.door_min_px, limits.door_max_px);
    let constriction = |b: &Border| limits.constriction * compared_width(b, widest, is_passage);
    let gaps = GapIndex::new(cues.gaps, width);
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
            gaps.crossed(&b.pixels).is_some()
                || (b.width_px >= door_min_px
                    && b.width_px <= door_px
                    && b.pixels.len() as f64 >= door_min_px
                    && b.width_px <= constriction(b)
                    && !open_pairs.contains(&b.pair))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A border between `pair` along row `y` of a 100-wide image, from
    /// column `x0` to `x1` (exclusive).
    fn row_border(pair: (u32, u32), y: u32, x0: u32, x1: u32) -> Border {
        Border {
            pair,
            width_px: f64::from(x1 - x0),
            pixels: (x0..x1).map(|x| y * 100 + x).collect(),
            near_px: (f64::INFINITY, f64::INFINITY),
        }
    }

    /// The chosen doors of `all` that stay, in a 100-wide image whose
    /// walls are 20 px deep at most.
    fn kept(all: &[Border], chosen: Vec<usize>) -> Vec<usize> {
        one_door_per_doorway(all, chosen, 20.0, 100)
    }

    #[test]
    fn the_two_faces_of_a_deep_doorway_give_one_door() {
        // Rows 10 and 28 of one doorway 20 px wide, 18 px deep: the longer
        // border stays, whichever comes first.
        let all = [
            row_border((1, 2), 10, 40, 60),
            row_border((1, 2), 28, 41, 60),
        ];
        assert_eq!(kept(&all, vec![0, 1]), vec![0]);
        let swapped = [all[1].clone(), all[0].clone()];
        assert_eq!(kept(&swapped, vec![0, 1]), vec![1]);
        // As long: the earlier stays.
        let even = [
            row_border((1, 2), 10, 40, 60),
            row_border((1, 2), 28, 40, 60),
        ];
        assert_eq!(kept(&even, vec![0, 1]), vec![0]);
    }

    #[test]
    fn doors_further_apart_or_between_other_spaces_all_stay() {
        // Two doorways of one wall 30 px apart, a wall 20 px deep at most.
        let apart = [
            row_border((1, 2), 10, 10, 30),
            row_border((1, 2), 10, 40, 59),
        ];
        assert_eq!(kept(&apart, vec![0, 1]), vec![0, 1]);
        // The same place between other spaces.
        let others = [
            row_border((1, 2), 10, 40, 60),
            row_border((2, 3), 28, 41, 60),
        ];
        assert_eq!(kept(&others, vec![0, 1]), vec![0, 1]);
        // Only the chosen borders count.
        let all = [
            row_border((1, 2), 10, 40, 60),
            row_border((1, 2), 28, 30, 60),
        ];
        assert_eq!(kept(&all, vec![0]), vec![0]);
    }
}
