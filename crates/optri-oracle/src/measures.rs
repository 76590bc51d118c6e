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
/// arithmetic-geometric mean inequality), and `q/x` is below it; both are
/// rounded outwards to multiples of `width/4` to keep the numbers (and
/// their sums) small.
fn sqrt_enclosure(q: &BigRational, width: &BigRational) -> (BigRational, BigRational) {
    let grid = width / BigRational::from_integer(BigInt::from(4));
    let up = |x: BigRational| (&x / &grid).ceil() * &grid;
    let down = |x: BigRational| (&x / &grid).floor() * &grid;
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
        let low = down(q / &x);
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

/// The rounding `round` of a real known by rational enclosures: `enclose(j)`
/// is an open interval around it (or a point, when the real is rational)
/// that shrinks as `j` grows; the answer is found once both ends round
/// alike (rounding is monotone).
fn round_enclosed(
    enclose: impl Fn(u32) -> (BigRational, BigRational),
    round: impl Fn(&BigRational) -> f64,
) -> f64 {
    for j in 1.. {
        let (low, high) = enclose(j);
        let (a, b) = (round(&low), round(&high));
        if a == b {
            return a;
        }
    }
    unreachable!()
}

/// `2^-e` as a rational.
fn two_to_minus(e: u32) -> BigRational {
    BigRational::new(BigInt::one(), BigInt::one() << e as usize)
}

/// Enclosures of `Σ √qᵢ`: exact when every `qᵢ` is a rational square (the
/// sum is rational only then: square roots of distinct square-free
/// integers are linearly independent over ℚ and positive terms cannot
/// cancel), else from [`sqrt_enclosure`] with widths `2^-64j` relative.
fn root_sum_enclosure(qs: &[BigRational]) -> impl Fn(u32) -> (BigRational, BigRational) + '_ {
    let roots: Vec<Option<BigRational>> = qs.iter().map(rational_root).collect();
    let scale = qs
        .iter()
        .map(|q| q.to_f64().unwrap_or(0.0).sqrt())
        .sum::<f64>();
    let scale = to_rational(if scale > 0.0 { scale } else { 1.0 });
    move |j| {
        let width = &scale * two_to_minus(64 * j);
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
        (low, high)
    }
}

/// The double nearest to `Σ √qᵢ` (rationals `qᵢ ≥ 0`).
pub fn nearest_root_sum(qs: &[BigRational]) -> f64 {
    round_enclosed(root_sum_enclosure(qs), nearest)
}

/// The largest double not above `Σ √qᵢ`.
pub fn below_root_sum(qs: &[BigRational]) -> f64 {
    round_enclosed(root_sum_enclosure(qs), below)
}

/// `[lo, hi]·2^-p` around `atan(y)` for `y ∈ [y_lo, y_hi]·2^-p ⊆ [0, ½]`:
/// the alternating Taylor series `Σ (−1)ⁿ y^(2n+1)/(2n+1)` with every term
/// bounded below and above in fixed point (floors and ceilings). Its partial
/// sums after an odd (even) count of terms are above (below) the limit, and
/// the bounds keep that. Every value is non-negative, so `/` and `>>` are
/// floors.
fn atan_fixed(y_lo: &BigInt, y_hi: &BigInt, p: u32) -> (BigInt, BigInt) {
    let shift = |v: BigInt| v >> p as usize;
    let ceil_div = |v: &BigInt, d: &BigInt| (v + d - 1) / d;
    let one = BigInt::one() << p as usize;
    let (sq_lo, sq_hi) = (shift(y_lo * y_lo), ceil_div(&(y_hi * y_hi), &one));
    let (mut pow_lo, mut pow_hi) = (y_lo.clone(), y_hi.clone());
    let (mut upper_sum, mut lower_sum) = (BigInt::zero(), BigInt::zero());
    let mut upper = BigInt::zero();
    for n in 0u32.. {
        let d = BigInt::from(2 * n + 1);
        let (t_lo, t_hi) = (&pow_lo / &d, ceil_div(&pow_hi, &d));
        if n % 2 == 0 {
            upper_sum += &t_hi;
            lower_sum += &t_lo;
            upper = upper_sum.clone();
        } else {
            upper_sum -= &t_lo;
            lower_sum -= &t_hi;
            if t_hi.is_zero() || t_hi == BigInt::one() {
                return (lower_sum, upper);
            }
        }
        pow_lo = shift(&pow_lo * &sq_lo);
        pow_hi = ceil_div(&(&pow_hi * &sq_hi), &one);
    }
    unreachable!()
}

/// `atan(x)·2^p` enclosed for a rational `0 ≤ x ≤ 1`, and `π/4 =
/// atan(½) + atan(⅓)` in the same precision; above ½, `atan(x) = π/4 −
/// atan((1 − x)/(1 + x))`.
fn atan_and_quarter_pi(x: &BigRational, p: u32) -> [(BigInt, BigInt); 2] {
    let fixed = |r: &BigRational| {
        let scaled = r * BigRational::from_integer(BigInt::one() << p as usize);
        (scaled.floor().to_integer(), scaled.ceil().to_integer())
    };
    let atan = |r: &BigRational| {
        let (lo, hi) = fixed(r);
        atan_fixed(&lo, &hi, p)
    };
    let (hl, hh) = atan(&BigRational::new(BigInt::one(), BigInt::from(2)));
    let (tl, th) = atan(&BigRational::new(BigInt::one(), BigInt::from(3)));
    let quarter = (hl + tl, hh + th);
    let one = BigRational::one();
    if *x <= BigRational::new(BigInt::one(), BigInt::from(2)) {
        return [atan(x), quarter];
    }
    let (rl, rh) = atan(&((&one - x) / (&one + x)));
    [(&quarter.0 - rh, &quarter.1 - rl), quarter]
}

/// The double nearest to `atan2(c, d)` in degrees for rationals `c ≥ 0`,
/// `d` (0 when both are 0).
pub fn nearest_atan2_degrees(c: &BigRational, d: &BigRational) -> f64 {
    if c.is_zero() {
        return if d.is_negative() { 180.0 } else { 0.0 };
    }
    if d.is_zero() {
        return 90.0;
    }
    if c == &d.abs() {
        return if d.is_positive() { 45.0 } else { 135.0 };
    }
    // θ in degrees = 90·base ± 180·atan(x)/π with x < 1; irrational, so
    // the enclosures eventually round alike.
    let (x, base, sign) = if c < &d.abs() {
        let forward = d.is_positive();
        (
            c / d.abs(),
            if forward { 0 } else { 2 },
            if forward { 1 } else { -1 },
        )
    } else {
        (d.abs() / c, 1, if d.is_positive() { -1 } else { 1 })
    };
    let enclose = |j: u32| {
        let p = 32 << j;
        let [(al, ah), (ql, qh)] = atan_and_quarter_pi(&x, p);
        let ratio = |a: BigInt, q: BigInt| BigRational::new(BigInt::from(45) * a, q);
        // 180·atan/π = 45·atan/(π/4).
        let (vl, vh) = (ratio(al.max(BigInt::zero()), qh), ratio(ah, ql));
        let b = BigRational::from_integer(BigInt::from(90 * base));
        if sign > 0 {
            (&b + vl, b + vh)
        } else {
            (&b - vh, b - vl)
        }
    };
    round_enclosed(enclose, nearest)
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
