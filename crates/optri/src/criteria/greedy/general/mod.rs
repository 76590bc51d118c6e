//! GT of arbitrary point sets: the idea of M. T. Dickerson, R. L. S.
//! Drysdale, S. A. McElfresh & E. Welzl, *Fast greedy triangulation
//! algorithms*, Computational Geometry 8 (1997), of processing only plausible
//! candidates (literature.md §b), made exact and cache-friendly.
//!
//! # Length rounds
//! Round `k` takes candidate pairs whose exact length lies in
//! `[T_{k-1}, T_k)`: in round 0 every pair shorter than `T_0`, later only
//! pairs of still-open vertices (below). Rounds are disjoint length ranges,
//! so every pair shorter than `T_{k-1}` has been decided when round `k`
//! starts. `T_0` is about 1.6 mean point spacings and `T_k = 2 T_{k-1}`
//! (more after rounds with few candidates: `guard::next_growth`, for points
//! at several length scales), unless a guard (`round_grid`) finds that the pairs within the proposed
//! threshold are too many — in total, or in one cell and its neighbours, as
//! in a dense cluster — and halves the step until they are not; the grids
//! store only occupied cells, so their cells can follow the threshold
//! however uneven the density. These choices only affect the running time.
//!
//! # Deciding a round without following the length order
//! The naive algorithm accepts a segment iff it contains no point and crosses
//! no *accepted shorter* segment. So the decision of candidate `r` depends
//! only on the decisions of the shorter candidates that cross it (its
//! *dependencies*) and on edges of earlier rounds: any evaluation order in
//! which dependencies come first gives the naive result. A round therefore
//! runs in two passes:
//! 1. in parallel and in spatial (Z-order) order — the expensive part —
//!    every candidate is tested against the points and earlier edges near it,
//!    and its dependencies are listed;
//! 2. in the global segment order, `accepted[r] = !blocked[r]` and no
//!    dependency accepted — a cheap pass over small integer arrays.
//!
//! The global order is thus only followed where it matters; the previous
//! design tested each candidate against the partial GT in length order, a
//! random walk through memory that cost ~1.4 µs a candidate at 10⁶ points.
//! In round 0 a segment that is the shortest at both of its endpoints needs
//! no dependency list: it is a GT edge (`decide_round`).
//!
//! # Earlier edges: only the *active* ones
//! **Lemma (empty triangles).** If every pair shorter than `ℓ` has been
//! decided and `u, w` are consecutive neighbours of `v` with `uw ∈ G`,
//! `|vu|, |vw|, |uw| < ℓ` and a left turn `v, u, w`, the triangle `vuw` holds
//! no point. *Proof:* all segments between points of the closed triangle are
//! shorter than `ℓ` and cannot cross the triangle's sides, so `G` restricted
//! to them is a maximal non-crossing set, i.e. a triangulation of those
//! points; with a point inside, `v` would have an edge into the triangle,
//! between `u` and `w`. ∎
//!
//! Call such a triangle *closed*, a vertex *closed* when every angular gap at
//! it is a closed triangle or the outer gap between its hull neighbours (no
//! further edge can reach it), and an edge *active* when both endpoints are
//! open and a side of it is not a closed triangle. Candidates of round `k ≥ 1`
//! join two open vertices and must leave both through an open gap (the
//! direction is not an existing edge's, which would put a point on the
//! segment, and is not inside a closed triangle, whose third side it would
//! cross). **Claim:** such a candidate `ab` with no point on it that crosses
//! an earlier edge crosses an active one. *Proof:* walk along `ab` from a
//! crossing of an inactive edge towards `a`; the walk runs through closed
//! triangles and leaves each through a side (not through a vertex: no point
//! on `ab`; not through `a`: `a`'s gap is open). A side whose far face is not
//! closed has both endpoints open (a closed endpoint's gaps are all closed
//! triangles) and is not a hull edge, so it is active. ∎ So round `k ≥ 1`
//! tests candidates only against active edges, which shrink with the open
//! vertices.
//!
//! The final round (once `T_k` exceeds the bounding-box diagonal) takes all
//! remaining pairs of open vertices; that is quadratic in their number, which
//! is why convex inputs go to [`super::convex`].
//!
//! # Collinear points
//! A *fan* (all points but one on a line) has one triangulation, returned
//! directly (`single_fan`). Open vertices whose open gaps are all straight
//! angles on one line form *line classes* (`line_classes`): no candidate
//! joins two points of a class, so their pairs are neither listed nor
//! counted by the guard. Both only change the running time. Runs with
//! several apexes still make the rounds crawl (issue 15, open).
//!
//! # Files
//! | file | what | implements |
//! |---|---|---|
//! | `mod.rs` | the rounds driver: thresholds, candidates, the two passes | "Length rounds", "Deciding a round…" |
//! | [`partial`] | the partial triangulation: closed triangles, closed vertices, active edges | the Lemma and the Claim |
//! | [`segment_index`] | what a candidate may cross, and whether a point lies on it | pass 1's tests |
//! | [`guard`] | the density guard choosing each round's threshold | "Length rounds" (the guard) |
//!
//! The cells behind every lookup are [`crate::spatial::SparseGrid`]s.

