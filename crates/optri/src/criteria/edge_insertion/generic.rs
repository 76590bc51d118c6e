//! The generic edge-insertion loop (Bern, Edelsbrunner, Eppstein, Mitchell
//! & Tan, *Edge insertion for optimal triangulations*, DCG 10, 1993, the
//! paradigm of §3), with the acceptance rule that survives ties:
//!
//! ```text
//! T ← Delaunay
//! loop
//!   for each worst triangle t (all tied ones, sorted by vertex triple):
//!     a ← anchor(t); for v = 0, 1, … with a–v valid and crossing t's side opposite a:
//!       N ← the insertion of a–v, sides retriangulated by lexicographic bottleneck
//!       if sortdesc(badness(N)) <lex sortdesc(badness(removed)): apply it; restart the loop
//!   stop: no anchor insertion improves, so the worst value is optimal
//! ```
//!
//! Every accepted step decreases the decreasing vector of badness values of
//! the whole triangulation lexicographically, so the loop terminates. Trying
//! the anchors of *all* tied worst triangles matters: two adjacent worst
//! triangles of equal value (coplanar lifted triangles for slope) may admit
//! an improving insertion only from the other one's anchor.
//!
//! Optionally the set of anchor–candidate pairs that failed (the weak-anchor
//! algorithm's n × n table, kept as a hash set so that its memory follows
//! the attempts made: n² bytes are 10 GB at 10⁵ points) skips pairs that
//! failed since the worst value last changed. Whether such a pair can
//! never succeed later is the paper's lemma, not checked here; so a pass
//! that finds nothing while it skipped pairs clears the set and runs
//! again, and the loop stops only after a full pass without skips — the
//! same stopping condition as without the set.

use super::insertion::{Badness, Mesh};
use crate::error::Result;
use crate::interrupt::Stop;
use crate::kernel::properly_cross;
use std::cmp::Ordering;
use std::collections::HashSet;

/// Counters of one run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Steps {
    /// Accepted insertions.
    pub insertions: u64,
    /// Insertions tried (valid segments whose sides were retriangulated).
    pub attempts: u64,
    /// The time limit ended the loop before its stopping condition: the
    /// mesh is valid and no worse than where it started, but not proven
    /// optimal.
    pub stopped: bool,
}

/// Does `a–v` properly cross the side `bc` of `[a, b, c]`?
fn crosses_opposite_side(badness: &Badness, [a, b, c]: [u32; 3], v: u32) -> bool {
    let p = |i: u32| badness.points[i as usize];
    properly_cross(p(a), p(v), p(b), p(c))
}

/// Runs the loop on `mesh` until no anchor insertion improves it, or until
/// `stop`'s time limit (read at every pass and every 64 candidates), which
/// leaves the mesh as it is with [`Steps::stopped`]. With
/// `remember_failures`, pairs that failed are not retried until the worst
/// value changes.
///
/// # Errors
/// [`crate::Error::Interrupted`] when the run is cancelled.
pub(crate) fn improve(
    mesh: &mut Mesh,
    badness: &Badness,
    remember_failures: bool,
    stop: &Stop,
) -> Result<Steps> {
    let n = badness.points.len();
    let mut steps = Steps::default();
    let mut tried: HashSet<u64> = HashSet::new();
    let mut worst_value: Option<[u32; 3]> = None;
    let mut skipped = false;
    let no_constraint = |_: u32, _: u32| false;
    let mut candidates = 0u32;
    // A spent time limit keeps the mesh reached; a cancel aborts.
    let spent = |steps: &mut Steps| -> Result<bool> {
        match stop.reason() {
            Some(crate::error::Interruption::TimeLimit { .. }) => {
                steps.stopped = true;
                Ok(true)
            }
            Some(why) => Err(crate::error::Error::Interrupted(why)),
            None => Ok(false),
        }
    };
    'improve: loop {
        if spent(&mut steps)? {
            return Ok(steps);
        }
        let worst = mesh.worst_triangles(badness);
        let Some(&representative) = worst.first() else {
            return Ok(steps);
        };
        if remember_failures {
            let changed = match worst_value {
                Some(w) => badness.compare(representative, w) != Ordering::Equal,
                None => true,
            };
            if changed {
                tried.clear();
                worst_value = Some(representative);
            }
        }
        for t in worst {
            let anchored = badness.anchored(t);
            let a = anchored[0];
            for v in 0..n as u32 {
                // Only pairs whose segment leaves through t's opposite side
                // belong to t (a pair failed from another triangle at the
                // same anchor is no skip here).
                if anchored.contains(&v)
                    || mesh.has_edge(a, v)
                    || !crosses_opposite_side(badness, anchored, v)
                {
                    continue;
                }
                candidates += 1;
                if candidates.is_multiple_of(64) && spent(&mut steps)? {
                    return Ok(steps);
                }
                let pair = (u64::from(a) << 32) | u64::from(v);
                if remember_failures && tried.contains(&pair) {
                    skipped = true;
                    continue;
                }
                let Some(insertion) = mesh.insertion(badness, anchored, v, &no_constraint) else {
                    continue;
                };
                steps.attempts += 1;
                let (mut added, mut removed) = (insertion.added.clone(), insertion.removed.clone());
                badness.sort_worst_first(&mut added);
                badness.sort_worst_first(&mut removed);
                if badness.compare_sorted(&added, &removed) == Ordering::Less {
                    mesh.apply(&insertion);
                    steps.insertions += 1;
                    continue 'improve;
                }
                if remember_failures {
                    tried.insert(pair);
                }
            }
        }
        if skipped {
            tried.clear();
            skipped = false;
            continue;
        }
        return Ok(steps);
    }
}
