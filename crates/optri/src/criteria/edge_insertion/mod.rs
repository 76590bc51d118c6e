//! The edge-insertion criteria (M. Bern, H. Edelsbrunner, D. Eppstein,
//! S. Mitchell & T. S. Tan, *Edge insertion for optimal triangulations*,
//! Discrete Comput. Geom. 10, 1993; H. Edelsbrunner, T. S. Tan &
//! R. Waupotitsch, *An O(n² log n) time algorithm for the minmax angle
//! triangulation*, SIAM J. Sci. Stat. Comput. 13, 1992; T. S. Vassilev,
//! *Optimal area triangulation*, PhD thesis, University of Saskatchewan,
//! 2005, §1.6, Definition 17, Property 18 and Table 1.1): `minmax-angle`,
//! `maxmin-height`, `minmax-eccentricity` (the distance from the
//! circumcentre to the closed triangle) and `minmax-slope` (the gradient of
//! the piecewise-linear interpolant of per-point elevations).
//!
//! Each is a bottleneck: the worst triangle decides. A vertex of a worst
//! triangle is its *anchor* when every better triangulation has an edge from
//! it crossing the opposite side ([`crate::kernel`]'s triangle measures
//! name the rule per measure); so either some insertion of an edge from the
//! anchor improves the triangulation, or it is optimal.
//!
//! | input | algorithm | time |
//! |---|---|---|
//! | point set | Delaunay, then the edge-insertion loop (`generic`): anchors of all tied worst triangles, sides of each insertion retriangulated by the lexicographic-bottleneck polygon program (`insertion`), accepted when the decreasing vector of badness values decreases; a set of failed anchor–candidate pairs, cleared when the worst value changes, and a final pass without it; a stop as soon as the worst value meets a lower bound from the hull edges' best empty triangles | no polynomial bound claimed (see below) |
//! | simple polygon | the polygon program with the bottleneck triangle objective (every measure here is decomposable) | O(n³) |
//!
//! # What is and is not implemented
//! The papers' bounds — O(n² log n) time and O(n) space for the strong
//! measures (angle, height: every triangle has an anchor) by a greedy wedge
//! walk with linear-time ear cutting, and O(n³) time and O(n²) space for the
//! weak ones (eccentricity, slope) — are *not* what runs here. This module
//! runs the generic loop with exact optimal side retriangulations, which is
//! correct (it stops only when no anchor insertion improves, the papers'
//! optimality criterion, and the tests check it against exhaustive
//! enumeration) but whose number of steps has no proven small polynomial
//! bound; each step tries O(n) candidates at O(k³) for sides of k corners.
//! Suitable for hundreds of points.
//!
//! # Exactness and ties
//! Every comparison of two triangles is exact (float filter, exact
//! rational fallback). Ties between worst triangles are common (coplanar
//! lifted triangles have equal slopes), which is why all tied worst
//! triangles are tried and acceptance compares sorted vectors: the plain
//! test "the new worst triangle is better than the old" can stall at a
//! non-optimal triangulation.

mod generic;
mod insertion;

use super::{CriterionEntry, CriterionInfo, Diagnostics, Optimality, Options, Solved};
use crate::error::{Error, Result};
use crate::interrupt::Stop;
use crate::kernel::{Corners, TriangleMeasure};
use crate::polygon_program::{corner_point, on_simple_polygon, Objective};
use crate::structures::{DelaunayGraph, PointSet, SimplePolygon, Triangulation};
use crate::timing::{timed, Phase};
use insertion::{Badness, Mesh};
use std::cmp::Ordering;

pub(crate) use generic::Steps;

const REFERENCE: &str = "M. Bern, H. Edelsbrunner, D. Eppstein, S. Mitchell, T. S. Tan, Edge \
                         insertion for optimal triangulations, Discrete Comput. Geom. 10, 1993";

const ALGORITHM: &str = "edge insertion from Delaunay: insertions from the anchors of the worst \
                         triangles (sides retriangulated by the lexicographic-bottleneck polygon \
                         program) until none improves, or until the worst value meets the lower \
                         bound of the hull edges' best triangles";

