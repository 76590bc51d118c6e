//! Exact geometric predicates on `f64` points.
//!
//! Orientation and in-circle come from the `robust` crate (Shewchuk's
//! adaptive predicates); only their *sign* is used. Length and dot-product
//! comparisons use a floating-point filter and fall back to exact
//! [`Expansion`] arithmetic when the filter cannot decide.

use super::certified_incircle::certified_incircle_sign;
use super::expansion::{sign_of_sum, two_diff, two_product, two_sum, Expansion};
use super::squared_length::{compare_rounded_keys, rounded_squared_length};
use super::{Point, UNIT_ROUNDOFF as U};
use std::cmp::Ordering;

#[inline]
fn coord(p: Point) -> robust::Coord<f64> {
    robust::Coord { x: p[0], y: p[1] }
}

/// Exact sign of the orientation determinant: `1` if `a, b, c` turn
/// counter-clockwise, `-1` if clockwise, `0` if collinear.
#[inline]
pub fn orient_sign(a: Point, b: Point, c: Point) -> i32 {
    let d = robust::orient2d(coord(a), coord(b), coord(c));
    (d > 0.0) as i32 - (d < 0.0) as i32
}

/// Exact in-circle test: `1` if `d` lies strictly inside the circle through
/// the counter-clockwise triangle `a, b, c`, `-1` if strictly outside, `0` if on it.
///
/// Certified `f64` and double-double filters first
/// (the kernel's `certified_incircle` module), then the `robust` crate's adaptive exact
/// evaluation for what they leave undecided.
#[inline]
pub fn incircle_sign(a: Point, b: Point, c: Point, d: Point) -> i32 {
    if let Some(s) = certified_incircle_sign(a, b, c, d) {
        return s;
    }
    let v = robust::incircle(coord(a), coord(b), coord(c), coord(d));
    if v > 0.0 {
        1
    } else if v < 0.0 {
        -1
    } else {
        0
    }
}

/// Exact sign of the orientation of `a·s, b·s, c·t`, every product taken
/// exactly (never rounded): `1` counter-clockwise, `-1` clockwise, `0`
/// collinear.
///
/// Locates a point given in one coordinate system among points computed in
/// another, scaled one: decimal input runs on integers `10^k` times the
/// decimals, and a query `c` in the caller's doubles is the exact point
/// `c·10^k` there (`s = 1`, `t = 10^k`), or, for `k < 0`, the vertices are
/// `10^-k` times larger than the working integers (`s = 10^-k`, `t = 1`);
/// orientation is homogeneous, so scaling all three alike keeps its sign.
///
/// Exact for coordinates in the kernel's range (0 or a magnitude in
/// [`MIN_COORDINATE`](super::MIN_COORDINATE)`..=`[`MAX_COORDINATE`](super::MAX_COORDINATE))
/// and integer scales `1 ≤ s, t ≤ 2⁷⁴`: every product is a two-term
/// expansion by an exact product (its error term is a multiple of 2⁻¹⁹⁴, far
/// from underflow), and the determinant, expanded over those terms, is
/// summed exactly. With `s = t = 1` it is [`orient_sign`].
pub fn orient_sign_scaled(a: Point, b: Point, c: Point, s: f64, t: f64) -> i32 {
    if s == 1.0 && t == 1.0 {
        return orient_sign(a, b, c);
    }
    let scaled = |p: Point, f: f64| [two_product(p[0], f), two_product(p[1], f)];
    let [ax, ay] = scaled(a, s);
    let [bx, by] = scaled(b, s);
    let [cx, cy] = scaled(c, t);
    // ax·by − ay·bx + bx·cy − by·cx + cx·ay − cy·ax: the Ax·Ay terms of the
    // difference form cancel, so six products of two-term values suffice.
    let mut sum = Expansion::new();
    for (p, q, sign) in [
        (ax, by, 1.0),
        (ay, bx, -1.0),
        (bx, cy, 1.0),
        (by, cx, -1.0),
        (cx, ay, 1.0),
        (cy, ax, -1.0),
    ] {
        sum.add_two_term_product(p, q, sign);
    }
    sum.sign()
}

/// Exact comparison of squared Euclidean lengths: `|ab|²` versus `|cd|²`.
///
/// Never computes a rounded length: a filtered `f64` evaluation decides
/// clear cases, and an exact expansion of `(a-b)² - (c-d)²` decides the rest.
pub fn compare_lengths(a: Point, b: Point, c: Point, d: Point) -> Ordering {
    // Rounded squared lengths are rounded keys (the squared-length module's
    // docs derive the filter).
    compare_rounded_keys(rounded_squared_length(a, b), rounded_squared_length(c, d))
        .unwrap_or_else(|| exact_length_difference_sign(a, b, c, d).cmp(&0))
}

