//! Step 2, the LMT loop (module docs of `skeleton`; M. T. Dickerson, J. M.
//! Keil & M. H. Montague, *A large subgraph of the minimum weight
//! triangulation*, DCG 18, 1997; the half-edge loop of R. Beirouti & J.
//! Snoeyink, *Implementations of the LMT heuristic for minimum weight
//! triangulation*, SoCG 1998): the candidate triangles and their lists per
//! edge, the atomic triangle states, the local-minimality test and the
//! parallel loop.

use super::{loop_bytes, too_many_points, Limits, Skeleton};
use crate::kernel::{compare_lengths, orient_sign, Point};
use crate::parallel::prelude::*;
use crate::spatial::PointCells;
use std::cmp::Ordering;
use std::sync::atomic::{AtomicBool, AtomicU8, AtomicUsize, Ordering::Relaxed, Ordering::SeqCst};

/// Edges between two reads of the stop in the parallel passes (a check is
/// an atomic load and a clock read; an edge's pass costs far more).
const STOP_CADENCE: usize = 256;

/// Builds the candidate triangles of the skeleton's edges and their lists
/// per edge, runs the LMT loop (`loop_chunk` edges per parallel task) and
/// keeps the empty triangles whose three edges are left; `grid` is
/// [`point_grid`](super::super::point_grid) of `pts`. Returns the bytes
/// needed, with nothing allocated, when the triangles' count puts
/// [`loop_bytes`] over `limits.bytes` (the count stops as soon as it does).
pub(super) fn run(
    pts: &[Point],
    grid: &PointCells,
    skeleton: &mut Skeleton,
    loop_chunk: usize,
    limits: Limits,
) -> crate::error::Result<Option<usize>> {
    let (n, m) = (pts.len(), skeleton.edges.len());
    // Triangles u < v < w of candidate edges, each found from its edge
    // (u, v): the common neighbours w > v of u and v, by merging their
    // sorted lists. Whether one is empty is decided only when the loop needs
    // it (most are never asked: their edge fails the length test first).
    // Counted first, then written in place: collecting them in one pass
    // (rayon's list of growing vectors) held about twice the final array at
    // the phase's peak.
    // The count stops once the running total is over the budget (points
    // in nearly convex position: Θ(n³) triangles, whose count alone would
    // take minutes) or the run must stop.
    let sk = &*skeleton;
    let counted = AtomicUsize::new(0);
    let refused = AtomicBool::new(false);
    let over = |total: usize| loop_bytes(total, m) > limits.bytes;
    let counts: Vec<u32> = (0..m as u32)
        .into_par_iter()
        .with_min_len(256)
        .map(|e| {
            if refused.load(Relaxed)
                || ((e as usize).is_multiple_of(STOP_CADENCE) && limits.stop.reason().is_some())
            {
                refused.store(true, Relaxed);
                return 0;
            }
            let mut count = 0;
            triangles_of_edge(pts, sk, e, |_| count += 1);
            if over(counted.fetch_add(count as usize, Relaxed) + count as usize) {
                refused.store(true, Relaxed);
            }
            count
        })
        .collect();
    limits.stop.check()?;
    let total = counted.into_inner();
    if refused.into_inner() {
        // Over the budget: at least this much (the count stopped early).
        return Ok(Some(loop_bytes(total, m)));
    }
    // Triangle ids and the per-edge lists' offsets (three entries a
    // triangle) are `u32`.
    if total > u32::MAX as usize / 3 {
        let because = "u32 ids of the LMT-skeleton's candidate triangles";
        return Err(too_many_points(n, total, u32::MAX as usize / 3, because));
    }
    let mut triangles = vec![[0u32; 3]; total];
    const BLOCK: usize = 1024;
    let mut pieces = Vec::with_capacity(m.div_ceil(BLOCK));
    let mut rest: &mut [[u32; 3]] = &mut triangles;
    for start in (0..m).step_by(BLOCK) {
        let end = (start + BLOCK).min(m);
        let len: usize = counts[start..end].iter().map(|&c| c as usize).sum();
        let (head, tail) = std::mem::take(&mut rest).split_at_mut(len);
        pieces.push((start..end, head));
        rest = tail;
    }
    drop(counts);
    pieces.into_par_iter().for_each(|(range, out)| {
        let mut k = 0;
        for e in range {
            triangles_of_edge(pts, sk, e as u32, |ids| {
                out[k] = ids;
                k += 1;
            });
        }
    });
    // Per edge (CSR): its triangles on the left of u → v, then on the right,
    // each list in triangle order. The edges are cut into ranges, one task
    // each; every task reads all triangles (a stream) and counts, then fills,
    // only its own edges' lists: no atomics, the same lists on any number of
    // threads.
    let ranges: Vec<std::ops::Range<usize>> = (0..CSR_PARTS)
        .map(|k| k * m / CSR_PARTS..(k + 1) * m / CSR_PARTS)
        .collect();
    let counted: Vec<(Vec<u32>, Vec<u32>)> = ranges
        .par_iter()
        .map(|range| {
            let (mut left, mut all) = (vec![0u32; range.len()], vec![0u32; range.len()]);
            for ids in &triangles {
                for (s, &e) in ids.iter().enumerate() {
                    if range.contains(&(e as usize)) {
                        debug_assert_eq!(on_left(*ids, s), on_left_by_corners(&sk.edges, *ids, s));
                        all[e as usize - range.start] += 1;
                        left[e as usize - range.start] += on_left(*ids, s) as u32;
                    }
                }
            }
            (left, all)
        })
        .collect();
    let mut left_len = Vec::with_capacity(m);
    let mut tri_offsets = Vec::with_capacity(m + 1);
    tri_offsets.push(0u32);
    for (left, all) in counted {
        left_len.extend(left);
        for count in all {
            tri_offsets.push(tri_offsets[tri_offsets.len() - 1] + count);
        }
    }
    let mut tri_list = vec![0u32; tri_offsets[m] as usize];
    let mut pieces = Vec::with_capacity(CSR_PARTS);
    let mut rest: &mut [u32] = &mut tri_list;
    for range in &ranges {
        let len = (tri_offsets[range.end] - tri_offsets[range.start]) as usize;
        let (head, tail) = std::mem::take(&mut rest).split_at_mut(len);
        pieces.push((range.clone(), head));
        rest = tail;
    }
    pieces.into_par_iter().for_each(|(range, out)| {
        let base = tri_offsets[range.start];
        let (mut next_left, mut next_right): (Vec<u32>, Vec<u32>) = range
            .clone()
            .map(|e| (tri_offsets[e] - base, tri_offsets[e] - base + left_len[e]))
            .unzip();
        for (t, ids) in triangles.iter().enumerate() {
            for (s, &e) in ids.iter().enumerate() {
                if range.contains(&(e as usize)) {
                    let k = e as usize - range.start;
                    let next = if on_left(*ids, s) {
                        &mut next_left[k]
                    } else {
                        &mut next_right[k]
                    };
                    out[*next as usize] = t as u32;
                    *next += 1;
                }
            }
        }
    });
    // From here on the loop reads a triangle's corners (one access where the
    // edge ids need three), converted in place.
    let edges = &skeleton.edges;
    triangles
        .par_iter_mut()
        .with_min_len(4096)
        .for_each(|t| *t = corners_of(edges, *t));
    skeleton.loop_triangles = triangles;
    skeleton.tri_left_len = left_len;
    skeleton.tri_offsets = tri_offsets;
    skeleton.tri_list = tri_list;
    // The loop needs no crossings; certainty does, among the survivors only
    // (far fewer and shorter than the filter's candidates).
    let state = run_lmt_loop(pts, grid, skeleton, loop_chunk, limits.stop);
    limits.stop.check()?;
    // The per-edge triangle lists served the loop alone: freed before the
    // kept triangles are collected (the phase's peak).
    skeleton.tri_offsets = Vec::new();
    skeleton.tri_list = Vec::new();
    skeleton.tri_left_len = Vec::new();
    // Keep the empty triangles whose edges are all left (the faces' only
    // use).
    let sk = &*skeleton;
    // A removed edge killed all its triangles, so a triangle not dead has
    // its three edges left.
    let kept: Vec<([u32; 3], [u32; 3])> = (0..sk.loop_triangles.len())
        .into_par_iter()
        .with_min_len(1024)
        .filter_map(|t| {
            let corners = sk.loop_triangles[t];
            let keep = match state.get(t as u32) {
                TriangleState::EMPTY => true,
                TriangleState::UNKNOWN => !triangle_has_point(pts, grid, corners),
                _ => false, // dead or holding a point
            };
            keep.then(|| (corners, sk.triangle_edges(corners)))
        })
        .collect();
    drop(state);
    skeleton.triangles = kept;
    skeleton.loop_triangles = Vec::new();
    Ok(None)
}

