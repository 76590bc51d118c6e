//! §3 steps 1–2 of Edelsbrunner & Tan (*A quadratic time algorithm for the
//! minmax length triangulation*, 1993) read off the Delaunay triangles: the
//! regions of `ch(S) ∪ rng(S′)`.
//!
//! Every edge of `ch(S) ∪ rng(S′)` is a Delaunay edge (see the module docs of
//! [`super`]), so each region is a union of Delaunay triangles: the classes of
//! triangles joined across sides that are neither hull nor `rng(S′)` edges.
//! The graph is connected (it contains the minimum spanning tree), so every
//! region is a simply connected polygon whose boundary is one closed walk; a
//! crack is a boundary edge with the same region on both sides and is walked
//! once per side. The region's Delaunay triangles are also a feasible
//! triangulation of it, which bounds the chords its optimum can use.

use crate::kernel::{compare_lengths, orient_sign, Point};
use crate::structures::{DelaunayGraph, NO_TRIANGLE};
use std::cmp::Ordering;

/// The Delaunay triangles grouped by region.
pub(crate) struct Regions {
    offsets: Vec<u32>,
    members: Vec<u32>,
}

/// The boundary walk of one region.
pub(crate) struct Boundary {
    /// Corners in counter-clockwise order (a vertex repeats at a crack or a
    /// pinch point).
    pub corners: Vec<u32>,
}

impl Regions {
    /// Flood-fills the triangles of `g` (built by `delaunay_mesh`) across
    /// the sides that are not region boundaries; `rng` flags the `rng(S′)`
    /// edges, indexed like `g.edges`.
    pub fn new(g: &DelaunayGraph, rng: &[bool]) -> Self {
        let count = g.triangles.len();
        let mut label = vec![u32::MAX; count];
        let mut members = Vec::with_capacity(count);
        let mut offsets = vec![0u32];
        for seed in 0..count {
            if label[seed] != u32::MAX {
                continue;
            }
            let region = offsets.len() as u32 - 1;
            label[seed] = region;
            let first = members.len();
            members.push(seed as u32);
            let mut next = first;
            while next < members.len() {
                let t = members[next] as usize;
                next += 1;
                for j in 0..3 {
                    if is_boundary(g, rng, t, j) {
                        continue;
                    }
                    let u = g.topology.neighbours[t][j] as usize;
                    if label[u] == u32::MAX {
                        label[u] = region;
                        members.push(u as u32);
                    }
                }
            }
            offsets.push(members.len() as u32);
        }
        Self { offsets, members }
    }

    /// Number of regions.
    pub fn len(&self) -> usize {
        self.offsets.len() - 1
    }

    /// The Delaunay triangles (indices into `g.triangles`) of region `r`.
    pub fn triangles(&self, r: usize) -> &[u32] {
        &self.members[self.offsets[r] as usize..self.offsets[r + 1] as usize]
    }

    /// Walks the boundary of region `r` counter-clockwise (the region on
    /// the left).
    ///
    /// From a boundary side `x → y` of triangle `t`, the next boundary side
    /// leaves `y`: turn around `y` through the region's triangles, crossing
    /// non-boundary sides, until a side leaving `y` is a boundary.
    pub fn boundary(&self, g: &DelaunayGraph, rng: &[bool], r: usize) -> Boundary {
        let mut boundary_sides = 0;
        let mut start = None;
        for &t in self.triangles(r) {
            for j in 0..3 {
                if is_boundary(g, rng, t as usize, j) {
                    boundary_sides += 1;
                    start.get_or_insert((t as usize, j));
                }
            }
        }
        let start = start.expect("a region of a bounded triangulation has a boundary");
        let mut corners = Vec::with_capacity(boundary_sides);
        let (mut t, mut j) = start;
        loop {
            corners.push(g.triangles[t][j]);
            let y = g.triangles[t][(j + 1) % 3];
            j = (j + 1) % 3;
            while !is_boundary(g, rng, t, j) {
                // Side `j` leaves `y`; across it the triangle holds the same
                // side reversed, and its own side leaving `y` comes next.
                t = g.topology.neighbours[t][j] as usize;
                j = g.triangles[t]
                    .iter()
                    .position(|&c| c == y)
                    .expect("neighbouring triangles share the side's endpoints");
            }
            if (t, j) == start || corners.len() > boundary_sides {
                break;
            }
        }
        debug_assert_eq!(
            corners.len(),
            boundary_sides,
            "one boundary walk per region"
        );
        Boundary { corners }
    }
}

