//! Reference integrity: unique ids, hrefs that resolve to the right kind
//! of element, duality both ways, `connects` both ways, inter-layer
//! connections, and thick/thin doors not mixed.

use std::collections::HashMap;

use super::super::document::{BoundaryClass, CellClass, Document, Target};
use super::{Finding, finding};

pub fn check_ids(doc: &Document, out: &mut Vec<Finding>) {
    let mut all: Vec<(&str, usize)> = Vec::new();
    all.extend(
        doc.cells()
            .iter()
            .map(|c| (c.info.id.as_str(), c.info.line)),
    );
    all.extend(
        doc.boundaries()
            .iter()
            .map(|b| (b.info.id.as_str(), b.info.line)),
    );
    for l in doc.layers() {
        all.push((l.info.id.as_str(), l.info.line));
        all.extend(l.states.iter().map(|s| (s.info.id.as_str(), s.info.line)));
        all.extend(
            l.transitions
                .iter()
                .map(|t| (t.info.id.as_str(), t.info.line)),
        );
    }
    let mut seen: HashMap<&str, usize> = HashMap::new();
    for (id, line) in all {
        if let Some(first) = seen.insert(id, line) {
            out.push(finding(
                "duplicate-id",
                id,
                line,
                format!("gml:id '{id}' is also used at line {first}"),
            ));
        }
    }
}

fn describe(t: Option<&Target>) -> &'static str {
    match t {
        None => "nothing (dangling)",
        Some(Target::Cell(_)) => "a cell",
        Some(Target::Boundary(_)) => "a boundary",
        Some(Target::State(..)) => "a State",
        Some(Target::Transition(..)) => "a Transition",
        Some(Target::Layer(_)) => "a SpaceLayer",
    }
}

