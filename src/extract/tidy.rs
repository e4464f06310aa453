//! Label tidying before tracing: every space label becomes one 4-connected
//! piece that never touches itself diagonally, so that its outline along
//! pixel edges (`boundaries.rs`) is one simple exterior ring with simple
//! holes that touch neither it nor each other.
//!
//! Two deterministic fixes, repeated until neither changes a pixel:
//! * a diagonal pinch (a 2×2 block `X Y / Z X` with Y, Z ≠ X, X ≠ 0) is
//!   closed by giving one of the other two pixels to X (a 0 pixel first,
//!   else the top right one);
//! * every 4-connected piece of a label but its largest goes to the label
//!   it borders most (possibly 0).
//!
//! Uses the label image only; label 0 (no space) is never tidied itself.

use std::collections::HashMap;

use crate::imaging::Labels;

/// Rounds of fixes before giving up (each round is a full scan; maps need 2–3).
const MAX_ROUNDS: usize = 16;

/// Tidies `labels` in place (see the module doc); returns the number of
/// pixels that changed label.
pub(crate) fn tidy_labels(labels: &mut Labels) -> usize {
    let mut changed = 0;
    // Pieces are looked for once the pinches are closed, and pinches again
    // after pieces moved.
    let mut pieces_due = true;
    for _ in 0..MAX_ROUNDS {
        let pinches = close_pinches(labels);
        changed += pinches;
        if pinches > 0 {
            pieces_due = true;
            continue;
        }
        if !pieces_due {
            break;
        }
        let pieces = give_away_pieces(labels);
        changed += pieces;
        if pieces == 0 {
            break;
        }
        pieces_due = false;
    }
    changed
}

/// One pass over all 2×2 blocks, closing diagonal pinches of non-zero
/// labels; returns how many pixels changed.
fn close_pinches(labels: &mut Labels) -> usize {
    let (w, h) = (labels.width as usize, labels.height as usize);
    let mut changed = 0;
    for y in 0..h.saturating_sub(1) {
        let (top, bottom) = labels.data.split_at_mut((y + 1) * w);
        let (r0, r1) = (&mut top[y * w..], &mut bottom[..w]);
        let mut x = 0;
        while x + 1 < w {
            // Skip blocks whose rows are each uniform (no pinch there).
            let Some(k) = r0[x..]
                .windows(2)
                .zip(r1[x..].windows(2))
                .position(|(p, q)| p[0] != p[1] || q[0] != q[1])
            else {
                break;
            };
            x += k;
            let (a, b, c, e) = (r0[x], r0[x + 1], r1[x], r1[x + 1]);
            // The diagonal pair's label, and the two pixels that could join it
            // (true: in the top row).
            let fix = if a == e && a != 0 && b != a && c != a {
                Some((a, (true, x + 1), (false, x)))
            } else if b == c && b != 0 && a != b && e != b {
                Some((b, (true, x), (false, x + 1)))
            } else {
                None
            };
            if let Some((label, first, second)) = fix {
                let get = |(top, i): (bool, usize)| if top { r0[i] } else { r1[i] };
                // A 0 pixel goes first, so that no space loses one.
                let (top, i) = if get(second) == 0 && get(first) != 0 {
                    second
                } else {
                    first
                };
                if top {
                    r0[i] = label;
                } else {
                    r1[i] = label;
                }
                changed += 1;
            }
            x += 1;
        }
    }
    changed
}

/// A horizontal run of one label in one row.
#[derive(Clone, Copy)]
struct Run {
    y: usize,
    x0: usize,
    /// One past the last column.
    x1: usize,
    label: u32,
}

