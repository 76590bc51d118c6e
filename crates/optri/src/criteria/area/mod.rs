//! Area-optimal triangulations (T. S. Vassilev, *Optimal area
//! triangulation*, PhD thesis, University of Saskatchewan, 2005):
//! `maxmin-area` maximises the smallest triangle area, `minmax-area`
//! minimises the largest.
//!
//! | input | algorithm | time |
//! |---|---|---|
//! | points in strictly convex position, strictly convex polygon | `convex` (Algorithm 44 as repaired; Algorithm 49 for the decision) | O(n² log n) time, O(n²) space |
//! | convex position with collinear boundary points | the polygon program on the hull, flat triangles forbidden | O(n³) |
//! | simple polygon | the polygon program on its diagonals (Algorithm 21, with the visibility test its listing omits) | O(n³) |
//! | other point sets | `general`: the best of Delaunay, Algorithm 75 (30°-triangulations over RNG ∪ hull), the optimum over all triangulations containing RNG ∪ hull, and Algorithm 76 (area-equalising flips); exact only when it meets a certified bound (reported in `Solution::bound`) | O(Σ k_f³) over the faces of RNG ∪ hull |
//!
//! Both measures are bottlenecks, so they decompose over a diagonal (thesis
//! §2.1: an optimum of a polygon is assembled from optima of the two sides
//! of its first triangle's diagonals) and fit the
//! [polygon program](crate::polygon_program) (objectives in `polygon`).
//! Algorithm 44 needs strict convexity (Lemma 23 is strict only then), so
//! collinear boundary points go to the polygon program; there a flat triangle
//! would have area 0 and "win" minmax-area, so it is forbidden.
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
pub(crate) mod general;
pub(crate) mod polygon;

pub use decision::{
    decide_area, maxmin_area_at_least, AreaDecision, AreaQuestion, DecisionInput,
    MaxMinAreaDecision,
};

use super::{
    AreaApproximation, BoundMeasure, CertifiedBound, CriterionEntry, CriterionInfo, Diagnostics,
    Optimality, Options, Solved,
};
use crate::error::{Error, Result, UnsupportedReason};
use crate::interrupt::Stop;
use crate::kernel::metrics::area;
use crate::kernel::{compare_areas, Point};
use crate::polygon_program::{check_size, corner_point, on_simple_polygon, MAX_POLYGON_VERTICES};
use crate::spatial::{convex_hull_cycle, is_strictly_convex_cycle};
use crate::structures::{PointSet, SimplePolygon, Triangulation};
use crate::timing::{timed, Phase};
use polygon::{convex_polygon_program, BottleneckArea};
use std::cmp::Ordering;

const REFERENCE: &str = "T. S. Vassilev, Optimal area triangulation, PhD thesis, \
                         University of Saskatchewan, 2005 (Algorithms 21 and 44)";

/// The weakest guarantee over all inputs: exact in convex position and on
/// polygons, an approximation (exact when certified) on general sets.
const GENERAL_OPTIMALITY: Optimality = Optimality::Approximation {
    bound: "exact in convex position and on simple polygons; on general point sets (or with \
            alpha or approximation set) never worse than Delaunay, within a certified bound \
            (exact when it meets it), optimal among the alpha-triangulations for alpha >= 30 \
            degrees, and within Vassilev's Theorem 81 factors of an optimum whose smallest \
            angle is below the result's",
};

/// The registry's entry of MaxMin area.
pub(crate) const MAXMIN_ENTRY: CriterionEntry = CriterionEntry {
    info: MAXMIN_INFO,
    solve: solve_maxmin,
    solve_polygon: Some(solve_maxmin_polygon),
};

/// The registry's entry of MinMax area.
pub(crate) const MINMAX_ENTRY: CriterionEntry = CriterionEntry {
    info: MINMAX_INFO,
    solve: solve_minmax,
    solve_polygon: Some(solve_minmax_polygon),
};

pub(crate) const MAXMIN_INFO: CriterionInfo = CriterionInfo {
    name: "maxmin-area",
    description: "maximises the smallest triangle area (exact in convex position and on simple \
                  polygons; general point sets: certified approximation)",
    optimality: GENERAL_OPTIMALITY,
    options: GENERAL_OPTIONS,
    reference: REFERENCE,
    needs_elevations: false,
    measure: Some(crate::structures::Measure::MinArea),
};

pub(crate) const MINMAX_INFO: CriterionInfo = CriterionInfo {
    name: "minmax-area",
    description: "minimises the largest triangle area (exact in convex position and on simple \
                  polygons; general point sets: certified approximation)",
    optimality: GENERAL_OPTIMALITY,
    options: GENERAL_OPTIONS,
    reference: REFERENCE,
    needs_elevations: false,
    measure: Some(crate::structures::Measure::MaxArea),
};

/// The options of the approximations of general point sets.
const GENERAL_OPTIONS: &[&str] = &["alpha", "approximation"];