const POLYGON_ALGORITHM: &str = "Klincsek's polygon program with the bottleneck triangle objective";

/// The reported measure a triangle measure's bottleneck is.
const fn optimised_measure(measure: TriangleMeasure) -> crate::structures::Measure {
    use crate::structures::Measure;
    match measure {
        TriangleMeasure::LargestAngle => Measure::MaxAngle,
        TriangleMeasure::SmallestHeight => Measure::MinHeight,
        TriangleMeasure::Eccentricity => Measure::MaxEccentricity,
        TriangleMeasure::Slope => Measure::MaxSlope,
    }
}

macro_rules! edge_insertion_entry {
    ($entry:ident, $measure:expr, $name:literal, $description:literal, $z:literal) => {
        pub(crate) const $entry: CriterionEntry = CriterionEntry {
            info: CriterionInfo {
                name: $name,
                description: $description,
                optimality: Optimality::Exact,
                options: &[],
                reference: REFERENCE,
                needs_elevations: $z,
                measure: Some(optimised_measure($measure)),
            },
            solve: |points, options, phases| solve(points, $measure, options, phases),
            solve_polygon: Some(|polygon, options, phases| {
                solve_polygon(polygon, $measure, options, phases)
            }),
        };
    };
}

edge_insertion_entry!(
    MINMAX_ANGLE_ENTRY,
    TriangleMeasure::LargestAngle,
    "minmax-angle",
    "minimises the largest angle (edge insertion)",
    false
);
edge_insertion_entry!(
    MAXMIN_HEIGHT_ENTRY,
    TriangleMeasure::SmallestHeight,
    "maxmin-height",
    "maximises the smallest triangle altitude (edge insertion)",
    false
);
edge_insertion_entry!(
    MINMAX_ECCENTRICITY_ENTRY,
    TriangleMeasure::Eccentricity,
    "minmax-eccentricity",
    "minimises the largest distance from a circumcentre to its triangle (edge insertion)",
    false
);
edge_insertion_entry!(
    MINMAX_SLOPE_ENTRY,
    TriangleMeasure::Slope,
    "minmax-slope",
    "minimises the steepest slope of the piecewise-linear surface over the elevations (edge \
     insertion)",
    true
);

/// The elevations of the distinct points, or zeros when the measure reads
/// none.
fn elevations_of(points: &PointSet, measure: TriangleMeasure) -> Result<Vec<f64>> {
    match (measure, points.elevations()) {
        (TriangleMeasure::Slope, Some(z)) => Ok(z.to_vec()),
        (TriangleMeasure::Slope, None) => Err(Error::Internal(
            "minmax-slope without elevations passed the registry".into(),
        )),
        _ => Ok(vec![0.0; points.len()]),
    }
}

/// The edge-insertion optimum of `points` under `measure` (distinct-index
/// triangles) and the loop's counters: the reference the tests and the
/// product share.
pub(crate) fn edge_insertion_triangles(
    points: &PointSet,
    measure: TriangleMeasure,
    remember_failures: bool,
    stop: &Stop,
) -> Result<(Vec<[u32; 3]>, Steps)> {
    let start = DelaunayGraph::new(points.points())?.triangles;
    let elevations = elevations_of(points, measure)?;
    let badness = Badness {
        measure,
        points: points.points(),
        elevations: &elevations,
    };
    let mut mesh = Mesh::new(&start);
    let steps = generic::improve(&mut mesh, &badness, remember_failures, stop)?;
    Ok((mesh.triangles().collect(), steps))
}

#[cfg(any(test, feature = "internals"))]
/// The value of the worst of `triangles` (distinct indices of `points`)
/// under `measure`, correctly rounded (degrees for angles; 0 for none).
pub(crate) fn worst_value(
    points: &PointSet,
    measure: TriangleMeasure,
    triangles: &[[u32; 3]],
) -> Result<f64> {
    let elevations = elevations_of(points, measure)?;
    let badness = Badness {
        measure,
        points: points.points(),
        elevations: &elevations,
    };
    Ok(badness
        .worst(triangles)
        .map_or(0.0, |t| badness.reported(t)))
}

