//! Squared-length keys: the rounded `f64` key that orders almost every pair
//! of segments, and a certified double-double key for the near-ties it
//! leaves. Every float filter of a Euclidean length comparison in the crate
//! is one of these two, with the error bounds derived here once.
//!
//! # Rounded keys
//! A *rounded key* is a non-negative `f64` `x` computed from an exact
//! non-negative quantity `X`, a sum of non-negative terms, such that each
//! term picks up at most four factors `(1 + δ)` with `|δ| ≤ u = 2⁻⁵³`
//! ([`UNIT_ROUNDOFF`](super::UNIT_ROUNDOFF)): no underflow or overflow.
//! Then `|x − X| ≤ γ·X` with `γ = (1 + u)⁴ − 1 < 4.0001u`. The rounded
//! squared length `fl(fl(fl(px − qx)²) + fl(fl(py − qy)²))`
//! ([`rounded_squared_length`]) is one (each square: the difference's factor
//! twice and the product's; then the sum's); so are `fl(t·t)` for a length
//! `t` and `|fl(a − b)|` for a coordinate difference (one factor).
//! The kernel's coordinate range ([`crate::kernel`]) keeps them clear of
//! underflow and overflow: differences are multiples of 2⁻¹⁹⁴ and at most
//! 2²⁰², so squares lie in `[2⁻³⁸⁸, 2⁴⁰⁵]`.
//!
//! **Deciding a comparison** ([`compare_rounded_keys`]). If `X ≤ Y` then
//! `x − y ≤ X − Y + γ(X + Y) ≤ γ(X + Y) ≤ γ/(1 − γ)·(x + y)`; the computed
//! `fl(x − y)` is at most `(1 + u)` times that, below `4.001u·(x + y)`,
//! while the computed bound `fl(8u·fl(x + y))` is at least
//! `8u(1 − u)(x + y)` (`8u` is a power of two: that product is exact). So
//! `fl(x − y)` above the bound proves `X > Y`, symmetrically for `X < Y`,
//! and an exact tie `X = Y` is never decided.
//!
//! **Sorting by keys** ([`in_one_key_run`]). Sort by rounded keys, ascending,
//! and let `x ≤ y` be the keys of two quantities in the wrong exact order or
//! exactly tied (`X ≥ Y`). As above, `y − x ≤ γ/(1 − γ)·(x + y) < 8.001u·y`,
//! and every key `z` between them differs from its neighbours by less than
//! that, which is below `8.002u·z` since `z ≥ x > (1 − 8.001u)·y`. Consecutive
//! keys `z ≤ z′` with `fl(z′ − z) > fl(16u·z′)` are therefore in the exact
//! order, strictly: the sorted keys split into runs at such steps, and
//! re-sorting each run of two or more by the exact comparison gives the
//! exact order.
//!
//! # Double-double keys
//! [`SquaredLength`]: the error-free transformations of T. J. Dekker, *A
//! floating-point technique for extending the available precision*, Numer.
//! Math. 18 (1971) (TwoSum, TwoProduct, here by a fused multiply-add), as in
//! J. R. Shewchuk, *Adaptive precision floating-point arithmetic and fast
//! robust geometric predicates*, 1997, §2 ([`super::expansion`]). A rounded
//! key cannot order the chords of one offset of a regular polygon sampled
//! with cos/sin: they are equal up to rounding, and every such comparison
//! would need the exact expansion. The double-double key is within about
//! `12u²`, so it decides every pair except those within ~`10⁻³⁰` relative of
//! each other, in practice exact ties (mirror-image chords), which only the
//! symbolic tie-break can order anyway.

use super::expansion::{two_diff, two_product, two_sum};
use super::{Point, UNIT_ROUNDOFF as U};
use std::cmp::Ordering;

/// The rounded squared length of `pq`, `fl(fl(dx)² + fl(dy)²)`: a rounded
/// key (module docs), equal to `SquaredLength::of_segment(p, q).hi`.
#[inline]
pub fn rounded_squared_length(p: Point, q: Point) -> f64 {
    let (dx, dy) = (p[0] - q[0], p[1] - q[1]);
    dx * dx + dy * dy
}

