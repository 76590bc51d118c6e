//! Exact comparisons of per-triangle measures for the edge-insertion
//! criteria (M. Bern, H. Edelsbrunner, D. Eppstein, S. Mitchell & T. S. Tan,
//! *Edge insertion for optimal triangulations*, Discrete Comput. Geom. 10,
//! 1993; H. Edelsbrunner, T. S. Tan & R. Waupotitsch, *An O(n² log n) time
//! algorithm for the minmax angle triangulation*, SIAM J. Sci. Stat.
//! Comput. 13, 1992): the largest angle, the smallest height, the
//! (absolute) eccentricity and the slope of a triangle, with each measure's
//! anchor vertex and a correctly rounded value for reports.
//!
//! For a triangle `abc` write `u = b − a`, `v = c − a`, `cr = u × v`
//! (`|cr|` is twice the area) and `ℓ²(pq)` for a squared side. The measures,
//! in the squared forms that are rational in the coordinates:
//!
//! | measure | exact form | degree of a comparison |
//! |---|---|---|
//! | largest angle | the corner opposite the longest side, compared as the vector `(dot, \|cr\|)` | 4 |
//! | smallest height | `h² = cr² / max ℓ²` | 6 |
//! | eccentricity (distance from the circumcentre to the closed triangle) | 0 without an obtuse corner; at an obtuse `a`: `ℓ²(bc)·dot_a² / (4 cr²)` | 10 |
//! | slope (gradient of the linear interpolant of `z`) | `(n_x² + n_y²) / cr²` for the normal `n = (u, z_b − z_a) × (v, z_c − z_a)` | 8 |
//!
//! Angles are compared by the kernel's corner-angle predicate. The other
//! three overflow or underflow f64 expansions for extreme coordinates
//! (degree up to 10), so they are evaluated in interval arithmetic first
//! ([`Interval`]: every operation's rounded result widened by `4u`
//! relative, `u = 2⁻⁵³`, which covers its rounding error; any non-finite
//! result, or a non-zero magnitude outside `[2⁻⁹⁰⁰, 2⁹⁰⁰]` where underflow
//! could hide error, abandons the filter); when the enclosures of two
//! triangles overlap, or the filter is abandoned, the values are computed
//! exactly as `BigRational`s (every finite f64 is an exact rational).
//!
//! # Anchors
//! An anchor of a worst triangle is the vertex from which every better
//! triangulation has an edge crossing the opposite side (Bern et al.,
//! §3–§8). Angle, height and eccentricity anchor at the vertex opposite
//! the longest side (the largest, resp. the obtuse, corner). Slope anchors
//! at the *gradient-line vertex*: the vertex whose line parallel to the
//! gradient passes through the triangle, i.e. the middle vertex in the
//! direction perpendicular to the gradient (not the middle elevation).
//! Ties (isosceles triangles, a side parallel to the gradient) go to the
//! vertex that comes first in the order the corners were given.

use super::expansion::{two_diff, two_product, two_sum};
use super::predicates::{compare_corner_angles, compare_lengths, dot_sign};
use super::reporting::angle_deg;
use super::rounding::{round_ratio, Rounding};
use super::{Point, UNIT_ROUNDOFF};
use num_bigint::BigUint;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

/// A triangle measure; larger is worse except for [`Self::SmallestHeight`],
/// whose larger values are better.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum TriangleMeasure {
    /// The largest interior angle.
    LargestAngle,
    /// The smallest altitude.
    SmallestHeight,
    /// The distance from the circumcentre to the closed triangle.
    Eccentricity,
    /// The gradient magnitude of the linear interpolant of the elevations.
    Slope,
}

/// A triangle's corners and their elevations (zeros where unused).
pub(crate) type Corners = ([Point; 3], [f64; 3]);