/// Does the closed triangle `abc` (counter-clockwise) contain a point other
/// than its corners?
fn triangle_has_point(pts: &[Point], grid: &PointCells, [i, j, k]: [u32; 3]) -> bool {
    let (a, b, c) = (pts[i as usize], pts[j as usize], pts[k as usize]);
    let lo = [a[0].min(b[0]).min(c[0]), a[1].min(b[1]).min(c[1])];
    let hi = [a[0].max(b[0]).max(c[0]), a[1].max(b[1]).max(c[1])];
    grid.any_near(lo, hi, 0.0, |coords, _| {
        coords.iter().any(|&d| {
            // Distinct points: only the corners have their coordinates.
            if d == a || d == b || d == c {
                return false;
            }
            if d[0] < lo[0] || d[0] > hi[0] || d[1] < lo[1] || d[1] > hi[1] {
                return false; // outside the box, exactly (coordinate comparison)
            }
            orient_sign(a, b, d) >= 0 && orient_sign(b, c, d) >= 0 && orient_sign(c, a, d) >= 0
        })
    })
}

/// Edge ranges of the triangle lists' construction (one per core of the
/// machines measured; each costs a read of all triangles per pass).
const CSR_PARTS: usize = 2;

/// Is the triangle with edge ids `ids` (as [`triangles_of_edge`] gives
/// them) on the left of its edge `ids[s]` directed from the smaller to the
/// larger index? With corners `u < v < w` the ids are `[uv, vw, uw]` when
/// `uvw` turns left (left of `u → v` and `v → w`, right of `u → w`) and
/// `[uw, vw, uv]` otherwise (left of `u → w` only); edges are sorted pairs,
/// so `uv` has the smaller id of `uv` and `uw`, which tells the two apart.
fn on_left(ids: [u32; 3], s: usize) -> bool {
    s == 0 || (s == 1 && ids[0] < ids[2])
}