mod guard;
mod partial;
mod segment_index;

use crate::error::{Error, Result};
use crate::kernel::{
    compare_equal_lengths_symbolic, compare_lengths, exact_squared_length, orient_sign,
    shorter_than, Point,
};
use crate::parallel::prelude::*;
use crate::spatial::{
    bounding_box, fmax, fmin, inverse_permutation, keyed_by_length, morton_order, sort_keyed_runs,
    sort_runs,
};
use crate::timing::{Phase, Stopwatch};
use guard::{next_floor, next_growth, round_grid, MIN_RELATIVE_STEP, NO_LINE, THRESHOLD_GROWTH};
use partial::{OpenGaps, Partial};
use segment_index::{PointsNear, Query, SegmentIndex, Step};

/// No candidate at a vertex yet (the lowest rank found so far).
const NO_RANK: u32 = u32::MAX;

/// Round 0's proposed threshold `T_0`, in mean point spacings. A tuning
/// choice (only the running time depends on it): uniform points then have
/// about 2.6 points a cell.
const FIRST_THRESHOLD_SPACINGS: f64 = 1.6;

/// For the mean spacing, each side of the bounding box counts as at least
/// this fraction of the other, so that a nearly flat box does not get a
/// spacing near zero. A chosen value.
const MIN_ASPECT: f64 = 1e-6;

/// The last round (every remaining pair, whatever its length) starts once
/// the threshold exceeds the rounded bounding-box diagonal by this factor, a
/// chosen margin over the diagonal's rounding. Correctness does not depend
/// on it: a round whose threshold exceeds every pair's length takes them all.
const LAST_ROUND_MARGIN: f64 = 1.01;

/// Cost model for coarsening the point grid: a round's point queries cost
/// about `QUERIES_PER_OPEN_VERTEX · open · ratio²` cells (`ratio` the
/// round's cell size over the grid's) against `REBUILD_COST_PER_POINT · n`
/// for rebuilding the grid, and a rebuild must coarsen it by more than
/// `MIN_COARSENING`. Tuning choices: commit 03a8948 measured the coarsening
/// as a whole (clustered 10⁶ points: 8.4 s → 7.2 s), not these factors.
const QUERIES_PER_OPEN_VERTEX: usize = 8;
const REBUILD_COST_PER_POINT: usize = 4;
const MIN_COARSENING: f64 = 4.0;

/// Open vertices per parallel task when listing candidates, and candidates
/// per task in pass 1. Tuning choices: large enough that a task's overhead
/// is small against its work, small enough for hundreds of tasks at 10⁶
/// points. Results do not depend on them.
const OPEN_VERTICES_PER_TASK: usize = 4096;
const CANDIDATES_PER_TASK: usize = 4096;

