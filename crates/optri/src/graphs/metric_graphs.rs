//! The relative neighbourhood graph and the minimum spanning tree under a
//! normed metric ([`Metric`]), with the metric's exact tie-break (the
//! simulated strictly convex norm of the kernel's norm module, so the graphs
//! are those of one perturbed point set under one strictly convex norm:
//! plane, connected, MST ⊆ RNG).
//!
//! Under L1 or L∞ the RNG is not a subgraph of the Euclidean Delaunay
//! triangulation, so the candidates come from the *sector* (region) approach
//! of J. Katajainen, *The region approach for computing relative
//! neighbourhood graphs in the Lp metric*, Computing 40 (1988), for which
//! we prove the step we rely on:
//!
//! **Sector Lemma.** Let `W` be a closed wedge at `p` such that for all
//! `q, r ∈ W` with `(‖·‖, |·|₂)(pr) < (‖·‖, |·|₂)(pq)` (lexicographically)
//! also `(‖·‖, |·|₂)(qr) < (‖·‖, |·|₂)(pq)`. If `pq` is an RNG edge and
//! `q ∈ W`, then `q` is among the points of `W` nearest to `p` in that
//! lexicographic order (ties kept). *Proof:* a nearer `r` lies in the lune
//! of `pq` already at the unperturbed level, hence under the tie-break. ∎
//!
//! The wedges used satisfy the hypothesis:
//! * **L∞, L1, Lp (p ≥ 3):** the 8 closed 45° octants bounded by the axes and
//!   the diagonals (all three norms have the square's symmetries, so one
//!   octant `0 ≤ y ≤ x` suffices). `r ↦ ‖q − r‖` is convex, so on
//!   `K = W ∩ {‖r‖ ≤ ‖q‖}` it is largest at an extreme point of `K`. L∞:
//!   `|xq − xr| ≤ xq` and `|yq − yr| ≤ max(yq, yr) ≤ xq`, equality only for
//!   `q = (a, a), r = (b, 0)`, where `|qr|₂ < |pq|₂`; or `r = (a, a),
//!   q = (a, 0)`, excluded because then `|pr|₂ > |pq|₂`. L1: if `r ≤ q`
//!   coordinatewise `‖q−r‖ = ‖q‖ − ‖r‖`; if `xr > xq` then
//!   `‖q − r‖ ≤ ‖q‖ ⇔ xr − yr ≤ 2xq`, true, with equality only when
//!   `‖r‖ = ‖q‖` and `|pr|₂ > |pq|₂`; if `yr > yq` then `yr − xr ≤ 0 ≤ 2yq`,
//!   equality only for `q = (a, 0), r = (b, b)`, where `|qr|₂ < |pq|₂`. Lp,
//!   p > 1 (strictly convex): the extreme points of `K` other than `p` are on
//!   the arc, whose two ends are at distance `((1−2^(−1/p))ᵖ + 1/2)^(1/p) < 1`,
//!   so `‖q − r‖ < ‖q‖` for `r ≠ p`.
//! * **Polygonal norms:** wedges bisected (integer directions, so exact) from
//!   the octants until, for each, the pairwise distances between the
//!   extreme points of its arc (the two ray ends and the polygon vertices
//!   strictly inside) are all `< 1`, checked exactly. By the same convexity
//!   argument (on each edge of the arc `q ↦ ‖q − e‖` is convex), every
//!   `r ∈ K \ {p}` is then strictly nearer to `q` than `p` is.
//!
//! Candidates are found with the points bucketed in cells
//! ([`crate::spatial::PointCells`]), scanning rings of cells around
//! `p` until every wedge is settled; then every candidate's lune is tested
//! exactly. The MST is Kruskal over the RNG in the tie-broken order (every
//! MST edge is an RNG edge: a point in the lune of `pq` makes `pq` the longest
//! edge of a triangle). Brute force (all lune tests) is a test reference only.
//! Ties use the distinct-point numbering.

use super::minimum_spanning_tree::kruskal;
use crate::error::{Error, Result};
use crate::interrupt::Stop;
use crate::kernel::{
    compare_rounded_keys, side_of_direction, LengthOrder, Metric, MetricProblem, Point,
};
use crate::parallel::prelude::*;
use crate::spatial::{bounding_box, PointCells};
use crate::structures::PointSet;
use std::cmp::Ordering;

