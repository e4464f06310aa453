//! What the store refuses before any engine sees it: map names it cannot
//! use and revision texts too long to keep.

use super::{ImportMeta, StoreError};

/// Longest revision message kept, in characters (issue 21: a 20 MB
/// upload message was stored and sent back in every revisions listing).
pub const MAX_MESSAGE_CHARS: usize = 4_096;

/// Longest author or source file name kept, in characters.
const MAX_LABEL_CHARS: usize = 256;

pub(crate) fn check_meta(meta: &ImportMeta) -> Result<(), StoreError> {
    let fields = [
        ("message", Some(meta.message.as_str()), MAX_MESSAGE_CHARS),
        ("author", Some(meta.author.as_str()), MAX_LABEL_CHARS),
        ("source", meta.source_name.as_deref(), MAX_LABEL_CHARS),
    ];
    for (field, text, limit) in fields {
        let chars = text.map_or(0, |t| t.chars().count());
        if chars > limit {
            return Err(StoreError::TooLong {
                field,
                chars,
                limit,
            });
        }
    }
    Ok(())
}

pub(crate) fn check_map_name(name: &str) -> Result<(), StoreError> {
    let reason = if name.trim().is_empty() {
        Some("it is empty")
    } else if name.contains('@') {
        Some("'@' separates a map from a revision (NAME@REV); choose another name")
    } else if name.chars().any(char::is_control) {
        Some("it contains control characters")
    } else if name.len() > 200 {
        Some("it is longer than 200 bytes")
    } else {
        None
    };
    match reason {
        Some(reason) => Err(StoreError::BadMapName {
            name: name.to_string(),
            reason,
        }),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 21, defect 6: a 20 MB message was stored and returned in
    /// every revisions listing; now it is refused, naming the field.
    #[test]
    fn long_messages_are_refused() {
        let mut meta = ImportMeta::new("x".repeat(MAX_MESSAGE_CHARS), "me");
        assert!(check_meta(&meta).is_ok());
        meta.message.push('y');
        let e = check_meta(&meta).unwrap_err().to_string();
        assert!(e.contains("message has 4097 characters"), "{e}");
        let meta = ImportMeta::new("ok", "a".repeat(300));
        assert!(matches!(
            check_meta(&meta),
            Err(StoreError::TooLong {
                field: "author",
                ..
            })
        ));
    }

    #[test]
    fn map_names_are_checked() {
        assert!(check_map_name("willow").is_ok());
        for bad in ["", "  ", "a@b", "x\ny"] {
            assert!(check_map_name(bad).is_err(), "{bad:?}");
        }
    }
}
