//! One request for every front end: an input as read, what to compute
//! (a criterion, a comparison, a graph or an area decision), options by name, and the run that
//! turns them into the one JSON document. The CLI, Python and the web API
//! all go through [`Request::run`], so they validate, time, refuse and
//! report alike.
//!
//! ```
//! use optri::io::{Input, ReadInput};
//! use optri::request::{Request, Task};
//! let read = ReadInput::from_doubles(Input::Points(vec![
//!     [0.0, 0.0], [4.0, 0.0], [0.0, 3.0], [4.0, 3.0], [2.0, 1.0],
//! ]));
//! let mut request = Request::new(read, Task::triangulate("minmax-length")?);
//! request.set_option("metric", "l1")?;
//! let outcome = request.run()?;
//! assert!(outcome.solution().unwrap().exact);
//! assert_eq!(outcome.to_json()["criterion"], "minmax-length");
//! # Ok::<(), optri::Error>(())
//! ```
//!
//! # Phases
//! A document's `timing_ms` lists the phases the front end timed before
//! the request ([`Request::after`], e.g. the CLI's `read`), `validate`, the
//! library's phases, whatever the front end adds ([`Outcome::add_phase`],
//! e.g. `write`), and `total` since the front end's start
//! ([`Outcome::finish`]).

use crate::criteria::area::{decide_area, AreaDecision, AreaQuestion};
use crate::criteria::{InputKind, Options, OPTIONS};
use crate::error::{Error, Result};
use crate::io::{
    ComparisonReport, DecisionReport, Document, GraphReport, Input, ReadInput, Threshold,
    TriangulationReport,
};
use crate::kernel::AreaThreshold;
use crate::registry::{
    compare, graph, triangulate_with, Comparison, Criterion, GraphKind, PointGraph, Solution,
};
use crate::structures::{PointSet, SimplePolygon};
use crate::timing::Phase;
use serde_json::Value;
use std::time::Instant;

/// What a [`Request`] computes.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Task {
    /// One criterion: a point set's hull, or a polygon's interior.
    Triangulate(Criterion),
    /// Several criteria side by side (every criterion when empty); a
    /// criterion that refuses the input is reported with its error.
    Compare(Vec<Criterion>),
    /// A proximity graph of the points (a polygon's vertices are taken as
    /// points); two points and collinear points are accepted.
    Graph(GraphKind),
    /// An area decision ([`crate::decide_area`]): is there a triangulation
    /// whose every triangle's area (not doubled, in the input's units) is at
    /// least (`maxmin-area`) or at most (`minmax-area`) the threshold?
    Decide {
        /// Which bound.
        question: AreaQuestion,
        /// The area, as the user wrote it.
        threshold: Threshold,
    },
}

impl Task {
    /// [`Task::Triangulate`] by criterion name (case-insensitive).
    ///
    /// # Errors
    /// [`Error::UnknownName`] listing the criteria.
    pub fn triangulate(criterion: &str) -> Result<Self> {
        Criterion::from_name(criterion).map(Task::Triangulate)
    }

    /// [`Task::Compare`] by criterion names (blank names are skipped; none:
    /// every criterion).
    ///
    /// # Errors
    /// [`Error::UnknownName`] for the first unknown name.
    pub fn compare<S: AsRef<str>>(criteria: &[S]) -> Result<Self> {
        criteria
            .iter()
            .map(|c| c.as_ref().trim())
            .filter(|c| !c.is_empty())
            .map(Criterion::from_name)
            .collect::<Result<Vec<_>>>()
            .map(Task::Compare)
    }

    /// [`Task::Graph`] by graph name (case-insensitive).
    ///
    /// # Errors
    /// [`Error::UnknownName`] listing the graph kinds.
    pub fn graph(kind: &str) -> Result<Self> {
        GraphKind::from_name(kind).map(Task::Graph)
    }

