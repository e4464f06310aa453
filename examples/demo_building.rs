//! Writes the generated demo building (the one the query benches and golden
//! files use) as nrgdb model JSON, e.g. for the networkx peer comparison:
//! `cargo run --example demo_building -- 1875 /tmp/demo-10k.json`.

use std::path::PathBuf;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let columns: usize = args
        .next()
        .ok_or("usage: demo_building SEGMENTS OUT.json")?
        .parse()?;
    let out = PathBuf::from(
        args.next()
            .ok_or("usage: demo_building SEGMENTS OUT.json")?,
    );
    let nrg = nrgdb::query::demo::building(columns);
    nrgdb::atomic::write(&out, nrg.to_json().as_bytes())?;
    eprintln!("{} spaces -> {}", nrg.spaces().len(), out.display());
    Ok(())
}
