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
    pub(crate) fn join_open(&mut self, gaps: &[WallGap], px: &PixelConfig) {
        self.borders = borders(&self.labels, &self.dist, px.border_join);
        let gap_px: HashSet<u32> = gaps.iter().flat_map(|g| g.line.iter().copied()).collect();
        let joins = open_joins(
            &self.borders,
            &self.widest,
            &self.is_passage,
            &gap_px,
            &px.doors,
        );
        if !joins.is_empty() {
            merge_pairs(&mut self.labels, &joins);
            self.borders = borders(&self.labels, &self.dist, px.border_join);
            self.widest = widest_passages(&self.labels, &self.dist);
            self.is_passage = self.passages();
        }
    }

    /// After pixels moved between regions (their labels kept): the
    /// borders and widest passages measured again. Which regions are
    /// passages stays as it was.
    pub(crate) fn remeasure(&mut self, px: &PixelConfig) {
        self.borders = borders(&self.labels, &self.dist, px.border_join);
        self.widest = widest_passages(&self.labels, &self.dist);
    }
}

/// The widest inscribed diameter (px) of every label.
fn widest_passages(labels: &Labels, dist: &[f32]) -> Vec<f64> {
    region_shapes(labels, dist)
        .into_iter()
        .map(|s| s.1)
        .collect()
}

/// (area in px, widest inscribed diameter in px) of every label.
pub(crate) fn region_shapes(labels: &Labels, dist: &[f32]) -> Vec<(usize, f64)> {
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
