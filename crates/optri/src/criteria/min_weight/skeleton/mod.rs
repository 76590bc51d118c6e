//! The candidate edges of a minimum-weight triangulation of a point set and
//! its LMT-skeleton.
//!
//! 1. **Diamond filter** (R. L. S. Drysdale, S. McElfresh & J. Snoeyink, *On
//!    exclusion regions for optimal triangulations*, Discrete Appl. Math. 109,
//!    2001): an edge `pq` of a minimum-weight triangulation has at least one
//!    of its two isosceles triangles with base `pq` and base angle `π/4.6`
//!    empty of points. The exact test uses the slightly smaller dyadic angle
//!    of [`angle_below_diamond`], so it removes only edges the theorem
//!    removes. Candidates come from each point's neighbourhood in a grid,
//!    searched in rings (radius ×1.25, each grid cell read once) until every
//!    direction *ahead* is *dead*. A pair is tested from the endpoint the
//!    other is ahead of (lexicographically greater `(x, y)`: directions in
//!    `(−π/2, π/2]`), so a search needs killers for the half-plane ahead
//!    only and skips the points too far behind to kill there (10⁵ uniform
//!    points: 6 % fewer rings and 14 % fewer pairs looked at than searching
//!    every direction; the rings hardly shrink, as the stop needs killers
//!    dense enough around the whole half-plane). A point `r`
//!    at distance `d` and angle `θ` from `p` lies strictly inside the left
//!    triangle (base angle `α'`, the exact test's) of every `pq` whose
//!    direction `φ` satisfies `0 < θ − φ < α'` once `|pq| > 2cos(α')·d ≈
//!    1.5515d` (the base angle at `q` is then below `α'`; `cos δ + sin δ·cot α`
//!    grows on `0 < δ < α` to `2cos α`), and symmetrically for the right
//!    triangle; directions whose ray leaves the bounding box are dead too.
//!    A dead direction fails the exact test, so the candidates do not depend
//!    on the rings' schedule. The exact test scans the disk around the
//!    midpoint (both triangles lie in it) with a certified `f64` filter
//!    before the exact predicates ([`DiamondTriangles`]). The search uses
//!    `1.6d` and angular margins of 10⁻⁷ rad, 500 times the error of its
//!    polynomial angles ([`angle_of`]), so the stop is conservative; it only
//!    chooses which pairs get the exact test. Each point read is handled
//!    once (its ring and its stop test are known from its distance), and
//!    the points are bucketed in [`PointCells`] (coordinates in cell order).
//!    Parallel over points.
//! 2. **LMT-skeleton** (M. T. Dickerson, J. M. Keil & M. H. Montague, *A large
//!    subgraph of the minimum weight triangulation*, DCG 18, 1997; the
//!    half-edge loop of R. Beirouti & J. Snoeyink, *Implementations of the
//!    LMT heuristic for minimum weight triangulation*, SoCG 1998): an edge of
//!    a minimum-weight triangulation `T` is *locally minimal* in `T` — with
//!    its two triangles `pqr`, `pqs` either the quadrilateral is not strictly
//!    convex or `|pq| ≤ |rs|` (exact). Triangles are empty candidate
//!    triangles (no point in the closed triangle but its corners) whose two
//!    other edges are still candidates; an edge without a locally minimal
//!    pair is removed, which can only invalidate triangles of its
//!    neighbours, so a work list reaches the fixed point. Emptiness is
//!    decided lazily, only for a pair of triangles that passes the length
//!    test (at 10⁴ uniform points the emptiness tests visit 47 % fewer grid
//!    cells, by callgrind call counts). Edges that
//!    intersect no remaining candidate are *certain*: in every triangulation
//!    drawn from the candidates (a triangulation is a maximal non-crossing
//!    set), hence in every minimum-weight triangulation. Convex-hull edges
//!    between consecutive hull points are always certain.

mod certain;
mod diamond;
mod lmt_loop;

#[cfg(any(test, feature = "internals"))]
pub(crate) use diamond::diamond_candidates;
pub(crate) use diamond::diamond_filter;
pub(crate) use lmt_loop::LOOP_CHUNK;

use crate::error::{Error, UnsupportedReason};
use crate::interrupt::Stop;
use crate::kernel::Point;
use crate::spatial::{convex_hull_cycle, PointCells};
use crate::structures::Csr;

