//! A change set as readable rows and an aligned text table.

use std::fmt::Write as _;

use super::change_set::{ChangeSet, ConnectionChangeKind, SpaceChangeKind};
use crate::model::Connection;

/// One line of a change report.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ChangeRow {
    /// What changed: `added`, `removed`, `resized`, `split`, `merged`,
    /// `rekinded`, `renamed`, `door_width`, `link_added`, `link_removed`,
    /// `link_rekinded`.
    pub change: String,
    /// Ids in A (`-` when none; `a-b` for connections).
    pub old: String,
    /// Ids in B.
    pub new: String,
    /// The space's label.
    pub space: String,
    /// Before → after.
    pub detail: String,
    /// The level (`0`, or `0-1` for a vertical connection), in a
    /// building with levels; empty otherwise.
    pub level: String,
}

fn ids(list: &[crate::model::SpaceId]) -> String {
    let v: Vec<String> = list.iter().map(ToString::to_string).collect();
    v.join(",")
}

fn link(c: Option<&Connection>) -> String {
    c.map_or_else(|| "-".to_string(), |c| format!("{}-{}", c.a, c.b))
}

impl ChangeSet {
    /// The reported changes, one row each: spaces first (by old id), then
    /// splits, merges and connections. Unchanged spaces and length-only
    /// connection changes are left out.
    pub fn rows(&self) -> Vec<ChangeRow> {
        let mut rows = Vec::new();
        let opt = |id: Option<crate::model::SpaceId>| id.map_or("-".to_string(), |i| i.to_string());
        for s in self.changed_spaces() {
            for c in &s.changes {
                let detail = match c {
                    SpaceChangeKind::Added => {
                        format!("{}, {:.1} m²", s.kind, s.new_area_m2.unwrap_or(0.0))
                    }
                    SpaceChangeKind::Removed => {
                        format!("{}, {:.1} m²", s.kind, s.old_area_m2.unwrap_or(0.0))
                    }
                    SpaceChangeKind::Resized => {
                        let (a, b) = (s.old_area_m2.unwrap_or(0.0), s.new_area_m2.unwrap_or(0.0));
                        let pct = if a > 0.0 { 100.0 * (b - a) / a } else { 0.0 };
                        format!("{a:.1} → {b:.1} m² ({pct:+.0}%)")
                    }
                    // Described by the split and merge rows below.
                    SpaceChangeKind::Split | SpaceChangeKind::Merged => continue,
                    SpaceChangeKind::Rekinded => {
                        format!("{} → {}", s.kind, s.new_kind.unwrap_or(s.kind))
                    }
                    SpaceChangeKind::Renamed => {
                        let [a, b] = s.names.clone().unwrap_or([None, None]);
                        let q = |n: Option<String>| {
                            n.map_or("(none)".to_string(), |n| format!("\"{n}\""))
                        };
                        format!("{} → {}", q(a), q(b))
                    }
                    SpaceChangeKind::DoorWidth => {
                        let [a, b] = s.door_width_m.unwrap_or([0.0, 0.0]);
                        format!("{a:.2} → {b:.2} m")
                    }
                };
                rows.push(ChangeRow {
                    change: c.as_str().to_string(),
                    old: opt(s.old),
                    new: opt(s.new),
                    space: s.label.clone(),
                    detail,
                    level: s.level.clone().unwrap_or_default(),
                });
            }
        }
        let entry_new = |id| self.spaces.iter().find(|s| s.new == Some(id));
        let entry_old = |id| self.spaces.iter().find(|s| s.old == Some(id));
        let label = |e: Option<&super::change_set::SpaceChange>| {
            e.map_or_else(String::new, |s| s.label.clone())
        };
        let level = |e: Option<&super::change_set::SpaceChange>| {
            e.and_then(|s| s.level.clone()).unwrap_or_default()
        };
        for sp in &self.splits {
            let parts: Vec<String> = sp
                .parts
                .iter()
                .map(|p| format!("{} ({:.0}%)", p.id, 100.0 * p.share))
                .collect();
            let new: Vec<_> = sp.parts.iter().map(|p| p.id).collect();
            rows.push(ChangeRow {
                change: "split".into(),
                old: sp.old.to_string(),
                new: ids(&new),
                space: label(entry_old(sp.old)),
                detail: format!("into {}", parts.join(", ")),
                level: level(entry_old(sp.old)),
            });
        }
        for m in &self.merges {
            let parts: Vec<String> = m
                .parts
                .iter()
                .map(|p| format!("{} ({:.0}%)", p.id, 100.0 * p.share))
                .collect();
            let old: Vec<_> = m.parts.iter().map(|p| p.id).collect();
            rows.push(ChangeRow {
                change: "merged".into(),
                old: ids(&old),
                new: m.new.to_string(),
                space: label(entry_new(m.new)),
                detail: format!("from {}", parts.join(", ")),
                level: level(entry_new(m.new)),
            });
        }
        for c in self.changed_connections() {
            let (ka, kb) = c.kinds();
            let detail = match c.change {
                ConnectionChangeKind::Rekinded => format!(
                    "{} → {}",
                    ka.map_or("-", |k| k.as_str()),
                    kb.map_or("-", |k| k.as_str())
                ),
                _ => ka.or(kb).map_or("", |k| k.as_str()).to_string(),
            };
            rows.push(ChangeRow {
                change: format!("link_{}", c.change.as_str()),
                old: link(c.old.as_ref()),
                new: link(c.new.as_ref()),
                space: String::new(),
                detail,
                level: c.levels.join("-"),
            });
        }
        rows
    }

