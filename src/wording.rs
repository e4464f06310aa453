//! Wording of reports: counts with their noun in the right number
//! ("1 corridor", "2 corridors"). Used by every report that prints counts.

/// `n` followed by `singular` when `n` is 1, else `plural`.
///
/// ```
/// use nrgdb::wording::count;
/// assert_eq!(count(1, "corridor", "corridors"), "1 corridor");
/// assert_eq!(count(0, "corridor", "corridors"), "0 corridors");
/// ```
pub fn count(n: usize, singular: &str, plural: &str) -> String {
    format!("{n} {}", if n == 1 { singular } else { plural })
}
