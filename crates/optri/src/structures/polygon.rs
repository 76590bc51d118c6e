//! [`SimplePolygon`]: a validated simple polygon given by its vertices in
//! boundary order, the input of the polygon criteria (the thesis's
//! decomposable criteria on simple polygons, minimum weight on polygons).

use super::PolygonCycle;
use crate::error::{Error, PolygonProblem, Result};
use crate::kernel::{dot_sign, orient_sign, segments_intersect, Point};
use crate::spatial::is_strictly_convex_cycle;
use crate::structures::PointSet;

/// A simple polygon: at least three distinct vertices in boundary order
/// (either orientation), no repeated vertex, and edges that meet only where
/// consecutive edges share their vertex. A vertex between two collinear edges
/// is allowed (it must then be the corner of some triangle that is not flat).
///
/// Vertex indices everywhere are positions in the caller's ring (`u32`), the
/// closing vertex of a ring that repeats its first vertex not counted.
#[derive(Clone, Debug)]
pub struct SimplePolygon {
    point_set: PointSet,
    /// Ring positions in counter-clockwise order, starting at position 0.
    counter_clockwise: Vec<u32>,
    clockwise_input: bool,
}

impl SimplePolygon {
    /// Validates the ring `vertices` (a last vertex equal to the first is
    /// dropped, as GeoJSON writes rings).
    ///
    /// Simplicity is checked exactly on every pair of edges whose x-ranges
    /// overlap (a sweep over edges sorted by their smallest x): O(n log n + k)
    /// for k such pairs. When k would exceed 16n, the edges are instead added
    /// one by one as constraints of a Delaunay triangulation (expected
    /// O(n log n) plus the triangulation edges they cross), which finds the
    /// first edge that meets an earlier one.
    ///
    /// # Errors
    /// The coordinate errors of [`PointSet::new`], and
    /// [`Error::InvalidPolygon`] naming the repeated vertices or the two edges
    /// that meet.
    pub fn new(vertices: &[Point]) -> Result<Self> {
        let ring = match vertices {
            [first, .., last] if vertices.len() > 3 && first == last => {
                &vertices[..vertices.len() - 1]
            }
            _ => vertices,
        };
        let n = ring.len();
        if n < 3 {
            return Err(Error::InvalidPolygon(PolygonProblem::TooFewVertices {
                count: n,
            }));
        }
        let point_set = match PointSet::new(ring) {
            Ok(ps) => ps,
            // Distinct-but-collinear rings have overlapping edges, which the
            // edge test below names more precisely; keep PointSet's range errors.
            Err(Error::AllCollinear { .. }) | Err(Error::TooFewPoints { .. }) => {
                return Err(Self::first_problem(ring).map_or_else(
                    || Error::InvalidPolygon(PolygonProblem::TooFewVertices { count: n }),
                    Error::InvalidPolygon,
                ))
            }
            Err(e) => return Err(e),
        };
        if let Some(&[dropped, kept]) = point_set.duplicates().first() {
            return Err(Error::InvalidPolygon(PolygonProblem::RepeatedVertex {
                first: kept as usize,
                second: dropped as usize,
            }));
        }
        if let Some(problem) = Self::first_problem(ring) {
            return Err(Error::InvalidPolygon(problem));
        }
        // The lexicographically smallest vertex is a strictly convex corner of
        // a simple polygon, so its turn gives the orientation exactly.
        let lowest = (0..n)
            .min_by(|&a, &b| {
                let (p, q) = (ring[a], ring[b]);
                p[0].total_cmp(&q[0]).then(p[1].total_cmp(&q[1]))
            })
            .unwrap_or(0);
        let turn = orient_sign(
            ring[(lowest + n - 1) % n],
            ring[lowest],
            ring[(lowest + 1) % n],
        );
        let clockwise_input = turn < 0;
        let counter_clockwise = if clockwise_input {
            std::iter::once(0).chain((1..n as u32).rev()).collect()
        } else {
            (0..n as u32).collect()
        };
        Ok(Self {
            point_set,
            counter_clockwise,
            clockwise_input,
        })
    }

