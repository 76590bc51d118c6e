//! Independent reference implementations for testing optri (tests only).
//!
//! Nothing here uses optri: every predicate is exact integer/rational
//! arithmetic on the `f64` inputs ([`exact`]), and every algorithm is the
//! simplest one that is obviously correct — exhaustive enumeration
//! ([`all_triangulations`], cross-checked by flip-graph search, with
//! [`optimum_by`] and the keys [`max_edge_squared`], [`total_length`],
//! [`min_twice_area`], [`max_twice_area`]), the greedy triangulation by
//! definition ([`greedy_triangulation`], O(n⁴), and the same scan made
//! scalable with exact float-filtered predicates and grids,
//! [`greedy_edges`]),
//! Klincsek's polygon DP ([`klincsek()`]), the minimum-weight
//! triangulation of a general set by integer programming over its empty
//! triangles ([`min_weight_ilp()`], tens of points), simple polygons by definition
//! (diagonals, every triangulation, the greedy triangulation, generators:
//! [`polygon`]), brute-force definitions of the
//! proximity graphs ([`graphs`]), a polynomial expansion of the
//! symbolic perturbation ([`symbolic`]) and correctly rounded measures by
//! rational arithmetic ([`measures`]). Slow by design; inputs are small
//! (except [`greedy_edges`]). [`inputs`] holds the seeded point-set
//! generators and named degenerate fixtures the tests, benches and examples
//! share.
//!
//! [`data_dir`] finds the test data (`$OPTRI_DATA`, else `shared/data`
//! beside the repository, else the TSPLIB files vendored in `data/`).
//!
//! Conventions: indices are `u32` into the caller's slice of *distinct*
//! points; triangles are counter-clockwise with the smallest index first,
//! lists of triangles and of `[min, max]` edges are sorted.

pub mod bottleneck_measures;
pub mod data;
pub mod delta;
pub mod enumerate;
pub mod exact;
pub mod graphs;
pub mod greedy;
pub mod inputs;
pub mod klincsek;
pub mod measures;
pub mod min_weight_ilp;
pub mod norm;
pub mod polygon;
pub mod symbolic;

pub use data::data_dir;
pub use delta::DeltaMeasure;
pub use enumerate::{
    all_triangulations, canonical_triangle, canonical_triangulation, edge_length, empty_segments,
    flip_graph_triangulations, greedy_triangulation, max_edge_squared, max_twice_area,
    min_twice_area, optimum_by, segments_by_perturbed_length, total_length, triangle_edges,
    TotalF64, MAX_ENUMERATION_POINTS,
};
pub use exact::{
    compare_squared_lengths, dot_sign, incircle, on_open_segment, orient, properly_cross,
    rational_to_f64, squared_length, to_rational, twice_area, Point,
};
pub use graphs::{
    bounded_faces, constrained_delaunay_check, convex_hull_edges, delaunay_check, gabriel_edges,
    is_cracked, is_minimum_spanning_tree, rng_edges,
};
pub use greedy::greedy_edges;
pub use inputs::integer_circle_points;
pub use klincsek::{
    klincsek, klincsek_unique, Criterion, MaxMinArea, MinMaxArea, MinMaxLength, MinWeight,
};
pub use min_weight_ilp::{min_weight_ilp, IlpTriangulation};
pub use num_bigint::BigInt;
pub use num_rational::BigRational;
pub use symbolic::{compare_lengths_perturbed, orient_perturbed};