/// GT triangles of `points` (distinct, not all collinear), counter-clockwise;
/// `hull` is their [`convex_hull_cycle`](crate::spatial::convex_hull_cycle) (computed once, by the caller's
/// shape test).
///
/// Works on a copy renumbered in Z-order, so that neighbouring vertices sit
/// close in memory; ties are broken on the original indices, because the
/// symbolic perturbation depends on them: the renumbered copy is only used
/// where an index never decides a tie.
pub(super) fn greedy_general(
    original: &[Point],
    hull: &[u32],
    phases: &mut Vec<Phase>,
) -> Result<Vec<[u32; 3]>> {
    if let Some(fan) = single_fan(original) {
        return Ok(fan);
    }
    let to_original = morton_order(original);
    let local: Vec<Point> = to_original.iter().map(|&v| original[v as usize]).collect();
    // The hull in local indices: the same cycle `convex_hull_cycle(&local)`
    // returns, as it depends only on the coordinates (distinct points,
    // lexicographic start).
    let to_local = inverse_permutation(&to_original);
    let hull: Vec<u32> = hull.iter().map(|&v| to_local[v as usize]).collect();
    drop(to_local);
    let renumbering = Renumbering {
        to_original: &to_original,
    };
    let mut triangles: Vec<[u32; 3]> = greedy_rounds(&local, &hull, &renumbering, phases)?
        .into_par_iter()
        .map(|t| smallest_corner_first(t.map(|v| to_original[v as usize])))
        .collect();
    // Sorted, as the Delaunay triangles are (`canonical_order` in
    // `structures::delaunay_graph`): the edge list every consumer builds
    // (`Triangulation::edges`, sorted) then starts from nearly sorted pairs,
    // not from pairs in spatial order, which are random in the input's
    // numbering (1 s of a 10⁶-point CLI run's writing).
    triangles.par_sort_unstable();
    Ok(triangles)
}

/// The same triangle (same orientation) rotated to start at its smallest
/// index.
fn smallest_corner_first(t: [u32; 3]) -> [u32; 3] {
    let [a, b, c] = t;
    if a < b && a < c {
        t
    } else if b < c {
        [b, c, a]
    } else {
        [c, a, b]
    }
}

/// The triangles of a *fan* — all points but one on a line — whose only
/// triangulation (hence GT) joins the apex to every point of the line and
/// consecutive line points to each other; `None` for any other input.
///
/// Why a shortcut: the line points stay open until the apex reaches them,
/// and every pair of them lies in the density guard's cells, so the length
/// rounds would crawl (issue 15: 157 s at 10⁴ points). The test is exact
/// (orientations and coordinate comparisons) and costs O(1) on most inputs:
/// it stops at the second point off a line.
pub(super) fn single_fan(points: &[Point]) -> Option<Vec<[u32; 3]>> {
    let n = points.len();
    if n < 4 {
        return None;
    }
    // The line holds n - 1 points, so two of the first three lie on it.
    let apex = [(0, 1), (0, 2), (1, 2)].into_iter().find_map(|(i, j)| {
        let (pi, pj) = (points[i], points[j]);
        let mut off = (0..n).filter(|&z| orient_sign(pi, pj, points[z]) != 0);
        let first = off.next()?;
        off.next().is_none().then_some(first)
    })?;
    let mut line: Vec<u32> = (0..n as u32).filter(|&v| v as usize != apex).collect();
    // On a line, lexicographic order is the order along it.
    line.sort_unstable_by(|&a, &b| {
        let (p, q) = (points[a as usize], points[b as usize]);
        p[0].total_cmp(&q[0]).then(p[1].total_cmp(&q[1]))
    });
    let pa = points[apex];
    let ccw = orient_sign(pa, points[line[0] as usize], points[line[1] as usize]) > 0;
    let apex = apex as u32;
    let mut triangles: Vec<[u32; 3]> = line
        .windows(2)
        .map(|w| {
            smallest_corner_first(if ccw {
                [apex, w[0], w[1]]
            } else {
                [apex, w[1], w[0]]
            })
        })
        .collect();
    // In the order of the other paths' output (see `greedy_general`).
    triangles.sort_unstable();
    Some(triangles)
}

/// Local (memory-friendly) numbering versus the caller's, which decides ties.
struct Renumbering<'a> {
    to_original: &'a [u32],
}

/// Original indices below this fit [`Renumbering::tie_key`]'s 31 bits.
const TIE_KEY_INDEX_LIMIT: usize = 1 << 31;

