//! String pulling: the shortest path through a channel of portals, by the
//! funnel algorithm (Lee & Preparata 1984; the "simple stupid funnel" form
//! of Mononen 2010).

use crate::model::Point;

fn sub(a: Point, b: Point) -> Point {
    [a[0] - b[0], a[1] - b[1]]
}

/// z of the cross product: > 0 when `v` turns left of `u`.
fn cross(u: Point, v: Point) -> f64 {
    u[0] * v[1] - u[1] * v[0]
}

/// Euclidean distance.
pub(crate) fn dist(a: Point, b: Point) -> f64 {
    let (dx, dy) = (a[0] - b[0], a[1] - b[1]);
    (dx * dx + dy * dy).sqrt()
}

/// The length of a polyline.
pub(crate) fn polyline_length(points: &[Point]) -> f64 {
    points.windows(2).map(|w| dist(w[0], w[1])).sum()
}

/// The shortest polyline from `start` to `end` crossing each portal in
/// order. A portal is `(right, left)` as seen walking along the channel.
/// The polyline starts at `start`, ends at `end` and bends only at portal
/// end points.
///
/// ```ignore
/// // A channel that turns left around (1, 1): the path bends there.
/// let portals = [([1.0, 0.0], [1.0, 1.0]), ([1.0, 1.0], [2.0, 1.0])];
/// let path = funnel([0.0, 0.5], [1.5, 2.0], &portals);
/// assert_eq!(path, vec![[0.0, 0.5], [1.0, 1.0], [1.5, 2.0]]);
/// ```
pub(crate) fn funnel(start: Point, end: Point, portals: &[(Point, Point)]) -> Vec<Point> {
    funnel_corners(start, end, portals)
        .into_iter()
        .map(|c| c.at)
        .collect()
}

/// A bend of a funnel path: where, and which portal end made it
/// (`(portal index, true for its left end)`; `None` for start and end).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Corner {
    pub at: Point,
    pub from: Option<(usize, bool)>,
}

/// Whether `p` lies on the segment of `portal` (to rounding): the
/// triangles on both sides of it hold `p`.
fn on_portal(p: Point, (a, b): (Point, Point)) -> bool {
    let (ab, ap) = (sub(b, a), sub(p, a));
    let len2 = ab[0] * ab[0] + ab[1] * ab[1];
    if len2 <= 0.0 {
        return ap == [0.0, 0.0];
    }
    let t = (ap[0] * ab[0] + ap[1] * ab[1]) / len2;
    // Twice the triangle's area over the length: the distance to the line.
    let off = cross(ab, ap).abs() / len2.sqrt();
    off <= 1e-9 * (1.0 + len2.sqrt()) && (-1e-9..=1.0 + 1e-9).contains(&t)
}

/// [`funnel`], saying which portal end each bend is.
///
/// Portals at the start of the channel that the start point lies on, and
/// at its end that the end point lies on, are passed already: a point on
/// a portal sees it edge-on, where the funnel's side tests have no sign
/// (a room's centre on a diagonal of its triangulation made a walk
/// through the room bend at a far corner).
pub(crate) fn funnel_corners(start: Point, end: Point, portals: &[(Point, Point)]) -> Vec<Corner> {
    let skip = portals.iter().take_while(|p| on_portal(start, **p)).count();
    let keep = portals.len()
        - portals[skip..]
            .iter()
            .rev()
            .take_while(|p| on_portal(end, **p))
            .count();
    let mut corners = funnel_through(start, end, &portals[skip..keep]);
    // Bends keep their index in the whole channel; one at the end point
    // itself (the funnel's last, degenerate portal) is no portal's end.
    for c in &mut corners {
        c.from = c
            .from
            .filter(|(i, _)| *i < keep - skip)
            .map(|(i, left)| (i + skip, left));
    }
    corners
}

