//! Golden query files: every `queries/*.nrgq` is run and its `# @expect:`
//! blocks compared. `NRGDB_BLESS=1` rewrites them (review the diff).
//!
//! File format: lines starting with `#` are comments, except
//! `# @model: demo N` (first, required: the built-in demo building with N
//! corridor segments, as map `demo`) and `# @expect:` blocks. A statement
//! ends with a line ending in `;`; the block after it holds the table
//! rendering, each line prefixed with `# `, and ends at the first line not
//! starting with `#` (separate the next query's comments with a blank line).

use std::path::Path;

use nrgdb::query::{Format, MemorySource, Session, demo};

fn session_for(text: &str, path: &Path) -> Session<MemorySource> {
    let directive = text
        .lines()
        .find_map(|l| l.strip_prefix("# @model:"))
        .unwrap_or_else(|| panic!("{}: missing '# @model: demo N'", path.display()));
    let mut words = directive.split_whitespace();
    assert_eq!(
        words.next(),
        Some("demo"),
        "{}: only 'demo N' models exist",
        path.display()
    );
    let n: usize = words.next().and_then(|w| w.parse().ok()).expect("demo N");
    let mut source = MemorySource::new();
    source.insert_with_note("demo", demo::building(n), "built-in demo building");
    Session::with_default_map(source).unwrap()
}

/// Runs a golden file and returns it with fresh `# @expect:` blocks.
pub fn render(text: &str, path: &Path) -> String {
    let mut session = session_for(text, path);
    let lines: Vec<&str> = text.lines().collect();
    let mut out = String::new();
    let mut pending = String::new();
    let mut i = 0;
    while i < lines.len() {
        let line = lines[i];
        i += 1;
        if line.starts_with("# @expect:") {
            // A stale block with no statement before it: drop it.
            while i < lines.len() && lines[i].starts_with('#') {
                i += 1;
            }
            continue;
        }
        out.push_str(line);
        out.push('\n');
        if line.starts_with('#') || line.trim().is_empty() && pending.is_empty() {
            continue;
        }
        pending.push_str(line);
        pending.push('\n');
        if !line.trim_end().ends_with(';') {
            continue;
        }
        let answer = match session.run(&pending, Format::Table) {
            Ok(a) => a,
            Err(e) => format!("error: {e}\n"),
        };
        pending.clear();
        out.push_str("# @expect:\n");
        for l in answer.lines() {
            if l.is_empty() {
                out.push_str("#\n");
            } else {
                out.push_str(&format!("# {l}\n"));
            }
        }
        if i < lines.len() && lines[i].starts_with("# @expect:") {
            i += 1;
            while i < lines.len() && lines[i].starts_with('#') {
                i += 1;
            }
        }
    }
    out
}

#[test]
fn golden_queries() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("queries");
    let mut paths: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "nrgq"))
        .collect();
    paths.sort();
    assert!(!paths.is_empty(), "no golden files in {}", dir.display());
    for path in paths {
        let text = std::fs::read_to_string(&path).unwrap();
        let got = render(&text, &path);
        if std::env::var_os("NRGDB_BLESS").is_some() {
            std::fs::write(&path, &got).unwrap();
        } else {
            assert_eq!(
                text,
                got,
                "{}: run with NRGDB_BLESS=1 to update",
                path.display()
            );
        }
    }
}