/// Exact `|pq| < t` for a length `t ≥ 0` (a threshold): [`compare_lengths`]
/// of `pq` with the segment from the origin to `(t, 0)`, inlined for the
/// loops that test many pairs against one threshold.
#[inline]
pub fn shorter_than(p: Point, q: Point, t: f64) -> bool {
    let (o, e) = ([0.0, 0.0], [t, 0.0]);
    compare_rounded_keys(rounded_squared_length(p, q), rounded_squared_length(o, e))
        .unwrap_or_else(|| exact_length_difference_sign(p, q, o, e).cmp(&0))
        == Ordering::Less
}

/// `|pq|²` when `f64` arithmetic computes it exactly, else `None`: both
/// coordinate differences, both squares and their sum are exact (their
/// error terms by the error-free `two_diff`, `two_product` and `two_sum` are zero).
/// Two such values compare as numbers exactly as [`compare_lengths`]
/// compares the segments. Integer coordinates below 2²⁵ in magnitude always
/// qualify: a file of six-decimal points is read as such integers, and its
/// equal lengths need no expansion arithmetic.
#[inline]
pub fn exact_squared_length(p: Point, q: Point) -> Option<f64> {
    let (dx, ex) = two_diff(p[0], q[0]);
    let (dy, ey) = two_diff(p[1], q[1]);
    if ex != 0.0 || ey != 0.0 {
        return None;
    }
    let ((xx, exx), (yy, eyy)) = (two_product(dx, dx), two_product(dy, dy));
    let (sum, es) = two_sum(xx, yy);
    (exx == 0.0 && eyy == 0.0 && es == 0.0).then_some(sum)
}

/// `|ab|² - |cd|²` evaluated exactly; returns its sign.
///
/// Each coordinate difference is an exact two-term value `h + l`
/// ([`two_diff`]), and `(h + l)² = h² + 2hl + l²` is a sum of exact
/// [`two_product`]s: at most 24 terms, summed on the stack by
/// [`sign_of_sum`]. When a difference is exact (`l = 0`, e.g. on integer
/// coordinates, where equal lengths are common and every tie comes here)
/// only `h²` is expanded.
fn exact_length_difference_sign(a: Point, b: Point, c: Point, d: Point) -> i32 {
    let mut terms = [0.0; 24];
    let mut n = 0;
    let mut push = |(p, e): (f64, f64)| {
        terms[n] = p;
        terms[n + 1] = e;
        n += 2;
    };
    for k in 0..2 {
        for (p, q, sign) in [(a, b, 1.0), (c, d, -1.0)] {
            let (h, l) = two_diff(p[k], q[k]);
            push(two_product(sign * h, h));
            if l != 0.0 {
                push(two_product(sign * 2.0 * h, l));
                push(two_product(sign * l, l));
            }
        }
    }
    sign_of_sum(&terms[..n])
}

/// Exact sign of the dot product `(a - o) · (b - o)`.
///
/// Negative iff the angle `a o b` is obtuse, i.e. iff `o` lies strictly inside
/// the circle with diameter `ab` (Thales); zero iff `o` is on that circle.
pub fn dot_sign(o: Point, a: Point, b: Point) -> i32 {
    let (ax, ay, bx, by) = (a[0] - o[0], a[1] - o[1], b[0] - o[0], b[1] - o[1]);
    let v = ax * bx + ay * by;
    let bound = 8.0 * U * ((ax * bx).abs() + (ay * by).abs());
    if v > bound {
        return 1;
    }
    if -v > bound {
        return -1;
    }
    let mut e = Expansion::new();
    for k in 0..2 {
        e.add_two_term_product(two_diff(a[k], o[k]), two_diff(b[k], o[k]), 1.0);
    }
    e.sign()
}

/// Exact comparison of triangle areas `|abc|` versus `|def|` (unsigned).
///
/// Filtered: each doubled area `D = l − r`, `l = (b−a)ₓ(c−a)_y`,
/// `r = (b−a)_y(c−a)ₓ`, is off by at most `(3u + 16u²)(|l| + |r|)` in
/// floating point (Shewchuk 1997, `ccwerrboundA`); comparing `|D₁|` with `|D₂|`
/// adds at most `u(|D₁| + |D₂|) ≤ u(s₁ + s₂)` with `s = |l| + |r|`. So a
/// computed difference beyond `8u(s₁ + s₂)` has the right sign; anything
/// closer goes to the exact expansion.
pub fn compare_areas(tri1: [Point; 3], tri2: [Point; 3]) -> Ordering {
    let parts = |[a, b, c]: [Point; 3]| {
        let l = (b[0] - a[0]) * (c[1] - a[1]);
        let r = (b[1] - a[1]) * (c[0] - a[0]);
        ((l - r).abs(), l.abs() + r.abs())
    };
    let ((d1, s1), (d2, s2)) = (parts(tri1), parts(tri2));
    let diff = d1 - d2;
    let bound = 8.0 * U * (s1 + s2);
    if diff > bound {
        return Ordering::Greater;
    }
    if -diff > bound {
        return Ordering::Less;
    }
    exact_area_difference_sign(tri1, tri2).cmp(&0)
}

