//! GT of arbitrary point sets: the Dickerson–Drysdale–McElfresh–Welzl idea of
//! processing only plausible candidates (literature.md §b), made exact and
//! cache-friendly.
//!
//! # Length rounds
//! Round `k` takes candidate pairs whose exact length lies in
//! `[T_{k-1}, T_k)`: in round 0 every pair shorter than `T_0`, later only
//! pairs of still-open vertices (below). Rounds are disjoint length ranges,
//! so every pair shorter than `T_{k-1}` has been decided when round `k`
//! starts. `T_0` is about 1.6 mean point spacings and `T_k = 2 T_{k-1}`,
//! unless a guard (`round_grid`) finds that the pairs within the proposed
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

use super::{keyed_by_length, rounded_squared_length, sort_keyed_runs};
use crate::error::{Error, Result};
use crate::kernel::compare_angles;
use crate::kernel::{compare_lengths, orient_sign, Point};
use crate::kernel::{on_open_segment, properly_cross};
use crate::parallel::prelude::*;
use crate::spatial::{bounding_box, convex_hull_cycle, morton_order};
use crate::timing::{Phase, Stopwatch};
use std::cmp::Ordering;

const NONE: u32 = u32::MAX;

/// Square cells over a bounding box, for cell sizes that follow a round's
/// length scale whatever the spread of the points (clustered inputs): a
/// table over all cells when there are not many more cells than items,
/// else only the occupied cells, found by binary search. Cell lookups only
/// choose which exact tests to run; they are padded by a slack that covers
/// their rounding.
struct SparseGrid<T> {
    x0: f64,
    y0: f64,
    inv: f64,
    /// Columns; a cell's key is `row * columns + column`.
    columns: u64,
    rows: u64,
    slack_x: f64,
    slack_y: f64,
    /// The occupied cells' keys, ascending, and their items' ranges.
    keys: Vec<u64>,
    start: Vec<u32>,
    /// Dense mode: the position in `keys` of every cell's key (`NONE` if
    /// empty). Empty in sparse mode.
    table: Vec<u32>,
    items: Vec<T>,
}

impl<T: Copy + Send + Sync> SparseGrid<T> {
    /// Buckets items `0..len` (`item(i)`, at `point(i)`) by cell, cells of
    /// about `cell` (never so small that keys overflow); within a cell, by
    /// ascending `order`.
    fn new(
        bbox: [f64; 4],
        cell: f64,
        len: usize,
        point: impl Fn(usize) -> Point + Sync,
        item: impl Fn(usize) -> T + Sync,
        order: impl Fn(usize) -> u32 + Sync,
    ) -> Self {
        let [x0, y0, x1, y1] = bbox;
        let (w, h) = (x1 - x0, y1 - y0);
        let cell = fmax(cell, fmax(w, h) * 2f64.powi(-30));
        let cell = if cell > 0.0 { cell } else { 1.0 };
        let columns = (w / cell) as u64 + 1;
        let rows = (h / cell) as u64 + 1;
        let mag_x = fmax(x0.abs(), x1.abs());
        let mag_y = fmax(y0.abs(), y1.abs());
        let mut grid = Self {
            x0,
            y0,
            inv: 1.0 / cell,
            columns,
            rows,
            slack_x: 1e-9 * cell + 1e-13 * mag_x,
            slack_y: 1e-9 * cell + 1e-13 * mag_y,
            keys: Vec::new(),
            start: Vec::new(),
            table: Vec::new(),
            items: Vec::new(),
        };
        let keys: Vec<u64> = (0..len)
            .into_par_iter()
            .map(|i| grid.key(point(i)))
            .collect();
        let cells = columns.saturating_mul(rows);
        if cells <= 4 * len as u64 + 65536 {
            // Counting sort over all cells, then each cell by `order`.
            let cells = cells as usize;
            let mut count = vec![0u32; cells + 1];
            for &k in &keys {
                count[k as usize + 1] += 1;
            }
            for c in 0..cells {
                count[c + 1] += count[c];
            }
            let mut fill = count.clone();
            let mut slots = vec![0u32; len];
            for (i, &k) in keys.iter().enumerate() {
                slots[fill[k as usize] as usize] = i as u32;
                fill[k as usize] += 1;
            }
            grid.table = vec![NONE; cells];
            for c in 0..cells {
                let (a, b) = (count[c] as usize, count[c + 1] as usize);
                if a < b {
                    slots[a..b].sort_unstable_by_key(|&i| order(i as usize));
                    grid.table[c] = grid.keys.len() as u32;
                    grid.keys.push(c as u64);
                    grid.start.push(a as u32);
                }
            }
            grid.start.push(len as u32);
            grid.items = slots.par_iter().map(|&i| item(i as usize)).collect();
        } else {
            let mut keyed: Vec<(u64, u32, u32)> = keys
                .par_iter()
                .enumerate()
                .map(|(i, &k)| (k, order(i), i as u32))
                .collect();
            keyed.par_sort_unstable();
            grid.items = keyed
                .par_iter()
                .map(|&(_, _, i)| item(i as usize))
                .collect();
            for (i, &(k, _, _)) in keyed.iter().enumerate() {
                if grid.keys.last() != Some(&k) {
                    grid.keys.push(k);
                    grid.start.push(i as u32);
                }
            }
            grid.start.push(keyed.len() as u32);
        }
        grid
    }

