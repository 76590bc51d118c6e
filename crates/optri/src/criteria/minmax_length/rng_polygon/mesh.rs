//! The Delaunay triangles addressed by directed edge, with the region
//! boundaries marked: what an [`super::RngPolygon`] reads its triangles and
//! its hull edges from.

use super::is_boundary;
use crate::structures::{DelaunayGraph, NO_TRIANGLE};

/// Delaunay triangles addressed by directed edge, with the region
/// boundaries (`ch(S) ∪ rng(S′)`) marked.
pub(crate) struct Mesh<'a> {
    pub(super) g: &'a DelaunayGraph,
    /// Per Delaunay edge (indexed like `g.edges`): is it in `rng(S′)`?
    rng: &'a [bool],
    /// One triangle at each vertex, where turning around it starts.
    vertex_triangle: Vec<u32>,
}

impl<'a> Mesh<'a> {
    /// `g` must come from [`DelaunayGraph::with_topology`].
    pub fn new(g: &'a DelaunayGraph, rng: &'a [bool]) -> Self {
        let mut vertex_triangle = vec![NO_TRIANGLE; g.offsets.len() - 1];
        for (t, tri) in g.triangles.iter().enumerate() {
            for &c in tri {
                vertex_triangle[c as usize] = t as u32;
            }
        }
        Self {
            g,
            rng,
            vertex_triangle,
        }
    }

    /// The triangle to the left of `u → v` and the side index of `u → v` in
    /// it: turn around `u` one way, then, if the hull stops the turn, the
    /// other way. O(degree of `u`).
    fn side(&self, u: u32, v: u32) -> Option<(u32, usize)> {
        let start = self.vertex_triangle[u as usize];
        let corner = |t: u32| {
            self.g.triangles[t as usize]
                .iter()
                .position(|&c| c == u)
                .expect("the turn stays at the vertex")
        };
        let nb = &self.g.topology.neighbours;
        let (mut t, mut i) = (start, corner(start));
        // Counter-clockwise: across the side entering `u`.
        loop {
            if self.g.triangles[t as usize][(i + 1) % 3] == v {
                return Some((t, i));
            }
            t = nb[t as usize][(i + 2) % 3];
            if t == NO_TRIANGLE || t == start {
                break;
            }
            i = corner(t);
        }
        if t == start {
            return None;
        }
        // Clockwise from the start: across the side leaving `u`.
        let (mut t, mut i) = (start, corner(start));
        loop {
            t = nb[t as usize][i];
            if t == NO_TRIANGLE {
                return None;
            }
            i = corner(t);
            if self.g.triangles[t as usize][(i + 1) % 3] == v {
                return Some((t, i));
            }
        }
    }

    /// Do the triangles tile the region with boundary walk `corners`
    /// (counter-clockwise): is every boundary edge a Delaunay edge with a
    /// triangle on its region side? Always so for the regions of
    /// `ch(S) ∪ rng(S′)`; under another metric only where the metric's RNG
    /// edges on the boundary happen to be Delaunay edges.
    pub fn tiles(&self, corners: &[u32]) -> bool {
        let k = corners.len();
        (0..k).all(|i| self.side(corners[i], corners[(i + 1) % k]).is_some())
    }

    /// The triangle to the left of `u → v`.
    pub(super) fn left_of(&self, u: u32, v: u32) -> Option<u32> {
        self.side(u, v).map(|(t, _)| t)
    }

    /// Is `u v` a region boundary (or no interior Delaunay edge at all)?
    pub(super) fn is_constraint(&self, u: u32, v: u32) -> bool {
        self.side(u, v)
            .is_none_or(|(t, j)| is_boundary(self.g, self.rng, t as usize, j))
    }

    /// Is `u v` a hull edge that is not in `rng(S′)`?
    pub fn is_hull_only(&self, u: u32, v: u32) -> bool {
        let on_hull = |(t, j): (u32, usize)| {
            let edge = self.g.topology.sides[t as usize][j] as usize;
            (self.g.topology.neighbours[t as usize][j] == NO_TRIANGLE).then_some(edge)
        };
        self.side(u, v)
            .and_then(on_hull)
            .or_else(|| self.side(v, u).and_then(on_hull))
            .is_some_and(|edge| !self.rng[edge])
    }
}