/// The funnel proper: the bends of the shortest path through `portals`.
fn funnel_through(start: Point, end: Point, portals: &[(Point, Point)]) -> Vec<Corner> {
    let mut path = vec![Corner {
        at: start,
        from: None,
    }];
    let n = portals.len() + 1;
    let portal = |i: usize| -> (Point, Point) {
        if i < portals.len() {
            portals[i]
        } else {
            (end, end)
        }
    };
    let (mut apex, mut left, mut right) = (start, start, start);
    let (mut left_i, mut right_i) = (0usize, 0usize);
    let mut i = 0usize;
    // Each restart moves the apex forward, so the loop ends; the guard
    // bounds it whatever the input.
    let mut guard = 0usize;
    let limit = 4 * (n + 4) * (n + 4);
    while i < n && guard < limit {
        guard += 1;
        let (r, l) = portal(i);
        // Tighten the right side.
        if cross(sub(right, apex), sub(r, apex)) >= 0.0 {
            if apex == right || cross(sub(left, apex), sub(r, apex)) < 0.0 {
                right = r;
                right_i = i + 1;
            } else {
                // The right side crossed the left one: its corner is on the path.
                push(&mut path, left, left_i, true);
                apex = left;
                right = apex;
                right_i = left_i;
                i = left_i;
                continue;
            }
        }
        // Tighten the left side.
        if cross(sub(left, apex), sub(l, apex)) <= 0.0 {
            if apex == left || cross(sub(right, apex), sub(l, apex)) > 0.0 {
                left = l;
                left_i = i + 1;
            } else {
                push(&mut path, right, right_i, false);
                apex = right;
                left = apex;
                left_i = right_i;
                i = right_i;
                continue;
            }
        }
        i += 1;
    }
    if path.last().map(|c| c.at) != Some(end) {
        path.push(Corner {
            at: end,
            from: None,
        });
    }
    path
}

/// Adds a bend at portal end `p`, the `index`-th funnel position (1-based
/// over the portals; 0 is the start).
fn push(path: &mut Vec<Corner>, p: Point, index: usize, left: bool) {
    if path.last().map(|c| c.at) == Some(p) {
        return;
    }
    let from = index.checked_sub(1).map(|i| (i, left));
    path.push(Corner { at: p, from });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn straight_channel_gives_a_straight_line() {
        let portals = [([1.0, -1.0], [1.0, 1.0]), ([2.0, -1.0], [2.0, 1.0])];
        let path = funnel([0.0, 0.0], [3.0, 0.5], &portals);
        assert_eq!(path, vec![[0.0, 0.0], [3.0, 0.5]]);
    }

    #[test]
    fn left_turn_bends_at_the_inner_corner() {
        // An L: east along y in [0, 1], then north along x in [1, 2].
        let portals = [([1.0, 0.0], [1.0, 1.0]), ([2.0, 1.0], [1.0, 1.0])];
        let path = funnel([0.0, 0.5], [1.5, 3.0], &portals);
        assert_eq!(path, vec![[0.0, 0.5], [1.0, 1.0], [1.5, 3.0]]);
        let expected = 0.5f64.hypot(1.0) + 0.5f64.hypot(2.0);
        assert!((polyline_length(&path) - expected).abs() < 1e-12);
    }

    #[test]
    fn right_turn_bends_at_the_inner_corner() {
        // East along y in [0, 1], then south along x in [1, 2].
        let portals = [([1.0, 0.0], [1.0, 1.0]), ([1.0, 0.0], [2.0, 0.0])];
        let path = funnel([0.0, 0.5], [1.5, -2.0], &portals);
        assert_eq!(path, vec![[0.0, 0.5], [1.0, 0.0], [1.5, -2.0]]);
    }

    #[test]
    fn a_start_on_a_portal_walks_straight() {
        // A rectangle cut by the diagonal (0, 0)-(4, 2), then a fan to the
        // target: the start (2, 1) lies on the first portal.
        let portals = [([4.0, 2.0], [0.0, 0.0]), ([0.0, 0.0], [4.0, -2.0])];
        let path = funnel([2.0, 1.0], [1.0, -1.0], &portals);
        assert_eq!(path, vec![[2.0, 1.0], [1.0, -1.0]]);
        // And the same at the end, walked the other way.
        let back = [([4.0, -2.0], [0.0, 0.0]), ([0.0, 0.0], [4.0, 2.0])];
        let path = funnel([1.0, -1.0], [2.0, 1.0], &back);
        assert_eq!(path, vec![[1.0, -1.0], [2.0, 1.0]]);
    }

    #[test]
    fn zigzag_through_offset_doors() {
        // Two doors in walls at x = 1 and x = 2, the first low, the second high.
        let portals = [([1.0, 0.0], [1.0, 0.2]), ([2.0, 0.8], [2.0, 1.0])];
        let path = funnel([0.0, 0.5], [3.0, 0.5], &portals);
        assert_eq!(path, vec![[0.0, 0.5], [1.0, 0.2], [2.0, 0.8], [3.0, 0.5]]);
    }
}
