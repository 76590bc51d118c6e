//! Layer 6: the registry the front ends share (CLI, demo, Python, web). It
//! lists every criterion and every graph kind with its name, description and
//! the options it reads, looks them up by name, and runs them:
//! [`triangulate`] on point sets and simple
//! polygons, [`compare`], and [`graph`].
//!
//! The registry reads each criterion's declaration (its `ENTRY`: info,
//! options, solvers) and nothing else, so adding a criterion is its module
//! and one line in [`Criterion`]'s list below.

use crate::criteria::{
    self, CertifiedBound, CriterionEntry, CriterionInfo, Diagnostics, InputKind, Optimality,
    Options, Solved,
};
use crate::error::{Error, Result, UnsupportedReason};
use crate::graphs;
use crate::structures::{PointSet, SimplePolygon, Triangulation};
use crate::timing::{timed, Phase};

/// Declares [`Criterion`] from one line per criterion: its variant (with
/// its doc comment) and its module's `ENTRY`.
macro_rules! criteria {
    ($($(#[doc = $doc:literal])* $variant:ident => $entry:path,)*) => {
        /// An optimality criterion optri can triangulate by.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        #[non_exhaustive]
        pub enum Criterion {
            $($(#[doc = $doc])* $variant,)*
        }

        impl Criterion {
            /// Every implemented criterion, in display order.
            pub const ALL: &'static [Criterion] = &[$(Criterion::$variant),*];

            /// The criterion's declaration: description, options, solvers.
            fn entry(self) -> &'static CriterionEntry {
                match self {
                    $(Criterion::$variant => &$entry,)*
                }
            }
        }
    };
}

criteria! {
    /// The Delaunay triangulation (maximises the smallest angle).
    Delaunay => criteria::delaunay::ENTRY,
    /// Minimises the longest edge (Edelsbrunner & Tan), under any norm.
    MinMaxLength => criteria::minmax_length::ENTRY,
    /// The greedy triangulation (shortest compatible segment first).
    Greedy => criteria::greedy::ENTRY,
    /// Minimum total edge length (LMT-skeleton, then exact face programs).
    MinWeight => criteria::min_weight::ENTRY,
    /// Maximises the smallest triangle area (exact on convex polygons,
    /// certified approximations on general point sets).
    MaxMinArea => criteria::area::MAXMIN_ENTRY,
    /// Minimises the largest triangle area (as MaxMin area).
    MinMaxArea => criteria::area::MINMAX_ENTRY,
    /// Minimises the largest angle (edge insertion).
    MinMaxAngle => criteria::edge_insertion::MINMAX_ANGLE_ENTRY,
    /// Maximises the smallest triangle altitude (edge insertion).
    MaxMinHeight => criteria::edge_insertion::MAXMIN_HEIGHT_ENTRY,
    /// Minimises the largest circumcentre-to-triangle distance (edge
    /// insertion).
    MinMaxEccentricity => criteria::edge_insertion::MINMAX_ECCENTRICITY_ENTRY,
    /// Minimises the steepest slope over per-point elevations (edge
    /// insertion).
    MinMaxSlope => criteria::edge_insertion::MINMAX_SLOPE_ENTRY,
    /// Minimises the largest minus the smallest triangle area (exact in
    /// convex position and on simple polygons).
    MinMaxDeltaArea => criteria::delta::AREA_ENTRY,
    /// Minimises the largest minus the smallest interior angle (as δ-area).
    MinMaxDeltaAngle => criteria::delta::ANGLE_ENTRY,
    /// Minimises the longest minus the shortest edge (as δ-area).
    MinMaxDeltaLength => criteria::delta::LENGTH_ENTRY,
}

impl Criterion {
    /// Does the criterion triangulate this kind of input?
    pub fn accepts(self, input: InputKind) -> bool {
        match input {
            InputKind::PointSet => true,
            InputKind::SimplePolygon => self.entry().solve_polygon.is_some(),
        }
    }

    /// The kinds of input the criterion triangulates.
    pub fn inputs(self) -> Vec<InputKind> {
        InputKind::ALL
            .iter()
            .copied()
            .filter(|&k| self.accepts(k))
            .collect()
    }

    /// Name, description, guarantee, options and reference.
    pub fn info(self) -> &'static CriterionInfo {
        &self.entry().info
    }

    /// The command-line name, e.g. `"delaunay"`, `"minmax-length"`.
    pub fn name(self) -> &'static str {
        self.info().name
    }

    /// One line describing what is optimised.
    pub fn description(self) -> &'static str {
        self.info().description
    }

    /// The names of the options the criterion reads
    /// ([`CriterionInfo::options`]).
    pub fn options(self) -> &'static [&'static str] {
        self.info().options
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

/// Refuses the options `what` does not read (those not in `declared`) when
/// they are set to something other than their default.
fn check_options(what: &'static str, declared: &[&str], options: &Options) -> Result<()> {
    match options.chosen().into_iter().find(|o| !declared.contains(o)) {
        None => Ok(()),
        Some("metric") => Err(Error::Unsupported {
            criterion: what,
            reason: UnsupportedReason::MetricNotSupported {
                metric: options.metric.name(),
                taken_by: takers_of("metric"),
            },
        }),
        Some(other) => Err(Error::Internal(format!(
            "option {other} has no refusal for {what}"
        ))),
    }
}

/// The criteria and graph kinds that read the option `name`.
fn takers_of(name: &str) -> Vec<&'static str> {
    let criteria = Criterion::ALL
        .iter()
        .filter(|c| c.options().contains(&name))
        .map(|c| c.name());
    let graphs = GraphKind::ALL
        .iter()
        .filter(|k| k.options().contains(&name))
        .map(|k| k.name());
    criteria.chain(graphs).collect()
}

