//! Open joins: watershed regions that meet where no doorway divides them
//! (the two halves of a corridor loop, the parts of an open hall) are one
//! space.

use std::collections::HashSet;

use super::doors::Border;
use super::stubs::compared_width;
use super::wall_support::WallSupport;

/// What makes a border a possible door or an open join, in pixels.
#[derive(Debug, Clone, Copy)]
pub(crate) struct JoinLimits {
    /// Narrowest border that can be a doorway (`door_width_min_m`).
    pub door_min_px: f64,
    /// Widest border that can be a doorway (`door_width_max_m`).
    pub door_max_px: f64,
    /// `door_constriction`: a door-wide border wider than this fraction of
    /// the narrower region's widest diameter near it (`Border::near_px`)
    /// is no doorway.
    pub constriction: f64,
    /// `open_join_fraction`: a border wider than any door at least this
    /// fraction of the narrower region's widest diameter near it joins;
    /// 0 = never join.
    pub fraction: f64,
}

/// The region pairs of `all` to merge: pairs with a border that crosses no
/// doorway-gap pixel (`gap_px`) and is either wider than any door and at
/// least `fraction` of the narrower region's widest inscribed diameter,
/// or door-wide but no constriction of the narrower region, or door-wide
/// without the building's walls round it (`support`, see `wall_support`);
/// both widths taken where the regions meet (`widest`, px, within
/// `Border::near_px`; see `stubs::compared_width`).
pub(crate) fn open_joins(
    all: &[Border],
    widest: &[f64],
    is_passage: &[bool],
    gap_px: &HashSet<u32>,
    limits: &JoinLimits,
    support: Option<&WallSupport>,
) -> Vec<(u32, u32)> {
    if limits.fraction <= 0.0 {
        return Vec::new();
    }
    let mut pairs: Vec<(u32, u32)> = all
        .iter()
        .filter(|b| {
            let narrow = compared_width(b, widest, is_passage);
            let w = b.width_px;
            let wide_open = w > limits.door_max_px && w >= limits.fraction * narrow;
            let door_wide = w >= limits.door_min_px && w <= limits.door_max_px;
            let no_constriction = door_wide && w > limits.constriction * narrow;
            let no_wall = door_wide && support.is_some_and(|s| s.lacks(&b.pixels));
            (wide_open || no_constriction || no_wall)
                && !b.pixels.iter().any(|p| gap_px.contains(p))
        })
        .map(|b| b.pair)
        .collect();
    pairs.dedup();
    pairs
}

#[cfg(test)]
mod tests {
    use super::*;

    fn border(pair: (u32, u32), width_px: f64, pixels: Vec<u32>) -> Border {
        Border {
            pair,
            width_px,
            pixels,
            near_px: (f64::INFINITY, f64::INFINITY),
        }
    }

    const LIMITS: JoinLimits = JoinLimits {
        door_min_px: 8.0,
        door_max_px: 36.0,
        constriction: 0.7,
        fraction: 0.5,
    };

    #[test]
    fn only_borders_no_doorway_divides_join() {
        // Regions 1 and 2 are 40 px wide at most, 3 is 100 px wide.
        let widest = [0.0, 40.0, 40.0, 100.0, 100.0];
        let all = [
            // A corridor's own width between two parts of it: joins.
            border((1, 2), 32.0, vec![1, 2]),
            // A doorway-wide constriction: may be a door, stays.
            border((1, 3), 20.0, vec![3, 4]),
            // Wider than any door but a strong constriction: stays.
            border((3, 4), 40.0, vec![5, 6]),
            // Wider than any door, more than half the hall: joins.
            border((3, 4), 60.0, vec![7, 8]),
        ];
        let joins = open_joins(&all, &widest, &[false; 5], &HashSet::new(), &LIMITS, None);
        assert_eq!(joins, vec![(1, 2), (3, 4)]);
    }

    #[test]
    fn a_doorway_gap_never_joins_and_zero_turns_joining_off() {
        let widest = [0.0, 40.0, 40.0];
        let all = [border((1, 2), 32.0, vec![1, 2])];
        let gap: HashSet<u32> = [2].into_iter().collect();
        assert!(open_joins(&all, &widest, &[false; 3], &gap, &LIMITS, None).is_empty());
        let off = JoinLimits {
            fraction: 0.0,
            ..LIMITS
        };
        assert!(open_joins(&all, &widest, &[false; 3], &HashSet::new(), &off, None).is_empty());
    }
}
