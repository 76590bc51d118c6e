//! Stopping a run from outside: a [`Cancel`] flag that a front end raises
//! (Ctrl-C in Python, a server whose request ran out of time) and a time
//! limit, checked between phases and inside the long loops.
//!
//! A leaf like `timing`: every layer may check it, and it decides nothing
//! about geometry. A check is one relaxed atomic load and, with a time
//! limit, one clock read, so loops check it every few thousand steps, not
//! every step. On `wasm32-unknown-unknown`, where `std::time::Instant`
//! panics, there is no clock and a time limit never expires (cancelling
//! still works).

use crate::error::{Error, Interruption, Result};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Duration;

/// A cancellation flag shared between a run and whoever may stop it.
///
/// Clones share the flag: give one clone to
/// [`Options::with_cancel`](crate::Options::with_cancel) and keep the other;
/// [`cancel`](Self::cancel) makes the run return
/// [`Error::Interrupted`] at its next check (criteria that can certify a
/// partial result return it instead, with `exact: false`). Two flags are
/// equal only if they are the same flag.
#[derive(Clone, Debug, Default)]
pub struct Cancel(Arc<AtomicBool>);

impl Cancel {
    /// A flag that is not raised.
    pub fn new() -> Self {
        Self::default()
    }

    /// Raises the flag: every run holding a clone stops at its next check.
    pub fn cancel(&self) {
        self.0.store(true, Ordering::Relaxed);
    }

    /// Has [`cancel`](Self::cancel) been called?
    pub fn is_cancelled(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }
}

impl PartialEq for Cancel {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

impl Eq for Cancel {}

/// When a run must stop: its cancellation flag and the deadline its time
/// limit set when the run started. Equal when the flag and the limit are.
#[derive(Clone, Debug, Default)]
pub(crate) struct Stop {
    cancel: Option<Cancel>,
    limit: Option<Duration>,
    #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
    deadline: Option<std::time::Instant>,
}

impl PartialEq for Stop {
    fn eq(&self, other: &Self) -> bool {
        self.cancel == other.cancel && self.limit == other.limit
    }
}

impl Eq for Stop {}

impl Stop {
    /// A stop for a run starting now: cancelled by `cancel`, out of time
    /// after `limit`.
    pub(crate) fn starting_now(cancel: Option<Cancel>, limit: Option<Duration>) -> Self {
        Self {
            cancel,
            limit,
            #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
            deadline: limit.and_then(|l| std::time::Instant::now().checked_add(l)),
        }
    }

    /// Why the run must stop now, if it must.
    pub(crate) fn reason(&self) -> Option<Interruption> {
        if self.cancel.as_ref().is_some_and(Cancel::is_cancelled) {
            return Some(Interruption::Cancelled);
        }
        #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
        if self
            .deadline
            .is_some_and(|d| std::time::Instant::now() >= d)
        {
            return Some(Interruption::TimeLimit {
                seconds: self.limit.map_or(0.0, |l| l.as_secs_f64()),
            });
        }
        None
    }

    /// A stop with this one's cancellation flag and a new time limit of
    /// `grace` from now: for the few steps a run whose time ran out takes
    /// to assemble the answer it has, bounded so that it still returns soon.
    pub(crate) fn grace(&self, grace: Duration) -> Self {
        Self::starting_now(self.cancel.clone(), Some(grace))
    }

    /// `Err(Error::Interrupted)` when the run must stop.
    pub(crate) fn check(&self) -> Result<()> {
        match self.reason() {
            Some(why) => Err(Error::Interrupted(why)),
            None => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_raised_flag_and_a_past_deadline_stop_the_run() {
        let cancel = Cancel::new();
        let stop = Stop::starting_now(Some(cancel.clone()), None);
        assert!(stop.check().is_ok());
        cancel.cancel();
        assert_eq!(
            stop.check(),
            Err(Error::Interrupted(Interruption::Cancelled))
        );
        let stop = Stop::starting_now(None, Some(Duration::ZERO));
        assert_eq!(
            stop.check(),
            Err(Error::Interrupted(Interruption::TimeLimit { seconds: 0.0 }))
        );
        let stop = Stop::starting_now(None, Some(Duration::from_secs(3600)));
        assert!(stop.check().is_ok());
        // A grace keeps the flag and replaces the limit.
        let cancel = Cancel::new();
        let spent = Stop::starting_now(Some(cancel.clone()), Some(Duration::ZERO));
        assert!(spent.grace(Duration::from_secs(3600)).check().is_ok());
        cancel.cancel();
        assert_eq!(
            spent.grace(Duration::from_secs(3600)).check(),
            Err(Error::Interrupted(Interruption::Cancelled))
        );
        assert!(Stop::default().check().is_ok());
        assert_ne!(Cancel::new(), Cancel::new());
    }
}