/// `|D₁| − |D₂|` of two doubled areas, evaluated exactly; returns its sign.
fn exact_area_difference_sign(tri1: [Point; 3], tri2: [Point; 3]) -> i32 {
    let s1 = orient_sign(tri1[0], tri1[1], tri1[2]) as f64;
    let s2 = orient_sign(tri2[0], tri2[1], tri2[2]) as f64;
    // |D1| - |D2| = s1*D1 - s2*D2, with D = (b-a)x(c-a) expanded exactly.
    let mut e = Expansion::new();
    for (tri, s) in [(tri1, s1), (tri2, -s2)] {
        if s == 0.0 {
            continue;
        }
        let [a, b, c] = tri;
        let (bax, bay) = (two_diff(b[0], a[0]), two_diff(b[1], a[1]));
        let (cax, cay) = (two_diff(c[0], a[0]), two_diff(c[1], a[1]));
        e.add_two_term_product(bax, cay, s);
        e.add_two_term_product(bay, cax, -s);
    }
    e.sign()
}

/// Exact comparison of the doubled (unsigned) area of `tri`,
/// `|(b − a) × (c − a)|`, with a finite number `value` (an `f64` is an exact
/// dyadic rational, so a user's threshold is compared exactly).
///
/// # Panics
/// If `value` is not finite.
pub fn compare_doubled_area(tri: [Point; 3], value: f64) -> Ordering {
    assert!(value.is_finite(), "area threshold must be finite");
    let [a, b, c] = tri;
    let sign = orient_sign(a, b, c) as f64;
    let mut sum = Expansion::new();
    if sign != 0.0 {
        sum.add_two_term_product(two_diff(b[0], a[0]), two_diff(c[1], a[1]), sign);
        sum.add_two_term_product(two_diff(b[1], a[1]), two_diff(c[0], a[0]), -sign);
    }
    sum.add(-value);
    sum.sign().cmp(&0)
}

/// Exact sign of the cross product of two difference vectors,
/// `(b − a) × (d − c)`: `1` if turning from direction `b − a` to `d − c` is
/// counter-clockwise (less than a half-turn), `-1` if clockwise, `0` if they
/// are parallel (or one is zero). `orient(a, b, d) − orient(a, b, c)` is the
/// same number, but rounding the two determinants separately is not exact.
pub fn cross_sign(a: Point, b: Point, c: Point, d: Point) -> i32 {
    // Filter: two rounded differences and a product per term, then one
    // subtraction: error below (3u + 16u²)(|l| + |r|) as for orientation.
    let l = (b[0] - a[0]) * (d[1] - c[1]);
    let r = (b[1] - a[1]) * (d[0] - c[0]);
    let det = l - r;
    if det.abs() > 4.0 * U * (l.abs() + r.abs()) {
        return if det > 0.0 { 1 } else { -1 };
    }
    let mut sum = Expansion::new();
    sum.add_two_term_product(two_diff(b[0], a[0]), two_diff(d[1], c[1]), 1.0);
    sum.add_two_term_product(two_diff(b[1], a[1]), two_diff(d[0], c[0]), -1.0);
    sum.sign()
}

/// The rounded cross and dot products of `u = a − o`, `v = b − o`, with
/// their permanents `|ux·vy| + |uy·vx|` and `|ux·vx| + |uy·vy|` (the error
/// scales of the filters below).
#[inline]
pub(super) fn rounded_cross_dot(o: Point, a: Point, b: Point) -> [f64; 4] {
    let (ux, uy, vx, vy) = (a[0] - o[0], a[1] - o[1], b[0] - o[0], b[1] - o[1]);
    let (xy, yx, xx, yy) = (ux * vy, uy * vx, ux * vx, uy * vy);
    [xy - yx, xx + yy, xy.abs() + yx.abs(), xx.abs() + yy.abs()]
}

/// The exact cross product `u × v` and dot product `u · v` of
/// `u = a − o`, `v = b − o`, as expansions (each difference is an exact
/// two-term value, each product of two such an exact four-term sum).
pub(super) fn exact_cross_dot(o: Point, a: Point, b: Point) -> (Expansion, Expansion) {
    let (ux, uy) = (two_diff(a[0], o[0]), two_diff(a[1], o[1]));
    let (vx, vy) = (two_diff(b[0], o[0]), two_diff(b[1], o[1]));
    let (mut cross, mut dot) = (Expansion::new(), Expansion::new());
    cross.add_two_term_product(ux, vy, 1.0);
    cross.add_two_term_product(uy, vx, -1.0);
    dot.add_two_term_product(ux, vx, 1.0);
    dot.add_two_term_product(uy, vy, 1.0);
    (cross, dot)
}