/// [`on_left`] from the corners (the definition), for the debug checks.
fn on_left_by_corners(edges: &[[u32; 2]], ids: [u32; 3], s: usize) -> bool {
    let corners = corners_of(edges, ids);
    corners[s] < corners[(s + 1) % 3]
}

/// The counter-clockwise corners of a triangle given by its edge ids
/// `[c0c1, c1c2, c2c0]`: `c1` is the endpoint its first two edges share.
fn corners_of(edges: &[[u32; 2]], [a, b, _]: [u32; 3]) -> [u32; 3] {
    let ([x, y], [z, w]) = (edges[a as usize], edges[b as usize]);
    let c1 = if x == z || x == w { x } else { y };
    let c0 = if x == c1 { y } else { x };
    let c2 = if z == c1 { w } else { z };
    [c0, c1, c2]
}

/// Visits the non-flat triangles `u < v < w` of candidate edges found from
/// edge `e = (u, v)` (the common neighbours `w > v` of `u` and `v`, by
/// merging their sorted lists), as edge ids in counter-clockwise order of
/// the corners. Emptiness is decided lazily, in the loop.
fn triangles_of_edge(pts: &[Point], sk: &Skeleton, e: u32, mut visit: impl FnMut([u32; 3])) {
    let [u, v] = sk.edges[e as usize];
    let (nu, nv) = (sk.neighbours(u), sk.neighbours(v));
    let (mut i, mut j) = (
        nu.partition_point(|x| x.0 <= v),
        nv.partition_point(|x| x.0 <= v),
    );
    while i < nu.len() && j < nv.len() {
        let ((w, uw), (x, vw)) = (nu[i], nv[j]);
        match w.cmp(&x) {
            Ordering::Less => i += 1,
            Ordering::Greater => j += 1,
            Ordering::Equal => {
                i += 1;
                j += 1;
                let o = orient_sign(pts[u as usize], pts[v as usize], pts[w as usize]);
                if o > 0 {
                    visit([e, vw, uw]); // corners u, v, w
                } else if o < 0 {
                    visit([uw, vw, e]); // corners u, w, v
                }
            }
        }
    }
}

