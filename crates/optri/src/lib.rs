//! # optri — exact optimal planar triangulations
//!
//! Given points in the plane, optri computes the triangulation that is best
//! under a stated criterion, exactly, together with the proximity graphs those
//! algorithms are built from.
//!
//! Architecture (dependencies point down):
//!
//! | layer | modules |
//! |---|---|
//! | geometry kernel | [`kernel`]: exact predicates, symbolic tie-break, lunes, metrics |
//! | data structures | [`PointSet`], [`planar_graph`], [`Triangulation`] |
//! | algorithms | [`mod@delaunay`], [`mod@convex_hull`], [`mod@relative_neighborhood_graph`], [`mod@gabriel_graph`], [`mod@minimum_spanning_tree`], [`mod@minmax_length`], [`mod@greedy`], [`mod@min_weight`] |
//! | I/O | [`io`] |
//!
//! ```
//! use optri::{delaunay, PointSet};
//! let points = PointSet::new(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]])?;
//! let t = delaunay(&points)?;
//! t.validate()?;
//! assert_eq!(t.triangles().len(), 2);
//! # Ok::<(), optri::Error>(())
//! ```
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod convex_hull;
mod criterion;
pub mod delaunay;
mod error;
pub mod gabriel_graph;
pub mod greedy;
pub mod io;
pub mod kernel;
pub mod min_weight;
pub mod minimum_spanning_tree;
pub mod minmax_length;
pub mod planar_graph;
mod point_set;
pub mod relative_neighborhood_graph;
mod triangulation;

pub use convex_hull::{convex_hull, convex_hull_edges};
pub use criterion::{triangulate, Criterion, Phase, Solution};
pub use delaunay::{delaunay, delaunay_edges};
pub use error::{Error, Result};
pub use gabriel_graph::gabriel_graph;
pub use greedy::greedy;
pub use min_weight::min_weight;
pub use minimum_spanning_tree::minimum_spanning_tree;
pub use minmax_length::minmax_length;
#[doc(hidden)]
pub use minmax_length::minmax_length_cubic;
pub use point_set::PointSet;
pub use relative_neighborhood_graph::relative_neighborhood_graph;
pub use triangulation::{Stats, Triangulation};
