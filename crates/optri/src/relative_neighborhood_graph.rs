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

use crate::delaunay::{delaunay_graph, to_input_edges, DelaunayGraph};
use crate::error::Result;
use crate::kernel::{compare_lengths, in_lune, Point};
use crate::point_set::PointSet;
use rayon::prelude::*;
use std::cmp::Ordering::Less;

/// Does some point lie strictly inside the lune of the Delaunay edge `pq`?
fn lune_is_occupied(
    points: &[Point],
    g: &DelaunayGraph,
    p: u32,
    q: u32,
    apexes: [Option<u32>; 2],
    scratch: &mut Search,
) -> bool {
    let (pp, pq) = (points[p as usize], points[q as usize]);
    // Fast path: an apex in the lune settles it (always so for non-Gabriel edges).
    if apexes
        .iter()
        .flatten()
        .any(|&a| in_lune(pp, pq, points[a as usize]))
    {
        return true;
    }
    scratch.stamp += 1;
    let stamp = scratch.stamp;
    scratch.stack.clear();
    scratch.stack.push(p);
    scratch.seen[p as usize] = stamp;
    while let Some(w) = scratch.stack.pop() {
        for &x in g.neighbors(w) {
            if scratch.seen[x as usize] == stamp {
                continue;
            }
            scratch.seen[x as usize] = stamp;
            let px = points[x as usize];
            if compare_lengths(px, pp, pp, pq) != Less {
                continue; // outside the open disc around p: not expanded
            }
            if compare_lengths(px, pq, pp, pq) == Less {
                return true;
            }
            scratch.stack.push(x);
        }
    }
    false
}

struct Search {
    seen: Vec<u32>,
    stack: Vec<u32>,
    stamp: u32,
}

/// RNG edges as distinct-index pairs, from a Delaunay graph.
pub(crate) fn rng_from_delaunay(points: &[Point], g: &DelaunayGraph) -> Vec<[u32; 2]> {
    let n = points.len();
    g.edges
        .par_iter()
        .map_init(
            || Search {
                seen: vec![0; n],
                stack: Vec::new(),
                stamp: 0,
            },
            |scratch, &([u, v], apexes)| {
                // Search from the endpoint of smaller degree: fewer disc neighbours.
                let (p, q) = if g.neighbors(u).len() <= g.neighbors(v).len() {
                    (u, v)
                } else {
                    (v, u)
                };
                (!lune_is_occupied(points, g, p, q, apexes, scratch)).then_some([u, v])
            },
        )
        .flatten()
        .collect()
}

/// The relative neighbourhood graph: edges as sorted `[min, max]` input-index pairs.
///
/// Runs in O(n log n) for the Delaunay triangulation plus, per Delaunay edge,
/// a search over the points of one disc (O(1) on typical data, O(n) worst case).
pub fn relative_neighborhood_graph(points: &PointSet) -> Result<Vec<[u32; 2]>> {
    let g = delaunay_graph(points.points())?;
    let e = rng_from_delaunay(points.points(), &g);
    Ok(to_input_edges(points, e.into_iter()))
}