    /// [`Task::Decide`] for `criterion` (`maxmin-area` with `at_least`,
    /// `minmax-area` with `at_most`).
    ///
    /// # Errors
    /// [`Error::UnknownName`] for an unknown criterion;
    /// [`Error::InvalidOption`] for another criterion, both bounds or
    /// neither, or the bound the criterion does not take.
    pub fn decide(
        criterion: &str,
        at_least: Option<Threshold>,
        at_most: Option<Threshold>,
    ) -> Result<Self> {
        let criterion = Criterion::from_name(criterion)?;
        let invalid = |option, message: &str| Error::InvalidOption {
            option,
            message: message.to_string(),
        };
        let question = match criterion {
            Criterion::MaxMinArea => AreaQuestion::SmallestAtLeast,
            Criterion::MinMaxArea => AreaQuestion::LargestAtMost,
            other => {
                return Err(invalid(
                    "criterion",
                    &format!(
                        "{} has no decision; decide takes maxmin-area (with at_least) or \
                         minmax-area (with at_most)",
                        other.name()
                    ),
                ))
            }
        };
        match (question, at_least, at_most) {
            (_, Some(_), Some(_)) => Err(invalid(
                "at_least",
                "give one bound, at_least or at_most, not both",
            )),
            (AreaQuestion::SmallestAtLeast, Some(threshold), None)
            | (AreaQuestion::LargestAtMost, None, Some(threshold)) => Ok(Task::Decide {
                question,
                threshold,
            }),
            (AreaQuestion::SmallestAtLeast, _, _) => Err(invalid(
                "at_least",
                "maxmin-area is decided with at_least (its smallest triangle's area)",
            )),
            (AreaQuestion::LargestAtMost, _, _) => Err(invalid(
                "at_most",
                "minmax-area is decided with at_most (its largest triangle's area)",
            )),
        }
    }

    /// Sets the option `name` of `options` from its text form
    /// ([`Options::set`]), refusing an option this task does not read.
    ///
    /// # Errors
    /// As [`Request::set_option`].
    pub fn set_option(&self, options: &mut Options, name: &str, value: &str) -> Result<()> {
        let read = self.options();
        if !read.contains(&name) {
            return Err(Error::UnknownOption {
                name: name.to_string(),
                of: self.describe(),
                available: read,
            });
        }
        options.set(name, value)
    }

    /// `"criterion delaunay"`, `"these criteria"`, `"graph rng"`: for
    /// messages.
    fn describe(&self) -> String {
        match self {
            Task::Triangulate(c) => format!("criterion {}", c.name()),
            Task::Compare(_) => "these criteria".to_string(),
            Task::Graph(kind) => format!("graph {}", kind.name()),
            Task::Decide { question, .. } => format!("decision {}", question.criterion()),
        }
    }

    /// The options the task reads: those its criteria or graph declare (for
    /// a comparison, those of any of its criteria), then the run controls.
    pub fn options(&self) -> Vec<&'static str> {
        let declared: Vec<&'static str> = match self {
            Task::Triangulate(c) => c.options().to_vec(),
            Task::Compare(criteria) => {
                let criteria = if criteria.is_empty() {
                    Criterion::ALL
                } else {
                    criteria
                };
                criteria.iter().flat_map(|c| c.options()).copied().collect()
            }
            Task::Graph(kind) => kind.options().to_vec(),
            Task::Decide { .. } => Vec::new(),
        };
        OPTIONS
            .iter()
            .filter(|o| o.every_run || declared.contains(&o.name))
            .map(|o| o.name)
            .collect()
    }
}

/// An input, a [`Task`] and its options: everything one front-end call
/// asks for.
#[derive(Clone, Debug)]
pub struct Request {
    read: ReadInput,
    task: Task,
    options: Options,
    before: Vec<Phase>,
    start: Instant,
}

impl Request {
    /// A request for `task` on `read` (what [`crate::io::read`] returned, or
    /// [`ReadInput::from_doubles`] of a front end's numbers), with
    /// default options, timed from now.
    pub fn new(read: ReadInput, task: Task) -> Self {
        Self {
            read,
            task,
            options: Options::default(),
            before: Vec::new(),
            start: Instant::now(),
        }
    }

