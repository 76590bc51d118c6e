//! # optri — exact optimal planar triangulations
//!
//! Given points in the plane, optri computes the triangulation that is best
//! under a stated criterion, exactly, together with the proximity graphs those
//! algorithms are built from.
//!
//! ```
//! use optri::{triangulate, Criterion, PointSet};
//! let points = PointSet::new(&[[0.0, 0.0], [4.0, 0.0], [0.0, 3.0], [4.0, 3.0], [2.0, 1.0]])?;
//! let solution = triangulate(&points, Criterion::MinMaxLength)?;
//! solution.triangulation.validate()?; // exact check that it is a triangulation
//! assert!(solution.exact);
//! assert_eq!(solution.triangulation.triangles().len(), 4);
//! # Ok::<(), optri::Error>(())
//! ```
//!
//! ## Layers
//! Dependencies point down this table only (`ARCHITECTURE.md` has the rules
//! and a test enforces them):
//!
//! | layer | module (private) | what it holds |
//! |---|---|---|
//! | 0 | [`kernel`] | exact predicates, the symbolic tie-break, lunes, correctly rounded reporting measures |
//! | — | `error`, `timing`, `parallel` | [`Error`], [`Phase`], the rayon shim |
//! | 1 | `spatial` | coordinate-only functions: bounding box, Z-order, hull cycle |
//! | 2 | `structures` | [`PointSet`], [`SimplePolygon`], [`Triangulation`] and its [`Domain`], Delaunay adjacency, planar graph |
//! | 3 | `graphs` | [`delaunay`], [`convex_hull`], [`relative_neighborhood_graph`], [`gabriel_graph`], [`minimum_spanning_tree`] |
//! | 4 | `polygon_program` | Klincsek's polygon dynamic program over an objective |
//! | 5 | `criteria` | one module per criterion (minmax length, greedy, min weight, the area criteria, edge insertion, the δ-criteria, Delaunay), run through [`triangulate`]; the polygon solvers |
//! | 6 | `registry` | [`Criterion`], [`GraphKind`], [`triangulate`], [`compare`], [`graph`] |
//! | 7 | `io` (public, feature `io`) | readers, writers, the one JSON result schema |
//!
//! ## Features
//! - `parallel` (default): rayon data parallelism; without it every step runs
//!   on one thread with identical results.
//! - `io` (default): file formats and JSON through serde.
//! - `internals`: test and benchmark hooks in `optri::internals`; not a stable API.
#![warn(missing_docs)]

mod criteria;
mod error;
mod graphs;
#[cfg(feature = "internals")]
pub mod internals;
mod interrupt;
#[cfg(feature = "io")]
pub mod io;
pub mod kernel;
mod parallel;
mod polygon_program;
mod registry;
#[cfg(feature = "io")]
pub mod request;
mod spatial;
mod structures;
mod timing;

pub use criteria::area::{
    decide_area, maxmin_area_at_least, AreaDecision, AreaQuestion, DecisionInput,
    MaxMinAreaDecision,
};
pub use criteria::{
    ApproximationReport, AreaApproximation, BoundMeasure, CertifiedBound, CriterionInfo,
    Diagnostics, Guarantee, InputKind, Optimality, OptionInfo, Options, Progress, OPTIONS,
};
pub use error::{ElevationProblem, Error, Interruption, PolygonProblem, Result, UnsupportedReason};
pub use graphs::{
    convex_hull, delaunay, gabriel_graph, minimum_spanning_tree, relative_neighborhood_graph,
};
pub use interrupt::Cancel;
pub use registry::{
    compare, graph, triangulate, triangulate_with, Comparison, Criterion, GraphKind, PointGraph,
    Solution, Triangulable,
};
pub use structures::{Better, Domain, Measure, PointSet, SimplePolygon, Stats, Triangulation};
pub use timing::Phase;

/// The README's Rust examples, compiled and run as doctests.
#[doc = include_str!("../../../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
