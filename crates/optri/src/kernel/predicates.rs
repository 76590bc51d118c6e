//! Exact geometric predicates on `f64` points.
//!
//! Orientation and in-circle come from the `robust` crate (Shewchuk's
//! adaptive predicates); only their *sign* is used. Length and dot-product
//! comparisons use a floating-point filter and fall back to exact
//! [`Expansion`] arithmetic when the filter cannot decide.

use super::expansion::{two_diff, Expansion};
use super::Point;
use std::cmp::Ordering;

/// Unit roundoff of `f64` (2⁻⁵³).
const U: f64 = f64::EPSILON * 0.5;

#[inline]
fn coord(p: Point) -> robust::Coord<f64> {
    robust::Coord { x: p[0], y: p[1] }
}

/// Exact sign of the orientation determinant: `1` if `a, b, c` turn
/// counter-clockwise, `-1` if clockwise, `0` if collinear.
#[inline]
pub fn orient_sign(a: Point, b: Point, c: Point) -> i32 {
    let d = robust::orient2d(coord(a), coord(b), coord(c));
    (d > 0.0) as i32 - (d < 0.0) as i32
}

/// Exact in-circle test: `1` if `d` lies strictly inside the circle through
/// the counter-clockwise triangle `a, b, c`, `-1` if strictly outside, `0` if on it.
#[inline]
pub fn incircle_sign(a: Point, b: Point, c: Point, d: Point) -> i32 {
    let v = robust::incircle(coord(a), coord(b), coord(c), coord(d));
    if v > 0.0 {
        1
    } else if v < 0.0 {
        -1
    } else {
        0
    }
}

/// Exact comparison of squared Euclidean lengths: `|ab|²` versus `|cd|²`.
///
/// Never computes a rounded length: a filtered `f64` evaluation decides
/// clear cases, and an exact expansion of `(a-b)² - (c-d)²` decides the rest.
pub fn compare_lengths(a: Point, b: Point, c: Point, d: Point) -> Ordering {
    let (dx1, dy1, dx2, dy2) = (a[0] - b[0], a[1] - b[1], c[0] - d[0], c[1] - d[1]);
    let l1 = dx1 * dx1 + dy1 * dy1;
    let l2 = dx2 * dx2 + dy2 * dy2;
    let diff = l1 - l2;
    // Each squared length carries relative error below 4u (one rounded
    // difference squared, one product, one sum); the subtraction adds u.
    let bound = 8.0 * U * (l1 + l2);
    if diff > bound {
        return Ordering::Greater;
    }
    if -diff > bound {
        return Ordering::Less;
    }
    exact_length_difference_sign(a, b, c, d).cmp(&0)
}

/// `|ab|² - |cd|²` evaluated exactly; returns its sign.
fn exact_length_difference_sign(a: Point, b: Point, c: Point, d: Point) -> i32 {
    let mut e = Expansion::new();
    for k in 0..2 {
        let (h, l) = two_diff(a[k], b[k]);
        e.add_square(h, l, 1.0);
        let (h, l) = two_diff(c[k], d[k]);
        e.add_square(h, l, -1.0);
    }
    e.sign()
}

/// Exact sign of the dot product `(a - o) · (b - o)`.
///
/// Negative iff the angle `a o b` is obtuse, i.e. iff `o` lies strictly inside
/// the circle with diameter `ab` (Thales); zero iff `o` is on that circle.
pub fn dot_sign(o: Point, a: Point, b: Point) -> i32 {
    let (ax, ay, bx, by) = (a[0] - o[0], a[1] - o[1], b[0] - o[0], b[1] - o[1]);
    let v = ax * bx + ay * by;
    let bound = 8.0 * U * ((ax * bx).abs() + (ay * by).abs());
    if v > bound {
        return 1;
    }
    if -v > bound {
        return -1;
    }
    let mut e = Expansion::new();
    for k in 0..2 {
        e.add_two_term_product(two_diff(a[k], o[k]), two_diff(b[k], o[k]), 1.0);
    }
    e.sign()
}

