//! Test and benchmark hooks (feature `internals`). Not the place you are
//! looking for: nothing here is a stable API, and every item exists so that
//! the test suite and the benchmarks can reach one algorithm variant or
//! reference directly.

pub use crate::criteria::area::general::AreaGeneralSteps;
pub use crate::criteria::greedy::{
    greedy_edges_by, greedy_naive_edges, greedy_triangulation, is_convex_position, is_semicircular,
    is_weakly_convex_position, GreedyAlgorithm,
};
pub use crate::criteria::min_weight::MAX_POINTS as MIN_WEIGHT_MAX_POINTS;
pub use crate::criteria::minmax_length::{
    minmax_length_cubic, minmax_length_under_with, minmax_length_with, SMALL_REGION,
};
pub use crate::structures::planar_graph::{Face, PlanarGraph};

/// Kernel predicates that serve one algorithm (the diamond filter, the
/// half-lunes, the symbolic orders), exported for their tests.
pub mod kernel {
    pub use crate::kernel::length_sums::{compare_length_sums_exactly, LengthInterval};
    pub use crate::kernel::lune::{in_half_lune, in_half_lune_symbolic};
    pub use crate::kernel::norm::side_of_direction;
    pub use crate::kernel::predicates::{
        angle_at_least_30_degrees, angle_below_diamond, certainly_outside_diamonds,
        compare_corner_angles, compare_doubled_area, cross_sign, dot_sign, exact_squared_length,
        on_open_segment, DiamondPosition, DiamondTriangles,
    };
    pub use crate::kernel::reporting::{
        area_scaled, length_scaled, over_power_of_ten_rounded, total_length_scaled, Rounding,
    };
    pub use crate::kernel::squared_length::SquaredLength;
    pub use crate::kernel::symbolic::{compare_equal_lengths_symbolic, height_sign, segment_order};
    pub use crate::kernel::wedge::{
        same_direction, strictly_inside_wedge, strictly_inside_wedge_symbolic,
    };
}

/// The area criteria on points in convex position by Klincsek's cubic
/// program (the reference Algorithm 44 is measured against): `criterion`
/// is `MaxMinArea` or `MinMaxArea`. Triangles as distinct indices.
///
/// # Errors
/// [`crate::Error::Internal`] for another criterion.
pub fn area_by_polygon_program(
    points: &crate::PointSet,
    criterion: crate::Criterion,
) -> crate::Result<Vec<[u32; 3]>> {
    use crate::criteria::area::polygon::convex_polygon_program;
    let hull = crate::spatial::convex_hull_cycle(points.points());
    Ok(convex_polygon_program(
        points.points(),
        &hull,
        area_bottleneck(criterion)?,
    ))
}

/// The bottleneck an area criterion optimises.
fn area_bottleneck(
    criterion: crate::Criterion,
) -> crate::Result<crate::criteria::area::AreaBottleneck> {
    use crate::criteria::area::AreaBottleneck;
    match criterion {
        crate::Criterion::MaxMinArea => Ok(AreaBottleneck::MaxMin),
        crate::Criterion::MinMaxArea => Ok(AreaBottleneck::MinMax),
        _ => Err(crate::Error::Internal(format!(
            "{} is not an area criterion",
            criterion.name()
        ))),
    }
}

