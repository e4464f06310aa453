//! Which map messages of a recording become revisions: each map that
//! differs from the one chosen before it (identical maps make none), and
//! with an interval, at most one per interval of recording time — the
//! last map of each interval, so the recording's final map is kept.

/// One map message seen while scanning: its number, time and content hash.
#[derive(Debug, Clone, PartialEq)]
pub struct Seen {
    /// Its number among the topic's messages, from 1.
    pub index: usize,
    /// Log time, nanoseconds since the epoch.
    pub log_time_ns: u64,
    /// SHA-256 of its map (frame, resolution, size, origin, cells; not
    /// its stamps), lower-case hex.
    pub sha256: String,
    /// Cells per row and rows.
    pub size: (u32, u32),
}

/// The choice made: positions (in the scanned list) of the messages to
/// store, and how many were left out for which reason.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Choice {
    /// Positions of the chosen messages, in order.
    pub chosen: Vec<usize>,
    /// Left out: the same map as the one chosen before.
    pub identical: usize,
    /// Left out: a later map of the same interval was kept.
    pub thinned: usize,
}

/// Chooses among `seen` (in recording order), with at most one per
/// `every_ns` nanoseconds of log time when given.
///
/// ```
/// use nrgdb::recording::{Seen, choose};
/// let m = |i: usize, t: u64, h: &str| Seen { index: i, log_time_ns: t, sha256: h.into(), size: (1, 1) };
/// let s = 1_000_000_000;
/// let seen = [m(1, 0, "a"), m(2, 10 * s, "b"), m(3, 20 * s, "b"), m(4, 25 * s, "c")];
/// assert_eq!(choose(&seen, None).chosen, vec![0, 1, 3]);
/// // One per 30 s: only the last map of the first 30 s.
/// assert_eq!(choose(&seen, Some(30 * s)).chosen, vec![3]);
/// ```
pub fn choose(seen: &[Seen], every_ns: Option<u64>) -> Choice {
    let mut choice = Choice::default();
    let mut last: Option<&str> = None;
    let Some(first) = seen.first() else {
        return choice;
    };
    let window = |s: &Seen| match every_ns {
        Some(every) if every > 0 => s.log_time_ns.saturating_sub(first.log_time_ns) / every,
        _ => s.index as u64,
    };
    for (i, s) in seen.iter().enumerate() {
        let last_of_window = seen.get(i + 1).is_none_or(|next| window(next) != window(s));
        let same = last == Some(s.sha256.as_str());
        if same {
            choice.identical += 1;
        } else if last_of_window {
            choice.chosen.push(i);
            last = Some(s.sha256.as_str());
        } else {
            choice.thinned += 1;
        }
    }
    choice
}

#[cfg(test)]
mod tests {
    use super::*;

    fn seen(list: &[(u64, &str)]) -> Vec<Seen> {
        list.iter()
            .enumerate()
            .map(|(i, (t, h))| Seen {
                index: i + 1,
                log_time_ns: t * 1_000_000_000,
                sha256: (*h).into(),
                size: (1, 1),
            })
            .collect()
    }

    #[test]
    fn identical_maps_make_no_revision() {
        let s = seen(&[(0, "a"), (1, "a"), (2, "b"), (3, "b"), (4, "a")]);
        let c = choose(&s, None);
        assert_eq!(c.chosen, vec![0, 2, 4]);
        assert_eq!((c.identical, c.thinned), (2, 0));
    }

    #[test]
    fn every_keeps_the_last_map_of_each_interval() {
        // Maps at 0, 10, 20 s (one interval of 30 s), 31 s and 65 s.
        let s = seen(&[(0, "a"), (10, "b"), (20, "c"), (31, "d"), (65, "e")]);
        let c = choose(&s, Some(30_000_000_000));
        assert_eq!(c.chosen, vec![2, 3, 4]);
        assert_eq!((c.identical, c.thinned), (0, 2));
        // The interval's last map equal to the one kept before: none kept.
        let s = seen(&[(0, "a"), (40, "b"), (50, "a")]);
        let c = choose(&s, Some(30_000_000_000));
        assert_eq!(c.chosen, vec![0]);
        assert_eq!((c.identical, c.thinned), (1, 1));
    }

    #[test]
    fn nothing_seen_nothing_chosen() {
        assert_eq!(choose(&[], Some(1)), Choice::default());
    }
}
