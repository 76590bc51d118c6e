//! Delaunay triangulation, through the `spade` crate (exact predicates,
//! O(n log n) bulk loading; chosen over delaunator, whose in-circle test is
//! not exact — see BENCHMARKS.md).
//!
//! For cocircular points spade picks one Delaunay completion; every consumer
//! in optri is correct for *any* completion (see the lemmas cited in
//! [`mod@crate::relative_neighborhood_graph`] and [`mod@crate::gabriel_graph`]).

use crate::error::{Error, Result};
use crate::kernel::Point;
use crate::point_set::PointSet;
use crate::triangulation::Triangulation;
use spade::handles::FixedVertexHandle;
use spade::{DelaunayTriangulation, HasPosition, Point2, Triangulation as _};

struct Vertex {
    position: Point2<f64>,
    id: u32,
}

impl HasPosition for Vertex {
    type Scalar = f64;
    fn position(&self) -> Point2<f64> {
        self.position
    }
}

/// A Delaunay triangulation of distinct points, as plain arrays.
pub(crate) struct DelaunayGraph {
    /// Counter-clockwise triangles (distinct indices).
    pub triangles: Vec<[u32; 3]>,
    /// Undirected edges `[u, v]` with the apex of the triangle to the left of
    /// `u → v` and of the one to the left of `v → u` (`None` on the hull).
    pub edges: Vec<([u32; 2], [Option<u32>; 2])>,
    /// CSR adjacency: neighbours of `v` are `adjacency[offsets[v]..offsets[v+1]]`.
    pub offsets: Vec<u32>,
    /// See `offsets`.
    pub adjacency: Vec<u32>,
}

impl DelaunayGraph {
    /// Neighbours of vertex `v`.
    #[inline]
    pub fn neighbors(&self, v: u32) -> &[u32] {
        &self.adjacency[self.offsets[v as usize] as usize..self.offsets[v as usize + 1] as usize]
    }
}

/// Builds the Delaunay triangulation of distinct, not-all-collinear points.
pub(crate) fn delaunay_graph(points: &[Point]) -> Result<DelaunayGraph> {
    let vertices: Vec<Vertex> = points
        .iter()
        .enumerate()
        .map(|(i, p)| Vertex {
            position: Point2::new(p[0], p[1]),
            id: i as u32,
        })
        .collect();
    let dt: DelaunayTriangulation<Vertex> = DelaunayTriangulation::bulk_load(vertices)
        .map_err(|e| Error::Unsupported(format!("the Delaunay triangulation failed: {e:?}")))?;
    if dt.num_vertices() != points.len() {
        return Err(Error::Unsupported(format!(
            "the Delaunay triangulation kept {} of {} distinct points",
            dt.num_vertices(),
            points.len()
        )));
    }
    let id = |h: FixedVertexHandle| dt.vertex(h).data().id;
    let triangles: Vec<[u32; 3]> = dt
        .inner_faces()
        .map(|f| f.vertices().map(|v| v.data().id))
        .collect();
    let mut edges = Vec::with_capacity(dt.num_undirected_edges());
    let mut degree = vec![0u32; points.len() + 1];
    for e in dt.undirected_edges() {
        let d = e.as_directed();
        let (u, v) = (id(d.from().fix()), id(d.to().fix()));
        let left = d.opposite_vertex().map(|w| w.data().id);
        let right = d.rev().opposite_vertex().map(|w| w.data().id);
        edges.push(([u, v], [left, right]));
        degree[u as usize] += 1;
        degree[v as usize] += 1;
    }
    let mut offsets = vec![0u32; points.len() + 1];
    for v in 0..points.len() {
        offsets[v + 1] = offsets[v] + degree[v];
    }
    let mut fill = offsets.clone();
    let mut adjacency = vec![0u32; offsets[points.len()] as usize];
    for &([u, v], _) in &edges {
        adjacency[fill[u as usize] as usize] = v;
        fill[u as usize] += 1;
        adjacency[fill[v as usize] as usize] = u;
        fill[v as usize] += 1;
    }
    Ok(DelaunayGraph {
        triangles,
        edges,
        offsets,
        adjacency,
    })
}

/// The Delaunay triangulation of `points`.
///
/// For cocircular points one Delaunay completion is returned (spade's).
/// Runs in O(n log n) expected time.
pub fn delaunay(points: &PointSet) -> Result<Triangulation> {
    let g = delaunay_graph(points.points())?;
    Ok(Triangulation::from_distinct(points, g.triangles))
}

/// The Delaunay edges of `points` as `[min, max]` input-index pairs, sorted.
pub fn delaunay_edges(points: &PointSet) -> Result<Vec<[u32; 2]>> {
    let g = delaunay_graph(points.points())?;
    Ok(to_input_edges(points, g.edges.iter().map(|&(e, _)| e)))
}

/// Maps distinct-index edges to sorted `[min, max]` input-index pairs.
pub(crate) fn to_input_edges(
    points: &PointSet,
    edges: impl Iterator<Item = [u32; 2]>,
) -> Vec<[u32; 2]> {
    let mut out: Vec<[u32; 2]> = edges
        .map(|[u, v]| {
            let (a, b) = (points.input_index(u), points.input_index(v));
            [a.min(b), a.max(b)]
        })
        .collect();
    out.sort_unstable();
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::incircle_sign;

    #[test]
    fn delaunay_is_valid_and_locally_delaunay_on_a_grid() {
        let mut pts = Vec::new();
        for x in 0..7 {
            for y in 0..5 {
                pts.push([x as f64 * 0.1, y as f64 * 0.1]);
            }
        }
        let ps = PointSet::new(&pts).unwrap();
        let t = delaunay(&ps).unwrap();
        t.validate().unwrap();
        let g = delaunay_graph(ps.points()).unwrap();
        for &([u, v], [l, r]) in &g.edges {
            if let (Some(l), Some(r)) = (l, r) {
                let p = |i: u32| ps.points()[i as usize];
                assert!(incircle_sign(p(u), p(v), p(l), p(r)) <= 0);
            }
        }
    }
}
