//! Layer 5: one module per optimality criterion, named after it. Each
//! module owns everything about its criterion — the algorithm, and its
//! `ENTRY` ([`CriterionEntry`]: the [`CriterionInfo`] with name,
//! description, [`Optimality`], the options it reads and its citation, and
//! its solvers for point sets and polygons, one signature each) — so that
//! the registry ([`crate::Criterion`]) only lists them.
//!
//! | criterion | module | paper |
//! |---|---|---|
//! | `delaunay` | `delaunay` | Delaunay 1934; via spade |
//! | `minmax-length` | `minmax_length` | Edelsbrunner & Tan 1991 |
//! | `greedy` | `greedy` | Levcopoulos & Lingas 1987; Dickerson et al. 1997 |
//! | `min-weight` | `min_weight` | Dickerson et al. 1997 (LMT-skeleton); Klincsek 1980 |
//! | `maxmin-area`, `minmax-area` | `area` | Vassilev 2005 |
//! | `minmax-angle`, `maxmin-height`, `minmax-eccentricity`, `minmax-slope` | `edge_insertion` | Bern, Edelsbrunner, Eppstein, Mitchell & Tan 1993 |
//! | `minmax-delta-area`, `minmax-delta-angle`, `minmax-delta-length` | `delta` | Vassilev 2005 (Table 1.1) |
//!
//! Simple polygons ([`crate::triangulate`]): every criterion has a
//! [`PolygonSolver`] in its own module; the decomposable ones run the shared
//! polygon program on the polygon ([`crate::polygon_program`]).

pub(crate) mod area;
pub(crate) mod delaunay;
pub(crate) mod delta;
pub(crate) mod edge_insertion;
pub(crate) mod greedy;
pub(crate) mod min_weight;
pub(crate) mod minmax_length;

use crate::error::Result;
use crate::structures::{Measure, PointSet, SimplePolygon, Triangulation};
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

    /// The guarantee in words: the approximation's `bound`, or what
    /// "exact" and "up-to-rounding" promise.
    pub fn statement(self) -> &'static str {
        match self {
            Optimality::Exact => "provably optimal on every input it accepts",
            Optimality::UpToRounding => "optimal up to floating-point rounding of sums",
            Optimality::Approximation { bound } => bound,
        }
    }

    /// Is the result provably optimal?
    pub fn is_exact(self) -> bool {
        self == Optimality::Exact
    }
}

/// A kind of input a criterion triangulates.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum InputKind {
    /// A point set: its convex hull is triangulated ([`crate::PointSet`]).
    PointSet,
    /// A simple polygon: its interior is triangulated
    /// ([`crate::SimplePolygon`]).
    SimplePolygon,
}

impl InputKind {
    /// Every input kind.
    pub const ALL: &'static [InputKind] = &[InputKind::PointSet, InputKind::SimplePolygon];

    /// `"points"` or `"polygon"`, as the registry listing names it.
    pub fn name(self) -> &'static str {
        match self {
            InputKind::PointSet => "points",
            InputKind::SimplePolygon => "polygon",
        }
    }
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
    /// Names of the options (of [`OPTIONS`]) the criterion reads, beyond
    /// the run controls every criterion takes; any other option set to a
    /// value other than its default is refused.
    pub options: &'static [&'static str],
    /// The paper the algorithm follows: authors, year, title.
    pub reference: &'static str,
    /// Does it read an elevation per point
    /// ([`crate::PointSet::with_elevations`])? An input without them is
    /// refused with [`crate::UnsupportedReason::NeedsElevations`].
    pub needs_elevations: bool,
    /// The quality measure whose worst value the criterion optimises, when
    /// it is one of [`Measure`] (a picture highlights its worst triangle);
    /// `None` for greedy and the δ-criteria.
    pub measure: Option<Measure>,
}

/// What a criterion module provides to the registry: its description and
/// its solvers. Each criterion declares one `ENTRY`; the registry lists them
/// and reads nothing else.
pub(crate) struct CriterionEntry {
    pub info: CriterionInfo,
    /// The solver for point sets.
    pub solve: Solver,
    /// The solver for simple polygons, if the criterion takes them.
    pub solve_polygon: Option<PolygonSolver>,
}

