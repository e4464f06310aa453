//! [`Regions`]: the segmented free space and what the stages between
//! segmentation and doors know of each region (its widest passage,
//! whether it is a narrow passage split off, its borders), kept together
//! and brought up to date whenever a stage relabels.

use std::collections::HashSet;

use super::doors::{Border, borders};
use super::joins::open_joins;
use super::merge::{merge_pairs, merge_small};
use super::pixel_config::PixelConfig;
use super::stubs::{passage_labels, split_off_passages};
use super::wall_gaps::WallGap;
use super::wall_support::WallSupport;
use crate::imaging::{Labels, max_distance};

/// The regions of one map between segmentation and doors.
pub(crate) struct Regions {
    /// Region per pixel (0 = none).
    pub labels: Labels,
    /// Distance to the nearest obstacle per pixel (px).
    pub dist: Vec<f32>,
    /// Per label: its widest inscribed diameter (px).
    pub widest: Vec<f64>,
    /// Per pixel: inside a narrow passage (see `stubs`); empty when none
    /// was split off.
    in_passage: Vec<bool>,
    /// Per label: a narrow passage split off as a space of its own.
    pub is_passage: Vec<bool>,
    /// Every border between two regions.
    pub borders: Vec<Border>,
}

impl Regions {
    /// Regions as segmented, their widest passages measured.
    pub(crate) fn new(labels: Labels, dist: Vec<f32>) -> Regions {
        let widest = widest_passages(&labels, &dist);
        Regions {
            labels,
            dist,
            widest,
            in_passage: Vec::new(),
            is_passage: Vec::new(),
            borders: Vec::new(),
        }
    }

    /// Per label: a narrow passage, from the pixels split off.
    fn passages(&self) -> Vec<bool> {
        if self.in_passage.is_empty() {
            vec![false; self.labels.count as usize + 1]
        } else {
            passage_labels(&self.labels, &self.in_passage)
        }
    }

    /// Stage `passages`: narrow passages (corridor stubs, strip corridors)
    /// become regions of their own (see `stubs`); tiny pieces left merge
    /// into a neighbour.
    pub(crate) fn split_passages(&mut self, px: &PixelConfig) {
        if let Some(limits) = &px.passages {
            self.in_passage =
                split_off_passages(&mut self.labels, &self.dist, &self.widest, limits);
            if !self.in_passage.is_empty() {
                merge_small(&mut self.labels, px.min_room_area);
                self.widest = widest_passages(&self.labels, &self.dist);
            }
        }
        self.is_passage = self.passages();
    }

    /// Stage `joins`: regions that meet where no doorway divides them are
    /// one (see `joins`); afterwards every border is known.
    pub(crate) fn join_open(&mut self, gaps: &[WallGap], support: &WallSupport, px: &PixelConfig) {
        self.borders = self.measured_borders(px);
        let gap_px: HashSet<u32> = gaps.iter().flat_map(|g| g.line.iter().copied()).collect();
        let joins = open_joins(
            &self.borders,
            &self.widest,
            &self.is_passage,
            &gap_px,
            &px.doors,
            Some(support),
        );
        if !joins.is_empty() {
            merge_pairs(&mut self.labels, &joins);
            self.borders = self.measured_borders(px);
            self.widest = widest_passages(&self.labels, &self.dist);
            self.is_passage = self.passages();
        }
    }

    /// Every border between two regions, with its regions' widths near it.
    fn measured_borders(&self, px: &PixelConfig) -> Vec<Border> {
        let mut all = borders(&self.labels, &self.dist, px.border_join);
        measure_near(&mut all, &self.labels, &self.dist, px.near_reach);
        all
    }

    /// After pixels moved between regions (their labels kept): the
    /// borders and widest passages measured again. Which regions are
    /// passages stays as it was.
    pub(crate) fn remeasure(&mut self, px: &PixelConfig) {
        self.borders = self.measured_borders(px);
        self.widest = widest_passages(&self.labels, &self.dist);
    }
}