/// What bounds the skeleton's construction: the bytes its candidate
/// triangles and their lists may take, and the run's stop.
#[derive(Clone, Copy)]
pub(crate) struct Limits<'a> {
    /// Bytes the loop's arrays may take ([`loop_bytes`]), decided from
    /// the count of candidate triangles before any of them is allocated.
    pub bytes: usize,
    /// Checked between the construction's passes and inside them.
    pub stop: &'a Stop,
}

/// The default of [`Limits::bytes`] on `n` points: 768 MiB, or 2 KiB a
/// point when that is more. Sets in general position need far less (at
/// 10⁶ uniform points about 0.2 KiB a point); points in nearly convex
/// position have Θ(n²) candidate edges and Θ(n³) candidate triangles
/// (1 000 points on a circle, rounded to integers: about 4 GB), which the
/// budget refuses before allocating them.
pub(crate) fn default_budget(n: usize) -> usize {
    (768usize << 20).max(n.saturating_mul(2048))
}

/// Bytes of the LMT loop's arrays for `triangles` candidate triangles on
/// `edges` candidate edges: per triangle its corners (12), its three
/// entries in the per-edge lists (12) and its state (1); per edge the
/// edge, its flags, its two adjacency entries and its list offsets.
pub(crate) fn loop_bytes(triangles: usize, edges: usize) -> usize {
    triangles
        .saturating_mul(25)
        .saturating_add(edges.saturating_mul(48))
}

/// The skeleton, or the bytes its construction would have needed beyond
/// the budget (nothing of that size allocated).
pub(crate) enum Built {
    Skeleton(Box<Skeleton>),
    OverBudget { bytes: usize },
}

/// Candidate edges with their empty triangles and the LMT state.
pub(crate) struct Skeleton {
    pub edges: Vec<[u32; 2]>,
    /// Edge still a candidate.
    pub alive: Vec<bool>,
    /// Edge in every minimum-weight triangulation.
    pub certain: Vec<bool>,
    /// Convex-hull edge (between consecutive hull points).
    pub hull: Vec<bool>,
    /// The empty triangles (counter-clockwise) whose three edges are left
    /// by the LMT loop, with their edge ids (filled after the loop).
    pub triangles: Vec<([u32; 3], [u32; 3])>,
    /// During the loop: every non-flat triangle of three candidate edges, as
    /// its counter-clockwise corners (12 bytes a triangle, the loop's largest
    /// array; the loop reads corners, its edge ids are looked up only when
    /// an empty triangle dies); emptied after the loop.
    loop_triangles: Vec<[u32; 3]>,
    /// CSR per edge: its triangles on the left of `u → v` (u < v), then
    /// right; emptied after the loop.
    tri_offsets: Vec<u32>,
    tri_list: Vec<u32>,
    tri_left_len: Vec<u32>,
    /// Per edge left: the edges left it intersects, sorted (computed on
    /// first use, for the faces with holes only).
    crossings: std::sync::OnceLock<Csr<u32>>,
    /// Per vertex: its neighbours (sorted) with the edge ids.
    adjacency: Csr<(u32, u32)>,
}

impl Skeleton {
    /// The skeleton of the candidate `edges` (sorted distinct pairs `u < v`)
    /// on `n` points, every edge `alive` or none, none certain or on the
    /// hull yet, and no triangles.
    fn new(n: usize, edges: Vec<[u32; 2]>, alive: bool) -> Self {
        let m = edges.len();
        let mut adjacency = Csr::from_pairs(
            n,
            edges
                .iter()
                .enumerate()
                .flat_map(|(id, &[u, v])| [(u, (v, id as u32)), (v, (u, id as u32))]),
        );
        adjacency.sort_rows();
        Skeleton {
            edges,
            alive: vec![alive; m],
            certain: vec![false; m],
            hull: vec![false; m],
            triangles: Vec::new(),
            loop_triangles: Vec::new(),
            tri_offsets: Vec::new(),
            tri_list: Vec::new(),
            tri_left_len: Vec::new(),
            crossings: std::sync::OnceLock::new(),
            adjacency,
        }
    }