/// Exact: is the angle at `o` between the rays `o → a` and `o → b` at least
/// 30°? (The angle is in `[0°, 180°]`; `a` and `b` must differ from `o`.)
///
/// With `u = a − o`, `v = b − o`: the angle is at least 30° iff
/// `u·v ≤ 0` (at least 90°) or `4(u·v)² ≤ 3|u|²|v|²` (cos² ≤ 3/4). By
/// Lagrange's identity `|u|²|v|² = (u·v)² + (u×v)²` the second condition is
/// `E = 3(u×v)² − (u·v)² ≥ 0` (tan² ≥ 1/3), a degree-4 polynomial in the
/// coordinate differences, which is what we evaluate. With rational
/// coordinates `E` is never zero for `u × v ≠ 0` (`√3` is irrational), so an
/// angle of exactly 30° cannot occur; the exact fallback still decides every
/// near tie correctly.
///
/// Filter (`u = 2⁻⁵³`, `γₖ = ku/(1−ku)`). The rounded differences and one
/// product give each computed product of differences a relative error `γ₃`,
/// the subtraction (addition) one more `u`: the computed cross `c̃` and dot
/// `d̃` satisfy `|c̃ − C| ≤ γ₄·P_c` and `|d̃ − D| ≤ γ₄·P_d`, where
/// `P_c = |UxVy| + |UyVx| ≥ |C|` and `P_d = |UxVx| + |UyVy| ≥ |D|` are the
/// exact permanents. Then `|3c̃² − d̃² − E| ≤ 3|c̃ − C||c̃ + C| + |d̃ − D||d̃ + D|
/// ≤ (2 + γ₄)γ₄(3P_c² + P_d²)`, and evaluating `3c̃² − d̃²` (two squares, one
/// scaling by 3, one subtraction) adds at most `γ₃(3c̃² + d̃²) ≤
/// γ₃(1 + γ₄)²(3P_c² + P_d²)`. In total the error is below
/// `11.001u·(3P_c² + P_d²)`. The computed permanents are at least
/// `(1 − γ₄)` times the exact ones and the tolerance is itself evaluated
/// with relative error below `γ₅`, so `16u·(3p̃_c² + p̃_d²)` exceeds the error
/// bound. The coordinate range keeps every product of four differences
/// within `[2⁻⁷⁷⁶, 2⁸¹⁰]` (module docs), so nothing underflows or overflows.
pub fn angle_at_least_30_degrees(o: Point, a: Point, b: Point) -> bool {
    if dot_sign(o, a, b) <= 0 {
        return true;
    }
    let [c, d, pc, pd] = rounded_cross_dot(o, a, b);
    let e = 3.0 * (c * c) - d * d;
    let tolerance = 16.0 * U * (3.0 * (pc * pc) + pd * pd);
    if e > tolerance {
        return true;
    }
    if -e > tolerance {
        return false;
    }
    let (cross, dot) = exact_cross_dot(o, a, b);
    let mut e = Expansion::new();
    // 3C² as 2C² + C²: scaling a component by 2 is exact.
    e.add_expansion_product(&cross, &cross, 2.0);
    e.add_expansion_product(&cross, &cross, 1.0);
    e.add_expansion_product(&dot, &dot, -1.0);
    e.sign() >= 0
}

/// `tan α'` for the diamond angle `α' = arctan(833/1024) ≈ 0.682905` rad,
/// just below `π/4.6 ≈ 0.682955` (`tan(π/4.6) ≈ 0.813560`, and
/// `833/1024 = 0.8134765625`).
pub const DIAMOND_TAN_NUMERATOR: f64 = 833.0;
/// See [`DIAMOND_TAN_NUMERATOR`].
pub const DIAMOND_TAN_DENOMINATOR: f64 = 1024.0;

/// Exact: is the angle at `o` between the rays to `a` and `b` strictly below
/// the diamond angle `α' = arctan(833/1024)`, a dyadic angle just below the
/// base angle `π/4.6` of Drysdale, McElfresh & Snoeyink's diamond property
/// (*An improved diamond property for minimum weight triangulation*, 1998)?
/// A smaller triangle is a subset of the true one, so a point found inside
/// it is inside the true one: using `α'` keeps the filter sound.
///
/// With `u = a − o`, `v = b − o`: the angle is below `α'` iff `u·v > 0` and
/// `1024|u×v| < 833(u·v)` (the tangent comparison `tangent_side`).
pub fn angle_below_diamond(o: Point, a: Point, b: Point) -> bool {
    if dot_sign(o, a, b) <= 0 {
        return false;
    }
    tangent_side(o, a, b, DIAMOND_TAN_NUMERATOR, DIAMOND_TAN_DENOMINATOR) > 0
}

