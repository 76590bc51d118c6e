//! The Delaunay triangulation of distinct points as plain arrays: triangles,
//! undirected edges with their two apexes, CSR vertex adjacency and (on
//! request) triangle adjacency. Built by the `spade` crate (exact predicates,
//! O(n log n) bulk loading; chosen over delaunator, whose in-circle test is
//! not exact — see BENCHMARKS.md). For cocircular points spade picks one
//! Delaunay completion; every consumer in optri is correct for any completion.

use crate::error::{Error, Result};
use crate::kernel::Point;
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
    /// Triangle adjacency, filled by [`DelaunayGraph::with_topology`] only (empty otherwise).
    pub topology: Topology,
}

/// How the triangles of a [`DelaunayGraph`] fit together. Side `j` of
/// triangle `t` runs from corner `j` to corner `j + 1`.
#[derive(Default)]
pub(crate) struct Topology {
    /// The triangle across each side, [`NO_TRIANGLE`] on the hull.
    pub neighbours: Vec<[u32; 3]>,
    /// The index into [`DelaunayGraph::edges`] of each side.
    pub sides: Vec<[u32; 3]>,
    /// Per adjacency slot (see [`DelaunayGraph::offsets`]): the edge index.
    pub slot_edges: Vec<u32>,
}

/// Marks a hull side in [`Topology::neighbours`].
pub(crate) const NO_TRIANGLE: u32 = u32::MAX;

impl DelaunayGraph {
    /// Builds the Delaunay triangulation of distinct, not-all-collinear points.
    pub fn new(points: &[Point]) -> Result<Self> {
        build(points, false)
    }

    /// [`DelaunayGraph::new`] with its [`Topology`] filled in.
    pub fn with_topology(points: &[Point]) -> Result<Self> {
        build(points, true)
    }

    /// Neighbours of vertex `v`.
    #[inline]
    pub fn neighbors(&self, v: u32) -> &[u32] {
        &self.adjacency[self.offsets[v as usize] as usize..self.offsets[v as usize + 1] as usize]
    }
}

fn build(points: &[Point], with_topology: bool) -> Result<DelaunayGraph> {
    let vertices: Vec<Vertex> = points
        .iter()
        .enumerate()
        .map(|(i, p)| Vertex {
            position: Point2::new(p[0], p[1]),
            id: i as u32,
        })
        .collect();
    let dt: DelaunayTriangulation<Vertex> = DelaunayTriangulation::bulk_load(vertices)
        .map_err(|e| Error::Internal(format!("spade's Delaunay bulk load failed: {e:?}")))?;
    if dt.num_vertices() != points.len() {
        return Err(Error::Internal(format!(
            "spade's Delaunay triangulation kept {} of {} distinct points",
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
    let mut topology = Topology::default();
    if with_topology {
        topology.slot_edges = vec![0u32; adjacency.len()];
    }
    for (i, &([u, v], _)) in edges.iter().enumerate() {
        for (a, b) in [(u, v), (v, u)] {
            let slot = fill[a as usize] as usize;
            adjacency[slot] = b;
            if with_topology {
                topology.slot_edges[slot] = i as u32;
            }
            fill[a as usize] += 1;
        }
    }
    if with_topology {
        // spade numbers the outer face 0 and lists inner faces in index
        // order, so triangle `t` is face `t + 1`; a face's edge `j` leaves its
        // vertex `j` (spade's `vertices()` is built from `adjacent_edges()`).
        topology.neighbours.reserve(triangles.len());
        topology.sides.reserve(triangles.len());
        for (t, f) in dt.inner_faces().enumerate() {
            debug_assert_eq!(f.fix().index(), t + 1);
            let e = f.adjacent_edges();
            topology.neighbours.push(e.map(|d| {
                let across = d.rev().face();
                if across.is_outer() {
                    NO_TRIANGLE
                } else {
                    across.fix().index() as u32 - 1
                }
            }));
            topology
                .sides
                .push(e.map(|d| d.as_undirected().fix().index() as u32));
        }
    }
    Ok(DelaunayGraph {
        triangles,
        edges,
        offsets,
        adjacency,
        topology,
    })
}
