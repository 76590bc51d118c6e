//! Layer 3: the proximity graphs — Delaunay, convex hull, relative
//! neighbourhood graph, Gabriel graph, minimum spanning tree — one module
//! each, all built from the Delaunay adjacency. Every graph is returned as
//! sorted `[min, max]` input-index pairs, except the hull, whose edges are
//! the counter-clockwise cycle `[a, b]`.

mod convex_hull;
mod delaunay;
mod gabriel_graph;
mod metric_graphs;
mod minimum_spanning_tree;
mod relative_neighborhood_graph;

pub use convex_hull::convex_hull;
pub(crate) use convex_hull::convex_hull_edges;
pub use delaunay::delaunay;
pub(crate) use delaunay::delaunay_edges;
pub use gabriel_graph::gabriel_graph;
pub(crate) use metric_graphs::{
    minimum_spanning_tree_under, relative_neighborhood_graph_under, rng_under,
};
pub use minimum_spanning_tree::minimum_spanning_tree;
pub(crate) use relative_neighborhood_graph::perturbed_rng_from_delaunay;
pub use relative_neighborhood_graph::relative_neighborhood_graph;
pub(crate) use relative_neighborhood_graph::rng_from_delaunay;
