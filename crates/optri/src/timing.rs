//! Wall-clock phases of a run, reported in [`crate::Solution::phases`].
//!
//! Timing is infrastructure, not an algorithm: every layer may record phases,
//! and nothing decides anything from them. On `wasm32-unknown-unknown`, where
//! `std::time::Instant` panics, the clock reads zero and every phase lasts 0 ms.

#[cfg(feature = "io")]
use serde::Serialize;

/// One timed phase of an algorithm run.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "io", derive(Serialize))]
pub struct Phase {
    /// Phase name, e.g. `"delaunay"`.
    pub name: &'static str,
    /// Wall-clock milliseconds.
    pub ms: f64,
}

/// A point in time, or nothing where the platform has no clock.
#[derive(Clone, Copy)]
struct Clock {
    #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
    start: std::time::Instant,
}

impl Clock {
    #[inline]
    fn now() -> Self {
        Self {
            #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
            start: std::time::Instant::now(),
        }
    }

    /// Milliseconds since `self`.
    #[inline]
    fn elapsed_ms(self) -> f64 {
        #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
        {
            self.start.elapsed().as_secs_f64() * 1e3
        }
        #[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
        {
            0.0
        }
    }
}

/// Times `f` as a phase named `name`.
pub(crate) fn timed<T>(phases: &mut Vec<Phase>, name: &'static str, f: impl FnOnce() -> T) -> T {
    let start = Clock::now();
    let out = f();
    phases.push(Phase {
        name,
        ms: start.elapsed_ms(),
    });
    out
}

/// Records consecutive phases: each [`lap`](Self::lap) closes the phase
/// that started at the previous lap (or at creation).
pub(crate) struct Stopwatch<'a> {
    phases: &'a mut Vec<Phase>,
    start: Clock,
}

impl<'a> Stopwatch<'a> {
    pub(crate) fn new(phases: &'a mut Vec<Phase>) -> Self {
        Self {
            phases,
            start: Clock::now(),
        }
    }

    /// Runs `f`, which records its own phases; the next lap starts when it
    /// returns.
    pub(crate) fn nested<T>(&mut self, f: impl FnOnce(&mut Vec<Phase>) -> T) -> T {
        let out = f(self.phases);
        self.start = Clock::now();
        out
    }

    pub(crate) fn lap(&mut self, name: &'static str) {
        self.phases.push(Phase {
            name,
            ms: self.start.elapsed_ms(),
        });
        self.start = Clock::now();
    }
}