    #[inline]
    fn column(&self, x: f64) -> u64 {
        // Truncation is the floor for c ≥ 1 (and avoids a libm call).
        let c = (x - self.x0) * self.inv;
        if c >= 1.0 {
            (c as u64).min(self.columns - 1)
        } else {
            0
        }
    }

    #[inline]
    fn row(&self, y: f64) -> u64 {
        let c = (y - self.y0) * self.inv;
        if c >= 1.0 {
            (c as u64).min(self.rows - 1)
        } else {
            0
        }
    }

    #[inline]
    fn key(&self, p: Point) -> u64 {
        self.row(p[1]) * self.columns + self.column(p[0])
    }

    /// The items of the `k`-th occupied cell.
    #[inline]
    fn cell(&self, k: usize) -> &[T] {
        &self.items[self.start[k] as usize..self.start[k + 1] as usize]
    }

    /// Calls `f` on the occupied cells (positions in `keys`) of row `r`
    /// between columns `c0` and `c1`; stops early and returns `true` when
    /// `f` does.
    #[inline]
    fn any_cell_in_row(&self, r: u64, c0: u64, c1: u64, mut f: impl FnMut(usize) -> bool) -> bool {
        let (lo, hi) = (r * self.columns + c0, r * self.columns + c1);
        if self.table.is_empty() {
            let mut k = self.keys.partition_point(|&key| key < lo);
            while k < self.keys.len() && self.keys[k] <= hi {
                if f(k) {
                    return true;
                }
                k += 1;
            }
        } else {
            for &k in &self.table[lo as usize..=hi as usize] {
                if k != NONE && f(k as usize) {
                    return true;
                }
            }
        }
        false
    }

    /// Calls `f` on the items of every occupied cell meeting the box around
    /// `a, b` widened by `pad` (and the slack); stops early and returns
    /// `true` when `f` does.
    #[inline]
    fn any_cell_near(&self, a: Point, b: Point, pad: f64, mut f: impl FnMut(&[T]) -> bool) -> bool {
        let (px, py) = (pad + self.slack_x, pad + self.slack_y);
        let (c0, c1) = (
            self.column(fmin(a[0], b[0]) - px),
            self.column(fmax(a[0], b[0]) + px),
        );
        let (r0, r1) = (
            self.row(fmin(a[1], b[1]) - py),
            self.row(fmax(a[1], b[1]) + py),
        );
        if self.table.is_empty() && r1 - r0 >= self.keys.len() as u64 {
            // More rows than occupied cells (a long query on a fine sparse
            // grid): scan the occupied cells in the key range instead.
            let (lo, hi) = (r0 * self.columns + c0, r1 * self.columns + c1);
            let first = self.keys.partition_point(|&key| key < lo);
            return self.keys[first..]
                .iter()
                .take_while(|&&key| key <= hi)
                .enumerate()
                .any(|(i, &key)| {
                    let column = key % self.columns;
                    (c0..=c1).contains(&column) && f(self.cell(first + i))
                });
        }
        (r0..=r1).any(|r| self.any_cell_in_row(r, c0, c1, |k| f(self.cell(k))))
    }

