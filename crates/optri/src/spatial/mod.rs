//! Layer 1: coordinate-only functions — bounding boxes, the Z-order numbering
//! and the randomized insertion order built on it,
//! the convex hull cycle, grids of cells, segments sorted by length. No
//! topology; they import only the kernel (and the rayon shim).

mod bbox;
mod cell_geometry;
mod grid;
mod hull;
mod insertion_order;
mod morton;
mod order;
mod point_cells;

pub(crate) use bbox::bounding_box;
pub(crate) use grid::{fmax, fmin, SparseGrid};
pub(crate) use hull::{convex_hull_cycle, empty_apexes, is_strictly_convex_cycle};
pub(crate) use insertion_order::brio_order;
pub(crate) use morton::morton_order;
pub(crate) use order::{
    inverse_permutation, keyed_by_length, sort_by_length, sort_keyed_runs, sort_runs,
};
pub(crate) use point_cells::{CellBlock, PointCells};