/// Which area bottleneck is optimised: the one enum of the area criteria
/// (the convex algorithm, the polygon program and the general
/// approximation all read it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum AreaBottleneck {
    /// Maximise the smallest triangle area.
    MaxMin,
    /// Minimise the largest triangle area.
    MinMax,
}

impl AreaBottleneck {
    /// Is the triangle `s` a strictly better bottleneck than `t` (corners
    /// by index, `point` their coordinates): strictly larger for MaxMin,
    /// strictly smaller for MinMax? Exact.
    #[inline]
    pub(crate) fn better(self, point: impl Fn(u32) -> Point, s: [u32; 3], t: [u32; 3]) -> bool {
        if s == t {
            return false;
        }
        let want = match self {
            AreaBottleneck::MaxMin => Ordering::Greater,
            AreaBottleneck::MinMax => Ordering::Less,
        };
        compare_areas(s.map(&point), t.map(&point)) == want
    }

    fn criterion(self) -> &'static str {
        match self {
            AreaBottleneck::MaxMin => MAXMIN_INFO.name,
            AreaBottleneck::MinMax => MINMAX_INFO.name,
        }
    }

    fn convex(self, points: &[Point], polygon: &[u32], stop: &Stop) -> Result<Vec<[u32; 3]>> {
        match self {
            AreaBottleneck::MaxMin => convex::maxmin_area_convex(points, polygon, stop),
            AreaBottleneck::MinMax => convex::minmax_area_convex(points, polygon, stop),
        }
    }
}

/// The algorithm of the strictly convex case, in words.
const CONVEX_ALGORITHM: &str = "Vassilev's Algorithm 44 as repaired (sleeve program over pieces \
     of zonality <= 2, then step iv by range-max search for MaxMin or staircases for MinMax), \
     O(n^2 log n) time, O(n^2) space";

/// Largest strictly convex input for Algorithm 44: its O(n²) tables peaked
/// at 1.27 GB for 10⁴ vertices (both criteria, `area_timing scale 10000`).
pub(crate) const MAX_CONVEX_VERTICES: usize = 12_000;

pub(crate) fn solve_maxmin(
    points: &PointSet,
    options: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    solve_points(points, AreaBottleneck::MaxMin, options, phases)
}

pub(crate) fn solve_minmax(
    points: &PointSet,
    options: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    solve_points(points, AreaBottleneck::MinMax, options, phases)
}

pub(crate) fn solve_maxmin_polygon(
    polygon: &SimplePolygon,
    options: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    refuse_general_options(options)?;
    solve_polygon(polygon, AreaBottleneck::MaxMin, options.stop(), phases)
}

pub(crate) fn solve_minmax_polygon(
    polygon: &SimplePolygon,
    options: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    refuse_general_options(options)?;
    solve_polygon(polygon, AreaBottleneck::MinMax, options.stop(), phases)
}

fn solved(triangulation: Triangulation, algorithm: &str) -> Solved {
    Solved {
        triangulation,
        algorithm: algorithm.to_string(),
        optimality: Optimality::Exact,
        diagnostics: Diagnostics::default(),
        bound: None,
        approximation: None,
    }
}

/// Do the options ask for the general approximation (an angle floor or an
/// approximation other than `best`)?
fn asks_for_approximation(options: &Options) -> bool {
    options.alpha.is_some() || options.approximation != AreaApproximation::Best
}

/// A polygon's optimum is computed exactly: `alpha` and `approximation`
/// choose among the approximations of point sets, so they are refused.
fn refuse_general_options(options: &Options) -> Result<()> {
    if !asks_for_approximation(options) {
        return Ok(());
    }
    let option = if options.alpha.is_some() {
        "alpha"
    } else {
        "approximation"
    };
    Err(Error::InvalidOption {
        option,
        message: "applies to point sets (the approximations of general sets); a polygon's \
                  optimum is computed exactly"
            .to_string(),
    })
}

fn solve_points(
    points: &PointSet,
    kind: AreaBottleneck,
    options: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    let criterion = kind.criterion();
    let stop = options.stop();
    let pts = points.points();
    let hull = convex_hull_cycle(pts);
    // Points in convex position have an exact algorithm; an angle floor or
    // a chosen approximation asks for the approximations instead.
    if hull.len() != pts.len() || asks_for_approximation(options) {
        return solve_general(points, kind, options, phases);
    }
    let strictly_convex = is_strictly_convex_cycle(pts, &hull);
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
        Ok::<_, Error>(if strictly_convex {
            (kind.convex(pts, &hull, stop)?, CONVEX_ALGORITHM)
        } else {
            (
                convex_polygon_program(pts, &hull, kind),
                "polygon program on the convex hull (collinear boundary points; flat \
                 triangles forbidden), O(n^3)",
            )
        })
    })?;
    Ok(solved(
        Triangulation::from_distinct(points, triangles),
        algorithm,
    ))
}

