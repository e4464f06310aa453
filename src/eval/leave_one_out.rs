//! Leave-one-building-out judgement of a parameter default: for each
//! building, the value that scores best on all the *other* buildings is the
//! one it gets, and its score under that value is what counts. A default
//! that only fits the buildings it was tuned on shows up as held-out scores
//! below the scores of the value tuned on everything.
//!
//! Maps of one building (a plain and a furnished drawing) are one building:
//! leaving out one of them while tuning on the other would leak.

use serde::Serialize;

use super::metrics::{Detection, Evaluation};

/// The building a map belongs to: its name without a `_furnitures` variant
/// suffix (the IPA benchmark's furnished copy of a plan).
pub fn building_of(map: &str) -> &str {
    map.strip_suffix("_furnitures").unwrap_or(map)
}

/// One number per evaluation to rank parameter values by: the mean of the
/// F1 scores of rooms (IPA per-room recall and precision), doors and
/// connections, in 0..=1.
pub fn score(e: &Evaluation) -> f64 {
    let f1 = |r: f64, p: f64| {
        if r + p > 0.0 {
            2.0 * r * p / (r + p)
        } else {
            0.0
        }
    };
    let detection = |d: &Detection| f1(d.recall, d.precision);
    (f1(e.rooms.recall_micro, e.rooms.precision_micro)
        + detection(&e.doors)
        + detection(&e.connections))
        / 3.0
}

/// What one held-out building got.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HeldOut {
    /// Index of the value tuned on the other buildings.
    pub chosen: usize,
    /// The building's score under it.
    pub score: f64,
    /// Index of the value best for this building alone (first on ties).
    pub own_best: usize,
}

/// For `scores[b][v]` (building `b` under value `v`), each building's
/// held-out result: the value with the highest mean over the other
/// buildings (the first on ties), and the building's score under it.
/// Empty when there are fewer than two buildings or no values.
pub fn leave_one_out(scores: &[Vec<f64>]) -> Vec<HeldOut> {
    let values = scores.first().map_or(0, Vec::len);
    if scores.len() < 2 || values == 0 || scores.iter().any(|s| s.len() != values) {
        return Vec::new();
    }
    let totals: Vec<f64> = (0..values)
        .map(|v| scores.iter().map(|s| s[v]).sum())
        .collect();
    let best =
        |of: &dyn Fn(usize) -> f64| (0..values).fold(0, |b, v| if of(v) > of(b) { v } else { b });
    scores
        .iter()
        .map(|own| {
            let chosen = best(&|v| totals[v] - own[v]);
            HeldOut {
                chosen,
                score: own[chosen],
                own_best: best(&|v| own[v]),
            }
        })
        .collect()
}

/// The value with the highest mean over all buildings (first on ties).
pub fn tuned_on_all(scores: &[Vec<f64>]) -> Option<usize> {
    let values = scores.first()?.len();
    let total = |v: usize| scores.iter().filter_map(|s| s.get(v)).sum::<f64>();
    (values > 0).then(|| (0..values).fold(0, |b, v| if total(v) > total(b) { v } else { b }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn furnished_copies_belong_to_their_building() {
        assert_eq!(building_of("lab_a_scan_furnitures"), "lab_a_scan");
        assert_eq!(building_of("lab_a_scan"), "lab_a_scan");
    }

    #[test]
    fn a_value_that_fits_one_building_is_not_given_to_it() {
        // Value 1 is best overall only because of building 0; held out,
        // building 0 gets value 0 (best on the others) and its lower score.
        let scores = vec![
            vec![0.50, 0.99],
            vec![0.90, 0.85],
            vec![0.90, 0.88],
            vec![0.80, 0.82],
        ];
        assert_eq!(tuned_on_all(&scores), Some(1));
        let held = leave_one_out(&scores);
        assert_eq!(held[0].chosen, 0);
        assert_eq!(held[0].score, 0.50);
        assert_eq!(held[0].own_best, 1);
        // The others, held out, still see building 0's pull to value 1.
        assert_eq!(held[1].chosen, 1);
        assert_eq!(held[1].own_best, 0);
        assert_eq!(held[3].chosen, 1);
        assert_eq!(held[3].score, 0.82);
    }

    #[test]
    fn ties_go_to_the_first_value_and_one_building_is_not_enough() {
        let scores = vec![vec![0.7, 0.7], vec![0.6, 0.6]];
        assert!(leave_one_out(&scores).iter().all(|h| h.chosen == 0));
        assert!(leave_one_out(&scores[..1]).is_empty());
        assert!(leave_one_out(&[vec![0.5], vec![0.5, 0.6]]).is_empty());
    }
}