/// The closed wedges (pairs of consecutive directions, counter-clockwise,
/// each angle < 90°) whose nearest points contain every RNG neighbour.
fn wedges(metric: &Metric) -> std::result::Result<Vec<[Point; 2]>, MetricProblem> {
    let octants: Vec<Point> = vec![
        [1.0, 0.0],
        [1.0, 1.0],
        [0.0, 1.0],
        [-1.0, 1.0],
        [-1.0, 0.0],
        [-1.0, -1.0],
        [0.0, -1.0],
        [1.0, -1.0],
    ];
    let pairs: Vec<[Point; 2]> = (0..8).map(|i| [octants[i], octants[(i + 1) % 8]]).collect();
    let Some(polygon) = metric.unit_polygon() else {
        return Ok(pairs);
    };
    if metric.name() == "l1" || metric.name() == "linf" {
        return Ok(pairs);
    }
    let polygon = polygon.to_vec();
    let mut out = Vec::new();
    let mut stack: Vec<([Point; 2], u32)> = pairs.into_iter().rev().map(|w| (w, 0)).collect();
    while let Some((w, depth)) = stack.pop() {
        if arc_is_short(metric, &polygon, w) {
            out.push(w);
        } else if depth >= 24 {
            return Err(MetricProblem::NotStrictlyConvex(0));
        } else {
            let mid = [w[0][0] + w[1][0], w[0][1] + w[1][1]];
            stack.push(([mid, w[1]], depth + 1));
            stack.push(([w[0], mid], depth + 1));
        }
    }
    Ok(out)
}

/// Are all pairwise norm distances between the extreme points of the unit
/// arc inside wedge `w` below 1 (exactly)?
fn arc_is_short(metric: &Metric, polygon: &[Point], w: [Point; 2]) -> bool {
    use num_rational::BigRational;
    let o = [0.0, 0.0];
    let rat = |v: f64| BigRational::from_float(v).expect("finite");
    // Extreme points as exact rationals: ray ends d / ‖d‖ and vertices inside.
    let norm_exact = |x: &BigRational, y: &BigRational| -> BigRational {
        // ‖(x, y)‖ for the polygon: max over edges of the facet functional.
        let k = polygon.len();
        (0..k)
            .map(|i| {
                let (a, b) = (polygon[i], polygon[(i + 1) % k]);
                let (ax, ay, bx, by) = (rat(a[0]), rat(a[1]), rat(b[0]), rat(b[1]));
                let support = &ax * &by - &ay * &bx;
                ((&by - &ay) * x + (&ax - &bx) * y) / support
            })
            .max()
            .expect("facets")
    };
    let mut extreme: Vec<[BigRational; 2]> = Vec::new();
    for d in w {
        let (x, y) = (rat(d[0]), rat(d[1]));
        let n = norm_exact(&x, &y);
        extreme.push([x / &n, y / &n]);
    }
    for &v in polygon {
        if side_of_direction(w[0], o, v) > 0 && side_of_direction(w[1], o, v) < 0 {
            extreme.push([rat(v[0]), rat(v[1])]);
        }
    }
    let one = BigRational::from_integer(1.into());
    let _ = metric;
    for i in 0..extreme.len() {
        for j in i + 1..extreme.len() {
            let dx = &extreme[i][0] - &extreme[j][0];
            let dy = &extreme[i][1] - &extreme[j][1];
            if norm_exact(&dx, &dy) >= one {
                return false;
            }
        }
    }
    true
}

/// The points bucketed in cells of about two points each.
fn point_cells(points: &[Point]) -> PointCells {
    let bbox = bounding_box(points);
    let [x0, y0, x1, y1] = bbox;
    let (w, h) = (x1 - x0, y1 - y0);
    // A flat box counts as at least `max(w, h)² / n`.
    let area = (w * h).max(w.max(h).powi(2) / points.len() as f64);
    PointCells::new(points, bbox, (2.0 * area / points.len() as f64).sqrt())
}

