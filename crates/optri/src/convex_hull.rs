//! Convex hull with collinear boundary points as vertices
//! (000_5891e11f36dd26ad.txt §2: "we think of each such point as a vertex").
//!
//! Andrew's monotone chain with exact orientation, O(n log n).

use crate::kernel::{orient_sign, Point};
use crate::point_set::PointSet;

/// Distinct-point indices of the hull in counter-clockwise order, starting at
/// the lexicographically smallest point; points on hull edges are included.
pub(crate) fn hull_distinct(points: &[Point]) -> Vec<u32> {
    let mut order: Vec<u32> = (0..points.len() as u32).collect();
    order.sort_unstable_by(|&a, &b| {
        let (p, q) = (points[a as usize], points[b as usize]);
        p[0].total_cmp(&q[0]).then(p[1].total_cmp(&q[1]))
    });
    let mut hull: Vec<u32> = Vec::with_capacity(points.len());
    let chain = |hull: &mut Vec<u32>, idx: &mut dyn Iterator<Item = u32>, floor: usize| {
        for i in idx {
            // Pop only on a strict right turn, so collinear points stay.
            while hull.len() >= floor + 2
                && orient_sign(
                    points[hull[hull.len() - 2] as usize],
                    points[hull[hull.len() - 1] as usize],
                    points[i as usize],
                ) < 0
            {
                hull.pop();
            }
            hull.push(i);
        }
    };
    chain(&mut hull, &mut order.iter().copied(), 0);
    hull.pop();
    let lower_len = hull.len();
    chain(&mut hull, &mut order.iter().rev().copied(), lower_len);
    hull.pop();
    hull
}

/// The convex hull of `points` as input indices in counter-clockwise order.
///
/// Points lying on a hull edge are vertices of the hull, so consecutive
/// entries are joined by edges that contain no other input point.
pub fn convex_hull(points: &PointSet) -> Vec<u32> {
    hull_distinct(points.points())
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
