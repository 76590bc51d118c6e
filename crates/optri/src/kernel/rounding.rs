//! Rounding a real number to `f64` once, correctly: the machinery behind
//! the reported measures ([`super::metrics`]).
//!
//! A measure is a real number `x` (a square root, a sum of square roots, a
//! rational, an arctangent) and its report is the double nearest to `x`
//! (ties to even), or for a certified lower bound the largest double not
//! above `x`. Following Ziv's strategy (A. Ziv, *Fast evaluation of
//! elementary functions with guaranteed precision of the floating-point
//! arithmetic*, ACM TOMS 17(3), 1991), the value is first enclosed cheaply
//! and rounded only if the whole enclosure rounds to one double; otherwise
//! it is enclosed again with more precision, or computed exactly.
//!
//! * [`Enclosure`] is the fast path: `x` within a derived bound `err` of a
//!   double-double `hi + lo`. Its rounding is certain when the enclosure
//!   stays strictly between the two rounding boundaries around the candidate
//!   (the midpoints to its neighbours for the nearest double, the double
//!   itself and its successor for the one below). The bound is about `u²·x`
//!   (`u = 2⁻⁵³`) and a boundary is `u·x` away at best, so this fails only
//!   for values within about `u²` (relative) of a boundary.
//! * [`round_ratio`] rounds an exact rational `num/den · 2^e` with integer
//!   division: the exact path of areas and of everything whose value is
//!   rational.
//! * [`round_root_sum`] rounds `Σ √Nᵢ · 2^e / 10^k` for integers `Nᵢ`: exact
//!   integer square roots at a precision that doubles until the enclosure
//!   rounds to one double (Ziv's loop). It terminates: a sum of square
//!   roots of non-squares is irrational (Besicovitch 1940: square roots of
//!   distinct square-free integers are linearly independent over ℚ, and the
//!   coefficients of a sum of positive terms cannot cancel), so it is
//!   neither a midpoint nor a double, and when every `Nᵢ` is a perfect
//!   square the sum is computed exactly.

use super::expansion::two_sum;
use num_bigint::BigUint;
use num_traits::{One, Zero};
use std::cmp::Ordering;

/// Unit roundoff of `f64` (2⁻⁵³).
pub(super) const U: f64 = f64::EPSILON * 0.5;

/// Which double a measure reports.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Rounding {
    /// The nearest double (ties to the one with an even significand).
    Nearest,
    /// The largest double not above the value (for certified lower bounds).
    #[cfg_attr(not(any(feature = "io", feature = "internals")), allow(dead_code))]
    Down,
}

/// Values between these (2⁻⁷⁰⁰ and 2⁷⁰⁰) keep every operation of the fast
/// path far from underflow (error terms near `2⁻¹⁰⁶` times the value must
/// be normal) and from overflow; outside, the exact path decides.
const SAFE_MIN: f64 = f64::from_bits((1023 - 700) << 52);
const SAFE_MAX: f64 = f64::from_bits((1023 + 700) << 52);

/// A nonzero low part below this (2⁻⁹⁰⁰) may have lost bits to underflow in
/// [`Enclosure::over_power_of_ten`]; that step then defers to the exact
/// path.
const TINY: f64 = f64::from_bits((1023 - 900) << 52);

/// A positive real known to lie within `err` of `hi + lo`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Enclosure {
    pub hi: f64,
    pub lo: f64,
    pub err: f64,
}

impl Enclosure {
    /// The rounded value, if every real of the enclosure rounds to it.
    ///
    /// With `(v, w) = two_sum(hi, lo)` (so `v + w = hi + lo` exactly) the
    /// reals are `v + w ± err`. The nearest double of all is `v` iff
    /// `w + err < g⁺/2` and `w − err > −g⁻/2`, with `g⁺ = succ(v) − v` and
    /// `g⁻ = v − pred(v)` (both exact, by Sterbenz's lemma, and powers of
    /// two, so halving is exact). The largest double below all is `v` iff
    /// `w − err ≥ 0` and `w + err < g⁺`, or `pred(v)` iff `w + err < 0` and
    /// `w − err > −g⁻`. Each test evaluates one rounded sum against a
    /// double: rounding is monotone and fixes doubles, so a rounded sum on
    /// the strict side of a double is an exact sum on that side (and a
    /// nonzero difference of doubles never rounds to zero, so `≥ 0` holds
    /// too). Strict comparisons leave an exact tie to the exact path.
    pub fn rounded(self, mode: Rounding) -> Option<f64> {
        let (v, w) = two_sum(self.hi, self.lo);
        if !(SAFE_MIN..=SAFE_MAX).contains(&v) || self.err.is_nan() || self.err < 0.0 {
            return None;
        }
        let (up, down) = (v.next_up() - v, v - v.next_down());
        let (above, below) = (w + self.err, w - self.err);
        match mode {
            Rounding::Nearest => (above < 0.5 * up && below > -0.5 * down).then_some(v),
            Rounding::Down if below >= 0.0 && above < up => Some(v),
            Rounding::Down if above < 0.0 && below > -down => Some(v.next_down()),
            Rounding::Down => None,
        }
    }