impl Renumbering<'_> {
    /// The global segment order of local-index segments (exact), both ways.
    ///
    /// That order is [`crate::kernel::segment_order`] on the original
    /// indices; the local copy holds the same coordinates, so lengths are
    /// compared there and only ties look at the original indices
    /// ([`compare_equal_lengths_symbolic`]). When `f64` computes every
    /// squared length exactly (integer coordinates, as from a file of
    /// six-decimal points, where ties are common: [`exact_squared_length`]),
    /// the order is that of one integer key per segment
    /// ([`Self::order_by_key`]); otherwise [`Self::order_by_comparison`].
    fn ranking(&self, points: &[Point], segments: &[[u32; 2]]) -> Ranking {
        let order = self
            .order_by_key(points, segments)
            .unwrap_or_else(|| self.order_by_comparison(points, segments));
        Ranking {
            rank: inverse_permutation(&order),
            order,
        }
    }

    /// [`Self::ranking`]'s order by sorting one `u128` per segment — its
    /// exact squared length (64 bits), [`Self::tie_key`] (32 bits) and its
    /// own index (32 bits) — then, in the rare runs that agree on the first
    /// 96 bits, by the other endpoint's `(y, x)` (descending); `None` if a
    /// squared length is not exact in `f64` (or there are too many points
    /// for the key). Each key is computed from the segment's own endpoints,
    /// in the candidates' spatial order; the comparison sort it replaces read
    /// every tied segment's endpoints at random (a fifth of greedy's time on
    /// a 10⁶-point CLI run), and a key holding the `(y, x)` position too
    /// needed a sort of the points and twice the bytes a segment.
    fn order_by_key(&self, points: &[Point], segments: &[[u32; 2]]) -> Option<Vec<u32>> {
        if points.len() > TIE_KEY_INDEX_LIMIT || segments.len() > u32::MAX as usize {
            return None;
        }
        let lengths: Option<Vec<f64>> = segments
            .par_iter()
            .map(|&[a, b]| exact_squared_length(points[a as usize], points[b as usize]))
            .collect();
        let lengths = lengths?;
        let mut keys: Vec<u128> = segments
            .par_iter()
            .zip(lengths)
            .enumerate()
            .map(|(i, (&s, length))| {
                // Non-negative doubles order as their bit patterns.
                (u128::from(length.to_bits()) << 64)
                    | (u128::from(self.tie_key(points, s)) << 32)
                    | i as u128
            })
            .collect();
        keys.par_sort_unstable();
        // Runs of one length and one tie key: segments sharing the endpoint
        // of lower original index, with the same length and the same kind.
        let far = |key: u128| {
            let [a, b] = segments[key as u32 as usize];
            let u = if self.to_original[a as usize] < self.to_original[b as usize] {
                b
            } else {
                a
            };
            let p = points[u as usize];
            (p[1], p[0])
        };
        sort_runs(
            &mut keys,
            |x, y| x >> 32 == y >> 32,
            |_: &mut (), run| {
                // Descending `(y, x)` of the far endpoint: distinct points.
                run.sort_unstable_by(|&x, &y| {
                    far(y).partial_cmp(&far(x)).expect("finite coordinates")
                });
            },
        );
        Some(keys.into_par_iter().map(|k| k as u32).collect())
    }

    /// The order of [`compare_equal_lengths_symbolic`] among segments of
    /// one exact length, but for the last criterion: with `m` a segment's
    /// lower original index and `u` its other endpoint, a segment whose `m`
    /// lies strictly below `u` is shorter than every segment of larger `m`,
    /// one whose `m` does not is longer, and at equal `m` the segment with
    /// the higher `u` in `(y, x)` order is shorter. So the shorter come
    /// first as: the first kind by ascending `m`, then the second by
    /// descending `m`; within one `m`, by descending `u` (left to
    /// [`Self::order_by_key`]'s runs). Key: the kind (1 bit), then `m` or
    /// its complement (31 bits).
    fn tie_key(&self, points: &[Point], [a, b]: [u32; 2]) -> u32 {
        let (oa, ob) = (self.to_original[a as usize], self.to_original[b as usize]);
        let ((m, pm), u) = if oa < ob {
            ((oa, points[a as usize]), b)
        } else {
            ((ob, points[b as usize]), a)
        };
        let holder_longer = pm[1] >= points[u as usize][1];
        if holder_longer {
            (1u32 << 31) | (TIE_KEY_INDEX_LIMIT as u32 - 1 - m)
        } else {
            m
        }
    }

    /// [`Self::ranking`]'s order by the exact comparison (see
    /// [`sort_keyed_runs`]): squared lengths that `f64` computes
    /// exactly are compared as numbers, the others by [`compare_lengths`].
    fn order_by_comparison(&self, points: &[Point], segments: &[[u32; 2]]) -> Vec<u32> {
        let mut keyed = keyed_by_length(points, segments, |i, _| i as u32);
        let gather = |i: u32| {
            let ends =
                segments[i as usize].map(|v| (self.to_original[v as usize], points[v as usize]));
            (ends, exact_squared_length(ends[0].1, ends[1].1))
        };
        type Gathered = ([(u32, Point); 2], Option<f64>);
        let exact = |x: &Gathered, y: &Gathered| {
            let ([a, b], [c, d]) = (x.0, y.0);
            match (x.1, y.1) {
                (Some(s), Some(t)) => s.total_cmp(&t),
                _ => compare_lengths(a.1, b.1, c.1, d.1),
            }
            .then_with(|| compare_equal_lengths_symbolic(x.0, y.0))
        };
        sort_keyed_runs(&mut keyed, gather, exact);
        keyed.into_par_iter().map(|(_, i)| i).collect()
    }
}

