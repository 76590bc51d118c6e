//! The angle at a corner in degrees, correctly rounded, from the exact cross
//! and dot products of its two rays.
//!
//! The angle is `θ = atan2(|C|, D)` for the cross product `C` and the dot
//! product `D`, both exact integers once the coordinates are scaled by a
//! common power of two (which leaves the angle unchanged). Exact special
//! cases first: a flat corner is 0° or 180°, `D = 0` is 90°, `|C| = |D|` is
//! 45° or 135°. Every other angle is irrational in degrees, so it is never a
//! rounding boundary and Ziv's loop below ends: if `θ/π` were rational,
//! `e^{2iθ} = (D + i|C|)²/(D² + C²)` would be a root of unity in `ℚ(i)`,
//! and the only ones are `±1, ±i` (a primitive `n`-th root of unity has
//! degree `φ(n)` over `ℚ`, and `ℚ(i)` holds the `n`-th roots only for
//! `n ∈ {1, 2, 4}`), so `θ` would be a multiple of 45°: one of the special
//! cases. (This is the tangent case of Niven's theorem: I. Niven,
//! *Irrational Numbers*, Carus Monographs 11, 1956, ch. 3.)
//!
//! There is no floating-point fast path: the accuracy of the platform's
//! `atan2` is unspecified, so no error bound can be derived for it. The
//! reduction `θ = 90°·b ± (180/π)·atan(x)` with `x = min(|C|, |D|) /
//! max(|C|, |D|) < 1` leaves an arctangent in `(0, 1)`, evaluated in
//! fixed-point integer arithmetic by Euler's series
//!
//! ```text
//!   atan(y) = Σₖ tₖ,   t₀ = y/(1 + y²),   tₖ₊₁ = tₖ · (2k + 2)/(2k + 3) · y²/(1 + y²)
//! ```
//!
//! (L. Euler, *Institutiones calculi differentialis*, 1755; every ratio is
//! below ½ for `y < 1`), and `π = 16·atan(1/5) − 4·atan(1/239)` (Machin,
//! 1706) by the same series. The error of every step is bounded in units of
//! the last place ([`atan_fixed`]), the quotient `180·atan(x)/π` is enclosed
//! by interval arithmetic, and the precision doubles until both ends of the
//! enclosure round to the same double. Only the two extreme corners of a
//! triangulation are converted, so the cost (tens of microseconds) does not
//! matter.

use super::length_sums::{decompose, scaled};
use super::rounding::{round_ratio, Rounding};
use super::Point;
use num_bigint::{BigInt, BigUint, Sign};
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// The angle at `o` between the rays to `a` and `b`, in degrees, in
/// `[0°, 180°]`, correctly rounded (0 if `a` or `b` is `o`).
pub(super) fn corner_degrees(o: Point, a: Point, b: Point) -> f64 {
    let (cross, dot) = scaled_cross_dot(o, a, b);
    degrees_of(&cross, &dot)
}

/// Exact: the angle at `o` between the rays to `a` and `b` (in degrees)
/// against `num / den` degrees, for `den > 0`. An angle that is not a
/// multiple of 45° is irrational in degrees (module docs), so it differs
/// from every rational and the loop below, which narrows its enclosure
/// until the rational falls outside, ends.
pub(super) fn compare_corner_with_degrees(
    o: Point,
    a: Point,
    b: Point,
    num: &BigUint,
    den: &BigUint,
) -> Ordering {
    let (c, d) = scaled_cross_dot(o, a, b);
    let whole = |degrees: u32| (BigUint::from(degrees) * den).cmp(num);
    match reduce(&c, &d) {
        Reduced::Exact(degrees) => whole(degrees),
        Reduced::Arctangent {
            n,
            den: atan_den,
            base,
            sign,
        } => {
            let target = BigInt::from_biguint(Sign::Plus, num.clone());
            let den = BigInt::from_biguint(Sign::Plus, den.clone());
            let mut q: u64 = 64;
            loop {
                if let Some([(low_num, low_den), (high_num, high_den)]) =
                    enclosure(n, atan_den, base, sign, q)
                {
                    // Ends are num/den with positive denominators.
                    if low_num * &den > &target * low_den {
                        return Ordering::Greater;
                    }
                    if high_num * &den < &target * high_den {
                        return Ordering::Less;
                    }
                }
                q *= 2;
            }
        }
    }
}

