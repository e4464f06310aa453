//! Free-space cleaning: the free mask without LiDAR rays leaking into unknown
//! space, speckle and tiny islands.

use super::furniture::{IslandLimits, Islands, free_without_furniture};
use crate::grid::OccupancyGrid;
use crate::imaging::{Mask, dilate, label_runs, open};

/// The cleaned free space and the free pixels it may grow back into.
pub(crate) struct FreeSpace {
    /// Free space after opening and dropping small components.
    pub clean: Mask,
    /// Originally free pixels near `clean` (corners the opening rounded off).
    pub reachable: Vec<bool>,
}

impl FreeSpace {
    /// The clean free space with the corners its opening rounded off
    /// given back (`reachable`): a room's corners square again, where a
    /// wall's face meets the wall across.
    pub(crate) fn with_corners(&self) -> Mask {
        let mut out = self.clean.clone();
        for (p, _) in out
            .iter_mut()
            .zip(&self.reachable)
            .filter(|&(_, &reachable)| reachable)
        {
            *p = 255;
        }
        out
    }
}

/// Fills furniture islands no wider than `furniture_px` (see
/// [`free_without_furniture`]; `wall_piece_gap_px` for the wall pieces
/// between doorways), opens the free mask with a disk of `noise_px`
/// (rays and speckle are narrower than its diameter) and drops
/// 8-connected components under `min_area_px`. Lengths in pixels.
pub(crate) fn clean_free(
    grid: &OccupancyGrid,
    obstacles: &Islands,
    noise_px: f64,
    min_area_px: usize,
    islands: &IslandLimits,
) -> FreeSpace {
    let free = free_without_furniture(grid, obstacles, islands);
    let r = noise_px;
    let mut clean = if r >= 0.5 {
        open(&free, r)
    } else {
        free.clone()
    };
    let comps = label_runs(&clean, true);
    let areas = comps.areas();
    let min_px = min_area_px;
    let w = clean.width() as usize;
    for r in comps
        .runs
        .iter()
        .filter(|r| areas[r.label as usize] < min_px.max(1))
    {
        let i = r.y as usize * w;
        clean.as_mut()[i + r.x0 as usize..i + r.x1 as usize].fill(0);
    }
    let near = dilate(&clean, r + 1.0);
    let reachable = free
        .iter()
        .zip(near.iter())
        .map(|(&f, &n)| f != 0 && n != 0)
        .collect();
    FreeSpace { clean, reachable }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::extract::clutter::LineLimits;
    use crate::extract::furniture::islands;
    use crate::grid::Cell;

    /// No furniture, clutter or wall pieces filled.
    const NO_ISLANDS: IslandLimits = IslandLimits {
        furniture: 0.0,
        clutter: 0.0,
        wall_piece_gap: 0.0,
        wall_elongation: 3.0,
        lines: LineLimits {
            min_run: 25.0,
            gap: 1,
            tolerance: 1,
            piece_min: 7.5,
            piece_gap: 21.0,
        },
    };

    #[test]
    fn rays_and_islands_go_rooms_stay() {
        // A 6x6 room with a one-pixel ray leaving it and a lone free pixel.
        let g = OccupancyGrid::from_ascii(
            "##########????
             #......#??????
             #...........??
             #......#??????
             #......#???.??
             #......#??????
             #......#??????
             ##########????",
            0.1,
        );
        let f = clean_free(&g, &islands(&g), 1.0, 5, &NO_ISLANDS);
        let w = g.width as usize;
        assert_eq!(f.clean.as_raw()[2 * w + 10], 0, "ray removed");
        assert_eq!(f.clean.as_raw()[4 * w + 11], 0, "island removed");
        assert_ne!(f.clean.as_raw()[3 * w + 3], 0, "room kept");
        assert!(
            !f.reachable[2 * w + 11],
            "the far end of the ray is not reachable"
        );
    }

    #[test]
    fn corners_the_opening_rounded_are_given_back() {
        // A 10 x 8 px room, opened with a disk of 2 px: its corners round
        // off; with them given back the room is square again, and nothing
        // outside it is added.
        let g = OccupancyGrid::from_ascii(
            "############
             #..........#
             #..........#
             #..........#
             #..........#
             #..........#
             #..........#
             #..........#
             #..........#
             ############",
            0.1,
        );
        let f = clean_free(&g, &islands(&g), 2.0, 1, &NO_ISLANDS);
        let w = g.width as usize;
        assert_eq!(f.clean.as_raw()[w + 1], 0, "the opening rounds the corner");
        let cornered = f.with_corners();
        let free: Vec<bool> = g.cells.iter().map(|&c| c == Cell::Free).collect();
        let given: Vec<bool> = cornered.iter().map(|&p| p != 0).collect();
        assert_eq!(given, free);
    }
}