/// An option a front end can set by name ([`Options::set`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct OptionInfo {
    /// The name, e.g. `"metric"`.
    pub name: &'static str,
    /// One line saying what it does.
    pub description: &'static str,
    /// The values it takes, in the text syntax of [`Options::set`].
    pub values: &'static str,
    /// The value when it is not set.
    pub default: &'static str,
    /// `true`: a run control every criterion and graph takes; `false`: taken
    /// only by those that list it ([`CriterionInfo::options`],
    /// [`crate::GraphKind::options`]).
    pub every_run: bool,
}

/// Every option a front end can set by name, in display order.
pub const OPTIONS: &[OptionInfo] = &[
    OptionInfo {
        name: "metric",
        description: "the norm lengths are measured in",
        values: "euclidean | l1 | linf | lp:P (integer 1 <= P <= 64) | polygon:x1,y1,x2,y2,... \
                 (a centrally symmetric convex unit polygon, counter-clockwise)",
        default: "euclidean",
        every_run: false,
    },
    OptionInfo {
        name: "alpha",
        description: "area criteria on general point sets: every angle of the result at least \
                      this many degrees (Vassilev's α-triangulations); at most the Delaunay \
                      triangulation's smallest angle",
        values: "a number of degrees, 0 or in [0.000000001, 90)",
        default: "none",
        every_run: false,
    },
    OptionInfo {
        name: "approximation",
        description: "area criteria on general point sets: which approximation answers",
        values: "thesis-75 | thesis-76 | rng-hull | best",
        default: "best",
        every_run: false,
    },
    OptionInfo {
        name: "time_limit",
        description: "seconds a run may take; past it the run stops, or returns its best \
                      certified result with exact: false where the criterion has one",
        values: "a positive number of seconds",
        default: "none",
        every_run: true,
    },
];