    /// The number of items in the occupied cell `k` and its eight
    /// neighbours.
    fn block_len(&self, k: usize) -> usize {
        let key = self.keys[k];
        let (row, column) = (key / self.columns, key % self.columns);
        let (c0, c1) = (column.saturating_sub(1), (column + 1).min(self.columns - 1));
        let mut len = 0;
        for r in row.saturating_sub(1)..=(row + 1).min(self.rows - 1) {
            self.any_cell_in_row(r, c0, c1, |m| {
                len += self.cell(m).len();
                false
            });
        }
        len
    }
}

/// `min` and `max` of finite numbers (one instruction each; `f64::min`
/// also handles NaN).
#[inline]
fn fmin(a: f64, b: f64) -> f64 {
    if a < b {
        a
    } else {
        b
    }
}

#[inline]
fn fmax(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

/// Segments bucketed by the cell of their midpoint: a segment that meets a
/// point `x` has its midpoint within `reach` (its longest half-length) of
/// `x`. Each bucket stores its segments' ids and coordinates contiguously, by
/// ascending id, so that a query reads memory in spatial order.
struct SegmentIndex {
    grid: SparseGrid<Indexed>,
    reach: f64,
}

/// A segment in a [`SegmentIndex`]: its id and its endpoints' coordinates.
#[derive(Clone, Copy)]
struct Indexed {
    id: u32,
    /// The endpoint with the smaller x.
    a: Point,
    b: Point,
}

impl Indexed {
    fn new(id: u32, p: Point, q: Point) -> Self {
        let (a, b) = if p[0] <= q[0] { (p, q) } else { (q, p) };
        Self { id, a, b }
    }

    /// Does this segment properly cross the query? (Exact; the box test
    /// first, which needs no `min` in x because `a` is the left endpoint.)
    #[inline]
    fn crosses(&self, q: &Query) -> bool {
        // One branch for the whole box test (`&`, not `&&`): its outcome is
        // unpredictable, so fewer branches mispredict less.
        let boxes_meet = (self.a[0] <= q.hi[0])
            & (self.b[0] >= q.lo[0])
            & (fmin(self.a[1], self.b[1]) <= q.hi[1])
            & (fmax(self.a[1], self.b[1]) >= q.lo[1]);
        boxes_meet && properly_cross(q.a, q.b, self.a, self.b)
    }
}

/// A query segment with its bounding box.
struct Query {
    a: Point,
    b: Point,
    lo: Point,
    hi: Point,
}

impl Query {
    fn new(a: Point, b: Point) -> Self {
        Self {
            a,
            b,
            lo: [fmin(a[0], b[0]), fmin(a[1], b[1])],
            hi: [fmax(a[0], b[0]), fmax(a[1], b[1])],
        }
    }
}

impl SegmentIndex {
    /// Indexes `segments`, tagging each with its entry of `ids`.
    fn new(points: &[Point], bbox: [f64; 4], segments: &[[u32; 2]], ids: &[u32]) -> Self {
        let p = |v: u32| points[v as usize];
        let reach = segments
            .par_iter()
            .map(|&[a, b]| half_length(p(a), p(b)))
            .reduce(|| 0.0, fmax)
            * (1.0 + 1e-9);
        let midpoint = |i: usize| {
            let [a, b] = segments[i];
            let (pa, pb) = (p(a), p(b));
            [0.5 * pa[0] + 0.5 * pb[0], 0.5 * pa[1] + 0.5 * pb[1]]
        };
        let item = |i: usize| {
            let [a, b] = segments[i];
            Indexed::new(ids[i], p(a), p(b))
        };
        Self {
            grid: SparseGrid::new(bbox, reach, segments.len(), midpoint, item, |i| ids[i]),
            reach,
        }
    }

    /// Calls `f` on every segment *no longer than `ab`* that may meet `ab`
    /// (and others), cell by cell, in ascending id within a cell; `f`
    /// returns `true` to stop the scan of the current cell. (Their midpoints
    /// lie within `|ab| / 2` of `ab`.)
    #[inline]
    fn scan_near(&self, a: Point, b: Point, mut f: impl FnMut(&Indexed) -> bool) {
        let pad = fmin(self.reach, half_length(a, b) * (1.0 + 1e-9));
        self.grid.any_cell_near(a, b, pad, |cell| {
            for s in cell {
                if f(s) {
                    break;
                }
            }
            false
        });
    }

    /// Does `ab` properly cross one of the segments, all shorter than `ab`?
    /// (Exact.)
    fn crossed_by(&self, q: &Query) -> bool {
        let pad = fmin(self.reach, half_length(q.a, q.b) * (1.0 + 1e-9));
        self.grid
            .any_cell_near(q.a, q.b, pad, |cell| cell.iter().any(|s| s.crosses(q)))
    }
}

/// Half the length of `ab`, rounded (only ever used, padded, to choose cells).
#[inline]
fn half_length(a: Point, b: Point) -> f64 {
    0.5 * ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt()
}

/// Do the closed bounding boxes of `ab` and `cd` meet? (Exact: comparisons only.)
#[inline]
fn boxes_meet(a: Point, b: Point, c: Point, d: Point) -> bool {
    fmax(a[0], b[0]) >= fmin(c[0], d[0])
        && fmax(c[0], d[0]) >= fmin(a[0], b[0])
        && fmax(a[1], b[1]) >= fmin(c[1], d[1])
        && fmax(c[1], d[1]) >= fmin(a[1], b[1])
}

/// The partial greedy triangulation: neighbours of each vertex sorted
/// counter-clockwise from the positive x-axis.
struct Partial<'a> {
    points: &'a [Point],
    adjacency: Vec<Vec<u32>>,
    hull_prev: Vec<u32>,
    hull_next: Vec<u32>,
    edges: usize,
}

