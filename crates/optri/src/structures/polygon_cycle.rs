//! [`PolygonCycle`]: the corners of a weakly simple polygon, and which
//! chords between them are diagonals.
//!
//! A weakly simple polygon is a closed walk whose edges meet only at shared
//! corners, where a zero-width crack may be walked on both sides, so one
//! point can be the vertex of several corners (H. Edelsbrunner & T. S. Tan,
//! *A quadratic time algorithm for the minmax length triangulation*, SIAM J.
//! Comput. 22, 1993, §3: "cracks opened up a tiny amount"). Each corner is
//! treated as its own, with the region on the left of the walk: the faces
//! of `ch(S) ∪ rng(S)` for minmax length and the area criteria, the faces
//! the min-weight skeleton leaves, and the simple polygons of
//! [`SimplePolygon`](super::SimplePolygon) (which validates its ring and
//! wraps a cycle) are all such walks. The corner rule is the kernel's
//! [`strictly_inside_wedge`].

use crate::kernel::{
    dot_sign, orient_sign, orient_symbolic, same_direction, strictly_inside_wedge,
    strictly_inside_wedge_symbolic, Point,
};
use crate::spatial::is_strictly_convex_cycle;

/// The corners of a weakly simple polygon: `corners[c]` is the point index
/// (into `points`) of corner `c`, counter-clockwise (the region to the left
/// of every boundary edge `c → c + 1`).
///
/// Exact predicates on the points, or, for a [`perturbed`](Self::perturbed)
/// cycle, on the kernel's perturbed points (no three collinear, module docs
/// of the kernel, "Ties", for distinct points); coordinates are compared
/// exactly in both.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PolygonCycle<'a> {
    points: &'a [Point],
    corners: &'a [u32],
    perturbed: bool,
}

impl<'a> PolygonCycle<'a> {
    /// A cycle decided by exact predicates on `points`.
    pub fn exact(points: &'a [Point], corners: &'a [u32]) -> Self {
        Self {
            points,
            corners,
            perturbed: false,
        }
    }

    /// A cycle decided exactly, or on the perturbed points if `perturbed`.
    pub fn new(points: &'a [Point], corners: &'a [u32], perturbed: bool) -> Self {
        Self {
            points,
            corners,
            perturbed,
        }
    }

    /// Number of corners.
    pub fn len(&self) -> usize {
        self.corners.len()
    }

    #[inline]
    fn point(&self, v: u32) -> Point {
        self.points[v as usize]
    }

    /// Orientation of three points by index (0 if two indices coincide).
    #[inline]
    pub fn orient(&self, i: u32, j: u32, k: u32) -> i32 {
        if self.perturbed {
            if i == j || j == k || i == k {
                0
            } else {
                orient_symbolic(self.points, i, j, k)
            }
        } else {
            orient_sign(self.point(i), self.point(j), self.point(k))
        }
    }

    /// [`strictly_inside_wedge`] on points by index: is `x − o` strictly
    /// inside the counter-clockwise wedge from ray `o → first` to ray
    /// `o → last` (the full turn minus that ray when the rays coincide)?
    #[inline]
    pub fn wedge_contains(&self, o: u32, first: u32, last: u32, x: u32) -> bool {
        if self.perturbed {
            strictly_inside_wedge_symbolic(self.points, o, first, last, x)
        } else {
            let p = |m: u32| self.point(m);
            strictly_inside_wedge(p(o), p(first), p(last), p(x))
        }
    }

    /// Does `x − o` point along the ray `o → r` (`x ≠ o`)?
    #[inline]
    fn on_ray(&self, o: u32, r: u32, x: u32) -> bool {
        if self.perturbed {
            x == r
        } else {
            same_direction(self.point(o), self.point(r), self.point(x))
        }
    }

    /// The wedge of corner `c`: its vertex and the vertices of the next and
    /// the previous corner (the region sweeps from the first ray to the
    /// second).
    #[inline]
    fn wedge(&self, c: usize) -> [u32; 3] {
        let k = self.len();
        let v = self.corners;
        [v[c], v[(c + 1) % k], v[(c + k - 1) % k]]
    }

    /// Does the segment from corner `c` towards point `x` leave the corner
    /// into the region: is its direction strictly inside the corner's wedge?
    #[inline]
    pub fn leaves_corner_into(&self, c: usize, x: u32) -> bool {
        let [o, first, last] = self.wedge(c);
        self.wedge_contains(o, first, last, x)
    }

    /// Is the angle at corner `c` of the counter-clockwise triangle
    /// `(corners[c], b, d)` inside the corner's wedge?
    ///
    /// The triangle's open angle `S` (less than a half turn) lies in the
    /// wedge `W` iff neither ray bounding `W` is strictly inside `S` (then
    /// the connected `S` is inside `W` or outside it) and `S` starts inside
    /// `W`: at `b` strictly inside `W`, or on the first ray of `W` (from
    /// which `W` sweeps the way `S` does).
    pub fn contains_triangle_corner(&self, c: usize, b: u32, d: u32) -> bool {
        let [o, first, last] = self.wedge(c);
        !self.wedge_contains(o, b, d, first)
            && !self.wedge_contains(o, b, d, last)
            && (self.wedge_contains(o, first, last, b) || self.on_ray(o, first, b))
    }

