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
        Budget {
            deadline: Instant::now().checked_add(limit),
            limit,
            calls: Cell::new(0),
            expired: Cell::new(false),
        }
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
}