/// Exact: the sign of `num·(u·v) − den·|u×v|` for `u = a − o`, `v = b − o`
/// and `num, den > 0`. When `u·v > 0` it is the sign of `num/den − tan θ`
/// for the angle `θ` at `o`: positive iff `θ < arctan(num/den)`.
///
/// A degree-2 polynomial in the differences. Filter: `|c̃ − C| ≤ γ₄P_c`,
/// `|d̃ − D| ≤ γ₄P_d` (see [`angle_at_least_30_degrees`]); the two scalings
/// and the subtraction add `γ₂` relative, so `16u(num·p̃_d + den·p̃_c)`
/// bounds the error; else exact expansions.
pub(super) fn tangent_side(o: Point, a: Point, b: Point, num: f64, den: f64) -> i32 {
    let [c, d, pc, pd] = rounded_cross_dot(o, a, b);
    let e = num * d - den * c.abs();
    let tolerance = 16.0 * U * (num * pd + den * pc);
    if e > tolerance {
        return 1;
    }
    if -e > tolerance {
        return -1;
    }
    let (cross, dot) = exact_cross_dot(o, a, b);
    let s = orient_sign(o, a, b) as f64; // the sign of the cross product
    let mut e = Expansion::new();
    e.add_scaled(&dot, num);
    e.add_scaled(&cross, -den * s);
    e.sign()
}

#[cfg(any(test, feature = "internals"))]
/// Filter, never wrong when it answers `true`: does `c` certainly lie
/// outside both closed diamond triangles on `ab` (the isosceles triangles
/// with base `ab` and base angle `α' = arctan(833/1024)` of
/// [`angle_below_diamond`])? `false` means "maybe inside": decide with the
/// exact predicates.
///
/// With `w = b − a`, `v = c − a`, `D = w·v`, `C = w×v`, `L = w·w`: a point of
/// either closed triangle has `|C| ≤ tan α'·D` (angle at `a`) and
/// `|C| ≤ tan α'·(L − D)` (angle at `b`, as `(a−b)·(c−b) = L − D`). In
/// floating point each of `D`, `C`, `L` is off by at most `γ₄` (< `5u`)
/// times `s = (|wₓ|+|w_y|)(|vₓ|+|v_y|) + (|wₓ|+|w_y|)²`, and forming
/// `0.814·min(D, L − D)` adds a few `u·s` more; the tolerance `10⁻¹⁰·s` is
/// far above that, so `|C| > 0.814·min(D, L − D) + 10⁻¹⁰·s` (with
/// `0.814 > 833/1024`) proves `c` outside. Near underflow or overflow the
/// filter abstains.
#[inline]
pub fn certainly_outside_diamonds(a: Point, b: Point, c: Point) -> bool {
    let (wx, wy, vx, vy) = (b[0] - a[0], b[1] - a[1], c[0] - a[0], c[1] - a[1]);
    let dot = wx * vx + wy * vy;
    let cross = wx * vy - wy * vx;
    let l2 = wx * wx + wy * wy;
    let w1 = wx.abs() + wy.abs();
    let s = w1 * (vx.abs() + vy.abs()) + w1 * w1;
    if !(s > 1e-280 && s < 1e280) {
        return false;
    }
    cross.abs() > 0.814 * dot.min(l2 - dot) + 1e-10 * s
}

/// Where a point lies against the two diamond triangles on a segment `ab`
/// (the isosceles triangles with base `ab` and base angle `α'` of
/// [`angle_below_diamond`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DiamondPosition {
    /// In neither triangle (on the line `ab`, on or beyond a slanted side).
    Outside,
    /// Strictly inside the triangle on the left of `a → b`.
    Left,
    /// Strictly inside the triangle on the right of `a → b`.
    Right,
}

/// The two diamond triangles on a segment `ab`, for many exact
/// [`position`](Self::position) queries (the segment's terms computed
/// once).
#[derive(Clone, Copy, Debug)]
pub struct DiamondTriangles {
    a: Point,
    b: Point,
    w: [f64; 2],
    l2: f64,
    w1: f64,
    w1_squared: f64,
    /// Whether the filter may answer (no underflow or overflow near).
    filtered: bool,
}

impl DiamondTriangles {
    /// The triangles on `ab` (`a ≠ b`).
    #[inline]
    pub fn new(a: Point, b: Point) -> Self {
        let w = [b[0] - a[0], b[1] - a[1]];
        let w1 = w[0].abs() + w[1].abs();
        DiamondTriangles {
            a,
            b,
            w,
            l2: w[0] * w[0] + w[1] * w[1],
            w1,
            w1_squared: w1 * w1,
            filtered: w1 > 1e-140 && w1 < 1e140,
        }
    }