    /// Is every corner a strict left turn (a strictly convex polygon, no
    /// cracks)? Then every chord between non-adjacent corners is a diagonal.
    pub fn is_strictly_convex(&self) -> bool {
        if self.perturbed {
            let k = self.len();
            let v = self.corners;
            (0..k).all(|i| self.orient(v[i], v[(i + 1) % k], v[(i + 2) % k]) > 0)
        } else {
            is_strictly_convex_cycle(self.points, self.corners)
        }
    }

    /// Is the chord between corners `a` and `b` a diagonal: is its
    /// relatively open segment inside the region? Exact, O(k).
    ///
    /// It must leave both corners into the region's wedge, contain no
    /// vertex and cross no boundary edge; then it cannot leave the region:
    /// the open chord is connected and meets the boundary nowhere, so it is
    /// inside or outside entirely, and near `a` it is inside. Chords between
    /// corners of one point, and boundary edges (they run along a ray of
    /// their corners' wedges), are not diagonals.
    pub fn is_diagonal(&self, a: usize, b: usize) -> bool {
        let k = self.len();
        let v = self.corners;
        let (va, vb) = (v[a], v[b]);
        if va == vb || !self.leaves_corner_into(a, vb) || !self.leaves_corner_into(b, va) {
            return false;
        }
        // Bounding boxes (exact coordinate comparisons) skip the boundary
        // edges far from the chord: a vertex on the chord lies in its box, and
        // a crossing edge's box meets it. The side of each vertex relative to
        // the chord's line is computed once and carried to the next edge.
        let p = |m: u32| self.point(m);
        let (pa, pb) = (p(va), p(vb));
        let lo = [pa[0].min(pb[0]), pa[1].min(pb[1])];
        let hi = [pa[0].max(pb[0]), pa[1].max(pb[1])];
        let side = |m: u32| self.orient(va, vb, m);
        let mut carried: Option<i32> = None;
        for i in 0..k {
            let (u, w) = (v[i], v[(i + 1) % k]);
            let (pu, pw) = (p(u), p(w));
            if (pu[0] < lo[0] && pw[0] < lo[0])
                || (pu[0] > hi[0] && pw[0] > hi[0])
                || (pu[1] < lo[1] && pw[1] < lo[1])
                || (pu[1] > hi[1] && pw[1] > hi[1])
            {
                carried = None;
                continue;
            }
            let su = carried.unwrap_or_else(|| side(u));
            let sw = side(w);
            carried = Some(sw);
            // u strictly inside the open segment ab?
            if su == 0 && u != va && u != vb && dot_sign(p(u), pa, pb) < 0 {
                return false;
            }
            if u == va || u == vb || w == va || w == vb {
                continue;
            }
            if su * sw < 0 && self.orient(u, w, va) * self.orient(u, w, vb) < 0 {
                return false;
            }
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A square with a crack from its corner `0` to the centre `4`, walked
    /// on both sides: the crack tip's wedge is a full turn, the corners at
    /// `0` are split by the crack, and chords are diagonals only on the
    /// side they leave into.
    #[test]
    fn a_crack_is_walked_on_both_sides() {
        let points = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0], [2.0, 2.0]];
        // 0 → 1 → 2 → 3 → 0 → 4 → 0 (the crack 0-4 walked out and back).
        let corners = [0, 1, 2, 3, 0, 4];
        for cycle in [
            PolygonCycle::exact(&points, &corners),
            PolygonCycle::new(&points, &corners, true),
        ] {
            assert!(!cycle.is_strictly_convex());
            // The tip 4 (corner 5): every direction but back along the crack.
            assert!(cycle.leaves_corner_into(5, 2) && cycle.leaves_corner_into(5, 1));
            assert!(!cycle.leaves_corner_into(5, 0));
            // The tip sees every other corner; the crack's own corners do
            // not see each other.
            assert!(cycle.is_diagonal(5, 1) && cycle.is_diagonal(5, 2) && cycle.is_diagonal(5, 3));
            assert!(!cycle.is_diagonal(0, 4) && !cycle.is_diagonal(0, 5));
            // Triangle (4, 1, 2) at the tip lies in the full turn; the
            // triangle (0, 1, 4) lies in corner 0, (0, 4, 3) in corner 4.
            assert!(cycle.contains_triangle_corner(5, 1, 2));
            assert!(cycle.contains_triangle_corner(0, 1, 4));
            assert!(!cycle.contains_triangle_corner(4, 1, 4));
            assert!(cycle.contains_triangle_corner(4, 4, 3));
            assert!(!cycle.contains_triangle_corner(0, 4, 3));
        }
    }
}
