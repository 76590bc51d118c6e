//! Exact comparisons of triangle areas with a decimal threshold.
//!
//! A user asks "is there a triangulation whose smallest triangle has area at
//! least `0.005`?" (T. S. Vassilev, *Optimal Area Triangulation*, PhD
//! thesis, University of Saskatchewan, 2005, §2.4: the decision problem of
//! Algorithm 49). The threshold is a decimal, usually not a binary double,
//! and the front end may have scaled the points by `10^k` (decimal input):
//! the threshold on the *doubled* area of the points the algorithms see is
//! then `θ = 2 · m · 10^(e + 2k)`, an exact rational `M · 10^x` that
//! [`AreaThreshold`] compares with `|orient(a, b, c)|` without rounding.
//!
//! # Why the comparison is exact
//! `x ≥ 0`: `θ` is an integer, built as an expansion by exact products
//! (`M` in three chunks below 2⁵³, then factors `10^s`, `s ≤ 22`, which are
//! exact doubles). `x < 0`: the doubled area's expansion is multiplied by
//! `10^(−x)` the same way and compared with `M`. Overflow and underflow are
//! ruled out before: coordinates in the kernel's range
//! ([`MIN_COORDINATE`](super::MIN_COORDINATE)`..=`[`MAX_COORDINATE`](super::MAX_COORDINATE))
//! are multiples of 2⁻¹⁹⁴ of magnitude at most 2²⁰¹, so a doubled area is 0
//! or in `[2⁻³⁸⁸, 2⁴⁰⁵]`; a `θ` outside `[2⁻⁴²⁰, 2⁴²⁰]` is decided by that
//! alone, and inside it every product stays below 2⁹⁵⁴ and above 2⁻⁹⁰⁰.
//!
//! # Filter
//! `θ` is bracketed once by `[θ₋, θ₊] = θ̃ · (1 ∓ 10⁻¹²)`, where `θ̃` is the
//! rounded sum of the expansion divided by rounded powers of ten: at most
//! 30 rounded operations, relative error below `30u ≈ 3.3·10⁻¹⁵`. A
//! triangle's doubled area `D` is approximated by `D̃ = |l − r|` (`l`, `r`
//! the rounded products of rounded differences) with
//! `|D − D̃| ≤ (3u + 16u²)(|l| + |r|)`, as for orientation. Taking
//! `ε = 8u(|l| + |r|)` leaves `4u(|l| + |r|) ≥ 4u·D̃` of slack, which covers
//! the rounding of `D̃ ∓ ε` itself, so `fl(D̃ − ε) > θ₊` proves `D > θ` and
//! `fl(D̃ + ε) < θ₋` proves `D < θ`. Below `|l| + |r| < 2⁻⁹⁰⁰` (subnormal
//! products possible) the filter is skipped.

use super::expansion::{two_diff, Expansion};
use super::{orient_sign, Point, UNIT_ROUNDOFF as U};
use std::cmp::Ordering;

/// Largest power of ten that is an exact double.
const EXACT_POWER_OF_TEN: u32 = 22;

/// `10^s` for `s ≤ 22`, each literal an exact double.
const POWERS_OF_TEN: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// A threshold on doubled triangle areas, `θ = mantissa · 10^exponent`
/// (`θ ≥ 0`), compared exactly with the doubled area `|orient(a, b, c)|` of
/// points in the kernel's coordinate range.
///
/// ```
/// use optri::kernel::AreaThreshold;
/// use std::cmp::Ordering;
/// // Doubled area 0.3 (= 3 · 10⁻¹) against a triangle of doubled area 0.3
/// // written in decimals scaled by 10: doubled area 30 against θ = 30.
/// let theta = AreaThreshold::new(3, 1);
/// assert_eq!(theta.compare([[0.0, 0.0], [6.0, 0.0], [0.0, 5.0]]), Ordering::Equal);
/// // 0.1 is no double; the decimal one-tenth is compared exactly.
/// let tenth = AreaThreshold::new(1, -1);
/// assert_eq!(tenth.compare([[0.0, 0.0], [0.1, 0.0], [0.0, 1.0]]), Ordering::Greater);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct AreaThreshold {
    range: Range,
}

