//! Layer 5: one module per optimality criterion, named after it. Each
//! module owns everything about its criterion — the algorithm, its
//! [`CriterionInfo`] (name, description, [`Optimality`], [`Requirement`],
//! citation) and a `solve` entry point with one signature — so that the
//! registry ([`crate::Criterion`]) only lists them.
//!
//! | criterion | module | paper |
//! |---|---|---|
//! | `delaunay` | `delaunay` | Delaunay 1934; via spade |
//! | `minmax-length` | `minmax_length` | Edelsbrunner & Tan 1991 |
//! | `greedy` | `greedy` | Levcopoulos & Lingas 1987; Dickerson et al. 1997 |
//! | `min-weight` | `min_weight` | Klincsek 1980 |
//! | `maxmin-area`, `minmax-area` | `area` | Vassilev 2005 |
//!
//! Simple polygons ([`crate::triangulate_polygon`]): every criterion has a
//! [`PolygonSolver`] in its own module; the decomposable ones run the shared
//! polygon program on the polygon ([`crate::polygon_program`]).

pub(crate) mod area;
pub(crate) mod delaunay;
pub(crate) mod greedy;
pub(crate) mod min_weight;
pub(crate) mod minmax_length;

use crate::error::Result;
use crate::structures::{PointSet, SimplePolygon, Triangulation};
use crate::timing::Phase;

/// How good a criterion's answer is guaranteed to be.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Optimality {
    /// Provably optimal: every decision was made exactly.
    Exact,
    /// Optimal up to floating-point rounding of sums (e.g. of edge lengths):
    /// when two candidates agree to within rounding either may be returned.
    UpToRounding,
    /// An approximation; `bound` states the proven guarantee in words.
    Approximation {
        /// The guarantee, e.g. `"within a factor 2 of the optimum"`.
        bound: &'static str,
    },
}

impl Optimality {
    /// `"exact"`, `"up-to-rounding"` or `"approximation"`.
    pub fn name(self) -> &'static str {
        match self {
            Optimality::Exact => "exact",
            Optimality::UpToRounding => "up-to-rounding",
            Optimality::Approximation { .. } => "approximation",
        }
    }

    /// Is the result provably optimal?
    pub fn is_exact(self) -> bool {
        self == Optimality::Exact
    }
}

/// What a criterion needs of its input.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Requirement {
    /// Any point set with three points not on one line.
    AnyPointSet,
    /// Every point on the convex hull (collinear boundary points allowed).
    ConvexPosition,
}

/// Everything a front end needs to list and explain a criterion.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct CriterionInfo {
    /// The registry name, e.g. `"minmax-length"`.
    pub name: &'static str,
    /// One line saying what is optimised.
    pub description: &'static str,
    /// The guarantee of the result on the inputs the criterion accepts.
    pub optimality: Optimality,
    /// What the input must satisfy.
    pub requirement: Requirement,
    /// Names of the [`Options`] fields the criterion reads (none yet).
    pub options: &'static [&'static str],
    /// The paper the algorithm follows: authors, year, title.
    pub reference: &'static str,
}

/// Options of a criterion run. `#[non_exhaustive]`: build it with
/// `Options::default()` and the `with_*` methods.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct Options {
    /// Called as the run goes (see [`Progress`]); `None`: nothing is called.
    pub progress: Option<Progress>,
    /// The norm lengths are measured in (Euclidean by default). Read by
    /// `minmax-length` (and by [`crate::graph_with`] for the RNG and MST);
    /// every other criterion refuses a non-Euclidean metric with [`crate::UnsupportedReason::MetricNotSupported`].
    pub metric: crate::kernel::Metric,
}

impl Options {
    /// These options with `progress` called as the run goes.
    pub fn with_progress(mut self, progress: Progress) -> Self {
        self.progress = Some(progress);
        self
    }

    /// These options with lengths measured in `metric`.
    pub fn with_metric(mut self, metric: crate::kernel::Metric) -> Self {
        self.metric = metric;
        self
    }

