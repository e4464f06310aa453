//! Readable steps of a walked route: "walk 12 m along corridor 2, turn left
//! through door 31 into Office 27", each with its distance and turn.

use serde::Serialize;

use super::Route;
use super::nav::{Profile, Walk, dist, mesh::Mesh};
use crate::model::{Nrg, Point, SpaceId, SpaceKind};

/// The manoeuvre at the end of a step.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Turn {
    /// Keep the heading (within 30°).
    Straight,
    /// Turn left (30–120°).
    Left,
    /// Turn right (30–120°).
    Right,
    /// Turn sharp left (120–160°).
    SharpLeft,
    /// Turn sharp right (120–160°).
    SharpRight,
    /// Turn around (over 160°).
    UTurn,
    /// The destination.
    Arrive,
}

impl std::fmt::Display for Step {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.instruction)
    }
}

impl Turn {
    /// The turn from heading `before` to heading `after` (vectors).
    pub fn between(before: Point, after: Point) -> Turn {
        let cross = before[0] * after[1] - before[1] * after[0];
        let dot = before[0] * after[0] + before[1] * after[1];
        if cross == 0.0 && dot == 0.0 {
            return Turn::Straight;
        }
        let angle = cross.atan2(dot).to_degrees();
        match angle {
            a if a.abs() < 30.0 => Turn::Straight,
            a if a.abs() > 160.0 => Turn::UTurn,
            a if a >= 120.0 => Turn::SharpLeft,
            a if a <= -120.0 => Turn::SharpRight,
            a if a > 0.0 => Turn::Left,
            _ => Turn::Right,
        }
    }

    fn phrase(self) -> &'static str {
        match self {
            Turn::Straight => "go straight",
            Turn::Left => "turn left",
            Turn::Right => "turn right",
            Turn::SharpLeft => "turn sharp left",
            Turn::SharpRight => "turn sharp right",
            Turn::UTurn => "turn around",
            Turn::Arrive => "arrive",
        }
    }
}

/// One step: walk `distance_m` in `space`, then `turn` (through `door`)
/// into `into`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Step {
    /// The sentence.
    pub instruction: String,
    /// Metres walked in this step.
    pub distance_m: f64,
    /// The space walked in (the first, when a step runs through several
    /// corridor segments).
    pub space: SpaceId,
    /// The manoeuvre at its end.
    pub turn: Turn,
    /// The door passed at its end, if any.
    pub door: Option<SpaceId>,
    /// The space entered at its end (`None` on arrival).
    pub into: Option<SpaceId>,
    /// Where the manoeuvre happens, metres.
    pub at: Point,
}

/// Metres as said in a step ("3.5 m", "12 m").
fn metres(d: f64) -> String {
    if d < 10.0 {
        format!("{d:.1} m")
    } else {
        format!("{d:.0} m")
    }
}