impl TriangleMeasure {
    /// Compares the measure's *values* of two triangles exactly (for
    /// [`Self::SmallestHeight`] a larger value is a better triangle).
    pub(crate) fn compare_values(self, s: &Corners, t: &Corners) -> Ordering {
        if self == TriangleMeasure::LargestAngle {
            let (p, q) = (s.0, t.0);
            let (i, j) = (longest_side_vertex(p), longest_side_vertex(q));
            return compare_corner_angles(rotate(p, i), rotate(q, j));
        }
        if let (Some(a), Some(b)) = (self.enclosure(s), self.enclosure(t)) {
            if a.hi < b.lo {
                return Ordering::Less;
            }
            if a.lo > b.hi {
                return Ordering::Greater;
            }
        }
        self.exact_squared(s).cmp(&self.exact_squared(t))
    }

    /// Compares the *badness* of two triangles: `Greater` when `s` is the
    /// worse one.
    pub(crate) fn compare_badness(self, s: &Corners, t: &Corners) -> Ordering {
        let values = self.compare_values(s, t);
        match self {
            TriangleMeasure::SmallestHeight => values.reverse(),
            _ => values,
        }
    }

    /// The position of the worst of `triangles` (exact; ties: the first),
    /// `None` when there is none.
    pub(crate) fn worst(self, triangles: impl Iterator<Item = Corners>) -> Option<usize> {
        self.worst_ties(triangles).first().copied()
    }

    /// The positions of every worst triangle of `triangles` (all tied at
    /// the worst value, in order). The worst so far keeps its enclosure and,
    /// once needed, its exact value, so each triangle is enclosed once and
    /// computed exactly at most once, only when the enclosures overlap (ties,
    /// common on lattices, need it for every triangle).
    pub(crate) fn worst_ties(self, triangles: impl Iterator<Item = Corners>) -> Vec<usize> {
        let mut ties = Vec::new();
        if self == TriangleMeasure::LargestAngle {
            let mut best: Option<Corners> = None;
            for (i, t) in triangles.enumerate() {
                let order = best
                    .as_ref()
                    .map_or(Ordering::Greater, |b| self.compare_badness(&t, b));
                if order == Ordering::Greater {
                    ties.clear();
                    best = Some(t);
                }
                if order != Ordering::Less {
                    ties.push(i);
                }
            }
            return ties;
        }
        // The worst so far: corners, enclosure, and once needed its exact
        // value and sorted sides.
        type Worst = (
            Corners,
            Option<Interval>,
            Option<BigRational>,
            Option<SortedSides>,
        );
        let mut best: Option<Worst> = None;
        for (i, t) in triangles.enumerate() {
            let enclosure = self.enclosure(&t);
            let mut exact = None;
            let badness = match &mut best {
                None => Ordering::Greater,
                Some((b, be, b_exact, b_sides)) => {
                    let values = match (enclosure, *be) {
                        (Some(x), Some(y)) if x.hi < y.lo => Ordering::Less,
                        (Some(x), Some(y)) if x.lo > y.hi => Ordering::Greater,
                        // Congruent triangles tie in every measure but the
                        // slope (a lattice's Delaunay triangles all do).
                        _ if self != TriangleMeasure::Slope
                            && congruent(
                                &sorted_sides(t.0),
                                b_sides.get_or_insert_with(|| sorted_sides(b.0)),
                            ) =>
                        {
                            Ordering::Equal
                        }
                        _ => {
                            let v = self.exact_squared(&t);
                            let order = v.cmp(b_exact.get_or_insert_with(|| self.exact_squared(b)));
                            exact = Some(v);
                            order
                        }
                    };
                    match self {
                        TriangleMeasure::SmallestHeight => values.reverse(),
                        _ => values,
                    }
                }
            };
            if badness == Ordering::Greater {
                ties.clear();
                best = Some((t, enclosure, exact, None));
            }
            if badness != Ordering::Less {
                ties.push(i);
            }
        }
        ties
    }

    /// The anchor vertex (0, 1 or 2) of the triangle (module docs).
    pub(crate) fn anchor(self, t: &Corners) -> usize {
        match self {
            TriangleMeasure::Slope => gradient_line_vertex(t),
            _ => longest_side_vertex(t.0),
        }
    }

