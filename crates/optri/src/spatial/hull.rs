//! The convex hull of distinct points as a counter-clockwise cycle, with
//! points on hull edges kept as vertices (Edelsbrunner & Tan, *A quadratic
//! time algorithm for the minmax length triangulation*, 1991, §2).
//!
//! Andrew's monotone chain (A. M. Andrew, *Another efficient algorithm for
//! convex hulls in two dimensions*, 1979) with exact orientation, O(n log n),
//! after the throw-away step of S. G. Akl & G. T. Toussaint (*A fast convex
//! hull algorithm*, 1978): points strictly inside the polygon of a few
//! extreme points cannot be on the hull, so only the others are sorted.

use crate::kernel::{orient_sign, Point};
use crate::parallel::prelude::*;
use std::cmp::Ordering;

/// Below this many points the throw-away step is skipped (a chosen size:
/// the sort is cheap there; the result does not depend on it).
const THROW_AWAY_MIN_POINTS: usize = 1024;

/// Distinct-point indices of the hull in counter-clockwise order, starting at
/// the lexicographically smallest point; points on hull edges are included.
pub(crate) fn convex_hull_cycle(points: &[Point]) -> Vec<u32> {
    let all = || (0..points.len() as u32).collect();
    if points.len() < THROW_AWAY_MIN_POINTS {
        return monotone_chain(points, all());
    }
    let polygon = extreme_polygon(points);
    if polygon.len() < 3 || !is_strictly_convex_cycle(points, &polygon) {
        return monotone_chain(points, all());
    }
    // Strictly inside a convex polygon of input points is strictly inside
    // the hull: such a point is neither a hull vertex nor on a hull edge.
    let inside = |p: Point| {
        let k = polygon.len();
        (0..k).all(|c| {
            let (a, b) = (
                points[polygon[c] as usize],
                points[polygon[(c + 1) % k] as usize],
            );
            orient_sign(a, b, p) > 0
        })
    };
    let kept: Vec<u32> = (0..points.len() as u32)
        .into_par_iter()
        .filter(|&i| !inside(points[i as usize]))
        .collect();
    monotone_chain(points, kept)
}

/// The hull cycle of up to eight extreme points: the extremes in `x`, `y`,
/// `x + y` and `x − y` (rounded sums: any input points would do, these
/// make the polygon large).
fn extreme_polygon(points: &[Point]) -> Vec<u32> {
    let keys: [fn(Point) -> f64; 4] = [|p| p[0], |p| p[1], |p| p[0] + p[1], |p| p[0] - p[1]];
    let mut extremes: Vec<u32> = Vec::with_capacity(8);
    for key in keys {
        let (mut lo, mut hi) = (0usize, 0usize);
        for (i, &p) in points.iter().enumerate() {
            if key(p) < key(points[lo]) {
                lo = i;
            }
            if key(p) > key(points[hi]) {
                hi = i;
            }
        }
        extremes.extend([lo as u32, hi as u32]);
    }
    extremes.sort_unstable();
    extremes.dedup();
    monotone_chain(points, extremes)
}

/// Andrew's monotone chain over the points `order` (indices into `points`).
fn monotone_chain(points: &[Point], mut order: Vec<u32>) -> Vec<u32> {
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

/// The *empty apexes* of the hull edge `ab` (consecutive counter-clockwise
/// hull points): every `r` strictly left of `a → b` whose closed triangle
/// `abr` holds no other point. Every triangulation has exactly one triangle
/// on `ab`, and it is one of these (it uses every point as a vertex and no
/// point lies on the open segment `ab`).
///
/// The closed triangle is the intersection of the closed wedges at `a` and
/// `b` with the half-plane, so `r` is empty iff no other point `q` of the
/// open half-plane has both `∠baq ≤ ∠bar` and `∠abq ≤ ∠abr`: sorting by the
/// angle at `a` (ties by the angle at `b`) and keeping the strict running
/// minima of the angle at `b` finds them, all by orientation tests, in
/// `O(n log n)`. Listed by increasing angle at `a`; `inner` is scratch space.
pub(crate) fn empty_apexes(points: &[Point], a: u32, b: u32, inner: &mut Vec<u32>) -> Vec<u32> {
    let p = |v: u32| points[v as usize];
    let (pa, pb) = (p(a), p(b));
    inner.clear();
    inner.extend((0..points.len() as u32).filter(|&r| orient_sign(pa, pb, p(r)) > 0));
    // Both angles are compared by orientations: at a counter-clockwise from
    // ab, at b clockwise from ba.
    inner.sort_unstable_by(|&q, &r| match orient_sign(pa, p(q), p(r)) {
        1 => Ordering::Less,
        -1 => Ordering::Greater,
        _ => orient_sign(pb, p(q), p(r)).cmp(&0),
    });
    let mut lowest_at_b: Option<u32> = None;
    let mut apexes = Vec::new();
    for &r in inner.iter() {
        if lowest_at_b.is_none_or(|m| orient_sign(pb, p(m), p(r)) > 0) {
            lowest_at_b = Some(r);
            apexes.push(r);
        }
    }
    apexes
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{rngs::StdRng, Rng, SeedableRng};

    /// The throw-away step keeps the cycle of the plain monotone chain, on
    /// random points, integer grids (many points on hull edges), points on
    /// a circle and a few points far out.
    #[test]
    fn throwing_interior_points_away_keeps_the_hull() {
        let mut rng = StdRng::seed_from_u64(3);
        for case in 0..40 {
            let n = rng.gen_range(THROW_AWAY_MIN_POINTS..4 * THROW_AWAY_MIN_POINTS);
            let points: Vec<Point> = match case % 4 {
                0 => (0..n)
                    .map(|_| [rng.gen_range(-1.0..1.0), rng.gen_range(-1e9..1e9)])
                    .collect(),
                1 => {
                    let side = (n as f64).sqrt() as i32;
                    (0..side * side)
                        .map(|i| [f64::from(i % side), f64::from(i / side)])
                        .collect()
                }
                2 => (0..n)
                    .map(|i| {
                        let t = i as f64 / n as f64 * std::f64::consts::TAU;
                        [t.cos(), t.sin()]
                    })
                    .collect(),
                _ => {
                    let mut p: Vec<Point> = (0..n)
                        .map(|_| [rng.gen_range(0.0..1.0), rng.gen_range(0.0..1.0)])
                        .collect();
                    p.extend([[50.0, 0.5], [0.5, -50.0], [-3.0, 7.0]]);
                    p
                }
            };
            let plain = monotone_chain(&points, (0..points.len() as u32).collect());
            assert!(plain.len() >= 3);
            // The throw-away step runs (its polygon is a proper one).
            let polygon = extreme_polygon(&points);
            assert!(
                polygon.len() >= 3 && is_strictly_convex_cycle(&points, &polygon),
                "case {case}: {polygon:?}"
            );
            assert_eq!(convex_hull_cycle(&points), plain, "case {case}");
        }
    }
}
