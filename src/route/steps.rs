//! Readable steps of a route: "leave Kitchen through door 7 into corridor 3".

use crate::model::{Nrg, SpaceId, SpaceKind};

/// Describes a path of spaces as sentences, one per change of non-door
/// space, ending with "arrive at …". Doors are folded into the step that
/// passes them, and a run of corridor segments into one step.
///
/// ```
/// use nrgdb::query::demo;
/// use nrgdb::route::describe_steps;
/// let nrg = demo::building(2);
/// let path: Vec<_> = nrg.spaces().iter().take(1).map(|s| s.id).collect();
/// assert_eq!(describe_steps(&nrg, &path), vec![format!("you are at {}", nrg.spaces()[0].label())]);
/// ```
pub fn describe_steps(nrg: &Nrg, path: &[SpaceId]) -> Vec<String> {
    let label = |id: &SpaceId| {
        nrg.space(*id)
            .map_or_else(|| format!("space {id}"), |s| s.label())
    };
    let kind = |id: &SpaceId| nrg.space(*id).map(|s| s.kind);
    let mut steps = Vec::new();
    if path.len() == 1 {
        steps.push(format!("you are at {}", label(&path[0])));
        return steps;
    }
    let mut i = 0;
    while i + 1 < path.len() {
        let from = &path[i];
        let mut j = i + 1;
        let mut doors = Vec::new();
        while j + 1 < path.len() && kind(&path[j]) == Some(SpaceKind::Door) {
            doors.push(label(&path[j]));
            j += 1;
        }
        // A run of corridor segments joined without doors is one step.
        let mut segments = 1;
        if doors.is_empty() && kind(from) == Some(SpaceKind::Corridor) {
            while j + 1 < path.len()
                && kind(&path[j]) == Some(SpaceKind::Corridor)
                && kind(&path[j + 1]) == Some(SpaceKind::Corridor)
            {
                j += 1;
                segments += 1;
            }
        }
        let into = &path[j];
        let verb = if i == 0 { "leave" } else { "go from" };
        let step = if segments > 1 {
            format!(
                "{verb} {} along the corridor to {} ({} segments)",
                label(from),
                label(into),
                segments + 1
            )
        } else if doors.is_empty() {
            format!("{verb} {} into {}", label(from), label(into))
        } else {
            format!(
                "{verb} {} through {} into {}",
                label(from),
                doors.join(" and "),
                label(into)
            )
        };
        steps.push(step);
        i = j;
    }
    if let Some(last) = path.last() {
        steps.push(format!("arrive at {}", label(last)));
    }
    steps
}
