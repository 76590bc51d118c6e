//! An angle floor given in degrees, and the exact test of a corner against
//! it: the angle condition of an *α-triangulation* (every angle at least
//! α; T. S. Vassilev, *Optimal area triangulation*, PhD thesis, University
//! of Saskatchewan, 2005, §3.4, Algorithm 76).
//!
//! The floor is the decimal the user wrote: a double `α` stands for its
//! shortest decimal representation (`25.3` is 253/10 degrees, not the
//! double nearest it), kept as an exact rational. A corner's angle `θ` has a
//! rational tangent `|u×v|/(u·v)`, while `tan α` is irrational unless α is
//! 0° or 45° (Niven's theorem), so the test is a chain of exact decisions:
//!
//! 1. `u·v ≤ 0`: `θ ≥ 90° > α`.
//! 2. Two doubles `t⁻ < tan α < t⁺`, certified once when the floor is built
//!    (the corner `(0,0), (1,0), (1,t)` has angle `atan t`, compared with α
//!    by step 4): `|u×v| ≥ t⁺·(u·v)` means `θ > α`, `|u×v| < t⁻·(u·v)` means
//!    `θ < α` (the kernel's `tangent_side`, a float filter with an exact
//!    fallback).
//! 3. Otherwise `θ` lies within a few units in the last place of α: it is
//!    compared with the rational α exactly by enclosing it in degrees to
//!    growing precision (the kernel's arctangent and Machin's π), which ends
//!    because `θ` is a multiple of 45° (decided exactly) or irrational in
//!    degrees.
//!
//! No comparison is ever left undecided or rounded: a corner of exactly 45°
//! meets a floor of 45°, and one a hair below any floor fails it.

use super::degrees::compare_corner_with_degrees;
use super::predicates::{dot_sign, tangent_side};
use super::Point;
use num_bigint::BigUint;
use num_traits::Zero;
use std::cmp::Ordering;

/// The smallest positive floor accepted, in degrees: below it the tangent
/// bounds would leave the range the kernel's expansions are exact in.
pub const MIN_ANGLE_FLOOR_DEGREES: f64 = 1e-9;

/// An angle floor `α` in degrees, `0 ≤ α < 90`, with its exact value and
/// certified tangent bounds (module docs). Two floors are equal when they
/// hold the same decimal.
#[derive(Clone, Debug)]
pub struct AngleFloor {
    degrees: f64,
    /// α = `numerator / denominator` degrees, exactly.
    numerator: BigUint,
    denominator: BigUint,
    /// `tan_below < tan α < tan_above` (unused for α = 0).
    tan_below: f64,
    tan_above: f64,
}

impl PartialEq for AngleFloor {
    fn eq(&self, other: &Self) -> bool {
        self.numerator == other.numerator && self.denominator == other.denominator
    }
}

impl Eq for AngleFloor {}

impl AngleFloor {
    /// The floor of `degrees` (its shortest decimal, module docs), or
    /// `None` unless it is 0 or in
    /// `[`[`MIN_ANGLE_FLOOR_DEGREES`]`, 90)`.
    pub fn new(degrees: f64) -> Option<Self> {
        if !(degrees == 0.0 || (MIN_ANGLE_FLOOR_DEGREES..90.0).contains(&degrees)) {
            return None;
        }
        let (numerator, denominator) = shortest_decimal(degrees);
        let mut floor = AngleFloor {
            degrees,
            numerator,
            denominator,
            tan_below: 0.0,
            tan_above: 0.0,
        };
        if degrees > 0.0 {
            let guess = degrees.to_radians().tan();
            floor.tan_above = floor.tangent_bound(guess, Ordering::Greater);
            floor.tan_below = floor.tangent_bound(guess, Ordering::Less);
        }
        Some(floor)
    }

    /// The floor in degrees, as given.
    pub fn degrees(&self) -> f64 {
        self.degrees
    }

    /// Exact: the angle at `o` between the rays to `a` and `b` (neither
    /// equal to `o`) against the floor.
    pub fn compare(&self, o: Point, a: Point, b: Point) -> Ordering {
        if self.numerator.is_zero() {
            return compare_corner_with_degrees(o, a, b, &self.numerator, &self.denominator);
        }
        if dot_sign(o, a, b) <= 0 {
            return Ordering::Greater; // at least 90°
        }
        // tangent_side(t) > 0 iff θ < atan t.
        if tangent_side(o, a, b, self.tan_above, 1.0) <= 0 {
            return Ordering::Greater; // θ ≥ atan t⁺ > α
        }
        if tangent_side(o, a, b, self.tan_below, 1.0) > 0 {
            return Ordering::Less; // θ < atan t⁻ < α
        }
        compare_corner_with_degrees(o, a, b, &self.numerator, &self.denominator)
    }

