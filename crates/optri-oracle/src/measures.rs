//! Correctly rounded measures by exact rational arithmetic, independent of
//! optri's kernel: the reference for its reported lengths, areas, angles
//! and total lengths.
//!
//! A real `x` rounds to the double `c` iff it lies strictly between the
//! midpoints from `c` to its neighbours (or on one, and `c` is even). Every
//! function here takes a candidate from plain floating point and moves it
//! one double at a time until that holds, deciding each side by exact
//! rational comparison: for rationals directly, for square roots by
//! comparing squares, and for sums of square roots and arctangents by
//! rational enclosures that are refined until they exclude the midpoint
//! (square roots by Newton's iteration from above with the quotient as the
//! lower bound; arctangents by the alternating Taylor series, whose partial
//! sums bracket the limit, after reducing to `|y| ≤ ½`; `π/4 = atan(½) +
//! atan(⅓)`). Slow and simple on purpose.

use crate::exact::{squared_length, to_rational, twice_area, Point};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::cmp::Ordering;

/// `10^k` as a rational.
pub fn power_of_ten(k: i32) -> BigRational {
    let p = BigRational::from_integer(BigInt::from(10).pow(k.unsigned_abs()));
    if k >= 0 {
        p
    } else {
        p.recip()
    }
}

/// The midpoints from a positive double `c` to its lower and upper
/// neighbours (above `f64::MAX`, the gap below is repeated).
fn midpoints(c: f64) -> (BigRational, BigRational) {
    let two = BigRational::from_integer(BigInt::from(2));
    let r = to_rational(c);
    let below = to_rational(c.next_down());
    let above = if c < f64::MAX {
        to_rational(c.next_up())
    } else {
        &r + (&r - &below)
    };
    ((&r + below) / &two, (&r + above) / two)
}

/// Is the significand of `c` even?
fn even(c: f64) -> bool {
    c.to_bits() & 1 == 0
}

/// The double nearest to a real `x > 0` (ties to even), given `side(m)`,
/// the exact ordering of `x` against a rational `m`, from the candidate
/// `c`: moves one double at a time towards `x` until `x` lies between the
/// midpoints around `c`.
fn nearest_by(c: f64, side: impl Fn(&BigRational) -> Ordering) -> f64 {
    let tiniest = f64::from_bits(1);
    let mut c = if c.is_nan() {
        1.0
    } else {
        c.clamp(tiniest, f64::MAX)
    };
    loop {
        let (low, high) = midpoints(c);
        match side(&high) {
            Ordering::Greater if c == f64::MAX => return f64::INFINITY,
            Ordering::Greater => {
                c = c.next_up();
                continue;
            }
            Ordering::Equal if even(c) => return c,
            Ordering::Equal if c == f64::MAX => return f64::INFINITY,
            Ordering::Equal => return c.next_up(),
            Ordering::Less => {}
        }
        match side(&low) {
            Ordering::Less if c == tiniest => return 0.0,
            Ordering::Less => c = c.next_down(),
            Ordering::Equal if even(c) => return c,
            Ordering::Equal => return c.next_down(),
            Ordering::Greater => return c,
        }
    }
}

/// The largest double not above a real `x > 0`, given `side` as in
/// [`nearest_by`].
fn below_by(c: f64, side: impl Fn(&BigRational) -> Ordering) -> f64 {
    let mut c = nearest_by(c, &side).min(f64::MAX);
    while c > 0.0 && side(&to_rational(c)) == Ordering::Less {
        c = c.next_down();
    }
    c
}

/// The double nearest to the rational `q ≥ 0` (ties to even).
pub fn nearest(q: &BigRational) -> f64 {
    if q.is_zero() {
        return 0.0;
    }
    nearest_by(q.to_f64().unwrap_or(f64::MAX), |m| q.cmp(m))
}

/// The largest double not above the rational `q ≥ 0`.
pub fn below(q: &BigRational) -> f64 {
    if q.is_zero() {
        return 0.0;
    }
    below_by(q.to_f64().unwrap_or(f64::MAX), |m| q.cmp(m))
}

/// The double nearest to `√q` for a rational `q ≥ 0`: `√q` against `m ≥ 0`
/// is `q` against `m²`.
pub fn nearest_sqrt(q: &BigRational) -> f64 {
    if q.is_zero() {
        return 0.0;
    }
    let candidate = q.to_f64().unwrap_or(f64::MAX).sqrt();
    nearest_by(candidate, |m| q.cmp(&(m * m)))
}

/// A rational enclosure `[low, high]` of `√q` (`q > 0`) narrower than
/// `width`: Newton's step `x ↦ (x + q/x)/2` stays above `√q` (the
/// arithmetic-geometric mean inequality), and `q/x` is below it; each
/// iterate is rounded up to a multiple of `width/4` to keep the numbers
/// small (rounding up keeps it above `√q`).
fn sqrt_enclosure(q: &BigRational, width: &BigRational) -> (BigRational, BigRational) {
    let grid = width / BigRational::from_integer(BigInt::from(4));
    let up = |x: BigRational| (&x / &grid).ceil() * &grid;
    let two = BigRational::from_integer(BigInt::from(2));
    // One Newton step from any positive guess is above √q.
    let guess = q.to_f64().map_or(1.0, f64::sqrt);
    let guess = if guess > 0.0 && guess.is_finite() {
        to_rational(guess)
    } else {
        BigRational::one()
    };
    let mut x = up((q / &guess + guess) / &two);
    loop {
        let low = q / &x;
        if &x - &low < *width {
            return (low, x);
        }
        x = up((&x + &low) / &two);
    }
}