/// The result of [`triangulate`]: the triangulation and how it was obtained.
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
    /// The algorithm that ran, short (e.g. `"spade bulk-load Delaunay"`,
    /// greedy's `"general"`).
    pub algorithm: String,
    /// The algorithm in full: its paper, steps and bounds, and what happened
    /// on this input (it starts with [`algorithm`](Self::algorithm)).
    pub algorithm_detail: String,
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
    /// General-set area results: the approximation, α*, the α used, the
    /// candidates, the flips and the guarantee.
    pub approximation: Option<crate::criteria::ApproximationReport>,
}

/// What a criterion triangulates: a [`PointSet`] (its convex hull) or a
/// [`SimplePolygon`] (its interior). [`triangulate`], [`triangulate_with`]
/// and [`compare`] take either; the triangulation's [`Domain`](crate::Domain)
/// says which, and its indices are the caller's input indices (ring
/// positions for a polygon).
pub trait Triangulable: sealed::Solve {}

impl Triangulable for PointSet {}
impl Triangulable for SimplePolygon {}

mod sealed {
    use super::*;

    /// How the registry runs a criterion on an input kind (sealed: the two
    /// kinds above are the ones the criteria declare solvers for).
    pub trait Solve {
        /// Runs `criterion`'s solver for this kind (options checked).
        fn solve(&self, criterion: Criterion, options: &Options) -> Result<Solution>;
    }

    impl Solve for PointSet {
        fn solve(&self, criterion: Criterion, options: &Options) -> Result<Solution> {
            let entry = criterion.entry();
            check_options(criterion.name(), entry.info.options, options)?;
            check_elevations(criterion, self)?;
            run(criterion, options, |options, phases| {
                (entry.solve)(self, options, phases)
            })
        }
    }

    impl Solve for SimplePolygon {
        fn solve(&self, criterion: Criterion, options: &Options) -> Result<Solution> {
            let entry = criterion.entry();
            let solve = entry.solve_polygon.ok_or_else(|| Error::Unsupported {
                criterion: criterion.name(),
                reason: UnsupportedReason::NoPolygonInput {
                    accepted_by: Criterion::ALL
                        .iter()
                        .filter(|c| c.accepts(InputKind::SimplePolygon))
                        .map(|c| c.name())
                        .collect(),
                },
            })?;
            // No criterion reads a metric on polygons yet.
            check_options(criterion.name(), &[], options)?;
            check_elevations(criterion, self.point_set())?;
            run(criterion, options, |options, phases| {
                solve(self, options, phases)
            })
        }
    }
}

