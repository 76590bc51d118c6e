//! Deciding one length round of the greedy triangulation (the module docs'
//! "Deciding a round without following the length order"; candidates after
//! M. T. Dickerson, R. L. S. Drysdale, S. A. McElfresh & E. Welzl, *Fast
//! greedy triangulation algorithms*, 1997): pass 1 scans every candidate in
//! spatial order for the earlier edges and points that block it and for its
//! dependencies, pass 2 decides them in the global segment order.

use super::ranking::Ranking;
use super::segment_index::{PointsNear, Query, SegmentIndex, Step};
use super::{CANDIDATES_PER_TASK, NO_RANK};
use crate::kernel::Point;
use crate::parallel::prelude::*;

/// What pass 1 of [`decide_round`] finds about a run of candidates: the
/// ranks of the blocked ones, and the ranks of each candidate's
/// dependencies, candidate after candidate in `dependencies`, the `k`-th
/// candidate's ending at `dependency_ends[k]`.
#[derive(Default)]
struct Scanned {
    blocked: Vec<u32>,
    dependency_ends: Vec<u32>,
    dependencies: Vec<u32>,
}

impl Scanned {
    /// The dependencies of the `k`-th candidate of the run.
    #[inline]
    fn dependencies_of(&self, k: usize) -> &[u32] {
        let begin = if k == 0 {
            0
        } else {
            self.dependency_ends[k - 1]
        };
        &self.dependencies[begin as usize..self.dependency_ends[k] as usize]
    }
}

/// The id of an earlier (active) edge in a round's segment index; the
/// candidate of rank `r` has id `r + 1`, so that in every cell, sorted by
/// id, the earlier edges come first and a scan stops at the candidates not
/// shorter than its own.
const EARLIER_EDGE: u32 = 0;

/// Pass 1 of [`decide_round`] on a chunk of candidates (see [`Scanned`]).
///
/// One scan of the round's index finds both the earlier edges a candidate
/// crosses (it is then blocked) and its dependencies: every earlier edge is
/// shorter than the candidate, so the dependency scan's cells hold every
/// earlier edge that may cross it.
///
/// Without a point grid `near` (round 0, where every pair shorter than the
/// threshold is a candidate) the point test is part of that scan too: a
/// point `z` on the open segment `ab` makes `az` a shorter candidate whose
/// midpoint lies on `ab`, so the scan meets it, and sees that it shares `a`
/// and ends on `ab`; no point grid query is needed.
#[inline(never)]
fn scan_chunk(
    points: &[Point],
    segments: &[[u32; 2]],
    ranks: &[u32],
    index: &SegmentIndex,
    near: Option<&PointsNear>,
    shortest_at: &[u32],
) -> Scanned {
    let points_by_scan = near.is_none();
    let mut out = Scanned {
        dependency_ends: Vec::with_capacity(segments.len()),
        ..Scanned::default()
    };
    for (&[a, b], &r) in segments.iter().zip(ranks) {
        if shortest_at.get(a as usize) == Some(&r) && shortest_at[b as usize] == r {
            // Accepted whatever the others do (see `decide_round`).
            out.dependency_ends.push(out.dependencies.len() as u32);
            continue;
        }
        let q = Query::new(points[a as usize], points[b as usize]);
        let listed = out.dependencies.len();
        let mut blocked = false;
        index.scan_near(q.a, q.b, |s| {
            if s.id > r {
                return Step::NextCell;
            }
            if s.id == EARLIER_EDGE {
                blocked = s.crosses(&q);
            } else if points_by_scan {
                match s.crosses_or_rests_on(&q) {
                    Some(true) => out.dependencies.push(s.id - 1),
                    Some(false) => blocked = true,
                    None => {}
                }
            } else if s.crosses(&q) {
                out.dependencies.push(s.id - 1);
            }
            if blocked {
                Step::Stop
            } else {
                Step::Next
            }
        });
        if blocked || near.is_some_and(|p| p.on_segment(q.a, q.b)) {
            out.dependencies.truncate(listed);
            out.blocked.push(r);
        }
        out.dependency_ends.push(out.dependencies.len() as u32);
    }
    out
}