/// Can the closed wedge `w` at `p` meet the box (conservative: `false` only
/// when the box is clearly on the outer side of one bounding ray)?
fn wedge_may_meet(w: [Point; 2], p: Point, b: [f64; 4]) -> bool {
    let corners = [[b[0], b[1]], [b[2], b[1]], [b[0], b[3]], [b[2], b[3]]];
    let side = |d: Point, c: Point| {
        let (x, y) = (c[0] - p[0], c[1] - p[1]);
        let v = d[0] * y - d[1] * x;
        let tol = 1e-9 * (d[0].abs() * y.abs() + d[1].abs() * x.abs()) + 1e-300;
        if v > tol {
            1
        } else if v < -tol {
            -1
        } else {
            0
        }
    };
    !(corners.iter().all(|&c| side(w[0], c) < 0) || corners.iter().all(|&c| side(w[1], c) > 0))
}

/// The octant of `r − p` when the rounded differences decide it (the signs
/// of rounded differences are exact; `|dx|` against `|dy|` is decided by the
/// kernel's filter for rounded keys, each within one rounding of the exact
/// difference); `None` on a boundary ray or near one, where the exact wedge
/// tests decide.
#[inline]
fn clear_octant(p: Point, r: Point) -> Option<usize> {
    let (dx, dy) = (r[0] - p[0], r[1] - p[1]);
    if dx == 0.0 || dy == 0.0 {
        return None;
    }
    let x_major = compare_rounded_keys(dx.abs(), dy.abs())? == Ordering::Greater;
    Some(match (dx > 0.0, dy > 0.0) {
        (true, true) => {
            if x_major {
                0
            } else {
                1
            }
        }
        (false, true) => {
            if x_major {
                3
            } else {
                2
            }
        }
        (false, false) => {
            if x_major {
                4
            } else {
                5
            }
        }
        (true, false) => {
            if x_major {
                7
            } else {
                6
            }
        }
    })
}

/// Per-thread scratch of the candidate search (reused across points: the
/// search is allocation-free after the first point of a chunk).
struct Search {
    /// The first nearest point found in each wedge (`NONE`: none yet).
    first: Vec<u32>,
    /// Its rounded length (a filter; decisions are exact).
    first_len: Vec<f64>,
    /// Further points tied with `first` in the wedge: (wedge, point).
    ties: Vec<(usize, u32)>,
    open: Vec<bool>,
    met: Vec<bool>,
}

const NONE: u32 = u32::MAX;

/// Points per parallel task of the candidate search.
const SEARCH_CHUNK: usize = 2048;

/// The candidate neighbours of every point (the nearest in each wedge, ties
/// kept), as sorted, deduplicated edges.
fn candidates(
    points: &[Point],
    grid: &PointCells,
    metric: &Metric,
    wedges: &[[Point; 2]],
    octants: bool,
    stop: &Stop,
) -> Result<Vec<[u32; 2]>> {
    let reach = metric.sup_radius();
    let ws = wedges.len();
    let n = points.len();
    // Points in cell order, so that consecutive searches touch nearby cells.
    let per_chunk: Vec<Vec<[u32; 2]>> = (0..n.div_ceil(SEARCH_CHUNK))
        .into_par_iter()
        .map(|chunk| {
            // A stopped run skips the remaining chunks and fails below.
            if stop.reason().is_some() {
                return Vec::new();
            }
            let mut out = Vec::with_capacity(SEARCH_CHUNK * 6);
            let mut st = Search {
                first: vec![NONE; ws],
                first_len: vec![f64::INFINITY; ws],
                ties: Vec::new(),
                open: vec![true; ws],
                met: vec![false; ws],
            };
            for slot in chunk * SEARCH_CHUNK..((chunk + 1) * SEARCH_CHUNK).min(n) {
                search_one(points, grid, metric, wedges, octants, reach, slot, &mut st);
                let pi = grid.ids()[slot];
                let edge = |q: u32| [pi.min(q), pi.max(q)];
                out.extend(st.first.iter().filter(|&&q| q != NONE).map(|&q| edge(q)));
                out.extend(st.ties.iter().map(|&(_, q)| edge(q)));
            }
            out
        })
        .collect();
    stop.check()?;
    let mut all: Vec<[u32; 2]> = per_chunk.into_iter().flatten().collect();
    all.par_sort_unstable();
    all.dedup();
    Ok(all)
}