fn solve(
    points: &PointSet,
    measure: TriangleMeasure,
    options: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    let (triangles, steps) = timed(phases, "edge insertion", || {
        edge_insertion_triangles(points, measure, true, options.stop())
    })?;
    let mut diagnostics = Diagnostics::default();
    diagnostics.add("insertions", steps.insertions);
    diagnostics.add("insertion attempts", steps.attempts);
    diagnostics.add("met the hull bound", u64::from(steps.met_hull_bound));
    let (algorithm, optimality) = if steps.stopped {
        (
            format!("{ALGORITHM}, stopped by the time limit"),
            Optimality::Approximation {
                bound: "not proven optimal: the time limit stopped the edge-insertion loop; \
                        the triangulation reached, no worse than Delaunay's under the measure",
            },
        )
    } else {
        (ALGORITHM.to_string(), Optimality::Exact)
    };
    Ok(Solved {
        triangulation: Triangulation::from_distinct(points, triangles),
        algorithm,
        optimality,
        diagnostics,
        bound: None,
        approximation: None,
    })
}

fn solve_polygon(
    polygon: &SimplePolygon,
    measure: TriangleMeasure,
    _: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    let point = corner_point(polygon);
    let ccw = polygon.counter_clockwise();
    let point_set = polygon.point_set();
    let elevation = |c: usize| match (measure, point_set.elevations()) {
        (TriangleMeasure::Slope, Some(z)) => z[point_set.distinct_index(ccw[c]) as usize],
        _ => 0.0,
    };
    let objective = WorstTriangle {
        measure,
        corners: |[i, m, j]: [usize; 3]| -> Corners {
            (
                [point(i), point(m), point(j)],
                [elevation(i), elevation(m), elevation(j)],
            )
        },
    };
    let name = match measure {
        TriangleMeasure::LargestAngle => MINMAX_ANGLE_ENTRY.info.name,
        TriangleMeasure::SmallestHeight => MAXMIN_HEIGHT_ENTRY.info.name,
        TriangleMeasure::Eccentricity => MINMAX_ECCENTRICITY_ENTRY.info.name,
        TriangleMeasure::Slope => MINMAX_SLOPE_ENTRY.info.name,
    };
    let triangulation = on_simple_polygon(polygon, name, &objective, phases)?;
    Ok(Solved {
        triangulation,
        algorithm: POLYGON_ALGORITHM.to_string(),
        optimality: Optimality::Exact,
        diagnostics: Diagnostics::default(),
        bound: None,
        approximation: None,
    })
}

/// The bottleneck objective over triangles: the worst triangle (corner
/// triple) under the measure's exact badness order; `None` before any.
struct WorstTriangle<F: Fn([usize; 3]) -> Corners> {
    measure: TriangleMeasure,
    corners: F,
}

impl<F: Fn([usize; 3]) -> Corners> WorstTriangle<F> {
    fn compare(&self, s: [usize; 3], t: [usize; 3]) -> Ordering {
        if s == t {
            return Ordering::Equal;
        }
        self.measure
            .compare_badness(&(self.corners)(s), &(self.corners)(t))
    }
}

impl<F: Fn([usize; 3]) -> Corners> Objective for WorstTriangle<F> {
    type Value = Option<[usize; 3]>;
    fn empty(&self) -> Self::Value {
        None
    }
    fn diagonal(&self, _: usize, _: usize) -> Option<Self::Value> {
        None
    }
    fn triangle(&self, i: usize, m: usize, j: usize) -> Option<Self::Value> {
        Some(Some([i, m, j]))
    }
    fn combine(&self, s: Self::Value, t: Self::Value) -> Self::Value {
        match (s, t) {
            (Some(x), Some(y)) => Some(if self.compare(x, y) == Ordering::Less {
                y
            } else {
                x
            }),
            (x, None) => x,
            (None, y) => y,
        }
    }
    fn better(&self, s: Self::Value, t: Self::Value) -> bool {
        match (s, t) {
            (_, None) => false,
            (None, Some(_)) => true,
            (Some(x), Some(y)) => self.compare(x, y) == Ordering::Less,
        }
    }
}