/// Refuses an input without elevations for a criterion that reads them.
fn check_elevations(criterion: Criterion, points: &PointSet) -> Result<()> {
    if criterion.info().needs_elevations && points.elevations().is_none() {
        return Err(Error::Unsupported {
            criterion: criterion.name(),
            reason: UnsupportedReason::NeedsElevations,
        });
    }
    Ok(())
}

/// Triangulates `input` (a [`PointSet`] or a [`SimplePolygon`]) by
/// `criterion` with default [`Options`].
///
/// ```
/// use optri::{triangulate, Criterion, SimplePolygon};
/// // An L-shape, listed clockwise: the chord 2-4 leaves the polygon.
/// let l = SimplePolygon::new(&[[0.0, 0.0], [0.0, 2.0], [1.0, 2.0], [1.0, 1.0], [2.0, 1.0], [2.0, 0.0]])?;
/// assert!(!l.is_diagonal(2, 4) && l.is_diagonal(0, 3) && l.is_diagonal(1, 3));
/// let solution = triangulate(&l, Criterion::MinMaxArea)?;
/// solution.triangulation.validate()?;
/// assert_eq!(solution.triangulation.triangles().len(), 4);
/// # Ok::<(), optri::Error>(())
/// ```
pub fn triangulate<T: Triangulable>(input: &T, criterion: Criterion) -> Result<Solution> {
    triangulate_with(input, criterion, &Options::default())
}

/// Triangulates `input` by `criterion` with `options`.
///
/// # Errors
/// [`Error::Unsupported`] when the criterion cannot handle the input (a
/// polygon for a criterion without a polygon solver:
/// [`UnsupportedReason::NoPolygonInput`], see [`Criterion::accepts`]; an
/// input too large for it) or does not read an option that is set (see
/// [`CriterionInfo::options`]); [`Error::Interrupted`] when the run is
/// cancelled or out of time and the criterion has no certified partial
/// result; [`Error::Internal`] on a bug.
pub fn triangulate_with<T: Triangulable>(
    input: &T,
    criterion: Criterion,
    options: &Options,
) -> Result<Solution> {
    input.solve(criterion, options)
}

/// Runs one solver with `options` started now: the progress hook hears the
/// start and the end, and the run stops if it is cancelled or out of time
/// before it starts or when it ends (the solvers check inside too).
fn run(
    criterion: Criterion,
    options: &Options,
    solve: impl FnOnce(&Options, &mut Vec<Phase>) -> Result<Solved>,
) -> Result<Solution> {
    let options = options.started();
    options.stop().check()?;
    let mut phases = Vec::new();
    options.report(criterion.name(), 0.0);
    let solved = solve(&options, &mut phases)?;
    options.report(criterion.name(), 1.0);
    Ok(Solution::from_solved(criterion, solved, phases, &options))
}

/// The result of one criterion in [`compare`]: its solution, or the error
/// with which it refused the input (e.g. [`Error::Unsupported`] for a
/// criterion that takes no metric).
pub type Comparison = (Criterion, Result<Solution>);

/// Triangulates `input` by each of `criteria`, in the order given, or by
/// every criterion of [`Criterion::ALL`] when `criteria` is empty. A
/// criterion that refuses the input is reported with its error and does not
/// stop the others, so a front end can show what each criterion says about
/// one input side by side (`optri compare`, the web playground, Python).
///
/// ```
/// use optri::{compare, Criterion, Options, PointSet};
/// let points = PointSet::new(&[[0.0, 0.0], [4.0, 0.0], [0.0, 3.0], [4.0, 3.0], [2.0, 1.0]])?
///     .with_elevations(&[0.0, 1.0, 2.0, 1.0, 3.0])?; // for minmax-slope
/// let results = compare(&points, &[], &Options::default());
/// assert_eq!(results.len(), Criterion::ALL.len());
/// assert!(results.iter().all(|(_, r)| r.is_ok()));
/// // Under L1 only minmax-length applies; the others refuse the metric.
/// let l1 = Options::default().with_metric(optri::kernel::Metric::l1());
/// let results = compare(&points, &[Criterion::MinMaxLength, Criterion::Delaunay], &l1);
/// assert!(results[0].1.is_ok() && results[1].1.is_err());
/// # Ok::<(), optri::Error>(())
/// ```
pub fn compare<T: Triangulable>(
    input: &T,
    criteria: &[Criterion],
    options: &Options,
) -> Vec<Comparison> {
    chosen(criteria)
        .iter()
        .map(|&c| (c, triangulate_with(input, c, options)))
        .collect()
}