/// The cross product's magnitude and the dot product of `a − o` and `b − o`,
/// as exact integers (every coordinate scaled by the same power of two).
fn scaled_cross_dot(o: Point, a: Point, b: Point) -> (BigUint, BigInt) {
    let coordinates = [o, a, b].into_iter().flatten();
    let emin = coordinates
        .filter(|&v| v != 0.0)
        .map(|v| decompose(v).1)
        .min()
        .unwrap_or(0);
    let d = |p: Point, k: usize| scaled(p[k], emin) - scaled(o[k], emin);
    let (ux, uy, vx, vy) = (d(a, 0), d(a, 1), d(b, 0), d(b, 1));
    let cross = &ux * &vy - &uy * &vx;
    let dot = ux * vx + uy * vy;
    (cross.magnitude().clone(), dot)
}

/// `atan2(c, d)` in degrees for `c ≥ 0`: a multiple of 45°, or an
/// arctangent of a ratio below 1 to evaluate.
enum Reduced<'a> {
    Exact(u32),
    /// `90°·base + sign·(180/π)·atan(n/den)`, with `0 < n < den`.
    Arctangent {
        n: &'a BigUint,
        den: &'a BigUint,
        base: u32,
        sign: i32,
    },
}

/// The reduction of the module docs.
fn reduce<'a>(c: &'a BigUint, d: &'a BigInt) -> Reduced<'a> {
    let m = d.magnitude();
    let forward = d.is_positive();
    if c.is_zero() {
        return Reduced::Exact(if d.is_negative() { 180 } else { 0 });
    }
    if m.is_zero() {
        return Reduced::Exact(90);
    }
    let (n, den, base, sign) = match c.cmp(m) {
        Ordering::Equal => return Reduced::Exact(if forward { 45 } else { 135 }),
        Ordering::Less if forward => (c, m, 0u32, 1),
        Ordering::Less => (c, m, 2, -1),
        Ordering::Greater if forward => (m, c, 1, -1),
        Ordering::Greater => (m, c, 1, 1),
    };
    Reduced::Arctangent { n, den, base, sign }
}

/// `atan2(c, d)` in degrees for `c ≥ 0`, correctly rounded.
fn degrees_of(c: &BigUint, d: &BigInt) -> f64 {
    match reduce(c, d) {
        Reduced::Exact(degrees) => f64::from(degrees),
        Reduced::Arctangent { n, den, base, sign } => {
            let mut q: u64 = 64;
            loop {
                if let Some(v) = enclose_and_round(n, den, base, sign, q) {
                    return v;
                }
                q *= 2;
            }
        }
    }
}

/// One step of Ziv's loop at precision `q`: the enclosure of
/// `90·base + sign·180·atan(n/den)/π` and its rounding if both ends agree.
fn enclose_and_round(n: &BigUint, den: &BigUint, base: u32, sign: i32, q: u64) -> Option<f64> {
    let ends = enclosure(n, den, base, sign, q)?;
    let [low, high] = ends.map(|(num, den)| {
        num.is_positive()
            .then(|| round_ratio(num.magnitude(), den.magnitude(), 0, Rounding::Nearest))
    });
    let (low, high) = (low?, high?);
    (low == high).then_some(low)
}

/// An enclosure `[low, high]` of `90·base + sign·180·atan(n/den)/π` at
/// precision `q`, each end as `(numerator, positive denominator)`; `None`
/// when the precision is too low to bound π and the arctangent away from 0.
fn enclosure(
    n: &BigUint,
    den: &BigUint,
    base: u32,
    sign: i32,
    q: u64,
) -> Option<[(BigInt, BigInt); 2]> {
    // The arctangent at a precision relative to its size (tiny angles of
    // needles need many fractional bits), π at `q` bits.
    let qa = q + den.bits().saturating_sub(n.bits());
    let (a, ea) = atan_fixed(n, den, qa);
    let (p1, e1) = atan_fixed(&BigUint::one(), &BigUint::from(5u32), q);
    let (p2, e2) = atan_fixed(&BigUint::one(), &BigUint::from(239u32), q);
    let int = |v: &BigUint| BigInt::from_biguint(Sign::Plus, v.clone());
    let (a, ea, p1, e1, p2, e2) = (int(&a), int(&ea), int(&p1), int(&e1), int(&p2), int(&e2));
    // π·2^q ∈ [pi_low, pi_high]; atan·2^qa ∈ [a_low, a_high].
    let pi_low: BigInt = 16 * (&p1 - &e1) - 4 * (&p2 + &e2);
    let pi_high: BigInt = 16 * (p1 + e1) - 4 * (p2 - e2);
    let (a_low, a_high) = (&a - &ea, a + ea);
    if !pi_low.is_positive() || a_low.is_negative() {
        return None;
    }
    // value = 90·base + sign·180·(A/2^qa)/(Π/2^q) = num/(Π·2^qa), and the
    // ends pair the smaller A with the larger Π for the lower end when the
    // arctangent is added (and the other way round when subtracted).
    let end = |a: &BigInt, pi: &BigInt| -> (BigInt, BigInt) {
        let num: BigInt = 90 * BigInt::from(base) * pi * (BigInt::one() << qa as usize)
            + sign * 180 * a * (BigInt::one() << q as usize);
        (num, pi << qa as usize)
    };
    Some(if sign > 0 {
        [end(&a_low, &pi_high), end(&a_high, &pi_low)]
    } else {
        [end(&a_high, &pi_low), end(&a_low, &pi_high)]
    })
}

