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

use crate::kernel::{
    compare_lengths, dot_sign, orient_sign, segments_intersect, DiamondPosition, DiamondTriangles,
    Point,
};
use crate::parallel::prelude::*;
use crate::spatial::{bounding_box, convex_hull_cycle, CellBlock, PointCells, SparseGrid};
use std::cmp::Ordering;
use std::f64::consts::PI;
use std::sync::atomic::{AtomicBool, AtomicU8, Ordering::SeqCst};

/// The angle of the exact test, `α' = arctan(833/1024)` (just below π/4.6),
/// for the search's stop: a killer is a point the exact test itself finds
/// inside (`2cos α' ≈ 1.5515 < 1.6`), so the candidates are exactly the pairs
/// that pass the exact test, whatever the rings' schedule.
const DIAMOND_ANGLE: f64 = 0.682_904_509_093_552_3;
/// Angular safety margin of the search's stop, radians: 500 times the error
/// of [`angle_of`].
const ANGLE_MARGIN: f64 = 1e-7;
/// Distance factor of the stop: 1.6 > 2cos(π/4.6) ≈ 1.551.
const KILL_FACTOR2: f64 = 1.6 * 1.6;
const TAU: f64 = 2.0 * PI;
/// A point at `(dx, dy)` from `p` with `dx < 0` and `|dy| < BEHIND_SLOPE·|dx|`
/// lies more than `α'` behind the half-plane ahead of `p` (`atan 1.2 ≈
/// 0.876 < π/2 − α' ≈ 0.888`), so it kills no direction ahead.
const BEHIND_SLOPE: f64 = 1.2;
/// A killer of a direction ahead of `p`, closer than the search radius `R`,
/// has `dx ≥ −R·sin α' ≈ −0.631R`; the search reads no farther behind than
/// `BEHIND_REACH·R`.
const BEHIND_REACH: f64 = 0.66;
/// Radius ratio of successive rings of the search: each cell is read once
/// whatever the ratio, so a small one only costs stop tests and saves the
/// exact tests of pairs beyond the stop radius (1.25 ran 5 % fewer
/// instructions than √2 at 10⁴ uniform points, same candidates).
const RING_GROWTH: f64 = 1.25;

/// [`diamond_filter`] with its own grid of the points (for the tests).
#[cfg(any(test, feature = "internals"))]
pub(crate) fn diamond_candidates(pts: &[Point]) -> Vec<[u32; 2]> {
    diamond_filter(pts, &super::point_grid(pts))
}

/// The candidate edges (pairs `u < v`, sorted) surviving the diamond filter,
/// with every convex-hull edge among them; `grid` is
/// [`point_grid`](super::point_grid) of `pts`.
pub(crate) fn diamond_filter(pts: &[Point], grid: &PointCells) -> Vec<[u32; 2]> {
    let bbox = bounding_box(pts);
    let (w, h) = (bbox[2] - bbox[0], bbox[3] - bbox[1]);
    let rings = Rings::new(grid.cell_size(), w.hypot(h));
    // Points in cell order, so that consecutive searches read the same
    // cells (the result is sorted below, so the order does not matter).
    let mut edges: Vec<[u32; 2]> = grid
        .ids()
        .par_chunks(64)
        .flat_map_iter(|chunk| {
            SCRATCH.with(|scratch| {
                let scratch = &mut scratch.borrow_mut();
                let mut out = Vec::new();
                for &p in chunk {
                    search_from(pts, grid, bbox, &rings, p, scratch, &mut out);
                }
                out
            })
        })
        .collect();
    let hull = convex_hull_cycle(pts);
    // Exact reservation: pushing onto the full collected vector would
    // double its capacity, and the candidates live through every phase.
    edges.reserve_exact(hull.len());
    for i in 0..hull.len() {
        let (a, b) = (hull[i], hull[(i + 1) % hull.len()]);
        edges.push([a.min(b), a.max(b)]);
    }
    edges.par_sort_unstable();
    edges.dedup();
    edges.shrink_to_fit();
    edges
}

/// The radii of the search's rings: `2·cell·1.25^k`, up to the first beyond
/// the bounding box's diagonal (the last ring, which holds every point).
struct Rings {
    radius: Vec<f64>,
    squared: Vec<f64>,
}

impl Rings {
    fn new(cell: f64, diagonal: f64) -> Self {
        let mut radius = vec![2.0 * cell];
        while radius[radius.len() - 1] <= diagonal {
            let next = radius[radius.len() - 1] * RING_GROWTH;
            radius.push(next);
        }
        let squared = radius.iter().map(|r| r * r).collect();
        Rings { radius, squared }
    }

    /// The first ring from `k` on whose squared radius exceeds `d2` (the
    /// last ring if none does).
    #[inline]
    fn first_beyond(&self, mut k: usize, d2: f64) -> usize {
        while k + 1 < self.squared.len() && d2 >= self.squared[k] {
            k += 1;
        }
        k
    }
}