    /// The first edge that meets another, found by adding the ring's edges
    /// one by one as constraints of a Delaunay triangulation (expected
    /// O(n log n) plus the edges crossed), named with the smallest other
    /// edge it meets (one O(n) scan). For rings whose edges share x-ranges
    /// (a star with alternating radii), where the sweep is quadratic.
    /// `None` when the points are not a valid point set (the sweep decides).
    fn first_crossing_by_constraints(ring: &[Point]) -> Option<Option<PolygonProblem>> {
        let n = ring.len();
        let seg = |i: usize| (ring[i], ring[(i + 1) % n]);
        let edges: Vec<[u32; 2]> = (0..n).map(|i| [i as u32, ((i + 1) % n) as u32]).collect();
        let first =
            crate::structures::constrained_delaunay::first_unfit_constraint(ring, &edges).ok()?;
        let Some(i) = first else {
            return Some(None);
        };
        let (a, b) = seg(i);
        let other = (0..n).find(|&j| {
            let adjacent = j == i || (i + 1) % n == j || (j + 1) % n == i;
            !adjacent && {
                let (c, d) = seg(j);
                segments_intersect(a, b, c, d)
            }
        })?;
        Some(Some(PolygonProblem::EdgesIntersect {
            first: [i.min(other), (i.min(other) + 1) % n],
            second: [i.max(other), (i.max(other) + 1) % n],
        }))
    }

    /// Would the sweep test more than 16 edge pairs per edge (x-ranges
    /// overlapping)? Counted in O(n log n) on the edges sorted by their low
    /// x (`by_low`), stopping at the budget.
    fn sweep_is_crowded(ring: &[Point], by_low: &[usize]) -> bool {
        let n = ring.len();
        let seg = |i: usize| (ring[i], ring[(i + 1) % n]);
        let low = |i: usize| seg(i).0[0].min(seg(i).1[0]);
        let high = |i: usize| seg(i).0[0].max(seg(i).1[0]);
        let lows: Vec<f64> = by_low.iter().map(|&i| low(i)).collect();
        let budget = 16 * n + 4096;
        let mut pairs = 0usize;
        (0..n).any(|i| {
            pairs +=
                lows.partition_point(|&x| x <= high(i)) - lows.partition_point(|&x| x < low(i));
            pairs > budget
        })
    }

    /// The first pair of edges that meet improperly, or `None` if simple.
    fn first_problem(ring: &[Point]) -> Option<PolygonProblem> {
        let n = ring.len();
        let edge = |i: usize| [i, (i + 1) % n];
        let seg = |i: usize| (ring[i], ring[(i + 1) % n]);
        // Consecutive edges share vertex i + 1; they overlap iff they fold
        // back along one line.
        for i in 0..n {
            let (a, b, c) = (ring[i], ring[(i + 1) % n], ring[(i + 2) % n]);
            if a == b || b == c {
                continue; // repeated vertices are reported by the caller
            }
            if orient_sign(a, b, c) == 0 && dot_sign(b, a, c) > 0 {
                return Some(PolygonProblem::EdgesIntersect {
                    first: edge(i),
                    second: edge((i + 1) % n),
                });
            }
        }
        let mut order: Vec<usize> = (0..n).collect();
        let low = |i: usize| seg(i).0[0].min(seg(i).1[0]);
        let high = |i: usize| seg(i).0[0].max(seg(i).1[0]);
        order.sort_by(|&a, &b| low(a).total_cmp(&low(b)));
        if Self::sweep_is_crowded(ring, &order) {
            if let Some(problem) = Self::first_crossing_by_constraints(ring) {
                return problem;
            }
        }
        let mut found: Option<[usize; 2]> = None;
        let mut active: Vec<usize> = Vec::new();
        for &i in &order {
            active.retain(|&j| high(j) >= low(i));
            for &j in &active {
                let adjacent = (i + 1) % n == j || (j + 1) % n == i;
                if adjacent {
                    continue;
                }
                let ((a, b), (c, d)) = (seg(i), seg(j));
                if segments_intersect(a, b, c, d) {
                    let pair = [i.min(j), i.max(j)];
                    if found.is_none_or(|f| pair < f) {
                        found = Some(pair);
                    }
                }
            }
            active.push(i);
        }
        found.map(|[i, j]| PolygonProblem::EdgesIntersect {
            first: edge(i),
            second: edge(j),
        })
    }

    /// This polygon with an elevation per vertex, in the caller's ring
    /// order (see [`PointSet::with_elevations`]).
    ///
    /// # Errors
    /// [`crate::Error::InvalidElevations`].
    pub fn with_elevations(mut self, z: &[f64]) -> Result<Self> {
        self.point_set = self.point_set.with_elevations(z)?;
        Ok(self)
    }

    /// The vertices as a point set (no duplicates: indices are ring positions).
    pub fn point_set(&self) -> &PointSet {
        &self.point_set
    }

    /// The vertices in the caller's ring order.
    pub fn vertices(&self) -> &[Point] {
        self.point_set.input_points()
    }

    /// Number of vertices.
    pub fn len(&self) -> usize {
        self.counter_clockwise.len()
    }

    /// Always `false`: a polygon has at least three vertices.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// Ring positions in counter-clockwise order, starting at position 0.
    pub fn counter_clockwise(&self) -> &[u32] {
        &self.counter_clockwise
    }