/// The global segment order of a round's candidates (indices into the
/// candidate list): `order[r]` is the candidate of rank `r`, `rank[i]` the
/// rank of candidate `i`.
struct Ranking {
    order: Vec<u32>,
    rank: Vec<u32>,
}

/// The length rounds of the module docs on `points` (local numbering; ties
/// through `renumbering`): the GT's triangles, each by its smallest corner.
fn greedy_rounds(
    points: &[Point],
    hull: &[u32],
    renumbering: &Renumbering,
    phases: &mut Vec<Phase>,
) -> Result<Vec<[u32; 3]>> {
    let mut stopwatch = Stopwatch::new(phases);
    let n = points.len();
    let bbox = bounding_box(points);
    let (w, h) = (bbox[2] - bbox[0], bbox[3] - bbox[1]);
    let mut g = Partial::new(points, hull);
    let target = 3 * n - 3 - hull.len();
    let diagonal = (w * w + h * h).sqrt();
    // `T_0` is about 1.6 mean spacings (a flat box still gets a sensible
    // one); the guard in `round_grid` shrinks it where the points are denser.
    let spacing = ((fmax(w, h * MIN_ASPECT) * fmax(h, w * MIN_ASPECT)) / n as f64).sqrt();
    let mut open: Vec<u32> = (0..n as u32).collect();
    // The open gaps of each open vertex (`Partial::still_open`; none before
    // the first edges).
    let mut gaps = OpenGaps::none(n);
    let mut near: Option<PointsNear> = None;
    let mut lower = 0.0;
    let mut round = 0;
    let mut floor = MIN_RELATIVE_STEP;
    let mut growth = THRESHOLD_GROWTH;
    while g.edge_count() < target && !open.is_empty() {
        debug_assert!(open.windows(2).all(|w| w[0] < w[1]), "open is ascending");
        let proposed = if round == 0 {
            FIRST_THRESHOLD_SPACINGS * spacing
        } else {
            growth * lower
        };
        let class = line_classes(points, &open, &gaps);
        let (threshold, grid) = round_grid(points, bbox, &open, &class, lower, proposed, floor);
        // Once every pair is shorter than the threshold, take all the rest.
        let last = threshold > LAST_ROUND_MARGIN * diagonal;
        // The point grid answers "a point on this segment?" from round 1 on
        // (round 0 finds such points in its segment scan); a query costs
        // about (length / cell)² cells, so coarsen it when the round's
        // candidates would cost more than rebuilding it (O(n)).
        let cell = fmin(threshold, diagonal);
        let coarsen = near.as_ref().is_some_and(|p| {
            let ratio = cell * p.inverse_cell();
            (ratio * ratio) * (QUERIES_PER_OPEN_VERTEX * open.len()) as f64
                > (REBUILD_COST_PER_POINT * n) as f64
                && ratio > MIN_COARSENING
        });
        if round > 0 && (near.is_none() || coarsen) {
            near = Some(PointsNear::new(points, bbox, cell));
        }
        // Pairs `open[i], open[j]` in the length range that may leave both
        // endpoints.
        let keep = |i: usize, j: usize| {
            let (a, b) = (open[i], open[j]);
            let (pa, pb) = (points[a as usize], points[b as usize]);
            !shorter_than(pa, pb, lower)
                && (last || shorter_than(pa, pb, threshold))
                && g.leaves_through(a, gaps.get(i), b)
                && g.leaves_through(b, gaps.get(j), a)
        };
        let candidates: Vec<[u32; 2]> = (0..open.len())
            .into_par_iter()
            .chunks(OPEN_VERTICES_PER_TASK)
            .map(|chunk| {
                let mut out = Vec::new();
                for i in chunk {
                    let (v, pv) = (open[i], points[open[i] as usize]);
                    // Cells a little wider than the threshold: close pairs
                    // sit in neighbouring cells (all cells, in the last round).
                    let reach = if last { diagonal } else { threshold };
                    let c = class[i];
                    grid.any_cell_near(pv, pv, reach, |cell| {
                        // Cells are sorted by class; skip `v`'s own line.
                        let (lo, hi) = if c == NO_LINE {
                            (cell.len(), cell.len())
                        } else {
                            (
                                cell.partition_point(|&j| class[j as usize] < c),
                                cell.partition_point(|&j| class[j as usize] <= c),
                            )
                        };
                        // `open` is ascending, so `j > i` is `open[j] > v`
                        // without a load.
                        for &j in cell[..lo].iter().chain(&cell[hi..]) {
                            if j as usize > i && keep(i, j as usize) {
                                out.push([v, open[j as usize]]);
                            }
                        }
                        false
                    });
                }
                out
            })
            .collect::<Vec<Vec<[u32; 2]>>>()
            .concat();
        drop(grid);
        let ranking = renumbering.ranking(points, &candidates);
        let mut is_open = vec![false; n];
        for &v in &open {
            is_open[v as usize] = true;
        }
        let active: Vec<[u32; 2]> = open
            .par_iter()
            .enumerate()
            .fold(Vec::new, |mut out, (i, &v)| {
                g.active_edges_at(v, gaps.get(i), &is_open, &mut out);
                out
            })
            .flatten()
            .collect();
        let accepted = decide_round(
            points,
            bbox,
            &candidates,
            &ranking,
            &active,
            near.as_ref(),
            round == 0,
        );
        g.add(&accepted);
        floor = next_floor(floor, candidates.len(), open.len());
        growth = next_growth(growth, candidates.len(), open.len());
        // The vertices still open keep their gaps for the next round.
        (open, gaps) = g.still_open(&open, OPEN_VERTICES_PER_TASK);
        if round == 0 {
            stopwatch.lap("round 0");
        }
        if last {
            break;
        }
        lower = threshold;
        round += 1;
    }
    stopwatch.lap("later rounds");
    if g.edge_count() != target {
        return Err(Error::Internal(format!(
            "the greedy triangulation has {} of {target} edges",
            g.edge_count()
        )));
    }
    let triangles = g.triangles();
    stopwatch.lap("triangles");
    Ok(triangles)
}

