//! Measures for *reporting*: lengths, areas, angles and total lengths, each
//! the exact value rounded once to the nearest `f64` (ties to even).
//!
//! The values are never used for combinatorial decisions (those go through
//! the exact predicates of [`crate::kernel`]), but they are what a user
//! reads, compares and checks: a triangle of positive area never reports
//! area 0, a certified bound equals the measure it bounds when they are the
//! same quantity, and two equal rounded values of different quantities are
//! at least as close as their exact values allow (correct rounding is
//! monotone: `round(x) < round(y)` implies `x < y`).
//!
//! Each measure follows Ziv's strategy (module `rounding`): a cheap
//! enclosure with a derived error bound, rounded when the enclosure stays
//! clear of every rounding boundary, and an exact or higher-precision
//! evaluation otherwise.
//!
//! * **Length** `√X`, `X` the exact squared length: the certified
//!   double-double `X ≈ hi + lo` of [`SquaredLength`] and one Newton
//!   correction of `fl(√hi)` give `√X` within `17u²·√X` (proof at
//!   `length_enclosure`); the exact path encloses `√X` by exact integer
//!   square roots.
//! * **Area** `|D|/2`, `D` the doubled signed area: `D` as a double-double
//!   with an error bound proportional to its permanent (fine unless the
//!   triangle is a needle whose `D` cancels), else `D` exactly in integers.
//! * **Angle** (module `degrees`): always at high precision; only the two
//!   extreme corners of a triangulation are converted.
//! * **Total length** (`LengthSum`): the enclosures of the lengths summed
//!   in double-double with a running bound on the rounding errors, so that
//!   ~3·10⁶ square roots cost little more than their rounded sum; the exact
//!   path sums exact integer square roots at a doubling precision.
//!
//! Decimal input (`io::decimal`) is triangulated as integers `10^k` times
//! the user's decimals; its measures in the user's units are the exact
//! measures divided by `10^k` (lengths) or `10^2k` (areas), rounded once:
//! the `_scaled` functions divide the enclosure (or the exact value), never
//! a rounded result.
//!
//! The fast paths need the kernel's coordinate range ([`crate::kernel`]),
//! which keeps every error term exact or relative; points outside it (the
//! public functions accept any finite points) take the exact path.

pub use super::rounding::Rounding;

use super::degrees::corner_degrees;
use super::expansion::{two_diff, two_product, two_sum};
use super::length_sums::{decompose, scaled};
use super::rounding::{over_power_of_ten, round_ratio, round_root_sum, Enclosure, U};
use super::{Point, SquaredLength, MAX_COORDINATE, MIN_COORDINATE};
use num_bigint::{BigInt, BigUint};
use num_traits::One;

/// `|ab|`, correctly rounded.
#[inline]
pub fn length(a: Point, b: Point) -> f64 {
    length_scaled(a, b, 0)
}

/// `|ab| / 10^k` (the length between the points divided by `10^k`),
/// correctly rounded.
pub fn length_scaled(a: Point, b: Point, k: i32) -> f64 {
    if !finite(&[a, b]) {
        return (a[0] - b[0]).hypot(a[1] - b[1]) / 10f64.powi(k);
    }
    if in_range(&[a, b]) {
        if let Some(v) = length_enclosure(a, b)
            .over_power_of_ten(k)
            .and_then(|e| e.rounded(Rounding::Nearest))
        {
            return v;
        }
    }
    let (radicand, exp2) = exact_squared_length(a, b);
    round_root_sum(1, |_| radicand.clone(), exp2, k, Rounding::Nearest)
}

/// Unsigned area of triangle `abc`, correctly rounded.
#[inline]
pub fn area(a: Point, b: Point, c: Point) -> f64 {
    area_scaled(a, b, c, 0)
}