/// The exact order of the two quantities behind the rounded keys `x` and
/// `y` when the keys decide it, `None` when they are too close (always for
/// an exact tie); never `Some(Equal)`. See the module docs, "Deciding a
/// comparison".
#[inline]
pub fn compare_rounded_keys(x: f64, y: f64) -> Option<Ordering> {
    let difference = x - y;
    let bound = 8.0 * U * (x + y);
    if difference > bound {
        Some(Ordering::Greater)
    } else if -difference > bound {
        Some(Ordering::Less)
    } else {
        None
    }
}

/// Relative step between consecutive sorted rounded keys at or below which
/// they may be out of exact order (module docs, "Sorting by keys").
const KEY_RUN_STEP: f64 = 16.0 * U;

/// For consecutive rounded keys `lower ≤ upper` of a sort: may their exact
/// quantities be tied or in the other order, so that they belong to one run
/// that the exact comparison re-sorts? `false` proves the strict exact order
/// (module docs, "Sorting by keys").
#[inline]
pub fn in_one_key_run(lower: f64, upper: f64) -> bool {
    upper - lower <= KEY_RUN_STEP * upper
}

/// Two keys whose certified difference is at most this times the sum of
/// their `hi` parts are left undecided: the proof in
/// [`SquaredLength::certainly_compare`] needs `(1 + u)(16.03 + ε)·u²`, and
/// `32u²` leaves a factor of two for the rounding of the bound itself.
const UNDECIDED_GAP: f64 = 32.0 * U * U;

/// `|pq|²` as `hi + lo` with `|hi + lo − |pq|²| ≤ 12.02·u²·hi` and
/// `|lo| ≤ 4.01·u·hi` (see [`SquaredLength::of_segment`]).
///
/// `hi` is the rounded `f64` evaluation `fl(fl(dx)² + fl(dy)²)`, the same
/// number as a plain rounded key.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SquaredLength {
    /// The rounded squared length.
    pub hi: f64,
    /// A correction: `hi + lo` is far closer to the exact value than `hi`.
    pub lo: f64,
}

impl SquaredLength {
    /// The key of the segment `pq`.
    ///
    /// Error bound. `dx = px − qx = hx + lx` exactly (`two_diff`, `|lx| ≤
    /// u|hx|`), likewise `dy`; so with `Q = hx² + hy²`,
    /// `|pq|² = Q + 2(hx·lx + hy·ly) + lx² + ly²` and `|hx·lx + hy·ly| ≤ uQ`.
    /// `two_product` gives `hx² = xx + exx` exactly (`|exx| ≤ u·xx`), and
    /// `two_sum` `xx + yy = hi + t` exactly (`|t| ≤ u·hi`), so
    /// `|pq|² = hi + t + exx + eyy + 2(hx·lx + hy·ly) + lx² + ly²`, and `lo`
    /// evaluates the middle terms in `f64`. Since `xx ≥ (1 − u)hx²`, `Q ≤ (1 + 3u)hi`.
    /// Rounding errors, each at most `u` times the rounded result:
    /// * `cross = fl(2·fl(fl(hx·lx) + fl(hy·ly)))`: within `2·((1 + u)² − 1)·uQ
    ///   ≤ 4.001u²Q` of `2(hx·lx + hy·ly)`, and `|cross| ≤ 2.001uQ`;
    /// * `fl(exx + eyy)`: error `≤ 1.001u²Q`, magnitude `≤ 1.001uQ`;
    /// * adding `t`: error `≤ 2.003u²Q`, magnitude `≤ 2.003uQ`;
    /// * adding `cross`: error `≤ 4.005u²Q`, so `|lo| ≤ 4.005uQ ≤ 4.01u·hi`;
    /// * the dropped `lx² + ly² ≤ u²Q`.
    ///
    /// In all `12.01u²Q ≤ 12.02u²·hi`. The kernel's coordinate range
    /// ([`crate::kernel`]) keeps every product normal (differences are
    /// multiples of 2⁻¹⁹⁴ and at most 2²⁰²), so `two_product` is exact and
    /// every rounding is relative (a sum that would be subnormal is exact).
    #[inline]
    pub fn of_segment(p: Point, q: Point) -> Self {
        let (hx, lx) = two_diff(p[0], q[0]);
        let (hy, ly) = two_diff(p[1], q[1]);
        let (xx, exx) = two_product(hx, hx);
        let (yy, eyy) = two_product(hy, hy);
        let (hi, t) = two_sum(xx, yy);
        let cross = 2.0 * (hx * lx + hy * ly);
        SquaredLength {
            hi,
            lo: (t + (exx + eyy)) + cross,
        }
    }