/// Line classes of the open vertices (indices into `open`), for the guard
/// and the candidate listing: a vertex `v` whose open gaps are all straight
/// angles (each bounded by two neighbours collinear with `v`, so all of them
/// lie on one line `L` through `v`) can only be left strictly off `L`, so no
/// candidate joins it to another point of `L`. Chains of such vertices along
/// one line (each the other's gap neighbour) share a class, the smallest
/// open index in the chain; any other vertex gets [`NO_LINE`]. Pairs within
/// a class are skipped unlisted: a run of collinear points waiting for a
/// far apex would otherwise fill the guard's cells with hopeless pairs and
/// hold the threshold down for thousands of rounds (issue 15: a run of 1000
/// points with two apexes took 8.8 s). Only the running time depends on the
/// classes: the skipped pairs fail `leaves_through` anyway.
fn line_classes(points: &[Point], open: &[u32], gaps: &OpenGaps) -> Vec<u32> {
    let p = |v: u32| points[v as usize];
    // A gap neighbour of each straight-angle vertex (`NO_LINE` if none).
    let line_neighbour: Vec<u32> = open
        .par_iter()
        .enumerate()
        .map(|(i, &v)| match gaps.get(i) {
            Some(list)
                if !list.is_empty()
                    && list
                        .iter()
                        .all(|&[u, w]| orient_sign(p(v), p(u), p(w)) == 0) =>
            {
                list[0][0]
            }
            _ => NO_LINE,
        })
        .collect();
    if line_neighbour.iter().all(|&u| u == NO_LINE) {
        return line_neighbour;
    }
    let mut index = vec![NO_LINE; points.len()];
    for (i, &v) in open.iter().enumerate() {
        index[v as usize] = i as u32;
    }
    // Union-find over open indices: `v` joins the gap neighbours of its own
    // gaps that are straight-angle vertices of the same line.
    let mut parent: Vec<u32> = (0..open.len() as u32).collect();
    fn root(parent: &mut [u32], mut x: u32) -> u32 {
        while parent[x as usize] != x {
            let up = parent[parent[x as usize] as usize];
            parent[x as usize] = up;
            x = up;
        }
        x
    }
    for (i, &v) in open.iter().enumerate() {
        if line_neighbour[i] == NO_LINE {
            continue;
        }
        for &[u, w] in gaps.get(i).unwrap_or_default() {
            for x in [u, w] {
                let j = index[x as usize];
                // `x` is on `v`'s line; it shares the line if its own line
                // passes through `v`.
                if j != NO_LINE
                    && line_neighbour[j as usize] != NO_LINE
                    && orient_sign(p(x), p(line_neighbour[j as usize]), p(v)) == 0
                {
                    let (a, b) = (root(&mut parent, i as u32), root(&mut parent, j));
                    parent[a.max(b) as usize] = a.min(b);
                }
            }
        }
    }
    let chain: Vec<u32> = (0..open.len())
        .map(|i| {
            if line_neighbour[i] == NO_LINE {
                NO_LINE
            } else {
                root(&mut parent, i as u32)
            }
        })
        .collect();
    merge_chains_on_one_line(points, open, &line_neighbour, chain)
}