/// Unsigned area of triangle `abc` divided by `10^2k` (the area of the
/// triangle with corners divided by `10^k`), correctly rounded.
pub fn area_scaled(a: Point, b: Point, c: Point, k: i32) -> f64 {
    if !finite(&[a, b, c]) {
        let naive = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).abs();
        return naive / 10f64.powi(2 * k);
    }
    if in_range(&[a, b, c]) {
        if let Some(v) = doubled_area_enclosure(a, b, c)
            .and_then(|e| e.over_power_of_ten(2 * k))
            .and_then(|e| e.rounded(Rounding::Nearest))
        {
            return 0.5 * v; // exact: v is far above the subnormal range
        }
    }
    let emin = min_exponent(&[a, b, c]);
    let s = |v: f64| scaled(v, emin);
    let (bx, by) = (s(b[0]) - s(a[0]), s(b[1]) - s(a[1]));
    let (cx, cy) = (s(c[0]) - s(a[0]), s(c[1]) - s(a[1]));
    let doubled = bx * cy - by * cx;
    let (num, den, exp2) = over_power_of_ten(
        doubled.magnitude().clone(),
        BigUint::one(),
        2 * i64::from(emin) - 1,
        2 * k,
    );
    round_ratio(&num, &den, exp2, Rounding::Nearest)
}

/// The angle at `o` between the rays to `a` and `b`, in degrees in
/// `[0°, 180°]`, correctly rounded (0 if `a` or `b` is `o`).
pub fn angle_deg(o: Point, a: Point, b: Point) -> f64 {
    if !finite(&[o, a, b]) {
        return f64::NAN;
    }
    corner_degrees(o, a, b)
}

/// The three interior angles of triangle `abc` in degrees (at `a`, `b`,
/// `c`), each correctly rounded.
pub fn angles_deg(a: Point, b: Point, c: Point) -> [f64; 3] {
    [angle_deg(a, b, c), angle_deg(b, c, a), angle_deg(c, a, b)]
}

/// `v / 10^k` for a finite `v ≥ 0`, rounded once as `mode` says (a lower
/// bound in the user's units stays a lower bound with [`Rounding::Down`]).
#[cfg_attr(not(any(feature = "io", feature = "internals")), allow(dead_code))] // bounds in the JSON
pub fn over_power_of_ten_rounded(v: f64, k: i32, mode: Rounding) -> f64 {
    if !(v.is_finite() && v > 0.0) {
        return v / 10f64.powi(k);
    }
    let (m, e) = decompose(v);
    let (num, den, exp2) = over_power_of_ten(
        BigUint::from(m.unsigned_abs()),
        BigUint::one(),
        i64::from(e),
        k,
    );
    round_ratio(&num, &den, exp2, mode)
}

/// The total length of `edges` (index pairs into `points`), correctly
/// rounded.
///
/// # Panics
/// If an edge refers to an index outside `points`.
pub fn total_length(points: &[Point], edges: &[[u32; 2]]) -> f64 {
    total_length_scaled(points, edges, 0, Rounding::Nearest)
}

/// The total length of `edges` divided by `10^k`, rounded once as `mode`
/// says.
///
/// # Panics
/// If an edge refers to an index outside `points`.
pub fn total_length_scaled(points: &[Point], edges: &[[u32; 2]], k: i32, mode: Rounding) -> f64 {
    let p = |i: u32| points[i as usize];
    let used = || edges.iter().flat_map(|&[a, b]| [p(a), p(b)]);
    if !used().all(|q| finite(&[q])) {
        let naive: f64 = edges
            .iter()
            .map(|&[a, b]| (p(a)[0] - p(b)[0]).hypot(p(a)[1] - p(b)[1]))
            .sum();
        return naive / 10f64.powi(k);
    }
    if used().all(|q| in_range(&[q])) {
        let sum = edges
            .iter()
            .fold(LengthSum::ZERO, |s, &[a, b]| s.plus_segment(p(a), p(b)));
        if let Some(v) = sum.rounded(k, mode) {
            return v;
        }
    }
    exact_total_length(edges.len(), |i| edges[i].map(p), k, mode)
}

