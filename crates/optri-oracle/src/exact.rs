//! Exact arithmetic on `f64` coordinates, independent of optri's kernel.
//!
//! Every finite `f64` is `m · 2^e` with an integer `m`. Multiplying all values
//! of one predicate by `2^-e_min` (a positive power of two, which preserves
//! every sign and scales every value by a known factor) turns them into
//! integers. When those integers are small enough that the polynomial cannot
//! overflow, the predicate runs in `i128`; otherwise in `BigInt`. Nothing is
//! ever rounded.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Float, One, Signed, Zero};
use std::cmp::Ordering;

/// A point in the plane.
pub type Point = [f64; 2];

/// Integer arithmetic used by the predicates: `i128` (fast path) or `BigInt`.
pub(crate) trait Ring: Clone + Ord + Signed {}
impl Ring for i128 {}
impl Ring for BigInt {}

/// Values scaled by a common power of two to exact integers.
pub(crate) enum Scaled {
    Small(Vec<i128>),
    Big(Vec<BigInt>),
}

/// Scales `values` by `2^-e_min` to integers. Returns the integers and
/// `e_min` (value = integer · 2^e_min). Uses `i128` when every integer has at
/// most `small_bits` bits.
///
/// # Panics
/// On a non-finite value.
pub(crate) fn scale(values: &[f64], small_bits: u32) -> (Scaled, i32) {
    let decoded: Vec<(u64, i32, i8)> = values
        .iter()
        .map(|v| {
            assert!(v.is_finite(), "optri-oracle: non-finite coordinate {v}");
            let (m, e, s) = v.integer_decode();
            // Strip trailing zero bits, so that e.g. integers scale to
            // themselves and stay on the fast path.
            let tz = if m == 0 { 0 } else { m.trailing_zeros() };
            (m >> tz, e as i32 + tz as i32, s)
        })
        .collect();
    let e_min = decoded
        .iter()
        .filter(|d| d.0 != 0)
        .map(|d| d.1)
        .min()
        .unwrap_or(0);
    let max_bits = decoded
        .iter()
        .filter(|d| d.0 != 0)
        .map(|d| (64 - d.0.leading_zeros()) as i32 + d.1 - e_min)
        .max()
        .unwrap_or(0);
    let scaled = if max_bits <= small_bits as i32 {
        Scaled::Small(
            decoded
                .iter()
                .map(|&(m, e, s)| {
                    if m == 0 {
                        0
                    } else {
                        let v = (m as i128) << (e - e_min) as u32;
                        if s < 0 {
                            -v
                        } else {
                            v
                        }
                    }
                })
                .collect(),
        )
    } else {
        Scaled::Big(
            decoded
                .iter()
                .map(|&(m, e, s)| {
                    if m == 0 {
                        BigInt::zero()
                    } else {
                        let v = BigInt::from(m) << (e - e_min) as usize;
                        if s < 0 {
                            -v
                        } else {
                            v
                        }
                    }
                })
                .collect(),
        )
    };
    (scaled, e_min)
}

/// `2^e` as an exact rational.
pub(crate) fn pow2(e: i32) -> BigRational {
    if e >= 0 {
        BigRational::from_integer(BigInt::one() << e as usize)
    } else {
        BigRational::new(BigInt::one(), BigInt::one() << (-e) as usize)
    }
}

/// The exact value of a finite `f64`, by this module's decomposition.
pub fn to_rational(v: f64) -> BigRational {
    let (s, e) = scale(&[v], 0);
    let m = match s {
        Scaled::Small(v) => BigInt::from(v[0]),
        Scaled::Big(v) => v[0].clone(),
    };
    BigRational::from_integer(m) * pow2(e)
}