/// Is `q ≥ 0` the square of a rational? Then its root.
fn rational_root(q: &BigRational) -> Option<BigRational> {
    let (n, d) = (q.numer().sqrt(), q.denom().sqrt());
    (&n * &n == *q.numer() && &d * &d == *q.denom()).then(|| BigRational::new(n, d))
}

/// `Σ √qᵢ` against a rational `m`, exactly: the sum is rational only when
/// every `qᵢ` is a rational square (square roots of distinct square-free
/// integers are linearly independent over ℚ, and positive terms cannot
/// cancel); otherwise enclosures are narrowed until they exclude `m`.
fn root_sum_side(qs: &[BigRational], m: &BigRational) -> Ordering {
    let roots: Vec<Option<BigRational>> = qs.iter().map(rational_root).collect();
    if roots.iter().all(Option::is_some) {
        let sum: BigRational = roots.into_iter().flatten().sum();
        return sum.cmp(m);
    }
    let mut width = BigRational::new(BigInt::one(), BigInt::from(1u64 << 40));
    loop {
        let (mut low, mut high) = (BigRational::zero(), BigRational::zero());
        for (q, root) in qs.iter().zip(&roots) {
            match root {
                Some(r) => {
                    low += r;
                    high += r;
                }
                None => {
                    let (l, h) = sqrt_enclosure(q, &width);
                    low += l;
                    high += h;
                }
            }
        }
        if &low > m {
            return Ordering::Greater;
        }
        if &high < m {
            return Ordering::Less;
        }
        width = &width * &width;
    }
}

/// The double nearest to `Σ √qᵢ` (rationals `qᵢ ≥ 0`, not all zero).
pub fn nearest_root_sum(qs: &[BigRational]) -> f64 {
    let candidate: f64 = qs.iter().map(|q| q.to_f64().unwrap_or(0.0).sqrt()).sum();
    nearest_by(candidate, |m| root_sum_side(qs, m))
}

/// The largest double not above `Σ √qᵢ`.
pub fn below_root_sum(qs: &[BigRational]) -> f64 {
    let candidate: f64 = qs.iter().map(|q| q.to_f64().unwrap_or(0.0).sqrt()).sum();
    below_by(candidate, |m| root_sum_side(qs, m))
}

/// Partial sums of `atan(y) = Σ (−1)ⁿ y^(2n+1)/(2n+1)` for `0 ≤ y ≤ ½`
/// after an even and an odd number of terms, so that they bracket the
/// limit, with the last term below `width`.
fn atan_enclosure(y: &BigRational, width: &BigRational) -> (BigRational, BigRational) {
    let y2 = y * y;
    let mut power = y.clone();
    let mut sum = BigRational::zero();
    let mut n: i64 = 0;
    loop {
        let term = &power / BigRational::from_integer(BigInt::from(2 * n + 1));
        let next = if n % 2 == 0 {
            &sum + &term
        } else {
            &sum - &term
        };
        if &term < width && n % 2 == 1 {
            // `sum` (after an odd count of terms) is above, `next` below.
            return (next, sum);
        }
        sum = next;
        power = &power * &y2;
        n += 1;
    }
}

/// An enclosure of `atan(x)` for rational `0 ≤ x ≤ 1`, with `π/4` in the
/// same precision: `atan(x) = π/4 − atan((1 − x)/(1 + x))` above ½.
fn atan_unit(x: &BigRational, width: &BigRational) -> (BigRational, BigRational) {
    let half = BigRational::new(BigInt::one(), BigInt::from(2));
    if *x <= half {
        return atan_enclosure(x, width);
    }
    let (ql, qh) = quarter_pi(width);
    let one = BigRational::one();
    let (rl, rh) = atan_enclosure(&((&one - x) / (&one + x)), width);
    (ql - rh, qh - rl)
}

/// `π/4 = atan(½) + atan(⅓)`, enclosed.
fn quarter_pi(width: &BigRational) -> (BigRational, BigRational) {
    let (al, ah) = atan_enclosure(&BigRational::new(BigInt::one(), BigInt::from(2)), width);
    let (bl, bh) = atan_enclosure(&BigRational::new(BigInt::one(), BigInt::from(3)), width);
    (al + bl, ah + bh)
}