    /// The edge id of `{u, v}`, if a candidate.
    pub fn edge_id(&self, u: u32, v: u32) -> Option<u32> {
        let list = self.adjacency.row(u);
        list.binary_search_by(|x| x.0.cmp(&v))
            .ok()
            .map(|i| list[i].1)
    }

    /// The neighbours of `u` with edge ids.
    pub fn neighbours(&self, u: u32) -> &[(u32, u32)] {
        self.adjacency.row(u)
    }

    /// The edge ids `[c0c1, c1c2, c2c0]` of a triangle of candidate edges
    /// with corners `[c0, c1, c2]`.
    fn triangle_edges(&self, [c0, c1, c2]: [u32; 3]) -> [u32; 3] {
        let id = |a: u32, b: u32| {
            self.edge_id(a, b)
                .expect("a loop triangle's sides are candidate edges")
        };
        [id(c0, c1), id(c1, c2), id(c2, c0)]
    }

    /// Triangles of edge `e` on its left (`u → v`) and right.
    fn sides(&self, e: u32) -> (&[u32], &[u32]) {
        let all = &self.tri_list
            [self.tri_offsets[e as usize] as usize..self.tri_offsets[e as usize + 1] as usize];
        all.split_at(self.tri_left_len[e as usize] as usize)
    }

    /// The edges left that `e` (left) intersects, sorted; `pts` are the
    /// skeleton's points. The first call computes the lists of all edges.
    pub fn crossing(&self, pts: &[Point], e: u32) -> &[u32] {
        self.crossings
            .get_or_init(|| certain::crossing_lists(pts, self))
            .row(e)
    }
}

/// [`z_order_skeleton`] for points in any order (for the tests): the work
/// runs on the points renumbered in Z-order and the result is mapped back,
/// identical, since the LMT-skeleton is the greatest fixed point of the
/// removal rule (removing an edge only removes triangles), whatever the
/// numbering and the work list's order.
#[cfg(test)]
pub(crate) fn lmt_skeleton(pts: &[Point], edges: Vec<[u32; 2]>) -> crate::error::Result<Skeleton> {
    lmt_skeleton_in_chunks(pts, edges, LOOP_CHUNK)
}

/// `lmt_skeleton` with `loop_chunk` edges per task of the parallel loop
/// (1: the most interleaving; `usize::MAX`: one task, the sequential loop).
#[cfg(any(test, feature = "internals"))]
pub(crate) fn lmt_skeleton_in_chunks(
    pts: &[Point],
    edges: Vec<[u32; 2]>,
    loop_chunk: usize,
) -> crate::error::Result<Skeleton> {
    debug_assert!(
        sorted_pairs(&edges),
        "candidates: sorted distinct pairs u < v"
    );
    use crate::parallel::prelude::*;
    let n = pts.len();
    let m = edges.len();
    let order = crate::spatial::morton_order(pts);
    let mut rank = vec![0u32; n];
    for (z, &v) in order.iter().enumerate() {
        rank[v as usize] = z as u32;
    }
    let z_pts: Vec<Point> = order.iter().map(|&v| pts[v as usize]).collect();
    let mut z_edges: Vec<[u32; 2]> = edges
        .par_iter()
        .map(|&[u, v]| {
            let (a, b) = (rank[u as usize], rank[v as usize]);
            [a.min(b), a.max(b)]
        })
        .collect();
    drop(rank);
    // Neither the input edges nor their ids are held during the loop: the
    // candidates are sorted distinct pairs `u < v`, so both follow from the
    // renumbered edges mapped back and sorted again.
    drop(edges);
    z_edges.par_sort_unstable();
    let z = {
        let grid = super::point_grid(&z_pts);
        let limits = Limits {
            bytes: usize::MAX,
            stop: &Stop::default(),
        };
        match z_order_skeleton(&z_pts, &grid, z_edges, loop_chunk, limits)? {
            Built::Skeleton(z) => *z,
            Built::OverBudget { .. } => unreachable!("no budget"),
        }
    };
    drop(z_pts);
    let mut mapped: Vec<([u32; 2], u32)> = z
        .edges
        .par_iter()
        .enumerate()
        .map(|(k, &[a, b])| {
            let (u, v) = (order[a as usize], order[b as usize]);
            ([u.min(v), u.max(v)], k as u32)
        })
        .collect();
    mapped.par_sort_unstable();
    // The original id of each renumbered edge.
    let mut original = vec![0u32; m];
    for (e, &(_, k)) in mapped.iter().enumerate() {
        original[k as usize] = e as u32;
    }
    let edges: Vec<[u32; 2]> = mapped.into_iter().map(|(pair, _)| pair).collect();
    let mut skeleton = Skeleton::new(n, edges, false);
    for (k, &e) in original.iter().enumerate() {
        let e = e as usize;
        skeleton.alive[e] = z.alive[k];
        skeleton.certain[e] = z.certain[k];
        skeleton.hull[e] = z.hull[k];
    }
    // The kept triangles as built in the original numbering: corners
    // counter-clockwise from the smallest index, edge ids `[c0c1, c1c2,
    // c2c0]`, in lexicographic order of the sorted corners (the order of
    // enumeration from each triangle's smallest edge).
    let mut triangles: Vec<([u32; 3], [u32; 3])> = z
        .triangles
        .par_iter()
        .map(|&(corners, ids)| {
            let c = corners.map(|v| order[v as usize]);
            let first = (0..3).min_by_key(|&i| c[i]).unwrap_or(0);
            (
                std::array::from_fn(|i| c[(i + first) % 3]),
                std::array::from_fn(|i| original[ids[(i + first) % 3] as usize]),
            )
        })
        .collect();
    drop(z);
    triangles.par_sort_unstable_by_key(|&(c, _)| {
        let mut key = c;
        key.sort_unstable();
        key
    });
    skeleton.triangles = triangles;
    Ok(skeleton)
}

