//! The convex hull as a graph of input indices, with collinear boundary points
//! as vertices (Edelsbrunner & Tan 1991, §2: "we think of each such point as a
//! vertex"); the cycle itself is [`crate::spatial::convex_hull_cycle`].

use crate::spatial::convex_hull_cycle;
use crate::structures::PointSet;

/// The convex hull of `points` as input indices in counter-clockwise order.
///
/// Points lying on a hull edge are vertices of the hull, so consecutive
/// entries are joined by edges that contain no other input point.
pub fn convex_hull(points: &PointSet) -> Vec<u32> {
    convex_hull_cycle(points.points())
        .into_iter()
        .map(|d| points.input_index(d))
        .collect()
}

/// The hull's edges as input-index pairs `[a, b]`, counter-clockwise.
pub fn convex_hull_edges(points: &PointSet) -> Vec<[u32; 2]> {
    let h = convex_hull(points);
    (0..h.len()).map(|i| [h[i], h[(i + 1) % h.len()]]).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::orient_sign;

    #[test]
    fn collinear_hull_points_are_vertices() {
        let mut pts = Vec::new();
        for x in 0..4 {
            for y in 0..3 {
                pts.push([x as f64, y as f64]);
            }
        }
        let ps = PointSet::new(&pts).unwrap();
        let h = convex_hull(&ps);
        // 4x3 grid: all but the 2 interior points are on the boundary.
        assert_eq!(h.len(), 10);
        for i in 0..h.len() {
            let (a, b, c) = (h[i], h[(i + 1) % h.len()], h[(i + 2) % h.len()]);
            assert!(orient_sign(pts[a as usize], pts[b as usize], pts[c as usize]) >= 0);
        }
    }

    #[test]
    fn triangle_with_points_on_edges() {
        let pts = [
            [0.0, 0.0],
            [4.0, 0.0],
            [0.0, 4.0],
            [2.0, 0.0],
            [2.0, 2.0],
            [0.0, 2.0],
            [1.0, 1.0],
        ];
        let ps = PointSet::new(&pts).unwrap();
        let h = convex_hull(&ps);
        assert_eq!(h, vec![0, 3, 1, 4, 2, 5]);
    }
}