impl<'a> Partial<'a> {
    #[inline]
    fn p(&self, v: u32) -> Point {
        self.points[v as usize]
    }

    fn has_edge(&self, u: u32, w: u32) -> bool {
        let (lu, lw) = (&self.adjacency[u as usize], &self.adjacency[w as usize]);
        if lu.len() <= lw.len() {
            lu.contains(&w)
        } else {
            lw.contains(&u)
        }
    }

    /// Is the gap between consecutive neighbours `u` then `w` (ccw) of `v`
    /// closed: a closed triangle or the outer gap of a hull vertex?
    #[inline]
    fn gap_closed(&self, v: u32, u: u32, w: u32) -> bool {
        (self.hull_prev[v as usize] == u && self.hull_next[v as usize] == w)
            || (orient_sign(self.p(v), self.p(u), self.p(w)) > 0 && self.has_edge(u, w))
    }

    /// The open gaps at `v` (not closed, see [`Self::gap_closed`]), each as
    /// the neighbours `[u, w]` bounding it counter-clockwise; `None` when `v`
    /// has fewer than two neighbours, so that only the direction of its
    /// neighbour (if any) is taken.
    fn open_gaps(&self, v: u32) -> Option<Vec<[u32; 2]>> {
        let list = &self.adjacency[v as usize];
        let len = list.len();
        (len >= 2).then(|| {
            (0..len)
                .map(|i| [list[i], list[(i + 1) % len]])
                .filter(|&[u, w]| !self.gap_closed(v, u, w))
                .collect()
        })
    }

    /// May an edge leave `a` towards `b`, given `a`'s open gaps? Not if its
    /// direction is taken (a point on the segment, or an overlapping edge —
    /// the nearest point `z` on `ab` gives a shorter `az` that was rejected
    /// for crossing an edge, which then crosses `ab` too) or falls into a
    /// closed triangle (whose third side it would cross): `b` must lie
    /// strictly inside an open gap.
    fn leaves_through(&self, a: u32, gaps: &Option<Vec<[u32; 2]>>, b: u32) -> bool {
        let (pa, pb) = (self.p(a), self.p(b));
        let Some(gaps) = gaps else {
            return self.adjacency[a as usize]
                .iter()
                .all(|&u| compare_angles(pa, self.p(u), pb) != Ordering::Equal);
        };
        gaps.iter().any(|&[u, w]| {
            let (pu, pw) = (self.p(u), self.p(w));
            if orient_sign(pa, pu, pw) > 0 {
                orient_sign(pa, pu, pb) > 0 && orient_sign(pa, pb, pw) > 0
            } else {
                // A gap of 180° or more: inside unless in the closed
                // complementary wedge from w to u (at most 180°).
                !(orient_sign(pa, pw, pb) >= 0 && orient_sign(pa, pb, pu) >= 0)
            }
        })
    }

    /// No edge can be added at `v` any more (module docs).
    fn closed(&self, v: u32) -> bool {
        let list = &self.adjacency[v as usize];
        let len = list.len();
        len >= 2 && (0..len).all(|i| self.gap_closed(v, list[i], list[(i + 1) % len]))
    }

