//! Area-optimal triangulations (T. S. Vassilev, *Optimal area
//! triangulation*, PhD thesis, University of Saskatchewan, 2005):
//! `maxmin-area` maximises the smallest triangle area, `minmax-area`
//! minimises the largest.
//!
//! | input | algorithm | time |
//! |---|---|---|
//! | points in strictly convex position, strictly convex polygon | `convex` (Algorithm 44) | O(n² log n) once merged; a temporary O(n³) stand-in now |
//! | convex position with collinear boundary points | the polygon program on the hull, flat triangles forbidden | O(n³) |
//! | simple polygon | the polygon program on its diagonals (Algorithm 21, with the visibility test its listing omits) | O(n³) |
//! | other point sets | not supported yet ([`UnsupportedReason::NotConvexPositionOrPolygon`]) | — |
//!
//! Both measures are bottlenecks, so they decompose over a diagonal (thesis
//! §2.1; brief §5: an optimum of a polygon is assembled from optima of the
//! two sides of its first triangle's diagonals) and fit the
//! [polygon program](crate::polygon_program) (objectives in `polygon`).
//! Algorithm 44 needs strict convexity (Lemma 23 is strict only then), so
//! collinear boundary points go to the polygon program; there a flat triangle
//! would have area 0 and "win" minmax-area, so it is forbidden (brief §1.1).
//!
//! # Exactness
//! Areas are compared, never added: every comparison is the kernel's exact
//! `compare_areas`, and no area is stored as a float (a value is its
//! bottleneck triangle's corners). The result is exactly optimal.
//!
//! # Degenerate input
//! Equal areas are common (lattice and symmetric inputs): the program keeps
//! the first best split corner, so some optimum is returned; which one may
//! differ between algorithms, never its value.

mod convex;
mod decision;
pub(crate) mod polygon;

pub use decision::{maxmin_area_at_least, MaxMinAreaDecision};

use super::polygon_criteria::{check_size, corner_point, polygon_program, MAX_POLYGON_VERTICES};
use super::{CriterionInfo, Diagnostics, Optimality, Options, Requirement, Solved};
use crate::error::{Error, Result, UnsupportedReason};
use crate::kernel::orient_sign;
use crate::spatial::convex_hull_cycle;
use crate::structures::{PointSet, SimplePolygon, Triangulation};
use crate::timing::{timed, Phase};
use polygon::{convex_polygon_program, AreaBottleneck, BottleneckArea};

const REFERENCE: &str = "T. S. Vassilev, Optimal area triangulation, PhD thesis, \
                         University of Saskatchewan, 2005 (Algorithms 21 and 44)";

pub(crate) const MAXMIN_INFO: CriterionInfo = CriterionInfo {
    name: "maxmin-area",
    description: "maximises the smallest triangle area (points in convex position, or a simple \
                  polygon)",
    optimality: Optimality::Exact,
    requirement: Requirement::ConvexPosition,
    options: &[],
    reference: REFERENCE,
};

pub(crate) const MINMAX_INFO: CriterionInfo = CriterionInfo {
    name: "minmax-area",
    description: "minimises the largest triangle area (points in convex position, or a simple \
                  polygon)",
    optimality: Optimality::Exact,
    requirement: Requirement::ConvexPosition,
    options: &[],
    reference: REFERENCE,
};

impl AreaBottleneck {
    fn criterion(self) -> &'static str {
        match self {
            AreaBottleneck::MaxMin => MAXMIN_INFO.name,
            AreaBottleneck::MinMax => MINMAX_INFO.name,
        }
    }

    fn convex(self, points: &[crate::kernel::Point], polygon: &[u32]) -> Vec<[u32; 3]> {
        match self {
            AreaBottleneck::MaxMin => convex::maxmin_area_convex(points, polygon),
            AreaBottleneck::MinMax => convex::minmax_area_convex(points, polygon),
        }
    }
}

/// The algorithm of the strictly convex case, in words.
const CONVEX_ALGORITHM: &str = "Vassilev's Algorithm 44 as repaired (sleeve program over pieces \
     of zonality <= 2, then step iv by range-max search for MaxMin or staircases for MinMax), \
     O(n^2 log n) time, O(n^2) space";

/// Largest strictly convex input for Algorithm 44: its O(n²) tables take
/// about 24 bytes per vertex pair (2.4 GB at 10⁴ vertices).
pub(crate) const MAX_CONVEX_VERTICES: usize = 12_000;