    /// The measure's value for reports: degrees for angles, lengths for the
    /// others (square roots of the exact squared forms), correctly rounded.
    pub(crate) fn reported(self, t: &Corners) -> f64 {
        self.reported_over_power_of_ten(t, 0)
    }

    /// [`Self::reported`] for corners that are `10^k` times the user's
    /// coordinates (decimal input; elevations are never scaled): heights
    /// and eccentricities are lengths, divided by `10^k`; a slope is an
    /// elevation over a length, multiplied by `10^k`; angles do not change.
    /// Rounded once, from the exact value.
    pub(crate) fn reported_over_power_of_ten(self, t: &Corners, k: i32) -> f64 {
        let squared = match self {
            TriangleMeasure::LargestAngle => {
                let i = longest_side_vertex(t.0);
                let [a, b, c] = rotate(t.0, i);
                return angle_deg(a, b, c);
            }
            TriangleMeasure::Slope => self.exact_squared(t) * power_of_ten(2 * k),
            _ => self.exact_squared(t) * power_of_ten(-2 * k),
        };
        rounded_square_root(&squared)
    }

    /// The squared value (cosine key for angles), exactly.
    fn exact_squared(self, t: &Corners) -> BigRational {
        let ([a, b, c], z) = *t;
        let r = |v: f64| BigRational::from_float(v).expect("finite coordinates");
        let d = |p: Point, q: Point, k: usize| r(p[k]) - r(q[k]);
        let (ux, uy, vx, vy) = (d(b, a, 0), d(b, a, 1), d(c, a, 0), d(c, a, 1));
        let cr = &ux * &vy - &uy * &vx;
        let cr2 = &cr * &cr;
        let sq = |p: Point, q: Point| {
            let (x, y) = (d(p, q, 0), d(p, q, 1));
            &x * &x + &y * &y
        };
        match self {
            TriangleMeasure::LargestAngle => {
                // −cos θ·|cos θ| at the largest corner, increasing in θ.
                let [o, p, q] = rotate([a, b, c], longest_side_vertex([a, b, c]));
                let (px, py, qx, qy) = (d(p, o, 0), d(p, o, 1), d(q, o, 0), d(q, o, 1));
                let dot = &px * &qx + &py * &qy;
                let key = &dot * &dot / (sq(p, o) * sq(q, o));
                if dot.is_negative() {
                    key
                } else {
                    -key
                }
            }
            TriangleMeasure::SmallestHeight => {
                let longest = [sq(a, b), sq(b, c), sq(c, a)]
                    .into_iter()
                    .max()
                    .expect("three sides");
                cr2 / longest
            }
            TriangleMeasure::Eccentricity => match obtuse_vertex(t.0) {
                None => BigRational::zero(),
                Some(i) => {
                    let [o, p, q] = rotate([a, b, c], i);
                    let (px, py, qx, qy) = (d(p, o, 0), d(p, o, 1), d(q, o, 0), d(q, o, 1));
                    let dot = &px * &qx + &py * &qy;
                    sq(p, q) * &dot * &dot / (cr2 * BigRational::from_integer(4.into()))
                }
            },
            TriangleMeasure::Slope => {
                let (uz, vz) = (r(z[1]) - r(z[0]), r(z[2]) - r(z[0]));
                let nx = &uy * &vz - &uz * &vy;
                let ny = &uz * &vx - &ux * &vz;
                (&nx * &nx + &ny * &ny) / cr2
            }
        }
    }