/// One run of the area criteria's approximation for general point sets on
/// any point set (convex ones included, which the product sends to the
/// convex algorithm instead).
pub struct AreaGeneralRun {
    /// The candidates computed, in their tie-breaking order: name and
    /// triangles (distinct indices).
    pub candidates: Vec<(&'static str, Vec<[u32; 3]>)>,
    /// The returned triangulation (distinct indices).
    pub triangles: Vec<[u32; 3]>,
    /// The name of the candidate returned.
    pub algorithm: String,
    /// Whether it attains the certified bound (proven optimal).
    pub exact: bool,
    /// Corners of the largest face of `RNG ∪ hull`.
    pub largest_face: usize,
    /// Flips made by Algorithm 76.
    pub flips: usize,
}

/// The approximation of `criterion` (`MaxMinArea` or `MinMaxArea`) on
/// `points`: its candidates and its result.
///
/// # Errors
/// [`crate::Error::Internal`] on a bug; `Unsupported` for another criterion.
pub fn area_general(
    points: &crate::PointSet,
    criterion: crate::Criterion,
) -> crate::Result<AreaGeneralRun> {
    use crate::criteria::area::general;
    let objective = area_bottleneck(criterion)?;
    let never = crate::interrupt::Stop::default();
    let settings = general::Settings::default();
    let candidates = general::candidates(points, objective, settings, &never)?;
    let result = general::best_of(points, objective, settings, &candidates, &never)?;
    Ok(AreaGeneralRun {
        candidates: candidates
            .list
            .into_iter()
            .map(|c| (c.name, c.triangles))
            .collect(),
        triangles: result.triangles,
        algorithm: result.algorithm,
        exact: result.exact,
        largest_face: candidates.largest_face,
        flips: candidates.flips,
    })
}

/// Runs and times each step of the area approximation for general point
/// sets on `points`, both objectives.
///
/// # Errors
/// [`crate::Error::Internal`] on a bug.
pub fn area_general_steps(points: &crate::PointSet) -> crate::Result<AreaGeneralSteps> {
    crate::criteria::area::general::step_times(points)
}

/// The general min-weight pipeline (diamond filter, LMT-skeleton, faces)
/// on any point set, convex ones included: the triangulation, whether it is
/// proven optimal, the diagnostics and the certified lower bound of the
/// optimal weight.
pub fn min_weight_pipeline(points: &crate::PointSet) -> crate::Result<MinWeightRun> {
    min_weight_pipeline_with_budget(points, crate::criteria::min_weight::FRONT_BUDGET)
}

/// The general min-weight pipeline's edge sets on `points`: the diamond
/// filter's candidates, the edges left by the LMT loop and the certain
/// edges (distinct indices, sorted pairs `u < v`, each list sorted). The
/// LMT loop runs `loop_chunk` edges per parallel task: 1 interleaves the
/// threads the most, `usize::MAX` is the sequential loop.
pub fn min_weight_skeleton_edges(
    points: &crate::PointSet,
    loop_chunk: usize,
) -> [Vec<[u32; 2]>; 3] {
    crate::criteria::min_weight::skeleton_edge_sets(points, loop_chunk)
}

/// [`min_weight_pipeline`] with the exact search on faces with holes
/// limited to `budget` memoised fronts per face (a tiny budget leaves such
/// faces unsolved: the result is then not exact, its bound certified).
pub fn min_weight_pipeline_with_budget(
    points: &crate::PointSet,
    budget: usize,
) -> crate::Result<MinWeightRun> {
    let mut phases = Vec::new();
    let g = crate::criteria::min_weight::general_min_weight(points, &mut phases, budget)?;
    let lower_bound = g.lower_bound.unwrap_or_else(|| {
        crate::criteria::min_weight::certified_weight_below(&g.solved.triangulation)
    });
    Ok(MinWeightRun {
        exact: g.solved.optimality.is_exact(),
        triangulation: g.solved.triangulation,
        diagnostics: g.solved.diagnostics,
        lower_bound,
    })
}

/// What the general min-weight pipeline returned ([`min_weight_pipeline`]).
#[derive(Clone, Debug)]
pub struct MinWeightRun {
    /// The triangulation found.
    pub triangulation: crate::Triangulation,
    /// Is it proven optimal?
    pub exact: bool,
    /// What the pipeline did (skeleton edges, faces, searches).
    pub diagnostics: crate::Diagnostics,
    /// A certified lower bound on the minimum weight (the weight itself,
    /// rounded down, when `exact`).
    pub lower_bound: f64,
}

/// The registry's [`Solution`](crate::Solution) of the general min-weight
/// pipeline with the exact search limited to `budget` fronts per face (for
/// the JSON document of a result that is not proven optimal).
pub fn min_weight_solution_with_budget(
    points: &crate::PointSet,
    budget: usize,
) -> crate::Result<crate::Solution> {
    let mut phases = Vec::new();
    let g = crate::criteria::min_weight::general_min_weight(points, &mut phases, budget)?;
    Ok(crate::Solution::from_solved(
        crate::Criterion::MinWeight,
        g.solved,
        phases,
        &crate::Options::default(),
    ))
}

/// The edge-insertion criteria's reference (the generic loop from
/// Delaunay, every anchor–candidate pair retried at every step):
/// distinct-index triangles of `points` under `criterion` (`MinMaxAngle`,
/// `MaxMinHeight`, `MinMaxEccentricity` or `MinMaxSlope`, the last reading
/// the point set's elevations), and the number of accepted insertions.
///
/// # Errors
/// [`crate::Error::Internal`] for another criterion; as the criterion.
pub fn edge_insertion_reference(
    points: &crate::PointSet,
    criterion: crate::Criterion,
) -> crate::Result<(Vec<[u32; 3]>, u64)> {
    use crate::criteria::edge_insertion::edge_insertion_triangles;
    let never = crate::interrupt::Stop::default();
    let (triangles, steps) =
        edge_insertion_triangles(points, edge_insertion_measure(criterion)?, false, &never)?;
    Ok((triangles, steps.insertions))
}

/// The worst triangle's value among `triangles` (distinct indices) under an
/// edge-insertion criterion, correctly rounded: degrees for
/// `MinMaxAngle`, lengths for the others (slope: rise over run).
///
/// # Errors
/// [`crate::Error::Internal`] for another criterion.
pub fn edge_insertion_worst_value(
    points: &crate::PointSet,
    criterion: crate::Criterion,
    triangles: &[[u32; 3]],
) -> crate::Result<f64> {
    crate::criteria::edge_insertion::worst_value(
        points,
        edge_insertion_measure(criterion)?,
        triangles,
    )
}

fn edge_insertion_measure(
    criterion: crate::Criterion,
) -> crate::Result<crate::kernel::TriangleMeasure> {
    use crate::kernel::TriangleMeasure;
    Ok(match criterion {
        crate::Criterion::MinMaxAngle => TriangleMeasure::LargestAngle,
        crate::Criterion::MaxMinHeight => TriangleMeasure::SmallestHeight,
        crate::Criterion::MinMaxEccentricity => TriangleMeasure::Eccentricity,
        crate::Criterion::MinMaxSlope => TriangleMeasure::Slope,
        _ => {
            return Err(crate::Error::Internal(format!(
                "{} is not an edge-insertion criterion",
                criterion.name()
            )))
        }
    })
}
