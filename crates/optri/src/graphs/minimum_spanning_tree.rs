//! Euclidean minimum spanning tree, by Kruskal over the relative neighbourhood
//! graph (every MST edge `pq` is an RNG edge: a point `r` in the lune of `pq`
//! makes `pq` the strictly longest edge of the cycle `p q r`).
//!
//! Equal lengths are ordered by the kernel's symbolic perturbation
//! ([`crate::kernel::compare_lengths_symbolic`]), so the tree is unique and
//! reproducible.

use super::relative_neighborhood_graph::rng_from_delaunay;
use crate::error::Result;
use crate::kernel::segment_order;
use crate::structures::DelaunayGraph;
use crate::structures::PointSet;

/// Kruskal over candidate edges (distinct indices) in the symbolic length order.
pub(crate) fn kruskal(points: &[crate::kernel::Point], candidates: Vec<[u32; 2]>) -> Vec<[u32; 2]> {
    let candidates = sort_by_length(points, candidates);
    let mut parent: Vec<u32> = (0..points.len() as u32).collect();
    fn find(parent: &mut [u32], mut x: u32) -> u32 {
        while parent[x as usize] != x {
            parent[x as usize] = parent[parent[x as usize] as usize];
            x = parent[x as usize];
        }
        x
    }
    let mut tree = Vec::with_capacity(points.len() - 1);
    for [u, v] in candidates {
        let (a, b) = (find(&mut parent, u), find(&mut parent, v));
        if a != b {
            parent[a as usize] = b;
            tree.push([u, v]);
        }
    }
    tree
}

/// Sorts segments by the symbolic length order.
///
/// Keys are rounded squared lengths; each carries relative error below 4u
/// (u = 2⁻⁵³), so two keys that differ by more than 16u of their sum are
/// ordered correctly, and only near-ties pay for the exact comparison.
pub(crate) fn sort_by_length(
    points: &[crate::kernel::Point],
    segments: Vec<[u32; 2]>,
) -> Vec<[u32; 2]> {
    const GAP: f64 = 16.0 * f64::EPSILON * 0.5;
    let exact = segment_order(points);
    let mut keyed: Vec<(f64, [u32; 2])> = segments
        .into_iter()
        .map(|s| {
            let (a, b) = (points[s[0] as usize], points[s[1] as usize]);
            let (dx, dy) = (a[0] - b[0], a[1] - b[1]);
            (dx * dx + dy * dy, s)
        })
        .collect();
    keyed.sort_unstable_by(|x, y| {
        if (x.0 - y.0).abs() > GAP * (x.0 + y.0) {
            x.0.total_cmp(&y.0)
        } else {
            exact(&x.1, &y.1)
        }
    });
    keyed.into_iter().map(|(_, s)| s).collect()
}

/// The Euclidean minimum spanning tree: `n - 1` edges as sorted `[min, max]`
/// input-index pairs (over the distinct points).
pub fn minimum_spanning_tree(points: &PointSet) -> Result<Vec<[u32; 2]>> {
    let g = DelaunayGraph::new(points.points())?;
    let rng = rng_from_delaunay(points.points(), &g);
    let tree = kruskal(points.points(), rng);
    Ok(points.to_input_edges(tree.into_iter()))
}
