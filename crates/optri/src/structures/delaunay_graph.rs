//! The Delaunay triangulation of distinct points as plain arrays: triangles,
//! undirected edges with their two apexes, CSR vertex adjacency and (on
//! request) triangle adjacency. Built by the `spade` crate (exact predicates;
//! chosen over delaunator, whose in-circle test is not exact — see
//! BENCHMARKS.md), inserting the points one by one in a biased randomized
//! insertion order ([`brio_order`]: N. Amenta, S. Choi and G. Rote,
//! *Incremental constructions con BRIO*, SoCG 2003), so the expected time is
//! O(n log n) on every input. spade's bulk load is a circle sweep whose work
//! depends on the input: quadratic on points in convex position (10⁵ points
//! on a parabola took 96 s) and on points on two crossing lines.
//!
//! Every consumer in optri is correct for
//! any Delaunay completion of cocircular points, but the answers must not
//! depend on how spade happened to build it (the completion it reaches
//! depends on the insertion order), so the graph is made canonical: faces of
//! four or more cocircular points are fanned from their smallest index (the
//! regular triangulation of an infinitesimal lifting perturbation, see
//! `fan_cocircular_faces`), triangles are numbered in sorted order and edges
//! in the order the triangles meet them. The graph is then a function of the
//! points and their numbering alone: the same under exact scaling by powers
//! of two, exact translations and any thread count, and whatever the
//! insertion order.

use crate::error::{Error, Result};
use crate::kernel::{incircle_sign, Point};
use crate::spatial::brio_order;
use spade::handles::FixedVertexHandle;
use spade::{
    DelaunayTriangulation, HasPosition, LastUsedVertexHintGenerator, Point2, Triangulation as _,
};

/// A point handed to spade with its index, so that every triangle read back
/// names its corners by the caller's numbering.
pub(super) struct Vertex {
    position: Point2<f64>,
    id: u32,
}

impl Vertex {
    /// The points `points` with their indices as ids (for spade's bulk
    /// loads, the reference constructions of the tests).
    #[cfg(test)]
    pub(super) fn numbered(points: &[Point]) -> Vec<Vertex> {
        points
            .iter()
            .enumerate()
            .map(|(i, p)| Vertex {
                position: Point2::new(p[0], p[1]),
                id: i as u32,
            })
            .collect()
    }
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
    let (triangles, neighbours) = spade_triangles(points)?;
    Ok(from_triangles(points, triangles, neighbours, with_topology))
}

/// The canonical graph of any Delaunay triangulation of `points` given as
/// triangles and, per side, the triangle across it.
fn from_triangles(
    points: &[Point],
    mut triangles: Vec<[u32; 3]>,
    mut neighbours: Vec<[u32; 3]>,
    with_topology: bool,
) -> DelaunayGraph {
    fan_cocircular_faces(points, &mut triangles, &mut neighbours, |_, _| false);
    canonical_order(&mut triangles, &mut neighbours);
    // Edges in the order their first triangle meets them: side `j` of `t`
    // is new unless the triangle across it comes earlier.
    let mut edges = Vec::with_capacity(triangles.len() * 3 / 2 + 2);
    let mut sides = vec![[0u32; 3]; if with_topology { triangles.len() } else { 0 }];
    for (t, tri) in triangles.iter().enumerate() {
        for j in 0..3 {
            let across = neighbours[t][j];
            if across != NO_TRIANGLE && (across as usize) < t {
                continue;
            }
            let (u, v) = (tri[j], tri[(j + 1) % 3]);
            let right = (across != NO_TRIANGLE).then(|| {
                let k = side_towards(&neighbours, across, t as u32);
                triangles[across as usize][(k + 2) % 3]
            });
            if with_topology {
                sides[t][j] = edges.len() as u32;
                if across != NO_TRIANGLE {
                    let k = side_towards(&neighbours, across, t as u32);
                    sides[across as usize][k] = edges.len() as u32;
                }
            }
            edges.push(([u, v], [Some(tri[(j + 2) % 3]), right]));
        }
    }
    let mut degree = vec![0u32; points.len() + 1];
    for &([u, v], _) in &edges {
        degree[u as usize] += 1;
        degree[v as usize] += 1;
    }
    let mut offsets = vec![0u32; points.len() + 1];
    for v in 0..points.len() {
        offsets[v + 1] = offsets[v] + degree[v];
    }
    drop(degree);
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
    drop(fill);
    if with_topology {
        topology.neighbours = neighbours;
        topology.sides = sides;
    }
    DelaunayGraph {
        triangles,
        edges,
        offsets,
        adjacency,
        topology,
    }
}