/// One search's working lists, kept per thread so that a search allocates
/// nothing.
#[derive(Default)]
struct SearchScratch {
    /// Per ring: the points (offsets from the search's point, index) first
    /// closer than its radius.
    ring: Vec<Vec<(f64, f64, u32)>>,
    /// Per ring: the points that become killers at its stop test (angle, or
    /// NaN if not computed yet, and offsets).
    killer: Vec<Vec<(f64, f64, f64)>>,
    /// The killers' angles, sorted.
    killers: Vec<f64>,
    merge: Vec<f64>,
}

thread_local! {
    static SCRATCH: std::cell::RefCell<SearchScratch> = std::cell::RefCell::default();
}

/// Appends to `out` the pairs `{p, q}` (as `[min, max]`), `q` [`ahead`] of
/// `p`, from `p`'s search that survive the exact test.
///
/// Each grid cell is read once, when a ring's block first covers it; each
/// point read goes to the first ring whose radius it is closer than, and
/// (unless it lies too far behind to kill a direction ahead) to the stop
/// test after which it is a killer (`1.6d` below that ring's radius). A
/// pair whose direction is dead for the killers of the previous stop test
/// fails the exact test (its length is at least that ring's radius), so it
/// is skipped without changing the result. Angles are computed only for
/// the points a test or a killer needs.
fn search_from(
    pts: &[Point],
    grid: &PointCells,
    bbox: [f64; 4],
    rings: &Rings,
    p: u32,
    scratch: &mut SearchScratch,
    out: &mut Vec<[u32; 2]>,
) {
    let a = pts[p as usize];
    let count = rings.radius.len();
    if scratch.ring.len() < count {
        scratch.ring.resize_with(count, Vec::new);
        scratch.killer.resize_with(count, Vec::new);
    }
    let SearchScratch {
        ring,
        killer,
        killers,
        merge,
    } = scratch;
    killers.clear();
    let mut read: Option<CellBlock> = None;
    let mut last = 0;
    for k in 0..count {
        last = k;
        let radius = rings.radius[k];
        // Every point closer than `radius` lies in this block. Points
        // farther behind than `BEHIND_REACH·radius` are neither ahead nor
        // killers for a direction ahead.
        let block = grid.block(
            [a[0] - BEHIND_REACH * radius, a[1] - radius],
            [a[0] + radius, a[1] + radius],
            0.0,
        );
        grid.for_each_between(block, read, |coords, ids| {
            for (b, &q) in coords.iter().zip(ids) {
                if q != p {
                    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
                    ring[rings.first_beyond(k, dx * dx + dy * dy)].push((dx, dy, q));
                }
            }
        });
        read = Some(block);
        // The killers (closer than inner/1.6) apply to every pair of this
        // ring: they are the previous stop test's.
        for &(dx, dy, q) in &ring[k] {
            let d2 = dx * dx + dy * dy;
            let mut angle = f64::NAN;
            if ahead(dx, dy) {
                angle = angle_of(dx, dy);
                if direction_alive(angle, killers) && diamond_survives(a, pts[q as usize], d2, grid)
                {
                    out.push([p.min(q), p.max(q)]);
                }
            }
            // A point more than α' behind the half-plane ahead (within
            // atan(1.2) < π/2 − α' of the direction straight back) kills no
            // direction ahead.
            if !(dx < 0.0 && dy.abs() < -BEHIND_SLOPE * dx) {
                let mut i = k;
                while i + 1 < count && d2 * KILL_FACTOR2 >= rings.squared[i] {
                    i += 1;
                }
                if d2 * KILL_FACTOR2 < rings.squared[i] {
                    killer[i].push((angle, dx, dy));
                }
            }
        }
        ring[k].clear();
        if k + 1 == count {
            break;
        }
        // The stop test: killers for every pair beyond this ring, in one
        // batch, sorted once and merged with the earlier ones.
        let before = killers.len();
        for &(angle, dx, dy) in &killer[k] {
            killers.push(if angle.is_nan() {
                angle_of(dx, dy)
            } else {
                angle
            });
        }
        killer[k].clear();
        if killers.len() > before {
            killers[before..].sort_unstable_by(f64::total_cmp);
            if before > 0 && killers[before - 1] > killers[before] {
                merge_sorted_runs(killers, before, merge);
            }
        }
        if all_directions_dead(a, bbox, radius, killers) {
            break;
        }
    }
    for k in last..count {
        ring[k].clear();
        killer[k].clear();
    }
}