/// An exact rational rounded to `f64` (for reporting and tolerance checks).
pub fn rational_to_f64(r: &BigRational) -> f64 {
    use num_traits::ToPrimitive;
    r.to_f64().expect("rational within f64 range")
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

/// `(q − p) × (r − p)` for `c = [px, py, qx, qy, rx, ry]`.
pub(crate) fn cross<T: Ring>(c: &[T]) -> T {
    let [px, py, qx, qy, rx, ry] = [0, 1, 2, 3, 4, 5].map(|i| c[i].clone());
    (qx - px.clone()) * (ry - py.clone()) - (qy - py) * (rx - px)
}

/// `(q − p) · (r − p)` for `c = [px, py, qx, qy, rx, ry]`.
pub(crate) fn dot<T: Ring>(c: &[T]) -> T {
    let [px, py, qx, qy, rx, ry] = [0, 1, 2, 3, 4, 5].map(|i| c[i].clone());
    (qx - px.clone()) * (rx - px) + (qy - py.clone()) * (ry - py)
}

/// `|pq|²` for `c = [px, py, qx, qy]`.
pub(crate) fn dist2<T: Ring>(c: &[T]) -> T {
    let dx = c[2].clone() - c[0].clone();
    let dy = c[3].clone() - c[1].clone();
    dx.clone() * dx + dy.clone() * dy
}

/// In-circle determinant for `c = [a, b, c, d]` flattened: positive iff `d`
/// is strictly inside the circle through counter-clockwise `a, b, c`.
fn incircle_det<T: Ring>(c: &[T]) -> T {
    let d = |i: usize| {
        (
            c[2 * i].clone() - c[6].clone(),
            c[2 * i + 1].clone() - c[7].clone(),
        )
    };
    let (ax, ay) = d(0);
    let (bx, by) = d(1);
    let (cx, cy) = d(2);
    let la = ax.clone() * ax.clone() + ay.clone() * ay.clone();
    let lb = bx.clone() * bx.clone() + by.clone() * by.clone();
    let lc = cx.clone() * cx.clone() + cy.clone() * cy.clone();
    la * (bx.clone() * cy.clone() - by.clone() * cx.clone())
        - lb * (ax.clone() * cy - ay.clone() * cx)
        + lc * (ax * by - ay * bx)
}

fn flat(points: &[Point]) -> Vec<f64> {
    points.iter().flat_map(|p| [p[0], p[1]]).collect()
}

/// Runs `$f` on the exactly scaled integers of `$values` (i128 if they have at
/// most `$bits` bits, else BigInt); evaluates to `($f(ints), e_min)`.
macro_rules! on_scaled {
    ($values:expr, $bits:expr, $f:ident) => {{
        let (s, e) = scale($values, $bits);
        match s {
            Scaled::Small(v) => ($f(&v), e),
            Scaled::Big(v) => ($f(&v), e),
        }
    }};
}

/// Exact orientation: `1` if `p, q, r` turn counter-clockwise, `-1` if
/// clockwise, `0` if collinear.
pub fn orient(p: Point, q: Point, r: Point) -> i32 {
    fn f<T: Ring>(c: &[T]) -> i32 {
        sign(&cross(c))
    }
    on_scaled!(&flat(&[p, q, r]), 60, f).0
}

/// Exact sign of `(q − p) · (r − p)`.
pub fn dot_sign(p: Point, q: Point, r: Point) -> i32 {
    fn f<T: Ring>(c: &[T]) -> i32 {
        sign(&dot(c))
    }
    on_scaled!(&flat(&[p, q, r]), 60, f).0
}

/// The scaled integers as `BigInt`s (also when they would fit the fast
/// path, e.g. when all of them are zero).
fn big(s: Scaled) -> Vec<BigInt> {
    match s {
        Scaled::Small(v) => v.into_iter().map(BigInt::from).collect(),
        Scaled::Big(v) => v,
    }
}

/// Exact `|pq|²`.
pub fn squared_length(p: Point, q: Point) -> BigRational {
    let (s, e) = scale(&flat(&[p, q]), 0);
    BigRational::from_integer(dist2(&big(s))) * pow2(2 * e)
}

/// Exact comparison of `|ab|²` with `|cd|²`.
pub fn compare_squared_lengths(a: Point, b: Point, c: Point, d: Point) -> Ordering {
    fn f<T: Ring>(c: &[T]) -> Ordering {
        dist2(&c[0..4]).cmp(&dist2(&c[4..8]))
    }
    on_scaled!(&flat(&[a, b, c, d]), 60, f).0
}

/// Exact twice the (unsigned) area of triangle `pqr`.
pub fn twice_area(p: Point, q: Point, r: Point) -> BigRational {
    let (s, e) = scale(&flat(&[p, q, r]), 0);
    BigRational::from_integer(cross(&big(s)).abs()) * pow2(2 * e)
}

/// Exact in-circle test: `1` if `d` is strictly inside the circle through
/// `a, b, c`, `-1` if strictly outside, `0` if on it. The orientation of
/// `a, b, c` does not matter; it must not be `0`.
///
/// # Panics
/// If `a, b, c` are collinear.
pub fn incircle(a: Point, b: Point, c: Point, d: Point) -> i32 {
    let o = orient(a, b, c);
    assert!(o != 0, "optri-oracle: incircle on collinear points");
    fn f<T: Ring>(c: &[T]) -> i32 {
        sign(&incircle_det(c))
    }
    // Degree 4: 28-bit inputs keep every product below 2^127.
    on_scaled!(&flat(&[a, b, c, d]), 28, f).0 * o
}

/// `true` iff `r` lies on the open segment `pq`.
pub fn on_open_segment(p: Point, q: Point, r: Point) -> bool {
    r != p && r != q && orient(p, q, r) == 0 && dot_sign(r, p, q) < 0
}

/// `true` iff the open segments `ab` and `cd` cross at a single point
/// interior to both (a proper crossing).
pub fn properly_cross(a: Point, b: Point, c: Point, d: Point) -> bool {
    orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::FromPrimitive;

    #[test]
    fn decomposition_is_exact() {
        let samples = [
            0.0,
            -0.0,
            1.0,
            -3.5,
            0.1,
            -0.1,
            1e-300,
            5e-324,
            f64::MAX,
            -f64::MIN_POSITIVE,
            2f64.powi(150) * 3.0,
            123456.789,
        ];
        for v in samples {
            let exact = BigRational::from_float(v).unwrap();
            assert_eq!(to_rational(v), exact, "{v}");
            assert_eq!(BigRational::from_f64(v).unwrap(), exact);
        }
    }

    #[test]
    fn fast_and_big_paths_agree() {
        let pts = [[0.1, 0.2], [0.3, 0.7], [1e10, -3.0], [0.5, 0.5], [7.0, 1.0]];
        for &a in &pts {
            for &b in &pts {
                for &c in &pts {
                    let exact = {
                        let r = |v| BigRational::from_float(v).unwrap();
                        let det = (r(b[0]) - r(a[0])) * (r(c[1]) - r(a[1]))
                            - (r(b[1]) - r(a[1])) * (r(c[0]) - r(a[0]));
                        if det.is_positive() {
                            1
                        } else if det.is_negative() {
                            -1
                        } else {
                            0
                        }
                    };
                    assert_eq!(orient(a, b, c), exact);
                }
            }
        }
        // 0.1 + 0.2 != 0.3 in binary: (0.1, 0.1), (0.2, 0.2), (0.3, 0.3) are
        // collinear, but the middle point (0.1 + 0.2) is not 0.3.
        assert_eq!(orient([0.1, 0.1], [0.2, 0.2], [0.3, 0.3]), 0);
        assert_ne!(orient([0.0, 0.0], [0.3, 0.3], [0.1 + 0.2, 0.3]), 0);
        assert_eq!(orient([0.0, 0.0], [1.0, 2.0], [3.0, 6.0]), 0);
        assert_eq!(incircle([0.0, 0.0], [2.0, 0.0], [0.0, 2.0], [2.0, 2.0]), 0);
        assert_eq!(incircle([0.0, 0.0], [0.0, 2.0], [2.0, 0.0], [1.0, 1.0]), 1);
        let big = 2f64.powi(150);
        assert_eq!(
            incircle(
                [0.0, 0.0],
                [2.0 * big, 0.0],
                [0.0, 2.0 * big],
                [2.0 * big, 2.0 * big]
            ),
            0
        );
        assert_eq!(
            squared_length([0.5, 0.0], [0.0, 0.25]),
            BigRational::new(5.into(), 16.into())
        );
        assert_eq!(
            twice_area([0.0, 0.0], [3.0, 0.0], [0.0, -0.5]),
            BigRational::new(3.into(), 2.into())
        );
    }
}
