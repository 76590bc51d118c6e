//! Relative neighbourhood graph (000_5891e11f36dd26ad.txt §2), from the
//! Delaunay triangulation.
//!
//! `pq` is an RNG edge iff its open lune `{x : max(|xp|, |xq|) < |pq|}`
//! contains no point (Toussaint 1980). A point on the open segment `pq` lies
//! in the lune, so it blocks `pq`. RNG ⊆ every Delaunay completion, because a
//! non-Delaunay pair has a point strictly inside its diametral disc, and a
//! Delaunay pair crossed by a cocircular edge `rs` has an angle `prq` or `psq`
//! of at least 90°; either point lies in the lune.
//!
//! Testing only the Delaunay neighbours of `p` and `q` is *wrong* (see
//! `shared/notes/literature.md` §a). Instead we use the greedy-routing lemma:
//! in a Delaunay triangulation every vertex `r ≠ p` has a neighbour strictly
//! closer to `p`. Hence the points of the open disc `D(p, |pq|)` together with
//! `p` induce a connected subgraph, and a depth-first search from `p` that only
//! enters that disc visits every candidate of the lune.

use crate::error::Result;
use crate::kernel::{compare_lengths, Point};
use crate::parallel::prelude::*;
use crate::spatial::morton_order;
use crate::structures::DelaunayGraph;
use crate::structures::PointSet;
use std::cmp::Ordering::Less;

/// The Delaunay graph renumbered along a Z-order curve, so that points close
/// in the plane are close in memory: the lune searches are memory-bound, and
/// input order scatters neighbours across the whole point array.
struct LocalGraph {
    points: Vec<Point>,
    offsets: Vec<u32>,
    adjacency: Vec<u32>,
    /// `original[local]` is the index in the caller's numbering.
    original: Vec<u32>,
}

impl LocalGraph {
    fn new(points: &[Point], g: &DelaunayGraph) -> Self {
        let original = morton_order(points);
        let mut local = vec![0u32; points.len()];
        for (l, &o) in original.iter().enumerate() {
            local[o as usize] = l as u32;
        }
        let mut offsets = Vec::with_capacity(points.len() + 1);
        let mut adjacency = Vec::with_capacity(g.adjacency.len());
        offsets.push(0);
        for &o in &original {
            adjacency.extend(g.neighbors(o).iter().map(|&x| local[x as usize]));
            offsets.push(adjacency.len() as u32);
        }
        Self {
            points: original.iter().map(|&o| points[o as usize]).collect(),
            offsets,
            adjacency,
            original,
        }
    }

    #[inline]
    fn neighbors(&self, v: u32) -> &[u32] {
        &self.adjacency[self.offsets[v as usize] as usize..self.offsets[v as usize + 1] as usize]
    }

    /// Does some point lie strictly inside the lune of the Delaunay edge `pq`?
    ///
    /// By the greedy-routing lemma the points of the open disc `D(p, |pq|)`
    /// and `p` induce a connected subgraph, so a search from `p` that only
    /// expands vertices inside the disc meets every point of the lune.
    fn lune_is_occupied(&self, p: u32, q: u32, inside: &mut Vec<u32>) -> bool {
        let (pp, pq) = (self.points[p as usize], self.points[q as usize]);
        // The disc holds O(1) points on typical data, so a short list of the
        // expanded vertices beats an n-sized "seen" array.
        inside.clear();
        inside.push(p);
        let mut next = 0;
        while next < inside.len() {
            let w = inside[next];
            next += 1;
            for &x in self.neighbors(w) {
                // q is on the disc's boundary; testing it would be an exact tie
                // that always takes the slow path of the predicate.
                if x == q {
                    continue;
                }
                let px = self.points[x as usize];
                if compare_lengths(px, pp, pp, pq) != Less || inside.contains(&x) {
                    continue; // outside the open disc around p, or already expanded
                }
                if compare_lengths(px, pq, pp, pq) == Less {
                    return true;
                }
                inside.push(x);
            }
        }
        false
    }
}

/// RNG edges as distinct-index pairs, from a Delaunay graph.
pub(crate) fn rng_from_delaunay(points: &[Point], g: &DelaunayGraph) -> Vec<[u32; 2]> {
    let local = LocalGraph::new(points, g);
    let n = points.len() as u32;
    (0..n)
        .into_par_iter()
        .with_min_len(4096)
        .fold(
            || (Vec::new(), Vec::new()),
            |(mut kept, mut inside), p| {
                for &q in local.neighbors(p) {
                    // Each edge once, searched from its lower-degree endpoint.
                    let (dp, dq) = (local.neighbors(p).len(), local.neighbors(q).len());
                    if (dp, p) < (dq, q) && !local.lune_is_occupied(p, q, &mut inside) {
                        kept.push([local.original[p as usize], local.original[q as usize]]);
                    }
                }
                (kept, inside)
            },
        )
        .map(|(kept, _)| kept)
        .reduce(Vec::new, |mut a, mut b| {
            a.append(&mut b);
            a
        })
}

/// The relative neighbourhood graph: edges as sorted `[min, max]` input-index pairs.
///
/// Runs in O(n log n) for the Delaunay triangulation plus, per Delaunay edge,
/// a search over the points of one disc (O(1) on typical data, O(n) worst case).
pub fn relative_neighborhood_graph(points: &PointSet) -> Result<Vec<[u32; 2]>> {
    let g = DelaunayGraph::new(points.points())?;
    let e = rng_from_delaunay(points.points(), &g);
    Ok(points.to_input_edges(e.into_iter()))
}
