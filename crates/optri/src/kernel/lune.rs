//! Lunes and half-lunes (H. Edelsbrunner & T. S. Tan, *A quadratic time
//! algorithm for the minmax length triangulation*, 1991, §2, §5).
//!
//! The lune of `pq` is `λ_pq = {x : max(|xp|, |xq|) < |pq|}` (open); the
//! half-lune of the directed edge `p → q` is `η_pq = λ_pq ∩ h_pq`, where
//! `h_pq` is the closed half-plane to the left of or on the line `p → q`.
//! So `λ_pq = η_pq ∪ η_qp`, and a point of the open segment `pq` lies in both.

use super::predicates::compare_lengths;
use super::symbolic::{compare_lengths_symbolic, orient_symbolic};
use super::Point;
use std::cmp::Ordering::Less;

/// Is `x` strictly inside the lune of `pq`? (exact)
#[inline]
pub fn in_lune(p: Point, q: Point, x: Point) -> bool {
    compare_lengths(x, p, p, q) == Less && compare_lengths(x, q, p, q) == Less
}

#[cfg(any(test, feature = "internals"))]
/// Is `x` in the half-lune `η_pq` (lune of `pq`, left of or on `p → q`)? (exact)
#[inline]
pub fn in_half_lune(p: Point, q: Point, x: Point) -> bool {
    super::predicates::orient_sign(p, q, x) >= 0 && in_lune(p, q, x)
}

/// Lune membership under the symbolic perturbation of
/// [the kernel's perturbation](crate::kernel#ties-symbolic-perturbation): indices into `points`.
pub fn in_lune_symbolic(points: &[Point], p: u32, q: u32, x: u32) -> bool {
    x != p
        && x != q
        && compare_lengths_symbolic(points, [x, p], [p, q]) == Less
        && compare_lengths_symbolic(points, [x, q], [p, q]) == Less
}

/// Half-lune membership under the symbolic perturbation (the perturbed point
/// is never on the line, so the half-plane is open or closed alike).
pub fn in_half_lune_symbolic(points: &[Point], p: u32, q: u32, x: u32) -> bool {
    in_lune_symbolic(points, p, q, x) && orient_symbolic(points, p, q, x) > 0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lune_is_open() {
        let (p, q) = ([0.0, 0.0], [2.0, 0.0]);
        assert!(in_lune(p, q, [1.0, 0.0]));
        assert!(in_lune(p, q, [1.0, 1.7]));
        // On the boundary circle around p: |xp| = |pq| exactly, not inside.
        assert!(!in_lune(p, q, [1.2, 1.6]));
        assert!(!in_lune(p, q, p));
        assert!(!in_lune(p, q, q));
        assert!(!in_lune(p, q, [3.0, 0.0]));
    }

    #[test]
    fn half_lunes_cover_the_lune_and_share_the_segment() {
        let (p, q) = ([0.0, 0.0], [2.0, 0.0]);
        assert!(in_half_lune(p, q, [1.0, 0.5]));
        assert!(!in_half_lune(q, p, [1.0, 0.5]));
        assert!(in_half_lune(q, p, [1.0, -0.5]));
        assert!(in_half_lune(p, q, [1.0, 0.0]) && in_half_lune(q, p, [1.0, 0.0]));
    }

    #[test]
    fn symbolic_lune_breaks_the_boundary_case_consistently() {
        // x on the circle (p, |pq|): exactly not in the lune; symbolically it is
        // in or out, and never both in η_pq and η_qp.
        let pts = [[0.0, 0.0], [2.0, 0.0], [1.2, 1.6], [1.0, 0.0]];
        let in_up = in_half_lune_symbolic(&pts, 0, 1, 2);
        let in_down = in_half_lune_symbolic(&pts, 1, 0, 2);
        assert!(!(in_up && in_down));
        // A point on the open segment is in exactly one perturbed half-lune.
        assert!(in_half_lune_symbolic(&pts, 0, 1, 3) != in_half_lune_symbolic(&pts, 1, 0, 3));
    }
}
