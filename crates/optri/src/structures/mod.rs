//! Layer 2: the data structures every algorithm shares — the validated
//! [`PointSet`] with its input ↔ distinct index maps, the [`Triangulation`]
//! of a [`Domain`] with its exact validation, the half-edge
//! [`PlanarGraph`], the Delaunay adjacency [`DelaunayGraph`], the
//! [`SimplePolygon`] input and the weakly simple [`PolygonCycle`] its
//! diagonals are decided on. They import the kernel and spatial layers only.

mod constrained_delaunay;
mod csr;
mod delaunay_graph;
#[cfg(feature = "geo-types")]
mod geo;
mod measures;
pub(crate) mod planar_graph;
mod point_set;
mod polygon;
mod polygon_cycle;
mod triangulation;

pub(crate) use constrained_delaunay::ConstrainedDelaunay;
pub(crate) use csr::Csr;
pub(crate) use delaunay_graph::{DelaunayGraph, NO_TRIANGLE};
pub use measures::{Better, Measure};
pub(crate) use planar_graph::PlanarGraph;
pub use point_set::PointSet;
pub use polygon::SimplePolygon;
pub(crate) use polygon_cycle::PolygonCycle;
pub use triangulation::{Domain, Stats, Triangulation};