/// Is side `j` of triangle `t` a hull edge or an `rng(S′)` edge?
#[inline]
pub(crate) fn is_boundary(g: &DelaunayGraph, rng: &[bool], t: usize, j: usize) -> bool {
    g.topology.neighbours[t][j] == NO_TRIANGLE || rng[g.topology.sides[t][j] as usize]
}

/// A region's own triangles with adjacency inside the region
/// ([`NO_TRIANGLE`] across its boundary), for local edge flips.
pub(crate) struct LocalMesh {
    pub triangles: Vec<[u32; 3]>,
    neighbours: Vec<[u32; 3]>,
}

impl Regions {
    /// The Delaunay triangles of region `r` as a [`LocalMesh`].
    pub fn local_mesh(&self, g: &DelaunayGraph, rng: &[bool], r: usize) -> LocalMesh {
        let members = self.triangles(r);
        let local = |t: u32| members.iter().position(|&m| m == t).expect("same region") as u32;
        let mut neighbours = Vec::with_capacity(members.len());
        for &t in members {
            let mut n = [NO_TRIANGLE; 3];
            for (j, slot) in n.iter_mut().enumerate() {
                if !is_boundary(g, rng, t as usize, j) {
                    *slot = local(g.topology.neighbours[t as usize][j]);
                }
            }
            neighbours.push(n);
        }
        LocalMesh {
            triangles: members.iter().map(|&t| g.triangles[t as usize]).collect(),
            neighbours,
        }
    }
}

impl LocalMesh {
    /// The longest diagonal (non-boundary side), as (triangle, side).
    fn longest_diagonal(&self, points: &[Point]) -> Option<(usize, usize)> {
        let p = |v: u32| points[v as usize];
        let mut best: Option<(usize, usize)> = None;
        for (t, tri) in self.triangles.iter().enumerate() {
            for j in 0..3 {
                let u = self.neighbours[t][j];
                // Each diagonal once: from the triangle with the smaller index.
                if u == NO_TRIANGLE || (u as usize) < t {
                    continue;
                }
                let (x, y) = (tri[j], tri[(j + 1) % 3]);
                if best.is_none_or(|(bt, bj)| {
                    let b = self.triangles[bt];
                    compare_lengths(p(x), p(y), p(b[bj]), p(b[(bj + 1) % 3])) == Ordering::Greater
                }) {
                    best = Some((t, j));
                }
            }
        }
        best
    }

    /// Flips the longest diagonal while its flip is legal (a strictly
    /// convex quadrilateral, exact orientations) and strictly shorter; each
    /// flip shortens the sorted diagonal lengths, so this stops. Returns the
    /// longest diagonal left: an upper bound on the region's optimum, as the
    /// result is a triangulation of the region.
    pub fn flip_longest_diagonals(&mut self, points: &[Point]) -> Option<[u32; 2]> {
        let p = |v: u32| points[v as usize];
        loop {
            let (t, j) = self.longest_diagonal(points)?;
            let [x, y, a] = [0, 1, 2].map(|o| self.triangles[t][(j + o) % 3]);
            let u = self.neighbours[t][j] as usize;
            let i = (0..3)
                .find(|&i| self.triangles[u][i] == y)
                .expect("neighbours share the side");
            let b = self.triangles[u][(i + 2) % 3];
            let legal = orient_sign(p(a), p(b), p(x)) < 0 && orient_sign(p(a), p(b), p(y)) > 0;
            if !legal || compare_lengths(p(a), p(b), p(x), p(y)) != Ordering::Less {
                return Some([x, y]);
            }
            // t = (x, y, a), u = (y, x, b) become t = (a, x, b), u = (b, y, a).
            let n_ya = self.neighbours[t][(j + 1) % 3];
            let n_ax = self.neighbours[t][(j + 2) % 3];
            let n_xb = self.neighbours[u][(i + 1) % 3];
            let n_by = self.neighbours[u][(i + 2) % 3];
            self.triangles[t] = [a, x, b];
            self.neighbours[t] = [n_ax, n_xb, u as u32];
            self.triangles[u] = [b, y, a];
            self.neighbours[u] = [n_by, n_ya, t as u32];
            for (n, from, to) in [(n_xb, u, t), (n_ya, t, u)] {
                if n != NO_TRIANGLE {
                    for s in self.neighbours[n as usize].iter_mut() {
                        if *s == from as u32 {
                            *s = to as u32;
                        }
                    }
                }
            }
        }
    }
}
