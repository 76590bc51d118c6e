//! A scalable greedy triangulation by definition: [`greedy_edges`].
//!
//! The definition is the one of [`crate::greedy_triangulation`]: the
//! candidates are the segments between two of the points whose open interior
//! contains no other point; they are scanned shortest first (exact squared
//! length, equal lengths in the order of the symbolic perturbation of
//! [`crate::symbolic`]); a candidate is kept iff it properly crosses no kept
//! segment. [`greedy_edges`] does exactly that scan, and only makes each
//! decision faster:
//!
//! * **Exact arithmetic.** All coordinates are scaled by one common power of
//!   two to integers ([`crate::exact`]'s decomposition). If they have at most
//!   62 bits, every predicate below is evaluated in `i128` without overflow
//!   (differences < 2^63, products < 2^126, sums < 2^127), else in `BigInt`.
//! * **Float filters.** Orientation and length comparisons are first tried in
//!   `f64` with a proven error bound (see [`orient_filter`] and
//!   [`clearly_shorter`]); only when the bound does not settle the sign is the
//!   exact integer value computed. A filter never answers wrongly; it answers
//!   "don't know".
//! * **Ties.** Equal squared lengths are ordered by the perturbed squared
//!   length `Σ_u (p_u + ε_{p,u} − q_u − ε_{q,u})²`, written out term by term
//!   (`Terms`) and compared by the lowest exponent whose coefficients
//!   differ. That is the same polynomial as [`crate::symbolic`] expands with
//!   rationals; the unit tests check the two agree on every pair of segments
//!   of many degenerate sets.
//! * **Crossings.** Kept segments are stored in a uniform grid, in every cell
//!   that meets their bounding box. If two segments properly cross, the
//!   x-ranges of their boxes overlap in an interval that starts at an
//!   endpoint's coordinate `v`, and the cell index is a monotone function of
//!   each coordinate (see `Grid`), so `v`'s column lies in both boxes'
//!   column ranges; likewise for rows: the two boxes share a cell. Checking
//!   the kept segments of every cell of a candidate's box is thus complete.
//! * **Empty segments.** A point on an open segment lies in its bounding box,
//!   so testing (exactly) the points of every cell of that box is complete.
//! * **Shortcuts.** Before the complete scans, three cheap tests that can only
//!   reject correctly (they use the same exact predicates): kept edges
//!   between kept neighbours of an endpoint (a long candidate usually leaves
//!   its endpoint through such a link edge), then points and kept segments
//!   in the cells along the candidate. They only change the running time.
//!
//! Nothing here is shared with optri; within the oracle it shares only the
//! integer decomposition and polynomial functions of [`crate::exact`].

use crate::exact::{cross, dist2, dot, scale, Point, Ring, Scaled};
use std::cmp::Ordering;
use std::collections::HashSet;

/// The greedy triangulation of the distinct points `points` (by definition,
/// see the module docs) as sorted `[min, max]` index pairs. The indices are
/// the perturbation ranks. Works for any finite coordinates, also for
/// all-collinear inputs (then the edges form a path). About O(n² log n) for
/// well-spread points; n = 2000 takes about a second in an optimised build.
///
/// # Panics
/// On coincident points or non-finite coordinates.
pub fn greedy_edges(points: &[Point]) -> Vec<[u32; 2]> {
    let mut seen = HashSet::with_capacity(points.len());
    for (i, p) in points.iter().enumerate() {
        let key = [(p[0] + 0.0).to_bits(), (p[1] + 0.0).to_bits()];
        assert!(
            seen.insert(key),
            "optri-oracle: point {i} repeats an earlier point"
        );
    }
    let flat: Vec<f64> = points.iter().flat_map(|p| [p[0], p[1]]).collect();
    match scale(&flat, 62).0 {
        Scaled::Small(c) => greedy_in(points, &c),
        Scaled::Big(c) => greedy_in(points, &c),
    }
}

/// Below this, products may have lost relative precision to underflow.
const TINY: f64 = 1e-270;