    /// Exact: where `c` lies: `Left` or `Right` iff `c` is strictly on that
    /// side of the line `ab` and both base angles (at `a` and at `b`) are
    /// strictly below `α'` — the decision of [`orient_sign`] and
    /// [`angle_below_diamond`] at both ends, which it makes when its filter
    /// cannot.
    ///
    /// Filter: with `w = b − a`, `v = c − a`, `D = w·v`, `C = w×v`, `L = w·w`
    /// and `m = min(D, L − D)`, a point is inside a triangle iff `|C| > 0`,
    /// `|C| < tan α'·D` and `|C| < tan α'·(L − D)` (the angle at `b` has
    /// dot product `L − D` and the same cross product). As in
    /// [`certainly_outside_diamonds`], each computed `D`, `C`, `L` is within
    /// `γ₄·s` (`< 5u·s`) of the exact value, `s = (|wₓ|+|w_y|)(|vₓ|+|v_y|) +
    /// (|wₓ|+|w_y|)²`, and the products and the minimum add a few `u·s`:
    /// the tolerance `10⁻¹⁰·s` is far above. So `|C| > 0.814·m + 10⁻¹⁰s`
    /// proves outside (`0.814 > 833/1024`), and `10⁻¹⁰s < |C| < 0.8134·m −
    /// 10⁻¹⁰s` proves inside on the side of `C`'s sign (`0.8134 <
    /// 833/1024`). Near underflow or overflow, and in the thin bands
    /// between, it decides exactly.
    #[inline]
    pub fn position(&self, c: Point) -> DiamondPosition {
        let (vx, vy) = (c[0] - self.a[0], c[1] - self.a[1]);
        let dot = self.w[0] * vx + self.w[1] * vy;
        let cross = self.w[0] * vy - self.w[1] * vx;
        let s = self.w1 * (vx.abs() + vy.abs()) + self.w1_squared;
        if self.filtered && s > 1e-280 && s < 1e280 {
            let m = dot.min(self.l2 - dot);
            let tolerance = 1e-10 * s;
            if cross.abs() > 0.814 * m + tolerance {
                return DiamondPosition::Outside;
            }
            if cross.abs() > tolerance && cross.abs() < 0.8134 * m - tolerance {
                return if cross > 0.0 {
                    DiamondPosition::Left
                } else {
                    DiamondPosition::Right
                };
            }
        }
        let (a, b) = (self.a, self.b);
        let side = orient_sign(a, b, c);
        if side == 0 || !angle_below_diamond(a, b, c) || !angle_below_diamond(b, a, c) {
            DiamondPosition::Outside
        } else if side > 0 {
            DiamondPosition::Left
        } else {
            DiamondPosition::Right
        }
    }
}

/// Exact comparison of two angles in `[0°, 180°]`: the angle at `p[0]`
/// between the rays to `p[1]` and `p[2]` versus the angle at `q[0]` between
/// the rays to `q[1]` and `q[2]`. The rays' points must differ from their
/// apexes.
///
/// A flat corner (cross product zero, exactly) is 0° or 180° by the sign of
/// its dot product. Otherwise both angles lie in `(0°, 180°)`, where the
/// cotangent `D/|C|` (dot over absolute cross) is strictly decreasing, so
/// `θ_p < θ_q ⟺ D_p/|C_p| > D_q/|C_q| ⟺ F = D_q·|C_p| − D_p·|C_q| < 0`, a
/// degree-4 polynomial (the signs of `C` come exactly from [`orient_sign`]).
///
/// Filter: as in [`angle_at_least_30_degrees`], `|c̃ − C| ≤ γ₄P_c` and
/// `|d̃ − D| ≤ γ₄P_d` for each corner, so `|d̃_q·|c̃_p| − D_q|C_p|| ≤
/// (2 + γ₄)γ₄·P_{d,q}P_{c,p}` (and the same for the other product); the
/// two products and the subtraction add `γ₂(1 + γ₄)²` times the same
/// permanents. The error is below `10.001u·(P_{d,q}P_{c,p} + P_{d,p}P_{c,q})`,
/// and `16u` times the computed permanents exceeds it (same argument).
pub fn compare_corner_angles(p: [Point; 3], q: [Point; 3]) -> Ordering {
    debug_assert!(p[1] != p[0] && p[2] != p[0] && q[1] != q[0] && q[2] != q[0]);
    let sp = orient_sign(p[0], p[1], p[2]);
    let sq = orient_sign(q[0], q[1], q[2]);
    // 0: a flat 0° corner, 1: inside (0°, 180°), 2: a flat 180° corner.
    let class = |s: i32, c: [Point; 3]| match s {
        0 if dot_sign(c[0], c[1], c[2]) > 0 => 0,
        0 => 2,
        _ => 1,
    };
    let (kp, kq) = (class(sp, p), class(sq, q));
    if kp != 1 || kq != 1 {
        return kp.cmp(&kq);
    }
    let [cp, dp, pcp, pdp] = rounded_cross_dot(p[0], p[1], p[2]);
    let [cq, dq, pcq, pdq] = rounded_cross_dot(q[0], q[1], q[2]);
    let (cp, cq) = (cp * sp as f64, cq * sq as f64);
    let f = dq * cp - dp * cq;
    let tolerance = 16.0 * U * (pdq * pcp + pdp * pcq);
    if f > tolerance {
        return Ordering::Greater;
    }
    if -f > tolerance {
        return Ordering::Less;
    }
    let (cross_p, dot_p) = exact_cross_dot(p[0], p[1], p[2]);
    let (cross_q, dot_q) = exact_cross_dot(q[0], q[1], q[2]);
    let mut e = Expansion::new();
    e.add_expansion_product(&dot_q, &cross_p, sp as f64);
    e.add_expansion_product(&dot_p, &cross_q, -(sq as f64));
    e.sign().cmp(&0)
}