    /// This request with `options` (set in code: a progress hook, a
    /// cancellation flag, a metric). Options the task does not read are
    /// refused when it runs, as the registry refuses them.
    pub fn with_options(mut self, options: Options) -> Self {
        self.options = options;
        self
    }

    /// This request timed from `start`, after the `phases` the front end
    /// timed already (e.g. reading a file).
    pub fn after(mut self, start: Instant, phases: Vec<Phase>) -> Self {
        self.start = start;
        self.before = phases;
        self
    }

    /// Sets the option `name` from its text form ([`Options::set`]),
    /// refusing an option the task does not read.
    ///
    /// # Errors
    /// [`Error::UnknownOption`] naming the options the task reads, or the
    /// errors of [`Options::set`] for its value.
    pub fn set_option(&mut self, name: &str, value: &str) -> Result<()> {
        self.task.set_option(&mut self.options, name, value)
    }

    /// The task.
    pub fn task(&self) -> &Task {
        &self.task
    }

    /// The options as set so far.
    pub fn options(&self) -> &Options {
        &self.options
    }

    /// The input as read.
    pub fn input(&self) -> &ReadInput {
        &self.read
    }

    /// Validates the input (timed as `validate`) and runs the task.
    ///
    /// # Errors
    /// The input errors of [`PointSet::new`], [`SimplePolygon::new`] and
    /// their `with_elevations` (for a graph: of [`graph`], which ignores
    /// elevations), and for a single
    /// criterion or a graph its refusal ([`Error::Unsupported`],
    /// [`Error::Interrupted`]). A comparison reports each criterion's
    /// refusal in its result instead.
    pub fn run(self) -> Result<Outcome> {
        let Request {
            read,
            task,
            options,
            mut before,
            start,
        } = self;
        let polygon = matches!(read.input, Input::Polygon(_)) && !matches!(task, Task::Graph(_));
        let t0 = Instant::now();
        let (results, domain) = if let Task::Graph(kind) = task {
            let graph = graph(read.working_points(), kind, &options)?;
            (Results::Graph { kind, graph }, None)
        } else {
            let domain = input_domain(&read, polygon)?;
            before.push(Phase {
                name: "validate",
                ms: ms_since(t0),
            });
            let results = match (&task, &domain) {
                (Task::Triangulate(c), Domain::Points(p)) => {
                    Results::Triangulation(Box::new(triangulate_with(p, *c, &options)?))
                }
                (Task::Triangulate(c), Domain::Polygon(p)) => {
                    Results::Triangulation(Box::new(triangulate_with(p, *c, &options)?))
                }
                (Task::Compare(cs), Domain::Points(p)) => {
                    Results::Comparison(compare(p, cs, &options))
                }
                (Task::Compare(cs), Domain::Polygon(p)) => {
                    Results::Comparison(compare(p, cs, &options))
                }
                (
                    Task::Decide {
                        question,
                        threshold,
                    },
                    domain,
                ) => {
                    let area = working_threshold(threshold, &read);
                    let decision = match domain {
                        Domain::Points(p) => decide_area(p, *question, &area, &options)?,
                        Domain::Polygon(p) => decide_area(p, *question, &area, &options)?,
                    };
                    Results::Decision {
                        question: *question,
                        threshold: threshold.clone(),
                        decision: Box::new(decision),
                    }
                }
                (Task::Graph(_), _) => unreachable!("graphs are handled above"),
            };
            (results, Some(domain))
        };
        let mut phases = before;
        match &results {
            Results::Triangulation(s) => phases.extend(s.phases.iter().cloned()),
            Results::Graph { graph, .. } => phases.extend(graph.phases.iter().cloned()),
            Results::Decision { decision, .. } => phases.extend(decision.phases.iter().cloned()),
            Results::Comparison(_) => phases.push(Phase {
                name: "compare",
                ms: ms_since(t0),
            }),
        }
        Ok(Outcome {
            read,
            options,
            results,
            domain,
            phases,
            start,
        })
    }
}

