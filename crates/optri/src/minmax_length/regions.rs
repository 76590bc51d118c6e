//! §3 steps 1–2 read off the Delaunay triangles: the regions of
//! `ch(S) ∪ rng(S′)` (000_5891e11f36dd26ad.txt §3).
//!
//! Every edge of `ch(S) ∪ rng(S′)` is a Delaunay edge (see the module docs of
//! [`super`]), so each region is a union of Delaunay triangles: the classes of
//! triangles joined across sides that are neither hull nor `rng(S′)` edges.
//! The graph is connected (it contains the minimum spanning tree), so every
//! region is a simply connected polygon whose boundary is one closed walk; a
//! crack is a boundary edge with the same region on both sides and is walked
//! once per side. The region's Delaunay triangles are also a feasible
//! triangulation of it, which bounds the chords its optimum can use.

use crate::delaunay::{DelaunayGraph, NO_TRIANGLE};
use crate::kernel::{compare_lengths, Point};
use std::cmp::Ordering;

/// The Delaunay triangles grouped by region.
pub(crate) struct Regions {
    offsets: Vec<u32>,
    members: Vec<u32>,
}

/// The boundary walk of one region and the longest Delaunay edge inside it.
pub(crate) struct Boundary {
    /// Corners in counter-clockwise order (a vertex repeats at a crack or a
    /// pinch point).
    pub corners: Vec<u32>,
    /// The longest non-boundary side of the region's Delaunay triangles.
    pub longest_diagonal: Option<[u32; 2]>,
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
    /// the left), and finds its longest Delaunay diagonal.
    ///
    /// From a boundary side `x → y` of triangle `t`, the next boundary side
    /// leaves `y`: turn around `y` through the region's triangles, crossing
    /// non-boundary sides, until a side leaving `y` is a boundary.
    pub fn boundary(
        &self,
        points: &[Point],
        g: &DelaunayGraph,
        rng: &[bool],
        r: usize,
    ) -> Boundary {
        let triangles = self.triangles(r);
        let p = |v: u32| points[v as usize];
        let mut longest: Option<[u32; 2]> = None;
        let mut boundary_sides = 0;
        let mut start = None;
        for &t in triangles {
            let tri = g.triangles[t as usize];
            for j in 0..3 {
                if is_boundary(g, rng, t as usize, j) {
                    boundary_sides += 1;
                    start.get_or_insert((t as usize, j));
                    continue;
                }
                let (x, y) = (tri[j], tri[(j + 1) % 3]);
                // Each diagonal is seen from both sides; compare it once.
                if x < y
                    && longest.map_or(true, |[a, b]| {
                        compare_lengths(p(x), p(y), p(a), p(b)) == Ordering::Greater
                    })
                {
                    longest = Some([x, y]);
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
        Boundary {
            corners,
            longest_diagonal: longest,
        }
    }
}

/// Is side `j` of triangle `t` a hull edge or an `rng(S′)` edge?
#[inline]
pub(crate) fn is_boundary(g: &DelaunayGraph, rng: &[bool], t: usize, j: usize) -> bool {
    g.topology.neighbours[t][j] == NO_TRIANGLE || rng[g.topology.sides[t][j] as usize]
}