/// Exact counter-clockwise angular order of directions `a - o` and `b - o`,
/// starting from the positive x-axis.
pub fn compare_angles(o: Point, a: Point, b: Point) -> Ordering {
    let half = |p: Point| -> u8 {
        // 0 for angles in [0, π), 1 for [π, 2π).
        if p[1] > o[1] || (p[1] == o[1] && p[0] > o[0]) {
            0
        } else {
            1
        }
    };
    half(a)
        .cmp(&half(b))
        .then_with(|| match orient_sign(o, a, b) {
            1 => Ordering::Less,
            -1 => Ordering::Greater,
            // Same ray (a farther or nearer) or opposite rays already split by half.
            _ => {
                debug_assert!(dot_sign(o, a, b) > 0 || half(a) != half(b));
                Ordering::Equal
            }
        })
}

/// Exact: do the open segments `ab` and `cd` cross in a single interior point?
#[inline]
pub fn properly_cross(a: Point, b: Point, c: Point, d: Point) -> bool {
    let (abc, abd) = (orient_sign(a, b, c), orient_sign(a, b, d));
    if abc * abd >= 0 {
        return false;
    }
    orient_sign(c, d, a) * orient_sign(c, d, b) < 0
}

/// Exact: does `z` lie on the open segment `ab`?
#[inline]
pub fn on_open_segment(z: Point, a: Point, b: Point) -> bool {
    orient_sign(a, b, z) == 0 && dot_sign(z, a, b) < 0
}

