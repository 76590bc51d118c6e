//! Exact comparisons of *differences* of measures, the decisions of the
//! δ-triangulations (T. S. Vassilev, *Optimal area triangulation*, PhD
//! thesis, University of Saskatchewan, 2005, Table 1.1: δ-area, δ-angle,
//! δ-length), whose value is the largest minus the smallest item of a
//! triangulation.
//!
//! A difference `x₁ − x₂` is compared with `x₃ − x₄` as the sums
//! `x₁ + x₄` and `x₃ + x₂`, so every test is a comparison of two sums of
//! two measures:
//!
//! * **areas**: doubled areas are orientation determinants, so
//!   `|D₁| + |D₄| − |D₃| − |D₂|` is a sum of four signed determinants (the
//!   signs from [`orient_sign`]), evaluated as one exact expansion;
//! * **lengths**: `√a + √d` against `√c + √b`, the sums of square roots that
//!   [`compare_length_sums`] decides exactly;
//! * **angles**: each corner angle `θ ∈ (0, π)` is `arg w` for
//!   `w = (u·v, |u×v|)`, so `θ₁ + θ₄ = arg(w₁w₄)` with the complex product
//!   lying in `(0, 2π)`: no wrap-around, and the two products are compared
//!   by half-plane, then by the sign of their cross product. The products
//!   have degree 4 and their cross product degree 8 in the coordinate
//!   differences, beyond the range of `f64` expansions for extreme inputs
//!   (see [`crate::kernel`]), so the test runs on big integers after scaling
//!   every coordinate by one power of two.
//!
//! These comparisons decide only which of a few candidate triangulations is
//! better (a handful per run), so they are exact without a float filter.

use super::expansion::{two_diff, Expansion};
use super::length_sums::{compare_length_sums, decompose, scaled};
use super::predicates::orient_sign;
use super::Point;
use num_bigint::BigInt;
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

/// Compares `|A₁| − |A₂|` with `|A₃| − |A₄|` for the (unsigned) areas of
/// the triangles `[t₁, t₂, t₃, t₄]`, exactly.
pub(crate) fn compare_area_differences(t: [[Point; 3]; 4]) -> Ordering {
    // |D1| + |D4| − |D3| − |D2|, each |D| = sign(D)·D expanded exactly.
    let mut e = Expansion::new();
    for (tri, outer) in [(t[0], 1.0), (t[3], 1.0), (t[2], -1.0), (t[1], -1.0)] {
        let [a, b, c] = tri;
        let s = orient_sign(a, b, c) as f64 * outer;
        if s == 0.0 {
            continue;
        }
        let (bax, bay) = (two_diff(b[0], a[0]), two_diff(b[1], a[1]));
        let (cax, cay) = (two_diff(c[0], a[0]), two_diff(c[1], a[1]));
        e.add_two_term_product(bax, cay, s);
        e.add_two_term_product(bay, cax, -s);
    }
    e.sign().cmp(&0)
}

/// Compares `|s₁| − |s₂|` with `|s₃| − |s₄|` for the segments
/// `[s₁, s₂, s₃, s₄]`, exactly.
pub(crate) fn compare_length_differences(s: [[Point; 2]; 4]) -> Ordering {
    compare_length_sums(&[s[0], s[3]], &[s[2], s[1]])
}

/// Compares `θ₁ − θ₂` with `θ₃ − θ₄` for the corner angles
/// `[c₁, c₂, c₃, c₄]`, each `[apex, a, b]`: the angle at `apex` between the
/// rays to `a` and `b`, in `[0, π]`; of each sum `θ₁ + θ₄`, `θ₃ + θ₂` at
/// most one term may be `π` (the sum lies in `[0, 2π)`). Exact.
pub(crate) fn compare_angle_differences(c: [[Point; 3]; 4]) -> Ordering {
    let emin = c
        .iter()
        .flatten()
        .flatten()
        .filter(|&&v| v != 0.0)
        .map(|&v| decompose(v).1)
        .min()
        .unwrap_or(0);
    // w = (u·v, |u×v|) on the integer-scaled coordinates.
    let w = |[o, a, b]: [Point; 3]| -> [BigInt; 2] {
        let [ox, oy, ax, ay, bx, by] =
            [o[0], o[1], a[0], a[1], b[0], b[1]].map(|v| scaled(v, emin));
        let (ux, uy, vx, vy) = (ax - &ox, ay - &oy, bx - ox, by - oy);
        let dot = &ux * &vx + &uy * &vy;
        let cross = (ux * vy - uy * vx).abs();
        [dot, cross]
    };
    let product = |p: [BigInt; 2], q: [BigInt; 2]| -> [BigInt; 2] {
        let [px, py] = p;
        let [qx, qy] = q;
        [&px * &qx - &py * &qy, px * qy + py * qx]
    };
    let [w1, w2, w3, w4] = c.map(w);
    let left = product(w1, w4);
    let right = product(w3, w2);
    compare_arguments(&left, &right)
}