/// Gives every 4-connected piece of a non-zero label but its largest to
/// the label it borders most; returns how many pixels changed.
fn give_away_pieces(labels: &mut Labels) -> usize {
    let (w, h) = (labels.width as usize, labels.height as usize);
    let runs = runs_of(labels);
    let mut parent: Vec<usize> = (0..runs.len()).collect();
    // Runs of each row start at row_start[y].
    let mut row_start = vec![0usize; h + 1];
    for r in &runs {
        row_start[r.y + 1] += 1;
    }
    for y in 0..h {
        row_start[y + 1] += row_start[y];
    }
    for y in 1..h {
        let (mut p, pe) = (row_start[y - 1], row_start[y]);
        let (mut q, qe) = (row_start[y], row_start[y + 1]);
        while p < pe && q < qe {
            let (a, b) = (runs[p], runs[q]);
            if a.label == b.label && a.label != 0 && a.x0 < b.x1 && b.x0 < a.x1 {
                union(&mut parent, p, q);
            }
            if a.x1 <= b.x1 {
                p += 1;
            } else {
                q += 1;
            }
        }
    }
    // Pixels per piece, and the largest piece of each label.
    let mut size = vec![0usize; runs.len()];
    for (k, run) in runs.iter().enumerate() {
        let r = find(&mut parent, k);
        size[r] += run.x1 - run.x0;
    }
    let mut largest: HashMap<u32, usize> = HashMap::new();
    for k in 0..runs.len() {
        if parent[k] != k || runs[k].label == 0 {
            continue;
        }
        let e = largest.entry(runs[k].label).or_insert(k);
        if size[k] > size[*e] {
            *e = k;
        }
    }
    let mut small: Vec<usize> = (0..runs.len())
        .filter(|&k| {
            runs[k].label != 0 && largest.get(&runs[k].label) != Some(&find(&mut parent, k))
        })
        .collect();
    if small.is_empty() {
        return 0;
    }
    // Per small piece, how often it borders each other label.
    let mut borders: HashMap<usize, HashMap<u32, usize>> = HashMap::new();
    let at = |x: usize, y: usize| labels.data[y * w + x];
    for &k in &small {
        let r = runs[k];
        let root = find(&mut parent, k);
        let count = borders.entry(root).or_default();
        let mut see = |l: u32| {
            if l != r.label {
                *count.entry(l).or_default() += 1;
            }
        };
        see(if r.x0 > 0 { at(r.x0 - 1, r.y) } else { 0 });
        see(if r.x1 < w { at(r.x1, r.y) } else { 0 });
        for x in r.x0..r.x1 {
            see(if r.y > 0 { at(x, r.y - 1) } else { 0 });
            see(if r.y + 1 < h { at(x, r.y + 1) } else { 0 });
        }
    }
    let target: HashMap<usize, u32> = borders
        .into_iter()
        .map(|(root, count)| {
            let best = count
                .into_iter()
                .max_by(|a, b| a.1.cmp(&b.1).then(b.0.cmp(&a.0)))
                .map_or(0, |(l, _)| l);
            (root, best)
        })
        .collect();
    let mut changed = 0;
    small.sort_unstable();
    for k in small {
        let root = find(&mut parent, k);
        let r = runs[k];
        let to = target.get(&root).copied().unwrap_or(0);
        labels.data[r.y * w + r.x0..r.y * w + r.x1].fill(to);
        changed += r.x1 - r.x0;
    }
    changed
}

/// The runs of equal labels, row by row, left to right.
fn runs_of(labels: &Labels) -> Vec<Run> {
    let w = labels.width as usize;
    let mut runs = Vec::new();
    for (y, row) in labels.data.chunks_exact(w.max(1)).enumerate() {
        let mut x0 = 0;
        while x0 < row.len() {
            let label = row[x0];
            let len = row[x0..]
                .iter()
                .position(|&l| l != label)
                .unwrap_or(row.len() - x0);
            runs.push(Run {
                y,
                x0,
                x1: x0 + len,
                label,
            });
            x0 += len;
        }
    }
    runs
}

fn find(parent: &mut [usize], mut k: usize) -> usize {
    while parent[k] != k {
        parent[k] = parent[parent[k]];
        k = parent[k];
    }
    k
}

fn union(parent: &mut [usize], a: usize, b: usize) {
    let (ra, rb) = (find(parent, a), find(parent, b));
    if ra != rb {
        // The smaller index stays the root, so roots are deterministic.
        parent[ra.max(rb)] = ra.min(rb);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_checkerboard_pinch_is_closed() {
        let mut l = Labels::from_digits(&["0000", "0120", "0210", "0000"]);
        assert!(tidy_labels(&mut l) > 0);
        // No 2x2 block has a diagonal pair apart from its other two pixels.
        assert_eq!(close_pinches(&mut l.clone()), 0);
        assert_eq!(give_away_pieces(&mut l.clone()), 0);
    }

    #[test]
    fn the_smaller_piece_goes_to_its_neighbour() {
        let mut l = Labels::from_digits(&["1110022", "1110212", "1110022"]);
        tidy_labels(&mut l);
        // The lone 1 among the 2s becomes a 2.
        assert_eq!(l.data[7 + 5], 2);
        assert_eq!(l.data.iter().filter(|&&v| v == 1).count(), 9);
    }
}
