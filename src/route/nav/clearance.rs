//! Keeping a clearance `r` from walls: which triangle edges and traversals
//! are wide enough (Demyen & Buro 2006, "Efficient triangulation-based
//! pathfinding", widths through a triangle), and the shortest path that
//! keeps `r` from the obstacle corners it bends around — the funnel on
//! portals shrunk by `r` at obstacle ends, then every bend at an obstacle
//! corner replaced by tangents and an arc of radius `r` around it.

use super::funnel::{dist, funnel_corners};
use super::mesh::{Across, Mesh};
use crate::model::Point;

/// Whether the edge `a`–`b` leaves a gap of `2r` between obstacle ends.
pub(crate) fn edge_open(mesh: &Mesh, a: u32, b: u32, r: f64) -> bool {
    if r <= 0.0 {
        return true;
    }
    let ends = f64::from(u8::from(mesh.obstacle[a as usize]) + u8::from(mesh.obstacle[b as usize]));
    dist(mesh.point(a), mesh.point(b)) >= ends * r
}

/// Whether a disc of radius `r` passes through triangle `t` from edge `e_in`
/// to edge `e_out`: the width at their common corner (Demyen & Buro).
pub(crate) fn traversal_open(mesh: &Mesh, t: u32, e_in: usize, e_out: usize, r: f64) -> bool {
    if r <= 0.0 || e_in == e_out || e_in > 2 || e_out > 2 {
        return true;
    }
    let tri = &mesh.tris[t as usize];
    // Edge i runs v[i] -> v[i+1]; the corner shared by the two edges.
    let (c, a, b) = if e_out == (e_in + 1) % 3 {
        (tri.v[e_out], tri.v[e_in], tri.v[(e_out + 1) % 3])
    } else {
        (tri.v[e_in], tri.v[(e_in + 1) % 3], tri.v[e_out])
    };
    if !mesh.obstacle[c as usize] {
        return true;
    }
    let (pc, pa, pb) = (mesh.point(c), mesh.point(a), mesh.point(b));
    let obtuse = |at: Point, p: Point, q: Point| {
        (p[0] - at[0]) * (q[0] - at[0]) + (p[1] - at[1]) * (q[1] - at[1]) <= 0.0
    };
    let third = 3 - e_in - e_out;
    let width = if obtuse(pa, pc, pb) || obtuse(pb, pc, pa) {
        dist(pc, pa).min(dist(pc, pb))
    } else if tri.across[third] == Across::Wall {
        super::segment_distance(pc, pa, pb)
    } else {
        dist(pc, pa).min(dist(pc, pb))
    };
    width >= 2.0 * r
}

/// Whether a disc of radius `r` passes along a channel of triangles: every
/// edge crossed is [`edge_open`] and every triangle [`traversal_open`].
pub(crate) fn channel_open(mesh: &Mesh, channel: &[u32], r: f64) -> bool {
    if r <= 0.0 {
        return true;
    }
    // The edge of `t` leading into `u`.
    let edge_to = |t: u32, u: u32| {
        mesh.tris[t as usize].across.iter().position(|a| match a {
            Across::Inside(n) | Across::Gate { tri: n, .. } => *n == u,
            Across::Wall => false,
        })
    };
    let mut entry = 3;
    for w in channel.windows(2) {
        let (t, u) = (w[0], w[1]);
        let Some(exit) = edge_to(t, u) else {
            return false;
        };
        let tri = &mesh.tris[t as usize];
        if !edge_open(mesh, tri.v[exit], tri.v[(exit + 1) % 3], r)
            || !traversal_open(mesh, t, entry, exit, r)
        {
            return false;
        }
        entry = edge_to(u, t).unwrap_or(3);
    }
    true
}

/// A point the path bends around: a corner with the radius kept from it
/// (0 when it is no obstacle) and the side it lies on (`left` of travel).
#[derive(Debug, Clone, Copy)]
struct Peg {
    centre: Point,
    radius: f64,
    left: bool,
}

/// Step of the polygon around an arc, radians (15°).
const ARC_STEP: f64 = std::f64::consts::PI / 12.0;

/// The shortest path from `from` to `to` through `portals` (vertex pairs
/// `(right, left)`) keeping `r` from obstacle corners.
pub(crate) fn clear_walk(
    mesh: &Mesh,
    from: Point,
    to: Point,
    portals: &[(u32, u32)],
    r: f64,
) -> Vec<Point> {
    let shrunk: Vec<(Point, Point)> = portals
        .iter()
        .map(|&(a, b)| shrink(mesh, a, b, r))
        .collect();
    let corners = funnel_corners(from, to, &shrunk);
    let mut pegs: Vec<(u32, Peg)> = Vec::new();
    for c in &corners {
        let Some((i, left)) = c.from else { continue };
        let Some(&(rv, lv)) = portals.get(i) else {
            continue;
        };
        let v = if left { lv } else { rv };
        if pegs.last().is_some_and(|(w, p)| *w == v && p.left == left) {
            continue;
        }
        let obstacle = mesh.obstacle[v as usize];
        pegs.push((
            v,
            Peg {
                centre: if obstacle { mesh.point(v) } else { c.at },
                radius: if obstacle { r } else { 0.0 },
                left,
            },
        ));
    }
    let pegs: Vec<Peg> = pegs.into_iter().map(|(_, p)| p).collect();
    wrap(from, to, &pegs).unwrap_or_else(|| corners.iter().map(|c| c.at).collect())
}

