//! Where a door node goes into a space's outline for the OpenStreetMap
//! export: Simple Indoor Tagging wants a door as a node *on* the outline
//! of each space it opens into, but our door spaces fill the wall between
//! two outlines, so the door's middle lies off both of them (half a wall
//! away).
//!
//! The rule: the nearest edge of the space's rings is split at the point
//! nearest the door's middle, and the outline dips to the door's middle in
//! a right-angled notch (legs at 45° to the edge, as wide on each side as
//! it is deep). The notch adds depth² to the outline's area: 0.0225 m² for
//! a 30 cm wall, against depth × width / 2 for a notch spanning the
//! doorway and the whole edge's length × depth / 2 for a bare split; no
//! spike, no self-intersection. A door already on the outline (depth under
//! a millimetre) is just inserted into the edge. Notches on one edge are
//! narrowed so they do not overlap.

use crate::model::Point;

/// Below this depth (metres) a door is on the edge: no notch.
const ON_EDGE_M: f64 = 1e-3;

/// A door to be put into a ring: the edge it splits (from vertex `edge`
/// to the next), where along it (`t` in [0, 1]), the door's middle and
/// its distance from the edge.
#[derive(Debug, Clone, Copy)]
pub(super) struct Notch {
    /// Index of the edge's first vertex.
    pub edge: usize,
    /// Position of the foot along the edge, 0 at its first vertex.
    pub t: f64,
    /// The door's middle: the notch's apex.
    pub apex: Point,
    /// The apex's distance from the edge.
    pub depth: f64,
}

/// The nearest edge of `rings` to `p`: the ring's index and the [`Notch`]
/// that puts `p` into it; `None` for rings without edges.
pub(super) fn nearest(rings: &[&[Point]], p: Point) -> Option<(usize, Notch)> {
    let mut best: Option<(usize, Notch)> = None;
    for (r, ring) in rings.iter().enumerate() {
        if ring.len() < 2 {
            continue;
        }
        for (i, &a) in ring.iter().enumerate() {
            let b = ring.get((i + 1) % ring.len()).copied().unwrap_or(a);
            let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
            let len2 = dx * dx + dy * dy;
            let t = if len2 > 0.0 {
                (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let depth = (p[0] - a[0] - t * dx).hypot(p[1] - a[1] - t * dy);
            if best.is_none_or(|(_, n)| depth < n.depth) {
                best = Some((
                    r,
                    Notch {
                        edge: i,
                        t,
                        apex: p,
                        depth,
                    },
                ));
            }
        }
    }
    best
}

/// `ring` with the `notches` put into their edges (see the module doc),
/// still open (the first point not repeated).
pub(super) fn with_notches(ring: &[Point], notches: &[Notch]) -> Vec<Point> {
    let mut out = Vec::with_capacity(ring.len() + 3 * notches.len());
    for (i, &a) in ring.iter().enumerate() {
        out.push(a);
        let b = ring.get((i + 1) % ring.len()).copied().unwrap_or(a);
        let mut on_edge: Vec<&Notch> = notches.iter().filter(|n| n.edge == i).collect();
        on_edge.sort_by(|x, y| x.t.total_cmp(&y.t));
        let len = (b[0] - a[0]).hypot(b[1] - a[1]);
        let at = |t: f64| [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
        for (k, n) in on_edge.iter().enumerate() {
            if n.depth < ON_EDGE_M || len <= 0.0 {
                out.push(n.apex);
                continue;
            }
            // Half-width as a fraction of the edge, kept clear of the
            // edge's ends and of the neighbouring notches.
            let mut half = n.depth / len;
            if let Some(prev) = k.checked_sub(1).and_then(|j| on_edge.get(j)) {
                half = half.min((n.t - prev.t) / 2.0);
            }
            if let Some(next) = on_edge.get(k + 1) {
                half = half.min((next.t - n.t) / 2.0);
            }
            let (t0, t1) = (n.t - half, n.t + half);
            if t0 > 0.0 && half > 0.0 {
                out.push(at(t0));
            }
            out.push(n.apex);
            if t1 < 1.0 && half > 0.0 {
                out.push(at(t1));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::polygon_area;

    #[test]
    fn a_notch_adds_its_depth_squared() {
        let square = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
        let door = [2.0, -0.15];
        let (ring, n) = nearest(&[&square], door).unwrap();
        assert_eq!((ring, n.edge), (0, 0));
        assert!((n.t - 0.5).abs() < 1e-12 && (n.depth - 0.15).abs() < 1e-12);
        let notched = with_notches(&square, &[n]);
        assert_eq!(notched.len(), 7);
        assert!(notched.contains(&door));
        let added = polygon_area(&notched).abs() - 16.0;
        assert!((added - 0.15 * 0.15).abs() < 1e-9, "{added}");
    }

    #[test]
    fn close_notches_do_not_overlap_and_doors_on_the_edge_split_it() {
        let square = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
        let notches: Vec<Notch> = [[1.0, -0.5], [1.2, -0.5], [3.0, 0.0]]
            .into_iter()
            .map(|p| nearest(&[&square], p).unwrap().1)
            .collect();
        let ring = with_notches(&square, &notches);
        let xs: Vec<f64> = ring
            .iter()
            .take_while(|p| p[0] < 4.0)
            .map(|p| p[0])
            .collect();
        assert!(xs.windows(2).all(|w| w[0] <= w[1]), "{xs:?}");
        assert!(ring.contains(&[3.0, 0.0]));
    }
}
