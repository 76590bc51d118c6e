//! Floating-point measures for *reporting* (lengths, areas, angles).
//!
//! These values are rounded and never used for combinatorial decisions;
//! comparisons go through the exact predicates of [`crate::kernel`].

use super::Point;

/// Euclidean length `|ab|` (rounded).
#[inline]
pub fn length(a: Point, b: Point) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// Unsigned area of triangle `abc` (rounded).
#[inline]
pub fn area(a: Point, b: Point, c: Point) -> f64 {
    0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).abs()
}

/// The three interior angles of triangle `abc` in degrees (at `a`, `b`, `c`).
pub fn angles_deg(a: Point, b: Point, c: Point) -> [f64; 3] {
    let angle = |o: Point, u: Point, v: Point| {
        let (ux, uy, vx, vy) = (u[0] - o[0], u[1] - o[1], v[0] - o[0], v[1] - o[1]);
        (ux * vy - uy * vx)
            .abs()
            .atan2(ux * vx + uy * vy)
            .to_degrees()
    };
    [angle(a, b, c), angle(b, c, a), angle(c, a, b)]
}