/// The total length of `count` segments `segment(i)`, divided by `10^k`,
/// computed exactly (the slow path of [`total_length_scaled`] and of
/// [`LengthSum::rounded`] when it is undecided).
pub(crate) fn exact_total_length(
    count: usize,
    segment: impl Fn(usize) -> [Point; 2],
    k: i32,
    mode: Rounding,
) -> f64 {
    let emin = (0..count)
        .flat_map(|i| segment(i).into_iter().flatten())
        .filter(|&v| v != 0.0)
        .map(|v| decompose(v).1)
        .min()
        .unwrap_or(0);
    let radicand = |i: usize| {
        let [a, b] = segment(i);
        squared_length_at(a, b, emin)
    };
    round_root_sum(count, radicand, i64::from(emin), k, mode)
}

/// A certified double-double enclosure of a sum of Euclidean lengths, for
/// a correctly rounded total ([`rounded`](Self::rounded)).
///
/// Each length `lᵢ` enters as its enclosure `sᵢ + tᵢ` (within `17u²·sᵢ`,
/// [`length_enclosure`]); `hi` collects the `sᵢ` by [`two_sum`], whose
/// errors `eᵢ` are exact, and `lo` the rounded sums of the `eᵢ + tᵢ`.
/// Every rounded addition into `lo` errs by at most `u` times its result,
/// so `rounding` — the sum of the magnitudes of those results — bounds the
/// accumulated error by `u·rounding`. With `Σsᵢ ≤ (hi + |lo| +
/// u·rounding)(1 + 3.1u)` the exact total is within
/// `17u²(hi + |lo|) + u·rounding·(1 + 2⁻⁹)` of `hi + lo`; `rounding` is
/// itself a rounded sum of fewer than `5n` non-negative terms, at most
/// `(1 − u)^{−5n} ≤ 1 + 2⁻¹⁸` below its exact value for `n < 2³²`, which
/// the factor `1 + 2⁻⁸` of [`rounded`](Self::rounded) covers. The order of
/// additions and merges does not matter to the bound, so parallel blocks
/// may be merged in any tree.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct LengthSum {
    hi: f64,
    lo: f64,
    rounding: f64,
}

impl LengthSum {
    /// The empty sum.
    pub(crate) const ZERO: LengthSum = LengthSum {
        hi: 0.0,
        lo: 0.0,
        rounding: 0.0,
    };

    /// The sum plus `|pq|`, for points in the kernel's coordinate range.
    #[inline]
    pub(crate) fn plus_segment(self, p: Point, q: Point) -> Self {
        let length = length_enclosure(p, q);
        let (hi, e) = two_sum(self.hi, length.hi);
        let x = e + length.lo;
        let lo = self.lo + x;
        LengthSum {
            hi,
            lo,
            rounding: self.rounding + (x.abs() + lo.abs()),
        }
    }

    /// The sum of two sums.
    #[inline]
    pub(crate) fn plus(self, other: Self) -> Self {
        let (hi, e) = two_sum(self.hi, other.hi);
        let x = self.lo + other.lo;
        let lo = x + e;
        LengthSum {
            hi,
            lo,
            rounding: (self.rounding + other.rounding) + (x.abs() + lo.abs()),
        }
    }

    /// The sum divided by `10^k`, rounded as `mode` says, if the enclosure
    /// decides it (else the exact path must: [`exact_total_length`]).
    pub(crate) fn rounded(self, k: i32, mode: Rounding) -> Option<f64> {
        let err =
            17.0 * U * U * (self.hi + self.lo.abs()) + U * self.rounding * (1.0 + 2f64.powi(-8));
        Enclosure {
            hi: self.hi,
            lo: self.lo,
            err,
        }
        .over_power_of_ten(k)?
        .rounded(mode)
    }
}

