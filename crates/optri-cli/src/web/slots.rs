//! Where the playground's computations run: a fixed number of slots, each
//! computation on a rayon thread pool of its own.
//!
//! The library parallelises with rayon inside a run; a run started on a
//! pool's thread uses that pool for its parallel loops. A pool per
//! computation therefore keeps one computation's work from queueing behind
//! another's (which rayon's global pool, shared by every run, would do), and
//! none of it runs on the thread that reads and writes the connections. The
//! pool costs a few thread starts, nothing beside a computation.
//!
//! A slot is held by the computation, not by the request that asked for it:
//! it is free again when the computation returns, even if the request gave
//! up before (its time limit passed and its [`optri::Cancel`] was raised, or
//! its client went away), so slow computations cannot pile up.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::Arc;
use tokio::sync::{oneshot, OwnedSemaphorePermit, Semaphore};

/// A fixed number of computation slots, each run on a pool of `threads`.
pub(crate) struct Slots {
    free: Arc<Semaphore>,
    count: usize,
    threads: usize,
    name: &'static str,
}

/// A slot taken from [`Slots`]: given back when dropped.
pub(crate) struct Slot {
    _permit: OwnedSemaphorePermit,
    threads: usize,
    name: &'static str,
}

/// What a computation left when it did not return a value: the message of
/// its panic, or why its pool could not start.
pub(crate) type Failure = String;

impl Slots {
    /// `count` slots (at least one) whose computations get `threads` threads
    /// each; `name` names the threads.
    pub(crate) fn new(count: usize, threads: usize, name: &'static str) -> Self {
        let count = count.clamp(1, Semaphore::MAX_PERMITS);
        Self {
            free: Arc::new(Semaphore::new(count)),
            count,
            threads: threads.max(1),
            name,
        }
    }

    /// The number of slots.
    pub(crate) fn count(&self) -> usize {
        self.count
    }

    /// A free slot, waiting for one.
    pub(crate) async fn wait(&self) -> Slot {
        let permit = Arc::clone(&self.free)
            .acquire_owned()
            .await
            .expect("the semaphore is never closed");
        self.slot(permit)
    }

    /// A free slot now, if there is one.
    pub(crate) fn try_take(&self) -> Option<Slot> {
        let permit = Arc::clone(&self.free).try_acquire_owned().ok()?;
        Some(self.slot(permit))
    }

    fn slot(&self, permit: OwnedSemaphorePermit) -> Slot {
        Slot {
            _permit: permit,
            threads: self.threads,
            name: self.name,
        }
    }
}

impl Slot {
    /// Runs `work` on a new rayon pool of the slot's threads and sends its
    /// value, or its [`Failure`], to the receiver. The slot is given back
    /// when `work` returns or panics, before the value is sent, so a client
    /// that has its answer finds the slot free.
    pub(crate) fn run<T: Send + 'static>(
        self,
        work: impl FnOnce() -> T + Send + 'static,
    ) -> oneshot::Receiver<Result<T, Failure>> {
        let (send, receive) = oneshot::channel();
        let name = self.name;
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(self.threads)
            .thread_name(move |i| format!("optri-{name}-{i}"))
            .build();
        match pool {
            // The pool's threads end once the spawned work is done, after
            // the handle is dropped here.
            Ok(pool) => pool.spawn(move || {
                let value = catch_unwind(AssertUnwindSafe(work)).map_err(|panic| {
                    panic
                        .downcast_ref::<&str>()
                        .map(|s| s.to_string())
                        .or_else(|| panic.downcast_ref::<String>().cloned())
                        .unwrap_or_else(|| "a panic".to_string())
                });
                drop(self);
                // The receiver may have stopped waiting: nothing to do then.
                let _ = send.send(value);
            }),
            Err(e) => {
                drop(self);
                let _ = send.send(Err(format!("cannot start a computation thread: {e}")));
            }
        }
        receive
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::web::block_on;
    use std::sync::mpsc;
    use std::time::Duration;

    #[test]
    fn a_slot_is_free_again_when_its_work_returns_not_when_its_caller_leaves() {
        let slots = Slots::new(1, 2, "test");
        let (release, hold) = mpsc::channel::<()>();
        let answer = slots.try_take().unwrap().run(move || {
            hold.recv().unwrap();
            rayon::current_num_threads()
        });
        // The caller stops waiting: the slot stays taken while the work runs.
        drop(answer);
        assert!(slots.try_take().is_none());
        release.send(()).unwrap();
        let again = block_on(async {
            tokio::time::timeout(Duration::from_secs(30), slots.wait())
                .await
                .expect("the slot comes back")
        });
        // The work ran on a pool of its own, of the slot's size.
        assert_eq!(block_on(again.run(rayon::current_num_threads)), Ok(Ok(2)));
    }

    #[test]
    fn a_panic_is_a_failure_and_frees_the_slot() {
        let slots = Slots::new(1, 1, "test");
        let failed = block_on(slots.try_take().unwrap().run(|| -> u8 { panic!("boom") }));
        assert_eq!(failed, Ok(Err("boom".to_string())));
        assert!(slots.try_take().is_some());
    }
}
