//! GT of arbitrary point sets: the Dickerson–Drysdale–McElfresh–Welzl idea of
//! processing only plausible candidates (literature.md §b), made exact.
//!
//! Candidates are processed in *length rounds*: round `k` takes every pair of
//! still-open vertices whose exact length lies in `[T_{k-1}, T_k)`
//! (`T_k = 2^k T_0`, `T_0` about 1.6 mean point spacings), sorted by the global
//! segment order. Rounds are disjoint length ranges, so the pairs are
//! processed in the global order, exactly as the naive algorithm would (pairs
//! at closed vertices are skipped; they could never be added).
//!
//! The partial GT `G` is kept as counter-clockwise neighbour lists (exact
//! comparator [`compare_angles`]). When a candidate `ab` comes up, every
//! shorter pair has been decided, and we rely on:
//!
//! **Lemma (empty triangles).** If every pair shorter than `ℓ` has been
//! decided and `u, w` are consecutive neighbours of `v` with `uw ∈ G`,
//! `|vu|, |vw|, |uw| < ℓ` and a left turn `v, u, w`, the triangle `vuw` holds
//! no point. *Proof:* all segments between points of the closed triangle are
//! shorter than `ℓ` and cannot cross the triangle's sides, so `G` restricted
//! to them is a maximal non-crossing set, i.e. a triangulation of those
//! points; with a point inside, `v` would have an edge into the triangle,
//! between `u` and `w`. ∎
//!
//! Hence `ab` is rejected at once if, at `a` or at `b`, its direction is that
//! of an existing edge (a point on the open segment `ab`, or an overlapping
//! edge — in both cases the nearest point `z` on `ab` gives a shorter `az`
//! that was rejected for crossing an edge, which then crosses `ab` too) or
//! falls into such a closed triangular gap (the far endpoint is outside the
//! empty triangle, so `ab` crosses its third side). Otherwise `ab` is tested
//! exactly against the edges registered in the grid cells along it.
//!
//! A vertex is *closed* when every angular gap is a closed triangle or, on
//! the hull, the outer gap between its two hull neighbours: no further edge
//! can reach it. After each round only open vertices take part, so rounds
//! shrink to the regions where long GT edges remain (mostly along the hull).
//! The final round (once `T_k` exceeds the bounding-box diagonal) takes all
//! remaining pairs of open vertices; that is quadratic in their number, which
//! is why convex inputs go to [`super::convex`].

use super::{properly_cross, sort_segments};
use crate::convex_hull::hull_distinct;
use crate::kernel::{compare_lengths, orient_sign, Point};
use crate::planar_graph::compare_angles;
use std::cmp::Ordering;

const NONE: u32 = u32::MAX;

/// A uniform grid over the bounding box of the points.
struct Grid {
    x0: f64,
    y0: f64,
    cell: f64,
    inv: f64,
    nx: usize,
    ny: usize,
    /// Absolute slack covering rounding in cell computations.
    slack_x: f64,
    slack_y: f64,
}

impl Grid {
    fn new(bbox: [f64; 4], cell: f64) -> Self {
        let [x0, y0, x1, y1] = bbox;
        let nx = (((x1 - x0) / cell).floor() as usize + 1).max(1);
        let ny = (((y1 - y0) / cell).floor() as usize + 1).max(1);
        let mag_x = x0.abs().max(x1.abs());
        let mag_y = y0.abs().max(y1.abs());
        Self {
            x0,
            y0,
            cell,
            inv: 1.0 / cell,
            nx,
            ny,
            slack_x: 1e-9 * cell + 1e-13 * mag_x,
            slack_y: 1e-9 * cell + 1e-13 * mag_y,
        }
    }

    #[inline]
    fn cx(&self, x: f64) -> usize {
        let c = ((x - self.x0) * self.inv).floor();
        if c <= 0.0 {
            0
        } else {
            (c as usize).min(self.nx - 1)
        }
    }

    #[inline]
    fn cy(&self, y: f64) -> usize {
        let c = ((y - self.y0) * self.inv).floor();
        if c <= 0.0 {
            0
        } else {
            (c as usize).min(self.ny - 1)
        }
    }

    #[inline]
    fn cell_of(&self, p: Point) -> usize {
        self.cy(p[1]) * self.nx + self.cx(p[0])
    }