/// A user's area threshold as a threshold on the doubled areas of `read`'s
/// working points: `2 · m · 10^(e + 2k)` for the threshold `m · 10^e` and
/// working points scaled by `10^k`.
fn working_threshold(threshold: &Threshold, read: &ReadInput) -> AreaThreshold {
    let (mantissa, exponent) = threshold.value();
    let k = read.scaled.as_ref().map_or(0, |s| i64::from(s.exponent));
    // The mantissa is below 10³⁶ (`Threshold`), so twice it fits.
    AreaThreshold::new(2 * mantissa, exponent + 2 * k)
}

/// The validated input of a triangulation or comparison: `read`'s working
/// points as a point set, or as a polygon when `polygon`, with its
/// elevations when it has them.
fn input_domain(read: &ReadInput, polygon: bool) -> Result<Domain> {
    let z = read.elevations.as_deref();
    if polygon {
        let ring = SimplePolygon::new(read.working_points())?;
        let Some(mut z) = z else {
            return Ok(Domain::Polygon(ring));
        };
        // A ring that repeats its first vertex at the end lost it in
        // `SimplePolygon::new`; its elevation goes with it if it agrees.
        let n = ring.point_set().input_points().len();
        if z.len() == n + 1 && z[n] == z[0] {
            z = &z[..n];
        }
        Ok(Domain::Polygon(ring.with_elevations(z)?))
    } else {
        let points = PointSet::new(read.working_points())?;
        Ok(Domain::Points(match z {
            Some(z) => points.with_elevations(z)?,
            None => points,
        }))
    }
}

/// The validated input of a triangulation or comparison.
#[derive(Clone, Debug)]
enum Domain {
    Points(PointSet),
    Polygon(SimplePolygon),
}

/// What a [`Task`] computed.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub enum Results {
    /// The solution of [`Task::Triangulate`].
    Triangulation(Box<Solution>),
    /// Each criterion's result, for [`Task::Compare`].
    Comparison(Vec<Comparison>),
    /// The graph, for [`Task::Graph`].
    Graph {
        /// Its kind.
        kind: GraphKind,
        /// Its edges and phases.
        graph: PointGraph,
    },
    /// The answer, for [`Task::Decide`].
    Decision {
        /// Which bound was asked.
        question: AreaQuestion,
        /// The threshold as given.
        threshold: Threshold,
        /// The answer and its witness.
        decision: Box<AreaDecision>,
    },
}

/// What a [`Request`] computed, with its input and phases: a front end
/// writes its document ([`to_json`](Self::to_json), [`document`](Self::document))
/// and reads the results.
#[derive(Clone, Debug)]
pub struct Outcome {
    read: ReadInput,
    options: Options,
    results: Results,
    domain: Option<Domain>,
    phases: Vec<Phase>,
    start: Instant,
}

impl Outcome {
    /// The triangulation, for [`Task::Triangulate`].
    pub fn solution(&self) -> Option<&Solution> {
        match &self.results {
            Results::Triangulation(s) => Some(s),
            _ => None,
        }
    }

    /// Each criterion's result, for [`Task::Compare`].
    pub fn comparison(&self) -> Option<&[Comparison]> {
        match &self.results {
            Results::Comparison(results) => Some(results),
            _ => None,
        }
    }

    /// The graph and its kind, for [`Task::Graph`].
    pub fn graph(&self) -> Option<(GraphKind, &PointGraph)> {
        match &self.results {
            Results::Graph { kind, graph } => Some((*kind, graph)),
            _ => None,
        }
    }

    /// The answer, for [`Task::Decide`].
    pub fn decision(&self) -> Option<&AreaDecision> {
        match &self.results {
            Results::Decision { decision, .. } => Some(decision),
            _ => None,
        }
    }

    /// The validated point set the criteria ran on (a polygon's vertices
    /// for a polygon); `None` for a graph.
    pub fn point_set(&self) -> Option<&PointSet> {
        match &self.domain {
            Some(Domain::Points(p)) => Some(p),
            Some(Domain::Polygon(p)) => Some(p.point_set()),
            None => None,
        }
    }