    /// Whether the caller listed the ring clockwise.
    pub fn is_clockwise_input(&self) -> bool {
        self.clockwise_input
    }

    /// The polygon as a counter-clockwise cycle of its ring positions.
    pub(crate) fn cycle(&self) -> PolygonCycle<'_> {
        PolygonCycle::exact(self.vertices(), &self.counter_clockwise)
    }

    /// The counter-clockwise corner of ring position `a`.
    #[inline]
    fn corner_of(&self, a: usize) -> usize {
        if self.clockwise_input {
            (self.len() - a) % self.len()
        } else {
            a
        }
    }

    /// Is the chord between ring positions `a` and `b` a *diagonal*: does its
    /// open segment lie in the polygon's open interior? Exact (kernel
    /// predicates only), O(n): the test of the polygon's corner cycle.
    ///
    /// Boundary edges, `a == b` and out-of-range positions are not
    /// diagonals; neither is a chord through a vertex (e.g. along a straight
    /// run of the boundary) or one that touches an edge.
    pub fn is_diagonal(&self, a: usize, b: usize) -> bool {
        let n = self.len();
        a < n
            && b < n
            && self
                .cycle()
                .is_diagonal(self.corner_of(a), self.corner_of(b))
    }

    /// Is no vertex a right turn (a convex polygon, straight runs allowed)?
    /// Then the boundary is the convex hull of the vertices with every one of
    /// them on it, so the triangulations of the interior are exactly the
    /// triangulations of the vertex set.
    pub(crate) fn is_convex(&self) -> bool {
        let ccw = &self.counter_clockwise;
        let p = |k: usize| self.vertices()[ccw[k % ccw.len()] as usize];
        (0..ccw.len()).all(|k| orient_sign(p(k), p(k + 1), p(k + 2)) >= 0)
    }

    /// Is every vertex a strict left turn (a strictly convex polygon)? Then
    /// every chord that is not a boundary edge is a diagonal.
    pub fn is_strictly_convex(&self) -> bool {
        is_strictly_convex_cycle(self.vertices(), &self.counter_clockwise)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn convex_polygons_allow_straight_runs_and_no_reflex_corner() {
        let square_with_run = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
        let p = SimplePolygon::new(&square_with_run).unwrap();
        assert!(p.is_convex() && !p.is_strictly_convex());
        let clockwise: Vec<Point> = square_with_run.iter().rev().copied().collect();
        assert!(SimplePolygon::new(&clockwise).unwrap().is_convex());
        let notch = [[0.0, 0.0], [2.0, 0.0], [1.0, 1.0], [2.0, 2.0], [0.0, 2.0]];
        assert!(!SimplePolygon::new(&notch).unwrap().is_convex());
    }

    #[test]
    fn orientation_is_normalised_and_input_order_kept() {
        let square = [[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]];
        let p = SimplePolygon::new(&square).unwrap();
        assert!(p.is_clockwise_input());
        assert_eq!(p.counter_clockwise(), &[0, 3, 2, 1]);
        assert_eq!(p.vertices(), &square);
        let closed = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]];
        let q = SimplePolygon::new(&closed).unwrap();
        assert!(!q.is_clockwise_input());
        assert_eq!(q.len(), 4);
    }

    #[test]
    fn diagonals_of_an_l_shape_and_a_straight_run() {
        // Clockwise L-shape; the reflex corner is position 3.
        let l = [
            [0.0, 0.0],
            [0.0, 2.0],
            [1.0, 2.0],
            [1.0, 1.0],
            [2.0, 1.0],
            [2.0, 0.0],
        ];
        let p = SimplePolygon::new(&l).unwrap();
        let mut diagonals = Vec::new();
        for a in 0..6 {
            for b in a + 1..6 {
                assert_eq!(p.is_diagonal(a, b), p.is_diagonal(b, a));
                if p.is_diagonal(a, b) {
                    diagonals.push([a, b]);
                }
            }
        }
        assert_eq!(diagonals, [[0, 2], [0, 3], [0, 4], [1, 3], [3, 5]]);
        assert!(!p.is_strictly_convex());
        // 0-2 runs along the boundary through the straight vertex 1.
        let t = SimplePolygon::new(&[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [1.0, 1.0]]).unwrap();
        assert!(!t.is_diagonal(0, 2) && t.is_diagonal(1, 3) && !t.is_diagonal(0, 1));
        assert!(!t.is_strictly_convex());
        let square = SimplePolygon::new(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]).unwrap();
        assert!(
            square.is_strictly_convex() && square.is_diagonal(0, 2) && !square.is_diagonal(4, 0)
        );
    }

    #[test]
    fn bad_rings_name_the_problem() {
        let bowtie = [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]];
        assert_eq!(
            SimplePolygon::new(&bowtie).unwrap_err(),
            Error::InvalidPolygon(PolygonProblem::EdgesIntersect {
                first: [0, 1],
                second: [2, 3]
            })
        );
        let repeated = [[0.0, 0.0], [2.0, 0.0], [1.0, 1.0], [2.0, 0.0], [2.0, 2.0]];
        assert_eq!(
            SimplePolygon::new(&repeated).unwrap_err(),
            Error::InvalidPolygon(PolygonProblem::RepeatedVertex {
                first: 1,
                second: 3
            })
        );
        // A vertex touching a non-adjacent edge.
        let touching = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [2.0, 0.0], [0.0, 4.0]];
        assert!(matches!(
            SimplePolygon::new(&touching).unwrap_err(),
            Error::InvalidPolygon(PolygonProblem::EdgesIntersect { .. })
        ));
        let folded = [[0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [1.0, 1.0]];
        assert_eq!(
            SimplePolygon::new(&folded).unwrap_err(),
            Error::InvalidPolygon(PolygonProblem::EdgesIntersect {
                first: [0, 1],
                second: [1, 2]
            })
        );
        let flat = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]];
        assert!(matches!(
            SimplePolygon::new(&flat).unwrap_err(),
            Error::InvalidPolygon(_)
        ));
        assert_eq!(
            SimplePolygon::new(&[[0.0, 0.0], [1.0, 0.0]]).unwrap_err(),
            Error::InvalidPolygon(PolygonProblem::TooFewVertices { count: 2 })
        );
        // Straight vertices are fine.
        assert!(SimplePolygon::new(&[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [1.0, 1.0]]).is_ok());
    }

    /// Stars with alternating radii share x-ranges between most edge pairs,
    /// so the check goes through the constrained triangulation: it agrees
    /// with the test of every pair on simple stars, stars with a crossing,
    /// a vertex moved onto another edge and a spike through several edges,
    /// and names two non-adjacent edges that meet.
    #[test]
    fn crowded_stars_are_checked_by_constraints() {
        let n = 400;
        let star: Vec<Point> = (0..n)
            .map(|k| {
                let a = std::f64::consts::TAU * k as f64 / n as f64;
                let r = if k % 2 == 0 { 1.0 } else { 0.5 };
                [r * a.cos(), r * a.sin()]
            })
            .collect();
        let mut by_low: Vec<usize> = (0..n).collect();
        let low = |i: usize| star[i][0].min(star[(i + 1) % n][0]);
        by_low.sort_by(|&a, &b| low(a).total_cmp(&low(b)));
        assert!(SimplePolygon::sweep_is_crowded(&star, &by_low));
        let meet = |ring: &[Point], i: usize, j: usize| {
            let m = ring.len();
            segments_intersect(ring[i], ring[(i + 1) % m], ring[j], ring[(j + 1) % m])
        };
        let all_pairs_simple = |ring: &[Point]| {
            let m = ring.len();
            (0..m).all(|i| (i + 2..m).all(|j| (j + 1) % m == i || !meet(ring, i, j)))
        };
        let mut variants = vec![star.clone()];
        let mut crossing = star.clone();
        crossing.swap(10, 12); // two outer vertices exchanged: edges cross
        variants.push(crossing);
        let mut touching = star.clone();
        // Vertex 101 (inner) moved onto the midpoint of edge 200-201.
        touching[101] = [
            (star[200][0] + star[201][0]) / 2.0,
            (star[200][1] + star[201][1]) / 2.0,
        ];
        variants.push(touching);
        let mut spike = star.clone();
        spike[51] = [-3.0 * star[51][0], -3.0 * star[51][1]]; // across the star
        variants.push(spike);
        // The exchange and the touching vertex are not simple; the spike is
        // decided by the test of every pair like the rest.
        assert!(all_pairs_simple(&variants[0]));
        assert!(!all_pairs_simple(&variants[1]) && !all_pairs_simple(&variants[2]));
        for ring in &variants {
            let simple = all_pairs_simple(ring);
            match SimplePolygon::new(ring) {
                Ok(_) => assert!(simple),
                Err(Error::InvalidPolygon(PolygonProblem::EdgesIntersect { first, second })) => {
                    assert!(!simple);
                    let m = ring.len();
                    assert_eq!(
                        [first[1], second[1]],
                        [(first[0] + 1) % m, (second[0] + 1) % m]
                    );
                    assert!(first[0] < second[0] && meet(ring, first[0], second[0]));
                    assert!((second[0] + 1) % m != first[0] && first[1] != second[0]);
                }
                Err(e) => panic!("unexpected {e}"),
            }
        }
    }
}