    /// Exact: is the angle at `o` between the rays to `a` and `b` at least
    /// the floor?
    #[inline]
    pub fn admits(&self, o: Point, a: Point, b: Point) -> bool {
        self.numerator.is_zero() || self.compare(o, a, b) != Ordering::Less
    }

    /// Does every angle of the triangle `abc` meet the floor?
    pub fn admits_triangle(&self, a: Point, b: Point, c: Point) -> bool {
        self.admits(a, b, c) && self.admits(b, c, a) && self.admits(c, a, b)
    }

    /// A double `t` from `guess` with `atan t` strictly on the side `side`
    /// of α, decided exactly: steps of about 2⁻⁴⁰ relative, doubling,
    /// away from α until the corner `(0,0), (1,0), (1,t)` is on that side.
    fn tangent_bound(&self, guess: f64, side: Ordering) -> f64 {
        let direction = if side == Ordering::Greater { 1.0 } else { -1.0 };
        let mut step = guess * 2f64.powi(-40);
        let mut t = guess;
        loop {
            let corner = compare_corner_with_degrees(
                [0.0, 0.0],
                [1.0, 0.0],
                [1.0, t],
                &self.numerator,
                &self.denominator,
            );
            if corner == side {
                return t;
            }
            t += direction * step;
            step *= 2.0;
        }
    }
}

/// `v ≥ 0` as `numerator / denominator`, from its shortest decimal
/// representation (Rust's `{:e}` formatting: the fewest digits that read
/// back as `v`).
fn shortest_decimal(v: f64) -> (BigUint, BigUint) {
    let text = format!("{v:e}");
    let (mantissa, exponent) = text.split_once('e').expect("{:e} writes an exponent");
    let exponent: i64 = exponent.parse().expect("{:e} writes an integer exponent");
    let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let digits: BigUint = format!("{whole}{fraction}")
        .parse()
        .expect("{:e} writes decimal digits");
    let power = exponent - fraction.len() as i64;
    let ten = |k: i64| BigUint::from(10u32).pow(k as u32);
    if power >= 0 {
        (digits * ten(power), BigUint::from(1u32))
    } else {
        (digits, ten(-power))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shortest_decimals_are_the_written_ones() {
        let ratio = |v: f64| {
            let (n, d) = shortest_decimal(v);
            (n.to_string(), d.to_string())
        };
        assert_eq!(ratio(25.3), ("253".into(), "10".into()));
        assert_eq!(ratio(30.0), ("30".into(), "1".into()));
        assert_eq!(ratio(0.0), ("0".into(), "1".into()));
        assert_eq!(ratio(1e-9), ("1".into(), "1000000000".into()));
    }

    #[test]
    fn tangent_bounds_enclose_the_floor() {
        for degrees in [1e-9, 0.5, 10.0, 25.3, 30.0, 44.999, 45.0, 59.9, 89.5] {
            let floor = AngleFloor::new(degrees).unwrap();
            assert!(floor.tan_below < floor.tan_above, "{degrees}");
            let tan = degrees.to_radians().tan();
            assert!((floor.tan_above / tan - 1.0).abs() < 1e-9, "{degrees}");
            assert!((floor.tan_below / tan - 1.0).abs() < 1e-9, "{degrees}");
        }
        assert!(AngleFloor::new(90.0).is_none());
        assert!(AngleFloor::new(-1.0).is_none());
        assert!(AngleFloor::new(f64::NAN).is_none());
        assert!(AngleFloor::new(1e-12).is_none());
    }

    #[test]
    fn exact_multiples_of_45_meet_their_floor() {
        let o = [0.0, 0.0];
        let floor = AngleFloor::new(45.0).unwrap();
        assert_eq!(floor.compare(o, [1.0, 0.0], [3.0, 3.0]), Ordering::Equal);
        assert!(floor.admits(o, [1.0, 0.0], [3.0, 3.0]));
        // A hair below 45°: tan = 1 − 2⁻⁵².
        let below = [1.0, 1.0 - f64::EPSILON];
        assert_eq!(floor.compare(o, [1.0, 0.0], below), Ordering::Less);
        let zero = AngleFloor::new(0.0).unwrap();
        assert!(zero.admits(o, [1.0, 0.0], [1.0, 1e-30]));
    }
}
