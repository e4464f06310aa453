//! Why there is no route: the request is retried with its constraints
//! relaxed one at a time, and the first that makes a route names the cause.

use super::route_avoiding::route_avoiding;
use super::{Budget, Endpoint, NavMesh, Profile, RouteRequest};

/// A sentence saying why `request` has no route ("every doorway into
/// Office 27 is narrower than 0.9 m"). Call it when a route came back
/// empty.
pub fn no_route_reason(nav: &NavMesh, request: &RouteRequest) -> String {
    let label = |e: &Endpoint| match e {
        Endpoint::Space(id) => nav
            .nrg()
            .space(*id)
            .map_or_else(|| format!("space {id}"), |s| s.label()),
        Endpoint::Point(p) | Endpoint::PointIn(p, _) => format!("({:.2}, {:.2})", p[0], p[1]),
    };
    let (from, to) = (label(&request.from), label(&request.to));
    let budget = Budget::new(std::time::Duration::from_secs(2));
    let found = |profile: Profile, avoid: bool| {
        let mut r = request.clone();
        r.profile = profile;
        r.alternatives = 1;
        let avoid = if avoid {
            request.avoid.clone()
        } else {
            Vec::new()
        };
        matches!(route_avoiding(nav, &r, &avoid, &budget), Ok(Some(_)))
    };
    let p = request.profile;
    let loose = Profile {
        clearance_m: 0.0,
        min_door_width_m: 0.0,
        ..p
    };
    // Between levels: the connectors the profile refuses.
    if (p.no_stairs || p.no_elevator)
        && !found(loose, false)
        && found(
            Profile {
                no_stairs: false,
                no_elevator: false,
                ..loose
            },
            false,
        )
    {
        let refused = match (p.no_stairs, p.no_elevator) {
            (true, true) => "without stairs or lifts",
            (true, false) => "without stairs (no lift serves both levels)",
            _ => "without a lift (no stairs lead there)",
        };
        return format!("no route: {from} and {to} are on levels not joined {refused}");
    }
    if !found(loose, false) {
        return format!("no route: {from} and {to} are not connected by any door or opening");
    }
    if !found(loose, true) {
        return format!("no route: every way from {from} to {to} passes a space in AVOID");
    }
    if p.min_door_width_m > 0.0
        && found(
            Profile {
                min_door_width_m: 0.0,
                ..p
            },
            true,
        )
    {
        let w = p.min_door_width_m;
        if let Some(sentence) = narrow_doors_around(nav, &request.to, w)
            .or_else(|| narrow_doors_around(nav, &request.from, w))
        {
            return sentence;
        }
        return format!(
            "no route: every way from {from} to {to} passes a door narrower than {w} m"
        );
    }
    format!(
        "no route: every way from {from} to {to} passes an opening narrower than {:.2} m (clearance {} m on each side)",
        2.0 * p.clearance_m,
        p.clearance_m
    )
}

/// "every doorway into X is narrower than w m" when all doors of X are.
fn narrow_doors_around(nav: &NavMesh, end: &Endpoint, w: f64) -> Option<String> {
    let id = match end {
        Endpoint::Space(id) => *id,
        Endpoint::Point(p) => nav.locate(*p)?,
        Endpoint::PointIn(_, id) => *id,
    };
    let nrg = nav.nrg();
    let doors: Vec<_> = nrg
        .connections_of(id)
        .filter(|c| c.kind.is_navigable())
        .filter_map(|c| c.other(id))
        .filter_map(|d| nrg.space(d))
        .filter(|d| d.kind == crate::model::SpaceKind::Door)
        .collect();
    let widths: Vec<f64> = doors.iter().map(|d| nav.door_width(d.id)).collect();
    let all_doors = nrg
        .connections_of(id)
        .filter(|c| c.kind.is_navigable())
        .count()
        == doors.len();
    (all_doors && !doors.is_empty() && widths.iter().all(|x| *x < w)).then(|| {
        let label = nrg.space(id).map_or_else(|| format!("space {id}"), |s| s.label());
        let widest = widths.iter().copied().fold(0.0, f64::max);
        format!(
            "no route: every doorway into {label} is narrower than {w} m (the widest is {widest:.2} m)"
        )
    })
}
