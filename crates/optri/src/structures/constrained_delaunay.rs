//! [`ConstrainedDelaunay`]: the constrained Delaunay triangulation of
//! distinct points with non-crossing constraint edges (D. T. Lee & A. K.
//! Lin, *Generalized Delaunay triangulation for planar graphs*, Discrete
//! Comput. Geom. 1, 1986; L. P. Chew, *Constrained Delaunay
//! triangulations*, Algorithmica 4, 1989): every side that is not a
//! constraint is locally Delaunay. Built by `spade`, the library's one
//! constrained Delaunay adapter, as [`DelaunayGraph`](super::DelaunayGraph)
//! is: the points inserted in a biased randomized insertion order (N.
//! Amenta, S. Choi and G. Rote, *Incremental constructions con BRIO*, SoCG
//! 2003), expected O(n log n) on every input, then the constraints one by
//! one, each flipping the edges it crosses into place and re-legalizing
//! the rest (work proportional to the edges crossed; a polygon side is
//! usually an edge already). spade's constrained bulk load is a circle
//! sweep, quadratic on points in convex position: a star-shaped polygon of
//! 10⁵ vertices took more than 30 s.
//!
//! The result is made canonical as the Delaunay graph is: faces of four or
//! more cocircular points that no constraint cuts are fanned from their
//! smallest index, and the triangles are numbered in sorted order, so
//! nothing depends on the order in which spade built it.

use super::delaunay_graph::{
    canonical_order, fan_cocircular_faces, insert_in_brio_order, triangle_arrays, Vertex,
};
use super::NO_TRIANGLE;
use crate::error::{Error, Result};
use crate::kernel::Point;
use spade::{ConstrainedDelaunayTriangulation, Triangulation as _};

/// A constrained Delaunay triangulation of the convex hull of distinct
/// points, as plain arrays.
pub(crate) struct ConstrainedDelaunay {
    /// Counter-clockwise triangles (point indices), each starting at its
    /// smallest corner, in sorted order.
    pub triangles: Vec<[u32; 3]>,
    /// Per side `j` of a triangle (corner `j` to corner `j + 1`), the
    /// triangle across it, [`NO_TRIANGLE`] on the hull.
    pub neighbours: Vec<[u32; 3]>,
    /// The constraints as sorted pairs `[min, max]`, sorted.
    constraints: Vec<[u32; 2]>,
}

impl ConstrainedDelaunay {
    /// The constrained Delaunay triangulation of `points` (distinct, not all
    /// collinear) with the edges `constraints` (pairs of point indices that
    /// cross nowhere and pass through no point).
    ///
    /// # Errors
    /// [`Error::Internal`] if spade fails or drops a point, or if
    /// constraints cross or pass through a point.
    pub fn new(points: &[Point], constraints: &[[u32; 2]]) -> Result<Self> {
        let sorted = sorted_pairs(constraints);
        let (cdt, unfit) = constrained_in_order(points, &sorted)?;
        if let Some(i) = unfit {
            let [u, v] = sorted[i];
            return Err(Error::Internal(format!(
                "the constraint {{{u}, {v}}} among {} constraints on {} points crosses \
                 another or passes through a point",
                sorted.len(),
                points.len()
            )));
        }
        let (mut triangles, mut neighbours) = triangle_arrays(&cdt);
        drop(cdt);
        let is_constraint = |u: u32, v: u32| sorted.binary_search(&[u.min(v), u.max(v)]).is_ok();
        fan_cocircular_faces(points, &mut triangles, &mut neighbours, is_constraint);
        canonical_order(&mut triangles, &mut neighbours);
        Ok(Self {
            triangles,
            neighbours,
            constraints: sorted,
        })
    }

    /// Is `{u, v}` a constraint?
    pub fn is_constraint(&self, u: u32, v: u32) -> bool {
        self.constraints
            .binary_search(&[u.min(v), u.max(v)])
            .is_ok()
    }

    /// Does side `j` of triangle `t` bound a region of triangles joined
    /// across the other sides: is it a constraint or on the hull?
    pub fn is_barrier(&self, t: usize, j: usize) -> bool {
        let tri = self.triangles[t];
        self.neighbours[t][j] == NO_TRIANGLE || self.is_constraint(tri[j], tri[(j + 1) % 3])
    }

