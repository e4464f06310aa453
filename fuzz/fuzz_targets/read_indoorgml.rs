//! Fuzzes the IndoorGML reader: any bytes must give a document or an
//! error, never a panic; a document read must survive export and re-import.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    if let Ok(doc) = nrgdb::indoorgml::read_str(text) {
        let _ = nrgdb::indoorgml::check(&doc);
        let _ = nrgdb::indoorgml::to_nrg(&doc);
        let written = nrgdb::indoorgml::write_string(&doc);
        assert!(nrgdb::indoorgml::read_str(&written).is_ok(), "re-import of an export failed");
    }
});
