//! The in-circle sign from `f64` filters, before the adaptive expansion
//! arithmetic of the `robust` crate (J. R. Shewchuk, *Adaptive precision
//! floating-point arithmetic and fast robust geometric predicates*, Discrete
//! Comput. Geom. 18 (1997), §4.3 and §2's error-free transformations).
//!
//! With `a, b, c` translated by `−d`, the in-circle determinant is
//! `Σ_cyc |a|²·(b × c)`, a sum of three rows `L·C` with the lift
//! `L = ax² + ay²` and the cross product `C = bx·cy − by·cx`. Its
//! *permanent* `P = Σ_cyc |a|²·(|bx·cy| + |by·cx|)` scales every error bound.
//!
//! 1. Plain `f64` evaluation: decides when `|det| > (10 + 96u)u·P`,
//!    Shewchuk's bound `iccerrboundA` (`u = 2⁻⁵³`).
//! 2. Double-double evaluation, when the six translated coordinates are
//!    exact (the error-free [`two_diff`] has zero tails, as for nearby
//!    points, Sterbenz): every row as an unevaluated sum `hi + lo` with an
//!    error below `23.3u²` times its share of `P`, proven at
//!    [`DOUBLE_DOUBLE_GAP`]. Points sampled on a circle with cos/sin are
//!    off the circle by the rounding of their coordinates, so their
//!    determinants are about `u·P`: stage 1 never decides them and the
//!    `robust` crate's adaptive stages (which zero several kilobytes of
//!    buffers per call) did every in-circle test of the convex Delaunay
//!    triangulation in the greedy triangulation of such points. Stage 2 decides
//!    all but near-exact ties.
//!
//! Undecided cases (exact zeros, inexact translations) go to `robust`.

use super::expansion::{two_diff, two_product, two_sum};
use super::{Point, UNIT_ROUNDOFF as U};

/// Shewchuk's `iccerrboundA`: the plain evaluation's error is below this
/// times the permanent.
const PLAIN_GAP: f64 = (10.0 + 96.0 * U) * U;

/// The double-double evaluation decides when its result exceeds this times
/// the permanent.
///
/// Error bound, with exact translated coordinates (so `L`, `C` are exact
/// polynomials in `f64` inputs) and `T = L·M`, `M = |bx·cy| + |by·cx|`, for
/// one row; each rounding is at most `u` times its result, and the kernel's
/// coordinate range keeps every product normal ([`crate::kernel`]):
/// * lift: `ax² + ay² = xx + exx + yy + eyy` ([`two_product`]) and
///   `xx + yy = Lh + t` ([`two_sum`]), `Ll = fl(t + fl(exx + eyy))`:
///   error `eL ≤ 2.01u²L`, `|Ll| ≤ 2.01u·L`, `Lh ≤ 1.001L`;
/// * cross: `bx·cy = p₁ + e₁`, `by·cx = p₂ + e₂`, `p₁ − p₂ = Ch + t`
///   exactly, `Cl = fl(t + fl(e₁ − e₂))`: error `eC ≤ 3.01u²M`,
///   `|Cl| ≤ 2.01u·M`, `|Ch| ≤ 1.001M`, and `|C| ≤ M`;
/// * product: `Lh·Ch = Ph + Pe` exactly, `Pl = fl(Pe + fl(fl(Lh·Cl) +
///   fl(Ll·Ch)))`; `L·C − (Ph + Pl)` consists of `Ll·Cl` (`≤ 4.05u²T`),
///   `eL·C` (`≤ 2.01u²T`), `(Lh + Ll)·eC` (`≤ 3.02u²T`) and the three
///   roundings in `Pl` (`≤ 4.05u²T`, `4.05u²T`, `5.06u²T`, as
///   `|Lh·Cl|, |Ll·Ch| ≤ 2.02u·T` and `|Pe| ≤ 1.003u·T`): `≤ 22.3u²T`, and
///   `|Pl| ≤ 5.06u·T`, `|Ph| ≤ 1.003T`.
///
/// The three `Ph` sum exactly to `S + t₁ + t₂` (two [`two_sum`]s), and the
/// five small terms `t₁, t₂, Pl₁, Pl₂, Pl₃` (absolute sum `≤ 7.1u·P`) are
/// added in `f64` with error `≤ 4·1.001u·7.1u·P ≤ 28.5u²P`. In all the
/// determinant is within `50.8u²P` of `S + lo`, whose sign `fl(S + lo)` has
/// exactly (a sum of two floats rounds to zero only if it is zero), at
/// most `1 + u` times larger. The computed permanent is within `8u`
/// relative, so `128u²` more than covers the bound and its own rounding.
const DOUBLE_DOUBLE_GAP: f64 = 128.0 * U * U;

