//! δ-triangulations (T. S. Vassilev, *Optimal area triangulation*, PhD
//! thesis, University of Saskatchewan, 2005, Table 1.1, rows on δ-area,
//! δ-angle and δ-length): minimise `δ(T)`, the largest minus the smallest
//! item of the triangulation `T`, where the items are its triangles'
//! areas (`minmax-delta-area`), the 3(n − 2) interior angles of its
//! triangles (`minmax-delta-angle`) or the lengths of all its edges,
//! boundary edges included (`minmax-delta-length`).
//!
//! | input | algorithm | time |
//! |---|---|---|
//! | points in convex position, simple polygon | the threshold sweep (`sweep`): the bottleneck polygon program once per candidate lower bound, pruned to `[M* − δ_ub, m*]` and by the monotonicity of `U(L)` | O(n³ log n) to rank the items, then O(w·n³) for `w` thresholds tried: O(n⁶) in the worst case for area and angle; for length in convex position O(n⁴) (below) |
//! | other point sets | the best of Delaunay, greedy and minmax-length by exact δ (`Optimality::Approximation`) | theirs |
//!
//! **δ-length in convex position.** Every boundary edge is in every
//! triangulation, so the smallest item is at most `s`, the shortest
//! boundary edge, and the sweep only tries thresholds up to `m* ≤ s`: `s`
//! and the diagonals shorter than `s`. Two crossing diagonals `ac`, `bd`
//! of a convex polygon have `|ac| + |bd| > |ab| + |cd| ≥ 2s`, so the
//! diagonals shorter than `s` do not cross: at most `n − 3` of them, so at
//! most `n − 2` programs of O(n³). (Table 1.1's O(n³) would need a single
//! threshold, which a thin rhombus refutes: its short diagonal gives the
//! smaller δ.)
//!
//! # Exactness
//! Items are ranked by the kernel's exact comparisons (areas, corner
//! angles, lengths) and the programs compare ranks; differences are
//! compared exactly (`kernel::differences`). The result is exactly optimal
//! on convex position and simple polygons. Ties: the programs keep their
//! first best split corner and the sweep keeps the first best δ, so some
//! optimum is returned.

mod measure;
mod sweep;

use super::{CriterionEntry, CriterionInfo, Diagnostics, Optimality, Options, Solved};
use crate::error::{Error, Result, UnsupportedReason};
use crate::polygon_program::{corner_point, diagonal_table};
use crate::spatial::convex_hull_cycle;
use crate::structures::{PointSet, SimplePolygon, Triangulation};
use crate::timing::{timed, Phase};
use measure::Measure;
use std::cmp::Ordering;

const REFERENCE: &str = "T. S. Vassilev, Optimal area triangulation, PhD thesis, University of \
                         Saskatchewan, 2005 (Table 1.1: the modified Klincsek program)";

/// Exact in convex position and on simple polygons only.
const OPTIMALITY: Optimality = Optimality::Approximation {
    bound: "exact in convex position and on simple polygons; on other point sets the best of \
            Delaunay, greedy and minmax-length by exact delta",
};

/// Largest polygon the sweep accepts: it ranks every triangle's items
/// (O(n³) memory: about 100 MB of tables for 256 corners under δ-angle).
pub(crate) const MAX_DELTA_VERTICES: usize = 256;

/// The registry's entry of δ-area.
pub(crate) const AREA_ENTRY: CriterionEntry = CriterionEntry {
    info: info(
        "minmax-delta-area",
        "minimises the largest minus the smallest triangle area (exact in convex position and \
         on simple polygons)",
    ),
    solve: |points, options, phases| solve_points(points, Measure::Area, options, phases),
    solve_polygon: Some(|polygon, options, phases| {
        solve_polygon(polygon, Measure::Area, options, phases)
    }),
};

/// The registry's entry of δ-angle.
pub(crate) const ANGLE_ENTRY: CriterionEntry = CriterionEntry {
    info: info(
        "minmax-delta-angle",
        "minimises the largest minus the smallest interior angle (exact in convex position and \
         on simple polygons)",
    ),
    solve: |points, options, phases| solve_points(points, Measure::Angle, options, phases),
    solve_polygon: Some(|polygon, options, phases| {
        solve_polygon(polygon, Measure::Angle, options, phases)
    }),
};

/// The registry's entry of δ-length.
pub(crate) const LENGTH_ENTRY: CriterionEntry = CriterionEntry {
    info: info(
        "minmax-delta-length",
        "minimises the longest minus the shortest edge, boundary included (exact in convex \
         position and on simple polygons)",
    ),
    solve: |points, options, phases| solve_points(points, Measure::Length, options, phases),
    solve_polygon: Some(|polygon, options, phases| {
        solve_polygon(polygon, Measure::Length, options, phases)
    }),
};

const fn info(name: &'static str, description: &'static str) -> CriterionInfo {
    CriterionInfo {
        name,
        description,
        optimality: OPTIMALITY,
        options: &[],
        reference: REFERENCE,
        needs_elevations: false,
        measure: None,
    }
}