    /// Calls `f` on every cell the segment `ab` may touch, walking from `a`
    /// towards `b`; stops early and returns `true` when `f` does.
    ///
    /// Conservative: if two segments share a point, both walks visit the cell
    /// containing it. Per column the segment's y-range is computed over the
    /// column widened by the slack, then padded by the slack.
    fn walk(&self, a: Point, b: Point, mut f: impl FnMut(usize) -> bool) -> bool {
        let (ca, cb) = (self.cx(a[0]), self.cx(b[0]));
        let (xlo_seg, xhi_seg) = (a[0].min(b[0]), a[0].max(b[0]));
        let (ylo_seg, yhi_seg) = (a[1].min(b[1]), a[1].max(b[1]));
        let dx = b[0] - a[0];
        let slope = if dx == 0.0 { 0.0 } else { (b[1] - a[1]) / dx };
        let columns = ca.abs_diff(cb) + 1;
        let upward = b[1] >= a[1];
        for step in 0..columns {
            let c = if ca <= cb { ca + step } else { ca - step };
            let (ylo, yhi) = if columns == 1 || dx == 0.0 {
                (ylo_seg, yhi_seg)
            } else {
                let xl = (self.x0 + c as f64 * self.cell - self.slack_x).max(xlo_seg);
                let xr = (self.x0 + (c + 1) as f64 * self.cell + self.slack_x).min(xhi_seg);
                let (yl, yr) = (a[1] + (xl - a[0]) * slope, a[1] + (xr - a[0]) * slope);
                (
                    yl.min(yr).max(ylo_seg).min(yhi_seg),
                    yl.max(yr).min(yhi_seg).max(ylo_seg),
                )
            };
            let (r0, r1) = (self.cy(ylo - self.slack_y), self.cy(yhi + self.slack_y));
            for k in 0..=r1 - r0 {
                let r = if upward { r0 + k } else { r1 - k };
                if f(r * self.nx + c) {
                    return true;
                }
            }
        }
        false
    }
}

/// Points bucketed by grid cell (CSR).
struct Buckets {
    start: Vec<u32>,
    items: Vec<u32>,
}

impl Buckets {
    fn new(grid: &Grid, points: &[Point], which: impl Iterator<Item = u32> + Clone) -> Self {
        let cells = grid.nx * grid.ny;
        let mut start = vec![0u32; cells + 1];
        for v in which.clone() {
            start[grid.cell_of(points[v as usize]) + 1] += 1;
        }
        for c in 0..cells {
            start[c + 1] += start[c];
        }
        let mut fill = start.clone();
        let mut items = vec![0u32; start[cells] as usize];
        for v in which {
            let c = grid.cell_of(points[v as usize]);
            items[fill[c] as usize] = v;
            fill[c] += 1;
        }
        Self { start, items }
    }

    #[inline]
    fn cell(&self, c: usize) -> &[u32] {
        &self.items[self.start[c] as usize..self.start[c + 1] as usize]
    }
}

/// The partial greedy triangulation.
struct Partial<'a> {
    points: &'a [Point],
    /// Neighbours of each vertex, counter-clockwise from the positive x-axis.
    adjacency: Vec<Vec<u32>>,
    edges: Vec<[u32; 2]>,
    hull_prev: Vec<u32>,
    hull_next: Vec<u32>,
    grid: Grid,
    /// Edge ids registered per grid cell.
    cell_edges: Vec<Vec<u32>>,
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

    /// Position at which direction `a → b` sorts into `a`'s neighbour list.
    fn angular_position(&self, a: u32, b: u32) -> usize {
        let (pa, pb) = (self.p(a), self.p(b));
        self.adjacency[a as usize]
            .partition_point(|&n| compare_angles(pa, self.points[n as usize], pb) == Ordering::Less)
    }

    /// May an edge leave `a` towards `b`? `None` if the direction is taken
    /// or falls into a closed triangular gap (module docs, Lemma); otherwise
    /// the position at which `b` sorts into `a`'s neighbour list.
    fn gap_open(&self, a: u32, b: u32) -> Option<usize> {
        let list = &self.adjacency[a as usize];
        let len = list.len();
        let pos = self.angular_position(a, b);
        let pa = self.p(a);
        if pos < len && compare_angles(pa, self.p(list[pos]), self.p(b)) == Ordering::Equal {
            return None;
        }
        if len < 2 {
            return Some(pos);
        }
        let u = list[(pos + len - 1) % len];
        let w = list[pos % len];
        let closed = orient_sign(pa, self.p(u), self.p(w)) > 0 && self.has_edge(u, w);
        (!closed).then_some(pos)
    }

    fn crosses_an_edge(&self, a: u32, b: u32) -> bool {
        let (pa, pb) = (self.p(a), self.p(b));
        self.grid.walk(pa, pb, |c| {
            self.cell_edges[c].iter().any(|&e| {
                let [u, w] = self.edges[e as usize];
                u != a && u != b && w != a && w != b && properly_cross(pa, pb, self.p(u), self.p(w))
            })
        })
    }

    fn try_add(&mut self, a: u32, b: u32) -> bool {
        let Some(at_a) = self.gap_open(a, b) else {
            return false;
        };
        let Some(at_b) = self.gap_open(b, a) else {
            return false;
        };
        if self.crosses_an_edge(a, b) {
            return false;
        }
        self.adjacency[a as usize].insert(at_a, b);
        self.adjacency[b as usize].insert(at_b, a);
        let id = self.edges.len() as u32;
        self.edges.push([a, b]);
        let (pa, pb) = (self.p(a), self.p(b));
        let (grid, cell_edges) = (&self.grid, &mut self.cell_edges);
        grid.walk(pa, pb, |c| {
            cell_edges[c].push(id);
            false
        });
        true
    }

    /// No edge can be added at `v` any more (module docs).
    fn closed(&self, v: u32) -> bool {
        let list = &self.adjacency[v as usize];
        let len = list.len();
        if len < 2 {
            return false;
        }
        let pv = self.p(v);
        (0..len).all(|i| {
            let (u, w) = (list[i], list[(i + 1) % len]);
            (self.hull_prev[v as usize] == u && self.hull_next[v as usize] == w)
                || (orient_sign(pv, self.p(u), self.p(w)) > 0 && self.has_edge(u, w))
        })
    }
}

