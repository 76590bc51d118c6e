//! Layer 6: the registry the front ends share (CLI, demo, Python, web). It
//! lists every criterion and every graph kind with its name and description,
//! looks them up by name, and runs them: [`triangulate`] on point sets,
//! [`triangulate_polygon`] on simple polygons, and [`graph`].
//!
//! Adding a criterion costs one variant of [`Criterion`], one arm in
//! [`Criterion::entry`] and, if it accepts polygons, one arm in
//! [`Criterion::polygon_entry`]; everything else lives in the criterion's
//! module.

use crate::criteria::{
    self, CertifiedBound, CriterionInfo, Diagnostics, Optimality, Options, PolygonSolver, Solved,
    Solver,
};
use crate::error::{Error, Result, UnsupportedReason};
use crate::graphs;
use crate::structures::{PointSet, SimplePolygon, Triangulation};
use crate::timing::{timed, Phase};

/// An optimality criterion optri can triangulate by.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Criterion {
    /// The Delaunay triangulation (maximises the smallest angle).
    Delaunay,
    /// Minimises the longest edge (Edelsbrunner–Tan).
    MinmaxLength,
    /// The greedy triangulation (shortest compatible segment first).
    Greedy,
    /// Minimum total edge length (convex position or a polygon, for now).
    MinWeight,
    /// Maximises the smallest triangle area (convex position or a polygon).
    MaxminArea,
    /// Minimises the largest triangle area (convex position or a polygon).
    MinmaxArea,
}

impl Criterion {
    /// Every implemented criterion, in display order.
    pub const ALL: &'static [Criterion] = &[
        Criterion::Delaunay,
        Criterion::MinmaxLength,
        Criterion::Greedy,
        Criterion::MinWeight,
        Criterion::MaxminArea,
        Criterion::MinmaxArea,
    ];

    /// The criterion's description and entry point.
    fn entry(self) -> (&'static CriterionInfo, Solver) {
        match self {
            Criterion::Delaunay => (&criteria::delaunay::INFO, criteria::delaunay::solve),
            Criterion::MinmaxLength => (
                &criteria::minmax_length::INFO,
                criteria::minmax_length::solve,
            ),
            Criterion::Greedy => (&criteria::greedy::INFO, criteria::greedy::solve),
            Criterion::MinWeight => (&criteria::min_weight::INFO, criteria::min_weight::solve),
            Criterion::MaxminArea => (&criteria::area::MAXMIN_INFO, criteria::area::solve_maxmin),
            Criterion::MinmaxArea => (&criteria::area::MINMAX_INFO, criteria::area::solve_minmax),
        }
    }

    /// The criterion's entry point for simple polygons, if it has one.
    fn polygon_entry(self) -> Option<PolygonSolver> {
        use criteria::polygon_criteria as polygon;
        match self {
            Criterion::Delaunay => Some(polygon::solve_delaunay),
            Criterion::MinmaxLength => Some(polygon::solve_minmax_length),
            Criterion::Greedy => Some(polygon::solve_greedy),
            Criterion::MinWeight => Some(polygon::solve_min_weight),
            Criterion::MaxminArea => Some(criteria::area::solve_maxmin_polygon),
            Criterion::MinmaxArea => Some(criteria::area::solve_minmax_polygon),
        }
    }

    /// Does [`triangulate_polygon`] accept this criterion?
    pub fn supports_polygons(self) -> bool {
        self.polygon_entry().is_some()
    }

    /// Name, description, guarantee, requirements and reference.
    pub fn info(self) -> &'static CriterionInfo {
        self.entry().0
    }

    /// The command-line name, e.g. `"delaunay"`, `"minmax-length"`.
    pub fn name(self) -> &'static str {
        self.info().name
    }

    /// One line describing what is optimised.
    pub fn description(self) -> &'static str {
        self.info().description
    }

    /// Looks a criterion up by its [`name`](Self::name), ignoring ASCII case
    /// (as input-format names do), so `DELAUNAY` is `delaunay`.
    ///
    /// # Errors
    /// [`Error::UnknownName`] listing the available names.
    pub fn from_name(name: &str) -> Result<Self> {
        Self::ALL
            .iter()
            .copied()
            .find(|c| c.name().eq_ignore_ascii_case(name))
            .ok_or_else(|| Error::UnknownName {
                kind: "criterion",
                name: name.to_string(),
                available: Self::ALL.iter().map(|c| c.name()).collect(),
            })
    }
}