/// Sign of the orientation determinant of `p, q, r` if `f64` proves it.
///
/// With `u = 2^-53`, each difference has relative error ≤ u, each product
/// ≤ (1+u)³ − 1 < 3.01u (plus at most 2^-1074 absolute if it underflows),
/// and the final subtraction ≤ u of its result; so the computed `det` is
/// within `4.02u · (|l| + |r|) + 2^-1073 < 1e-15 · (|l| + |r|)` of the exact
/// determinant when `|l| + |r| ≥ TINY`. Overflow gives a non-finite bound.
pub fn orient_filter(p: Point, q: Point, r: Point) -> Option<i32> {
    let l = (q[0] - p[0]) * (r[1] - p[1]);
    let rr = (q[1] - p[1]) * (r[0] - p[0]);
    let det = l - rr;
    let mag = l.abs() + rr.abs();
    if !mag.is_finite() || mag < TINY {
        return None;
    }
    let bound = 1e-15 * mag;
    if det > bound {
        Some(1)
    } else if det < -bound {
        Some(-1)
    } else {
        None
    }
}

/// `|pq|²` in `f64` (relative error ≤ (1+u)⁴ − 1 < 4.01u when it neither
/// overflows nor underflows).
fn approx_squared_length(p: Point, q: Point) -> f64 {
    let (dx, dy) = (p[0] - q[0], p[1] - q[1]);
    dx * dx + dy * dy
}

/// `true` only if the exact squared lengths behind the `f64` values `a`, `b`
/// of `approx_squared_length` satisfy `A < B`: from `a ≥ A(1 − 4.01u)`,
/// `b ≤ B(1 + 4.01u)` and `a < b(1 − 10⁻¹⁴)` follows
/// `A < B(1 + 4.01u)(1 − 10⁻¹⁴)/(1 − 4.01u) < B`.
pub fn clearly_shorter(a: f64, b: f64) -> bool {
    a >= TINY && b.is_finite() && a < b * (1.0 - 1e-14)
}

/// The scaled integer coordinates and the exact predicates on them.
struct Exact<'a, T> {
    p: &'a [Point],
    c: &'a [T],
}