/// Arc length along `points` where it first crosses segment `a`–`b` at or
/// after segment `from`; the segment index and the position.
fn crossing(points: &[Point], from: usize, a: Point, b: Point, offset: f64) -> (usize, f64, Point) {
    let mut s = offset;
    let mut best = (
        from,
        offset,
        points.get(from).copied().unwrap_or(a),
        f64::INFINITY,
    );
    for i in from..points.len().saturating_sub(1) {
        let (p, q) = (points[i], points[i + 1]);
        let len = dist(p, q);
        // Closest approach of the segments, by sampling the path segment's
        // intersection with the gate's line.
        let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
        let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
        let den = dx * ey - dy * ex;
        let t = if den.abs() > 1e-15 {
            (((a[0] - p[0]) * ey - (a[1] - p[1]) * ex) / den).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let x = [p[0] + t * dx, p[1] + t * dy];
        let miss = super::nav::segment_distance(x, a, b);
        if miss < best.3 - 1e-12 {
            best = (i, s + t * len, x, miss);
        }
        if miss < 1e-9 {
            break;
        }
        s += len;
    }
    (best.0, best.1, best.2)
}

/// The point at arc length `s` along `points`.
fn point_at(points: &[Point], cumulative: &[f64], s: f64) -> Point {
    let s = s.clamp(0.0, cumulative.last().copied().unwrap_or(0.0));
    let i = cumulative
        .partition_point(|c| *c < s)
        .clamp(1, points.len().max(2) - 1);
    let (p, q) = (points[i - 1], points[i]);
    let seg = cumulative[i] - cumulative[i - 1];
    let t = if seg > 0.0 {
        (s - cumulative[i - 1]) / seg
    } else {
        0.0
    };
    [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]
}

/// Builds the route of consecutive walked legs: spaces, doors, length,
/// polyline, duration and steps.
pub(crate) fn describe(nrg: &Nrg, mesh: &Mesh, legs: &[Walk], profile: &Profile) -> Route {
    let mut points: Vec<Point> = Vec::new();
    let mut spaces: Vec<u32> = Vec::new();
    // Arc length of each crossing between consecutive `spaces`.
    let mut crossings: Vec<(f64, Point)> = Vec::new();
    for leg in legs {
        let base = points.len().saturating_sub(1);
        if points.last() == leg.points.first() {
            points.extend(leg.points.iter().skip(1));
        } else {
            points.extend(leg.points.iter());
        }
        let mut seg = base;
        // Arc length at the start of segment `seg`, kept as it advances.
        let mut at = cumulative_at(&points, seg);
        let mut leg_spaces = leg.spaces.iter();
        if spaces.last() == leg.spaces.first() {
            leg_spaces.next();
        }
        spaces.extend(leg_spaces);
        for g in &leg.gates {
            let gate = &mesh.gates[*g as usize];
            let [a, b] = gate.ends.map(|v| mesh.point(v));
            let (i, s, x) = crossing(&points, seg, a, b, at);
            at += points[seg..=i.min(points.len().saturating_sub(1))]
                .windows(2)
                .map(|w| dist(w[0], w[1]))
                .sum::<f64>();
            seg = i;
            crossings.push((s, x));
        }
    }
    let length_m: f64 = legs.iter().map(|l| l.length_m).sum();
    let ids: Vec<SpaceId> = spaces.iter().map(|s| mesh.space_ids[*s as usize]).collect();
    // The mesh's dense index is the position in `nrg.spaces()`: a long
    // route passes thousands of spaces, so no search per space.
    let space_at = |i: usize| {
        let id = ids[i];
        nrg.spaces()
            .get(spaces[i] as usize)
            .filter(|s| s.id == id)
            .or_else(|| nrg.space(id))
    };
    let kinds: Vec<Option<SpaceKind>> = (0..ids.len())
        .map(|i| space_at(i).map(|s| s.kind))
        .collect();
    let label = |i: usize| space_at(i).map_or_else(|| format!("space {}", ids[i]), |s| s.label());
    let doors: Vec<SpaceId> = ids
        .iter()
        .zip(&kinds)
        .filter(|(_, k)| **k == Some(SpaceKind::Door))
        .map(|(id, _)| *id)
        .collect();
    let cumulative: Vec<f64> = std::iter::once(0.0)
        .chain(points.windows(2).scan(0.0, |acc, w| {
            *acc += dist(w[0], w[1]);
            Some(*acc)
        }))
        .collect();
    let heading = |from: f64, to: f64| {
        let (p, q) = (
            point_at(&points, &cumulative, from),
            point_at(&points, &cumulative, to),
        );
        [q[0] - p[0], q[1] - p[1]]
    };
    let mut steps = Vec::new();
    let mut start = 0.0;
    let mut i = 0;
    // Merge corridor segments passed straight through open boundaries.
    let mut along: Vec<usize> = Vec::new();
    while i < ids.len() {
        along.push(i);
        // The next space that is not a door, and the doors on the way.
        let mut j = i + 1;
        let mut through = Vec::new();
        while j + 1 < ids.len() && kinds[j] == Some(SpaceKind::Door) {
            through.push(j);
            j += 1;
        }
        if j >= ids.len() {
            let distance_m = length_m - start;
            let instruction = if ids.len() == 1 && length_m < 1e-9 {
                format!("you are at {}", label(i))
            } else {
                format!(
                    "walk {} {} {} and arrive",
                    metres(distance_m),
                    preposition(kinds[i]),
                    names(&along, &label)
                )
            };
            steps.push(Step {
                instruction,
                distance_m,
                space: first_of(&ids, i, along.len()),
                turn: Turn::Arrive,
                door: None,
                into: None,
                at: points.last().copied().unwrap_or([0.0, 0.0]),
            });
            break;
        }
        let (leave, at) = crossings.get(i).copied().unwrap_or((length_m, [0.0, 0.0]));
        let enter = crossings.get(j - 1).map_or(leave, |c| c.0);
        let before = heading((leave - 1.0).max(start), leave);
        let after = heading(enter, (enter + 1.0).min(length_m));
        let turn = Turn::between(before, after);
        let merge = through.is_empty()
            && turn == Turn::Straight
            && kinds[i] == Some(SpaceKind::Corridor)
            && kinds[j] == Some(SpaceKind::Corridor);
        if merge {
            i = j;
            continue;
        }
        let door = through.first().map(|d| ids[*d]);
        let via = if through.is_empty() {
            String::new()
        } else {
            format!("through {} ", names(&through, &label))
        };
        let distance_m = leave - start;
        steps.push(Step {
            instruction: format!(
                "walk {} {} {}, {} {}into {}",
                metres(distance_m),
                preposition(kinds[i]),
                names(&along, &label),
                turn.phrase(),
                via,
                label(j)
            ),
            distance_m,
            space: first_of(&ids, i, along.len()),
            turn,
            door,
            into: Some(ids[j]),
            at,
        });
        along.clear();
        start = leave;
        i = j;
    }
    Route {
        levels: Vec::new(),
        spaces: ids,
        doors,
        length_m,
        leg_lengths_m: legs.iter().map(|l| l.length_m).collect(),
        duration_s: length_m / profile.speed_m_s,
        waypoints: points,
        steps,
    }
}

/// The spaces at route positions `at` as said in a step: "corridor 1",
/// "corridor 1 and corridor 6", "corridor 1, corridor 6 and corridor 11";
/// past [`NAMED_IN_A_STEP`] the first two, the count and the last
/// ("corridor 1, corridor 6, … and corridor 96 (20 spaces)").
fn names(at: &[usize], label: &impl Fn(usize) -> String) -> String {
    match at {
        [] => String::new(),
        [one] => label(*one),
        [first, second, .., last] if at.len() > NAMED_IN_A_STEP => format!(
            "{}, {}, … and {} ({} spaces)",
            label(*first),
            label(*second),
            label(*last),
            at.len()
        ),
        [rest @ .., last] => {
            let rest: Vec<String> = rest.iter().map(|i| label(*i)).collect();
            format!("{} and {}", rest.join(", "), label(*last))
        }
    }
}

/// Most spaces named one by one in a step.
const NAMED_IN_A_STEP: usize = 4;

fn first_of(ids: &[SpaceId], i: usize, merged: usize) -> SpaceId {
    // The step began `merged - 1` non-door spaces back; count back over
    // the spaces (corridor merges never pass doors).
    ids[i + 1 - merged.max(1)]
}

fn cumulative_at(points: &[Point], seg: usize) -> f64 {
    points.windows(2).take(seg).map(|w| dist(w[0], w[1])).sum()
}

fn preposition(kind: Option<SpaceKind>) -> &'static str {
    match kind {
        Some(SpaceKind::Corridor) => "along",
        _ => "in",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn said(n: usize) -> String {
        let at: Vec<usize> = (0..n).collect();
        names(&at, &|i| format!("corridor {}", 1 + 5 * i))
    }

    #[test]
    fn a_step_names_a_few_spaces_and_counts_many() {
        assert_eq!(said(1), "corridor 1");
        assert_eq!(said(2), "corridor 1 and corridor 6");
        assert_eq!(
            said(4),
            "corridor 1, corridor 6, corridor 11 and corridor 16"
        );
        assert_eq!(
            said(20),
            "corridor 1, corridor 6, … and corridor 96 (20 spaces)"
        );
    }
}