/// The nearest points of every wedge at the point of grid slot `slot`, into
/// `st.first` and `st.ties` (see the Sector Lemma in the module docs).
///
/// Rings of cells around the point's cell, until every wedge is settled:
/// a point of ring `k + 1` or beyond lies in the box of its cell widened by
/// the grid's slack (the cell geometry's `cell_box`), at least `k` cells
/// from the point's own, so at `L∞` distance at least `k·cell − 2·slack`,
/// and its norm is at least that over `reach`.
#[allow(clippy::too_many_arguments)]
fn search_one(
    points: &[Point],
    grid: &PointCells,
    metric: &Metric,
    wedges: &[[Point; 2]],
    octants: bool,
    reach: f64,
    slot: usize,
    st: &mut Search,
) {
    let ws = wedges.len();
    let (pi, p) = (grid.ids()[slot], grid.coords()[slot]);
    let geometry = grid.geometry();
    let c = geometry.cell_of(p);
    st.first.iter_mut().for_each(|f| *f = NONE);
    st.first_len.iter_mut().for_each(|l| *l = f64::INFINITY);
    st.ties.clear();
    st.open.iter_mut().for_each(|o| *o = true);
    let mut open_count = ws;
    let mut k = 0u64;
    let offer = |s: usize, ri: u32, r: Point, st: &mut Search| {
        let q = st.first[s];
        let lr = metric.length(p, r);
        if q == NONE {
            st.first[s] = ri;
            st.first_len[s] = lr;
            return;
        }
        // Clearly farther: skip the exact comparison.
        if lr > st.first_len[s] * (1.0 + 1e-9) {
            return;
        }
        match metric.compare_norm_then_euclidean(p, r, p, points[q as usize]) {
            Ordering::Less => {
                st.first[s] = ri;
                st.first_len[s] = lr;
                st.ties.retain(|&(w, _)| w != s);
            }
            Ordering::Equal => st.ties.push((s, ri)),
            Ordering::Greater => {}
        }
    };
    while open_count > 0 {
        st.met.iter_mut().for_each(|m| *m = false);
        grid.for_each_cell_in_ring(c, k, |cell| {
            let bounds = geometry.cell_box(cell);
            // Only the open wedges this cell can still improve: it may
            // meet the wedge and is not beyond the wedge's best (norm ≥
            // the cell's L∞ distance / reach).
            let gap = (bounds[0] - p[0])
                .max(p[0] - bounds[2])
                .max(bounds[1] - p[1])
                .max(p[1] - bounds[3])
                .max(0.0);
            let lb = gap / reach * (1.0 - 1e-9);
            let useful = wedges.iter().enumerate().any(|(s, &w)| {
                st.open[s]
                    && (st.first[s] == NONE || st.first_len[s] * (1.0 + 1e-9) >= lb)
                    && (k < 2 || wedge_may_meet(w, p, bounds))
            });
            if !useful {
                return;
            }
            let (coords, ids) = grid.cell(cell);
            for (&ri, &r) in ids.iter().zip(coords) {
                if ri == pi {
                    continue;
                }
                match octants.then(|| clear_octant(p, r)).flatten() {
                    Some(s) => {
                        if st.open[s] {
                            offer(s, ri, r, st);
                        }
                    }
                    None => {
                        for (s, &w) in wedges.iter().enumerate() {
                            if st.open[s]
                                && side_of_direction(w[0], p, r) >= 0
                                && side_of_direction(w[1], p, r) <= 0
                            {
                                offer(s, ri, r, st);
                            }
                        }
                    }
                }
            }
            // An empty wedge is settled once a ring has no in-grid
            // cell meeting it (wedge ∩ bounding box is convex).
            for (s, &w) in wedges.iter().enumerate() {
                if st.open[s] && st.first[s] == NONE && !st.met[s] && wedge_may_meet(w, p, bounds) {
                    st.met[s] = true;
                }
            }
        });
        // Points of ring k+1 are at L∞ distance ≥ k·cell − 2·slack, norm ≥
        // that / reach.
        let distance = k as f64 * geometry.cell_size() - 2.0 * geometry.slack();
        let lower = distance.max(0.0) / reach * (1.0 - 1e-9);
        for s in 0..ws {
            let settled = if st.first[s] == NONE {
                !st.met[s]
            } else {
                st.first_len[s] * (1.0 + 1e-9) < lower
            };
            if st.open[s] && settled {
                st.open[s] = false;
                open_count -= 1;
            }
        }
        k += 1;
    }
}