/// Options of a criterion run. `#[non_exhaustive]`: build it with
/// `Options::default()` and the `with_*` methods, or by name with
/// [`Options::set`].
#[derive(Clone, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct Options {
    /// Called as the run goes (see [`Progress`]); `None`: nothing is called.
    pub progress: Option<Progress>,
    /// The norm lengths are measured in (Euclidean by default). Read by the
    /// criteria and graphs that list `metric` in their options; the others
    /// refuse a non-Euclidean metric with
    /// [`crate::UnsupportedReason::MetricNotSupported`].
    pub metric: crate::kernel::Metric,
    /// How long one run may take (`None`: no limit). Past it the run returns
    /// [`crate::Error::Interrupted`], or its best certified result with
    /// `exact: false` where the criterion has one. In a comparison each
    /// criterion has the whole limit.
    pub time_limit: Option<std::time::Duration>,
    /// A flag that stops the run when raised (see [`crate::Cancel`]).
    pub cancel: Option<crate::Cancel>,
    /// The angle floor α of the area criteria on general point sets: every
    /// angle of the result at least α (`None`: no floor; Algorithm 76 then
    /// keeps the Delaunay triangulation's smallest angle α*).
    pub alpha: Option<crate::kernel::AngleFloor>,
    /// Which approximation answers the area criteria on general point sets.
    pub approximation: AreaApproximation,
    /// The stop of a started run: `time_limit` counted from its start.
    stop: crate::interrupt::Stop,
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

    /// These options with the angle floor `alpha` (the `alpha` option).
    pub fn with_alpha(mut self, alpha: crate::kernel::AngleFloor) -> Self {
        self.alpha = Some(alpha);
        self
    }

    /// These options with the area approximation `approximation`.
    pub fn with_approximation(mut self, approximation: AreaApproximation) -> Self {
        self.approximation = approximation;
        self
    }

    /// These options with a time limit per run.
    pub fn with_time_limit(mut self, limit: std::time::Duration) -> Self {
        self.time_limit = Some(limit);
        self
    }

    /// These options stopped when `cancel` is raised.
    pub fn with_cancel(mut self, cancel: crate::Cancel) -> Self {
        self.cancel = Some(cancel);
        self
    }

    /// Sets the option `name` (one of [`OPTIONS`]) from its text form, as
    /// every front end takes it: `metric` in [`crate::kernel::Metric::parse`]'s
    /// syntax, `alpha` in degrees, `approximation` by
    /// [`AreaApproximation::name`], `time_limit` in seconds.
    ///
    /// # Errors
    /// [`Error::UnknownName`](crate::Error::UnknownName) for an unknown
    /// option; [`Error::InvalidMetric`](crate::Error::InvalidMetric) or
    /// [`Error::InvalidOption`](crate::Error::InvalidOption) for a value it
    /// cannot take.
    pub fn set(&mut self, name: &str, value: &str) -> crate::Result<()> {
        let Some(option) = OPTIONS.iter().find(|o| o.name == name) else {
            return Err(crate::Error::UnknownName {
                kind: "option",
                name: name.to_string(),
                available: OPTIONS.iter().map(|o| o.name).collect(),
            });
        };
        match option.name {
            "metric" => {
                self.metric =
                    crate::kernel::Metric::parse(value).map_err(crate::Error::InvalidMetric)?
            }
            "alpha" => {
                let degrees: f64 = value.trim().parse().unwrap_or(f64::NAN);
                let floor = crate::kernel::AngleFloor::new(degrees).ok_or_else(|| {
                    crate::Error::InvalidOption {
                        option: "alpha",
                        message: format!(
                            "'{}' is not a number of degrees, 0 or in [{}, 90)",
                            shown(value),
                            crate::kernel::MIN_ANGLE_FLOOR_DEGREES
                        ),
                    }
                })?;
                self.alpha = Some(floor);
            }
            "approximation" => {
                self.approximation = AreaApproximation::ALL
                    .iter()
                    .copied()
                    .find(|a| a.name() == value.trim())
                    .ok_or_else(|| crate::Error::UnknownName {
                        kind: "approximation",
                        name: value.to_string(),
                        available: AreaApproximation::ALL.iter().map(|a| a.name()).collect(),
                    })?;
            }
            "time_limit" => {
                let seconds: f64 = value.trim().parse().map_err(|_| invalid_time(value))?;
                if seconds.is_nan() || seconds <= 0.0 {
                    return Err(invalid_time(value));
                }
                let limit = std::time::Duration::try_from_secs_f64(seconds)
                    .map_err(|_| invalid_time(value))?;
                self.time_limit = Some(limit);
            }
            other => unreachable!("option {other} has no decoder"),
        }
        Ok(())
    }

    /// The names of the options whose value differs from the default,
    /// run controls excluded.
    pub(crate) fn chosen(&self) -> Vec<&'static str> {
        let mut chosen = Vec::new();
        if !self.metric.is_euclidean() {
            chosen.push("metric");
        }
        if self.alpha.is_some() {
            chosen.push("alpha");
        }
        if self.approximation != AreaApproximation::default() {
            chosen.push("approximation");
        }
        chosen
    }

    /// These options for a run that starts now: its time limit counts
    /// from here.
    pub(crate) fn started(&self) -> Options {
        let mut started = self.clone();
        started.stop = crate::interrupt::Stop::starting_now(self.cancel.clone(), self.time_limit);
        started
    }

    /// When the run must stop (never, unless the options were
    /// [`started`](Self::started) with a limit or a cancellation flag).
    pub(crate) fn stop(&self) -> &crate::interrupt::Stop {
        &self.stop
    }

    /// Reports `fraction` (0 to 1) of the phase `phase` to the progress
    /// hook, if there is one.
    pub(crate) fn report(&self, phase: &str, fraction: f64) {
        if let Some(progress) = &self.progress {
            (progress.0)(phase, fraction);
        }
    }
}

/// The message for a time limit that is not a positive number of seconds.
fn invalid_time(value: &str) -> crate::Error {
    crate::Error::InvalidOption {
        option: "time_limit",
        message: format!("'{}' is not a positive number of seconds", shown(value)),
    }
}

/// At most 40 characters of an option's value, escaped, for a message.
fn shown(value: &str) -> String {
    value
        .chars()
        .take(40)
        .flat_map(char::escape_default)
        .collect()
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

/// Which approximation answers `maxmin-area` and `minmax-area` on a point
/// set not in convex position (the `approximation` option; T. S. Vassilev,
/// *Optimal area triangulation*, 2005, §3.4).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum AreaApproximation {
    /// Algorithm 75: the Delaunay triangulation if its smallest angle α* is
    /// below 30°, else the optimal 30°-triangulation (with `alpha` above
    /// 30°, the optimal α-triangulation).
    Thesis75,
    /// Algorithm 76: area-equalising reverse-Delaunay flips that keep every
    /// angle at least `alpha` (α* without it): the area/angle compromise.
    Thesis76,
    /// The optimum over the triangulations containing the relative
    /// neighbourhood graph and the hull (only triangles with every angle at
    /// least `alpha` when it is set).
    RngHull,
    /// The best of Delaunay and the three above.
    #[default]
    Best,
}

