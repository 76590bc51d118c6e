//! Layer 1: coordinate-only helpers — bounding boxes, the Z-order numbering,
//! the convex hull cycle. No topology, no index maps; they import only the
//! kernel.

mod bbox;
mod grid;
mod hull;
mod morton;
mod point_cells;

pub(crate) use bbox::bounding_box;
pub(crate) use grid::{fmax, fmin, SparseGrid};
pub(crate) use hull::{convex_hull_cycle, is_strictly_convex_cycle};
pub(crate) use morton::morton_order;
pub(crate) use point_cells::{CellBlock, PointCells};