    /// A one-line summary, e.g. `120 unchanged, 1 added, 1 removed, …`.
    pub fn summary_line(&self) -> String {
        let s = &self.summary;
        let mut parts = vec![format!("{} unchanged", s.unchanged)];
        for (n, what) in [
            (s.added, "added"),
            (s.removed, "removed"),
            (s.resized, "resized"),
            (s.split, "split"),
            (s.merged, "merged"),
            (s.rekinded, "rekinded"),
            (s.renamed, "renamed"),
            (s.door_width, "door width changed"),
            (s.connections_added, "connections added"),
            (s.connections_removed, "connections removed"),
            (s.connections_rekinded, "connections rekinded"),
        ] {
            if n > 0 {
                parts.push(format!("{n} {what}"));
            }
        }
        parts.join(", ")
    }

    /// The report as an aligned text table ending with the summary line;
    /// `no changes (N unchanged)` when nothing is reported.
    pub fn table(&self) -> String {
        let mut out = String::new();
        if let Some(t) = &self.alignment {
            let _ = writeln!(
                out,
                "aligned: rotation {:.2}°, translation ({:.3}, {:.3}) m",
                t.rotation_deg(),
                t.tx_m,
                t.ty_m
            );
        }
        let rows = self.rows();
        if rows.is_empty() {
            let _ = writeln!(out, "no changes ({} unchanged)", self.summary.unchanged);
            return out;
        }
        let leveled = rows.iter().any(|r| !r.level.is_empty());
        let header = ["change", "level", "old", "new", "space", "detail"];
        let cells: Vec<[&str; 6]> = rows
            .iter()
            .map(|r| {
                [
                    &*r.change, &*r.level, &*r.old, &*r.new, &*r.space, &*r.detail,
                ]
            })
            .collect();
        let mut widths = header.map(|h| h.chars().count());
        for row in &cells {
            for (w, c) in widths.iter_mut().zip(row) {
                *w = (*w).max(c.chars().count());
            }
        }
        // The level column only in a building with levels.
        let mut line = |cols: [&str; 6]| {
            let parts: Vec<String> = cols
                .iter()
                .zip(widths)
                .enumerate()
                .filter(|(k, _)| leveled || *k != 1)
                .map(|(_, (c, w))| format!("{c:<w$}"))
                .collect();
            let _ = writeln!(out, "{}", parts.join("  ").trim_end());
        };
        line(header);
        let rules = widths.map(|w| "-".repeat(w));
        line([
            &rules[0], &rules[1], &rules[2], &rules[3], &rules[4], &rules[5],
        ]);
        for row in cells {
            line(row);
        }
        let _ = writeln!(out, "{}", self.summary_line());
        let levels = self.changed_levels();
        if !levels.is_empty() {
            let _ = writeln!(out, "changed levels: {}", levels.join(", "));
        }
        out
    }
}