/// Is a point at offset `(dx, dy)` (computed differences, whose signs are
/// exact) ahead: `(b.x, b.y) > (a.x, a.y)` lexicographically, so its
/// direction's angle is in `(−π/2, π/2]`? Each pair of distinct points is
/// tested from the endpoint the other is ahead of, so a search needs to
/// kill only the directions ahead.
#[inline]
fn ahead(dx: f64, dy: f64) -> bool {
    dx > 0.0 || (dx == 0.0 && dy > 0.0)
}

/// Merges the sorted runs `v[..mid]` and `v[mid..]` (finite values) in
/// place, through `scratch`.
fn merge_sorted_runs(v: &mut [f64], mid: usize, scratch: &mut Vec<f64>) {
    scratch.clear();
    scratch.extend_from_slice(&v[..mid]);
    let (mut i, mut j, mut k) = (0, mid, 0);
    while i < scratch.len() && j < v.len() {
        if v[j] < scratch[i] {
            v[k] = v[j];
            j += 1;
        } else {
            v[k] = scratch[i];
            i += 1;
        }
        k += 1;
    }
    // What is left of the second run is already in place.
    v[k..k + scratch.len() - i].copy_from_slice(&scratch[i..]);
}

/// The direction of `(dx, dy) ≠ 0` in `[0, 2π]`, within [`ANGLE_ERROR`] of
/// the exact angle. Only the search's schedule reads it (which pairs get the
/// exact test), through margins of [`ANGLE_MARGIN`] far above that error.
/// `atan2` of libm cost a tenth of the filter; this is the octant reduction
/// and an odd polynomial of degree 21 for `atan` on `[0, 1]` (least-squares
/// weights refined towards the minimax: its error, measured against a
/// 30-digit `atan` on 2·10⁶ points of `[0, 1]`, is `1.401·10⁻¹⁰`, and the
/// unit test checks `ANGLE_ERROR` against libm's `atan2` on 10⁶ directions).
fn angle_of(dx: f64, dy: f64) -> f64 {
    const ATAN: [f64; 11] = [
        0.999_999_996_672_434_2,
        -0.333_333_020_895_448_6,
        0.199_991_297_980_091_13,
        -0.142_744_321_387_259_6,
        0.110_286_512_192_770_55,
        -0.087_138_610_759_487_81,
        0.065_413_805_023_052_62,
        -0.042_088_142_757_197_68,
        0.020_467_873_118_257_946,
        -0.006_394_788_388_519_606,
        0.000_937_562_738_847_779_3,
    ];
    let (ax, ay) = (dx.abs(), dy.abs());
    let t = if ay <= ax { ay / ax } else { ax / ay };
    let u = t * t;
    let mut r = ATAN[10];
    for &c in ATAN[..10].iter().rev() {
        r = r * u + c;
    }
    let mut r = t * r;
    if ay > ax {
        r = 0.5 * PI - r;
    }
    if dx < 0.0 {
        r = PI - r;
    }
    if dy < 0.0 {
        TAU - r
    } else {
        r
    }
}

/// A bound on the error of [`angle_of`] (its polynomial's `1.401·10⁻¹⁰`
/// plus rounding), checked by the unit test.
#[cfg(test)]
const ANGLE_ERROR: f64 = 2e-10;

/// Is direction `phi` not provably dead for the killers (sorted angles)?
/// Dead: a killer strictly beyond `phi + margin` and one strictly before
/// `phi − margin`, each within `α' − margin` of it (angles taken around the
/// circle).
#[inline]
fn direction_alive(phi: f64, killers: &[f64]) -> bool {
    let k = killers.len();
    if k == 0 {
        return true;
    }
    // Successor strictly beyond phi + margin; the predecessor strictly
    // before phi − margin is the killer before it, unless killers lie within
    // the margin of phi (rare: walk back over them).
    let s = killers.partition_point(|&t| t <= phi + ANGLE_MARGIN);
    let succ = if s < k { killers[s] } else { killers[0] + TAU };
    let mut pidx = s;
    while pidx > 0 && killers[pidx - 1] >= phi - ANGLE_MARGIN {
        pidx -= 1;
    }
    let pred = if pidx > 0 {
        killers[pidx - 1]
    } else {
        killers[k - 1] - TAU
    };
    let left = succ - phi < DIAMOND_ANGLE - ANGLE_MARGIN && succ - phi > ANGLE_MARGIN;
    let right = phi - pred < DIAMOND_ANGLE - ANGLE_MARGIN && phi - pred > ANGLE_MARGIN;
    !(left && right)
}