/// The side of triangle `u` whose neighbour is `t`.
#[inline]
fn side_towards(neighbours: &[[u32; 3]], u: u32, t: u32) -> usize {
    let n = neighbours[u as usize];
    if n[0] == t {
        0
    } else if n[1] == t {
        1
    } else {
        debug_assert_eq!(n[2], t, "triangles {u} and {t} are not adjacent");
        2
    }
}

/// spade's Delaunay triangles (counter-clockwise, distinct indices) and,
/// per side `j` (corner `j` to corner `j + 1`), the triangle across it.
/// spade's own structure is dropped before returning.
#[allow(clippy::type_complexity)]
fn spade_triangles(points: &[Point]) -> Result<(Vec<[u32; 3]>, Vec<[u32; 3]>)> {
    let mut dt: DelaunayTriangulation<Vertex, (), (), (), LastUsedVertexHintGenerator> =
        DelaunayTriangulation::with_capacity(points.len(), 3 * points.len(), 2 * points.len());
    insert_in_brio_order(&mut dt, points)?;
    Ok(triangle_arrays(&dt))
}

/// Inserts `points` into the empty spade triangulation `dt` (Delaunay or
/// constrained) in [`brio_order`], each located by a walk from the last one
/// inserted (close in the Z-order of its round), and returns each point's
/// vertex handle by index.
///
/// # Errors
/// [`Error::Internal`] if spade fails or merges points.
pub(super) fn insert_in_brio_order<T>(
    dt: &mut T,
    points: &[Point],
) -> Result<Vec<FixedVertexHandle>>
where
    T: spade::Triangulation<Vertex = Vertex>,
{
    let mut handles = vec![FixedVertexHandle::from_index(0); points.len()];
    for v in brio_order(points) {
        let p = points[v as usize];
        handles[v as usize] = dt
            .insert(Vertex {
                position: Point2::new(p[0], p[1]),
                id: v,
            })
            .map_err(|e| Error::Internal(format!("spade's Delaunay insertion failed: {e:?}")))?;
    }
    kept_every_point(dt, points.len())?;
    Ok(handles)
}

/// An error unless spade's triangulation `dt` holds all `n` points (it
/// merges equal ones).
fn kept_every_point<T: spade::Triangulation>(dt: &T, n: usize) -> Result<()> {
    if dt.num_vertices() != n {
        return Err(Error::Internal(format!(
            "spade's Delaunay triangulation kept {} of {} distinct points",
            dt.num_vertices(),
            n
        )));
    }
    Ok(())
}