/// Exact `|pq| < t` for a threshold length `t`, with a rounded shortcut.
#[inline]
fn shorter_than(p: Point, q: Point, t: f64) -> bool {
    let (dx, dy) = (p[0] - q[0], p[1] - q[1]);
    let d2 = dx * dx + dy * dy;
    let t2 = t * t;
    if d2 < t2 * (1.0 - 1e-9) {
        return true;
    }
    if d2 > t2 * (1.0 + 1e-9) {
        return false;
    }
    compare_lengths(p, q, [0.0, 0.0], [t, 0.0]) == Ordering::Less
}

/// GT edges of `points` (distinct, not all collinear).
///
/// Works on a copy renumbered along a Morton (Z-order) curve of grid cells,
/// so that neighbouring vertices sit close in memory; ties are broken on the
/// original indices, because the symbolic perturbation depends on them: the
/// renumbered copy is only used where an index never decides a tie.
pub(super) fn greedy_general(original: &[Point]) -> Vec<[u32; 2]> {
    let n = original.len();
    let bbox = bounding_box(original);
    let grid = Grid::new(bbox, mean_spacing(bbox, n));
    let morton = |p: Point| {
        let spread = |mut v: u64| {
            v &= 0xffff_ffff;
            v = (v | (v << 16)) & 0x0000_ffff_0000_ffff;
            v = (v | (v << 8)) & 0x00ff_00ff_00ff_00ff;
            v = (v | (v << 4)) & 0x0f0f_0f0f_0f0f_0f0f;
            v = (v | (v << 2)) & 0x3333_3333_3333_3333;
            (v | (v << 1)) & 0x5555_5555_5555_5555
        };
        spread(grid.cx(p[0]) as u64) | (spread(grid.cy(p[1]) as u64) << 1)
    };
    let mut to_original: Vec<u32> = (0..n as u32).collect();
    to_original.sort_by_cached_key(|&v| morton(original[v as usize]));
    let mut to_local = vec![0u32; n];
    for (local, &v) in to_original.iter().enumerate() {
        to_local[v as usize] = local as u32;
    }
    let local: Vec<Point> = to_original.iter().map(|&v| original[v as usize]).collect();
    let renumbering = Renumbering {
        original,
        to_original: &to_original,
        to_local: &to_local,
    };
    greedy_rounds(&local, &renumbering)
        .into_iter()
        .map(|[a, b]| [to_original[a as usize], to_original[b as usize]])
        .collect()
}

/// Local (memory-friendly) numbering versus the caller's, which decides ties.
struct Renumbering<'a> {
    original: &'a [Point],
    to_original: &'a [u32],
    to_local: &'a [u32],
}

impl Renumbering<'_> {
    /// Sorts local-index segments by the global order on original indices.
    fn sort(&self, segments: &mut Vec<[u32; 2]>) {
        for s in segments.iter_mut() {
            *s = s.map(|v| self.to_original[v as usize]);
        }
        sort_segments(self.original, segments);
        for s in segments.iter_mut() {
            *s = s.map(|v| self.to_local[v as usize]);
        }
    }
}

fn bounding_box(points: &[Point]) -> [f64; 4] {
    let mut bbox = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for p in points {
        bbox[0] = bbox[0].min(p[0]);
        bbox[1] = bbox[1].min(p[1]);
        bbox[2] = bbox[2].max(p[0]);
        bbox[3] = bbox[3].max(p[1]);
    }
    bbox
}

/// About one point per cell; a flat box still gets a sensible cell.
fn mean_spacing(bbox: [f64; 4], n: usize) -> f64 {
    let (w, h) = (bbox[2] - bbox[0], bbox[3] - bbox[1]);
    ((w.max(h * 1e-6) * h.max(w * 1e-6)) / n as f64).sqrt()
}

