//! GT of arbitrary point sets: the idea of M. T. Dickerson, R. L. S.
//! Drysdale, S. A. McElfresh & E. Welzl, *Fast greedy triangulation
//! algorithms*, Computational Geometry 8 (1997), of processing only plausible
//! candidates, made exact and cache-friendly.
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
//! angles on one line form *line classes* ([`collinear`]): no candidate
//! joins two points of a class, so their pairs are neither listed nor
//! counted by the guard. Both only change the running time. Runs with
//! several apexes still make the rounds crawl.
//!
//! # Files
//! | file | what | implements |
//! |---|---|---|
//! | `mod.rs` | the rounds driver: thresholds, candidates, the fan shortcut | "Length rounds" |
//! | [`ranking`] | the global segment order of a round's candidates, ties on the caller's numbering | "Deciding a round…" (the order of pass 2) |
//! | [`scan`] | one round's two passes | "Deciding a round…" |
//! | [`partial`] | the partial triangulation: closed triangles, closed vertices, active edges | the Lemma and the Claim |
//! | [`segment_index`] | what a candidate may cross, and whether a point lies on it | pass 1's tests |
//! | [`guard`] | the density guard choosing each round's threshold | "Length rounds" (the guard) |
//! | [`collinear`] | line classes of open vertices | "Collinear points" |
//!
//! The cells behind every lookup are [`crate::spatial::SparseGrid`]s.

mod collinear;
mod guard;
mod partial;
mod ranking;
mod scan;
mod segment_index;

use crate::error::{Error, Result};
use crate::interrupt::Stop;
use crate::kernel::{orient_sign, shorter_than, Point};
use crate::parallel::prelude::*;
use crate::spatial::{bounding_box, fmax, fmin, inverse_permutation, morton_order};
use crate::timing::{Phase, Stopwatch};
use collinear::line_classes;
use guard::{next_floor, next_growth, round_grid, MIN_RELATIVE_STEP, NO_LINE, THRESHOLD_GROWTH};
use partial::{OpenGaps, Partial};
use ranking::Renumbering;
use scan::decide_round;
use segment_index::PointsNear;

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
/// [`Error::Interrupted`] when `stop` says so (checked once per round).
pub(super) fn greedy_general(
    original: &[Point],
    hull: &[u32],
    stop: &Stop,
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
    let mut triangles: Vec<[u32; 3]> = greedy_rounds(&local, &hull, &renumbering, stop, phases)?
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
/// rounds would crawl (157 s at 10⁴ points). The test is exact
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

/// The length rounds of the module docs on `points` (local numbering; ties
/// through `renumbering`): the GT's triangles, each by its smallest corner.
fn greedy_rounds(
    points: &[Point],
    hull: &[u32],
    renumbering: &Renumbering,
    stop: &Stop,
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
        stop.check()?;
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
