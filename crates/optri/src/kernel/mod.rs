//! The exact geometry kernel: predicates, the symbolic tie-break, lunes,
//! certified squared-length keys, the length orders and correctly rounded
//! reporting metrics. Layer 0: it imports nothing else of the crate.
//!
//! Every combinatorial decision in optri (orientation, in-circle, which of two
//! lengths, areas or angles is larger, lune membership, segment crossings) is
//! made here, exactly. Signs are `i32` in `{-1, 0, 1}`; comparisons return
//! [`std::cmp::Ordering`].
//!
//! # Coordinate range
//! Exactness of the expansion arithmetic needs every product of coordinate
//! differences to be free of overflow and underflow. [`crate::PointSet`]
//! therefore accepts a coordinate `v` only if `v == 0` or
//! [`MIN_COORDINATE`] `≤ |v| ≤` [`MAX_COORDINATE`] (the range spade uses for
//! the same reason). Differences of such numbers are multiples of 2⁻¹⁹⁴ and
//! at most 2²⁰², so the degree-4 in-circle expansions stay within
//! `[2⁻⁷⁷⁶, 2⁸⁰⁸]`, far from the subnormal and overflow limits.
//!
//! # Ties: symbolic perturbation
//! The minmax-length and greedy algorithms assume that no two lengths are
//! equal and no three points are collinear. Instead of special cases, optri
//! decides every tie as if the points had been perturbed (Edelsbrunner &
//! Mücke, *Simulation of Simplicity*, ACM TOG 9(1), 1990):
//!
//! ```text
//!   y_m  ←  y_m + ε^(3^(2m))        x_m  ←  x_m + ε^(3^(2m+1))
//! ```
//!
//! for the point with (distinct-point) index `m` and an infinitesimal `ε > 0`.
//! A lower index is perturbed more, and within a point `y` more than `x`.
//! Base 3 (not SoS's base 2) matters: squared lengths contain `ε_v²`, and with
//! base 2 the square of one variable's perturbation would coincide with the
//! next variable's, making the order of monomials ambiguous. With base 3 every
//! monomial of degree ≤ 2 has a distinct exponent, so the sign of any
//! polynomial of degree ≤ 2 per variable is the sign of its first non-zero
//! coefficient in order of increasing exponent. Orientation is multilinear,
//! so its rule is the same as in the original paper.
//!
//! Because all decisions come from one perturbed point set, they are mutually
//! consistent: perturbed lengths are pairwise distinct and perturbed
//! orientations are never zero, for *distinct* input points.

mod angle_floor;
mod area_threshold;
mod certified_incircle;
mod degrees;
mod differences;
pub(crate) mod expansion;
mod extremes;
mod length_order;
pub(crate) mod length_sums;
pub(crate) mod lune;
pub(crate) mod norm;
pub(crate) mod predicates;
pub(crate) mod reporting;
mod rounding;
pub(crate) mod squared_length;
pub(crate) mod symbolic;
mod triangle_measures;
pub(crate) mod wedge;

/// Measures for reporting: lengths, areas, angles and total lengths, each
/// the exact value rounded once to the nearest `f64`. They never decide
/// anything (the predicates above do); they are what a user reads, so a
/// triangle of positive area never reports area 0. How each is rounded:
/// the `reporting` module's docs.
pub mod metrics {
    pub use super::reporting::{angle_deg, angles_deg, area, length, total_length};
}

/// A point in the plane, `[x, y]`.
pub type Point = [f64; 2];

/// The unit roundoff of `f64`, `u = 2⁻⁵³`: a rounded operation's result is
/// `(1 + δ)` times the exact one with `|δ| ≤ u` (no underflow or overflow).
/// Every float filter's error bound is a multiple of it.
pub(crate) const UNIT_ROUNDOFF: f64 = f64::EPSILON * 0.5;

/// Largest accepted absolute coordinate value, 2²⁰¹.
pub const MAX_COORDINATE: f64 = 3.2138760885179806e60; // 2^201
/// Smallest accepted non-zero absolute coordinate value, 2⁻¹⁴².
pub const MIN_COORDINATE: f64 = 1.793662034335766e-43; // 2^-142

pub use angle_floor::{AngleFloor, MIN_ANGLE_FLOOR_DEGREES};
pub use area_threshold::AreaThreshold;
pub(crate) use differences::{
    compare_angle_differences, compare_area_differences, compare_length_differences,
};
pub(crate) use extremes::Extremes;
pub(crate) use length_order::{EuclideanOrder, LengthOrder};
pub use length_sums::compare_length_sums;
pub(crate) use length_sums::LengthInterval;
pub use lune::{in_lune, in_lune_symbolic};
pub(crate) use norm::side_of_direction;
pub use norm::{Metric, MetricProblem, MAX_LP_EXPONENT};
pub(crate) use predicates::shorter_than;
pub(crate) use predicates::{
    angle_at_least_30_degrees, compare_doubled_area, exact_squared_length, DiamondPosition,
    DiamondTriangles,
};
pub use predicates::{
    compare_angles, compare_areas, compare_lengths, incircle_sign, orient_sign, orient_sign_scaled,
    properly_cross, segments_intersect,
};
pub(crate) use predicates::{compare_corner_angles, cross_sign, dot_sign, on_open_segment};
pub(crate) use squared_length::SquaredLength;
pub(crate) use squared_length::{compare_rounded_keys, in_one_key_run, rounded_squared_length};
pub(crate) use symbolic::{compare_equal_lengths_symbolic, segment_order};
pub use symbolic::{compare_lengths_symbolic, orient_symbolic};
pub(crate) use triangle_measures::{Corners, TriangleMeasure};
pub(crate) use wedge::strictly_inside_wedge_symbolic;
pub(crate) use wedge::{same_direction, strictly_inside_wedge};

/// Why a coordinate is not accepted (see the module docs for the range).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CoordinateProblem {
    /// NaN or infinite.
    NonFinite,
    /// Non-zero with `|v|` below [`MIN_COORDINATE`] or above [`MAX_COORDINATE`].
    OutOfRange,
}

/// Checks one coordinate against the exact range of the kernel.
#[inline]
pub fn check_coordinate(v: f64) -> Result<f64, CoordinateProblem> {
    if !v.is_finite() {
        Err(CoordinateProblem::NonFinite)
    } else if v != 0.0 && !(MIN_COORDINATE..=MAX_COORDINATE).contains(&v.abs()) {
        Err(CoordinateProblem::OutOfRange)
    } else {
        Ok(v)
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn range_constants_are_powers_of_two() {
        assert_eq!(super::MAX_COORDINATE, 2f64.powi(201));
        assert_eq!(super::MIN_COORDINATE, 2f64.powi(-142));
    }
}