/// Are all directions ahead (the half-plane of [`ahead`]) dead beyond
/// `radius`: killed on both sides by the killers, or leaving the bounding
/// box?
fn all_directions_dead(a: Point, bbox: [f64; 4], radius: f64, killers: &[f64]) -> bool {
    // Arcs of directions that need no killer: those behind (angles in
    // (π/2, 3π/2), shrunk by margins far above atan2's rounding) and those
    // whose point at `radius` lies outside the box (at most four sides),
    // each with three shifts: fixed arrays, as this runs once per ring of
    // every point's search.
    let mut arcs = [[0.0f64; 2]; 15];
    let behind = [0.5 * PI + 4.0 * ANGLE_MARGIN, 1.5 * PI - 4.0 * ANGLE_MARGIN];
    for (k, shift) in [-TAU, 0.0, TAU].into_iter().enumerate() {
        arcs[k] = [behind[0] + shift, behind[1] + shift];
    }
    let mut arc_count = 3;
    let slack = 1e-9 * radius;
    for (distance, centre) in [
        (bbox[2] - a[0], 0.0),
        (bbox[3] - a[1], 0.5 * PI),
        (a[0] - bbox[0], PI),
        (a[1] - bbox[1], 1.5 * PI),
    ] {
        let c = (distance + slack) / radius;
        if c < 1.0 {
            let half = c.acos() - ANGLE_MARGIN;
            if half > 0.0 {
                for shift in [-TAU, 0.0, TAU] {
                    arcs[arc_count] = [centre - half + shift, centre + half + shift];
                    arc_count += 1;
                }
            }
        }
    }
    let arcs = &mut arcs[..arc_count];
    arcs.sort_unstable_by(|x, y| x[0].total_cmp(&y[0]));
    let mut merged = [[0.0f64; 2]; 15];
    let mut merged_count = 0;
    for &arc in arcs.iter() {
        if merged_count > 0 && arc[0] <= merged[merged_count - 1][1] {
            let last = &mut merged[merged_count - 1];
            last[1] = last[1].max(arc[1]);
        } else {
            merged[merged_count] = arc;
            merged_count += 1;
        }
    }
    let merged = &merged[..merged_count];
    let covered = |lo: f64, hi: f64| merged.iter().any(|m| m[0] < lo && hi < m[1]);
    let k = killers.len();
    if k == 0 {
        return covered(0.0, TAU);
    }
    let m = ANGLE_MARGIN;
    for i in 0..k {
        let lo = killers[i];
        let hi = if i + 1 < k {
            killers[i + 1]
        } else {
            killers[0] + TAU
        };
        if hi - lo < DIAMOND_ANGLE - 4.0 * m {
            continue; // every direction in this gap is killed on both sides
        }
        // Directions in the gap not killed on the left (successor `hi` too
        // far) or on the right (predecessor `lo` too far), widened.
        let first = [lo - 4.0 * m, hi - DIAMOND_ANGLE + 4.0 * m];
        let second = [lo + DIAMOND_ANGLE - 4.0 * m, hi + 4.0 * m];
        let parts = if first[1] >= second[0] {
            [[first[0], second[1]], [first[0], second[1]]]
        } else {
            [first, second]
        };
        for [x, y] in parts {
            if !covered(x, y) {
                return false;
            }
        }
    }
    true
}

/// Exact: is at least one of the two diamond triangles on `ab` empty? `d2`
/// is the rounded squared length of `ab`.
fn diamond_survives(a: Point, b: Point, d2: f64, grid: &PointCells) -> bool {
    // Both closed triangles lie in the disk of radius |ab|/2 around the
    // midpoint (the apexes are 0.407|ab| from it); the relative padding
    // covers the rounding of the midpoint and the length.
    let mid = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
    let reach = 0.5 * d2.sqrt() * (1.0 + 1e-9);
    let diamonds = DiamondTriangles::new(a, b);
    let (mut left, mut right) = (false, false);
    grid.any_near(mid, mid, reach, |coords, _| {
        for &c in coords {
            // Distinct points: only `a` and `b` have their coordinates.
            if c == a || c == b {
                continue;
            }
            let side = match diamonds.position(c) {
                DiamondPosition::Outside => continue,
                DiamondPosition::Left => &mut left,
                DiamondPosition::Right => &mut right,
            };
            *side = true;
            if left && right {
                return true;
            }
        }
        false
    });
    !(left && right)
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
    /// Per edge left: the edges left it intersects (computed on first use).
    crossings: std::sync::OnceLock<CrossingLists>,
    /// CSR per vertex: neighbours (sorted) and edge ids.
    adj_offsets: Vec<u32>,
    adj: Vec<(u32, u32)>,
}

impl Skeleton {
    /// The edge id of `{u, v}`, if a candidate.
    pub fn edge_id(&self, u: u32, v: u32) -> Option<u32> {
        let list = &self.adj
            [self.adj_offsets[u as usize] as usize..self.adj_offsets[u as usize + 1] as usize];
        list.binary_search_by(|x| x.0.cmp(&v))
            .ok()
            .map(|i| list[i].1)
    }