/// `|pq|` enclosed: `(s, t, 20u²·s)` with `|√X − (s + t)| < 17u²·s`, for
/// `X = |pq|²` and points in the kernel's coordinate range.
///
/// [`SquaredLength`] gives `X = hi + lo + δ` with `|δ| ≤ 12.02u²·hi` and
/// `|lo| ≤ 4.01u·hi`. With `s = fl(√hi) = √hi(1 + ε)`, `|ε| ≤ u`, the
/// remainder `r = hi − s²` is a double (that of a correctly rounded square
/// root), computed exactly by a fused multiply-add, `|r| ≤ 2.0001u·hi`.
/// `N = r + lo` has `|N| ≤ 6.03u·s²`, and `√X − s = (N + δ)/(√X + s)`,
/// where `√X + s ≥ 2s(1 − 1.52u)`. The computed `t = fl(fl(N)/2s)` then
/// differs from `√X − s` by at most
/// `|N||N + δ|/(2s(√X + s)²) + |δ|/(√X + s) + 2.001u·|N|/(2s)
/// ≤ (4.56 + 6.02 + 6.04)u²·s < 17u²·s`, and `|t| ≤ 3.02u·s`. The bound is
/// returned as `20u²·s`, above `17u²·s` after its own rounding.
#[inline]
fn length_enclosure(p: Point, q: Point) -> Enclosure {
    let square = SquaredLength::of_segment(p, q);
    let s = square.hi.sqrt();
    if s == 0.0 {
        return Enclosure {
            hi: 0.0,
            lo: 0.0,
            err: 0.0,
        };
    }
    let r = (-s).mul_add(s, square.hi);
    let t = (r + square.lo) / (2.0 * s);
    Enclosure {
        hi: s,
        lo: t,
        err: 20.0 * U * U * s,
    }
}

/// `|D|` enclosed, `D = (b − a) × (c − a)`, or `None` when the enclosure
/// is useless (`D` nearly cancels).
///
/// With `bx − ax = x₁ + x₀` exactly ([`two_diff`], `|x₀| ≤ u|x₁|`), and so
/// on, `D = x₁y₁ − z₁w₁ + (x₁y₀ + x₀y₁ + x₀y₀) − (z₁w₀ + z₀w₁ + z₀w₀)`.
/// `x₁y₁ = P₁ + e₁` and `z₁w₁ = P₂ + e₂` exactly ([`two_product`]), and
/// `P₁ − P₂ = S + e₃` exactly ([`two_sum`]), so `D = S + tail` for a tail of
/// nine terms of total magnitude at most `4.01u(|P₁| + |P₂|)`. Summed in
/// `f64` (six products and eight additions), the tail errs by at most
/// `(γ₈ + u(1 + γ₈))·4.02u(|P₁| + |P₂|) ≤ 36.3u²(|P₁| + |P₂|)`; the bound is
/// returned as `40u²(|P₁| + |P₂|)`.
fn doubled_area_enclosure(a: Point, b: Point, c: Point) -> Option<Enclosure> {
    let (x1, x0) = two_diff(b[0], a[0]);
    let (y1, y0) = two_diff(c[1], a[1]);
    let (z1, z0) = two_diff(b[1], a[1]);
    let (w1, w0) = two_diff(c[0], a[0]);
    let (p1, e1) = two_product(x1, y1);
    let (p2, e2) = two_product(z1, w1);
    let (s, e3) = two_sum(p1, -p2);
    let tail = (e1 - e2 + e3) + (x1 * y0 + x0 * y1 + x0 * y0) - (z1 * w0 + z0 * w1 + z0 * w0);
    let err = 40.0 * U * U * (p1.abs() + p2.abs());
    let (hi, lo) = if s < 0.0 { (-s, -tail) } else { (s, tail) };
    (hi > 0.0).then_some(Enclosure { hi, lo, err })
}

/// Are all coordinates finite?
fn finite(points: &[Point]) -> bool {
    points.iter().flatten().all(|v| v.is_finite())
}