/// `(A, E)` with `|A − 2^q·atan(n/den)| < E`, for `0 ≤ n < den`.
///
/// `X = ⌊n·2^q/den⌋`, and Euler's series is summed for `y = X/2^q` in
/// integers: `T₀ = ⌊X·4^q/(4^q + X²)⌋` and `Tₖ₊₁ = ⌊Tₖ·(2k + 2)·X² /
/// ((2k + 3)(4^q + X²))⌋` until a term is zero. With `τₖ = 2^q·tₖ` and
/// ratios `ρₖ < ½`, each floor loses less than 1, so `|Tₖ − τₖ| < ρ·|Tₖ₋₁
/// − τₖ₋₁| + 1 < 2`; when `T_K = 0`, `τ_K < 2` and the tail `Σ_{j≥K} τⱼ ≤
/// 2τ_K < 4`. So the sum is within `2K + 4` of `2^q·atan(y)`, and `atan`
/// is 1-Lipschitz while `0 ≤ x − y < 2^-q`: `E = 2K + 5`.
fn atan_fixed(n: &BigUint, den: &BigUint, q: u64) -> (BigUint, BigUint) {
    let x = (n << q as usize) / den;
    let square = &x * &x;
    let denominator = (BigUint::one() << (2 * q) as usize) + &square;
    let mut term = (&x << (2 * q) as usize) / &denominator;
    let mut sum = BigUint::zero();
    let mut k = 0u64;
    while !term.is_zero() {
        sum += &term;
        term = &term * &square * (2 * k + 2) / (&denominator * (2 * k + 3));
        k += 1;
    }
    (sum, BigUint::from(2 * k + 5))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn special_corners_are_exact() {
        let o = [0.0, 0.0];
        assert_eq!(corner_degrees(o, [1.0, 0.0], [0.0, 3.0]), 90.0);
        assert_eq!(corner_degrees(o, [1.0, 0.0], [2.0, 2.0]), 45.0);
        assert_eq!(corner_degrees(o, [1.0, 0.0], [-2.0, 2.0]), 135.0);
        assert_eq!(corner_degrees(o, [1.0, 0.0], [5.0, 0.0]), 0.0);
        assert_eq!(corner_degrees(o, [1.0, 0.0], [-5.0, 0.0]), 180.0);
        assert_eq!(corner_degrees(o, o, [1.0, 1.0]), 0.0);
    }

    #[test]
    fn familiar_angles_agree_with_the_library() {
        // 60° is not exact in rationals, but atan(√3) rounds the same way in
        // degrees: compare against values whose last digit is safe.
        let o = [0.0, 0.0];
        let deg = corner_degrees(o, [4.0, 0.0], [4.0, 3.0]);
        assert!((deg - 36.869_897_645_844_02).abs() < 1e-13, "{deg}");
        let deg = corner_degrees(o, [1.0, 0.0], [-1.0, 2.0]);
        assert!((deg - 116.565_051_177_077_99).abs() < 1e-12, "{deg}");
        // The three angles of a triangle sum to 180° up to rounding.
        let (a, b, c) = ([0.0, 0.0], [7.0, 1.0], [2.0, 5.0]);
        let sum = corner_degrees(a, b, c) + corner_degrees(b, c, a) + corner_degrees(c, a, b);
        assert!((sum - 180.0).abs() < 1e-12, "{sum}");
    }

    #[test]
    fn needle_corners_are_tiny_but_positive() {
        let big = 2f64.powi(200);
        let deg = corner_degrees([0.0, 0.0], [big, 0.0], [big, 2f64.powi(-140)]);
        // atan(2^-340) in degrees: 2^-340 · 180/π.
        let expected = 2f64.powi(-340) * (180.0 / std::f64::consts::PI);
        assert!(deg > 0.0 && (deg / expected - 1.0).abs() < 1e-15, "{deg}");
    }
}