    /// The side of triangle `u` whose neighbour is `t`.
    pub fn side_towards(&self, u: u32, t: u32) -> usize {
        let n = self.neighbours[u as usize];
        (0..3)
            .find(|&k| n[k] == t)
            .expect("the triangles are adjacent")
    }
}

/// The first of `edges` (in their order) that crosses an earlier one or
/// passes through a point, when each is added in turn as a constraint to
/// the Delaunay triangulation of `points` (distinct, not all collinear);
/// `None` when all of them fit. spade decides both by its exact
/// orientation tests; the work is expected O(n log n) plus the triangulation
/// edges the constraints cross, where a sweep over x-ranges is quadratic on
/// polygons whose edges share x-ranges (a star with alternating radii).
///
/// # Errors
/// [`Error::Internal`] if spade fails or drops a point.
pub fn first_unfit_constraint(points: &[Point], edges: &[[u32; 2]]) -> Result<Option<usize>> {
    constrained_in_order(points, edges).map(|(_, unfit)| unfit)
}

/// The Delaunay triangulation of `points` (inserted in BRIO order) with
/// `edges` added in turn as constraints, up to the first that crosses an
/// earlier one or passes through a point (spade then changes nothing, or
/// splits it): the triangulation and that edge's position, if any.
fn constrained_in_order(
    points: &[Point],
    edges: &[[u32; 2]],
) -> Result<(ConstrainedDelaunayTriangulation<Vertex>, Option<usize>)> {
    let mut cdt: ConstrainedDelaunayTriangulation<Vertex> =
        ConstrainedDelaunayTriangulation::with_capacity(
            points.len(),
            3 * points.len(),
            2 * points.len(),
        );
    let handles = insert_in_brio_order(&mut cdt, points)?;
    for (i, &[u, v]) in edges.iter().enumerate() {
        // Empty if the constraint crosses one added before, two or more
        // pieces if it passes through a point.
        let pieces = cdt.try_add_constraint(handles[u as usize], handles[v as usize]);
        if pieces.len() != 1 {
            return Ok((cdt, Some(i)));
        }
    }
    Ok((cdt, None))
}