    /// Edges at open `v` towards larger open vertices with a side that is not
    /// a closed triangle.
    fn active_edges_at(&self, v: u32, is_open: &[bool], out: &mut Vec<[u32; 2]>) {
        let list = &self.adjacency[v as usize];
        let len = list.len();
        for i in 0..len {
            let u = list[i];
            if u < v || !is_open[u as usize] {
                continue;
            }
            let both_closed = len >= 2
                && self.gap_closed(v, list[(i + len - 1) % len], u)
                && self.gap_closed(v, u, list[(i + 1) % len]);
            if !both_closed {
                out.push([v, u]);
            }
        }
    }

    /// The triangles of a complete triangulation: at every vertex, each
    /// pair of consecutive neighbours with a left turn bounds a triangle
    /// (every gap but a hull vertex's outer one is a triangle, and that one
    /// turns right or is straight); each is reported by its smallest corner.
    fn triangles(&self) -> Vec<[u32; 3]> {
        (0..self.points.len() as u32)
            .into_par_iter()
            .fold(Vec::new, |mut out, v| {
                let list = &self.adjacency[v as usize];
                for i in 0..list.len() {
                    let (u, w) = (list[i], list[(i + 1) % list.len()]);
                    if v < u && v < w && orient_sign(self.p(v), self.p(u), self.p(w)) > 0 {
                        out.push([v, u, w]);
                    }
                }
                out
            })
            .flatten()
            .collect()
    }

    /// Adds a round's accepted edges (they cross nothing and share no
    /// direction at a vertex, so the angular order is strict).
    fn add(&mut self, accepted: &[[u32; 2]]) {
        // Half-edges grouped by origin, then every touched list extended and
        // re-sorted in parallel.
        let mut half: Vec<[u32; 2]> = accepted
            .par_iter()
            .flat_map_iter(|&[a, b]| [[a, b], [b, a]])
            .collect();
        half.par_sort_unstable();
        let mut start = vec![0u32; self.points.len() + 1];
        for &[a, _] in &half {
            start[a as usize + 1] += 1;
        }
        for v in 0..self.points.len() {
            start[v + 1] += start[v];
        }
        let points = self.points;
        self.adjacency
            .par_iter_mut()
            .enumerate()
            .for_each(|(v, list)| {
                let new = &half[start[v] as usize..start[v + 1] as usize];
                if new.is_empty() {
                    return;
                }
                list.extend(new.iter().map(|&[_, b]| b));
                let pv = points[v];
                list.sort_unstable_by(|&x, &y| {
                    compare_angles(pv, points[x as usize], points[y as usize])
                });
            });
        self.edges += accepted.len();
    }
}

/// Exact `|pq| < t` for a threshold length `t`, with a rounded shortcut.
#[inline]
fn shorter_than(p: Point, q: Point, t: f64) -> bool {
    let d2 = rounded_squared_length(p, q);
    let t2 = t * t;
    if d2 < t2 * (1.0 - 1e-9) {
        return true;
    }
    if d2 > t2 * (1.0 + 1e-9) {
        return false;
    }
    compare_lengths(p, q, [0.0, 0.0], [t, 0.0]) == Ordering::Less
}

/// GT triangles of `points` (distinct, not all collinear), counter-clockwise.
///
/// Works on a copy renumbered in Z-order, so that neighbouring vertices sit
/// close in memory; ties are broken on the original indices, because the
/// symbolic perturbation depends on them: the renumbered copy is only used
/// where an index never decides a tie.
pub(super) fn greedy_general(original: &[Point], phases: &mut Vec<Phase>) -> Result<Vec<[u32; 3]>> {
    let to_original = morton_order(original);
    let local: Vec<Point> = to_original.iter().map(|&v| original[v as usize]).collect();
    let renumbering = Renumbering {
        original,
        to_original: &to_original,
    };
    Ok(greedy_rounds(&local, &renumbering, phases)?
        .into_iter()
        .map(|t| t.map(|v| to_original[v as usize]))
        .collect())
}

/// Local (memory-friendly) numbering versus the caller's, which decides ties.
struct Renumbering<'a> {
    original: &'a [Point],
    to_original: &'a [u32],
}