    /// An enclosure of [`Self::exact_squared`] (angles excepted), or `None`
    /// when the filter cannot vouch for one.
    fn enclosure(self, t: &Corners) -> Option<Interval> {
        let ([a, b, c], z) = *t;
        let d = |p: Point, q: Point, k: usize| Interval::difference(p[k], q[k]);
        let (ux, uy, vx, vy) = (d(b, a, 0)?, d(b, a, 1)?, d(c, a, 0)?, d(c, a, 1)?);
        let cr2 = ux.mul(vy)?.sub(uy.mul(vx)?)?.square()?;
        let sq = |p: Point, q: Point| d(p, q, 0)?.square()?.add(d(p, q, 1)?.square()?);
        match self {
            TriangleMeasure::LargestAngle => None,
            TriangleMeasure::SmallestHeight => {
                let (l1, l2, l3) = (sq(a, b)?, sq(b, c)?, sq(c, a)?);
                let longest = Interval {
                    lo: l1.lo.max(l2.lo).max(l3.lo),
                    hi: l1.hi.max(l2.hi).max(l3.hi),
                };
                cr2.div(longest)
            }
            TriangleMeasure::Eccentricity => match obtuse_vertex(t.0) {
                None => Some(Interval { lo: 0.0, hi: 0.0 }),
                Some(i) => {
                    let [o, p, q] = rotate([a, b, c], i);
                    let dot = d(p, o, 0)?
                        .mul(d(q, o, 0)?)?
                        .add(d(p, o, 1)?.mul(d(q, o, 1)?)?)?;
                    sq(p, q)?
                        .mul(dot.square()?)?
                        .div(cr2.mul(Interval { lo: 4.0, hi: 4.0 })?)
                }
            },
            TriangleMeasure::Slope => {
                let (uz, vz) = (
                    Interval::difference(z[1], z[0])?,
                    Interval::difference(z[2], z[0])?,
                );
                let nx = uy.mul(vz)?.sub(uz.mul(vy)?)?;
                let ny = uz.mul(vx)?.sub(ux.mul(vz)?)?;
                nx.square()?.add(ny.square()?)?.div(cr2)
            }
        }
    }
}

/// A triangle's sides, shortest first (exact), and their squared lengths
/// when every one is exactly a double (lattices: then congruence is three
/// comparisons of doubles).
#[derive(Clone, Copy)]
struct SortedSides {
    sides: [[Point; 2]; 3],
    exact: Option<[f64; 3]>,
}

/// `|pq|²` when the differences, their squares and the sum are all exact
/// in floating point.
fn squared_length_if_exact(p: Point, q: Point) -> Option<f64> {
    let (dx, ex) = two_diff(q[0], p[0]);
    let (dy, ey) = two_diff(q[1], p[1]);
    let (xx, exx) = two_product(dx, dx);
    let (yy, eyy) = two_product(dy, dy);
    let (sum, es) = two_sum(xx, yy);
    // Away from underflow, a zero error term of the fused multiply-add
    // means an exact square.
    let normal = |d: f64| d == 0.0 || d.abs() >= 2f64.powi(-400);
    let exact = [ex, ey, exx, eyy, es].iter().all(|&e| e == 0.0)
        && normal(dx)
        && normal(dy)
        && sum.is_finite();
    exact.then_some(sum)
}

fn sorted_sides(p: [Point; 3]) -> SortedSides {
    let mut sides = [[p[0], p[1]], [p[1], p[2]], [p[2], p[0]]];
    let lengths: Option<Vec<f64>> = sides
        .iter()
        .map(|s| squared_length_if_exact(s[0], s[1]))
        .collect();
    if let Some(mut l) = lengths {
        l.sort_by(f64::total_cmp);
        return SortedSides {
            sides,
            exact: Some([l[0], l[1], l[2]]),
        };
    }
    sides.sort_by(|x, y| compare_lengths(x[0], x[1], y[0], y[1]));
    SortedSides { sides, exact: None }
}

/// Are triangles with these sorted sides congruent (equal side lengths)?
fn congruent(a: &SortedSides, b: &SortedSides) -> bool {
    if let (Some(x), Some(y)) = (a.exact, b.exact) {
        return x == y;
    }
    let (a, b) = (sorted_by_length(a), sorted_by_length(b));
    (0..3).all(|k| compare_lengths(a[k][0], a[k][1], b[k][0], b[k][1]) == Ordering::Equal)
}

/// The sides shortest first (those with exact lengths were not sorted).
fn sorted_by_length(s: &SortedSides) -> [[Point; 2]; 3] {
    let mut sides = s.sides;
    if s.exact.is_some() {
        sides.sort_by(|x, y| compare_lengths(x[0], x[1], y[0], y[1]));
    }
    sides
}