fn greedy_rounds(points: &[Point], renumbering: &Renumbering) -> Vec<[u32; 2]> {
    let n = points.len();
    let mut bbox = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for p in points {
        bbox[0] = bbox[0].min(p[0]);
        bbox[1] = bbox[1].min(p[1]);
        bbox[2] = bbox[2].max(p[0]);
        bbox[3] = bbox[3].max(p[1]);
    }
    let (w, h) = (bbox[2] - bbox[0], bbox[3] - bbox[1]);
    // About one point per cell; a flat box still gets a sensible cell.
    let spacing = ((w.max(h * 1e-6) * h.max(w * 1e-6)) / n as f64).sqrt();
    let hull = hull_distinct(points);
    let mut hull_prev = vec![NONE; n];
    let mut hull_next = vec![NONE; n];
    for i in 0..hull.len() {
        let v = hull[i] as usize;
        hull_prev[v] = hull[(i + hull.len() - 1) % hull.len()];
        hull_next[v] = hull[(i + 1) % hull.len()];
    }
    let grid = Grid::new(bbox, spacing);
    let cells = grid.nx * grid.ny;
    let mut g = Partial {
        points,
        // Allocated in vertex order, so lists of nearby vertices are close in memory.
        adjacency: (0..n).map(|_| Vec::with_capacity(8)).collect(),
        edges: Vec::with_capacity(3 * n),
        hull_prev,
        hull_next,
        grid,
        cell_edges: vec![Vec::new(); cells],
    };
    let target = 3 * n - 3 - hull.len();

    // Round 0: all pairs shorter than T_0, from the point grid.
    let mut threshold = 1.6 * spacing;
    let mut candidates: Vec<[u32; 2]> = Vec::new();
    {
        let buckets = Buckets::new(&g.grid, points, 0..n as u32);
        let reach = (threshold / spacing).ceil() as usize + 1;
        for v in 0..n as u32 {
            let pv = points[v as usize];
            let (cx, cy) = (g.grid.cx(pv[0]), g.grid.cy(pv[1]));
            for r in cy.saturating_sub(reach)..=(cy + reach).min(g.grid.ny - 1) {
                for c in cx.saturating_sub(reach)..=(cx + reach).min(g.grid.nx - 1) {
                    for &u in buckets.cell(r * g.grid.nx + c) {
                        if u > v && shorter_than(pv, points[u as usize], threshold) {
                            candidates.push([v, u]);
                        }
                    }
                }
            }
        }
    }
    renumbering.sort(&mut candidates);
    for &[a, b] in &candidates {
        g.try_add(a, b);
    }
    let mut open: Vec<u32> = (0..n as u32).filter(|&v| !g.closed(v)).collect();

    // Later rounds: only pairs of open vertices, doubling the threshold.
    let diagonal = (w * w + h * h).sqrt();
    while g.edges.len() < target && !open.is_empty() {
        let lower = threshold;
        threshold *= 2.0;
        // Once every pair is shorter than the threshold, take all the rest.
        let last = threshold > 1.01 * diagonal;
        candidates.clear();
        let keep = |g: &Partial, a: u32, b: u32| {
            let (pa, pb) = (points[a as usize], points[b as usize]);
            !shorter_than(pa, pb, lower)
                && (last || shorter_than(pa, pb, threshold))
                && g.gap_open(a, b).is_some()
                && g.gap_open(b, a).is_some()
        };
        if last {
            for (i, &a) in open.iter().enumerate() {
                for &b in &open[i + 1..] {
                    if keep(&g, a, b) {
                        candidates.push([a, b]);
                    }
                }
            }
        } else {
            // Cells a little wider than the threshold: close pairs sit in
            // neighbouring cells.
            let round_grid = Grid::new(bbox, threshold * 1.001);
            let buckets = Buckets::new(&round_grid, points, open.iter().copied());
            for &v in &open {
                let pv = points[v as usize];
                let (cx, cy) = (round_grid.cx(pv[0]), round_grid.cy(pv[1]));
                for r in cy.saturating_sub(1)..=(cy + 1).min(round_grid.ny - 1) {
                    for c in cx.saturating_sub(1)..=(cx + 1).min(round_grid.nx - 1) {
                        for &u in buckets.cell(r * round_grid.nx + c) {
                            if u > v && keep(&g, v, u) {
                                candidates.push([v, u]);
                            }
                        }
                    }
                }
            }
        }
        renumbering.sort(&mut candidates);
        for &[a, b] in &candidates {
            g.try_add(a, b);
        }
        open.retain(|&v| !g.closed(v));
        if last {
            break;
        }
    }
    debug_assert_eq!(
        g.edges.len(),
        target,
        "greedy did not complete a triangulation"
    );
    g.edges
}