    /// The neighbours of `u` with edge ids.
    pub fn neighbours(&self, u: u32) -> &[(u32, u32)] {
        &self.adj[self.adj_offsets[u as usize] as usize..self.adj_offsets[u as usize + 1] as usize]
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
        let lists = self.crossings.get_or_init(|| crossing_lists(pts, self));
        &lists.list[lists.offsets[e as usize] as usize..lists.offsets[e as usize + 1] as usize]
    }
}

/// Does the closed triangle `abc` (counter-clockwise) contain a point other
/// than its corners?
pub(crate) fn triangle_has_point(pts: &[Point], grid: &PointCells, [i, j, k]: [u32; 3]) -> bool {
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

/// Do the candidate edges `e = [a, b]` and `f` intersect other than in a
/// shared endpoint (collinear overlap at a shared endpoint counts)?
fn edges_conflict(pts: &[Point], e: [u32; 2], f: [u32; 2]) -> bool {
    let p = |i: u32| pts[i as usize];
    let ([a, b], [c, d]) = ([p(e[0]), p(e[1])], [p(f[0]), p(f[1])]);
    // Disjoint bounding boxes (exact coordinate comparisons): no contact.
    for k in 0..2 {
        if a[k].max(b[k]) < c[k].min(d[k]) || c[k].max(d[k]) < a[k].min(b[k]) {
            return false;
        }
    }
    let shared = e.iter().find(|&&x| f.contains(&x)).copied();
    match shared {
        None => segments_intersect(a, b, c, d),
        Some(s) => {
            let u = if e[0] == s { e[1] } else { e[0] };
            let v = if f[0] == s { f[1] } else { f[0] };
            u != v && orient_sign(p(s), p(u), p(v)) == 0 && dot_sign(p(s), p(u), p(v)) > 0
        }
    }
}

use crate::error::{Error, UnsupportedReason};

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
        edges.windows(2).all(|w| w[0] < w[1]) && edges.iter().all(|&[u, v]| u < v),
        "candidates: sorted distinct pairs u < v"
    );
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
        z_order_skeleton(&z_pts, &grid, z_edges, loop_chunk)?
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
    let (adj_offsets, adj) = adjacency(n, &edges);
    let mut skeleton = Skeleton {
        alive: vec![false; m],
        certain: vec![false; m],
        hull: vec![false; m],
        triangles: Vec::new(),
        loop_triangles: Vec::new(),
        tri_offsets: Vec::new(),
        tri_list: Vec::new(),
        tri_left_len: Vec::new(),
        crossings: std::sync::OnceLock::new(),
        adj_offsets,
        adj,
        edges,
    };
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

/// CSR adjacency of `n` vertices: per vertex its neighbours (sorted) with
/// the edge ids.
fn adjacency(n: usize, edges: &[[u32; 2]]) -> (Vec<u32>, Vec<(u32, u32)>) {
    let mut degree = vec![0u32; n + 1];
    for &[u, v] in edges {
        degree[u as usize] += 1;
        degree[v as usize] += 1;
    }
    let mut adj_offsets = vec![0u32; n + 1];
    for v in 0..n {
        adj_offsets[v + 1] = adj_offsets[v] + degree[v];
    }
    let mut fill = adj_offsets.clone();
    let mut adj = vec![(0u32, 0u32); 2 * edges.len()];
    for (id, &[u, v]) in edges.iter().enumerate() {
        adj[fill[u as usize] as usize] = (v, id as u32);
        fill[u as usize] += 1;
        adj[fill[v as usize] as usize] = (u, id as u32);
        fill[v as usize] += 1;
    }
    for v in 0..n {
        adj[adj_offsets[v] as usize..adj_offsets[v + 1] as usize].sort_unstable();
    }
    (adj_offsets, adj)
}