    /// The enclosure of the value divided by `10^k` (`k < 0` multiplies),
    /// in steps by exact powers `P = 10^j ≤ 10²²` (`5^j < 2⁵³`), or `None`
    /// where an intermediate would leave the safe range.
    ///
    /// Division: `q₁ = fl(h/P)`, `r = h − q₁P` exactly (fused multiply-add;
    /// the remainder of a correctly rounded quotient is a double), so
    /// `(h + l)/P = q₁ + (r + l)/P`, and `q₂ = fl(fl(r + l)/P)` is within
    /// `u|fl(r + l)|/P + u|q₂| ≤ 2.0001u|q₂|` of `(r + l)/P`: the new bound is
    /// `err/P + 2.0001u|q₂|`, computed as `(err/P)(1 + 4u) + 3u|q₂|`, which
    /// exceeds it despite the three roundings of its own evaluation.
    /// Multiplication: `p₁ = fl(hP)`, `e = hP − p₁` exactly, `(h + l)P =
    /// p₁ + e + lP`, and `p₂ = fl(e + fl(lP))` is within `u|lP|(1 + u) +
    /// u|p₂|` of `e + lP`: the bound `errP(1 + 4u) + 2u(|fl(lP)| + |p₂|)`
    /// covers it the same way. `(q₁, q₂)` is renormalized by `two_sum`
    /// (exact) after each step. These relative bounds hold while no result
    /// is subnormal: `h` stays within the safe range, and a nonzero low
    /// part below 2⁻⁹⁰⁰ (which could have underflowed) gives up.
    pub fn over_power_of_ten(self, k: i32) -> Option<Enclosure> {
        let mut e = self;
        let mut left = k.unsigned_abs();
        while left > 0 {
            let j = left.min(22);
            left -= j;
            let p = 10f64.powi(j as i32); // exact: 5^j < 2^53
            if e.lo != 0.0 && e.lo.abs() < TINY {
                return None;
            }
            let (hi, lo, err) = if k > 0 {
                let q1 = e.hi / p;
                let r = (-q1).mul_add(p, e.hi);
                let n = r + e.lo;
                let q2 = n / p;
                if n != 0.0 && q2.abs() < TINY {
                    return None;
                }
                (q1, q2, e.err / p * (1.0 + 4.0 * U) + 3.0 * U * q2.abs())
            } else {
                let p1 = e.hi * p;
                let r = e.hi.mul_add(p, -p1);
                let lp = e.lo * p;
                let p2 = r + lp;
                (
                    p1,
                    p2,
                    e.err * p * (1.0 + 4.0 * U) + 2.0 * U * (lp.abs() + p2.abs()),
                )
            };
            if !(SAFE_MIN..=SAFE_MAX).contains(&hi.abs()) {
                return None;
            }
            let (hi, lo) = two_sum(hi, lo);
            e = Enclosure { hi, lo, err };
        }
        Some(e)
    }
}