/// Joins the chains of [`line_classes`] that lie on one line into one class.
///
/// A closed vertex or a vertex with a non-straight open gap (the end of an
/// apex's fan) cuts a run into several chains, and the pairs between them
/// would fill the guard's cells (issue 15: a run of 1000 points with two
/// apexes crawled through 3000 rounds). They are as hopeless as pairs within
/// a chain: a straight-angle vertex of a line `L` can only be left strictly
/// off `L`, whichever chain holds the other point of `L`. Chains are sorted
/// by a rounded key of their line (direction angle, then offset) and a
/// chain joins the previous one when both of its defining points lie on the
/// previous chain's line — an exact test, so only the running time depends
/// on the rounding (a missed join leaves two classes).
fn merge_chains_on_one_line(
    points: &[Point],
    open: &[u32],
    line_neighbour: &[u32],
    mut class: Vec<u32>,
) -> Vec<u32> {
    let p = |v: u32| points[v as usize];
    // The chains' roots (each is its own class), by the rounded line key.
    let mut roots: Vec<(f64, f64, u32)> = (0..open.len() as u32)
        .filter(|&i| class[i as usize] == i)
        .map(|i| {
            let (a, b) = (p(open[i as usize]), p(line_neighbour[i as usize]));
            let (mut dx, mut dy) = (b[0] - a[0], b[1] - a[1]);
            if dx < 0.0 || (dx == 0.0 && dy < 0.0) {
                (dx, dy) = (-dx, -dy);
            }
            let angle = dy.atan2(dx);
            let offset = (dx * a[1] - dy * a[0]) / dx.hypot(dy);
            (angle, offset, i)
        })
        .collect();
    if roots.len() < 2 {
        return class;
    }
    roots.sort_unstable_by(|x, y| x.0.total_cmp(&y.0).then(x.1.total_cmp(&y.1)));
    let mut joined_to = vec![NO_LINE; open.len()];
    let mut leader = roots[0].2;
    for &(_, _, r) in &roots[1..] {
        let (la, lb) = (p(open[leader as usize]), p(line_neighbour[leader as usize]));
        let (ra, rb) = (p(open[r as usize]), p(line_neighbour[r as usize]));
        if orient_sign(la, lb, ra) == 0 && orient_sign(la, lb, rb) == 0 {
            joined_to[r as usize] = leader;
        } else {
            leader = r;
        }
    }
    for c in class.iter_mut() {
        if *c != NO_LINE && joined_to[*c as usize] != NO_LINE {
            *c = joined_to[*c as usize];
        }
    }
    class
}

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
fn decide_round(
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

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{rngs::StdRng, seq::SliceRandom, Rng, SeedableRng};

    /// The integer keys give the comparison sort's order, with many ties
    /// (points of a 7×7 grid, halved: exact dyadic lengths), under a random
    /// renumbering; non-exact squared lengths fall back.
    #[test]
    fn integer_keys_order_segments_as_the_exact_comparison() {
        let mut rng = StdRng::seed_from_u64(12);
        for case in 0..200 {
            let mut points: Vec<Point> = (0..49)
                .map(|i| [f64::from(i % 7) * 0.5, f64::from(i / 7) * 0.5 - 1.0])
                .collect();
            points.shuffle(&mut rng);
            points.truncate(rng.gen_range(3..=49));
            let mut to_original: Vec<u32> = (0..points.len() as u32).collect();
            to_original.shuffle(&mut rng);
            let renumbering = Renumbering {
                to_original: &to_original,
            };
            let n = points.len() as u32;
            let mut segments: Vec<[u32; 2]> = Vec::new();
            for a in 0..n {
                for b in a + 1..n {
                    if rng.gen_bool(0.5) {
                        segments.push(if rng.gen_bool(0.5) { [a, b] } else { [b, a] });
                    }
                }
            }
            let by_key = renumbering.order_by_key(&points, &segments).expect("exact");
            assert_eq!(
                by_key,
                renumbering.order_by_comparison(&points, &segments),
                "case {case}"
            );
            if case % 10 == 0 && !segments.is_empty() {
                points[0][0] += 0.1; // 0.1 is not dyadic: not exact
                let touched = segments.iter().any(|s| s.contains(&0));
                assert_eq!(
                    renumbering.order_by_key(&points, &segments).is_none(),
                    touched
                );
            }
        }
    }

    /// Chains on one line join; a chain on a parallel line, one on a line
    /// whose rounded key equals the first line's but which is not it, and a
    /// vertex off every line stay apart.
    #[test]
    fn chains_join_exactly_when_on_one_line() {
        let points: Vec<Point> = vec![
            [0.0, 0.0],
            [1.0, 0.0],
            [5.0, 0.0],
            [6.0, 0.0],
            [8.0, 0.0],
            [9.0, 1e-300], // the line through 4 and 5 is not y = 0
            [0.0, 1.0],
            [1.0, 1.0],
            [20.0, 0.0],
        ];
        let open: Vec<u32> = (0..9).collect();
        let line_neighbour = [1, 0, 3, 2, 5, 4, 7, 6, NO_LINE];
        let chains = vec![0, 0, 2, 2, 4, 4, 6, 6, NO_LINE];
        let joined = merge_chains_on_one_line(&points, &open, &line_neighbour, chains);
        assert_eq!(joined, vec![0, 0, 0, 0, 4, 4, 6, 6, NO_LINE]);
        // Listed in the other order, the later chain joins the earlier one.
        let chains = vec![0, 0, 2, 2, NO_LINE, NO_LINE, NO_LINE, NO_LINE, NO_LINE];
        let line_neighbour = [1, 0, 3, 2, NO_LINE, NO_LINE, NO_LINE, NO_LINE, NO_LINE];
        let joined = merge_chains_on_one_line(&points, &open, &line_neighbour, chains);
        assert_eq!(joined[..4], [0, 0, 0, 0]);
    }
}