pub fn check_references(doc: &Document, out: &mut Vec<Finding>) {
    let index = doc.index();
    let layers = doc.layers();
    let bad =
        |out: &mut Vec<Finding>, id: &str, line: usize, what: &str, href: &str, want: &str| {
            let got = index.get(href);
            let code = if got.is_none() {
                "dangling-href"
            } else {
                "wrong-target"
            };
            out.push(finding(
                code,
                id,
                line,
                format!("{what} → '{href}' names {}, expected {want}", describe(got)),
            ));
        };
    for c in doc.cells() {
        let (id, line) = (c.info.id.as_str(), c.info.line);
        if let Some(d) = &c.duality {
            match index.get(d.as_str()) {
                Some(Target::State(l, s)) => {
                    let back = layers
                        .get(*l)
                        .and_then(|l| l.states.get(*s))
                        .and_then(|s| s.duality.as_deref());
                    not_mutual(out, id, line, "State", d, back);
                }
                _ => bad(out, id, line, "duality", d, "a State"),
            }
        }
        for b in &c.bounded_by {
            if !matches!(index.get(b.as_str()), Some(Target::Boundary(_))) {
                bad(out, id, line, "partialboundedBy", b, "a CellSpaceBoundary");
            }
        }
    }
    for b in doc.boundaries() {
        let (id, line) = (b.info.id.as_str(), b.info.line);
        if let Some(d) = &b.duality {
            match index.get(d.as_str()) {
                Some(Target::Transition(l, t)) => {
                    let back = layers
                        .get(*l)
                        .and_then(|l| l.transitions.get(*t))
                        .and_then(|t| t.duality.as_deref());
                    not_mutual(out, id, line, "Transition", d, back);
                }
                _ => bad(out, id, line, "duality", d, "a Transition"),
            }
        }
    }
    for layer in &layers {
        for s in &layer.states {
            let (id, line) = (s.info.id.as_str(), s.info.line);
            if let Some(d) = &s.duality
                && !matches!(index.get(d.as_str()), Some(Target::Cell(_)))
            {
                bad(out, id, line, "duality", d, "a cell");
            }
            for t in &s.connects {
                if !matches!(index.get(t.as_str()), Some(Target::Transition(..))) {
                    bad(out, id, line, "connects", t, "a Transition");
                }
            }
        }
        for t in &layer.transitions {
            let (id, line) = (t.info.id.as_str(), t.info.line);
            if t.connects.len() != 2 {
                out.push(finding(
                    "connects-count",
                    id,
                    line,
                    format!("has {} connects, expected 2", t.connects.len()),
                ));
            }
            for s in &t.connects {
                match index.get(s.as_str()) {
                    Some(Target::State(l, i)) => {
                        let listed = layers
                            .get(*l)
                            .and_then(|l| l.states.get(*i))
                            .is_some_and(|st| st.connects.iter().any(|c| c == id));
                        if !listed {
                            out.push(finding(
                                "connects-not-mutual",
                                id,
                                line,
                                format!("connects State '{s}', which does not list this Transition in its connects"),
                            ));
                        }
                    }
                    _ => bad(out, id, line, "connects", s, "a State"),
                }
            }
            if let Some(d) = &t.duality
                && !matches!(index.get(d.as_str()), Some(Target::Boundary(_)))
            {
                bad(out, id, line, "duality", d, "a CellSpaceBoundary");
            }
        }
    }
    for group in doc.graph.iter().flat_map(|g| &g.inter_edges) {
        for c in &group.connections {
            let (id, line) = (c.info.id.as_str(), c.info.line);
            let mut state_layers = Vec::new();
            for s in &c.inter_connects {
                match index.get(s.as_str()) {
                    Some(Target::State(l, _)) => state_layers.push(*l),
                    _ => bad(out, id, line, "interConnects", s, "a State"),
                }
            }
            if c.inter_connects.len() != 2 {
                out.push(finding(
                    "interconnects-count",
                    id,
                    line,
                    format!("has {} interConnects, expected 2", c.inter_connects.len()),
                ));
            } else if state_layers.len() == 2 && state_layers[0] == state_layers[1] {
                out.push(finding(
                    "same-layer",
                    id,
                    line,
                    "interConnects two States of the same SpaceLayer (OGC ETS Req 4)".into(),
                ));
            }
            for l in &c.connected_layers {
                if !matches!(index.get(l.as_str()), Some(Target::Layer(_))) {
                    bad(out, id, line, "ConnectedLayers", l, "a SpaceLayer");
                }
            }
        }
    }
}

/// Reports a duality whose target's duality does not name `id` back.
fn not_mutual(
    out: &mut Vec<Finding>,
    id: &str,
    line: usize,
    kind: &str,
    target: &str,
    back: Option<&str>,
) {
    if back != Some(id) {
        let back = back.map_or("absent".into(), |b| format!("'{b}'"));
        out.push(finding(
            "duality-not-mutual",
            id,
            line,
            format!("duality → {kind} '{target}', whose duality is {back}"),
        ));
    }
}

/// OGC ETS Req 5–7: thick doors (ConnectionSpace/AnchorSpace) and thin
/// doors (ConnectionBoundary/AnchorBoundary) never both present.
pub fn check_doors(doc: &Document, out: &mut Vec<Finding>) {
    let thick = doc
        .cells()
        .iter()
        .find(|c| matches!(c.class, CellClass::ConnectionSpace | CellClass::AnchorSpace));
    let thin = doc.boundaries().iter().find(|b| {
        matches!(
            b.class,
            BoundaryClass::ConnectionBoundary | BoundaryClass::AnchorBoundary
        )
    });
    if let (Some(a), Some(b)) = (thick, thin) {
        out.push(finding(
            "doors-mixed",
            &b.info.id,
            b.info.line,
            format!(
                "thin door {} {} while {} {} (line {}) is a thick door: use one door model (OGC ETS Req 5-7)",
                b.class.element_name(),
                b.info.id,
                a.class.element_name(),
                a.info.id,
                a.info.line
            ),
        ));
    }
}