impl Measure {
    fn criterion(self) -> &'static str {
        match self {
            Measure::Area => AREA_ENTRY.info.name,
            Measure::Angle => ANGLE_ENTRY.info.name,
            Measure::Length => LENGTH_ENTRY.info.name,
        }
    }
}

const SWEEP: &str = "threshold sweep of the bottleneck polygon program over the distinct lower \
                     bounds in [M* - delta_ub, m*], exact";

fn check_size(measure: Measure, k: usize) -> Result<()> {
    if k > MAX_DELTA_VERTICES {
        return Err(Error::Unsupported {
            criterion: measure.criterion(),
            reason: UnsupportedReason::TooManyPoints {
                limit: MAX_DELTA_VERTICES,
                distinct: k,
                because: "the threshold sweep ranks the items of all O(n³) triangles",
            },
        });
    }
    Ok(())
}

fn exact(triangulation: Triangulation, programs: u64) -> Solved {
    let mut diagnostics = Diagnostics::default();
    diagnostics.add("polygon programs", programs);
    Solved {
        triangulation,
        algorithm: SWEEP.to_string(),
        optimality: Optimality::Exact,
        diagnostics,
        bound: None,
        approximation: None,
    }
}

fn solve_points(
    points: &PointSet,
    measure: Measure,
    options: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    let pts = points.points();
    let hull = convex_hull_cycle(pts);
    if hull.len() != pts.len() {
        return solve_general(points, measure, options, phases);
    }
    check_size(measure, hull.len())?;
    let point = |c: usize| pts[hull[c] as usize];
    // Every chord of a convex polygon is a diagonal; chords along a
    // straight side bound only flat triangles, which are never used.
    let swept = timed(phases, measure.criterion(), || {
        sweep::least_delta(measure, hull.len(), &point, &|_, _| true, options.stop())
    })?
    .ok_or_else(|| Error::Internal("a convex polygon without a triangulation".into()))?;
    let triangles = swept.triangles.iter().map(|t| t.map(|c| hull[c])).collect();
    Ok(exact(
        Triangulation::from_distinct(points, triangles),
        swept.programs,
    ))
}

fn solve_polygon(
    polygon: &SimplePolygon,
    measure: Measure,
    options: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    let k = polygon.len();
    check_size(measure, k)?;
    let table = timed(phases, "diagonals", || {
        Ok::<_, Error>(diagonal_table(polygon))
    })?;
    let point = corner_point(polygon);
    let swept = timed(phases, measure.criterion(), || {
        sweep::least_delta(measure, k, &point, &|i, j| table[i * k + j], options.stop())
    })?
    .ok_or_else(|| Error::Internal("a simple polygon without a triangulation".into()))?;
    let ccw = polygon.counter_clockwise();
    let triangles = swept.triangles.iter().map(|t| t.map(|c| ccw[c])).collect();
    Ok(exact(
        Triangulation::from_polygon_positions(polygon, triangles),
        swept.programs,
    ))
}

/// Points not in convex position: the best of the triangulations other
/// criteria compute quickly, by exact δ; not proven optimal.
fn solve_general(
    points: &PointSet,
    measure: Measure,
    options: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    let stop = options.stop();
    let candidates = timed(phases, "candidates", || {
        let mut candidates = vec![("Delaunay", crate::graphs::delaunay(points)?)];
        stop.check()?;
        candidates.push(("greedy", super::greedy::greedy(points)?));
        stop.check()?;
        candidates.push((
            "minmax-length",
            super::minmax_length::minmax_length(points)?,
        ));
        Ok::<_, Error>(candidates)
    })?;
    let (name, triangulation) = timed(phases, measure.criterion(), || {
        Ok::<_, Error>(least_delta_of(measure, candidates))
    })?;
    Ok(Solved {
        triangulation,
        algorithm: format!(
            "the least delta of Delaunay, greedy and minmax-length (exact comparisons): {name}"
        ),
        optimality: Optimality::Approximation {
            bound: "the best of Delaunay, greedy and minmax-length by exact delta; not proven \
                    optimal",
        },
        diagnostics: Diagnostics::default(),
        bound: None,
        approximation: None,
    })
}

/// The candidate with the least δ (the first of equals), by exact
/// comparisons; all candidates triangulate the same points.
fn least_delta_of(
    measure: Measure,
    candidates: Vec<(&'static str, Triangulation)>,
) -> (&'static str, Triangulation) {
    let points = candidates[0].1.points().to_vec();
    let point = |i: usize| points[i];
    let mut best: Option<(&'static str, Triangulation, [measure::Item; 2])> = None;
    for (name, candidate) in candidates {
        let extremes = measure.extremes(&point, candidate.triangles());
        let replace = best.as_ref().is_none_or(|(_, _, current)| {
            measure.compare_differences(&point, extremes, *current) == Ordering::Less
        });
        if replace {
            best = Some((name, candidate, extremes));
        }
    }
    let (name, triangulation, _) = best.expect("at least one candidate");
    (name, triangulation)
}