/// The result of [`triangulate`] or [`triangulate_polygon`]: the triangulation and how it was obtained.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct Solution {
    /// The criterion that was optimised.
    pub criterion: Criterion,
    /// Whether the result is provably optimal for the criterion
    /// (`optimality == Optimality::Exact`).
    pub exact: bool,
    /// The guarantee of this result.
    pub optimality: Optimality,
    /// The algorithm that ran (e.g. `"spade bulk load"`).
    pub algorithm: String,
    /// The triangulation.
    pub triangulation: Triangulation,
    /// Timed phases, in order.
    pub phases: Vec<Phase>,
    /// Counters the algorithm reported (may be empty).
    pub diagnostics: Diagnostics,
    /// For a result that is not proven optimal, a certified bound on the
    /// optimum when one is cheap (e.g. MaxMin area of a general point set).
    pub bound: Option<CertifiedBound>,
    /// The metric lengths were measured in ([`Options::metric`]).
    pub metric: crate::kernel::Metric,
}

/// Triangulates `points` by `criterion` with default [`Options`].
pub fn triangulate(points: &PointSet, criterion: Criterion) -> Result<Solution> {
    triangulate_with(points, criterion, &Options::default())
}

/// Triangulates `points` by `criterion` with `options`.
///
/// # Errors
/// [`Error::Unsupported`] when the criterion cannot handle the input (see
/// [`CriterionInfo::requirement`]); [`Error::Internal`] on a bug.
pub fn triangulate_with(
    points: &PointSet,
    criterion: Criterion,
    options: &Options,
) -> Result<Solution> {
    if !options.metric.is_euclidean() && criterion != Criterion::MinmaxLength {
        return Err(Error::Unsupported {
            criterion: criterion.name(),
            reason: UnsupportedReason::MetricNotSupported {
                metric: options.metric.name(),
            },
        });
    }
    let mut phases = Vec::new();
    let solved = (criterion.entry().1)(points, options, &mut phases)?;
    Ok(Solution::new(criterion, solved, phases, options))
}

/// Triangulates the interior of `polygon` by `criterion` with default
/// [`Options`]. The triangulation's [`Domain`](crate::Domain) is the polygon
/// and its indices are positions in the caller's ring.
///
/// ```
/// use optri::{triangulate_polygon, Criterion, SimplePolygon};
/// // An L-shape, listed clockwise: the chord 2-4 leaves the polygon.
/// let l = SimplePolygon::new(&[[0.0, 0.0], [0.0, 2.0], [1.0, 2.0], [1.0, 1.0], [2.0, 1.0], [2.0, 0.0]])?;
/// assert!(!l.is_diagonal(2, 4) && l.is_diagonal(0, 3) && l.is_diagonal(1, 3));
/// let solution = triangulate_polygon(&l, Criterion::MinmaxArea)?;
/// solution.triangulation.validate()?;
/// assert_eq!(solution.triangulation.triangles().len(), 4);
/// # Ok::<(), optri::Error>(())
/// ```
pub fn triangulate_polygon(polygon: &SimplePolygon, criterion: Criterion) -> Result<Solution> {
    triangulate_polygon_with(polygon, criterion, &Options::default())
}

/// Triangulates the interior of `polygon` by `criterion` with `options`.
///
/// # Errors
/// [`Error::Unsupported`] when the criterion takes no polygons
/// ([`UnsupportedReason::NoPolygonInput`], see
/// [`Criterion::supports_polygons`]) or the polygon is too large for it;
/// [`Error::Internal`] on a bug.
pub fn triangulate_polygon_with(
    polygon: &SimplePolygon,
    criterion: Criterion,
    options: &Options,
) -> Result<Solution> {
    if !options.metric.is_euclidean() {
        return Err(Error::Unsupported {
            criterion: criterion.name(),
            reason: UnsupportedReason::MetricNotSupported {
                metric: options.metric.name(),
            },
        });
    }
    let solve = criterion.polygon_entry().ok_or(Error::Unsupported {
        criterion: criterion.name(),
        reason: UnsupportedReason::NoPolygonInput,
    })?;
    let mut phases = Vec::new();
    let solved = solve(polygon, options, &mut phases)?;
    Ok(Solution::new(criterion, solved, phases, options))
}

impl Solution {
    fn new(
        criterion: Criterion,
        solved: Solved,
        phases: Vec<crate::timing::Phase>,
        options: &Options,
    ) -> Self {
        Solution {
            criterion,
            exact: solved.optimality.is_exact(),
            optimality: solved.optimality,
            algorithm: solved.algorithm,
            triangulation: solved.triangulation,
            phases,
            diagnostics: solved.diagnostics,
            bound: solved.bound,
            metric: options.metric.clone(),
        }
    }
}

impl Solution {
    /// The longest edge under [`Solution::metric`] (exact comparisons) and its
    /// length, rounded.
    pub fn longest_edge_under_metric(&self) -> ([u32; 2], f64) {
        let t = &self.triangulation;
        let p = t.points();
        let m = &self.metric;
        let at = |e: [u32; 2]| [p[e[0] as usize], p[e[1] as usize]];
        let mut best = t.edges()[0];
        for e in t.edges() {
            let (a, b) = (at(e), at(best));
            if m.compare_norm(a[0], a[1], b[0], b[1]) == std::cmp::Ordering::Greater {
                best = e;
            }
        }
        let b = at(best);
        (best, m.length(b[0], b[1]))
    }
}

