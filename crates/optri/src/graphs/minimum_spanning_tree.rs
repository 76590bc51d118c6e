//! Euclidean minimum spanning tree, by Kruskal over the relative neighbourhood
//! graph (every MST edge `pq` is an RNG edge: a point `r` in the lune of `pq`
//! makes `pq` the strictly longest edge of the cycle `p q r`).
//!
//! Equal lengths are ordered by the kernel's symbolic perturbation
//! ([`crate::kernel::compare_lengths_symbolic`]), so the tree is unique and
//! reproducible. [`kruskal`] takes any of the kernel's length orders: under a
//! normed metric it runs over that metric's RNG (`metric_graphs.rs`).

use super::relative_neighborhood_graph::rng_from_delaunay;
use crate::error::Result;
use crate::kernel::{EuclideanOrder, LengthOrder, Point};
use crate::spatial::sort_by_length;
use crate::structures::DelaunayGraph;
use crate::structures::PointSet;

/// Kruskal over candidate edges (distinct indices) that contain a minimum
/// spanning tree under `order` (a total order: the tree is unique).
pub(crate) fn kruskal<O: LengthOrder>(
    points: &[Point],
    order: O,
    mut candidates: Vec<[u32; 2]>,
) -> Vec<[u32; 2]> {
    sort_by_length(points, order, &mut candidates);
    let mut parent: Vec<u32> = (0..points.len() as u32).collect();
    fn find(parent: &mut [u32], mut x: u32) -> u32 {
        while parent[x as usize] != x {
            parent[x as usize] = parent[parent[x as usize] as usize];
            x = parent[x as usize];
        }
        x
    }
    let mut tree = Vec::with_capacity(points.len().saturating_sub(1));
    for [u, v] in candidates {
        let (a, b) = (find(&mut parent, u), find(&mut parent, v));
        if a != b {
            parent[a as usize] = b;
            tree.push([u, v]);
        }
    }
    tree
}

/// The Euclidean minimum spanning tree: `n - 1` edges as sorted `[min, max]`
/// input-index pairs (over the distinct points).
pub fn minimum_spanning_tree(points: &PointSet) -> Result<Vec<[u32; 2]>> {
    let g = DelaunayGraph::new(points.points())?;
    let rng = rng_from_delaunay(points.points(), &g);
    let tree = kruskal(points.points(), EuclideanOrder, rng);
    Ok(points.to_input_edges(tree.into_iter()))
}