/// Is the lune of `pq` free of points (under the metric's tie-break)?
fn lune_is_empty(points: &[Point], metric: &Metric, grid: &PointCells, [p, q]: [u32; 2]) -> bool {
    let (pp, pq) = (points[p as usize], points[q as usize]);
    let len = metric.length(pp, pq);
    let r = metric.sup_radius() * len * (1.0 + 1e-9);
    // The lune lies in both balls of radius |pq| about p and q, so in the
    // intersection of their bounding squares (half-side `r` ≥ R·|pq|); the
    // lookup's slack covers the rounding of its corners.
    let lo = [pp[0].max(pq[0]) - r, pp[1].max(pq[1]) - r];
    let hi = [pp[0].min(pq[0]) + r, pp[1].min(pq[1]) + r];
    let slack = len * (1.0 + 1e-9);
    !grid.any_near(lo, hi, 0.0, |coords, ids| {
        ids.iter().zip(coords).any(|(&x, &px)| {
            x != p
                && x != q
                && metric.length(pp, px) <= slack
                && metric.length(pq, px) <= slack
                && metric.in_lune(points, p, q, x)
        })
    })
}

/// Candidate edges per lune-test task, between two reads of the stop.
const LUNE_CHUNK: usize = 4096;

/// The RNG under `metric` on distinct points (distinct indices, sorted pairs).
///
/// # Errors
/// [`Error::InvalidMetric`] for a metric without usable wedges,
/// [`Error::Interrupted`] when `stop` says so (read every few thousand
/// points or candidates).
pub(crate) fn rng_under(points: &[Point], metric: &Metric, stop: &Stop) -> Result<Vec<[u32; 2]>> {
    let octants =
        metric.unit_polygon().is_none() || metric.name() == "l1" || metric.name() == "linf";
    let wedges = wedges(metric).map_err(Error::InvalidMetric)?;
    let grid = &point_cells(points);
    let cands = candidates(points, grid, metric, &wedges, octants, stop)?;
    let rng = cands
        .par_chunks(LUNE_CHUNK)
        .flat_map_iter(|chunk| {
            let stopped = stop.reason().is_some();
            chunk
                .iter()
                .copied()
                .filter(move |&e| !stopped && lune_is_empty(points, metric, grid, e))
        })
        .collect();
    stop.check()?;
    Ok(rng)
}

/// The relative neighbourhood graph of `points` under `metric`: `pq` is an
/// edge iff no other point `x` has `max(|px|, |qx|) < |pq|` (lengths and
/// ties as in [`Metric::compare_lengths_symbolic`]). Sorted input-index pairs.
/// The Euclidean metric gives [`crate::relative_neighborhood_graph`].
pub(crate) fn relative_neighborhood_graph_under(
    points: &PointSet,
    metric: &Metric,
) -> Result<Vec<[u32; 2]>> {
    if metric.is_euclidean() {
        return super::relative_neighborhood_graph(points);
    }
    let edges = rng_under(points.points(), metric, &Stop::default())?;
    Ok(points.to_input_edges(edges.into_iter()))
}

/// The minimum spanning tree of `points` under `metric` (unique under the
/// tie-break). Sorted input-index pairs. The Euclidean metric gives
/// [`crate::minimum_spanning_tree`].
pub(crate) fn minimum_spanning_tree_under(
    points: &PointSet,
    metric: &Metric,
) -> Result<Vec<[u32; 2]>> {
    if metric.is_euclidean() {
        return super::minimum_spanning_tree(points);
    }
    let pts = points.points();
    let rng = rng_under(pts, metric, &Stop::default())?;
    let tree = kruskal(pts, metric, rng);
    Ok(points.to_input_edges(tree.into_iter()))
}