/// Builds the triangles and crossings of the candidate edges (sorted
/// distinct pairs `u < v`, as [`diamond_filter`] gives them) and runs the
/// LMT loop; `grid` is [`point_grid`](super::point_grid) of `pts`. Correct in
/// any numbering, meant for points in Z-order (the loop's accesses to
/// triangles, edges and points then stay mostly within cache: in input
/// order each is a miss).
pub(crate) fn z_order_skeleton(
    pts: &[Point],
    grid: &PointCells,
    edges: Vec<[u32; 2]>,
    loop_chunk: usize,
) -> crate::error::Result<Skeleton> {
    debug_assert!(
        edges.windows(2).all(|w| w[0] < w[1]) && edges.iter().all(|&[u, v]| u < v),
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
    let (adj_offsets, adj) = adjacency(n, &edges);
    let hull_cycle = convex_hull_cycle(pts);
    let mut skeleton = Skeleton {
        alive: vec![true; m],
        certain: Vec::new(),
        hull: vec![false; m],
        triangles: Vec::new(),
        loop_triangles: Vec::new(),
        tri_offsets: Vec::new(),
        tri_list: Vec::new(),
        tri_left_len: Vec::new(),
        crossings: std::sync::OnceLock::new(),
        adj_offsets,
        adj,
        edges,
    };
    for i in 0..hull_cycle.len() {
        let (a, b) = (hull_cycle[i], hull_cycle[(i + 1) % hull_cycle.len()]);
        if let Some(e) = skeleton.edge_id(a, b) {
            skeleton.hull[e as usize] = true;
        }
    }
    // Triangles u < v < w of candidate edges, each found from its edge
    // (u, v): the common neighbours w > v of u and v, by merging their
    // sorted lists. Whether one is empty is decided only when the loop needs
    // it (most are never asked: their edge fails the length test first).
    // Counted first, then written in place: collecting them in one pass
    // (rayon's list of growing vectors) held about twice the final array at
    // the phase's peak.
    let sk = &skeleton;
    let counts: Vec<u32> = (0..m as u32)
        .into_par_iter()
        .with_min_len(256)
        .map(|e| {
            let mut count = 0;
            triangles_of_edge(pts, sk, e, |_| count += 1);
            count
        })
        .collect();
    let total: usize = counts.iter().map(|&c| c as usize).sum();
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
    let state = run_lmt_loop(pts, grid, &mut skeleton, loop_chunk);
    // The per-edge triangle lists served the loop alone: freed before the
    // kept triangles are collected (the phase's peak).
    skeleton.tri_offsets = Vec::new();
    skeleton.tri_list = Vec::new();
    skeleton.tri_left_len = Vec::new();
    // Keep the empty triangles whose edges are all left (the faces' only
    // use).
    let sk = &skeleton;
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
    skeleton.certain = certain_edges(pts, &skeleton);
    Ok(skeleton)
}

/// The certain edges: those left by the loop that are hull edges or that no
/// other edge left crosses, by a local test.
///
/// **Lemma.** After the loop, an edge `pq` left (not a hull edge) is crossed
/// by another edge left iff a kept triangle with corner `p` has the
/// direction `p → q` strictly inside its angle at `p`. *Proof.* If such a
/// triangle `pab` exists, `q` is not in it (it is empty), so `pq` leaves it
/// through the inside of `ab`, an edge left. Conversely, let `rs` (left)
/// cross `pq` at `X`; `rs` is no hull edge, and no edge left has a point
/// inside it (its closed triangles would all hold the point, so it would
/// have no valid pair). Every edge left that is not a hull edge has a
/// kept triangle on each side (its locally minimal pair). Walk along `pq`
/// from `X` towards `p`: start in a kept triangle of `rs` on `p`'s side;
/// the walk leaves each triangle through the inside of another side (not
/// through a corner: none lies on `pq`), an edge left, into a kept triangle
/// on that side's other side, always closer to `p`, until a triangle has
/// `p` as a corner — with `p → q` strictly inside its angle at `p`. ∎
///
/// So the test reads, per vertex, its edges left in angular order and its
/// kept triangles; debug builds check that both endpoints of every edge
/// agree, as the lemma says they must.
fn certain_edges(pts: &[Point], sk: &Skeleton) -> Vec<bool> {
    let n = pts.len();
    let m = sk.edges.len();
    // Kept triangles per corner (CSR).
    let mut offsets = vec![0u32; n + 1];
    for (corners, _) in &sk.triangles {
        for &c in corners {
            offsets[c as usize + 1] += 1;
        }
    }
    for v in 0..n {
        offsets[v + 1] += offsets[v];
    }
    let mut at = vec![0u32; offsets[n] as usize];
    let mut fill = offsets.clone();
    for (t, (corners, _)) in sk.triangles.iter().enumerate() {
        for &c in corners {
            at[fill[c as usize] as usize] = t as u32;
            fill[c as usize] += 1;
        }
    }
    drop(fill);
    // Per endpoint (smaller, larger): is the edge inside a kept triangle's
    // angle there?
    let flags = || -> Vec<AtomicBool> { (0..m).map(|_| AtomicBool::new(false)).collect() };
    let (from_smaller, from_larger) = (flags(), flags());
    (0..n).into_par_iter().with_min_len(256).for_each(|p| {
        let a = pts[p];
        let mut around: Vec<(u32, u32)> = sk
            .neighbours(p as u32)
            .iter()
            .copied()
            .filter(|&(_, e)| sk.alive[e as usize])
            .collect();
        around.sort_unstable_by(|x, y| ccw_from_east(a, pts[x.0 as usize], pts[y.0 as usize]));
        let d = around.len();
        let mut inside = vec![false; d];
        let position = |w: u32| {
            around
                .iter()
                .position(|&(x, _)| x == w)
                .expect("a kept triangle's sides are edges left")
        };
        for &t in &at[offsets[p] as usize..offsets[p + 1] as usize] {
            let c = sk.triangles[t as usize].0;
            let k = c.iter().position(|&x| x as usize == p).unwrap_or(0);
            // Counter-clockwise corners p, b, c: the angle at p runs
            // counter-clockwise from p → b to p → c (below π).
            let (first, last) = (position(c[(k + 1) % 3]), position(c[(k + 2) % 3]));
            let mut i = (first + 1) % d;
            while i != last {
                inside[i] = true;
                i = (i + 1) % d;
            }
        }
        for (&(w, e), &crossed) in around.iter().zip(&inside) {
            if crossed {
                let flag = if (p as u32) < w {
                    &from_smaller
                } else {
                    &from_larger
                };
                flag[e as usize].store(true, SeqCst);
            }
        }
    });
    (0..m)
        .map(|e| {
            let (s, l) = (from_smaller[e].load(SeqCst), from_larger[e].load(SeqCst));
            debug_assert!(
                !sk.alive[e] || sk.hull[e] || s == l,
                "the crossing lemma: both endpoints of edge {e} must agree"
            );
            sk.alive[e] && (sk.hull[e] || !s)
        })
        .collect()
}

/// Exact counter-clockwise order of the directions `a → x`, `a → y` from
/// east (the direction `+x` first).
pub(crate) fn ccw_from_east(a: Point, x: Point, y: Point) -> Ordering {
    // Upper half-plane, with east, first; the signs of f64 differences are
    // exact.
    let half = |w: Point| {
        if w[1] > a[1] || (w[1] == a[1] && w[0] > a[0]) {
            0
        } else {
            1
        }
    };
    half(x)
        .cmp(&half(y))
        .then_with(|| match orient_sign(a, x, y) {
            1 => Ordering::Less,
            -1 => Ordering::Greater,
            _ => Ordering::Equal,
        })
}

/// The candidate edges each edge left by the loop intersects, among the
/// edges left (CSR, each list sorted); for the faces with holes only, so
/// computed on first use.
struct CrossingLists {
    offsets: Vec<u32>,
    list: Vec<u32>,
}

fn crossing_lists(pts: &[Point], skeleton: &Skeleton) -> CrossingLists {
    let m = skeleton.edges.len();
    // Edges in length classes of powers of two, each class in a
    // grid of its midpoints; an edge of class k (length < 2^(k+1)·base)
    // meeting segment e has its midpoint within 2^k·base of e.
    let length = |e: &[u32; 2]| {
        let (a, b) = (pts[e[0] as usize], pts[e[1] as usize]);
        (a[0] - b[0]).hypot(a[1] - b[1])
    };
    let alive_ids: Vec<u32> = (0..m as u32)
        .filter(|&e| skeleton.alive[e as usize])
        .collect();
    // Any positive base is correct (shorter edges join class 0, whose reach
    // still covers their half-length); a quarter of the median length keeps
    // the finest grid from being far finer than the typical edge.
    let mut lengths: Vec<f64> = alive_ids
        .iter()
        .map(|&e| length(&skeleton.edges[e as usize]))
        .collect();
    let base = if lengths.is_empty() {
        f64::MIN_POSITIVE
    } else {
        let middle = lengths.len() / 2;
        let (_, median, _) = lengths.select_nth_unstable_by(middle, f64::total_cmp);
        (0.25 * *median).max(f64::MIN_POSITIVE)
    };
    drop(lengths);
    let class_of = |e: &[u32; 2]| ((length(e) / base).log2().floor().max(0.0)) as usize;
    let classes = alive_ids
        .iter()
        .map(|&e| class_of(&skeleton.edges[e as usize]))
        .max()
        .unwrap_or(0)
        + 1;
    let mut members: Vec<Vec<u32>> = vec![Vec::new(); classes];
    for &id in &alive_ids {
        members[class_of(&skeleton.edges[id as usize])].push(id);
    }
    let mid = |id: u32| {
        let e = skeleton.edges[id as usize];
        let (a, b) = (pts[e[0] as usize], pts[e[1] as usize]);
        [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]
    };
    let bbox = bounding_box(pts);
    // A crossing pair is looked for from its edge of the larger class, in
    // the grid of the other's class (whose reach covers it), or from the
    // smaller id within a class: each edge queries the grids of its own and
    // the shorter classes only, not the sparse grids of the few long edges
    // (2·10⁵ uniform points have 11 classes, and every query of a grid has
    // its cost, whatever the grid holds).
    let grids: Vec<(usize, f64, SparseGrid<u32>)> = members
        .par_iter()
        .enumerate()
        .filter(|(_, list)| !list.is_empty())
        .map(|(k, list)| {
            let reach = 2f64.powi(k as i32) * base * 1.0000001;
            let grid = SparseGrid::new(
                bbox,
                2.0 * reach,
                list.len(),
                |i| mid(list[i]),
                |i| list[i],
                |i| list[i],
            );
            (k, reach, grid)
        })
        .collect();
    let sk = &skeleton;
    // Per surviving edge only (a list header for every filter candidate
    // cost 24 bytes each, about a third of them survive).
    let crossings: Vec<Vec<u32>> = alive_ids
        .par_iter()
        .with_min_len(256)
        .map(|&e| {
            let ends = sk.edges[e as usize];
            let (a, b) = (pts[ends[0] as usize], pts[ends[1] as usize]);
            let own = class_of(&ends);
            // Each conflicting pair once; the lists are mirrored below.
            let mut out = Vec::new();
            for (k, reach, g) in grids.iter().take_while(|(k, _, _)| *k <= own) {
                g.any_cell_near(a, b, *reach, |items| {
                    for &f in items {
                        if (*k < own || f > e) && edges_conflict(pts, ends, sk.edges[f as usize]) {
                            out.push(f);
                        }
                    }
                    false
                });
            }
            out.sort_unstable();
            out.dedup();
            out
        })
        .collect();
    let mut cross_offsets = vec![0u32; m + 1];
    for (&e, list) in alive_ids.iter().zip(&crossings) {
        let e = e as usize;
        cross_offsets[e + 1] += list.len() as u32;
        for &f in list {
            cross_offsets[f as usize + 1] += 1;
        }
    }
    for e in 0..m {
        cross_offsets[e + 1] += cross_offsets[e];
    }
    let mut cross_list = vec![0u32; cross_offsets[m] as usize];
    let mut next: Vec<u32> = cross_offsets[..m].to_vec();
    for (&e, list) in alive_ids.iter().zip(crossings) {
        let e = e as usize;
        for f in list {
            cross_list[next[e] as usize] = f;
            next[e] += 1;
            cross_list[next[f as usize] as usize] = e as u32;
            next[f as usize] += 1;
        }
    }
    drop(next);
    // Each list sorted (a pair is recorded from either end).
    for &e in &alive_ids {
        let (start, end) = (cross_offsets[e as usize], cross_offsets[e as usize + 1]);
        cross_list[start as usize..end as usize].sort_unstable();
    }
    CrossingLists {
        offsets: cross_offsets,
        list: cross_list,
    }
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
fn run_lmt_loop(
    pts: &[Point],
    grid: &PointCells,
    sk: &mut Skeleton,
    chunk: usize,
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
    (0..m.div_ceil(chunk)).into_par_iter().for_each(|k| {
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

#[cfg(test)]
mod tests {
    use super::{angle_of, merge_sorted_runs, ANGLE_ERROR};

    #[test]
    fn the_polynomial_angle_is_within_its_error_bound() {
        let mut rng = StdRng::seed_from_u64(11);
        let mut worst = 0.0f64;
        let mut check = |dx: f64, dy: f64| {
            let exact = dy.atan2(dx).rem_euclid(std::f64::consts::TAU);
            let mut d = (angle_of(dx, dy) - exact).abs();
            // 0 and 2π are the same direction.
            d = d.min((d - std::f64::consts::TAU).abs());
            worst = worst.max(d);
        };
        for _ in 0..1_000_000 {
            let scale = 10f64.powi(rng.gen_range(-30..30));
            check(
                scale * rng.gen_range(-1.0..1.0),
                scale * rng.gen_range(-1.0..1.0),
            );
        }
        for (dx, dy) in [
            (1.0, 0.0),
            (0.0, 1.0),
            (-1.0, 0.0),
            (0.0, -1.0),
            (1.0, 1.0),
            (-1.0, -1.0),
            (1.0, -1e-300),
            (-3.0, 1e-300),
        ] {
            check(dx, dy);
        }
        assert!(worst < ANGLE_ERROR, "{worst}");
        assert!(
            worst > 1e-11,
            "the test should see the polynomial's error: {worst}"
        );
    }
    use rand::{rngs::StdRng, Rng, SeedableRng};

    #[test]
    fn merging_two_sorted_runs_sorts_them() {
        let mut rng = StdRng::seed_from_u64(7);
        let mut scratch = Vec::new();
        for _ in 0..2000 {
            let len = rng.gen_range(0..40);
            let mid = rng.gen_range(0..=len);
            // Few distinct values, so that equal keys across the runs occur.
            let mut v: Vec<f64> = (0..len)
                .map(|_| f64::from(rng.gen_range(0..12u8)))
                .collect();
            v[..mid].sort_unstable_by(f64::total_cmp);
            v[mid..].sort_unstable_by(f64::total_cmp);
            let mut expected = v.clone();
            expected.sort_unstable_by(f64::total_cmp);
            merge_sorted_runs(&mut v, mid, &mut scratch);
            assert_eq!(v, expected);
        }
    }
}