/// What the LMT loop knows of each candidate triangle, as bits that only
/// get set (so the loop's threads may record emptiness concurrently:
/// the value recorded is a fact about the points, whoever computes it).
struct TriangleState(Vec<AtomicU8>);

impl TriangleState {
    /// Not yet tested for emptiness, no edge removed.
    const UNKNOWN: u8 = 0;
    /// Tested: no point but its corners in the closed triangle.
    const EMPTY: u8 = 1;
    /// Tested: a point inside; never valid.
    const HOLDS_POINT: u8 = 2;
    /// An edge removed; never valid again.
    const DEAD: u8 = 4;

    fn new(len: usize) -> Self {
        TriangleState((0..len).map(|_| AtomicU8::new(Self::UNKNOWN)).collect())
    }

    fn get(&self, t: u32) -> u8 {
        self.0[t as usize].load(SeqCst)
    }

    /// Certainly not valid (an edge removed, or a point inside)?
    fn invalid(&self, t: u32) -> bool {
        self.get(t) & (Self::HOLDS_POINT | Self::DEAD) != 0
    }

    /// Marks `t` dead; returns its bits before.
    fn kill(&self, t: u32) -> u8 {
        self.0[t as usize].fetch_or(Self::DEAD, SeqCst)
    }
}

/// The corner of a triangle (`corners`) that is not on its side `uv`.
#[inline]
fn apex_of([c0, c1, c2]: [u32; 3], u: u32, v: u32) -> u32 {
    if c0 != u && c0 != v {
        c0
    } else if c1 != u && c1 != v {
        c1
    } else {
        c2
    }
}

/// Is triangle `t` valid (no edge removed and empty)? Decides emptiness on
/// first use.
fn valid_triangle(
    pts: &[Point],
    grid: &PointCells,
    sk: &Skeleton,
    state: &TriangleState,
    t: u32,
) -> bool {
    let mut bits = state.get(t);
    if bits & (TriangleState::EMPTY | TriangleState::HOLDS_POINT) == 0 {
        let found = if triangle_has_point(pts, grid, sk.loop_triangles[t as usize]) {
            TriangleState::HOLDS_POINT
        } else {
            TriangleState::EMPTY
        };
        bits = state.0[t as usize].fetch_or(found, SeqCst) | found;
    }
    bits == TriangleState::EMPTY
}

/// Is `e` locally minimal for some pair of valid triangles? The pair's
/// shape (not a strictly convex quadrilateral, or `e` not longer than the
/// other diagonal) is tested first, emptiness only for a pair that passes.
/// `apexes` is scratch space for the right side's apexes.
fn locally_minimal(
    pts: &[Point],
    grid: &PointCells,
    sk: &Skeleton,
    state: &TriangleState,
    e: u32,
    apexes: &mut Vec<Option<Point>>,
) -> bool {
    let [u, v] = sk.edges[e as usize];
    let (left, right) = sk.sides(e);
    let apex = |t: u32| pts[apex_of(sk.loop_triangles[t as usize], u, v) as usize];
    // The right apexes are found once each, when first needed (the first
    // pairs usually decide).
    apexes.clear();
    apexes.resize(right.len(), None);
    let (a, b) = (pts[u as usize], pts[v as usize]);
    for &tl in left {
        if state.invalid(tl) {
            continue;
        }
        let r = apex(tl);
        for (&tr, slot) in right.iter().zip(apexes.iter_mut()) {
            if state.invalid(tr) {
                continue;
            }
            let s = *slot.get_or_insert_with(|| apex(tr));
            // The length first: when `e` is not longer, the pair passes
            // without the convexity test (the conjunction is unchanged).
            if compare_lengths(a, b, r, s) == Ordering::Greater
                && crosses_from_both_sides(a, b, r, s)
            {
                continue;
            }
            if !valid_triangle(pts, grid, sk, state, tl) {
                break; // tl holds a point: no pair with it
            }
            if valid_triangle(pts, grid, sk, state, tr) {
                return true;
            }
        }
    }
    false
}