    /// Reports `fraction` (0 to 1) of the phase `phase` to the progress
    /// hook, if there is one.
    pub(crate) fn report(&self, phase: &str, fraction: f64) {
        if let Some(progress) = &self.progress {
            (progress.0)(phase, fraction);
        }
    }
}

/// A progress hook: called with a phase name and the fraction of it done
/// (`0.0` when it starts, `1.0` when it ends), from the thread that runs the
/// criterion. It is part of the [`Options`] of one run (no global state), so
/// a front end can draw a progress bar without the library depending on
/// one. Two hooks are equal only if they are the same closure.
#[derive(Clone)]
pub struct Progress(std::sync::Arc<ProgressFn>);

/// What a [`Progress`] hook calls: `(phase, fraction)`.
type ProgressFn = dyn Fn(&str, f64) + Send + Sync;

impl Progress {
    /// A hook calling `f(phase, fraction)`.
    pub fn new(f: impl Fn(&str, f64) + Send + Sync + 'static) -> Self {
        Self(std::sync::Arc::new(f))
    }
}

impl std::fmt::Debug for Progress {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Progress(..)")
    }
}

impl PartialEq for Progress {
    fn eq(&self, other: &Self) -> bool {
        std::sync::Arc::ptr_eq(&self.0, &other.0)
    }
}

impl Eq for Progress {}

/// Named counters a run reports, e.g. how many regions each method solved.
/// They are part of the result (never global state), so concurrent runs do
/// not mix and tests can assert on them.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Diagnostics {
    counters: Vec<(&'static str, u64)>,
}

impl Diagnostics {
    /// The counter `name`, or `None` if this run did not report it.
    pub fn get(&self, name: &str) -> Option<u64> {
        self.counters
            .iter()
            .find(|(n, _)| *n == name)
            .map(|&(_, v)| v)
    }

    /// All counters in the order the algorithm reported them.
    pub fn iter(&self) -> impl Iterator<Item = (&'static str, u64)> + '_ {
        self.counters.iter().copied()
    }

    /// Is there no counter?
    pub fn is_empty(&self) -> bool {
        self.counters.is_empty()
    }

    /// Adds `value` to the counter `name` (creating it).
    pub(crate) fn add(&mut self, name: &'static str, value: u64) {
        match self.counters.iter_mut().find(|(n, _)| *n == name) {
            Some((_, v)) => *v += value,
            None => self.counters.push((name, value)),
        }
    }
}

/// A certified bound on the optimal value of a criterion whose result is
/// not proven optimal: the optimum is no better than `value` — a
/// triangle's area (area criteria) or a total edge length (min-weight).
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct CertifiedBound {
    /// What `value` measures.
    pub measure: BoundMeasure,
    /// Area bounds: the triangle (input indices) whose area is the bound.
    pub triangle: Option<[u32; 3]>,
    /// The bound, rounded for reporting in the safe direction where it is
    /// a sum (a lower bound rounded down); decided exactly.
    pub value: f64,
    /// `true`: no triangulation does better than `value` from above (a
    /// MaxMin criterion's optimum is at most `value`); `false`: from below.
    pub upper: bool,
}

/// What a [`CertifiedBound`]'s value measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum BoundMeasure {
    /// A triangle's area (MaxMin / MinMax area).
    Area,
    /// A total edge length (min-weight: the optimal weight is at least it).
    TotalLength,
}

/// What a criterion's `solve` returns to the registry.
pub(crate) struct Solved {
    pub triangulation: Triangulation,
    /// The algorithm that ran, in words (it may depend on the input).
    pub algorithm: String,
    pub optimality: Optimality,
    pub diagnostics: Diagnostics,
    /// For results that are not proven optimal: how far off they can be.
    pub bound: Option<CertifiedBound>,
}

/// The one signature of every criterion's entry point.
pub(crate) type Solver = fn(&PointSet, &Options, &mut Vec<Phase>) -> Result<Solved>;

/// The one signature of every criterion's entry point for a simple polygon
/// (its triangulation's domain is the polygon, its indices ring positions).
pub(crate) type PolygonSolver = fn(&SimplePolygon, &Options, &mut Vec<Phase>) -> Result<Solved>;
