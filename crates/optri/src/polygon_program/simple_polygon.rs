//! The polygon program on a [`SimplePolygon`]: the run that every
//! decomposable criterion on simple polygons shares (G. T. Klincsek,
//! *Minimal triangulations of polygonal domains*, Ann. Discrete Math. 9,
//! 1980; Algorithm 21 of T. S. Vassilev, *Optimal area triangulation*, PhD
//! thesis, University of Saskatchewan, 2005, whose listing omits the
//! visibility test).
//!
//! The program runs over the polygon's corners in counter-clockwise order.
//! A chord may be used only if it is a diagonal
//! ([`SimplePolygon::is_diagonal`]: its open segment inside the polygon,
//! exact) and a triangle only if its three corners are not collinear (a
//! straight 180° vertex is then always the corner of a proper triangle).
//! Chords inside a simple polygon split it into two simple polygons, so the
//! recursion is exact. The diagonal table costs O(n) per chord, O(n³) in all
//! (skipped for a strictly convex polygon, where every chord is a diagonal),
//! computed in parallel; the program is O(n³) time and O(n²) memory.
//!
//! Ties between equal values: the program keeps the first best split corner
//! (module docs of [`crate::polygon_program`]), so some optimum is returned.

use super::{optimal_triangulation, Objective};
use crate::error::{Error, Result, UnsupportedReason};
use crate::kernel::{orient_sign, Point};
use crate::parallel::prelude::*;
use crate::structures::{SimplePolygon, Triangulation};
use crate::timing::{Phase, Stopwatch};

/// Largest polygon the polygon program accepts (O(n²) tables, O(n³) time).
pub const MAX_POLYGON_VERTICES: usize = 4000;

/// The point at corner `c` (counter-clockwise position `c`) of `polygon`.
pub(crate) fn corner_point(polygon: &SimplePolygon) -> impl Fn(usize) -> Point + '_ {
    let (vertices, ccw) = (polygon.vertices(), polygon.counter_clockwise());
    move |c| vertices[ccw[c] as usize]
}

/// `table[i * k + j]` for corners `i < j`: is the chord a diagonal? Boundary
/// edges are `false`. Rows in parallel; every chord is a diagonal of a
/// strictly convex polygon.
pub(crate) fn diagonal_table(polygon: &SimplePolygon) -> Vec<bool> {
    let k = polygon.len();
    let ccw = polygon.counter_clockwise();
    let convex = polygon.is_strictly_convex();
    let rows: Vec<Vec<bool>> = (0..k)
        .into_par_iter()
        .map(|i| {
            (0..k)
                .map(|j| {
                    let boundary = j <= i + 1 || (i == 0 && j == k - 1);
                    !boundary && (convex || polygon.is_diagonal(ccw[i] as usize, ccw[j] as usize))
                })
                .collect()
        })
        .collect();
    rows.concat()
}

/// Refuses polygons above [`MAX_POLYGON_VERTICES`].
pub(crate) fn check_size(polygon: &SimplePolygon, criterion: &'static str) -> Result<()> {
    if polygon.len() > MAX_POLYGON_VERTICES {
        return Err(Error::Unsupported {
            criterion,
            reason: UnsupportedReason::TooManyPoints {
                limit: MAX_POLYGON_VERTICES,
                distinct: polygon.len(),
                because: "Klincsek's O(n³) program with O(n²) tables",
            },
        });
    }
    Ok(())
}

/// The optimal triangulation of `polygon` under `objective`, whose corner
/// `c` is [`corner_point`]`(polygon)(c)`: diagonals only, no flat triangle.
/// Records the phases `"diagonals"` and `"polygon program"`.
pub(crate) fn on_simple_polygon<O: Objective>(
    polygon: &SimplePolygon,
    criterion: &'static str,
    objective: &O,
    phases: &mut Vec<Phase>,
) -> Result<Triangulation> {
    check_size(polygon, criterion)?;
    let mut stopwatch = Stopwatch::new(phases);
    let k = polygon.len();
    let table = diagonal_table(polygon);
    stopwatch.lap("diagonals");
    let p = corner_point(polygon);
    let solved = optimal_triangulation(
        k,
        |i, j| table[i * k + j],
        |i, m, j| orient_sign(p(i), p(m), p(j)) > 0,
        objective,
    )
    .ok_or_else(|| Error::Internal("a simple polygon without a triangulation".into()))?;
    stopwatch.lap("polygon program");
    let ccw = polygon.counter_clockwise();
    let triangles = solved
        .triangles
        .into_iter()
        .map(|t| t.map(|c| ccw[c]))
        .collect();
    Ok(Triangulation::from_polygon_positions(polygon, triangles))
}