/// Are the candidate edges sorted distinct pairs `u < v` (as the diamond
/// filter gives them)?
fn sorted_pairs(edges: &[[u32; 2]]) -> bool {
    edges.windows(2).all(|w| w[0] < w[1]) && edges.iter().all(|&[u, v]| u < v)
}

/// The error for `count` ids (of edges or triangles) above `limit` on `n`
/// points: the limit on points is estimated at this input's density.
fn too_many_points(n: usize, count: usize, limit: usize, because: &'static str) -> Error {
    Error::Unsupported {
        criterion: "min-weight",
        reason: UnsupportedReason::TooManyPoints {
            limit: (n as f64 * limit as f64 / count as f64) as usize,
            distinct: n,
            because,
        },
    }
}

/// Builds the triangles and crossings of the candidate edges (sorted
/// distinct pairs `u < v`, as [`diamond_filter`] gives them) and runs the
/// LMT loop; `grid` is [`point_grid`](super::point_grid) of `pts`. Correct in
/// any numbering, meant for points in Z-order (the loop's accesses to
/// triangles, edges and points then stay mostly within cache: in input
/// order each is a miss). Over `limits.bytes` nothing large is allocated.
///
/// # Errors
/// [`Error::Interrupted`] when `limits.stop` says so.
pub(crate) fn z_order_skeleton(
    pts: &[Point],
    grid: &PointCells,
    edges: Vec<[u32; 2]>,
    loop_chunk: usize,
    limits: Limits,
) -> crate::error::Result<Built> {
    debug_assert!(
        sorted_pairs(&edges),
        "candidates: sorted distinct pairs u < v"
    );
    let n = pts.len();
    let m = edges.len();
    // Edge ids are `u32`, the adjacency's offsets count `2m`.
    if m > u32::MAX as usize / 2 {
        return Err(too_many_points(
            n,
            m,
            u32::MAX as usize / 2,
            "u32 ids of candidate edges",
        ));
    }
    let hull_cycle = convex_hull_cycle(pts);
    let mut skeleton = Skeleton::new(n, edges, true);
    for i in 0..hull_cycle.len() {
        let (a, b) = (hull_cycle[i], hull_cycle[(i + 1) % hull_cycle.len()]);
        if let Some(e) = skeleton.edge_id(a, b) {
            skeleton.hull[e as usize] = true;
        }
    }
    if let Some(bytes) = lmt_loop::run(pts, grid, &mut skeleton, loop_chunk, limits)? {
        return Ok(Built::OverBudget { bytes });
    }
    limits.stop.check()?;
    skeleton.certain = certain::certain_edges(pts, &skeleton);
    Ok(Built::Skeleton(Box::new(skeleton)))
}