impl AreaApproximation {
    /// Every approximation, in the order of the option's values.
    pub const ALL: &'static [AreaApproximation] = &[
        AreaApproximation::Thesis75,
        AreaApproximation::Thesis76,
        AreaApproximation::RngHull,
        AreaApproximation::Best,
    ];

    /// `"thesis-75"`, `"thesis-76"`, `"rng-hull"` or `"best"`.
    pub fn name(self) -> &'static str {
        match self {
            AreaApproximation::Thesis75 => "thesis-75",
            AreaApproximation::Thesis76 => "thesis-76",
            AreaApproximation::RngHull => "rng-hull",
            AreaApproximation::Best => "best",
        }
    }
}

/// How a general-set area result was obtained and what is proven about it
/// ([`crate::Solution::approximation`]).
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct ApproximationReport {
    /// The approximation asked for.
    pub choice: AreaApproximation,
    /// The candidate returned (its short name is the solution's algorithm).
    pub candidate: &'static str,
    /// The candidates computed, in tie-breaking order.
    pub candidates: Vec<&'static str>,
    /// Candidates not computed, each with why (a face of `RNG ∪ hull`
    /// beyond the face programs' size cap).
    pub skipped: Vec<(&'static str, String)>,
    /// The Delaunay triangulation's smallest angle α* as a corner
    /// `[apex, a, b]` (input indices) ...
    pub delaunay_smallest_angle: [u32; 3],
    /// ... and in degrees, correctly rounded.
    pub delaunay_smallest_angle_degrees: f64,
    /// The angle floor α given (`alpha`), in degrees; `None`: Algorithm 76
    /// kept α* and the other candidates had no floor.
    pub alpha_degrees: Option<f64>,
    /// Flips made by Algorithm 76 (0 when it did not run).
    pub flips: usize,
    /// What is proven about the result.
    pub guarantee: Guarantee,
}

/// What the seeds prove about one result.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct Guarantee {
    /// `"optimal"` (the result attains the certified bound),
    /// `"optimal-among-alpha-triangulations"` (no triangulation whose angles
    /// are all at least `alpha_degrees` does better) or `"approximation"`.
    pub kind: &'static str,
    /// The floor of `"optimal-among-alpha-triangulations"`, in degrees.
    pub alpha_degrees: Option<f64>,
    /// The guarantee in words.
    pub statement: String,
    /// The result's smallest angle in degrees, correctly rounded.
    pub smallest_angle_degrees: f64,
    /// Theorem 81's approximation factor against an optimum of smallest
    /// angle β, as `[β, factor]` for sampled β (empty for an optimal
    /// result).
    pub theorem_81: Vec<[f64; 2]>,
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
    /// General-set area results: how they were obtained, their guarantee.
    pub approximation: Option<ApproximationReport>,
}

/// The one signature of every criterion's entry point.
pub(crate) type Solver = fn(&PointSet, &Options, &mut Vec<Phase>) -> Result<Solved>;

/// A convex polygon (straight runs allowed) by the criterion's point-set
/// `solver` on its vertices: its triangulations are exactly those of the
/// vertex set, and the point-set algorithms for convex position (greedy's
/// Theorem 4.2, Edelsbrunner–Tan for minmax length) are far faster than the
/// cubic polygon program. `None` for a polygon that is not convex.
pub(crate) fn solve_convex_polygon(
    polygon: &SimplePolygon,
    options: &Options,
    phases: &mut Vec<Phase>,
    solver: Solver,
) -> Option<Result<Solved>> {
    if !polygon.is_convex() {
        return None;
    }
    // The polygon's point set has no duplicates: its indices are ring
    // positions, as a polygon triangulation's are.
    Some(
        solver(polygon.point_set(), options, phases).map(|solved| Solved {
            triangulation: Triangulation::from_polygon_positions(
                polygon,
                solved.triangulation.triangles().to_vec(),
            ),
            algorithm: format!("convex polygon as its vertex set: {}", solved.algorithm),
            ..solved
        }),
    )
}

/// The one signature of every criterion's entry point for a simple polygon
/// (its triangulation's domain is the polygon, its indices ring positions).
pub(crate) type PolygonSolver = fn(&SimplePolygon, &Options, &mut Vec<Phase>) -> Result<Solved>;
