//! Layer 2: the data structures every algorithm shares — the validated
//! [`PointSet`] with its input ↔ distinct index maps, the [`Triangulation`]
//! of a [`Domain`] with its exact validation, the half-edge
//! [`PlanarGraph`], the Delaunay adjacency [`DelaunayGraph`] and the
//! [`SimplePolygon`] input. They import the kernel and spatial layers only.

mod delaunay_graph;
#[cfg(feature = "geo-types")]
mod geo;
pub(crate) mod planar_graph;
mod point_set;
mod polygon;
mod triangulation;

pub(crate) use delaunay_graph::{DelaunayGraph, NO_TRIANGLE};
pub(crate) use planar_graph::PlanarGraph;
pub use point_set::PointSet;
pub use polygon::SimplePolygon;
pub use triangulation::{Domain, Measure, Stats, Triangulation};
