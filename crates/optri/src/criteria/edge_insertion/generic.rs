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
//!
//! # Stopping early: a lower bound from the hull
//! Every triangulation has, on each hull edge `ab`, one triangle `abr`
//! whose apex is an *empty apex* of `ab` ([`empty_apexes`]), so its worst
//! triangle is at least `β(ab) = min_r badness(abr)` over those apexes, and
//! the optimum is at least the largest `β` of any hull edges. When the
//! worst value reaches such a bound the triangulation is optimal and the
//! loop stops, before trying the anchors of every tied worst triangle. On a
//! lattice, where every Delaunay triangle is a tied worst one (right
//! angles, equal heights, zero eccentricity), that is the first pass. The
//! hull edges searched are sides of worst triangles, a few per pass and
//! [`MAX_BOUND_EDGES`] in all, so the bound costs `O(n log n)` per run.

use super::insertion::{Badness, Mesh};
use crate::error::Result;
use crate::interrupt::Stop;
use crate::kernel::properly_cross;
use crate::spatial::{convex_hull_cycle, empty_apexes};
use std::cmp::Ordering;
use std::collections::HashSet;

/// Hull edges searched for the lower bound in one run.
const MAX_BOUND_EDGES: usize = 16;
/// Hull edges searched in one pass of the loop.
const BOUND_EDGES_PER_PASS: usize = 4;

/// The lower bound of the module docs: the best triangle of the hull edges
/// searched so far (its badness is the bound).
struct HullBound {
    /// Hull edges in counter-clockwise direction (inner side on the left).
    hull_edges: HashSet<[u32; 2]>,
    searched: HashSet<[u32; 2]>,
    bound: Option<[u32; 3]>,
    scratch: Vec<u32>,
}

impl HullBound {
    fn new(badness: &Badness) -> Self {
        let hull = convex_hull_cycle(badness.points);
        let h = hull.len();
        HullBound {
            hull_edges: (0..h).map(|e| [hull[e], hull[(e + 1) % h]]).collect(),
            searched: HashSet::new(),
            bound: None,
            scratch: Vec::new(),
        }
    }

    /// Searches a few hull edges that are sides of `worst` triangles and
    /// were not searched before, raising the bound.
    fn tighten(&mut self, badness: &Badness, worst: &[[u32; 3]]) {
        let mut this_pass = 0;
        for t in worst {
            for k in 0..3 {
                let side = [t[k], t[(k + 1) % 3]];
                for [a, b] in [side, [side[1], side[0]]] {
                    if this_pass == BOUND_EDGES_PER_PASS || self.searched.len() == MAX_BOUND_EDGES {
                        return;
                    }
                    if !self.hull_edges.contains(&[a, b]) || !self.searched.insert([a, b]) {
                        continue;
                    }
                    this_pass += 1;
                    // β(ab): the best triangle on ab.
                    let best = empty_apexes(badness.points, a, b, &mut self.scratch)
                        .into_iter()
                        .map(|r| [a, b, r])
                        .reduce(|s, t| {
                            if badness.compare(t, s) == Ordering::Less {
                                t
                            } else {
                                s
                            }
                        });
                    if let Some(best) = best {
                        if self
                            .bound
                            .is_none_or(|b| badness.compare(best, b) == Ordering::Greater)
                        {
                            self.bound = Some(best);
                        }
                    }
                }
            }
        }
    }

    /// Does the bound prove a worst triangle `w` optimal?
    fn certifies(&self, badness: &Badness, w: [u32; 3]) -> bool {
        self.bound
            .is_some_and(|b| badness.compare(w, b) != Ordering::Greater)
    }
}

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
    /// The worst value met the hull's lower bound (module docs): optimal
    /// without trying every anchor.
    pub met_hull_bound: bool,
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
    let mut hull_bound = HullBound::new(badness);
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
        hull_bound.tighten(badness, &worst);
        if hull_bound.certifies(badness, representative) {
            steps.met_hull_bound = true;
            return Ok(steps);
        }
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