/// Does `rs` properly cross `ab`, given `r` strictly left and `s` strictly
/// right of the line `ab` (the apexes of a left and a right triangle of
/// `ab`)? `rs` then meets the line `ab` in one point, inside the segment iff
/// `a` and `b` lie strictly on either side of the line `rs`: two of
/// [`properly_cross`](crate::kernel::properly_cross)'s four orientations.
#[inline]
fn crosses_from_both_sides(a: Point, b: Point, r: Point, s: Point) -> bool {
    debug_assert!(orient_sign(a, b, r) > 0 && orient_sign(a, b, s) < 0);
    orient_sign(r, s, a) * orient_sign(r, s, b) < 0
}

/// Consecutive edges (in Z-order, so nearby) per parallel task of the loop.
pub(crate) const LOOP_CHUNK: usize = 1024;

/// The LMT loop, in parallel; returns the triangles' final states.
///
/// A triangle dies once one of its edges is removed; only an edge whose
/// local minimality rested on a triangle known to be empty can lose it, so
/// only the other edges of such a triangle are queued again (an untested
/// triangle supported none). Each task takes a run of edges and works off
/// the edges its removals queue again before the next, as the sequential
/// loop would. The threads share the triangle states, the alive flags and
/// the queued flags (sequentially consistent atomics), and the result is
/// the sequential loop's:
/// * an edge is removed only when every pair of its triangles was seen
///   invalid, and a triangle seen dead or holding a point stays so, so no
///   edge of the skeleton (the greatest fixed point of the rule; removing an
///   edge only invalidates triangles) is ever removed;
/// * when a triangle known to be empty dies, every edge that may have
///   rested on it is tested again after the death: either its queued flag
///   was clear and the killer queues it, or the flag was still set and the
///   edge's pending test clears it after the death and reads the triangle
///   dead. So when all tasks are done, every edge left is locally minimal.
///
/// When `stop` says so, the tasks not yet started return at once and the
/// states are incomplete (the caller checks `stop` and drops them).
fn run_lmt_loop(
    pts: &[Point],
    grid: &PointCells,
    sk: &mut Skeleton,
    chunk: usize,
    stop: &crate::interrupt::Stop,
) -> TriangleState {
    let chunk = chunk.max(1);
    let m = sk.edges.len();
    let state = TriangleState::new(sk.loop_triangles.len());
    let flags =
        |value: bool| -> Vec<AtomicBool> { (0..m).map(|_| AtomicBool::new(value)).collect() };
    let (alive, queued) = (flags(true), flags(true));
    let skr = &*sk;
    let process = |e: u32, apexes: &mut Vec<Option<Point>>, stack: &mut Vec<u32>| {
        queued[e as usize].store(false, SeqCst);
        if !alive[e as usize].load(SeqCst)
            || skr.hull[e as usize]
            || locally_minimal(pts, grid, skr, &state, e, apexes)
        {
            return;
        }
        alive[e as usize].store(false, SeqCst);
        let (left, right) = skr.sides(e);
        for &t in left.iter().chain(right) {
            // Exactly one removal sees a supporting triangle die.
            if state.kill(t) != TriangleState::EMPTY {
                continue;
            }
            let [u, v] = skr.edges[e as usize];
            let w = apex_of(skr.loop_triangles[t as usize], u, v);
            // Its other two sides (`e` itself is no longer alive).
            for f in [skr.edge_id(u, w), skr.edge_id(v, w)] {
                let f = f.expect("a loop triangle's sides are candidate edges");
                if alive[f as usize].load(SeqCst)
                    && !skr.hull[f as usize]
                    && !queued[f as usize].swap(true, SeqCst)
                {
                    stack.push(f);
                }
            }
        }
    };
    let stopped = AtomicBool::new(false);
    (0..m.div_ceil(chunk)).into_par_iter().for_each(|k| {
        if stopped.load(Relaxed) || stop.reason().is_some() {
            stopped.store(true, Relaxed);
            return;
        }
        let (mut apexes, mut stack) = (Vec::new(), Vec::new());
        for e in k * chunk..m.min(k.saturating_add(1).saturating_mul(chunk)) {
            process(e as u32, &mut apexes, &mut stack);
            while let Some(f) = stack.pop() {
                process(f, &mut apexes, &mut stack);
            }
        }
    });
    for (flag, a) in sk.alive.iter_mut().zip(alive) {
        *flag = a.into_inner();
    }
    state
}