/// Exact comparison of triangle areas `|abc|` versus `|def|` (unsigned).
///
/// A filtered `f64` evaluation decides clear cases, an exact expansion the
/// rest. Each doubled area `D = l − r`, `l = (b−a)ₓ(c−a)_y`,
/// `r = (b−a)_y(c−a)ₓ`, is computed with error at most
/// `(3u + 16u²)(|l̃| + |r̃|) < 4u·S` (Shewchuk's `ccwerrboundA`, stated for
/// the rounded products; no underflow or overflow in the kernel's coordinate
/// range). So `|D₁| − |D₂| ≥ Ã₁ − Ã₂ − 4u(S₁ + S₂)`, and a rounded
/// difference `Ã₁ − Ã₂` above `8u(S₁ + S₂)` (its own and the bound's
/// rounding cost less than a relative `3u`) proves `|D₁| > |D₂|`.
pub fn compare_areas(tri1: [Point; 3], tri2: [Point; 3]) -> Ordering {
    let rounded = |[a, b, c]: [Point; 3]| {
        let l = (b[0] - a[0]) * (c[1] - a[1]);
        let r = (b[1] - a[1]) * (c[0] - a[0]);
        ((l - r).abs(), l.abs() + r.abs())
    };
    let ((a1, s1), (a2, s2)) = (rounded(tri1), rounded(tri2));
    let diff = a1 - a2;
    let bound = 8.0 * U * (s1 + s2);
    if diff > bound {
        return Ordering::Greater;
    }
    if -diff > bound {
        return Ordering::Less;
    }
    exact_area_comparison(tri1, tri2)
}

/// `|D₁|` versus `|D₂|` by exact expansions.
fn exact_area_comparison(tri1: [Point; 3], tri2: [Point; 3]) -> Ordering {
    let s1 = orient_sign(tri1[0], tri1[1], tri1[2]) as f64;
    let s2 = orient_sign(tri2[0], tri2[1], tri2[2]) as f64;
    // |D1| - |D2| = s1*D1 - s2*D2, with D = (b-a)x(c-a) expanded exactly.
    let mut e = Expansion::new();
    for (tri, s) in [(tri1, s1), (tri2, -s2)] {
        if s == 0.0 {
            continue;
        }
        let [a, b, c] = tri;
        let (bax, bay) = (two_diff(b[0], a[0]), two_diff(b[1], a[1]));
        let (cax, cay) = (two_diff(c[0], a[0]), two_diff(c[1], a[1]));
        e.add_two_term_product(bax, cay, s);
        e.add_two_term_product(bay, cax, -s);
    }
    e.sign().cmp(&0)
}

/// Exact counter-clockwise angular order of directions `a - o` and `b - o`,
/// starting from the positive x-axis.
pub fn compare_angles(o: Point, a: Point, b: Point) -> Ordering {
    let half = |p: Point| -> u8 {
        // 0 for angles in [0, π), 1 for [π, 2π).
        if p[1] > o[1] || (p[1] == o[1] && p[0] > o[0]) {
            0
        } else {
            1
        }
    };
    half(a)
        .cmp(&half(b))
        .then_with(|| match orient_sign(o, a, b) {
            1 => Ordering::Less,
            -1 => Ordering::Greater,
            // Same ray (a farther or nearer) or opposite rays already split by half.
            _ => {
                debug_assert!(dot_sign(o, a, b) > 0 || half(a) != half(b));
                Ordering::Equal
            }
        })
}

/// Exact: do the open segments `ab` and `cd` cross in a single interior point?
#[inline]
pub fn properly_cross(a: Point, b: Point, c: Point, d: Point) -> bool {
    let (abc, abd) = (orient_sign(a, b, c), orient_sign(a, b, d));
    if abc * abd >= 0 {
        return false;
    }
    orient_sign(c, d, a) * orient_sign(c, d, b) < 0
}

/// Exact: does `z` lie on the open segment `ab`?
#[inline]
pub fn on_open_segment(z: Point, a: Point, b: Point) -> bool {
    orient_sign(a, b, z) == 0 && dot_sign(z, a, b) < 0
}