/// A proximity graph optri computes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum GraphKind {
    /// The convex hull, collinear boundary points included (edges `[a, b]`
    /// counter-clockwise).
    Hull,
    /// The Delaunay triangulation's edges.
    Delaunay,
    /// The relative neighbourhood graph.
    Rng,
    /// The Gabriel graph.
    Gabriel,
    /// The Euclidean minimum spanning tree.
    Mst,
}

impl GraphKind {
    /// Every graph kind, in display order.
    pub const ALL: &'static [GraphKind] = &[
        GraphKind::Hull,
        GraphKind::Delaunay,
        GraphKind::Rng,
        GraphKind::Gabriel,
        GraphKind::Mst,
    ];

    /// The command-line name, e.g. `"rng"`.
    pub fn name(self) -> &'static str {
        match self {
            GraphKind::Hull => "hull",
            GraphKind::Delaunay => "delaunay",
            GraphKind::Rng => "rng",
            GraphKind::Gabriel => "gabriel",
            GraphKind::Mst => "mst",
        }
    }

    /// One line describing the graph.
    pub fn description(self) -> &'static str {
        match self {
            GraphKind::Hull => "convex hull (collinear boundary points are vertices)",
            GraphKind::Delaunay => "Delaunay triangulation edges",
            GraphKind::Rng => "relative neighbourhood graph (empty open lunes)",
            GraphKind::Gabriel => "Gabriel graph (empty diametral circles)",
            GraphKind::Mst => "Euclidean minimum spanning tree",
        }
    }

    /// Looks a graph kind up by [`name`](Self::name), ignoring ASCII case.
    ///
    /// # Errors
    /// [`Error::UnknownName`] listing the available names.
    pub fn from_name(name: &str) -> Result<Self> {
        Self::ALL
            .iter()
            .copied()
            .find(|k| k.name().eq_ignore_ascii_case(name))
            .ok_or_else(|| Error::UnknownName {
                kind: "graph kind",
                name: name.to_string(),
                available: Self::ALL.iter().map(|k| k.name()).collect(),
            })
    }
}

/// The edges of the graph `kind` of `points`, as input-index pairs (see
/// [`GraphKind`] for the edge convention), with its timed phase.
pub fn graph(points: &PointSet, kind: GraphKind) -> Result<(Vec<[u32; 2]>, Vec<Phase>)> {
    graph_with(points, kind, &Options::default())
}

/// [`graph`] with lengths in `options.metric`: the RNG and the MST take any
/// [`crate::kernel::Metric`] (sector candidates, exact lunes); the other
/// graphs are Euclidean notions and refuse a non-Euclidean metric with
/// [`UnsupportedReason::MetricNotSupported`].
pub fn graph_with(
    points: &PointSet,
    kind: GraphKind,
    options: &Options,
) -> Result<(Vec<[u32; 2]>, Vec<Phase>)> {
    let metric = &options.metric;
    if !metric.is_euclidean() {
        let mut phases = Vec::new();
        let edges = timed(&mut phases, kind.name(), || match kind {
            GraphKind::Rng => graphs::relative_neighborhood_graph_under(points, metric),
            GraphKind::Mst => graphs::minimum_spanning_tree_under(points, metric),
            _ => Err(Error::Unsupported {
                criterion: kind.name(),
                reason: UnsupportedReason::MetricNotSupported {
                    metric: metric.name(),
                },
            }),
        })?;
        return Ok((edges, phases));
    }
    let mut phases = Vec::new();
    let edges = timed(&mut phases, kind.name(), || match kind {
        GraphKind::Hull => Ok(graphs::convex_hull_edges(points)),
        GraphKind::Delaunay => graphs::delaunay_edges(points),
        GraphKind::Rng => graphs::relative_neighborhood_graph(points),
        GraphKind::Gabriel => graphs::gabriel_graph(points),
        GraphKind::Mst => graphs::minimum_spanning_tree(points),
    })?;
    Ok((edges, phases))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unknown_criterion_lists_the_available_ones() {
        let e = Criterion::from_name("nope").unwrap_err().to_string();
        assert!(e.contains("delaunay"), "{e}");
        assert_eq!(
            Criterion::from_name("delaunay").unwrap(),
            Criterion::Delaunay
        );
    }

    #[test]
    fn every_registered_name_round_trips() {
        for &c in Criterion::ALL {
            assert_eq!(Criterion::from_name(c.name()).unwrap(), c);
            assert_eq!(c.info().name, c.name());
        }
        for &k in GraphKind::ALL {
            assert_eq!(GraphKind::from_name(&k.name().to_uppercase()).unwrap(), k);
        }
        assert!(matches!(
            GraphKind::from_name("voronoi"),
            Err(Error::UnknownName {
                kind: "graph kind",
                ..
            })
        ));
    }
}