/// `num/den · 2^exp2` rounded to `f64` (`num`, `den > 0`; zero gives 0),
/// exactly, subnormal and overflowing results included.
///
/// The significand is the integer quotient `m = ⌊num·2^s/den⌋` with `s`
/// chosen so that `2⁵² ≤ m < 2⁵³` (or `s = 1074` for subnormal results),
/// and the remainder decides the rounding: up when twice it exceeds `den`,
/// or equals it and `m` is odd.
pub(super) fn round_ratio(num: &BigUint, den: &BigUint, exp2: i64, mode: Rounding) -> f64 {
    if num.is_zero() {
        return 0.0;
    }
    // num/den ∈ [2^(b−1), 2^(b+1)) for b = bits(num) − bits(den).
    let b = num.bits() as i64 - den.bits() as i64 + exp2;
    let mut s = (53 - b).min(1074);
    let (mut m, remainder) = loop {
        let shift = s + exp2;
        let (n, d) = if shift >= 0 {
            (num << shift as usize, den.clone())
        } else {
            (num.clone(), den << (-shift) as usize)
        };
        let m = &n / &d;
        if m.bits() > 53 {
            s -= 1;
            continue;
        }
        let twice_remainder = (&n - &m * &d) << 1usize;
        break (m, twice_remainder.cmp(&d));
    };
    let odd = m.bit(0);
    if mode == Rounding::Nearest
        && (remainder == Ordering::Greater || (remainder == Ordering::Equal && odd))
    {
        m += 1u32;
    }
    let mut m: u64 = m.try_into().expect("a significand of at most 54 bits");
    if m == 1 << 53 {
        m >>= 1;
        s -= 1;
    }
    if m < 1 << 52 {
        // Only with s = 1074: a subnormal (or zero after rounding down).
        return f64::from_bits(m);
    }
    let biased = 1075 - s;
    if biased >= 2047 {
        return match mode {
            Rounding::Nearest => f64::INFINITY,
            Rounding::Down => f64::MAX,
        };
    }
    f64::from_bits(((biased as u64) << 52) | (m - (1 << 52)))
}

/// `num/den · 2^exp2 / 10^k` as a fraction `num'/den' · 2^exp2'` of
/// integers (`10^k = 5^k · 2^k`).
pub(super) fn over_power_of_ten(
    num: BigUint,
    den: BigUint,
    exp2: i64,
    k: i32,
) -> (BigUint, BigUint, i64) {
    let five = BigUint::from(5u32).pow(k.unsigned_abs());
    if k >= 0 {
        (num, den * five, exp2 - i64::from(k))
    } else {
        (num * five, den, exp2 - i64::from(k))
    }
}