/// Moves an obstacle end of a portal `r` towards the other end.
fn shrink(mesh: &Mesh, a: u32, b: u32, r: f64) -> (Point, Point) {
    let (pa, pb) = (mesh.point(a), mesh.point(b));
    let (oa, ob) = (mesh.obstacle[a as usize], mesh.obstacle[b as usize]);
    if !(oa || ob) {
        return (pa, pb);
    }
    let len = dist(pa, pb);
    if len <= 0.0 {
        return (pa, pb);
    }
    let room = if oa && ob { len / 2.0 } else { len };
    let t = (r / len).min(room / len);
    let toward = |p: Point, q: Point| [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])];
    (
        if oa { toward(pa, pb) } else { pa },
        if ob { toward(pb, pa) } else { pb },
    )
}

/// Tangent points from circle 1 to circle 2 with signed radii (positive:
/// the obstacle on the left of travel), or `None` when they overlap.
fn tangent(c1: Point, r1: f64, c2: Point, r2: f64) -> Option<(Point, Point)> {
    let d = [c2[0] - c1[0], c2[1] - c1[1]];
    let l = d[0].hypot(d[1]);
    if l <= 1e-12 || (r1 - r2).abs() > l {
        return None;
    }
    let phi = d[1].atan2(d[0]);
    let theta = phi - ((r1 - r2) / l).acos();
    // n is the right-hand normal of travel; a left obstacle (positive
    // radius) has the path on its right.
    let n = [theta.cos(), theta.sin()];
    Some((
        [c1[0] + r1 * n[0], c1[1] + r1 * n[1]],
        [c2[0] + r2 * n[0], c2[1] + r2 * n[1]],
    ))
}

/// The path from `from` around `pegs` to `to`: tangents and arcs drawn as
/// a polygon outside each circle (so it keeps the radius).
fn wrap(from: Point, to: Point, pegs: &[Peg]) -> Option<Vec<Point>> {
    let signed = |p: &Peg| if p.left { p.radius } else { -p.radius };
    let nodes: Vec<(Point, f64)> = std::iter::once((from, 0.0))
        .chain(pegs.iter().map(|p| (p.centre, signed(p))))
        .chain(std::iter::once((to, 0.0)))
        .collect();
    let mut legs = Vec::with_capacity(nodes.len() - 1);
    for w in nodes.windows(2) {
        legs.push(tangent(w[0].0, w[0].1, w[1].0, w[1].1)?);
    }
    let mut out = vec![from];
    for (k, peg) in pegs.iter().enumerate() {
        let arrive = legs[k].1;
        let depart = legs[k + 1].0;
        out.push(arrive);
        if peg.radius > 0.0 {
            arc(&mut out, peg, arrive, depart);
        }
        out.push(depart);
    }
    out.push(to);
    out.dedup_by(|a, b| dist(*a, *b) < 1e-12);
    Some(out)
}

/// Appends the polygon outside the arc from `a` to `b` around `peg`
/// (counter-clockwise around a left obstacle, clockwise around a right one).
fn arc(out: &mut Vec<Point>, peg: &Peg, a: Point, b: Point) {
    let c = peg.centre;
    let (ta, tb) = (
        (a[1] - c[1]).atan2(a[0] - c[0]),
        (b[1] - c[1]).atan2(b[0] - c[0]),
    );
    let tau = std::f64::consts::TAU;
    let sweep = if peg.left {
        (tb - ta).rem_euclid(tau)
    } else {
        (ta - tb).rem_euclid(tau)
    };
    if !(1e-9..=1.5 * std::f64::consts::PI).contains(&sweep) {
        return;
    }
    let k = (sweep / ARC_STEP).ceil().max(1.0);
    let h = sweep / k;
    let radius = peg.radius / (h / 2.0).cos();
    let sign = if peg.left { 1.0 } else { -1.0 };
    for j in 0..k as usize {
        let angle = ta + sign * (j as f64 + 0.5) * h;
        out.push([c[0] + radius * angle.cos(), c[1] + radius * angle.sin()]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tangent_from_a_point_to_a_left_circle() {
        // From (0, -1) east to a circle of radius 1 at (5, 0) on the left:
        // the tangent touches its bottom.
        let (p, q) = tangent([-5.0, -1.0], 0.0, [5.0, 0.0], 1.0).unwrap();
        assert!(dist(p, [-5.0, -1.0]) < 1e-12);
        assert!((dist(q, [5.0, 0.0]) - 1.0).abs() < 1e-12);
        // The segment is perpendicular to the radius at q.
        let (u, v) = ([q[0] - p[0], q[1] - p[1]], [q[0] - 5.0, q[1]]);
        assert!((u[0] * v[0] + u[1] * v[1]).abs() < 1e-9);
        assert!(q[1] < 0.0, "the path passes below a left obstacle");
    }

    #[test]
    fn wrapping_a_corner_keeps_the_radius() {
        // Around a corner at the origin on the left, from below-left to above-right.
        let peg = Peg {
            centre: [0.0, 0.0],
            radius: 0.5,
            left: true,
        };
        let path = wrap([-3.0, -1.0], [1.0, 3.0], &[peg]).unwrap();
        for w in path.windows(2) {
            let d = super::super::segment_distance([0.0, 0.0], w[0], w[1]);
            assert!(d >= 0.5 - 1e-9, "segment {w:?} is {d} from the corner");
        }
        assert!(path.len() > 3, "an arc was drawn");
    }
}
