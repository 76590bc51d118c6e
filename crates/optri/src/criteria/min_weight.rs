//! Minimum-weight triangulation (MWT) of points in convex position by
//! Klincsek's dynamic program (G. T. Klincsek, *Minimal triangulations of
//! polygonal domains*, Ann. Discrete Math. 9 (1980)) — the library's
//! [polygon program](crate::polygon_program) with total length as an
//! additive objective — O(n³) time, O(n²) memory.
//!
//! It is provided so that the approximation ratio |GT| / |MWT| that
//! Levcopoulos & Lingas (*On approximation behavior of the greedy
//! triangulation for convex polygons*, Algorithmica 1987) bound can be
//! observed. Points must all lie on their
//! convex hull; collinear boundary points are allowed (flat triangles are
//! excluded exactly with the orientation predicate). Other inputs get
//! [`Error::Unsupported`].
//!
//! # Exactness
//! The weight is a sum of square roots; comparing such sums exactly is out of
//! scope. Candidate sums are compared in `f64`, so the result is *optimal up
//! to floating-point rounding of the sums*: when two triangulations' weights
//! agree to within rounding, either may be returned (the first split vertex
//! in polygon order wins exact `f64` ties).

use super::{CriterionInfo, Diagnostics, Optimality, Options, Requirement, Solved};
use crate::error::{Error, Result, UnsupportedReason};
use crate::kernel::metrics::length;
use crate::kernel::{orient_sign, Point};
use crate::polygon_program::{optimal_triangulation, Objective};
use crate::spatial::convex_hull_cycle;
use crate::structures::PointSet;
use crate::structures::Triangulation;
use crate::timing::{timed, Phase};

pub(crate) const INFO: CriterionInfo = CriterionInfo {
    name: "min-weight",
    description: "minimises the total edge length (points in convex position only)",
    optimality: Optimality::UpToRounding,
    requirement: Requirement::ConvexPosition,
    options: &[],
    reference: "G. T. Klincsek, Minimal triangulations of polygonal domains, 1980",
};

pub(crate) fn solve(points: &PointSet, _: &Options, phases: &mut Vec<Phase>) -> Result<Solved> {
    let triangulation = timed(phases, "min-weight", || min_weight(points))?;
    Ok(Solved {
        triangulation,
        algorithm:
            "Klincsek dynamic program, O(n^3); optimal up to floating-point rounding of sums"
                .to_string(),
        optimality: Optimality::UpToRounding,
        diagnostics: Diagnostics::default(),
        bound: None,
    })
}

/// Largest number of distinct points [`min_weight`] accepts (O(n²) memory).
pub const MAX_POINTS: usize = 4000;

/// A minimum-weight triangulation of `points`, which must be in convex
/// position (see the module docs for the exactness caveat).
///
/// # Errors
/// [`Error::Unsupported`] if some point is not on the convex hull, or above
/// 4000 distinct points (the program's O(n²) tables and O(n³)
/// time).
pub fn min_weight(points: &PointSet) -> Result<Triangulation> {
    let pts = points.points();
    let polygon = convex_hull_cycle(pts);
    if polygon.len() != pts.len() {
        return Err(Error::Unsupported {
            criterion: "min-weight",
            reason: UnsupportedReason::NotConvexPosition {
                interior: pts.len() - polygon.len(),
                distinct: pts.len(),
            },
        });
    }
    if pts.len() > MAX_POINTS {
        return Err(Error::Unsupported {
            criterion: "min-weight",
            reason: UnsupportedReason::TooManyPoints {
                limit: MAX_POINTS,
                distinct: pts.len(),
                because: "Klincsek's O(n³) program with O(n²) tables",
            },
        });
    }
    let p = |i: usize| pts[polygon[i] as usize];
    let solved = optimal_triangulation(
        polygon.len(),
        |_, _| true, // convex position: every chord is a diagonal
        |i, m, j| orient_sign(p(i), p(m), p(j)) != 0, // a flat triangle is not allowed
        &TotalLength { point: &p },
    )
    .ok_or_else(|| {
        Error::Internal("the convex polygon has no triangulation without flat triangles".into())
    })?;
    let triangles = solved
        .triangles
        .into_iter()
        .map(|t| t.map(|c| polygon[c]))
        .collect();
    Ok(Triangulation::from_distinct(points, triangles))
}

/// Total length of the diagonals, summed in `f64` (the module's exactness
/// caveat): an additive objective.
pub(crate) struct TotalLength<'a, P: Fn(usize) -> Point> {
    pub(crate) point: &'a P,
}

impl<P: Fn(usize) -> Point> Objective for TotalLength<'_, P> {
    type Value = f64;
    fn empty(&self) -> f64 {
        0.0
    }
    fn diagonal(&self, i: usize, j: usize) -> Option<f64> {
        Some(length((self.point)(i), (self.point)(j)))
    }
    fn triangle(&self, _: usize, _: usize, _: usize) -> Option<f64> {
        None
    }
    fn combine(&self, a: f64, b: f64) -> f64 {
        a + b
    }
    fn better(&self, a: f64, b: f64) -> bool {
        a < b
    }
}