/// The corners rotated so that corner `i` comes first (orientation kept).
fn rotate<T: Copy>(t: [T; 3], i: usize) -> [T; 3] {
    [t[i], t[(i + 1) % 3], t[(i + 2) % 3]]
}

/// The vertex opposite the longest side (exact); among equal longest sides
/// the first vertex in the given order.
pub(crate) fn longest_side_vertex(t: [Point; 3]) -> usize {
    let opposite = |i: usize| (t[(i + 1) % 3], t[(i + 2) % 3]);
    let mut best = 0;
    for i in 1..3 {
        let ((a, b), (c, d)) = (opposite(i), opposite(best));
        if compare_lengths(a, b, c, d) == Ordering::Greater {
            best = i;
        }
    }
    best
}

/// The obtuse corner, if any (exact).
fn obtuse_vertex(t: [Point; 3]) -> Option<usize> {
    (0..3).find(|&i| {
        let [o, p, q] = rotate(t, i);
        dot_sign(o, p, q) < 0
    })
}

/// The slope's anchor: the middle vertex in the direction perpendicular to
/// the gradient, i.e. ordered by `n_y·x − n_x·y`; ties keep the given
/// order (a stable sort).
fn gradient_line_vertex(t: &Corners) -> usize {
    let ([a, b, c], z) = *t;
    let r = |v: f64| BigRational::from_float(v).expect("finite coordinates");
    let (ux, uy, vx, vy) = (
        r(b[0]) - r(a[0]),
        r(b[1]) - r(a[1]),
        r(c[0]) - r(a[0]),
        r(c[1]) - r(a[1]),
    );
    let (uz, vz) = (r(z[1]) - r(z[0]), r(z[2]) - r(z[0]));
    let nx = &uy * &vz - &uz * &vy;
    let ny = &uz * &vx - &ux * &vz;
    // Projections relative to a (a common shift does not change the order).
    let projection = [
        BigRational::zero(),
        &ny * &ux - &nx * &uy,
        &ny * &vx - &nx * &vy,
    ];
    let mut order = [0, 1, 2];
    order.sort_by(|&i, &j| projection[i].cmp(&projection[j]));
    order[1]
}

/// `√r` for a rational `r ≥ 0`, correctly rounded to the nearest double:
/// `s = ⌊√(r·4^K)⌋` brackets `√r` in `[s, s + 1)·2^−K`, and `K` grows until
/// both ends round to the same double (an exact square root stops the loop
/// at once).
/// `10^e` as an exact rational.
fn power_of_ten(e: i32) -> BigRational {
    let p = BigRational::from_integer(num_bigint::BigInt::from(10u8).pow(e.unsigned_abs()));
    if e < 0 {
        p.recip()
    } else {
        p
    }
}

fn rounded_square_root(r: &BigRational) -> f64 {
    if r.is_zero() {
        return 0.0;
    }
    let (num, den) = (r.numer().magnitude(), r.denom().magnitude());
    // √r ≈ 2^((bits(num) − bits(den))/2): aim for about 64 + extra bits.
    let magnitude = (num.bits() as i64 - den.bits() as i64) / 2;
    let mut k = 70 - magnitude;
    loop {
        let scaled = shifted_quotient(num, den, 2 * k);
        let s = scaled.sqrt();
        let exact = &s * &s == scaled && exact_shift(num, den, 2 * k);
        let low = round_ratio(&s, &BigUint::from(1u8), -k, Rounding::Nearest);
        if exact {
            return low;
        }
        let high = round_ratio(&(&s + 1u8), &BigUint::from(1u8), -k, Rounding::Nearest);
        if low == high {
            return low;
        }
        k += 64;
    }
}

/// `⌊num·2^e / den⌋` for any integer `e`.
fn shifted_quotient(num: &BigUint, den: &BigUint, e: i64) -> BigUint {
    if e >= 0 {
        (num << e as usize) / den
    } else {
        num / (den << (-e) as usize)
    }
}