pub(crate) fn solve_maxmin(
    points: &PointSet,
    _: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    solve_points(points, AreaBottleneck::MaxMin, phases)
}

pub(crate) fn solve_minmax(
    points: &PointSet,
    _: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    solve_points(points, AreaBottleneck::MinMax, phases)
}

pub(crate) fn solve_maxmin_polygon(
    polygon: &SimplePolygon,
    _: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    solve_polygon(polygon, AreaBottleneck::MaxMin, phases)
}

pub(crate) fn solve_minmax_polygon(
    polygon: &SimplePolygon,
    _: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    solve_polygon(polygon, AreaBottleneck::MinMax, phases)
}

/// A triangulation of `points` (in convex position) maximising the smallest
/// triangle area, exactly. Polygons: [`crate::triangulate_polygon`] with
/// [`crate::Criterion::MaxminArea`].
///
/// # Errors
/// [`Error::Unsupported`] with
/// [`UnsupportedReason::NotConvexPositionOrPolygon`] if some point is inside
/// the convex hull, or [`UnsupportedReason::TooManyPoints`] above 4000
/// distinct points.
pub fn maxmin_area(points: &PointSet) -> Result<Triangulation> {
    solve_points(points, AreaBottleneck::MaxMin, &mut Vec::new()).map(|s| s.triangulation)
}

/// A triangulation of `points` (in convex position) minimising the largest
/// triangle area, exactly; see [`maxmin_area`].
///
/// # Errors
/// As [`maxmin_area`].
pub fn minmax_area(points: &PointSet) -> Result<Triangulation> {
    solve_points(points, AreaBottleneck::MinMax, &mut Vec::new()).map(|s| s.triangulation)
}

fn solved(triangulation: Triangulation, algorithm: &str) -> Solved {
    Solved {
        triangulation,
        algorithm: algorithm.to_string(),
        optimality: Optimality::Exact,
        diagnostics: Diagnostics::default(),
    }
}

fn solve_points(
    points: &PointSet,
    kind: AreaBottleneck,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    let criterion = kind.criterion();
    let pts = points.points();
    let hull = convex_hull_cycle(pts);
    if hull.len() != pts.len() {
        return Err(Error::Unsupported {
            criterion,
            reason: UnsupportedReason::NotConvexPositionOrPolygon {
                interior: pts.len() - hull.len(),
                distinct: pts.len(),
            },
        });
    }
    let k = hull.len();
    let p = |c: usize| pts[hull[c] as usize];
    let strictly_convex = (0..k).all(|c| orient_sign(p(c), p((c + 1) % k), p((c + 2) % k)) > 0);
    let (limit, because) = if strictly_convex {
        (MAX_CONVEX_VERTICES, "Algorithm 44's O(n²) tables")
    } else {
        (
            MAX_POLYGON_VERTICES,
            "Klincsek's O(n³) program with O(n²) tables",
        )
    };
    if pts.len() > limit {
        return Err(Error::Unsupported {
            criterion,
            reason: UnsupportedReason::TooManyPoints {
                limit,
                distinct: pts.len(),
                because,
            },
        });
    }
    let (triangles, algorithm) = timed(phases, criterion, || {
        if strictly_convex {
            (kind.convex(pts, &hull), CONVEX_ALGORITHM)
        } else {
            (
                convex_polygon_program(pts, &hull, kind),
                "polygon program on the convex hull (collinear boundary points; flat \
                 triangles forbidden), O(n^3)",
            )
        }
    });
    Ok(solved(
        Triangulation::from_distinct(points, triangles),
        algorithm,
    ))
}

fn solve_polygon(
    polygon: &SimplePolygon,
    kind: AreaBottleneck,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    let criterion = kind.criterion();
    check_size(polygon, criterion)?;
    if polygon.is_strictly_convex() {
        let triangles = timed(phases, criterion, || {
            kind.convex(polygon.vertices(), polygon.counter_clockwise())
        });
        return Ok(solved(
            Triangulation::from_polygon_positions(polygon, triangles),
            CONVEX_ALGORITHM,
        ));
    }
    let p = corner_point(polygon);
    let objective = BottleneckArea { point: &p, kind };
    let triangulation = polygon_program(polygon, criterion, &objective, phases)?;
    Ok(solved(
        triangulation,
        "Klincsek dynamic program on the polygon's diagonals, O(n^3), exact area comparisons",
    ))
}
