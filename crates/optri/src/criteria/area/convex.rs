//! TEMPORARY: MaxMin and MinMax area of a strictly convex polygon.
//!
//! **This file is a placeholder, replaced by Algorithm 44 of T. S. Vassilev,
//! *Optimal area triangulation*, PhD thesis, University of Saskatchewan, 2005
//! (O(n² log n), as repaired in the area brief §2), which another developer
//! is writing with these two signatures.** Until it is merged both functions
//! run the O(n³) polygon program with every chord allowed, which is exact
//! but cubic.

use super::polygon::{convex_polygon_program, AreaBottleneck};
use crate::kernel::Point;

/// A triangulation of the strictly convex polygon `polygon` (the
/// counter-clockwise vertex cycle, indices into `points`) maximising the
/// smallest triangle area; triangles as indices into `points`.
pub(crate) fn maxmin_area_convex(points: &[Point], polygon: &[u32]) -> Vec<[u32; 3]> {
    convex_polygon_program(points, polygon, AreaBottleneck::MaxMin)
}

/// A triangulation of the strictly convex polygon `polygon` (as in
/// [`maxmin_area_convex`]) minimising the largest triangle area.
pub(crate) fn minmax_area_convex(points: &[Point], polygon: &[u32]) -> Vec<[u32; 3]> {
    convex_polygon_program(points, polygon, AreaBottleneck::MinMax)
}