/// The sign of the in-circle determinant of `a, b, c, d` (positive if `d`
/// is inside the circle through the ccw triangle `a, b, c`) when the
/// filters of the module docs decide it, else `None`.
#[inline]
pub(super) fn certified_incircle_sign(a: Point, b: Point, c: Point, d: Point) -> Option<i32> {
    let (adx, ady) = (a[0] - d[0], a[1] - d[1]);
    let (bdx, bdy) = (b[0] - d[0], b[1] - d[1]);
    let (cdx, cdy) = (c[0] - d[0], c[1] - d[1]);
    let (alift, blift, clift) = (
        adx * adx + ady * ady,
        bdx * bdx + bdy * bdy,
        cdx * cdx + cdy * cdy,
    );
    let (bc1, bc2) = (bdx * cdy, bdy * cdx);
    let (ca1, ca2) = (cdx * ady, cdy * adx);
    let (ab1, ab2) = (adx * bdy, ady * bdx);
    let det = alift * (bc1 - bc2) + blift * (ca1 - ca2) + clift * (ab1 - ab2);
    let permanent = alift * (bc1.abs() + bc2.abs())
        + blift * (ca1.abs() + ca2.abs())
        + clift * (ab1.abs() + ab2.abs());
    let plain = PLAIN_GAP * permanent;
    if det > plain {
        return Some(1);
    }
    if -det > plain {
        return Some(-1);
    }
    let exact = |p: Point| {
        let (x, ex) = two_diff(p[0], d[0]);
        let (y, ey) = two_diff(p[1], d[1]);
        (ex == 0.0 && ey == 0.0).then_some([x, y])
    };
    let (a, b, c) = (exact(a)?, exact(b)?, exact(c)?);
    let rows = [row(a, b, c), row(b, c, a), row(c, a, b)];
    let (s, t1) = two_sum(rows[0].0, rows[1].0);
    let (hi, t2) = two_sum(s, rows[2].0);
    let lo = (((t1 + t2) + rows[0].1) + rows[1].1) + rows[2].1;
    let value = hi + lo;
    let bound = DOUBLE_DOUBLE_GAP * permanent;
    if value > bound {
        Some(1)
    } else if value < -bound {
        Some(-1)
    } else {
        None
    }
}