/// Is `num·2^e / den` an integer?
fn exact_shift(num: &BigUint, den: &BigUint, e: i64) -> bool {
    if e >= 0 {
        ((num << e as usize) % den).is_zero()
    } else {
        (num % (den << (-e) as usize)).is_zero()
    }
}

/// A closed interval `[lo, hi]` known to contain an exact real; each
/// operation rounds to nearest and then widens both ends by `4u` relative,
/// which covers the rounding of the operation and of the widening itself
/// (a rounded result is within `u` relative of the exact one when it is
/// normal). Results that are not finite, or non-zero with a magnitude
/// outside `[2⁻⁹⁰⁰, 2⁹⁰⁰]`, give `None`; so does a product or quotient that
/// rounds to zero from non-zero operands (underflow).
#[derive(Clone, Copy, Debug)]
struct Interval {
    lo: f64,
    hi: f64,
}

const FILTER_MIN: f64 = f64::from_bits((1023 - 900) << 52);
const FILTER_MAX: f64 = f64::from_bits((1023 + 900) << 52);

fn in_filter_range(x: f64) -> bool {
    x == 0.0 || (FILTER_MIN..=FILTER_MAX).contains(&x.abs())
}

impl Interval {
    fn widened(lo: f64, hi: f64) -> Option<Interval> {
        if !(in_filter_range(lo) && in_filter_range(hi)) {
            return None;
        }
        let w = 4.0 * UNIT_ROUNDOFF;
        Some(Interval {
            lo: lo - lo.abs() * w,
            hi: hi + hi.abs() * w,
        })
    }

    /// `p − q`, enclosed.
    fn difference(p: f64, q: f64) -> Option<Interval> {
        let d = p - q;
        if d == 0.0 && p != q {
            return None;
        }
        Interval::widened(d, d)
    }

    fn add(self, o: Interval) -> Option<Interval> {
        Interval::widened(self.lo + o.lo, self.hi + o.hi)
    }

    fn sub(self, o: Interval) -> Option<Interval> {
        Interval::widened(self.lo - o.hi, self.hi - o.lo)
    }

    fn mul(self, o: Interval) -> Option<Interval> {
        let products = [
            (self.lo, o.lo),
            (self.lo, o.hi),
            (self.hi, o.lo),
            (self.hi, o.hi),
        ];
        let mut lo = f64::INFINITY;
        let mut hi = f64::NEG_INFINITY;
        for (x, y) in products {
            let p = x * y;
            if p == 0.0 && x != 0.0 && y != 0.0 {
                return None;
            }
            lo = lo.min(p);
            hi = hi.max(p);
        }
        Interval::widened(lo, hi)
    }

    fn square(self) -> Option<Interval> {
        let (a, b) = (self.lo.abs(), self.hi.abs());
        let low = if self.lo <= 0.0 && self.hi >= 0.0 {
            0.0
        } else {
            a.min(b)
        };
        let high = a.max(b);
        let (l2, h2) = (low * low, high * high);
        if (l2 == 0.0 && low != 0.0) || (h2 == 0.0 && high != 0.0) {
            return None;
        }
        Interval::widened(l2, h2)
    }

    /// `self / o` for a positive divisor enclosure.
    fn div(self, o: Interval) -> Option<Interval> {
        if o.lo <= 0.0 {
            return None;
        }
        let quotients = [
            self.lo / o.hi,
            self.lo / o.lo,
            self.hi / o.hi,
            self.hi / o.lo,
        ];
        if quotients
            .iter()
            .zip([self.lo, self.lo, self.hi, self.hi])
            .any(|(&q, x)| q == 0.0 && x != 0.0)
        {
            return None;
        }
        let lo = quotients.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = quotients.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Interval::widened(lo, hi)
    }
}

/// The exact squared value of a measure, for tests against independent
/// evaluations.
#[cfg(test)]
pub(crate) fn exact_squared_value(measure: TriangleMeasure, t: &Corners) -> BigRational {
    measure.exact_squared(t)
}

#[cfg(test)]
mod tests;
