//! "Did you mean …?": the closest candidate by edit distance.

/// Optimal-string-alignment distance (Levenshtein plus adjacent
/// transpositions), case-insensitive.
///
/// ```
/// use nrgdb::query::edit_distance;
/// assert_eq!(edit_distance("ROUET", "route"), 1);
/// assert_eq!(edit_distance("Kitchn", "Kitchen"), 1);
/// ```
pub fn edit_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.to_lowercase().chars().collect();
    let b: Vec<char> = b.to_lowercase().chars().collect();
    let w = b.len() + 1;
    let mut d = vec![0usize; (a.len() + 1) * w];
    for i in 0..=a.len() {
        d[i * w] = i;
    }
    for (j, cell) in d.iter_mut().enumerate().take(w) {
        *cell = j;
    }
    for i in 1..=a.len() {
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            let mut v = (d[(i - 1) * w + j] + 1)
                .min(d[i * w + j - 1] + 1)
                .min(d[(i - 1) * w + j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                v = v.min(d[(i - 2) * w + j - 2] + 1);
            }
            d[i * w + j] = v;
        }
    }
    d[a.len() * w + b.len()]
}

/// The candidate closest to `word`, if it is close enough to be a typo
/// (distance at most 2, at most half the word's length rounded up, and
/// less than the word's length: 'x' suggests nothing).
///
/// ```
/// use nrgdb::query::suggest;
/// assert_eq!(suggest("ofice_g", ["office_g", "lab"]), Some("office_g"));
/// assert_eq!(suggest("x", ["a", "b"]), None);
/// ```
pub fn suggest<'a>(word: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let len = word.chars().count();
    let limit = 2.min(len.div_ceil(2));
    candidates
        .into_iter()
        .map(|c| (edit_distance(word, c), c))
        .filter(|(d, _)| *d <= limit && *d < len)
        .min_by_key(|(d, _)| *d)
        .map(|(_, c)| c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn suggests_close_words_only() {
        assert_eq!(suggest("ROUET", ["ROUTE", "FIND"]), Some("ROUTE"));
        assert_eq!(suggest("neighbors", ["NEIGHBOURS"]), Some("NEIGHBOURS"));
        assert_eq!(suggest("xyz", ["ROUTE", "FIND"]), None);
        assert_eq!(edit_distance("", "abc"), 3);
    }
}
