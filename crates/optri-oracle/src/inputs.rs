//! Exactly degenerate test inputs shared by the test suites.

use crate::exact::Point;

/// All integer points on the circle `x² + y² = r²` (every sign and
/// coordinate-swap variant of the Pythagorean triples): exactly cocircular.
pub fn integer_circle_points(r: i64) -> Vec<Point> {
    let mut v = Vec::new();
    for x in -r..=r {
        let y2 = r * r - x * x;
        let y = (y2 as f64).sqrt().round() as i64;
        if y * y == y2 {
            v.push([x as f64, y as f64]);
            if y != 0 {
                v.push([x as f64, -y as f64]);
            }
        }
    }
    v
}