/// Counter-clockwise order of the arguments in `[0, 2π)` of two non-zero
/// vectors.
fn compare_arguments(p: &[BigInt; 2], q: &[BigInt; 2]) -> Ordering {
    // 0 for arguments in [0, π), 1 for [π, 2π).
    let half = |v: &[BigInt; 2]| -> u8 {
        if v[1].is_positive() || (v[1].is_zero() && v[0].is_positive()) {
            0
        } else {
            1
        }
    };
    half(p).cmp(&half(q)).then_with(|| {
        // In one half plane: arg p < arg q iff p × q > 0.
        let cross = &p[0] * &q[1] - &p[1] * &q[0];
        if cross.is_positive() {
            Ordering::Less
        } else if cross.is_negative() {
            Ordering::Greater
        } else {
            Ordering::Equal
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;
    use rand::{rngs::StdRng, Rng, SeedableRng};

    fn rational(v: f64) -> BigRational {
        BigRational::from_float(v).unwrap()
    }

    fn doubled_area([a, b, c]: [Point; 3]) -> BigRational {
        let d = (rational(b[0]) - rational(a[0])) * (rational(c[1]) - rational(a[1]))
            - (rational(b[1]) - rational(a[1])) * (rational(c[0]) - rational(a[0]));
        d.abs()
    }

    fn random_point(rng: &mut StdRng, range: i32) -> Point {
        [
            rng.gen_range(-range..=range) as f64,
            rng.gen_range(-range..=range) as f64,
        ]
    }

    #[test]
    fn area_differences_match_rationals_with_ties() {
        let mut rng = StdRng::seed_from_u64(0xDE17A);
        let mut ties = 0;
        for _ in 0..20_000 {
            let t: [[Point; 3]; 4] =
                std::array::from_fn(|_| std::array::from_fn(|_| random_point(&mut rng, 3)));
            let [a1, a2, a3, a4] = t.map(doubled_area);
            let expected = (a1 - a2).cmp(&(a3 - a4));
            ties += (expected == Ordering::Equal) as usize;
            assert_eq!(compare_area_differences(t), expected, "{t:?}");
        }
        assert!(ties > 500, "only {ties} ties");
        // Tiny coordinates far apart in scale.
        let t = [
            [[0.0, 0.0], [1e-30, 0.0], [0.0, 1e-30]],
            [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]],
            [[0.0, 0.0], [2e-30, 0.0], [0.0, 1e-30]],
            [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]],
        ];
        assert_eq!(compare_area_differences(t), Ordering::Less);
    }

    /// Squares both sides of `√a − √b` vs `√c − √d` on small integers:
    /// an independent exact reference (`x = √a + √d`, `y = √c + √b`,
    /// `x² − y² = (a + d − c − b) + 2(√(ad) − √(cb))`).
    fn root_difference_order(a: i64, b: i64, c: i64, d: i64) -> Ordering {
        // Compare x = √a + √d with y = √c + √b; both ≥ 0, so compare squares:
        // a + d + 2√(ad) vs c + b + 2√(cb), i.e. r + 2√(ad) vs 2√(cb) with
        // r = a + d − c − b.
        let r = a + d - c - b;
        let (p, q) = (4 * a * d, 4 * c * b); // (2√ad)², (2√cb)²
                                             // sign(r + √p − √q)
        let sign_sqrt_diff = |p: i64, q: i64| p.cmp(&q); // sign(√p − √q)
        match (r.cmp(&0), sign_sqrt_diff(p, q)) {
            (Ordering::Equal, s) => s,
            (s, t) if s == t || t == Ordering::Equal => s,
            (Ordering::Greater, Ordering::Less) => {
                // r > 0 > √p − √q: compare r + √p with √q: (r + √p)² vs q,
                // r² + p + 2r√p vs q, i.e. 2r√p vs q − p − r².
                let rhs = q - p - r * r;
                if rhs < 0 {
                    Ordering::Greater
                } else {
                    (4 * r * r * p).cmp(&(rhs * rhs))
                }
            }
            _ => {
                // r < 0 < √p − √q: sign(√p − (√q − r)) with −r > 0:
                // p vs q + r² − 2r√q = q + r² + 2|r|√q.
                let lhs = p - q - r * r;
                if lhs < 0 {
                    Ordering::Less
                } else {
                    (lhs * lhs).cmp(&(4 * r * r * q))
                }
            }
        }
    }

    #[test]
    fn length_differences_match_squaring_with_ties() {
        let mut rng = StdRng::seed_from_u64(0x1E6A7);
        let mut ties = 0;
        for _ in 0..20_000 {
            let s: [[Point; 2]; 4] =
                std::array::from_fn(|_| [[0.0, 0.0], random_point(&mut rng, 4)]);
            let sq = s.map(|[_, q]| (q[0] * q[0] + q[1] * q[1]) as i64);
            let expected = root_difference_order(sq[0], sq[1], sq[2], sq[3]);
            ties += (expected == Ordering::Equal) as usize;
            assert_eq!(compare_length_differences(s), expected, "{s:?}");
        }
        assert!(ties > 150, "only {ties} ties");
    }

    /// Angles compared through high-precision floats where they are far
    /// apart, and exact rational identities for ties.
    #[test]
    fn angle_differences_match_high_precision_and_ties() {
        let angle = |[o, a, b]: [Point; 3]| {
            let (ux, uy, vx, vy) = (a[0] - o[0], a[1] - o[1], b[0] - o[0], b[1] - o[1]);
            (ux * vy - uy * vx).abs().atan2(ux * vx + uy * vy)
        };
        let mut rng = StdRng::seed_from_u64(0xA4611E);
        let mut checked = 0;
        for _ in 0..20_000 {
            let c: [[Point; 3]; 4] = std::array::from_fn(|_| loop {
                let t: [Point; 3] = std::array::from_fn(|_| random_point(&mut rng, 50));
                if t[0] != t[1] && t[0] != t[2] {
                    break t;
                }
            });
            let [a1, a2, a3, a4] = c.map(angle);
            let gap = (a1 - a2) - (a3 - a4);
            if gap.abs() > 1e-9 {
                checked += 1;
                let expected = if gap > 0.0 {
                    Ordering::Greater
                } else {
                    Ordering::Less
                };
                assert_eq!(compare_angle_differences(c), expected, "{c:?}");
            }
        }
        assert!(checked > 19_000);
        // Ties: right angles and 45° corners of a lattice, and a corner
        // against itself.
        let right = [[0.0, 0.0], [1.0, 0.0], [0.0, 3.0]];
        let half_right = [[0.0, 0.0], [2.0, 0.0], [5.0, 5.0]];
        let flat_half = [[0.0, 0.0], [-1.0, 1.0], [0.0, 7.0]];
        assert_eq!(
            compare_angle_differences([right, half_right, half_right, flat_half.map(|p| p)]),
            Ordering::Greater
        );
        // 90 − 45 = 45 − 0? (the last corner is a 0° corner: two rays alike)
        let zero = [[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]];
        assert_eq!(
            compare_angle_differences([right, half_right, half_right, zero]),
            Ordering::Equal
        );
        // 135 − 45 = 90 − 0
        let obtuse = [[0.0, 0.0], [1.0, 0.0], [-3.0, 3.0]];
        assert_eq!(
            compare_angle_differences([obtuse, half_right, right, zero]),
            Ordering::Equal
        );
        // Sums near 2π: 179.x + 179.x vs 179.y + 179.y.
        let wide = [[0.0, 0.0], [1000.0, 1.0], [-1000.0, 1.0]];
        let wider = [[0.0, 0.0], [1000.0, 1.0], [-1000.0, 0.5]];
        assert_eq!(
            compare_angle_differences([wide, wider, wide, wider]),
            Ordering::Equal
        );
        assert_eq!(
            compare_angle_differences([wider, zero, wide, zero]),
            Ordering::Greater
        );
        assert_eq!(
            compare_angle_differences([wide, wider, wider, wide]),
            Ordering::Less
        );
    }
}
