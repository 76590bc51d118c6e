//! Test and benchmark hooks (feature `internals`). Not the place you are
//! looking for: nothing here is a stable API, and every item exists so that
//! the test suite and the benchmarks can reach one algorithm variant or
//! reference directly.

pub use crate::criteria::greedy::{
    greedy_edges_by, greedy_naive_edges, greedy_triangulation, is_convex_position, is_semicircular,
    GreedyAlgorithm,
};
pub use crate::criteria::min_weight::MAX_POINTS as MIN_WEIGHT_MAX_POINTS;
pub use crate::criteria::minmax_length::{minmax_length_cubic, minmax_length_with, SMALL_REGION};
pub use crate::structures::planar_graph::{Face, PlanarGraph};
