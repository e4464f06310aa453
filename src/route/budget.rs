//! A time bound checked cheaply from inside search loops.

use std::cell::Cell;
use std::time::{Duration, Instant};

/// A deadline for a search. Checking it reads the clock only every 256 calls.
#[derive(Debug, Clone)]
pub struct Budget {
    deadline: Option<Instant>,
    limit: Duration,
    calls: Cell<u32>,
    expired: Cell<bool>,
}

impl Budget {
    /// No time bound.
    pub fn unlimited() -> Budget {
        Budget {
            deadline: None,
            limit: Duration::MAX,
            calls: Cell::new(0),
            expired: Cell::new(false),
        }
    }

    /// A bound of `limit` from now.
    pub fn new(limit: Duration) -> Budget {
        Budget::within(limit, None)
    }

    /// When work bounded by `limit` from now and by `deadline` must stop:
    /// the earlier of the two (`None`: never).
    pub fn stop_at(limit: Duration, deadline: Option<Instant>) -> Option<Instant> {
        let own = Instant::now().checked_add(limit);
        match (own, deadline) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        }
    }

    /// A bound of `limit` from now, cut short at `deadline` when that
    /// comes first (a request's deadline over several statements). A
    /// deadline already passed expires at the first check.
    pub fn within(limit: Duration, deadline: Option<Instant>) -> Budget {
        let deadline = Budget::stop_at(limit, deadline);
        let budget = Budget {
            deadline,
            limit,
            calls: Cell::new(0),
            expired: Cell::new(false),
        };
        if budget.deadline.is_some_and(|d| Instant::now() >= d) {
            budget.expired.set(true);
        }
        budget
    }

    /// Whether the deadline has passed (sticky once true).
    pub fn check(&self) -> bool {
        if self.expired.get() {
            return true;
        }
        let calls = self.calls.get().wrapping_add(1);
        self.calls.set(calls);
        if calls.is_multiple_of(256)
            && let Some(deadline) = self.deadline
            && Instant::now() >= deadline
        {
            self.expired.set(true);
        }
        self.expired.get()
    }

    /// Whether a check has found the deadline passed.
    pub fn is_expired(&self) -> bool {
        self.expired.get()
    }

    /// The bound in milliseconds (for messages).
    pub fn limit_ms(&self) -> u128 {
        self.limit.as_millis()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zero_budget_expires() {
        let b = Budget::new(Duration::ZERO);
        let expired = (0..1000).any(|_| b.check());
        assert!(expired && b.is_expired());
        assert!(!(0..1000).any(|_| Budget::unlimited().check()));
    }

    /// Issue 21, defect 7: the earlier of the own bound and the request's
    /// deadline wins; a passed deadline stops work at the first check.
    #[test]
    fn issue_21_defect_7_a_passed_deadline_expires_at_once() {
        let passed = Some(Instant::now());
        let b = Budget::within(Duration::from_secs(3600), passed);
        assert!(b.check() && b.limit_ms() == 3_600_000);
        let later = Instant::now().checked_add(Duration::from_secs(3600));
        assert!(!Budget::within(Duration::from_secs(3600), later).check());
        assert!(Budget::within(Duration::ZERO, later).check());
    }
}
