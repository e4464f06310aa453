//! `nrgdb import RECORDING`: a ROS 2 recording (MCAP, `.db3` bag or bag
//! folder) stored as one revision per map that changed.

use std::io::Write;
use std::path::Path;
use std::process::ExitCode;

use miette::{IntoDiagnostic, WrapErr};
use nrgdb::format::{Declared, FileKind, detect};
use nrgdb::ingest::{IngestOptions, StoredMap, import_recording};
use nrgdb::recording::{Recording, RecordingOptions};

use super::db::author;
use super::import::Args;

/// Whether `path` is to be read as a recording: a folder (a bag), or a
/// file whose name or first bytes say recording.
pub(super) fn is_recording(path: &Path) -> bool {
    if path.is_dir() {
        return true;
    }
    let name = path.to_string_lossy();
    if matches!(FileKind::by_extension(&name), Some(FileKind::Recording(_))) {
        return true;
    }
    let mut head = [0u8; 16];
    let n = std::fs::File::open(path)
        .and_then(|mut f| std::io::Read::read(&mut f, &mut head))
        .unwrap_or(0);
    matches!(
        detect(&Declared::default(), &head[..n]),
        Ok(FileKind::Recording(_))
    )
}

/// Runs `nrgdb import` on a recording.
pub(super) fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let recording = Recording::open(&args.file).into_diagnostic()?;
    let options = RecordingOptions {
        topic: args.topic.clone(),
        every: args.every,
        ..RecordingOptions::default()
    };
    let ingest_options = IngestOptions {
        allow_invalid: args.allow_invalid,
        ..IngestOptions::default()
    };
    let meta = nrgdb::store::ImportMeta::new(args.message.clone(), author(args.author.clone()));
    let mut store = args.db.open()?;
    let spinner = super::progress::spinner(format!("reading {}", args.file.display()));
    let mut lines = Vec::new();
    let done = import_recording(
        &mut store,
        &args.map,
        &recording,
        &options,
        &ingest_options,
        &meta,
        |m| {
            spinner.set_message(format!("stored map message {} ({})", m.index, m.time));
            lines.push(describe(m));
        },
    );
    spinner.finish_and_clear();
    for line in &lines {
        writeln!(out, "{line}").into_diagnostic()?;
    }
    let done = done
        .into_diagnostic()
        .wrap_err_with(|| format!("importing {} into map '{}'", args.file.display(), args.map))?;
    for (index, time, why) in &done.unusable {
        writeln!(out, "map message {index} ({time}) left out: {why}").into_diagnostic()?;
    }
    let written = done.revisions().count();
    let unchanged = done.maps.len() - written;
    writeln!(
        out,
        "{}: {} on {} ({} read): {} stored{}{}{}{}{}",
        done.recording,
        nrgdb::wording::count(done.messages, "map message", "map messages"),
        done.topic,
        size(done.bytes_read),
        nrgdb::wording::count(written, "revision", "revisions"),
        skipped(done.identical, "identical to the map before"),
        skipped(done.thinned, "left out by --every"),
        skipped(unchanged, "gave the latest model again"),
        skipped(done.already_stored, "stored already"),
        skipped(done.unusable.len(), "could not be extracted"),
    )
    .into_diagnostic()?;
    if written == 0 && !done.unusable.is_empty() {
        return Err(miette::miette!(
            "no map of {} could be made into a model; nothing was stored",
            done.recording
        ));
    }
    Ok(ExitCode::SUCCESS)
}

fn size(bytes: u64) -> String {
    if bytes < 1_000_000 {
        format!("{:.0} kB", bytes as f64 / 1e3)
    } else {
        format!("{:.1} MB", bytes as f64 / 1e6)
    }
}

fn skipped(n: usize, why: &str) -> String {
    if n == 0 {
        String::new()
    } else {
        format!(", {n} {why}")
    }
}

fn describe(m: &StoredMap) -> String {
    let r = &m.ingested.imported.revision;
    if m.ingested.imported.unchanged {
        return format!(
            "map message {} ({}): nothing changed from {}@{}",
            m.index, m.time, r.map, r.seq
        );
    }
    format!(
        "{}@{} (map message {}, {}): {} spaces ({} new, {} changed, {} gone), {} connections",
        r.map,
        r.seq,
        m.index,
        m.time,
        r.spaces,
        r.spaces_added,
        r.spaces_changed,
        r.spaces_removed,
        r.connections
    )
}