impl Renumbering<'_> {
    /// The position of each local-index segment in the global segment order
    /// (exact; see [`super::sort_keyed_runs`]).
    fn ranks(&self, points: &[Point], segments: &[[u32; 2]]) -> Vec<u32> {
        let mut keyed = keyed_by_length(points, segments, |i, _| i as u32);
        let order = crate::kernel::segment_order(self.original);
        let original = |i: u32| segments[i as usize].map(|v| self.to_original[v as usize]);
        sort_keyed_runs(&mut keyed, |&i, &j| order(&original(i), &original(j)));
        let mut rank = vec![0u32; segments.len()];
        for (position, &(_, i)) in keyed.iter().enumerate() {
            rank[i as usize] = position as u32;
        }
        rank
    }
}

fn greedy_rounds(
    points: &[Point],
    renumbering: &Renumbering,
    phases: &mut Vec<Phase>,
) -> Result<Vec<[u32; 3]>> {
    let mut stopwatch = Stopwatch::new(phases);
    let n = points.len();
    let bbox = bounding_box(points);
    let (w, h) = (bbox[2] - bbox[0], bbox[3] - bbox[1]);
    let hull = convex_hull_cycle(points);
    let mut hull_prev = vec![NONE; n];
    let mut hull_next = vec![NONE; n];
    for i in 0..hull.len() {
        let v = hull[i] as usize;
        hull_prev[v] = hull[(i + hull.len() - 1) % hull.len()];
        hull_next[v] = hull[(i + 1) % hull.len()];
    }
    let mut g = Partial {
        points,
        adjacency: vec![Vec::new(); n],
        hull_prev,
        hull_next,
        edges: 0,
    };
    let target = 3 * n - 3 - hull.len();
    let diagonal = (w * w + h * h).sqrt();
    // About 1.6 mean spacings (a flat box still gets a sensible one); the
    // guard in `round_grid` shrinks it where the points are denser.
    let spacing = ((fmax(w, h * 1e-6) * fmax(h, w * 1e-6)) / n as f64).sqrt();
    let mut open: Vec<u32> = (0..n as u32).collect();
    let mut near: Option<PointsNear> = None;
    let mut lower = 0.0;
    let mut round = 0;
    while g.edges < target && !open.is_empty() {
        let proposed = if round == 0 {
            1.6 * spacing
        } else {
            2.0 * lower
        };
        let (threshold, grid) = round_grid(points, bbox, &open, lower, proposed);
        // Once every pair is shorter than the threshold, take all the rest.
        let last = threshold > 1.01 * diagonal;
        // The point grid answers "a point on this segment?"; a query costs
        // about (length / cell)² cells, so coarsen it when the round's
        // candidates would cost more than rebuilding it (O(n)).
        let cell = fmin(threshold, diagonal);
        let coarsen = near.as_ref().is_some_and(|p| {
            let ratio = cell * p.grid.inv;
            (ratio * ratio) * (8 * open.len()) as f64 > (4 * n) as f64 && ratio > 4.0
        });
        if near.is_none() || coarsen {
            near = Some(PointsNear::new(points, bbox, cell));
        }
        let near = near.as_ref().expect("just built");
        let gaps: Vec<Option<Vec<[u32; 2]>>> = if round == 0 {
            vec![None; n]
        } else {
            open.par_iter().map(|&v| g.open_gaps(v)).collect()
        };
        // Pairs `open[i], open[j]` in the length range that may leave both
        // endpoints.
        let keep = |i: usize, j: usize| {
            let (a, b) = (open[i], open[j]);
            let (pa, pb) = (points[a as usize], points[b as usize]);
            !shorter_than(pa, pb, lower)
                && (last || shorter_than(pa, pb, threshold))
                && g.leaves_through(a, &gaps[i], b)
                && g.leaves_through(b, &gaps[j], a)
        };
        let candidates: Vec<[u32; 2]> = (0..open.len())
            .into_par_iter()
            .chunks(4096)
            .map(|chunk| {
                let mut out = Vec::new();
                for i in chunk {
                    let (v, pv) = (open[i], points[open[i] as usize]);
                    // Cells a little wider than the threshold: close pairs
                    // sit in neighbouring cells (all cells, in the last round).
                    let reach = if last { diagonal } else { threshold };
                    grid.any_cell_near(pv, pv, reach, |cell| {
                        for &j in cell {
                            if open[j as usize] > v && keep(i, j as usize) {
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
        let rank = renumbering.ranks(points, &candidates);
        let mut is_open = vec![false; n];
        for &v in &open {
            is_open[v as usize] = true;
        }
        let active: Vec<[u32; 2]> = open
            .par_iter()
            .fold(Vec::new, |mut out, &v| {
                g.active_edges_at(v, &is_open, &mut out);
                out
            })
            .flatten()
            .collect();
        let accepted = decide_round(points, bbox, &candidates, &rank, &active, near, round == 0);
        g.add(&accepted);
        open = open.into_par_iter().filter(|&v| !g.closed(v)).collect();
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
    if g.edges != target {
        return Err(Error::Internal(format!(
            "the greedy triangulation has {} of {target} edges",
            g.edges
        )));
    }
    let triangles = g.triangles();
    stopwatch.lap("triangles");
    Ok(triangles)
}

/// The threshold of the next round, at most `proposed`, and the grid of the
/// open vertices (indices into `open`) with cells a little wider than it.
///
/// Guard: a round enumerates the pairs of open vertices in neighbouring
/// cells, and its candidates' crossings grow with their square; where points
/// are much denser than average (clustered inputs) a threshold scaled to the
/// mean spacing would make that quadratic. So the step above `lower` is
/// halved until the pair count is linear in the number of open vertices
/// (only the running time depends on this choice; rounds stay disjoint
/// length ranges).
fn round_grid(
    points: &[Point],
    bbox: [f64; 4],
    open: &[u32],
    lower: f64,
    proposed: f64,
) -> (f64, SparseGrid<u32>) {
    let budget = 48 * open.len() + 4096;
    let mut threshold = proposed;
    loop {
        let grid = SparseGrid::new(
            bbox,
            threshold * 1.001,
            open.len(),
            |j| points[open[j] as usize],
            |j| j as u32,
            |j| j as u32,
        );
        let (pairs, worst) = (0..grid.keys.len())
            .into_par_iter()
            .map(|k| {
                let pairs = grid.cell(k).len() * grid.block_len(k);
                (pairs, pairs)
            })
            .reduce(|| (0, 0), |(s1, m1), (s2, m2)| (s1 + s2, m1.max(m2)));
        let step = threshold - lower;
        // Both in total and in every cell: one dense cluster's pairs would
        // cross each other quadratically often. Stop shrinking once the step
        // is tiny or the grid has reached its finest cells (points closer
        // than that stay together whatever the threshold).
        let finest = grid.inv * threshold * 1.001 < 0.999;
        if (pairs <= budget && worst <= MAX_CELL_PAIRS) || step <= 1e-3 * threshold || finest {
            return (threshold, grid);
        }
        threshold = lower + 0.5 * step;
    }
}

/// The guard's bound on the pairs a cell and its neighbours make (uniform
/// points at the first threshold stay well below it).
const MAX_CELL_PAIRS: usize = 1024;

/// The points, bucketed by a grid of about one point per cell.
struct PointsNear<'a> {
    points: &'a [Point],
    grid: SparseGrid<u32>,
}

impl<'a> PointsNear<'a> {
    fn new(points: &'a [Point], bbox: [f64; 4], cell: f64) -> Self {
        Self {
            points,
            grid: SparseGrid::new(
                bbox,
                cell,
                points.len(),
                |i| points[i],
                |i| i as u32,
                |i| i as u32,
            ),
        }
    }

    /// Does some point lie on the open segment `ab`? (Exact.)
    fn on_segment(&self, a: Point, b: Point) -> bool {
        self.grid.any_cell_near(a, b, 0.0, |cell| {
            cell.iter().any(|&z| {
                let pz = self.points[z as usize];
                boxes_meet(a, b, pz, pz) && pz != a && pz != b && on_open_segment(pz, a, b)
            })
        })
    }
}

/// Pass 1 of [`decide_round`] on a chunk of candidates: the blocked ranks
/// and the (rank, dependency rank) pairs.
#[inline(never)]
fn scan_chunk(
    points: &[Point],
    segments: &[[u32; 2]],
    ranks: &[u32],
    index: &SegmentIndex,
    earlier: Option<&SegmentIndex>,
    near: &PointsNear,
    shortest_at: &[u32],
) -> (Vec<u32>, Vec<[u32; 2]>) {
    let (mut blocked, mut deps) = (Vec::new(), Vec::new());
    for (&[a, b], &r) in segments.iter().zip(ranks) {
        if shortest_at.get(a as usize) == Some(&r) && shortest_at[b as usize] == r {
            continue; // accepted whatever the others do (see `decide_round`)
        }
        let q = Query::new(points[a as usize], points[b as usize]);
        if earlier.is_some_and(|e| e.crossed_by(&q)) || near.on_segment(q.a, q.b) {
            blocked.push(r);
            continue;
        }
        index.scan_near(q.a, q.b, |s| {
            if s.id >= r {
                return true;
            }
            if s.crosses(&q) {
                deps.push([r, s.id]);
            }
            false
        });
    }
    (blocked, deps)
}

/// Decides one round: `candidates` in spatial order with `rank` their
/// positions in the global segment order, `active` the earlier edges they
/// must not cross (module docs). Returns the accepted candidates.
fn decide_round(
    points: &[Point],
    bbox: [f64; 4],
    candidates: &[[u32; 2]],
    rank: &[u32],
    active: &[[u32; 2]],
    near: &PointsNear,
    first_round: bool,
) -> Vec<[u32; 2]> {
    let m = candidates.len();
    if m == 0 {
        return Vec::new();
    }
    // In the first round (no earlier edges) every segment shorter than the
    // threshold is a candidate, so the lowest rank at a vertex is the
    // shortest segment there. A segment shortest at both ends is a GT edge:
    // a shorter `cd` crossing `ab` would make, by the □-Lemma,
    // `|ac| + |bd| < |ab| + |cd| < 2|ab|`, so `ac` or `bd` would be shorter
    // still; and a point on `ab` would make a shorter segment at `a`. Its
    // dependencies need not be listed.
    let shortest_at: Vec<u32> = if active.is_empty() && first_round {
        let lowest: Vec<std::sync::atomic::AtomicU32> = (0..points.len())
            .map(|_| std::sync::atomic::AtomicU32::new(NONE))
            .collect();
        candidates.par_iter().zip(rank).for_each(|(&[a, b], &r)| {
            lowest[a as usize].fetch_min(r, std::sync::atomic::Ordering::Relaxed);
            lowest[b as usize].fetch_min(r, std::sync::atomic::Ordering::Relaxed);
        });
        lowest.into_iter().map(|x| x.into_inner()).collect()
    } else {
        Vec::new()
    };
    let index = SegmentIndex::new(points, bbox, candidates, rank);
    let earlier = (!active.is_empty()).then(|| {
        let ids: Vec<u32> = (0..active.len() as u32).collect();
        SegmentIndex::new(points, bbox, active, &ids)
    });

    // Pass 1, in spatial order: blocked candidates and (rank, dependency) pairs.
    const CHUNK: usize = 4096;
    let (blocked, dependencies): (Vec<u32>, Vec<[u32; 2]>) = candidates
        .par_chunks(CHUNK)
        .zip(rank.par_chunks(CHUNK))
        .map(|(segments, ranks)| {
            scan_chunk(
                points,
                segments,
                ranks,
                &index,
                earlier.as_ref(),
                near,
                &shortest_at,
            )
        })
        .reduce(
            || (Vec::new(), Vec::new()),
            |(mut b1, mut d1), (b2, d2)| {
                b1.extend(b2);
                d1.extend(d2);
                (b1, d1)
            },
        );

    // Pass 2, in the global order.
    let mut start = vec![0u32; m + 1];
    for &[r, _] in &dependencies {
        start[r as usize + 1] += 1;
    }
    for r in 0..m {
        start[r + 1] += start[r];
    }
    let mut fill = start.clone();
    let mut flat = vec![0u32; dependencies.len()];
    for &[r, s] in &dependencies {
        flat[fill[r as usize] as usize] = s;
        fill[r as usize] += 1;
    }
    drop(dependencies);
    let mut accepted = vec![true; m];
    for r in blocked {
        accepted[r as usize] = false;
    }
    for r in 0..m {
        if accepted[r] {
            let deps = &flat[start[r] as usize..start[r + 1] as usize];
            accepted[r] = deps.iter().all(|&s| !accepted[s as usize]);
        }
    }
    candidates
        .iter()
        .zip(rank)
        .filter(|(_, &r)| accepted[r as usize])
        .map(|(s, _)| *s)
        .collect()
}