/// The pairs `[min, max]` of `constraints`, sorted, without repeats.
fn sorted_pairs(constraints: &[[u32; 2]]) -> Vec<[u32; 2]> {
    let mut sorted: Vec<[u32; 2]> = constraints
        .iter()
        .map(|&[u, v]| [u.min(v), u.max(v)])
        .collect();
    sorted.sort_unstable();
    sorted.dedup();
    sorted
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::incircle_sign;
    use optri_oracle::constrained_delaunay_check;
    use rand::rngs::StdRng;
    use rand::seq::SliceRandom;
    use rand::SeedableRng;

    /// The construction the randomized insertion replaced: spade's
    /// constrained bulk load (a circle sweep), made canonical the same way.
    fn bulk_loaded(points: &[Point], constraints: &[[u32; 2]]) -> ConstrainedDelaunay {
        let sorted = sorted_pairs(constraints);
        let edges = sorted
            .iter()
            .map(|&[u, v]| [u as usize, v as usize])
            .collect();
        let cdt = ConstrainedDelaunayTriangulation::<Vertex>::bulk_load_cdt(
            Vertex::numbered(points),
            edges,
        )
        .unwrap();
        assert_eq!(cdt.num_constraints(), sorted.len());
        let (mut triangles, mut neighbours) = triangle_arrays(&cdt);
        let is_constraint = |u: u32, v: u32| sorted.binary_search(&[u.min(v), u.max(v)]).is_ok();
        fan_cocircular_faces(points, &mut triangles, &mut neighbours, is_constraint);
        canonical_order(&mut triangles, &mut neighbours);
        ConstrainedDelaunay {
            triangles,
            neighbours,
            constraints: sorted,
        }
    }

    /// Both constructions give the same arrays, which the oracle accepts as
    /// constrained Delaunay; and so do they after a random renumbering of
    /// the points (which moves the canonical completion).
    fn assert_same_both_ways(name: &str, points: &[Point], constraints: &[[u32; 2]]) {
        let mut rng = StdRng::seed_from_u64(points.len() as u64);
        let mut numbering: Vec<u32> = (0..points.len() as u32).collect();
        for round in 0..3 {
            let mut renumbered = vec![[0.0; 2]; points.len()];
            for (i, &v) in numbering.iter().enumerate() {
                renumbered[v as usize] = points[i];
            }
            let mapped: Vec<[u32; 2]> = constraints
                .iter()
                .map(|&[u, v]| [numbering[u as usize], numbering[v as usize]])
                .collect();
            let inserted = ConstrainedDelaunay::new(&renumbered, &mapped).unwrap();
            let bulk = bulk_loaded(&renumbered, &mapped);
            assert_eq!(
                inserted.triangles, bulk.triangles,
                "{name} ({round}): triangles"
            );
            assert_eq!(
                inserted.neighbours, bulk.neighbours,
                "{name} ({round}): neighbours"
            );
            assert_eq!(inserted.constraints, bulk.constraints, "{name} ({round})");
            constrained_delaunay_check(&renumbered, &inserted.triangles, &mapped)
                .unwrap_or_else(|e| panic!("{name} ({round}): {e}"));
            numbering.shuffle(&mut rng);
        }
    }

    /// The sides of the closed ring `0, 1, …, n − 1`.
    fn ring_sides(n: usize) -> Vec<[u32; 2]> {
        let n = n as u32;
        (0..n).map(|i| [i, (i + 1) % n]).collect()
    }

    /// The integer points of a circle of radius 65 (exactly cocircular, 36
    /// of them) in angular order.
    fn circle_65() -> Vec<Point> {
        let mut points = optri_oracle::inputs::integer_circle_points(65);
        points.sort_by(|p, q| p[1].atan2(p[0]).total_cmp(&q[1].atan2(q[0])));
        points
    }

    /// A comb on the integer lattice: `teeth` teeth one unit wide and `h`
    /// high, one unit apart, on a base one unit high, every lattice point of
    /// the boundary a vertex (collinear runs along every side, cocircular
    /// unit squares), counter-clockwise.
    fn comb(teeth: usize, h: usize) -> Vec<Point> {
        let right = 2 * teeth - 1;
        let mut ring: Vec<Point> = (0..right).map(|x| [x as f64, 0.0]).collect();
        ring.extend((0..=h).map(|y| [right as f64, y as f64]));
        for tooth in (0..teeth).rev() {
            let left = (2 * tooth) as f64;
            ring.extend((1..=h).rev().map(|y| [left, y as f64]));
            if tooth > 0 {
                ring.extend((1..=h).map(|y| [left - 1.0, y as f64]));
            }
        }
        ring
    }

    #[test]
    fn randomized_insertion_agrees_with_the_bulk_load() {
        // Cocircular: the ring itself, and with chords cutting it.
        let circle = circle_65();
        let n = circle.len();
        assert_same_both_ways("circle", &circle, &ring_sides(n));
        let mut chords = ring_sides(n);
        chords.extend([[0, 9], [9, 18], [20, 33], [2, 7]]);
        assert_same_both_ways("circle with chords", &circle, &chords);
        // Collinear boundary runs: a lattice rectangle with every boundary
        // point a vertex, and one with its inner lattice points too.
        let mut rectangle = Vec::new();
        for x in 0..8 {
            rectangle.push([x as f64, 0.0]);
        }
        for y in 0..5 {
            rectangle.push([8.0, y as f64]);
        }
        for x in (1..=8).rev() {
            rectangle.push([x as f64, 5.0]);
        }
        for y in (1..=5).rev() {
            rectangle.push([0.0, y as f64]);
        }
        let sides = ring_sides(rectangle.len());
        assert_same_both_ways("rectangle", &rectangle, &sides);
        let mut filled = rectangle.clone();
        for x in 1..8 {
            for y in 1..5 {
                filled.push([x as f64, y as f64]);
            }
        }
        assert_same_both_ways("filled rectangle", &filled, &sides);
        // Stars: radii alternating 1 and 1/2, and exactly cocircular inner
        // and outer rings of lattice points (radii 65 and 25, interleaved).
        let star: Vec<Point> = (0..200)
            .map(|i| {
                let (r, a) = (
                    if i % 2 == 0 { 1.0 } else { 0.5 },
                    i as f64 * std::f64::consts::PI / 100.0,
                );
                [r * a.cos(), r * a.sin()]
            })
            .collect();
        assert_same_both_ways("star", &star, &ring_sides(star.len()));
        let angle = |p: &Point| p[1].atan2(p[0]);
        let mut inner = optri_oracle::inputs::integer_circle_points(25);
        inner.sort_by(|p, q| angle(p).total_cmp(&angle(q)));
        let mut lattice_star = Vec::new();
        for p in &circle {
            if let Some(q) = inner.iter().find(|q| angle(q) > angle(p)) {
                if lattice_star.last() != Some(q) {
                    lattice_star.push(*p);
                    lattice_star.push(*q);
                }
            }
        }
        assert!(lattice_star.len() > 12);
        assert_same_both_ways(
            "lattice star",
            &lattice_star,
            &ring_sides(lattice_star.len()),
        );
        // A comb: long collinear sides and unit squares.
        let comb = comb(6, 7);
        assert_same_both_ways("comb", &comb, &ring_sides(comb.len()));
        // A lattice with constraints along alternate rows and a diagonal
        // in every other cell (cocircular unit squares cut or not).
        let grid = optri_oracle::inputs::grid(9, 9, 1.0);
        let at = |x: u32, y: u32| y * 9 + x;
        let mut constraints = Vec::new();
        for y in (0..9).step_by(2) {
            for x in 0..8 {
                constraints.push([at(x, y), at(x + 1, y)]);
            }
        }
        for y in (1..8).step_by(2) {
            for x in (0..8).step_by(2) {
                constraints.push([at(x, y), at(x + 1, y + 1)]);
            }
        }
        assert_same_both_ways("grid", &grid, &constraints);
    }

    /// The twelve integer points of the circle of radius 5 with three
    /// chords as constraints: the constraints are sides and every other
    /// diagonal of the cocircular faces they leave joins the face's smallest
    /// index (the flip rule's fixed point); then with the centre added and
    /// constraints along two spokes. Constraints that cross, or that pass
    /// through a point, are refused.
    #[test]
    fn cocircular_faces_are_fanned_around_the_constraints() {
        let mut points = optri_oracle::inputs::circle_r5_ccw();
        let cdt = ConstrainedDelaunay::new(&points, &[[1, 7], [5, 2], [8, 11]]).unwrap();
        assert_eq!(cdt.triangles.len(), 10);
        let sides = |c: &ConstrainedDelaunay| -> Vec<[u32; 2]> {
            let mut s: Vec<[u32; 2]> = c
                .triangles
                .iter()
                .flat_map(|t| [[t[0], t[1]], [t[1], t[2]], [t[2], t[0]]])
                .map(|[u, v]| [u.min(v), u.max(v)])
                .collect();
            s.sort_unstable();
            s.dedup();
            s
        };
        for c in [[1, 7], [2, 5], [8, 11]] {
            assert!(sides(&cdt).contains(&c), "{c:?}");
        }
        for (t, tri) in cdt.triangles.iter().enumerate() {
            assert_eq!(tri[0], *tri.iter().min().unwrap());
            for j in 0..3 {
                let u = cdt.neighbours[t][j];
                if u == NO_TRIANGLE || cdt.is_constraint(tri[j], tri[(j + 1) % 3]) {
                    continue;
                }
                let k = cdt.side_towards(u, t as u32);
                let d = cdt.triangles[u as usize][(k + 2) % 3];
                let p = |v: u32| points[v as usize];
                assert_eq!(
                    incircle_sign(p(tri[0]), p(tri[1]), p(tri[2]), p(d)),
                    0,
                    "cocircular"
                );
                // The diagonal through the face's smallest corner.
                let c = tri[(j + 2) % 3];
                assert!(tri[j].min(tri[(j + 1) % 3]) < c.min(d));
            }
        }
        // With the centre added, no face is cocircular: the constraints
        // through it are edges, and so are the spokes.
        points.push([0.0, 0.0]);
        let cdt = ConstrainedDelaunay::new(&points, &[[1, 12], [12, 7]]).unwrap();
        assert_eq!(cdt.triangles.len(), 12);
        assert!(sides(&cdt).contains(&[1, 12]) && sides(&cdt).contains(&[7, 12]));
        assert!(ConstrainedDelaunay::new(&points, &[[0, 6], [3, 9]]).is_err());
        points.pop();
        assert!(ConstrainedDelaunay::new(&points, &[[0, 6], [3, 9]]).is_err());
    }
}
