//! The reader never panics: random edits of a valid document give a
//! document or an error, and whatever is read survives export and re-import.
//! (The same property drives the libFuzzer target in `fuzz/`.)

use nrgdb::indoorgml::{check, from_nrg, read_str, to_nrg, write_string};
use proptest::prelude::*;

use crate::support::building;

fn exercise(text: &str) {
    if let Ok(doc) = read_str(text) {
        let _ = check(&doc);
        let _ = to_nrg(&doc);
        let written = write_string(&doc);
        assert!(read_str(&written).is_ok(), "re-import of an export failed");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]
    #[test]
    fn random_edits_never_panic(
        edits in proptest::collection::vec((any::<prop::sample::Index>(), 0usize..40, "[<>/=\"#a-zA-Z0-9 :.-]{0,12}"), 1..6)
    ) {
        let mut text = write_string(&from_nrg(&building(2)));
        for (at, cut, insert) in edits {
            let mut start = at.index(text.len());
            while !text.is_char_boundary(start) { start -= 1; }
            let mut end = (start + cut).min(text.len());
            while !text.is_char_boundary(end) { end -= 1; }
            text.replace_range(start..end, &insert);
        }
        exercise(&text);
    }

    #[test]
    fn arbitrary_text_never_panics(text in "\\PC{0,300}") {
        exercise(&text);
    }
}