/// Exact: do the closed segments `ab` and `cd` share a point? Collinear
/// segments intersect iff their coordinate intervals overlap (the same test
/// on x and on y, so vertical segments need no special case).
pub fn segments_intersect(a: Point, b: Point, c: Point, d: Point) -> bool {
    let (abc, abd) = (orient_sign(a, b, c), orient_sign(a, b, d));
    let (cda, cdb) = (orient_sign(c, d, a), orient_sign(c, d, b));
    if abc * abd > 0 || cda * cdb > 0 {
        return false;
    }
    if abc != 0 || abd != 0 || cda != 0 || cdb != 0 {
        return true;
    }
    // All four collinear: compare the intervals exactly (min/max never round).
    (0..2).all(|k| a[k].min(b[k]) <= c[k].max(d[k]) && c[k].min(d[k]) <= a[k].max(b[k]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cmp::Ordering::*;

    #[test]
    fn orientation_of_near_collinear_points_is_exact() {
        // c is one ulp off the line through a and b.
        let a = [0.5, 0.5];
        let b = [12.0, 12.0];
        let c = [24.0, 24.0];
        assert_eq!(orient_sign(a, b, c), 0);
        let c_up = [24.0, f64::from_bits(24f64.to_bits() + 1)];
        assert_eq!(orient_sign(a, b, c_up), 1);
        let c_down = [24.0, f64::from_bits(24f64.to_bits() - 1)];
        assert_eq!(orient_sign(a, b, c_down), -1);
    }

    #[test]
    fn incircle_sign_convention() {
        let (a, b, c) = ([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]);
        assert_eq!(incircle_sign(a, b, c, [0.5, 0.5]), 1);
        assert_eq!(incircle_sign(a, b, c, [1.0, 1.0]), 0);
        assert_eq!(incircle_sign(a, b, c, [2.0, 2.0]), -1);
    }

    #[test]
    fn equal_lengths_compare_equal_even_when_f64_rounding_differs() {
        // 3-4-5 and 5-0: equal exactly.
        assert_eq!(
            compare_lengths([0.0, 0.0], [3.0, 4.0], [1.0, 1.0], [6.0, 1.0]),
            Equal
        );
        // Lengths differing by 2^-100 relative: invisible to f64, seen exactly.
        let x = 1.0 + 2f64.powi(-52);
        assert_eq!(
            compare_lengths([0.0, 0.0], [x, 0.0], [0.0, 0.0], [0.0, 1.0]),
            Greater
        );
        // (1e8+1e-8)^2 vs (1e8)^2 + 2: d1^2 = 1e16 + 2 + 1e-16 > 1e16 + 2.
        let big = 1e8;
        let tiny = 1e-8;
        let sq2 = 2f64.sqrt();
        let _ = sq2;
        assert_eq!(
            compare_lengths([0.0, 0.0], [big, tiny], [0.0, 0.0], [big, 0.0]),
            Greater
        );
        assert_eq!(
            compare_lengths([big, 0.0], [0.0, 0.0], [0.0, 0.0], [big, tiny]),
            Less
        );
    }

    #[test]
    fn huge_and_negative_coordinates_compare_exactly() {
        let h = 2f64.powi(200);
        let a = [-h, -h];
        let b = [h, h];
        let c = [-h, h];
        let d = [h, -h];
        assert_eq!(compare_lengths(a, b, c, d), Equal);
        let d2 = [h, f64::from_bits((-h).to_bits() + 1)]; // -h - ulp: farther
        assert_eq!(compare_lengths(a, b, c, d2), Less);
    }

    #[test]
    fn tiny_coordinates_compare_exactly() {
        let t = 2f64.powi(-140);
        assert_eq!(
            compare_lengths([0.0, 0.0], [3.0 * t, 4.0 * t], [t, t], [6.0 * t, t]),
            Equal
        );
        assert_eq!(
            compare_lengths([0.0, 0.0], [3.0 * t, 4.0 * t], [t, t], [6.0 * t, 1.5 * t]),
            Less
        );
    }

    #[test]
    fn dot_sign_is_thales() {
        let (a, b) = ([-1.0, 0.0], [1.0, 0.0]);
        assert_eq!(dot_sign([0.0, 1.0], a, b), 0);
        assert_eq!(dot_sign([0.0, 0.999], a, b), -1);
        assert_eq!(dot_sign([0.0, 1.001], a, b), 1);
        // (3, 4) is on the circle with diameter (-5, 0)-(5, 0); nudge it by one ulp.
        let (a5, b5) = ([-5.0, 0.0], [5.0, 0.0]);
        assert_eq!(dot_sign([3.0, 4.0], a5, b5), 0);
        assert_eq!(
            dot_sign([3.0, f64::from_bits(4f64.to_bits() - 1)], a5, b5),
            -1
        );
        assert_eq!(
            dot_sign([3.0, f64::from_bits(4f64.to_bits() + 1)], a5, b5),
            1
        );
    }

    #[test]
    fn area_comparison_ignores_orientation_and_is_exact() {
        let t1 = [[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]];
        let t2 = [[0.0, 0.0], [0.0, 4.0], [1.0, 0.0]]; // clockwise, same area
        assert_eq!(compare_areas(t1, t2), Equal);
        let t3 = [[0.0, 0.0], [0.0, 4.0], [1.0 + 2f64.powi(-50), 0.0]];
        assert_eq!(compare_areas(t1, t3), Less);
        let flat = [[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]];
        assert_eq!(compare_areas(flat, t1), Less);
        assert_eq!(compare_areas(flat, flat), Equal);
    }
}