impl<T: Ring> Exact<'_, T> {
    fn xy(&self, i: u32) -> [T; 2] {
        [
            self.c[2 * i as usize].clone(),
            self.c[2 * i as usize + 1].clone(),
        ]
    }

    fn orient(&self, i: u32, j: u32, k: u32) -> i32 {
        let (p, q, r) = (self.p[i as usize], self.p[j as usize], self.p[k as usize]);
        if let Some(s) = orient_filter(p, q, r) {
            return s;
        }
        let [a, b, c] = [i, j, k].map(|m| self.xy(m));
        let [ax, ay] = a;
        let [bx, by] = b;
        let [cx, cy] = c;
        sign(&cross(&[ax, ay, bx, by, cx, cy]))
    }

    /// Do the open segments `s` and `t` cross in one point interior to both?
    fn properly_cross(&self, s: [u32; 2], t: [u32; 2]) -> bool {
        let [a, b] = s;
        let [c, d] = t;
        if a == c || a == d || b == c || b == d {
            return false; // a shared endpoint makes an orientation zero
        }
        self.orient(a, b, c) * self.orient(a, b, d) < 0
            && self.orient(c, d, a) * self.orient(c, d, b) < 0
    }

    /// Is point `k` on the open segment `s`?
    fn on_open_segment(&self, s: [u32; 2], k: u32) -> bool {
        let [a, b] = s;
        if k == a || k == b || self.orient(a, b, k) != 0 {
            return false;
        }
        // Collinear: between the endpoints iff (a − k)·(b − k) < 0.
        let [kx, ky] = self.xy(k);
        let [ax, ay] = self.xy(a);
        let [bx, by] = self.xy(b);
        sign(&dot(&[kx, ky, ax, ay, bx, by])) < 0
    }

    fn squared_length(&self, s: [u32; 2]) -> T {
        let [ax, ay] = self.xy(s[0]);
        let [bx, by] = self.xy(s[1]);
        dist2(&[ax, ay, bx, by])
    }

    /// The total order of the scan: exact squared length, then the
    /// perturbation. `Equal` only for the same segment.
    fn compare(&self, x: &(f64, [u32; 2]), y: &(f64, [u32; 2])) -> Ordering {
        if x.1 == y.1 {
            return Ordering::Equal;
        }
        if clearly_shorter(x.0, y.0) {
            return Ordering::Less;
        }
        if clearly_shorter(y.0, x.0) {
            return Ordering::Greater;
        }
        self.squared_length(x.1)
            .cmp(&self.squared_length(y.1))
            .then_with(|| self.compare_ties(x.1, y.1))
    }

    /// Orders two different segments of equal exact length by their
    /// perturbed squared lengths: the sign of the coefficient of the lowest
    /// exponent at which the two polynomials differ.
    fn compare_ties(&self, s: [u32; 2], t: [u32; 2]) -> Ordering {
        let (ts, tt) = (self.terms(s), self.terms(t));
        let (mut i, mut j) = (0, 0);
        let zero = T::zero();
        while i < ts.len() || j < tt.len() {
            let ks = ts.get(i).map(|t| t.0);
            let kt = tt.get(j).map(|t| t.0);
            let (cs, ct) = match (ks, kt) {
                (Some(a), Some(b)) if a == b => {
                    i += 1;
                    j += 1;
                    (&ts[i - 1].1, &tt[j - 1].1)
                }
                (Some(a), Some(b)) if a < b => {
                    i += 1;
                    (&ts[i - 1].1, &zero)
                }
                (Some(_), None) => {
                    i += 1;
                    (&ts[i - 1].1, &zero)
                }
                _ => {
                    j += 1;
                    (&zero, &tt[j - 1].1)
                }
            };
            match cs.cmp(ct) {
                Ordering::Equal => continue,
                o => return o,
            }
        }
        unreachable!("optri-oracle: two different segments with the same perturbed length")
    }

    /// The non-constant terms of the perturbed squared length of `s`, in
    /// increasing order of exponent. See [`Terms`].
    fn terms(&self, s: [u32; 2]) -> Terms<T> {
        // The polynomial is symmetric in the endpoints; take a < b.
        let (a, b) = (s[0].min(s[1]), s[0].max(s[1]));
        let (pa, pb) = (self.xy(a), self.xy(b));
        let one = T::one();
        let two = one.clone() + one.clone();
        let dx = two.clone() * (pa[0].clone() - pb[0].clone());
        let dy = two.clone() * (pa[1].clone() - pb[1].clone());
        let (ya, xa, yb, xb) = (
            2 * a as u64,
            2 * a as u64 + 1,
            2 * b as u64,
            2 * b as u64 + 1,
        );
        // Ranks ya < xa < yb < xb; the exponents in increasing order.
        let terms = [
            (Exponent::single(ya), dy.clone()),
            (Exponent::square(ya), one.clone()),
            (Exponent::single(xa), dx.clone()),
            (Exponent::square(xa), one.clone()),
            (Exponent::single(yb), -dy),
            (Exponent::product(yb, ya), -two.clone()),
            (Exponent::square(yb), one.clone()),
            (Exponent::single(xb), -dx),
            (Exponent::product(xb, xa), -two),
            (Exponent::square(xb), one),
        ];
        debug_assert!(terms.windows(2).all(|w| w[0].0 < w[1].0));
        terms
    }
}

/// `(exponent, coefficient)` terms of a perturbed squared length. For segment
/// `ab` and each coordinate `u` with `D = a_u − b_u` and `ε_v = ε^(3^rank(v))`
/// (`rank(y_m) = 2m`, `rank(x_m) = 2m + 1`):
/// `(D + ε_{a,u} − ε_{b,u})² − D² = 2D ε_{a,u} − 2D ε_{b,u} + ε_{a,u}² + ε_{b,u}² − 2 ε_{a,u} ε_{b,u}`.
type Terms<T> = [(Exponent, T); 10];

