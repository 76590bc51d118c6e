//! A planar straight-line graph as half-edges, and its faces.
//!
//! Used to cut the convex hull into the polygonal regions of `ch(S) ∪ rng(S)`
//! (Edelsbrunner & Tan 1991, §3). Following §3, every edge is a pair of
//! opposite half-edges and a face is the cycle of half-edges that have it on
//! their left, so a zero-width crack is traversed on both sides and a vertex
//! may occur several times in one boundary.

use super::Csr;
use crate::kernel::{compare_angles, Point};

/// Half-edge representation of a plane graph on distinct points.
///
/// Half-edge `2k` runs `edges[k][0] → edges[k][1]`, `2k + 1` the reverse.
#[derive(Clone, Debug)]
pub struct PlanarGraph {
    origin: Vec<u32>,
    /// Next half-edge along the face to the left.
    next: Vec<u32>,
    /// For each vertex, one outgoing half-edge (or `u32::MAX`).
    outgoing: Vec<u32>,
}

/// One face: its boundary half-edges in counter-clockwise order (for bounded
/// faces), and the origins of those half-edges.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Face {
    /// Half-edge ids along the boundary.
    pub half_edges: Vec<u32>,
    /// Vertex sequence (origins of `half_edges`); may repeat a vertex at cracks.
    pub vertices: Vec<u32>,
}

// The walk accessors serve the tests (`internals`) and future face consumers.
#[cfg_attr(not(any(test, feature = "internals")), allow(dead_code))]
impl PlanarGraph {
    /// Builds the half-edge structure of `edges` (distinct-index pairs of a
    /// plane graph on `points`; no duplicate edges, no crossings).
    pub fn new(points: &[Point], edges: &[[u32; 2]]) -> Self {
        let n = points.len();
        let m = edges.len();
        let mut origin = Vec::with_capacity(2 * m);
        for &[u, v] in edges {
            origin.push(u);
            origin.push(v);
        }
        let dest = |h: u32| origin[(h ^ 1) as usize];
        // Outgoing half-edges of each vertex, sorted counter-clockwise.
        let mut around = Csr::from_pairs(n, origin.iter().enumerate().map(|(h, &o)| (o, h as u32)));
        let mut outgoing = vec![u32::MAX; n];
        let mut next = vec![0u32; 2 * m];
        for (v, star) in around.rows_mut().enumerate() {
            if star.is_empty() {
                continue;
            }
            let o = points[v];
            star.sort_unstable_by(|&a, &b| {
                compare_angles(o, points[dest(a) as usize], points[dest(b) as usize])
            });
            outgoing[v] = star[0];
            // Arriving at v along h (reverse of star[i]), the face on the left
            // continues with the outgoing half-edge just clockwise of star[i].
            let k = star.len();
            for i in 0..k {
                let incoming = star[i] ^ 1;
                next[incoming as usize] = star[(i + k - 1) % k];
            }
        }
        Self {
            origin,
            next,
            outgoing,
        }
    }

    /// Origin vertex of half-edge `h`.
    pub fn origin(&self, h: u32) -> u32 {
        self.origin[h as usize]
    }

    /// Destination vertex of half-edge `h`.
    pub fn destination(&self, h: u32) -> u32 {
        self.origin[(h ^ 1) as usize]
    }

    /// Next half-edge around the face to the left of `h`.
    pub fn next(&self, h: u32) -> u32 {
        self.next[h as usize]
    }

    /// All faces (each half-edge belongs to exactly one).
    pub fn faces(&self) -> Vec<Face> {
        let mut done = vec![false; self.origin.len()];
        let mut faces = Vec::new();
        for start in 0..self.origin.len() as u32 {
            if done[start as usize] {
                continue;
            }
            let mut face = Face {
                half_edges: Vec::new(),
                vertices: Vec::new(),
            };
            let mut h = start;
            loop {
                done[h as usize] = true;
                face.half_edges.push(h);
                face.vertices.push(self.origin[h as usize]);
                h = self.next[h as usize];
                if h == start {
                    break;
                }
            }
            faces.push(face);
        }
        faces
    }

    /// The bounded faces, for a connected graph: all faces but the outer one.
    ///
    /// The outer face is identified exactly: at the lowest (then leftmost)
    /// vertex every edge points into the upper half-plane, so the outer face is
    /// to the left of the outgoing half-edge of largest angle.
    pub fn bounded_faces(&self, points: &[Point]) -> Vec<Face> {
        let lowest = (0..points.len())
            .filter(|&v| self.outgoing[v] != u32::MAX)
            .min_by(|&a, &b| {
                let (p, q) = (points[a], points[b]);
                p[1].total_cmp(&q[1]).then(p[0].total_cmp(&q[0]))
            });
        let Some(lowest) = lowest else {
            return Vec::new();
        };
        // The star is sorted ccw from angle 0, so the largest angle is the
        // one just before `outgoing` cyclically: the half-edge h with next(h^1)...
        // Walk the star: prev-in-ccw of outgoing[v] is next[outgoing[v] ^ 1].
        let first = self.outgoing[lowest];
        let outer_edge = self.next[(first ^ 1) as usize];
        self.faces()
            .into_iter()
            .filter(|f| !f.half_edges.contains(&outer_edge))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_with_diagonal_has_two_triangles_and_outer_face() {
        let pts = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let g = PlanarGraph::new(&pts, &[[0, 1], [1, 2], [2, 3], [3, 0], [0, 2]]);
        assert_eq!(g.faces().len(), 3);
        let mut inner: Vec<Vec<u32>> = g
            .bounded_faces(&pts)
            .into_iter()
            .map(|f| f.vertices)
            .collect();
        for f in &mut inner {
            let k = f
                .iter()
                .position(|&v| v == *f.iter().min().unwrap())
                .unwrap();
            f.rotate_left(k);
        }
        inner.sort();
        assert_eq!(inner, vec![vec![0, 1, 2], vec![0, 2, 3]]);
    }

    #[test]
    fn cracks_are_traversed_on_both_sides() {
        // Triangle with a dangling edge from a corner into the interior.
        let pts = [[0.0, 0.0], [4.0, 0.0], [0.0, 4.0], [1.0, 1.0]];
        let g = PlanarGraph::new(&pts, &[[0, 1], [1, 2], [2, 0], [0, 3]]);
        let inner = g.bounded_faces(&pts);
        assert_eq!(inner.len(), 1);
        let f = &inner[0].vertices;
        assert_eq!(f.len(), 5);
        assert_eq!(f.iter().filter(|&&v| v == 0).count(), 2);
        assert_eq!(f.iter().filter(|&&v| v == 3).count(), 1);
    }
}