/// Sets each border's `near_px`: the widest inscribed diameter (twice the
/// largest `dist`) of each of its two regions within a disk around the
/// border, `reach` px wider than the border's own extent from its centre
/// (that extent counted up to `reach`).
/// A region's width far from the border (a corridor that opens into a
/// hall further on, a room's far end) says nothing of whether the border
/// narrows it; a disk, not a box, so a turned map measures alike.
fn measure_near(all: &mut [Border], labels: &Labels, dist: &[f32], reach: f64) {
    let (w, h) = (labels.width as usize, labels.height as usize);
    if w == 0 || h == 0 {
        return;
    }
    let at = |p: u32| ((p as usize % w) as f64, (p as usize / w) as f64);
    for b in all.iter_mut() {
        if b.pixels.is_empty() {
            continue;
        }
        let n = b.pixels.len() as f64;
        let (sx, sy) = b
            .pixels
            .iter()
            .map(|&p| at(p))
            .fold((0.0, 0.0), |(sx, sy), (x, y)| (sx + x, sy + y));
        let (cx, cy) = (sx / n, sy / n);
        let extent = b
            .pixels
            .iter()
            .map(|&p| {
                let (x, y) = at(p);
                (x - cx).hypot(y - cy)
            })
            .fold(0.0f64, f64::max);
        // A long border is looked at around its middle: the scan stays
        // within 2 × reach of it, however long the border.
        let r = extent.min(reach) + reach;
        let (x0, y0) = (
            (cx - r).floor().max(0.0) as usize,
            (cy - r).floor().max(0.0) as usize,
        );
        let (x1, y1) = (
            ((cx + r).ceil() as usize).min(w - 1),
            ((cy + r).ceil() as usize).min(h - 1),
        );
        let (mut a, mut c) = (0.0f32, 0.0f32);
        for y in y0..=y1 {
            let dy = y as f64 - cy;
            for x in x0..=x1 {
                let dx = x as f64 - cx;
                if dx * dx + dy * dy > r * r {
                    continue;
                }
                let i = y * w + x;
                let l = labels.data[i];
                if l == b.pair.0 {
                    a = a.max(dist[i]);
                } else if l == b.pair.1 {
                    c = c.max(dist[i]);
                }
            }
        }
        b.near_px = (2.0 * f64::from(a), 2.0 * f64::from(c));
    }
}

/// The widest inscribed diameter (px) of every label.
fn widest_passages(labels: &Labels, dist: &[f32]) -> Vec<f64> {
    let mut widest = vec![0.0f32; labels.count as usize + 1];
    // A run of one label updates it once (no store-to-load chain per pixel).
    let mut i = 0;
    while i < labels.data.len() {
        let l = labels.data[i];
        let run = labels.data[i..].iter().position(|&m| m != l);
        let end = run.map_or(labels.data.len(), |r| i + r);
        let e = &mut widest[l as usize];
        *e = e.max(max_distance(&dist[i..end]));
        i = end;
    }
    widest.into_iter().map(|d| 2.0 * f64::from(d)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_border_is_measured_against_its_regions_near_it() {
        // Region 1 (columns 0-19) and region 2 (20-59) of a 60 x 9 strip;
        // region 2 is 2 px "wide" (dist 1) up to column 29 and widens to
        // dist 6 at column 55: a corridor opening into a hall far off.
        let (w, h) = (60usize, 9usize);
        let mut data = vec![0u32; w * h];
        let mut dist = vec![0f32; w * h];
        for y in 0..h {
            for x in 0..w {
                data[y * w + x] = if x < 20 { 1 } else { 2 };
                dist[y * w + x] = match x {
                    0..20 => 3.0,
                    20..30 => 1.0,
                    _ if x == 55 => 6.0,
                    _ => 2.0,
                };
            }
        }
        let labels = Labels {
            width: w as u32,
            height: h as u32,
            data,
            count: 2,
        };
        let mut all = borders(&labels, &dist, 2);
        assert_eq!(all.len(), 1);
        measure_near(&mut all, &labels, &dist, 5.0);
        // The border's extent from its centre is 4 px (the 9 rows), so the
        // disk reaches 9 px into each region: region 2 up to column 28.
        assert_eq!(all[0].near_px, (6.0, 2.0));
        measure_near(&mut all, &labels, &dist, 40.0);
        assert_eq!(all[0].near_px, (6.0, 12.0), "far enough to see the hall");
        let widest = widest_passages(&labels, &dist);
        assert_eq!((widest[1], widest[2]), (6.0, 12.0));
    }
}
