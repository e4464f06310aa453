//! Region adjacency (Shapiro's RAG): which labels touch, 4-adjacency.

use std::collections::BTreeMap;

use super::Labels;

/// For every touching pair of labels `(a, b)` with `a < b`: the number of
/// 4-adjacent pixel pairs between them (the length of their shared border).
pub type Adjacency = BTreeMap<(u32, u32), usize>;

/// The region adjacency graph of a label image; label 0 is ignored.
///
/// ```
/// use nrgdb::imaging::{Labels, region_adjacency};
/// let l = Labels { width: 3, height: 1, data: vec![1, 2, 3], count: 3 };
/// let rag = region_adjacency(&l);
/// assert_eq!(rag.keys().copied().collect::<Vec<_>>(), vec![(1, 2), (2, 3)]);
/// ```
pub fn region_adjacency(labels: &Labels) -> Adjacency {
    let (w, h) = (labels.width as usize, labels.height as usize);
    let d = &labels.data;
    let mut rag = Adjacency::new();
    let mut add = |a: u32, b: u32| {
        if a != 0 && b != 0 && a != b {
            *rag.entry((a.min(b), a.max(b))).or_insert(0) += 1;
        }
    };
    // Neighbours across a column edge, then across a row edge; most pairs
    // are equal and are skipped in one compare.
    for row in d.chunks_exact(w.max(1)).take(h) {
        for pair in row.windows(2) {
            if pair[0] != pair[1] {
                add(pair[0], pair[1]);
            }
        }
    }
    for (upper, lower) in d
        .chunks_exact(w.max(1))
        .zip(d.chunks_exact(w.max(1)).skip(1))
    {
        for (&a, &b) in upper.iter().zip(lower) {
            if a != b {
                add(a, b);
            }
        }
    }
    rag
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn diagonal_contact_is_not_adjacency() {
        let l = Labels {
            width: 2,
            height: 2,
            data: vec![1, 2, 2, 1],
            count: 2,
        };
        assert_eq!(region_adjacency(&l).get(&(1, 2)), Some(&4));
        let l = Labels {
            width: 2,
            height: 2,
            data: vec![1, 0, 0, 2],
            count: 2,
        };
        assert!(region_adjacency(&l).is_empty());
    }
}