/// `criteria`, or every criterion when it is empty.
fn chosen(criteria: &[Criterion]) -> &[Criterion] {
    if criteria.is_empty() {
        Criterion::ALL
    } else {
        criteria
    }
}

impl Solution {
    pub(crate) fn from_solved(
        criterion: Criterion,
        solved: Solved,
        phases: Vec<crate::timing::Phase>,
        options: &Options,
    ) -> Self {
        Solution {
            criterion,
            exact: solved.optimality.is_exact(),
            optimality: solved.optimality,
            algorithm: short_algorithm(&solved.algorithm).to_string(),
            algorithm_detail: solved.algorithm,
            triangulation: solved.triangulation,
            phases,
            diagnostics: solved.diagnostics,
            bound: solved.bound,
            metric: options.metric.clone(),
            approximation: solved.approximation,
        }
    }
}

/// The short name of an algorithm description: the criteria write
/// `"name: details"`, `"name (details)"`, `"name; details"` or
/// `"name, details"`, and the name is what comes before the first of those
/// separators.
fn short_algorithm(detail: &str) -> &str {
    let end = [": ", " (", "; ", ", "]
        .iter()
        .filter_map(|sep| detail.find(sep))
        .min()
        .unwrap_or(detail.len());
    &detail[..end]
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

    /// The names of the options the graph reads (of
    /// [`crate::OPTIONS`]): `metric` for the RNG and the MST, which are
    /// defined by length comparisons alone, and for the hull, which is the
    /// same under every norm (convexity does not depend on one).
    pub fn options(self) -> &'static [&'static str] {
        match self {
            GraphKind::Hull | GraphKind::Rng | GraphKind::Mst => &["metric"],
            GraphKind::Delaunay | GraphKind::Gabriel => &[],
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

/// A proximity graph of points that need not form a [`PointSet`]
/// ([`graph`]).
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct PointGraph {
    /// The edges, as input-index pairs (see [`GraphKind`]).
    pub edges: Vec<[u32; 2]>,
    /// The timed phase.
    pub phases: Vec<Phase>,
    /// The number of distinct points.
    pub distinct: usize,
    /// Every merged duplicate as `[dropped, kept]` input indices.
    pub duplicates: Vec<[u32; 2]>,
}

/// The proximity graph `kind` of `points` (any points with at least two
/// distinct ones) with `options` (e.g. a metric: the RNG and the MST take
/// any [`crate::kernel::Metric`], with sector candidates and exact lunes;
/// the other graphs are Euclidean notions and refuse a non-Euclidean metric
/// with [`UnsupportedReason::MetricNotSupported`]). Edges are input-index
/// pairs (see [`GraphKind`] for the edge convention); duplicates are merged
/// and reported.
///
/// Two distinct points, or points all on one line, give the path through
/// them in their order along the line, for every kind. That path is the
/// minimum spanning tree, the RNG and the Gabriel graph (consecutive points
/// have empty lunes and diametral disks; any other pair has a point between
/// them), under every norm too (for `a, b, c` in order on a line,
/// `‖c − a‖ = ‖b − a‖ + ‖c − b‖` puts `b` strictly inside the lune of
/// `ac`); it is the hull (a segment, every point on it a boundary point,
/// listed from the lexicographically smallest end); and it is the Delaunay
/// graph, the dual of the Voronoi diagram, whose cells are parallel strips
/// of which only consecutive ones share an edge. Edges are sorted
/// `[min, max]` input-index pairs, the hull's in path order.
///
/// ```
/// use optri::{graph, GraphKind, Options};
/// let points = [[0.0, 0.0], [4.0, 0.0], [0.0, 3.0], [4.0, 3.0], [2.0, 1.0]];
/// let mst = graph(&points, GraphKind::Mst, &Options::default())?;
/// assert_eq!(mst.edges.len(), 4);
/// # Ok::<(), optri::Error>(())
/// ```
///
/// # Errors
/// The coordinate errors of [`PointSet::new`]; [`Error::TooFewPointsForGraph`]
/// for fewer than two distinct points; [`Error::Unsupported`] for a metric
/// the kind does not take; [`Error::Interrupted`] when cancelled.
pub fn graph(
    points: &[crate::kernel::Point],
    kind: GraphKind,
    options: &Options,
) -> Result<PointGraph> {
    check_options(kind.name(), kind.options(), options)?;
    match PointSet::new(points) {
        Ok(point_set) => {
            let (edges, phases) = graph_of_point_set(&point_set, kind, options)?;
            Ok(PointGraph {
                edges,
                phases,
                distinct: point_set.len(),
                duplicates: point_set.duplicates().to_vec(),
            })
        }
        Err(Error::TooFewPoints { distinct } | Error::AllCollinear { distinct })
            if distinct >= 2 =>
        {
            let mut phases = Vec::new();
            let (path, duplicates) = timed(&mut phases, kind.name(), || collinear_path(points));
            let distinct = path.len();
            let mut edges: Vec<[u32; 2]> = path.windows(2).map(|w| [w[0], w[1]]).collect();
            if kind != GraphKind::Hull {
                edges.iter_mut().for_each(|e| e.sort_unstable());
                edges.sort_unstable();
            }
            Ok(PointGraph {
                edges,
                phases,
                distinct,
                duplicates,
            })
        }
        Err(Error::TooFewPoints { distinct } | Error::AllCollinear { distinct }) => {
            Err(Error::TooFewPointsForGraph { distinct })
        }
        Err(e) => Err(e),
    }
}

/// The distinct points of collinear `points` (input indices of first
/// occurrences) in lexicographic order, which is their order along the line
/// (comparisons of doubles are exact), and the merged duplicates.
fn collinear_path(points: &[crate::kernel::Point]) -> (Vec<u32>, Vec<[u32; 2]>) {
    let mut seen = std::collections::HashMap::with_capacity(points.len());
    let mut duplicates = Vec::new();
    let mut distinct = Vec::new();
    for (i, p) in points.iter().enumerate() {
        // -0.0 and 0.0 are the same point, as in `PointSet`.
        let key = [(p[0] + 0.0).to_bits(), (p[1] + 0.0).to_bits()];
        match seen.get(&key) {
            Some(&kept) => duplicates.push([i as u32, kept]),
            None => {
                seen.insert(key, i as u32);
                distinct.push(i as u32);
            }
        }
    }
    distinct.sort_by(|&a, &b| {
        let (p, q) = (points[a as usize], points[b as usize]);
        p[0].total_cmp(&q[0]).then(p[1].total_cmp(&q[1]))
    });
    (distinct, duplicates)
}

/// The graph `kind` of a point set: its edges as input-index pairs and the
/// timed phase (see [`graph`]).
pub(crate) fn graph_of_point_set(
    points: &PointSet,
    kind: GraphKind,
    options: &Options,
) -> Result<(Vec<[u32; 2]>, Vec<Phase>)> {
    check_options(kind.name(), kind.options(), options)?;
    options.started().stop().check()?;
    let metric = &options.metric;
    if !metric.is_euclidean() && kind != GraphKind::Hull {
        let mut phases = Vec::new();
        let edges = timed(&mut phases, kind.name(), || match kind {
            GraphKind::Rng => graphs::relative_neighborhood_graph_under(points, metric),
            GraphKind::Mst => graphs::minimum_spanning_tree_under(points, metric),
            _ => Err(Error::Internal(format!("{} takes no metric", kind.name()))),
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
    fn algorithm_names_are_short_and_the_details_kept() {
        assert_eq!(short_algorithm("general (exact rounds)"), "general");
        assert_eq!(
            short_algorithm("Vassilev Algorithm 75: optimal"),
            "Vassilev Algorithm 75"
        );
        assert_eq!(short_algorithm("Klincsek, O(n^3); up to"), "Klincsek");
        assert_eq!(short_algorithm("plain"), "plain");
        let points = PointSet::new(&[[0.0, 0.0], [3.0, 0.0], [0.0, 3.0], [1.0, 1.0]]).unwrap();
        for &criterion in Criterion::ALL {
            let Ok(s) = triangulate(&points, criterion) else {
                continue;
            };
            assert!(s.algorithm.len() <= 40, "{criterion:?}: {}", s.algorithm);
            assert!(s.algorithm_detail.starts_with(&s.algorithm));
        }
    }

    #[test]
    fn the_progress_hook_hears_the_run_start_and_end() {
        use std::sync::{Arc, Mutex};
        let heard = Arc::new(Mutex::new(Vec::new()));
        let log = Arc::clone(&heard);
        let options = Options::default().with_progress(crate::criteria::Progress::new(
            move |phase, fraction| log.lock().unwrap().push((phase.to_string(), fraction)),
        ));
        let points = PointSet::new(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]]).unwrap();
        triangulate_with(&points, Criterion::Greedy, &options).unwrap();
        assert_eq!(
            *heard.lock().unwrap(),
            [("greedy".to_string(), 0.0), ("greedy".to_string(), 1.0)]
        );
        assert_eq!(options.clone(), options);
        assert_ne!(options, Options::default());
    }

    #[test]
    fn graphs_of_two_and_of_collinear_points_are_the_path() {
        // Input order scrambled along the line y = 2x, with a duplicate.
        let line = [[2.0, 4.0], [0.0, 0.0], [3.0, 6.0], [1.0, 2.0], [0.0, 0.0]];
        for &kind in GraphKind::ALL {
            let g = graph(&line, kind, &Options::default()).unwrap();
            assert_eq!(g.distinct, 4);
            assert_eq!(g.duplicates, [[4, 1]]);
            let expected: &[[u32; 2]] = if kind == GraphKind::Hull {
                &[[1, 3], [3, 0], [0, 2]]
            } else {
                &[[0, 2], [0, 3], [1, 3]]
            };
            assert_eq!(g.edges, expected, "{kind:?}");
        }
        let two = graph(
            &[[5.0, 1.0], [-1.0, 1.0]],
            GraphKind::Mst,
            &Options::default(),
        )
        .unwrap();
        assert_eq!(two.edges, [[0, 1]]);
        assert_eq!(
            graph(
                &[[1.0, 1.0], [1.0, 1.0]],
                GraphKind::Rng,
                &Options::default()
            )
            .unwrap_err(),
            Error::TooFewPointsForGraph { distinct: 1 }
        );
        // Not collinear: the ordinary graphs.
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let g = graph(&square, GraphKind::Mst, &Options::default()).unwrap();
        assert_eq!(
            g.edges,
            graph_of_point_set(
                &PointSet::new(&square).unwrap(),
                GraphKind::Mst,
                &Options::default()
            )
            .unwrap()
            .0
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

    #[test]
    fn compare_runs_every_criterion_or_the_chosen_ones_in_order() {
        // A square with its centre: min-weight and the convex-only area
        // criteria may refuse it, but every criterion is reported.
        let points =
            PointSet::new(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, 0.7]]).unwrap();
        let all = compare(&points, &[], &Options::default());
        let names: Vec<Criterion> = all.iter().map(|(c, _)| *c).collect();
        assert_eq!(names, Criterion::ALL);
        for (c, r) in &all {
            match r {
                Ok(s) => {
                    assert_eq!(s.criterion, *c);
                    s.triangulation.validate().unwrap();
                }
                Err(e) => assert!(matches!(e, Error::Unsupported { .. }), "{c:?}: {e}"),
            }
        }
        assert!(all[0].1.is_ok(), "Delaunay accepts every point set");
        let two = compare(
            &points,
            &[Criterion::Greedy, Criterion::Delaunay],
            &Options::default(),
        );
        assert_eq!(two.len(), 2);
        assert_eq!(
            (two[0].0, two[1].0),
            (Criterion::Greedy, Criterion::Delaunay)
        );
        let polygon =
            SimplePolygon::new(&[[0.0, 0.0], [2.0, 0.0], [1.0, 1.0], [2.0, 2.0], [0.0, 2.0]])
                .unwrap()
                .with_elevations(&[0.0, 1.0, 2.0, 1.0, 0.0]) // for minmax-slope
                .unwrap();
        for (c, r) in compare(&polygon, &[], &Options::default()) {
            let s = r.unwrap_or_else(|e| panic!("{c:?}: {e}"));
            assert_eq!(s.triangulation.triangles().len(), 3);
        }
    }
}