/// The inner triangles of a spade triangulation (Delaunay or constrained)
/// of numbered vertices, counter-clockwise in the vertices' ids, and per
/// side `j` (corner `j` to corner `j + 1`) the triangle across it
/// ([`NO_TRIANGLE`] on the outer face).
#[allow(clippy::type_complexity)]
pub(super) fn triangle_arrays<T>(dt: &T) -> (Vec<[u32; 3]>, Vec<[u32; 3]>)
where
    T: spade::Triangulation<Vertex = Vertex>,
{
    let mut triangles = Vec::with_capacity(dt.num_inner_faces());
    let mut neighbours = Vec::with_capacity(dt.num_inner_faces());
    // spade numbers the outer face 0 and lists inner faces in index order,
    // so triangle `t` is face `t + 1`; a face's edge `j` leaves its vertex
    // `j` (spade's `vertices()` is built from `adjacent_edges()`).
    for (t, f) in dt.inner_faces().enumerate() {
        debug_assert_eq!(f.fix().index(), t + 1);
        triangles.push(f.vertices().map(|v| v.data().id));
        neighbours.push(f.adjacent_edges().map(|d| {
            let across = d.rev().face();
            if across.is_outer() {
                NO_TRIANGLE
            } else {
                across.fix().index() as u32 - 1
            }
        }));
    }
    (triangles, neighbours)
}

/// Makes the triangulation independent of how spade built it: every face of
/// four or more cocircular points is fanned from its smallest index. Sides
/// that are `fixed` (the constraints of a constrained triangulation) are
/// never flipped, so a face they cut is fanned part by part.
///
/// This is the regular triangulation of the points lifted to the paraboloid
/// and then lowered by `δ_m` with `δ_0 ≫ δ_1 ≫ …` infinitesimal (a lowered
/// point is inside the circle of three others on a common circle). It is
/// one particular Delaunay completion: a non-cocircular quadrilateral keeps
/// its Delaunay diagonal, and in a cocircular quadrilateral `abcd` the lowest
/// point lies below the plane of the other three, so the diagonal through
/// `min(a, b, c, d)` is the locally regular one. Lawson's flips under this
/// perturbed (never zero) in-circle test end in the unique regular
/// triangulation (each flip lowers the lifted surface; locally convex means
/// convex), and starting from a Delaunay triangulation only cocircular
/// quadrilaterals — always convex — are ever flipped. With fixed sides the
/// same flips end in the constrained regular triangulation (every side not
/// fixed locally regular), unique for the perturbed points and constrained
/// Delaunay for the points themselves; starting from a constrained Delaunay
/// triangulation, again only cocircular quadrilaterals are flipped.
pub(super) fn fan_cocircular_faces(
    points: &[Point],
    triangles: &mut [[u32; 3]],
    neighbours: &mut [[u32; 3]],
    fixed: impl Fn(u32, u32) -> bool,
) {
    let p = |v: u32| points[v as usize];
    let mut stack: Vec<(u32, u8)> = Vec::new();
    for (t, across) in neighbours.iter().enumerate() {
        for (j, &u) in across.iter().enumerate() {
            if u != NO_TRIANGLE && (t as u32) < u {
                stack.push((t as u32, j as u8));
            }
        }
    }
    // Only the sides whose in-circle test is zero (or, defensively,
    // positive) stay on the stack; on points in general position it empties
    // in one pass.
    let mut pending: Vec<(u32, u8)> = Vec::new();
    let illegal = |triangles: &[[u32; 3]], neighbours: &[[u32; 3]], t: u32, j: usize| {
        let u = neighbours[t as usize][j];
        if u == NO_TRIANGLE {
            return None;
        }
        let tri = triangles[t as usize];
        let (a, b, c) = (tri[j], tri[(j + 1) % 3], tri[(j + 2) % 3]);
        let k = side_towards(neighbours, u, t);
        let d = triangles[u as usize][(k + 2) % 3];
        let s = incircle_sign(p(a), p(b), p(c), p(d));
        ((s > 0 || (s == 0 && c.min(d) < a.min(b))) && !fixed(a, b)).then_some((u, k))
    };
    for &(t, j) in &stack {
        if illegal(triangles, neighbours, t, j as usize).is_some() {
            pending.push((t, j));
        }
    }
    drop(stack);
    while let Some((t, j)) = pending.pop() {
        let j = j as usize;
        let Some((u, k)) = illegal(triangles, neighbours, t, j) else {
            continue;
        };
        let (ti, ui) = (t as usize, u as usize);
        let [a, b, c] = [
            triangles[ti][j],
            triangles[ti][(j + 1) % 3],
            triangles[ti][(j + 2) % 3],
        ];
        let d = triangles[ui][(k + 2) % 3];
        let (n_bc, n_ca) = (neighbours[ti][(j + 1) % 3], neighbours[ti][(j + 2) % 3]);
        let (n_ad, n_db) = (neighbours[ui][(k + 1) % 3], neighbours[ui][(k + 2) % 3]);
        // t = (a, b, c) and u = (b, a, d) become t = (c, a, d), u = (d, b, c).
        triangles[ti] = [c, a, d];
        neighbours[ti] = [n_ca, n_ad, u];
        triangles[ui] = [d, b, c];
        neighbours[ui] = [n_db, n_bc, t];
        if n_ad != NO_TRIANGLE {
            let s = side_towards(neighbours, n_ad, u);
            neighbours[n_ad as usize][s] = t;
        }
        if n_bc != NO_TRIANGLE {
            let s = side_towards(neighbours, n_bc, t);
            neighbours[n_bc as usize][s] = u;
        }
        pending.extend([(t, 0), (t, 1), (u, 0), (u, 1)]);
    }
}