/// Exact: do the closed segments `ab` and `cd` share a point? Collinear
/// segments intersect iff their coordinate intervals overlap (the same test
/// on x and on y, so vertical segments need no special case).
pub fn segments_intersect(a: Point, b: Point, c: Point, d: Point) -> bool {
    let (abc, abd) = (orient_sign(a, b, c), orient_sign(a, b, d));
    let (cda, cdb) = (orient_sign(c, d, a), orient_sign(c, d, b));
    if abc * abd > 0 || cda * cdb > 0 {
        return false;
    }
    if abc != 0 || abd != 0 || cda != 0 || cdb != 0 {
        return true;
    }
    // All four collinear: compare the intervals exactly (min/max never round).
    (0..2).all(|k| a[k].min(b[k]) <= c[k].max(d[k]) && c[k].min(d[k]) <= a[k].max(b[k]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cmp::Ordering::*;

    /// The exact orientation of `a·s, b·s, c·t` in rational arithmetic
    /// (the oracle's, which shares no code with the kernel).
    fn orient_scaled_reference(a: Point, b: Point, c: Point, s: f64, t: f64) -> i32 {
        use optri_oracle::{to_rational, BigRational};
        let scaled = |p: Point, f: f64| -> [BigRational; 2] {
            [
                to_rational(p[0]) * to_rational(f),
                to_rational(p[1]) * to_rational(f),
            ]
        };
        let ([ax, ay], [bx, by], [cx, cy]) = (scaled(a, s), scaled(b, s), scaled(c, t));
        let d = (&bx - &ax) * (&cy - &ay) - (&by - &ay) * (&cx - &ax);
        match d.cmp(&BigRational::from_integer(0.into())) {
            Greater => 1,
            Less => -1,
            Equal => 0,
        }
    }

    #[test]
    fn scaled_orientation_matches_rational_arithmetic() {
        // A query exactly on the scaled line, one ulp to either side, and
        // decimals whose doubles miss the line by their rounding error.
        let (a, b) = ([0.0, 0.0], [3.0, 1.0]);
        let mut queries = vec![
            [0.375, 0.125],
            [0.3, 0.1],
            [0.6, 0.2],
            [0.9, 0.3],
            [1.5, 0.5],
        ];
        for delta in [-1i64, 1] {
            let y = f64::from_bits((0.125f64.to_bits() as i64 + delta) as u64);
            queries.push([0.375, y]);
        }
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..200 {
            queries.push([3.0 * next(), next()]);
        }
        let scales = [
            (1.0, 10.0),
            (1.0, 1e22),
            (10.0, 1.0),
            (1e22, 1.0),
            (1.0, 1.0),
        ];
        for (s, t) in scales {
            for &c in &queries {
                let expected = orient_scaled_reference(a, b, c, s, t);
                let got = orient_sign_scaled(a, b, c, s, t);
                assert_eq!(got, expected, "c = {c:?}, s = {s}, t = {t}");
            }
        }
        assert_eq!(orient_sign_scaled(a, b, [0.375, 0.125], 1.0, 8.0), 0);
        // The doubles of 0.3 and 0.1 are not 3/10 and 1/10: scaled by ten
        // they miss the line through (0, 0) and (3, 1).
        assert_ne!(orient_sign_scaled(a, b, [0.3, 0.1], 1.0, 10.0), 0);
    }

    #[test]
    fn orientation_of_near_collinear_points_is_exact() {
        // c is one ulp off the line through a and b.
        let a = [0.5, 0.5];
        let b = [12.0, 12.0];
        let c = [24.0, 24.0];
        assert_eq!(orient_sign(a, b, c), 0);
        let c_up = [24.0, f64::from_bits(24f64.to_bits() + 1)];
        assert_eq!(orient_sign(a, b, c_up), 1);
        let c_down = [24.0, f64::from_bits(24f64.to_bits() - 1)];
        assert_eq!(orient_sign(a, b, c_down), -1);
    }

    #[test]
    fn incircle_sign_convention() {
        let (a, b, c) = ([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]);
        assert_eq!(incircle_sign(a, b, c, [0.5, 0.5]), 1);
        assert_eq!(incircle_sign(a, b, c, [1.0, 1.0]), 0);
        assert_eq!(incircle_sign(a, b, c, [2.0, 2.0]), -1);
    }

    #[test]
    fn equal_lengths_compare_equal_even_when_f64_rounding_differs() {
        // 3-4-5 and 5-0: equal exactly.
        assert_eq!(
            compare_lengths([0.0, 0.0], [3.0, 4.0], [1.0, 1.0], [6.0, 1.0]),
            Equal
        );
        // Lengths differing by 2^-100 relative: invisible to f64, seen exactly.
        let x = 1.0 + 2f64.powi(-52);
        assert_eq!(
            compare_lengths([0.0, 0.0], [x, 0.0], [0.0, 0.0], [0.0, 1.0]),
            Greater
        );
        // (1e8+1e-8)^2 vs (1e8)^2 + 2: d1^2 = 1e16 + 2 + 1e-16 > 1e16 + 2.
        let big = 1e8;
        let tiny = 1e-8;
        let sq2 = 2f64.sqrt();
        let _ = sq2;
        assert_eq!(
            compare_lengths([0.0, 0.0], [big, tiny], [0.0, 0.0], [big, 0.0]),
            Greater
        );
        assert_eq!(
            compare_lengths([big, 0.0], [0.0, 0.0], [0.0, 0.0], [big, tiny]),
            Less
        );
    }

    #[test]
    fn huge_and_negative_coordinates_compare_exactly() {
        let h = 2f64.powi(200);
        let a = [-h, -h];
        let b = [h, h];
        let c = [-h, h];
        let d = [h, -h];
        assert_eq!(compare_lengths(a, b, c, d), Equal);
        let d2 = [h, f64::from_bits((-h).to_bits() + 1)]; // -h - ulp: farther
        assert_eq!(compare_lengths(a, b, c, d2), Less);
    }

    #[test]
    fn tiny_coordinates_compare_exactly() {
        let t = 2f64.powi(-140);
        assert_eq!(
            compare_lengths([0.0, 0.0], [3.0 * t, 4.0 * t], [t, t], [6.0 * t, t]),
            Equal
        );
        assert_eq!(
            compare_lengths([0.0, 0.0], [3.0 * t, 4.0 * t], [t, t], [6.0 * t, 1.5 * t]),
            Less
        );
    }

    #[test]
    fn dot_sign_is_thales() {
        let (a, b) = ([-1.0, 0.0], [1.0, 0.0]);
        assert_eq!(dot_sign([0.0, 1.0], a, b), 0);
        assert_eq!(dot_sign([0.0, 0.999], a, b), -1);
        assert_eq!(dot_sign([0.0, 1.001], a, b), 1);
        // (3, 4) is on the circle with diameter (-5, 0)-(5, 0); nudge it by one ulp.
        let (a5, b5) = ([-5.0, 0.0], [5.0, 0.0]);
        assert_eq!(dot_sign([3.0, 4.0], a5, b5), 0);
        assert_eq!(
            dot_sign([3.0, f64::from_bits(4f64.to_bits() - 1)], a5, b5),
            -1
        );
        assert_eq!(
            dot_sign([3.0, f64::from_bits(4f64.to_bits() + 1)], a5, b5),
            1
        );
    }

    #[test]
    fn area_comparison_ignores_orientation_and_is_exact() {
        let t1 = [[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]];
        let t2 = [[0.0, 0.0], [0.0, 4.0], [1.0, 0.0]]; // clockwise, same area
        assert_eq!(compare_areas(t1, t2), Equal);
        let t3 = [[0.0, 0.0], [0.0, 4.0], [1.0 + 2f64.powi(-50), 0.0]];
        assert_eq!(compare_areas(t1, t3), Less);
        let flat = [[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]];
        assert_eq!(compare_areas(flat, t1), Less);
        assert_eq!(compare_areas(flat, flat), Equal);
    }
}
