//! The model out of the final labels: labels renumbered to space ids
//! 1..=n, each space's outline, anchor and (for a door) doorway line in
//! metres, and the connections between them.

use std::collections::BTreeMap;

use super::ExtractError;
use super::polygon::outlines;
use crate::grid::OccupancyGrid;
use crate::imaging::Labels;
use crate::model::{Connection, Nrg, Space, SpaceId, SpaceKind, point_in_ring};

/// The label image renumbered, the model and each space's pixel centroid.
pub(crate) type Built = (Labels, Nrg, BTreeMap<SpaceId, [f64; 2]>);

/// The doorway lines of the door labels (pixel coordinates): label
/// `first + k` has `lines[k]`.
pub(crate) struct DoorLines<'a> {
    /// The first door label.
    pub first: u32,
    /// Each door label's doorway line, in order.
    pub lines: &'a [Option<[[f64; 2]; 2]>],
}

impl DoorLines<'_> {
    fn of(&self, label: usize) -> Option<[[f64; 2]; 2]> {
        let k = label.checked_sub(self.first as usize)?;
        self.lines.get(k).copied().flatten()
    }
}

/// Renumbers non-empty labels to space ids 1..=n and builds spaces and connections.
pub(crate) fn build(
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
