//! [`ConstrainedDelaunay`]: the constrained Delaunay triangulation of
//! distinct points with non-crossing constraint edges (D. T. Lee & A. K.
//! Lin, *Generalized Delaunay triangulation for planar graphs*, Discrete
//! Comput. Geom. 1, 1986; L. P. Chew, *Constrained Delaunay
//! triangulations*, Algorithmica 4, 1989): every side that is not a
//! constraint is locally Delaunay. Built by `spade`, the library's one
//! constrained Delaunay adapter, and made canonical as
//! [`DelaunayGraph`](super::DelaunayGraph) is: faces of four or more
//! cocircular points that no constraint cuts are fanned from their smallest
//! index, and the triangles are numbered in sorted order, so nothing
//! depends on how spade built it (its bulk load makes rounding- and
//! scale-dependent choices).

use super::delaunay_graph::{canonical_order, fan_cocircular_faces, triangle_arrays, Vertex};
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
    /// [`Error::Internal`] if spade fails, drops a point, or finds
    /// constraints that cross or pass through a point.
    pub fn new(points: &[Point], constraints: &[[u32; 2]]) -> Result<Self> {
        let mut sorted: Vec<[u32; 2]> = constraints
            .iter()
            .map(|&[u, v]| [u.min(v), u.max(v)])
            .collect();
        sorted.sort_unstable();
        sorted.dedup();
        let edges: Vec<[usize; 2]> = sorted
            .iter()
            .map(|&[u, v]| [u as usize, v as usize])
            .collect();
        let mut conflicts = 0usize;
        let cdt = ConstrainedDelaunayTriangulation::<Vertex>::try_bulk_load_cdt(
            Vertex::numbered(points),
            edges,
            |_| conflicts += 1,
        )
        .map_err(|e| Error::Internal(format!("spade's constrained bulk load failed: {e:?}")))?;
        // A constraint through a point is split there: it counts twice.
        if conflicts > 0
            || cdt.num_vertices() != points.len()
            || cdt.num_constraints() != sorted.len()
        {
            return Err(Error::Internal(format!(
                "spade's constrained triangulation of {} points with {} constraints has {} \
                 vertices, {} constraints and {conflicts} conflicts",
                points.len(),
                sorted.len(),
                cdt.num_vertices(),
                cdt.num_constraints()
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::incircle_sign;

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
