//! Query results and their renderings: an aligned table, JSON or CSV.

use std::fmt::Write as _;

use serde::Serialize;
use serde_json::json;

use crate::route::Route;

/// One cell of a table.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Cell {
    /// Empty.
    Null,
    /// A whole number.
    Int(i64),
    /// A measurement (printed with 2 decimals in tables and CSV).
    Float(f64),
    /// Text.
    Text(String),
}

impl Cell {
    fn text(&self) -> String {
        match self {
            Cell::Null => String::new(),
            Cell::Int(i) => i.to_string(),
            Cell::Float(x) => format!("{x:.2}"),
            Cell::Text(s) => s.clone(),
        }
    }
}

/// Columns and rows.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Table {
    /// Column names.
    pub columns: Vec<String>,
    /// Rows, each as long as `columns`.
    pub rows: Vec<Vec<Cell>>,
}

/// The answer to one statement.
#[derive(Debug, Clone, PartialEq)]
pub enum QueryResult {
    /// A table (FIND, NEIGHBOURS, REACHABLE, LOCATE, SHOW …).
    Table(Table),
    /// Routes, shortest first; empty means "no route".
    Routes(Vec<Route>),
    /// A message (USE, NAME).
    Message(String),
    /// The plan of an EXPLAIN.
    Plan(String),
}

/// How to render results.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Format {
    /// Aligned plain-text table.
    #[default]
    Table,
    /// One JSON document per statement.
    Json,
    /// CSV with a header row.
    Csv,
}

impl QueryResult {
    /// Renders the result; the text ends with a newline.
    pub fn render(&self, format: Format) -> String {
        match format {
            Format::Table => self.render_table(),
            Format::Json => self.render_json(),
            Format::Csv => self.render_csv(),
        }
    }

    /// Rows of a result (routes count one row per route; messages none).
    pub fn row_count(&self) -> usize {
        match self {
            QueryResult::Table(t) => t.rows.len(),
            QueryResult::Routes(r) => r.len(),
            _ => 0,
        }
    }

    fn route_table(route: &Route) -> Table {
        Table {
            columns: ["point", "x_m", "y_m"].map(String::from).to_vec(),
            rows: route
                .waypoints
                .iter()
                .enumerate()
                .map(|(i, p)| {
                    vec![
                        Cell::Int(i as i64 + 1),
                        Cell::Float(p[0]),
                        Cell::Float(p[1]),
                    ]
                })
                .collect(),
        }
    }

    fn render_table(&self) -> String {
        match self {
            QueryResult::Table(t) => aligned(t),
            QueryResult::Message(m) | QueryResult::Plan(m) => format!("{}\n", m.trim_end()),
            QueryResult::Routes(routes) if routes.is_empty() => "no route\n".into(),
            QueryResult::Routes(routes) => {
                let mut out = String::new();
                for (i, r) in routes.iter().enumerate() {
                    let doors: Vec<String> = r.doors.iter().map(ToString::to_string).collect();
                    let _ = writeln!(
                        out,
                        "route {}: {:.2} m walked ({:.0} s), {}, doors [{}]",
                        i + 1,
                        r.length_m,
                        r.duration_s,
                        crate::wording::count(r.spaces.len(), "space", "spaces"),
                        doors.join(", ")
                    );
                    for step in &r.steps {
                        let _ = writeln!(out, "  {step}");
                    }
                    for line in aligned(&Self::route_table(r)).lines() {
                        let _ = writeln!(out, "  {line}");
                    }
                }
                out
            }
        }
    }

    fn render_json(&self) -> String {
        let value = match self {
            QueryResult::Table(t) => json!({"columns": t.columns, "rows": t.rows}),
            QueryResult::Routes(r) => json!({"routes": r}),
            QueryResult::Message(m) => json!({"message": m}),
            QueryResult::Plan(p) => json!({"plan": p}),
        };
        format!("{value}\n")
    }

    fn render_csv(&self) -> String {
        match self {
            QueryResult::Table(t) => csv(t),
            QueryResult::Message(m) | QueryResult::Plan(m) => {
                let t = Table {
                    columns: vec!["message".into()],
                    rows: m.lines().map(|l| vec![Cell::Text(l.into())]).collect(),
                };
                csv(&t)
            }
            QueryResult::Routes(routes) => {
                let mut t = Table {
                    columns: ["route", "length_m", "point", "x_m", "y_m"]
                        .map(String::from)
                        .to_vec(),
                    rows: Vec::new(),
                };
                for (i, r) in routes.iter().enumerate() {
                    for row in Self::route_table(r).rows {
                        let mut full = vec![Cell::Int(i as i64 + 1), Cell::Float(r.length_m)];
                        full.extend(row);
                        t.rows.push(full);
                    }
                }
                csv(&t)
            }
        }
    }
}

/// An aligned table: text left, numbers right, `(N rows)` at the end.
fn aligned(t: &Table) -> String {
    let cells: Vec<Vec<String>> = t
        .rows
        .iter()
        .map(|r| r.iter().map(Cell::text).collect())
        .collect();
    let mut widths: Vec<usize> = t.columns.iter().map(|c| c.chars().count()).collect();
    for row in &cells {
        for (w, c) in widths.iter_mut().zip(row) {
            *w = (*w).max(c.chars().count());
        }
    }
    let mut out = String::new();
    let line = |out: &mut String, cols: Vec<(String, bool)>| {
        let parts: Vec<String> = cols
            .into_iter()
            .zip(&widths)
            .map(|((c, right), w)| {
                // Padded by hand: `format!("{c:<w$}")` panics past a width
                // of 65 535 (a 70 000-character name broke every listing).
                let pad = " ".repeat(w.saturating_sub(c.chars().count()));
                if right { pad + &c } else { c + &pad }
            })
            .collect();
        let _ = writeln!(out, "{}", parts.join("  ").trim_end());
    };
    line(
        &mut out,
        t.columns.iter().map(|c| (c.clone(), false)).collect(),
    );
    line(
        &mut out,
        widths.iter().map(|w| ("-".repeat(*w), false)).collect(),
    );
    for (row, texts) in t.rows.iter().zip(cells) {
        let cols = row
            .iter()
            .zip(texts)
            .map(|(c, s)| (s, matches!(c, Cell::Int(_) | Cell::Float(_))))
            .collect();
        line(&mut out, cols);
    }
    let n = t.rows.len();
    let _ = writeln!(out, "({n} row{})", if n == 1 { "" } else { "s" });
    out
}

fn csv(t: &Table) -> String {
    let field = |s: &str| {
        if s.contains([',', '"', '\n']) {
            format!("\"{}\"", s.replace('"', "\"\""))
        } else {
            s.to_string()
        }
    };
    let mut out = String::new();
    let header: Vec<String> = t.columns.iter().map(|c| field(c)).collect();
    let _ = writeln!(out, "{}", header.join(","));
    for row in &t.rows {
        let cells: Vec<String> = row.iter().map(|c| field(&c.text())).collect();
        let _ = writeln!(out, "{}", cells.join(","));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_and_csv() {
        let t = QueryResult::Table(Table {
            columns: vec!["id".into(), "name".into()],
            rows: vec![vec![Cell::Int(3), Cell::Text("a, \"b\"".into())]],
        });
        assert_eq!(
            t.render(Format::Table),
            "id  name\n--  ------\n 3  a, \"b\"\n(1 row)\n"
        );
        assert_eq!(t.render(Format::Csv), "id,name\n3,\"a, \"\"b\"\"\"\n");
        assert_eq!(
            QueryResult::Routes(vec![]).render(Format::Table),
            "no route\n"
        );
    }
}