    /// The validated polygon, when the input was one (not for a graph).
    pub fn polygon(&self) -> Option<&SimplePolygon> {
        match &self.domain {
            Some(Domain::Polygon(p)) => Some(p),
            _ => None,
        }
    }

    /// The kind of input that was triangulated.
    pub fn input_kind(&self) -> InputKind {
        match &self.domain {
            Some(Domain::Polygon(_)) => InputKind::SimplePolygon,
            _ => InputKind::PointSet,
        }
    }

    /// What the task computed.
    pub fn results(&self) -> &Results {
        &self.results
    }

    /// The input as read, the phases and the results, for a front end that
    /// keeps them (the phases are those so far: [`finish`](Self::finish)
    /// first for `total`).
    pub fn into_parts(self) -> (ReadInput, Vec<Phase>, Results) {
        (self.read, self.phases, self.results)
    }

    /// The input as read (the user's values, the arithmetic, warnings).
    pub fn input(&self) -> &ReadInput {
        &self.read
    }

    /// The options the run used.
    pub fn options(&self) -> &Options {
        &self.options
    }

    /// The phases so far (see the module docs).
    pub fn phases(&self) -> &[Phase] {
        &self.phases
    }

    /// Appends a phase the front end timed (e.g. `write`).
    pub fn add_phase(&mut self, phase: Phase) {
        self.phases.push(phase);
    }

    /// Closes the timing with `total`, since the request's start.
    pub fn finish(&mut self) {
        self.phases.push(Phase {
            name: "total",
            ms: ms_since(self.start),
        });
    }

    /// The document, with the phases so far.
    pub fn document(&self) -> Document<'_> {
        let read = &self.read;
        match &self.results {
            Results::Triangulation(s) => Document::Triangulation(
                TriangulationReport::of_solution(s)
                    .with_input(read)
                    .with_timing(&self.phases),
            ),
            Results::Comparison(results) => Document::Comparison(
                ComparisonReport::new(results)
                    .with_input(read)
                    .with_timing(&self.phases),
            ),
            Results::Decision {
                question,
                threshold,
                decision,
            } => Document::Decision(
                DecisionReport::new(*question, threshold, decision)
                    .with_input(read)
                    .with_timing(&self.phases),
            ),
            Results::Graph { kind, graph } => Document::Graph(
                GraphReport::of_points(
                    read.input.points(),
                    *kind,
                    &graph.edges,
                    graph.distinct,
                    &graph.duplicates,
                )
                .with_input(read)
                .with_metric(&self.options.metric)
                .with_timing(&self.phases),
            ),
        }
    }

    /// The document as a JSON value.
    pub fn to_json(&self) -> Value {
        self.document().to_json()
    }
}