/// An exponent `3^r`, `2·3^r` or `3^r + 3^s` (`s < r`), ordered as numbers.
/// Base-3 digits are at most 2, so the number is determined by its top
/// position `r`, and below that `3^r < 3^r + 3^s` (increasing in `s`)
/// `< 2·3^r`; everything with top position `r` is below `3^(r+1)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
struct Exponent {
    top: u64,
    /// 0 for `3^top`, `1 + s` for `3^top + 3^s`, `u64::MAX` for `2·3^top`.
    rest: u64,
}

impl Exponent {
    fn single(r: u64) -> Self {
        Self { top: r, rest: 0 }
    }
    fn square(r: u64) -> Self {
        Self {
            top: r,
            rest: u64::MAX,
        }
    }
    fn product(r: u64, s: u64) -> Self {
        assert_ne!(r, s);
        Self {
            top: r.max(s),
            rest: 1 + r.min(s),
        }
    }
}

fn sign<T: Ring>(v: &T) -> i32 {
    if v.is_positive() {
        1
    } else if v.is_negative() {
        -1
    } else {
        0
    }
}

/// A uniform grid over the bounding box of the points. The cell of a
/// coordinate `v` is `floor((v/2 − min/2) / span · cells)` clamped to
/// `0..cells` (halves avoid overflow): every step is monotone
/// non-decreasing in `v`, so a value between two others gets a cell between
/// theirs. That is all the correctness arguments use.
struct Grid {
    min: [f64; 2],
    span: [f64; 2],
    cells: [usize; 2],
}

impl Grid {
    fn new(points: &[Point]) -> Self {
        let n = points.len().max(1);
        let mut min = [f64::INFINITY; 2];
        let mut max = [f64::NEG_INFINITY; 2];
        for p in points {
            for u in 0..2 {
                min[u] = min[u].min(p[u]);
                max[u] = max[u].max(p[u]);
            }
        }
        let span = [0, 1].map(|u| max[u] * 0.5 - min[u] * 0.5);
        let ok = |s: f64| s.is_finite() && s > 0.0;
        // About one point per cell, cells roughly square.
        let cells = match (ok(span[0]), ok(span[1])) {
            (true, true) => {
                let side = (span[0] * span[1] / n as f64).sqrt();
                [0, 1].map(|u| {
                    let c = (span[u] / side).ceil();
                    if c >= 1.0 {
                        (c as usize).min(n)
                    } else {
                        1
                    }
                })
            }
            (true, false) => [n, 1],
            (false, true) => [1, n],
            (false, false) => [1, 1],
        };
        Self { min, span, cells }
    }

    fn len(&self) -> usize {
        self.cells[0] * self.cells[1]
    }

    /// Fractional cell coordinate (not clamped).
    fn position(&self, v: f64, u: usize) -> f64 {
        if self.cells[u] == 1 {
            return 0.0;
        }
        (v * 0.5 - self.min[u] * 0.5) / self.span[u] * self.cells[u] as f64
    }

    /// `floor(f)` clamped to the cells of axis `u`: `as` truncates towards
    /// zero (= floor for `f ≥ 0`) and saturates (negative and NaN → 0), so
    /// this is monotone in `f`.
    fn clamp(&self, f: f64, u: usize) -> usize {
        (f as usize).min(self.cells[u] - 1)
    }

    fn cell_1d(&self, v: f64, u: usize) -> usize {
        self.clamp(self.position(v, u), u)
    }

    fn cell(&self, p: Point) -> usize {
        self.cell_1d(p[0], 0) + self.cells[0] * self.cell_1d(p[1], 1)
    }