/// Are all coordinates zero or within the kernel's range?
fn in_range(points: &[Point]) -> bool {
    points
        .iter()
        .flatten()
        .all(|&v| v == 0.0 || (MIN_COORDINATE..=MAX_COORDINATE).contains(&v.abs()))
}

/// The smallest exponent `e` of the nonzero coordinates `m·2^e`.
fn min_exponent(points: &[Point]) -> i32 {
    points
        .iter()
        .flatten()
        .filter(|&&v| v != 0.0)
        .map(|&v| decompose(v).1)
        .min()
        .unwrap_or(0)
}

/// `|ab|²` as an integer `N` and the exponent `e` with `|ab| = √N · 2^e`.
fn exact_squared_length(a: Point, b: Point) -> (BigUint, i64) {
    let emin = min_exponent(&[a, b]);
    (squared_length_at(a, b, emin), i64::from(emin))
}

/// `|ab|² / 4^emin` as an integer (`emin` at most every coordinate's
/// exponent).
fn squared_length_at(a: Point, b: Point, emin: i32) -> BigUint {
    let d = |k: usize| -> BigInt { scaled(a[k], emin) - scaled(b[k], emin) };
    let (dx, dy) = (d(0), d(1));
    (&dx * &dx + &dy * &dy).magnitude().clone()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn familiar_values_are_exact() {
        assert_eq!(length([0.0, 0.0], [3.0, 4.0]), 5.0);
        assert_eq!(length([1.0, 1.0], [2.0, 2.0]), 2f64.sqrt());
        assert_eq!(length_scaled([0.0, 0.0], [3.0, 4.0], 1), 0.5);
        assert_eq!(length_scaled([0.0, 0.0], [3.0, 4.0], -2), 500.0);
        assert_eq!(area([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]), 0.5);
        assert_eq!(area([0.0, 0.0], [0.0, 1.0], [1.0, 0.0]), 0.5);
        assert_eq!(area_scaled([0.0, 0.0], [10.0, 0.0], [0.0, 10.0], 1), 0.5);
        assert_eq!(area([0.0, 0.0], [1.0, 1.0], [2.0, 2.0]), 0.0);
        assert_eq!(
            angles_deg([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]),
            [90.0, 45.0, 45.0]
        );
        let lengths = [[0.0, 0.0], [3.0, 4.0], [3.0, 0.0]];
        assert_eq!(total_length(&lengths, &[[0, 1], [1, 2], [2, 0]]), 12.0);
        assert_eq!(over_power_of_ten_rounded(3.0, 1, Rounding::Nearest), 0.3);
        // fl(0.3) is below 0.3, fl(0.1) above 0.1.
        assert_eq!(over_power_of_ten_rounded(3.0, 1, Rounding::Down), 0.3);
        assert_eq!(
            over_power_of_ten_rounded(1.0, 1, Rounding::Down),
            0.1f64.next_down()
        );
    }

    #[test]
    fn a_midpoint_length_ties_to_even() {
        // 2^53 + 1 is halfway between two doubles.
        let two53 = 2f64.powi(53);
        assert_eq!(length([-1.0, 0.0], [two53, 0.0]), two53);
        assert_eq!(length([-3.0, 0.0], [two53, 0.0]), two53 + 4.0);
        assert_eq!(total_length(&[[-1.0, 0.0], [two53, 0.0]], &[[0, 1]]), two53);
    }

    #[test]
    fn needles_keep_a_positive_area() {
        // Doubled area 2^-11 from products near 2^41.
        let big = 2f64.powi(40);
        let a = [0.0, 0.0];
        let b = [big, 1.0];
        let c = [2.0 * big, 2.0 + 2f64.powi(-51)];
        let expected = 2f64.powi(-12);
        assert_eq!(area(a, b, c), expected);
        assert!(doubled_area_enclosure(a, b, c)
            .and_then(|e| e.rounded(Rounding::Nearest))
            .is_none());
    }
}