/// `Σ √Nᵢ · 2^exp2 / 10^k` rounded to `f64`, for the `count` integers
/// `radicand(i)` (each called once per precision tried).
///
/// At precision `q`, `⌊√(Nᵢ·4^q)⌋` is `2^q√Nᵢ` exactly for a perfect square
/// and otherwise lies strictly within one of it, so the sum lies in the open
/// interval `(S, S + j)·2^-q` for `j` inexact terms; its ends are rounded by
/// [`round_ratio`] and agree once `q` is large enough (see the module docs
/// for why that happens). When every term is exact the sum is rounded
/// exactly.
pub(super) fn round_root_sum(
    count: usize,
    radicand: impl Fn(usize) -> BigUint,
    exp2: i64,
    k: i32,
    mode: Rounding,
) -> f64 {
    let mut q: u64 = 64;
    loop {
        let mut low = BigUint::zero();
        let mut inexact = 0u64;
        for i in 0..count {
            let scaled = radicand(i) << (2 * q) as usize;
            let root = scaled.sqrt();
            if &root * &root != scaled {
                inexact += 1;
            }
            low += root;
        }
        let round = |n: BigUint| {
            let (n, d, e) = over_power_of_ten(n, BigUint::one(), exp2 - q as i64, k);
            round_ratio(&n, &d, e, mode)
        };
        if inexact == 0 {
            return round(low);
        }
        let high = &low + inexact;
        let (a, b) = (round(low), round(high));
        if a == b {
            return a;
        }
        q *= 2;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn big(v: u64) -> BigUint {
        BigUint::from(v)
    }

    #[test]
    fn ratios_round_to_nearest_even_and_down() {
        let n = Rounding::Nearest;
        assert_eq!(round_ratio(&big(1), &big(3), 0, n), 1.0 / 3.0);
        assert_eq!(round_ratio(&big(2), &big(3), 0, n), 2.0 / 3.0);
        assert_eq!(round_ratio(&big(1), &big(10), 0, n), 0.1);
        assert_eq!(round_ratio(&big(7), &big(1), -3, n), 0.875);
        // 2^53 + 1 is a midpoint: ties to the even 2^53; 2^53 + 3 to 2^53 + 4.
        let two53 = 1u64 << 53;
        assert_eq!(round_ratio(&big(two53 + 1), &big(1), 0, n), two53 as f64);
        assert_eq!(
            round_ratio(&big(two53 + 3), &big(1), 0, n),
            (two53 + 4) as f64
        );
        assert_eq!(
            round_ratio(&big(two53 + 3), &big(1), 0, Rounding::Down),
            (two53 + 2) as f64
        );
        // Just above a midpoint rounds up.
        let above = (big(two53 + 1) << 10usize) + 1u32;
        assert_eq!(round_ratio(&above, &big(1), -10, n), (two53 + 2) as f64);
        assert_eq!(round_ratio(&big(1), &big(3), 0, Rounding::Down), 1.0 / 3.0);
        // fl(2/3) is below 2/3, fl(0.1) above 0.1.
        assert_eq!(round_ratio(&big(2), &big(3), 0, Rounding::Down), 2.0 / 3.0);
        assert_eq!(
            round_ratio(&big(1), &big(10), 0, Rounding::Down),
            0.1f64.next_down()
        );
        // Subnormal, the smallest normal, overflow.
        assert_eq!(round_ratio(&big(3), &big(1), -1075, n), 2.0 * 5e-324);
        assert_eq!(round_ratio(&big(1), &big(1), -1022, n), f64::MIN_POSITIVE);
        assert_eq!(round_ratio(&big(1), &big(1), 1024, n), f64::INFINITY);
        assert_eq!(
            round_ratio(&big(1), &big(1), 1024, Rounding::Down),
            f64::MAX
        );
        assert_eq!(round_ratio(&big(0), &big(7), 5, n), 0.0);
    }

    #[test]
    fn enclosures_round_only_when_certain() {
        let n = Rounding::Nearest;
        let e = |hi, lo, err| Enclosure { hi, lo, err };
        assert_eq!(e(1.0, 1e-20, 1e-25).rounded(n), Some(1.0));
        // A quarter ulp above 1 rounds to 1; within err of the midpoint not.
        let half = 0.5 * (1f64.next_up() - 1.0);
        assert_eq!(e(1.0, half * 0.5, 1e-30).rounded(n), Some(1.0));
        assert_eq!(e(1.0, half, 1e-40).rounded(n), None);
        assert_eq!(e(1.0, half * 0.999_999, half * 0.01).rounded(n), None);
        // Below a power of two the gap halves.
        assert_eq!(
            e(1.0, -half * 0.75, 1e-30).rounded(n),
            Some(1f64.next_down())
        );
        assert_eq!(e(1.0, -half * 0.25, 1e-30).rounded(n), Some(1.0));
        // Rounding down.
        let d = Rounding::Down;
        assert_eq!(e(1.0, 1e-20, 1e-25).rounded(d), Some(1.0));
        assert_eq!(e(1.0, -1e-20, 1e-25).rounded(d), Some(1f64.next_down()));
        assert_eq!(e(1.0, 1e-20, 2e-20).rounded(d), None);
        assert_eq!(e(1.0, 0.0, 0.0).rounded(d), Some(1.0));
    }

    #[test]
    fn scaling_by_powers_of_ten_keeps_the_value_enclosed() {
        // 1/3 ± 0 over 10^k against the exact ratio, for k across steps.
        let third = Enclosure {
            hi: 1.0 / 3.0,
            lo: 0.0,
            err: 0.0,
        };
        for k in [-40, -23, -22, -1, 1, 15, 22, 23, 45] {
            let s = third.over_power_of_ten(k).unwrap();
            let (n, d, e) = over_power_of_ten(big(6004799503160661), big(1), -54, k);
            let exact = round_ratio(&n, &d, e, Rounding::Nearest);
            if let Some(v) = s.rounded(Rounding::Nearest) {
                assert_eq!(v, exact, "k = {k}");
            }
            assert!(s.err > 0.0 && s.err < 1e-30 * s.hi, "k = {k}");
        }
    }

    #[test]
    fn root_sums_round_exactly() {
        let n = Rounding::Nearest;
        // √2 + √8 = 3√2 = √18 (3·fl(√2) is one ulp off).
        let sum = round_root_sum(2, |i| big([2, 8][i]), 0, 0, n);
        assert_eq!(sum, 18f64.sqrt());
        assert_ne!(sum, 3.0 * 2f64.sqrt());
        // Perfect squares: exact, a midpoint ties to even.
        let two53 = 1u64 << 53;
        let sq = |v: u64| big(v) * big(v);
        assert_eq!(round_root_sum(1, |_| sq(two53 + 1), 0, 0, n), two53 as f64);
        assert_eq!(
            round_root_sum(2, |i| [sq(two53), sq(1)][i].clone(), 0, 0, n),
            two53 as f64
        );
        // √2 / 10 and rounded down.
        assert_eq!(round_root_sum(1, |_| big(200), 0, 1, n), 2f64.sqrt());
        // fl(√2) is above √2.
        assert_eq!(
            round_root_sum(1, |_| big(2), 0, 0, Rounding::Down),
            2f64.sqrt().next_down()
        );
        assert_eq!(round_root_sum(1, |_| big(9), -2, -1, n), 7.5);
    }
}