    /// Every cell meeting the bounding box of `p` and `q`.
    fn box_cells(&self, p: Point, q: Point) -> impl Iterator<Item = usize> + '_ {
        let xs = (
            self.cell_1d(p[0].min(q[0]), 0),
            self.cell_1d(p[0].max(q[0]), 0),
        );
        let ys = (
            self.cell_1d(p[1].min(q[1]), 1),
            self.cell_1d(p[1].max(q[1]), 1),
        );
        let w = self.cells[0];
        (ys.0..=ys.1).flat_map(move |y| (xs.0..=xs.1).map(move |x| x + w * y))
    }

    /// Calls `f` on cells near the segment `pq`, from `p` on, until it
    /// returns `true` (then returns `true`). A heuristic visiting order only:
    /// cells the segment merely clips may be missed.
    fn any_cell_along(&self, p: Point, q: Point, mut f: impl FnMut(usize) -> bool) -> bool {
        let (fp, fq) = (
            [self.position(p[0], 0), self.position(p[1], 1)],
            [self.position(q[0], 0), self.position(q[1], 1)],
        );
        let d = [fq[0] - fp[0], fq[1] - fp[1]];
        let reach = d[0].abs().max(d[1].abs());
        if !reach.is_finite() {
            return false;
        }
        let steps = ((2.0 * reach) as usize + 1).min(4 * self.len());
        let mut last = usize::MAX;
        for i in 0..=steps {
            let t = i as f64 / steps as f64;
            let c =
                self.clamp(fp[0] + t * d[0], 0) + self.cells[0] * self.clamp(fp[1] + t * d[1], 1);
            if c != last {
                if f(c) {
                    return true;
                }
                last = c;
            }
        }
        false
    }
}

fn greedy_in<T: Ring>(points: &[Point], c: &[T]) -> Vec<[u32; 2]> {
    let n = points.len() as u32;
    let ex = Exact { p: points, c };
    let p = |i: u32| points[i as usize];
    let mut segments: Vec<(f64, [u32; 2])> =
        Vec::with_capacity(points.len() * points.len().saturating_sub(1) / 2);
    for i in 0..n {
        for j in i + 1..n {
            segments.push((approx_squared_length(p(i), p(j)), [i, j]));
        }
    }
    segments.sort_unstable_by(|x, y| ex.compare(x, y));

    let grid = Grid::new(points);
    let mut points_in: Vec<Vec<u32>> = vec![Vec::new(); grid.len()];
    for i in 0..n {
        points_in[grid.cell(p(i))].push(i);
    }
    let mut kept_in: Vec<Vec<u32>> = vec![Vec::new(); grid.len()];
    let mut kept: Vec<[u32; 2]> = Vec::new();
    let mut adjacent: Vec<Vec<u32>> = vec![Vec::new(); points.len()];
    for (_, s) in segments {
        let (a, b) = (p(s[0]), p(s[1]));
        let crosses = |t: &u32| ex.properly_cross(s, kept[*t as usize]);
        let crosses_in = |cell: usize| kept_in[cell].iter().any(crosses);
        let (lo, hi) = (
            [a[0].min(b[0]), a[1].min(b[1])],
            [a[0].max(b[0]), a[1].max(b[1])],
        );
        let blocks = |k: &u32| {
            let q = p(*k);
            (lo[0]..=hi[0]).contains(&q[0])
                && (lo[1]..=hi[1]).contains(&q[1])
                && ex.on_open_segment(s, *k)
        };
        let blocked_in = |cell: usize| points_in[cell].iter().any(blocks);
        // Shortcuts, each of which only ever rejects correctly: kept edges
        // between neighbours of an endpoint (s usually leaves through one),
        // then cells along s.
        let e = if adjacent[s[0] as usize].len() <= adjacent[s[1] as usize].len() {
            s[0]
        } else {
            s[1]
        };
        let near = &adjacent[e as usize];
        let crosses_link = near.len() <= 64
            && near.iter().any(|&u| {
                let around = &adjacent[u as usize];
                around.len() <= 64
                    && around
                        .iter()
                        .any(|&w| w != e && ex.properly_cross(s, [u, w]))
            });
        if crosses_link
            || grid.any_cell_along(a, b, blocked_in)
            || grid.any_cell_along(a, b, crosses_in)
        {
            continue;
        }
        // The complete tests.
        if grid.box_cells(a, b).any(crosses_in) || grid.box_cells(a, b).any(blocked_in) {
            continue;
        }
        let id = kept.len() as u32;
        kept.push(s);
        adjacent[s[0] as usize].push(s[1]);
        adjacent[s[1] as usize].push(s[0]);
        for cell in grid.box_cells(a, b) {
            kept_in[cell].push(id);
        }
    }
    kept.sort_unstable();
    kept
}