/// `|p|²·(q × r)` as `(hi, lo)` with the error of [`DOUBLE_DOUBLE_GAP`]'s
/// proof, for exact (translated) coordinates.
#[inline]
fn row(p: Point, q: Point, r: Point) -> (f64, f64) {
    let (xx, exx) = two_product(p[0], p[0]);
    let (yy, eyy) = two_product(p[1], p[1]);
    let (lift_hi, t) = two_sum(xx, yy);
    let lift_lo = t + (exx + eyy);
    let (p1, e1) = two_product(q[0], r[1]);
    let (p2, e2) = two_product(q[1], r[0]);
    let (cross_hi, t) = two_diff(p1, p2);
    let cross_lo = t + (e1 - e2);
    let (hi, e) = two_product(lift_hi, cross_hi);
    (hi, e + (lift_hi * cross_lo + lift_lo * cross_hi))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{rngs::StdRng, Rng, SeedableRng};

    fn robust_sign(a: Point, b: Point, c: Point, d: Point) -> i32 {
        let p = |p: Point| robust::Coord { x: p[0], y: p[1] };
        let v = robust::incircle(p(a), p(b), p(c), p(d));
        (v > 0.0) as i32 - (v < 0.0) as i32
    }

    /// Checks every decided quadruple against `robust`'s exact sign; returns
    /// how many were decided.
    fn check(quadruples: &[[Point; 4]]) -> usize {
        let mut decided = 0;
        for &[a, b, c, d] in quadruples {
            let exact = robust_sign(a, b, c, d);
            if let Some(s) = certified_incircle_sign(a, b, c, d) {
                assert_eq!(s, exact, "{a:?} {b:?} {c:?} {d:?}");
                decided += 1;
            }
            if exact == 0 {
                assert_eq!(certified_incircle_sign(a, b, c, d), None);
            }
        }
        decided
    }

    /// Quadruples of nearby points of a regular polygon sampled with
    /// cos/sin, scaled and shifted: determinants about `u` times the
    /// permanent, or exactly zero.
    fn sampled_quadruples(n: usize, scale: f64, shift: Point) -> Vec<[Point; 4]> {
        let p = |i: usize| {
            let t = std::f64::consts::TAU * (i % n) as f64 / n as f64;
            [scale * t.cos() + shift[0], scale * t.sin() + shift[1]]
        };
        let mut quadruples = Vec::new();
        for i in 0..n {
            for (j, k, l) in [(1, 2, 3), (1, 3, 5), (2, 4, 9), (n / 4, n / 2, 3 * n / 4)] {
                quadruples.push([p(i), p(i + j), p(i + k), p(i + l)]);
                quadruples.push([p(i), p(i + j), p(i + k), p(i + k + 1)]);
            }
        }
        quadruples
    }

    #[test]
    fn near_cocircular_points_are_decided_correctly() {
        for (scale, shift) in [
            (1000.0, [0.0, 0.0]),
            (1.0, [-3.5, 2.25]),
            (2f64.powi(48), [2f64.powi(50), -(2f64.powi(49))]),
            (2f64.powi(-100), [2f64.powi(-98), -(2f64.powi(-99))]),
            (-7.0e-30, [1.0e-29, -2.0e-29]),
        ] {
            let quadruples = sampled_quadruples(720, scale, shift);
            let decided = check(&quadruples);
            assert!(
                decided >= quadruples.len() / 2,
                "scale {scale}: {decided} of {}",
                quadruples.len()
            );
        }
    }

    #[test]
    fn exactly_cocircular_points_stay_undecided() {
        let mut rng = StdRng::seed_from_u64(15);
        let mut quadruples = Vec::new();
        for _ in 0..2000 {
            let s = 2f64.powi(rng.gen_range(-100..100));
            let (x, y) = (rng.gen_range(0.5..1.0) * s, rng.gen_range(0.5..1.0) * s);
            let (cx, cy) = (rng.gen_range(-4.0..4.0) * s, rng.gen_range(-4.0..4.0) * s);
            // A rectangle centred at (cx, cy), rounded: exactly cocircular
            // when the corners are exact, else a near-tie.
            let corners = [
                [cx + x, cy + y],
                [cx - x, cy + y],
                [cx - x, cy - y],
                [cx + x, cy - y],
            ];
            quadruples.push(corners);
            quadruples.push([corners[1], corners[2], corners[3], corners[0]]);
        }
        check(&quadruples);
        let exact: Vec<[Point; 4]> = (0..200)
            .map(|i| {
                let v = i as f64 + 1.0;
                [[v, 0.0], [0.0, v], [-v, 0.0], [0.0, -v]]
            })
            .collect();
        assert_eq!(check(&exact), 0);
    }

    #[test]
    fn random_quadruples_agree_with_the_exact_sign() {
        let mut rng = StdRng::seed_from_u64(2026);
        let mut quadruples = Vec::new();
        for _ in 0..20000 {
            let s = 2f64.powi(rng.gen_range(-100..100));
            let mut q = [[0.0; 2]; 4];
            for p in &mut q {
                *p = [rng.gen_range(1.0..2.0) * s, rng.gen_range(-2.0..-1.0) * s];
            }
            quadruples.push(q);
            // The fourth point moved onto the (rounded) circle through the
            // others' perturbation scale: a near-tie.
            let [a, b, c, _] = q;
            quadruples.push([a, b, c, [a[0], c[1]]]);
            quadruples.push([a, b, c, [b[0].next_up(), b[1]]]);
        }
        check(&quadruples);
    }
}