/// Numbers the triangles canonically: each rotated to start at its smallest
/// corner, then sorted, so that the graph depends only on the triangles and
/// never on spade's construction order (which depends on rounding: its bulk
/// load compares projections with an absolute `f64::EPSILON`).
pub(super) fn canonical_order(triangles: &mut Vec<[u32; 3]>, neighbours: &mut Vec<[u32; 3]>) {
    let rotation = |t: &[u32; 3]| {
        if t[0] < t[1] && t[0] < t[2] {
            0
        } else if t[1] < t[2] {
            1
        } else {
            2
        }
    };
    // A counting sort by the smallest corner, then each (tiny) bucket by the
    // other two: O(n), where a comparison sort of indices by their
    // triangles missed the cache on every comparison (2-3x the bulk load).
    let corners = triangles
        .iter()
        .flatten()
        .max()
        .map_or(0, |&m| m as usize + 1);
    let mut start = vec![0u32; corners + 1];
    for t in triangles.iter() {
        start[t[rotation(t)] as usize + 1] += 1;
    }
    for v in 0..corners {
        start[v + 1] += start[v];
    }
    let mut order = vec![0u32; triangles.len()];
    {
        let mut fill = start.clone();
        for (i, t) in triangles.iter().enumerate() {
            let m = t[rotation(t)] as usize;
            order[fill[m] as usize] = i as u32;
            fill[m] += 1;
        }
    }
    let key = |i: &u32| {
        let t = &triangles[*i as usize];
        let r = rotation(t);
        [t[(r + 1) % 3], t[(r + 2) % 3]]
    };
    for v in 0..corners {
        order[start[v] as usize..start[v + 1] as usize].sort_unstable_by_key(key);
    }
    drop(start);
    let mut rank = vec![0u32; triangles.len()];
    for (new, &old) in order.iter().enumerate() {
        rank[old as usize] = new as u32;
    }
    let relabel = |n: u32| {
        if n == NO_TRIANGLE {
            n
        } else {
            rank[n as usize]
        }
    };
    let mut new_triangles = Vec::with_capacity(triangles.len());
    let mut new_neighbours = Vec::with_capacity(triangles.len());
    for &old in &order {
        let (t, n) = (triangles[old as usize], neighbours[old as usize]);
        let r = rotation(&t);
        new_triangles.push([t[r], t[(r + 1) % 3], t[(r + 2) % 3]]);
        new_neighbours.push([n[r], n[(r + 1) % 3], n[(r + 2) % 3]].map(relabel));
    }
    *triangles = new_triangles;
    *neighbours = new_neighbours;
}

#[cfg(test)]
mod tests;