/// [`greedy_edges`] with a chosen integer type, for the tests.
#[cfg(test)]
fn greedy_edges_with<T: Ring + From<i128>>(points: &[Point]) -> Vec<[u32; 2]> {
    let flat: Vec<f64> = points.iter().flat_map(|p| [p[0], p[1]]).collect();
    let c: Vec<T> = match scale(&flat, 62).0 {
        Scaled::Small(c) => c.into_iter().map(T::from).collect(),
        Scaled::Big(_) => panic!("test inputs must fit the small path"),
    };
    greedy_in(points, &c)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::enumerate::{greedy_triangulation, triangle_edges};
    use crate::exact::orient;
    use crate::inputs::{
        collinear_runs, grid, integer_circle_points as circle, lattice_points, uniform_in_box,
    };
    use crate::symbolic::compare_lengths_perturbed;
    use num_bigint::BigInt;
    use rand::rngs::StdRng;
    use rand::{Rng, SeedableRng};

    const SEED_RANDOM_SMALL_SETS: u64 = 1;
    const SEED_COLLINEAR_RUNS: u64 = 2;
    const SEED_TIE_ORDER: u64 = 3;
    const SEED_FILTERS: u64 = 4;
    const SEED_INTEGER_PATHS: u64 = 5;

    /// Drops repeated points (first occurrence kept).
    fn distinct(pts: Vec<Point>) -> Vec<Point> {
        let mut out: Vec<Point> = Vec::new();
        for p in pts {
            if !out.contains(&p) {
                out.push(p);
            }
        }
        out
    }

    /// Compares with the O(n⁴) definition; returns 1 for counting.
    fn check(pts: &[Point], what: &str) -> usize {
        let by_definition = if (0..pts.len()).all(|k| orient(pts[0], pts[1], pts[k]) == 0) {
            None // no triangles: the O(n⁴) reference only returns faces
        } else {
            Some(triangle_edges(&greedy_triangulation(pts)))
        };
        let fast = greedy_edges(pts);
        if let Some(e) = by_definition {
            assert_eq!(fast, e, "{what}: {pts:?}");
        } else {
            assert_eq!(fast.len(), pts.len() - 1, "{what}: a path");
        }
        1
    }

    #[test]
    fn matches_the_definition_on_random_small_sets() {
        let mut rng = StdRng::seed_from_u64(SEED_RANDOM_SMALL_SETS);
        let mut checked = 0;
        for case in 0..400 {
            let n = rng.gen_range(3..17);
            let side = [3, 5, 8, 1000][case % 4];
            let pts = distinct(lattice_points(&mut rng, n, 0..side, 0..side));
            if pts.len() >= 3 {
                checked += check(&pts, &format!("integer case {case}"));
            }
        }
        for case in 0..100 {
            let n = rng.gen_range(3..17);
            let pts = uniform_in_box(&mut rng, n, [-1.0, -1.5], [1.0, 1.5]);
            checked += check(&pts, &format!("float case {case}"));
        }
        assert!(checked >= 480, "{checked}");
    }

    #[test]
    fn matches_the_definition_on_degenerate_sets() {
        let mut checked = 0;
        for w in 1..=6 {
            for h in 1..=5 {
                if w * h >= 3 {
                    checked += check(&grid(w, h, 1.0), &format!("grid {w}x{h}"));
                }
            }
        }
        for k in 3..=12 {
            checked += check(&grid(2, k, 1.0), &format!("grid 2x{k}"));
            checked += check(&grid(k, 1, 1.0), &format!("collinear {k}"));
        }
        for r in [5, 25] {
            let mut c = circle(r);
            checked += check(&c, &format!("circle {r}"));
            c.push([0.0, 0.0]);
            checked += check(&c, &format!("circle {r} with centre"));
        }
        checked += check(&circle(65), "circle 65");
        // Collinear runs with noise; scaled and negative copies; duplicates
        // removed (about one set in twenty keeps fewer than three points and
        // is skipped).
        let mut rng = StdRng::seed_from_u64(SEED_COLLINEAR_RUNS);
        for case in 0..72 {
            let pts = collinear_runs(&mut rng, 1..4, 2..8, 0..4);
            let s = [1.0, 2f64.powi(150), -(2f64.powi(-120)), 0.1][case % 4];
            let pts = distinct(pts.into_iter().map(|p| [p[0] * s, p[1] * s]).collect());
            if pts.len() >= 3 {
                checked += check(&pts, &format!("collinear runs case {case}"));
            }
        }
        assert!(checked >= 110, "{checked}");
    }

    #[test]
    fn tie_order_is_the_symbolic_perturbation() {
        let mut rng = StdRng::seed_from_u64(SEED_TIE_ORDER);
        let mut sets = vec![grid(3, 3, 1.0), grid(4, 2, 1.0), circle(5)];
        for _ in 0..30 {
            let n = rng.gen_range(4..10);
            sets.push(distinct(lattice_points(&mut rng, n, 0..4, 0..4)));
        }
        let mut compared = 0;
        for pts in sets {
            let flat: Vec<f64> = pts.iter().flat_map(|p| [p[0], p[1]]).collect();
            let Scaled::Small(c) = scale(&flat, 62).0 else {
                unreachable!()
            };
            let ex = Exact { p: &pts, c: &c };
            let n = pts.len() as u32;
            let segs: Vec<(f64, [u32; 2])> = (0..n)
                .flat_map(|i| (i + 1..n).map(move |j| [i, j]))
                .map(|s| {
                    (
                        approx_squared_length(pts[s[0] as usize], pts[s[1] as usize]),
                        s,
                    )
                })
                .collect();
            for x in &segs {
                for y in &segs {
                    assert_eq!(
                        ex.compare(x, y),
                        compare_lengths_perturbed(&pts, x.1, y.1),
                        "{x:?} {y:?} in {pts:?}"
                    );
                    compared += 1;
                }
            }
        }
        assert!(compared > 10_000, "{compared}");
    }

    #[test]
    fn filters_agree_with_exact_predicates() {
        let mut rng = StdRng::seed_from_u64(SEED_FILTERS);
        for _ in 0..20_000 {
            // Nearly collinear triples: r close to the line pq.
            let p: Point = [rng.gen(), rng.gen()];
            let q = [rng.gen::<f64>() * 1e3, rng.gen::<f64>() * 1e3];
            let t: f64 = rng.gen();
            let mut r = [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])];
            r[rng.gen_range(0..2)] += rng.gen_range(-2..=2) as f64 * 1e-13;
            let s = [1.0, 2f64.powi(200), 2f64.powi(-140)][rng.gen_range(0..3)];
            let [p, q, r] = [p, q, r].map(|v| [v[0] * s, v[1] * s]);
            if let Some(o) = orient_filter(p, q, r) {
                assert_eq!(o, orient(p, q, r), "{p:?} {q:?} {r:?}");
            }
            let (a, b) = (approx_squared_length(p, q), approx_squared_length(p, r));
            if clearly_shorter(a, b) {
                assert_eq!(
                    crate::exact::compare_squared_lengths(p, q, p, r),
                    Ordering::Less
                );
            }
        }
    }

    #[test]
    fn small_and_big_integer_paths_agree_and_count_edges() {
        let mut rng = StdRng::seed_from_u64(SEED_INTEGER_PATHS);
        for case in 0..6 {
            let n = 150 + 50 * case;
            let side = if case % 2 == 0 { 30 } else { 1 << 20 };
            let pts = distinct(lattice_points(&mut rng, n, 0..side, 0..side));
            let small = greedy_edges_with::<i128>(&pts);
            assert_eq!(small, greedy_edges_with::<BigInt>(&pts), "case {case}");
            assert_eq!(small, greedy_edges(&pts));
            // A triangulation with h boundary points has 3n − 3 − h edges.
            let h = crate::graphs::convex_hull_edges(&pts).len();
            assert_eq!(small.len(), 3 * pts.len() - 3 - h, "case {case}");
        }
    }
}
