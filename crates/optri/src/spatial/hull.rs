//! The convex hull of distinct points as a counter-clockwise cycle, with
//! points on hull edges kept as vertices (Edelsbrunner & Tan, *A quadratic
//! time algorithm for the minmax length triangulation*, 1991, §2).
//!
//! Andrew's monotone chain (A. M. Andrew, *Another efficient algorithm for
//! convex hulls in two dimensions*, 1979) with exact orientation, O(n log n).

use crate::kernel::{orient_sign, Point};

/// Distinct-point indices of the hull in counter-clockwise order, starting at
/// the lexicographically smallest point; points on hull edges are included.
pub(crate) fn convex_hull_cycle(points: &[Point]) -> Vec<u32> {
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

/// Does the cycle (indices into `points`) turn strictly left at every
/// vertex? For a hull cycle that means no three hull vertices are collinear:
/// the points are in strictly convex position.
pub(crate) fn is_strictly_convex_cycle(points: &[Point], cycle: &[u32]) -> bool {
    let k = cycle.len();
    let p = |c: usize| points[cycle[c % k] as usize];
    (0..k).all(|c| orient_sign(p(c), p(c + 1), p(c + 2)) > 0)
}
