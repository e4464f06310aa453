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
    select_doors(
        &regions.borders,
        &regions.widest,
        &regions.is_passage,
        cues,
        &px.doors,
        regions.labels.width,
    )
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