fn ms_since(start: Instant) -> f64 {
    start.elapsed().as_secs_f64() * 1e3
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(points: &[[f64; 2]]) -> ReadInput {
        ReadInput::from_doubles(Input::Points(points.to_vec()))
    }

    #[test]
    fn options_the_task_does_not_read_are_refused_by_name() {
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let mut r = Request::new(read(&square), Task::triangulate("delaunay").unwrap());
        let e = r.set_option("metric", "l1").unwrap_err();
        assert_eq!(
            e.to_string(),
            "unknown option 'metric' for criterion delaunay; available: time_limit"
        );
        let e = r.set_option("nope", "1").unwrap_err();
        assert!(matches!(e, Error::UnknownOption { .. }), "{e}");
        r.set_option("time_limit", "5").unwrap();
        assert!(matches!(
            r.set_option("time_limit", "-1"),
            Err(Error::InvalidOption {
                option: "time_limit",
                ..
            })
        ));
        let mut g = Request::new(read(&square), Task::graph("mst").unwrap());
        g.set_option("metric", "linf").unwrap();
        let mut c = Request::new(read(&square), Task::compare::<&str>(&[]).unwrap());
        c.set_option("metric", "l1").unwrap();
    }

    #[test]
    fn a_comparison_reports_refusals_and_a_graph_takes_collinear_points() {
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let mut c = Request::new(
            read(&square),
            Task::compare(&["delaunay", "minmax-length"]).unwrap(),
        );
        c.set_option("metric", "l1").unwrap();
        let mut outcome = c.run().unwrap();
        let results = outcome.comparison().unwrap();
        assert!(results[0].1.is_err() && results[1].1.is_ok());
        outcome.finish();
        let doc = outcome.to_json();
        assert_eq!(doc["document"], "comparison");
        assert!(doc["timing_ms"]["total"].is_number());
        let line = [[0.0, 0.0], [2.0, 2.0], [1.0, 1.0]];
        let g = Request::new(read(&line), Task::graph("rng").unwrap())
            .run()
            .unwrap();
        assert_eq!(g.graph().unwrap().1.edges, [[0, 2], [1, 2]]);
        assert!(matches!(
            Request::new(read(&line), Task::triangulate("greedy").unwrap()).run(),
            Err(Error::AllCollinear { distinct: 3 })
        ));
    }

    #[test]
    fn a_polygon_input_is_triangulated_inside() {
        let l = [
            [0.0, 0.0],
            [0.0, 2.0],
            [1.0, 2.0],
            [1.0, 1.0],
            [2.0, 1.0],
            [2.0, 0.0],
        ];
        let read = ReadInput::from_doubles(Input::Polygon(l.to_vec()));
        let outcome = Request::new(read, Task::triangulate("min-weight").unwrap())
            .run()
            .unwrap();
        assert_eq!(outcome.input_kind(), InputKind::SimplePolygon);
        assert_eq!(
            outcome.solution().unwrap().triangulation.triangles().len(),
            4
        );
        assert_eq!(outcome.phases()[0].name, "validate");
    }

    #[test]
    fn elevations_reach_the_point_set_and_the_document_or_are_refused() {
        use crate::error::ElevationProblem;
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0]];
        let z = vec![1.0, 2.0, 3.0, 4.0, 2.0];
        let task = || Task::triangulate("delaunay").unwrap();
        let outcome = Request::new(read(&square).with_elevations(z.clone()), task())
            .run()
            .unwrap();
        assert_eq!(
            outcome.point_set().unwrap().elevations(),
            Some(&[1.0, 2.0, 3.0, 4.0][..])
        );
        let doc = outcome.to_json();
        assert_eq!(doc["elevations"], serde_json::json!(z));
        // Without elevations the document has no such field.
        let plain = Request::new(read(&square), task()).run().unwrap();
        assert!(plain.to_json().get("elevations").is_none());
        // Duplicates that disagree, a NaN, a wrong count: refused by name.
        for (z, problem) in [
            (
                vec![1.0, 2.0, 3.0, 4.0, 9.0],
                ElevationProblem::ConflictingDuplicate { index: 4, kept: 1 },
            ),
            (
                vec![1.0, f64::NAN, 3.0, 4.0, 2.0],
                ElevationProblem::NonFinite {
                    index: 1,
                    value: f64::NAN,
                },
            ),
            (
                vec![1.0, 2.0],
                ElevationProblem::CountMismatch {
                    points: 5,
                    elevations: 2,
                },
            ),
        ] {
            let e = Request::new(read(&square).with_elevations(z), task())
                .run()
                .unwrap_err();
            match (&e, &problem) {
                (
                    Error::InvalidElevations(ElevationProblem::NonFinite { index, .. }),
                    ElevationProblem::NonFinite {
                        index: expected, ..
                    },
                ) => assert_eq!(index, expected),
                (Error::InvalidElevations(p), _) => assert_eq!(p, &problem),
                _ => panic!("{e:?}"),
            }
        }
        // A polygon's ring may close on its first vertex, elevation included.
        let ring = ReadInput::from_doubles(Input::Polygon(vec![
            [0.0, 0.0],
            [2.0, 0.0],
            [1.0, 2.0],
            [0.0, 0.0],
        ]))
        .with_elevations(vec![5.0, 6.0, 7.0, 5.0]);
        let outcome = Request::new(ring, task()).run().unwrap();
        assert_eq!(
            outcome.polygon().unwrap().point_set().elevations(),
            Some(&[5.0, 6.0, 7.0][..])
        );
    }
}