#[derive(Clone, Debug, PartialEq)]
enum Range {
    /// `θ = 0`.
    Zero,
    /// `0 < θ < 2⁻⁴²⁰`: below every positive doubled area.
    BelowEveryArea,
    /// `θ > 2⁴²⁰`: above every doubled area.
    AboveEveryArea,
    /// Compare `D · 10^scale` with the expansion `terms` (increasing
    /// magnitude, non-overlapping); `θ` lies in `[low, high]`.
    Exact {
        scale: u32,
        terms: Vec<f64>,
        low: f64,
        high: f64,
    },
}

impl AreaThreshold {
    /// The threshold `mantissa · 10^exponent` on doubled areas.
    pub fn new(mantissa: u128, exponent: i64) -> Self {
        if mantissa == 0 {
            return Self { range: Range::Zero };
        }
        // log₂ θ to within far less than the margins of 15 around the
        // range [2⁻³⁸⁸, 2⁴⁰⁵] of doubled areas.
        let log2 = (mantissa as f64).log2() + exponent as f64 * std::f64::consts::LOG2_10;
        if log2 > 420.0 {
            return Self {
                range: Range::AboveEveryArea,
            };
        }
        if log2 < -420.0 {
            return Self {
                range: Range::BelowEveryArea,
            };
        }
        let mut value = Expansion::new();
        let mask = (1u128 << 53) - 1;
        for shift in [0u32, 53, 106] {
            // Each chunk is below 2⁵³, times a power of two: exact.
            let chunk = ((mantissa >> shift) & mask) as f64;
            value.add(chunk * 2f64.powi(shift as i32));
        }
        let scale = if exponent >= 0 {
            value = times_power_of_ten(value, exponent as u32);
            0
        } else {
            exponent.unsigned_abs() as u32
        };
        let terms = value.components().to_vec();
        let mut estimate: f64 = terms.iter().sum();
        let mut left = scale;
        while left > 0 {
            let step = left.min(EXACT_POWER_OF_TEN);
            estimate /= POWERS_OF_TEN[step as usize];
            left -= step;
        }
        Self {
            range: Range::Exact {
                scale,
                terms,
                low: estimate * (1.0 - 1e-12),
                high: estimate * (1.0 + 1e-12),
            },
        }
    }

    /// The doubled area of `tri` compared with `θ`: `Greater` when the
    /// doubled area is larger. Exact (coordinates in the kernel's range).
    pub fn compare(&self, tri: [Point; 3]) -> Ordering {
        let [a, b, c] = tri;
        let (scale, terms, low, high) = match &self.range {
            Range::Zero => return orient_sign(a, b, c).abs().cmp(&0),
            Range::BelowEveryArea => {
                return if orient_sign(a, b, c) == 0 {
                    Ordering::Less
                } else {
                    Ordering::Greater
                }
            }
            Range::AboveEveryArea => return Ordering::Less,
            Range::Exact {
                scale,
                terms,
                low,
                high,
            } => (*scale, terms, *low, *high),
        };
        let l = (b[0] - a[0]) * (c[1] - a[1]);
        let r = (b[1] - a[1]) * (c[0] - a[0]);
        let permanent = l.abs() + r.abs();
        if permanent >= 2f64.powi(-900) {
            let approximate = (l - r).abs();
            let error = 8.0 * U * permanent;
            if approximate - error > high {
                return Ordering::Greater;
            }
            if approximate + error < low {
                return Ordering::Less;
            }
        }
        let sign = orient_sign(a, b, c) as f64;
        let mut doubled = Expansion::new();
        if sign != 0.0 {
            doubled.add_two_term_product(two_diff(b[0], a[0]), two_diff(c[1], a[1]), sign);
            doubled.add_two_term_product(two_diff(b[1], a[1]), two_diff(c[0], a[0]), -sign);
        }
        let mut difference = times_power_of_ten(doubled, scale);
        for &t in terms {
            difference.add(-t);
        }
        difference.sign().cmp(&0)
    }
}

/// `value · 10^power`, exactly: factors `10^s`, `s ≤ 22`, are exact doubles
/// and each product is expanded exactly (the callers keep it in range).
fn times_power_of_ten(mut value: Expansion, mut power: u32) -> Expansion {
    while power > 0 {
        let step = power.min(EXACT_POWER_OF_TEN);
        let mut scaled = Expansion::new();
        scaled.add_scaled(&value, POWERS_OF_TEN[step as usize]);
        value = scaled;
        power -= step;
    }
    value
}