    /// `Some(ordering)` of the two exact squared lengths when the keys
    /// decide it; `None` when they are too close (always for equal lengths).
    /// Never `Some(Equal)`.
    ///
    /// Why it is exact when it decides. If one `hi` exceeds twice the other,
    /// the `hi` order is the exact order (`|lo|` and the error together are
    /// below `5u·hi`). Otherwise `x.hi − y.hi` is exact (Sterbenz), and with
    /// `B = fl(x.lo − y.lo) = x.lo − y.lo + e_B`, `|e_B| ≤ 4.01u²(x.hi + y.hi)`,
    /// the exact difference is `(x.hi − y.hi) + B − e_B + e_x − e_y`, where
    /// `e_x`, `e_y` are the keys' errors (`≤ 12.02u²·hi` each). The computed
    /// `gap = fl((x.hi − y.hi) + B)` has the sign of the exact sum
    /// `(x.hi − y.hi) + B` and at most `1 + u` times its magnitude; so
    /// `|gap| > UNDECIDED_GAP·(x.hi + y.hi)` makes that sum exceed
    /// `16.03u²·(x.hi + y.hi) ≥ |e_B| + |e_x| + |e_y|`, and the sign of
    /// `gap` is the exact sign.
    #[inline]
    pub fn certainly_compare(self, other: Self) -> Option<Ordering> {
        let (x, y) = (self, other);
        if x.hi > 2.0 * y.hi {
            return Some(Ordering::Greater);
        }
        if y.hi > 2.0 * x.hi {
            return Some(Ordering::Less);
        }
        let gap = (x.hi - y.hi) + (x.lo - y.lo);
        let bound = UNDECIDED_GAP * (x.hi + y.hi);
        if gap > bound {
            Some(Ordering::Greater)
        } else if gap < -bound {
            Some(Ordering::Less)
        } else {
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::compare_lengths;
    use rand::{rngs::StdRng, Rng, SeedableRng};

    /// Checks every decided pair against the exact comparison; returns how
    /// many pairs the keys decided.
    fn check(pairs: &[([Point; 2], [Point; 2])]) -> usize {
        let mut decided = 0;
        for &([a, b], [c, d]) in pairs {
            let exact = compare_lengths(a, b, c, d);
            let keys =
                SquaredLength::of_segment(a, b).certainly_compare(SquaredLength::of_segment(c, d));
            if let Some(o) = keys {
                assert_eq!(o, exact, "{a:?}{b:?} vs {c:?}{d:?}");
                decided += 1;
            }
            if exact == Ordering::Equal {
                assert_eq!(keys, None, "an exact tie is never decided");
            }
        }
        decided
    }

    /// A coordinate of magnitude in `[s/2, s)` and random sign: inside the
    /// kernel's range for the exponents used below.
    fn coordinate(rng: &mut StdRng, s: f64) -> f64 {
        let sign = if rng.gen_bool(0.5) { 1.0 } else { -1.0 };
        sign * rng.gen_range(0.5..1.0) * s
    }

    /// A random point with coordinates of magnitude about `2^e`, `e` in
    /// `[-130, 190)`, and that scale.
    fn random_point(rng: &mut StdRng) -> (Point, f64) {
        let s = 2f64.powi(rng.gen_range(-130..190));
        ([coordinate(rng, s), coordinate(rng, s)], s)
    }

    /// The chords of one offset of a regular polygon sampled with cos/sin,
    /// scaled by `scale` and shifted by `shift`: equal up to rounding.
    fn sampled_chords(n: usize, scale: f64, shift: Point) -> Vec<([Point; 2], [Point; 2])> {
        let p = |i: usize| {
            let t = std::f64::consts::TAU * (i % n) as f64 / n as f64;
            [scale * t.cos() + shift[0], scale * t.sin() + shift[1]]
        };
        let mut pairs = Vec::new();
        for offset in [1, 2, 7, n / 3] {
            for i in 0..n {
                let j = (i * 7 + 3) % n;
                pairs.push(([p(i), p(i + offset)], [p(j), p(j + offset)]));
            }
        }
        pairs
    }

    #[test]
    fn near_ties_on_a_sampled_circle_are_decided_correctly() {
        for (scale, shift) in [
            (1000.0, [0.0, 0.0]),
            (1.0, [-3.5, 2.25]),
            (2f64.powi(150), [-(2f64.powi(149)), 0.0]),
            (2f64.powi(-120), [2f64.powi(-118), -(2f64.powi(-119))]),
            (-7.0e-30, [1.0e-29, -2.0e-29]),
        ] {
            let pairs = sampled_chords(500, scale, shift);
            let decided = check(&pairs);
            // Nearly all near-ties that are not exact ties are decided.
            let ties = pairs
                .iter()
                .filter(|&&([a, b], [c, d])| compare_lengths(a, b, c, d) == Ordering::Equal)
                .count();
            assert!(
                decided + ties >= pairs.len() * 99 / 100,
                "scale {scale}: {decided} decided, {ties} ties of {}",
                pairs.len()
            );
        }
    }

    #[test]
    fn mirror_ties_stay_undecided() {
        let mut rng = StdRng::seed_from_u64(15);
        let mut pairs = Vec::new();
        for _ in 0..2000 {
            let (a, s) = random_point(&mut rng);
            let b: Point = [coordinate(&mut rng, s), coordinate(&mut rng, s)];
            // Mirror images in both axes and a swap of the coordinates.
            pairs.push(([a, b], [[-a[0], a[1]], [-b[0], b[1]]]));
            pairs.push(([a, b], [[a[0], -a[1]], [b[0], -b[1]]]));
            pairs.push(([a, b], [[a[1], a[0]], [b[1], b[0]]]));
            pairs.push(([a, b], [b, a]));
        }
        assert_eq!(check(&pairs), 0);
    }

    #[test]
    fn random_near_ties_and_far_pairs_agree_with_the_exact_order() {
        let mut rng = StdRng::seed_from_u64(2026);
        let mut pairs = Vec::new();
        for _ in 0..20000 {
            let (a, s) = random_point(&mut rng);
            let b: Point = [coordinate(&mut rng, s), coordinate(&mut rng, s)];
            // `cd`: `ab` rotated by 90° (same length up to the rounding of the
            // shift), then nudged by a few ulps, or a far-away segment.
            let c: Point = [a[1] + 4.0 * s, -a[0]];
            let mut d: Point = [b[1] + 4.0 * s, -b[0]];
            match rng.gen_range(0..4) {
                0 => {}
                1 => d[0] = d[0].next_up(),
                2 => d[1] = d[1].next_down().next_down(),
                _ => d = [d[0] * 1.5, d[1] * 3.0],
            }
            pairs.push(([a, b], [c, d]));
            pairs.push(([c, d], [a, b]));
        }
        let decided = check(&pairs);
        assert!(decided > pairs.len() / 2, "{decided} of {}", pairs.len());
    }

    #[test]
    fn the_high_part_is_the_rounded_key() {
        let (p, q) = ([0.1, -0.7], [3.3, 1e-3]);
        let (dx, dy) = (p[0] - q[0], p[1] - q[1]);
        assert_eq!(SquaredLength::of_segment(p, q).hi, dx * dx + dy * dy);
        assert_eq!(rounded_squared_length(p, q), dx * dx + dy * dy);
    }

    /// `|pq|²` in exact rational arithmetic (independent of the kernel's
    /// expansions).
    fn exact_squared(p: Point, q: Point) -> num_rational::BigRational {
        let r = |v: f64| num_rational::BigRational::from_float(v).expect("finite");
        let (dx, dy) = (r(p[0]) - r(q[0]), r(p[1]) - r(q[1]));
        &dx * &dx + &dy * &dy
    }

    /// Segment pairs of every kind used above: sampled-circle chords
    /// (equal up to rounding), mirror images (exact ties), rotated copies
    /// nudged by an ulp, far pairs.
    fn mixed_pairs(rng: &mut StdRng) -> Vec<([Point; 2], [Point; 2])> {
        let mut pairs = sampled_chords(200, 1000.0, [0.0, 0.0]);
        pairs.extend(sampled_chords(120, 2f64.powi(-100), [2f64.powi(-99), 0.0]));
        for _ in 0..3000 {
            let (a, s) = random_point(rng);
            let b: Point = [coordinate(rng, s), coordinate(rng, s)];
            let c: Point = [a[1] + 4.0 * s, -a[0]];
            let mut d: Point = [b[1] + 4.0 * s, -b[0]];
            match rng.gen_range(0..4) {
                0 => {}
                1 => d[0] = d[0].next_up(),
                2 => d = [-b[0], b[1]],
                _ => d = [d[0] * 1.5, d[1] * 3.0],
            }
            let c = if d == [-b[0], b[1]] { [-a[0], a[1]] } else { c };
            pairs.push(([a, b], [c, d]));
        }
        pairs
    }

    /// The rounded-key filter never decides a pair against the exact
    /// rational order, never decides a tie, and decides most far pairs;
    /// `shorter_than` is the exact `|pq| < t`.
    #[test]
    fn rounded_keys_decide_only_what_is_certain() {
        let mut rng = StdRng::seed_from_u64(2027);
        let (mut decided, mut ties) = (0, 0);
        let pairs = mixed_pairs(&mut rng);
        for &([a, b], [c, d]) in &pairs {
            let exact = exact_squared(a, b).cmp(&exact_squared(c, d));
            ties += usize::from(exact == Ordering::Equal);
            let keys = (rounded_squared_length(a, b), rounded_squared_length(c, d));
            if let Some(o) = compare_rounded_keys(keys.0, keys.1) {
                assert_eq!(o, exact, "{a:?}{b:?} vs {c:?}{d:?}");
                decided += 1;
            }
            // `|ab| < |cd|` through a threshold equal to `|cd|` when that
            // length is a double (the square root of the exact square).
            let t = keys.1.sqrt();
            let threshold = num_rational::BigRational::from_float(t).unwrap();
            let want = exact_squared(a, b) < &threshold * &threshold;
            assert_eq!(super::super::shorter_than(a, b, t), want);
        }
        assert!(ties > 500, "{ties}");
        assert!(decided > pairs.len() / 3, "{decided} of {}", pairs.len());
    }

    /// Sorting by rounded keys, then re-sorting each run that
    /// `in_one_key_run` joins by the exact order, gives the exact order, on
    /// lengths equal up to rounding; and the runs stay as short as the
    /// near-ties allow.
    #[test]
    fn key_runs_contain_every_disorder() {
        let mut rng = StdRng::seed_from_u64(2028);
        let mut segments: Vec<[Point; 2]> = Vec::new();
        for &(s, t) in &mixed_pairs(&mut rng) {
            segments.push(s);
            segments.push(t);
        }
        segments.sort_by(|s, t| {
            rounded_squared_length(s[0], s[1]).total_cmp(&rounded_squared_length(t[0], t[1]))
        });
        let mut start = 0;
        let mut longest = 0;
        for end in 1..=segments.len() {
            let joined = end < segments.len() && {
                let [s, t] = [segments[end - 1], segments[end]];
                in_one_key_run(
                    rounded_squared_length(s[0], s[1]),
                    rounded_squared_length(t[0], t[1]),
                )
            };
            if !joined {
                segments[start..end]
                    .sort_by(|s, t| exact_squared(s[0], s[1]).cmp(&exact_squared(t[0], t[1])));
                longest = longest.max(end - start);
                start = end;
            }
        }
        for w in segments.windows(2) {
            assert!(exact_squared(w[0][0], w[0][1]) <= exact_squared(w[1][0], w[1][1]));
        }
        // The longest runs are the chords of one offset of a sampled circle
        // (400 segments equal up to rounding), not the whole list.
        assert!(longest <= 400, "{longest} of {}", segments.len());
    }
}
