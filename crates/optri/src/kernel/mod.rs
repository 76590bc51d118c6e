//! The exact geometry kernel: predicates, the symbolic tie-break, lunes and
//! reporting metrics.
//!
//! Every combinatorial decision in optri (orientation, in-circle, which of two
//! lengths or areas is larger, lune membership) is made here, exactly.
//!
//! # Coordinate range
//! Exactness of the expansion arithmetic needs every product of coordinate
//! differences to be free of overflow and underflow. [`crate::PointSet`]
//! therefore accepts a coordinate `v` only if `v == 0` or
//! [`MIN_COORDINATE`] `≤ |v| ≤` [`MAX_COORDINATE`] (the range spade uses for
//! the same reason). Differences of such numbers are multiples of 2⁻¹⁹⁴ and
//! at most 2²⁰², so the degree-4 in-circle expansions stay within
//! `[2⁻⁷⁷⁶, 2⁸⁰⁸]`, far from the subnormal and overflow limits.

pub mod expansion;
pub mod lune;
pub mod metrics;
pub mod predicates;
pub mod symbolic;

/// A point in the plane, `[x, y]`.
pub type Point = [f64; 2];

/// Largest accepted absolute coordinate value, 2²⁰¹.
pub const MAX_COORDINATE: f64 = 3.2138760885179806e60; // 2^201
/// Smallest accepted non-zero absolute coordinate value, 2⁻¹⁴².
pub const MIN_COORDINATE: f64 = 1.793662034335766e-43; // 2^-142

pub use lune::{in_half_lune, in_half_lune_symbolic, in_lune, in_lune_symbolic};
pub use predicates::{
    compare_areas, compare_lengths, dot_sign, incircle_sign, orient, orient_sign, Orientation,
};
pub use symbolic::{compare_lengths_symbolic, orient_symbolic, segment_order};

#[cfg(test)]
mod tests {
    #[test]
    fn range_constants_are_powers_of_two() {
        assert_eq!(super::MAX_COORDINATE, 2f64.powi(201));
        assert_eq!(super::MIN_COORDINATE, 2f64.powi(-142));
    }
}
