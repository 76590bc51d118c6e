//! Step 1, the diamond filter (module docs of `skeleton`): the candidate
//! edges of a minimum-weight triangulation, by R. L. S. Drysdale, S.
//! McElfresh & J. Snoeyink, *On exclusion regions for optimal
//! triangulations*, Discrete Appl. Math. 109, 2001: each point's search in
//! rings, the directions its killers leave alive, and the exact test.

use crate::error::Result;
use crate::interrupt::Stop;
use crate::kernel::{DiamondPosition, DiamondTriangles, Point};
use crate::parallel::prelude::*;
use crate::spatial::{bounding_box, convex_hull_cycle, CellBlock, PointCells};
use std::f64::consts::PI;

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
    diamond_filter(pts, &super::super::point_grid(pts), &Stop::default())
        .expect("no stop without a limit")
}

/// The candidate edges (pairs `u < v`, sorted) surviving the diamond filter,
/// with every convex-hull edge among them; `grid` is
/// [`point_grid`](super::super::point_grid) of `pts`.
///
/// # Errors
/// [`crate::Error::Interrupted`] when `stop` says so (read every 64
/// points, and inside a point's search at every ring and every 64 exact
/// tests: on points in nearly convex position a point has Θ(n) candidates
/// whose diamonds each span Θ(n) grid cells).
pub(crate) fn diamond_filter(
    pts: &[Point],
    grid: &PointCells,
    stop: &Stop,
) -> Result<Vec<[u32; 2]>> {
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
                // A stopped run skips the remaining chunks and fails below.
                if stop.reason().is_some() {
                    return out;
                }
                for &p in chunk {
                    search_from(pts, grid, bbox, &rings, p, stop, scratch, &mut out);
                }
                out
            })
        })
        .collect();
    stop.check()?;
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
    Ok(edges)
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
/// the points a test or a killer needs. A search that `stop` ends leaves
/// `out` incomplete (the filter then fails).
#[allow(clippy::too_many_arguments)]
fn search_from(
    pts: &[Point],
    grid: &PointCells,
    bbox: [f64; 4],
    rings: &Rings,
    p: u32,
    stop: &Stop,
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
    let mut tests = 0u32;
    'rings: for k in 0..count {
        last = k;
        if stop.reason().is_some() {
            break;
        }
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
                if direction_alive(angle, killers) {
                    tests += 1;
                    if tests.is_multiple_of(64) && stop.reason().is_some() {
                        break 'rings;
                    }
                    if diamond_survives(a, pts[q as usize], d2, grid) {
                        out.push([p.min(q), p.max(q)]);
                    }
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

#[cfg(test)]
mod tests {
    use super::{angle_of, merge_sorted_runs, ANGLE_ERROR};
    use rand::{rngs::StdRng, Rng, SeedableRng};

    const SEED_ANGLES: u64 = 11;
    const SEED_RUNS: u64 = 7;

    #[test]
    fn the_polynomial_angle_is_within_its_error_bound() {
        let mut rng = StdRng::seed_from_u64(SEED_ANGLES);
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

    #[test]
    fn merging_two_sorted_runs_sorts_them() {
        let mut rng = StdRng::seed_from_u64(SEED_RUNS);
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