/// The double nearest to `atan2(c, d)` in degrees for rationals `c ≥ 0`,
/// `d` (0 when both are 0).
pub fn nearest_atan2_degrees(c: &BigRational, d: &BigRational) -> f64 {
    let ninety = BigRational::from_integer(BigInt::from(90));
    if c.is_zero() {
        return if d.is_negative() { 180.0 } else { 0.0 };
    }
    if d.is_zero() {
        return 90.0;
    }
    if c == &d.abs() {
        return if d.is_positive() { 45.0 } else { 135.0 };
    }
    let as_f64 = |v: &BigRational| v.to_f64().unwrap_or(f64::MAX);
    let candidate = as_f64(c).atan2(as_f64(d)).to_degrees();
    // θ in degrees = base·90 ± 180·atan(x)/π with x < 1.
    let (x, base, sign) = if c < &d.abs() {
        (
            c / d.abs(),
            if d.is_positive() { 0 } else { 2 },
            if d.is_positive() { 1 } else { -1 },
        )
    } else {
        (d.abs() / c, 1, if d.is_positive() { -1 } else { 1 })
    };
    let side = |m: &BigRational| -> Ordering {
        // Enclose the angle until the enclosure excludes m (it is
        // irrational: never equal to a midpoint).
        let mut width = BigRational::new(BigInt::one(), BigInt::from(1u64 << 40));
        loop {
            let (al, ah) = atan_unit(&x, &width);
            let (ql, qh) = quarter_pi(&width);
            // 180·atan/π = 45·atan/(π/4).
            let f = BigRational::from_integer(BigInt::from(45));
            let (vl, vh) = (&f * &al / &qh, &f * &ah / &ql);
            let b = &ninety * BigRational::from_integer(BigInt::from(base));
            let (low, high) = if sign > 0 {
                (&b + vl, &b + vh)
            } else {
                (&b - vh, &b - vl)
            };
            if &low > m {
                return Ordering::Greater;
            }
            if &high < m {
                return Ordering::Less;
            }
            width = &width * &width;
        }
    };
    nearest_by(candidate, side)
}

/// `|ab| / 10^k`, correctly rounded.
pub fn length(a: Point, b: Point, k: i32) -> f64 {
    nearest_sqrt(&(squared_length(a, b) * power_of_ten(-2 * k)))
}

/// The area of `abc` divided by `10^2k`, correctly rounded.
pub fn area(a: Point, b: Point, c: Point, k: i32) -> f64 {
    nearest(&(twice_area(a, b, c) * power_of_ten(-2 * k) / BigRational::from_integer(2.into())))
}

/// The total length of `segments` divided by `10^k`, correctly rounded
/// (`down`: the largest double not above it).
pub fn total_length(segments: &[[Point; 2]], k: i32, down: bool) -> f64 {
    let scale = power_of_ten(-2 * k);
    let qs: Vec<BigRational> = segments
        .iter()
        .map(|&[a, b]| squared_length(a, b) * &scale)
        .collect();
    if down {
        below_root_sum(&qs)
    } else {
        nearest_root_sum(&qs)
    }
}

/// The angle at `o` between the rays to `a` and `b`, in degrees, correctly
/// rounded.
pub fn angle_degrees(o: Point, a: Point, b: Point) -> f64 {
    let r = |p: Point| {
        [
            to_rational(p[0]) - to_rational(o[0]),
            to_rational(p[1]) - to_rational(o[1]),
        ]
    };
    let (u, v) = (r(a), r(b));
    let cross = &u[0] * &v[1] - &u[1] * &v[0];
    let dot = &u[0] * &v[0] + &u[1] * &v[1];
    nearest_atan2_degrees(&cross.abs(), &dot)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(BigInt::from(n), BigInt::from(d))
    }

    #[test]
    fn rationals_and_roots_round_correctly() {
        assert_eq!(nearest(&q(1, 10)), 0.1);
        assert_eq!(nearest(&q(2, 3)), 2.0 / 3.0);
        assert_eq!(below(&q(1, 10)), 0.1f64.next_down());
        let two53 = BigRational::from_integer(BigInt::from(1u64 << 53));
        assert_eq!(nearest(&(&two53 + q(1, 1))), 2f64.powi(53));
        assert_eq!(nearest(&(&two53 + q(3, 1))), 2f64.powi(53) + 4.0);
        assert_eq!(nearest_sqrt(&q(2, 1)), 2f64.sqrt());
        assert_eq!(nearest_sqrt(&q(9, 4)), 1.5);
        assert_eq!(nearest_root_sum(&[q(2, 1), q(8, 1)]), 18f64.sqrt());
        assert_eq!(below_root_sum(&[q(2, 1)]), 2f64.sqrt().next_down());
        assert_eq!(nearest_root_sum(&[q(9, 1), q(16, 1)]), 7.0);
    }

    #[test]
    fn angles_round_correctly() {
        let o = [0.0, 0.0];
        assert_eq!(angle_degrees(o, [1.0, 0.0], [0.0, 1.0]), 90.0);
        assert_eq!(angle_degrees(o, [1.0, 0.0], [1.0, 1.0]), 45.0);
        let a = angle_degrees(o, [4.0, 0.0], [4.0, 3.0]);
        assert!((a - 36.869_897_645_844_02).abs() < 1e-13, "{a}");
        let a = angle_degrees(o, [1.0, 0.0], [-1.0, 2.0]);
        assert!((a - 116.565_051_177_077_99).abs() < 1e-12, "{a}");
    }
}