/// Decides one round: `candidates` in spatial order, `ranking` their
/// positions in the global segment order, `active` the earlier edges they
/// must not cross (module docs), `near` the point grid (none in round 0: see
/// [`scan_chunk`]). Returns the accepted candidates.
pub(super) fn decide_round(
    points: &[Point],
    bbox: [f64; 4],
    candidates: &[[u32; 2]],
    ranking: &Ranking,
    active: &[[u32; 2]],
    near: Option<&PointsNear>,
    first_round: bool,
) -> Vec<[u32; 2]> {
    let m = candidates.len();
    if m == 0 {
        return Vec::new();
    }
    let rank = &ranking.rank;
    // In the first round (no earlier edges) every segment shorter than the
    // threshold is a candidate, so the lowest rank at a vertex is the
    // shortest segment there. A segment shortest at both ends is a GT edge:
    // a shorter `cd` crossing `ab` would make, by the □-Lemma (Edelsbrunner
    // & Tan, *A quadratic time algorithm for the minmax length
    // triangulation*, 1991, §4),
    // `|ac| + |bd| < |ab| + |cd| < 2|ab|`, so `ac` or `bd` would be shorter
    // still; and a point on `ab` would make a shorter segment at `a`. Its
    // dependencies need not be listed.
    let shortest_at: Vec<u32> = if active.is_empty() && first_round {
        let lowest: Vec<std::sync::atomic::AtomicU32> = (0..points.len())
            .map(|_| std::sync::atomic::AtomicU32::new(NO_RANK))
            .collect();
        candidates.par_iter().zip(rank).for_each(|(&[a, b], &r)| {
            lowest[a as usize].fetch_min(r, std::sync::atomic::Ordering::Relaxed);
            lowest[b as usize].fetch_min(r, std::sync::atomic::Ordering::Relaxed);
        });
        lowest.into_iter().map(|x| x.into_inner()).collect()
    } else {
        Vec::new()
    };
    // One index of the candidates and the earlier edges (see `scan_chunk`).
    let index = {
        let segments: Vec<[u32; 2]> = candidates.iter().chain(active).copied().collect();
        let ids: Vec<u32> = rank
            .par_iter()
            .map(|&r| r + 1)
            .chain(active.par_iter().map(|_| EARLIER_EDGE))
            .collect();
        SegmentIndex::new(points, bbox, &segments, &ids)
    };

    // Pass 1, in spatial order: blocked candidates and each candidate's
    // dependencies, listed in candidate order.
    let scanned: Vec<Scanned> = candidates
        .par_chunks(CANDIDATES_PER_TASK)
        .zip(rank.par_chunks(CANDIDATES_PER_TASK))
        .map(|(segments, ranks)| scan_chunk(points, segments, ranks, &index, near, &shortest_at))
        .collect();
    drop(index);

    // The dependencies regrouped in rank order (in parallel, a scattered
    // read per candidate), so that the sequential pass 2 reads them in turn.
    let by_rank: Vec<(Vec<u32>, Vec<u32>)> = ranking
        .order
        .par_chunks(CANDIDATES_PER_TASK)
        .map(|run| {
            let mut ends = Vec::with_capacity(run.len());
            let mut flat = Vec::new();
            for &i in run {
                let i = i as usize;
                let chunk = &scanned[i / CANDIDATES_PER_TASK];
                flat.extend_from_slice(chunk.dependencies_of(i % CANDIDATES_PER_TASK));
                ends.push(flat.len() as u32);
            }
            (ends, flat)
        })
        .collect();

    // Pass 2, in the global order: the dependencies of rank `r` (ranks below
    // `r`) are decided before it.
    let mut accepted = vec![true; m];
    for chunk in &scanned {
        for &r in &chunk.blocked {
            accepted[r as usize] = false;
        }
    }
    drop(scanned);
    let mut r = 0;
    for (ends, flat) in &by_rank {
        let mut begin = 0;
        for &end in ends {
            if accepted[r] {
                let deps = &flat[begin as usize..end as usize];
                accepted[r] = deps.iter().all(|&s| !accepted[s as usize]);
            }
            begin = end;
            r += 1;
        }
    }
    candidates
        .iter()
        .zip(rank)
        .filter(|(_, &r)| accepted[r as usize])
        .map(|(s, _)| *s)
        .collect()
}
