//! The corner predicate of polygon cycles: is a direction strictly inside the
//! wedge that a boundary sweeps at a corner?
//!
//! A region to the left of a counter-clockwise boundary walk `… → last → o →
//! first → …` occupies, near the corner `o`, the wedge that sweeps
//! counter-clockwise from the ray `o → first` to the ray `o → last`. Weakly
//! simple cycles (H. Edelsbrunner & T. S. Tan, *A quadratic time algorithm
//! for the minmax length triangulation*, SIAM J. Comput. 22, 1993, §3:
//! regions whose zero-width cracks are walked on both sides) need two rules
//! that simple polygons never meet: at the tip of a crack the two rays
//! coincide and the wedge is the *full turn* minus that ray, and a straight
//! corner (opposite rays) is the open half-plane to the left of `o → first`.
//! Every chord test of a polygon cycle (is it a diagonal, does a candidate
//! edge leave a corner into the region) starts here.

use super::predicates::{dot_sign, orient_sign};
use super::symbolic::orient_symbolic;
use super::Point;

/// Is the direction `x − o` strictly inside the counter-clockwise wedge at
/// `o` from the ray `o → first` to the ray `o → last`? Exact.
///
/// Measure angles counter-clockwise from the ray `o → first`, and let `θ`
/// be the angle of the ray `o → last`, taken as `2π` when the two rays
/// coincide (a full turn, the tip of a crack). The answer is whether the
/// angle of `x − o` lies in the open interval `(0, θ)`. A zero direction
/// (`x = o`) is in no wedge: `false`.
///
/// *Proof of the case analysis.* With `f = orient(o, first, x)`,
/// `l = orient(o, last, x)`, the sign `f > 0` says the angle of `x` is in
/// `(0, π)`, `f < 0` in `(π, 2π)`, and `l` says the same relative to `θ`.
/// * `orient(o, first, last) > 0`, so `θ ∈ (0, π)`: inside iff `f > 0`
///   and `l < 0`, as `(0, π) ∩ (θ − π, θ) = (0, θ)`.
/// * `orient(o, first, last) < 0`, so `θ ∈ (π, 2π)`: the complement of
///   `(0, θ)` is the closed short wedge `[θ, 2π] ∪ {0}` from `last` to
///   `first`, which is `{l ≥ 0} ∩ {f ≤ 0}` (the intersection of
///   `[θ, θ + π]` and `{0} ∪ [π, 2π)` has no part in `[π, θ − π]`, empty as
///   `θ < 2π`); inside iff not both.
/// * Collinear rays pointing apart, `θ = π`: inside iff `f > 0`.
/// * Collinear rays pointing the same way, `θ = 2π`: inside iff `x − o`
///   is not on the ray `o → first`, i.e. unless `f = 0` and
///   `(first − o)·(x − o) > 0`.
///
/// # Panics
/// If `first = o` or `last = o`: a zero-length ray bounds no wedge.
pub fn strictly_inside_wedge(o: Point, first: Point, last: Point, x: Point) -> bool {
    assert!(
        first != o && last != o,
        "strictly_inside_wedge: a ray of the wedge has zero length"
    );
    if x == o {
        return false;
    }
    inside_wedge_by(orient_sign, dot_sign, o, first, last, x)
}

/// [`strictly_inside_wedge`] on the kernel's perturbed points (module docs
/// of the kernel, "Ties"), with points given by their indices into
/// `points` (distinct points): no three distinct indices are collinear
/// there, so the two rays coincide only when `first = last`, and `x` is
/// on the ray `o → first` only when `x = first`.
///
/// # Panics
/// If `first = o` or `last = o`.
pub fn strictly_inside_wedge_symbolic(
    points: &[Point],
    o: u32,
    first: u32,
    last: u32,
    x: u32,
) -> bool {
    assert!(
        first != o && last != o,
        "strictly_inside_wedge_symbolic: a ray of the wedge has zero length"
    );
    if x == o {
        return false;
    }
    // A repeated index is a zero orientation; for distinct indices the
    // perturbed orientation is never zero. The dot product is read only
    // for a repeated index, where the perturbed and the exact sign are
    // both the squared distance's, positive.
    let orient = |a: u32, b: u32, c: u32| {
        if a == b || b == c || a == c {
            0
        } else {
            orient_symbolic(points, a, b, c)
        }
    };
    let p = |m: u32| points[m as usize];
    inside_wedge_by(
        orient,
        |a, b, c| dot_sign(p(a), p(b), p(c)),
        o,
        first,
        last,
        x,
    )
}

/// Does `x − o` point the same way as `r − o` (both non-zero)? Exact: the
/// ray rule of [`strictly_inside_wedge`] (a direction on a bounding ray is
/// not inside).
pub fn same_direction(o: Point, r: Point, x: Point) -> bool {
    orient_sign(o, r, x) == 0 && dot_sign(o, r, x) > 0
}

/// The case analysis of [`strictly_inside_wedge`] over any orientation and
/// dot-product signs of labelled points (`o`, `first`, `last`, `x` with
/// non-zero directions from `o`).
#[inline]
fn inside_wedge_by<V: Copy>(
    orient: impl Fn(V, V, V) -> i32,
    dot: impl Fn(V, V, V) -> i32,
    o: V,
    first: V,
    last: V,
    x: V,
) -> bool {
    let left_of_first = orient(o, first, x);
    match orient(o, first, last) {
        1 => left_of_first > 0 && orient(o, last, x) < 0,
        -1 => !(orient(o, last, x) >= 0 && left_of_first <= 0),
        _ => {
            if dot(o, first, last) < 0 {
                left_of_first > 0
            } else {
                !(left_of_first == 0 && dot(o, first, x) > 0)
            }
        }
    }
}