fn solve_polygon(
    polygon: &SimplePolygon,
    kind: AreaBottleneck,
    stop: &Stop,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    let criterion = kind.criterion();
    if polygon.is_strictly_convex() {
        if polygon.len() > MAX_CONVEX_VERTICES {
            return Err(Error::Unsupported {
                criterion,
                reason: UnsupportedReason::TooManyPoints {
                    limit: MAX_CONVEX_VERTICES,
                    distinct: polygon.len(),
                    because: "Algorithm 44's O(n²) tables",
                },
            });
        }
        let triangles = timed(phases, criterion, || {
            kind.convex(polygon.vertices(), polygon.counter_clockwise(), stop)
        })?;
        return Ok(solved(
            Triangulation::from_polygon_positions(polygon, triangles),
            CONVEX_ALGORITHM,
        ));
    }
    check_size(polygon, criterion)?;
    let p = corner_point(polygon);
    let objective = BottleneckArea { point: &p, kind };
    let triangulation = on_simple_polygon(polygon, criterion, &objective, phases)?;
    Ok(solved(
        triangulation,
        "Klincsek dynamic program on the polygon's diagonals, O(n^3), exact area comparisons",
    ))
}

/// General point sets (not in convex position): the best of Delaunay,
/// Algorithm 75, the optimum over triangulations containing RNG ∪ hull and
/// Algorithm 76 (`general`), exact only when it meets the certified bound.
fn solve_general(
    points: &PointSet,
    kind: AreaBottleneck,
    options: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    let settings = general::Settings {
        alpha: options.alpha.as_ref(),
        approximation: options.approximation,
    };
    let result = timed(phases, kind.criterion(), || {
        general::area_general(points, kind, settings, options.stop())
    })?;
    let mut report = result.report;
    report.delaunay_smallest_angle = report
        .delaunay_smallest_angle
        .map(|d| points.input_index(d));
    let triangulation = Triangulation::from_distinct(points, result.triangles);
    let pts = points.points();
    let bound = result.bound.map(|t| CertifiedBound {
        measure: BoundMeasure::Area,
        triangle: Some(t.map(|d| points.input_index(d))),
        value: area(pts[t[0] as usize], pts[t[1] as usize], pts[t[2] as usize]),
        upper: kind == AreaBottleneck::MaxMin,
    });
    Ok(Solved {
        triangulation,
        algorithm: result.algorithm,
        optimality: if result.exact {
            Optimality::Exact
        } else {
            Optimality::Approximation {
                bound: "never worse than Delaunay; the optimum is within the certified `bound`; \
                        what else is proven: `approximation.guarantee`",
            }
        },
        diagnostics: Diagnostics::default(),
        bound,
        approximation: Some(report),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::Interruption;
    use rand::{rngs::StdRng, Rng, SeedableRng};

    /// Options whose stop has fired: a raised cancel flag, then a time limit
    /// of 0 s.
    fn stopped() -> [(Options, Interruption); 2] {
        let cancel = crate::Cancel::new();
        cancel.cancel();
        [
            (
                Options::default().with_cancel(cancel),
                Interruption::Cancelled,
            ),
            (
                Options::default().with_time_limit(std::time::Duration::ZERO),
                Interruption::TimeLimit { seconds: 0.0 },
            ),
        ]
    }

    /// Every area solver stops inside its loops (the registry checks before
    /// a run starts; these call the solvers directly): the general
    /// approximation, Algorithm 44 on points in convex position and on a
    /// convex polygon.
    #[test]
    fn a_stopped_run_stops_each_area_solver() {
        let mut rng = StdRng::seed_from_u64(0xA4EA_5709);
        let scattered: Vec<Point> = (0..200)
            .map(|_| [rng.gen_range(0..1000) as f64, rng.gen_range(0..1000) as f64])
            .collect();
        let scattered = PointSet::new(&scattered).unwrap();
        let convex_points = optri_oracle::inputs::strict_hull(
            optri_oracle::inputs::ellipse_polygon(&mut rng, 60, 1e6, 1.5),
        );
        let convex = PointSet::new(&convex_points).unwrap();
        let polygon = SimplePolygon::new(&convex_points).unwrap();
        assert!(polygon.is_strictly_convex());
        type PointSolver = fn(&PointSet, &Options, &mut Vec<Phase>) -> Result<Solved>;
        type PolygonSolver = fn(&SimplePolygon, &Options, &mut Vec<Phase>) -> Result<Solved>;
        let point_solvers: [PointSolver; 2] = [solve_maxmin, solve_minmax];
        let polygon_solvers: [PolygonSolver; 2] = [solve_maxmin_polygon, solve_minmax_polygon];
        for (options, why) in stopped() {
            let options = options.started();
            for solve in point_solvers {
                for points in [&scattered, &convex] {
                    let result = solve(points, &options, &mut Vec::new()).map(|_| ());
                    assert_eq!(result, Err(Error::Interrupted(why.clone())));
                }
            }
            for solve in polygon_solvers {
                let result = solve(&polygon, &options, &mut Vec::new()).map(|_| ());
                assert_eq!(result, Err(Error::Interrupted(why.clone())));
            }
        }
        let never = Options::default();
        for solve in point_solvers {
            assert!(solve(&scattered, &never, &mut Vec::new()).is_ok());
        }
    }
}
