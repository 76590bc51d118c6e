//! optri's JSON documents: one schema, version [`SCHEMA_VERSION`], for every
//! front end (the CLI's `--json` and `-o x.json`, Python, web). There are two
//! documents, told apart by their `"document"` field:
//!
//! - `"triangulation"`: [`TriangulationReport`] — a triangulation and, when
//!   it comes from [`triangulate`](crate::triangulate), how it was obtained
//!   (criterion, optimality, algorithm, diagnostics, timings);
//! - `"graph"`: [`GraphReport`] — an edge set over the points and, when it
//!   comes from [`graph`](crate::graph), its kind and timings;
//! - `"comparison"`: [`ComparisonReport`] — the results of
//!   [`compare`](crate::compare), each a triangulation document or an error;
//! - `"decision"`: [`DecisionReport`] — the answer to an area decision
//!   ([`decide_area`](crate::decide_area)) and its witness triangulation.
//!
//! `docs/json-schema.md` in the repository lists every field with its type
//! and meaning. The reports implement `serde::Serialize` (fields in the
//! documented order) and convert to a `serde_json::Value`;
//! [`triangulation_from_json`] reads a triangulation document back, and the
//! GeoJSON reader reads the `coordinates` of either as a point file.
//!
//! Indices are input indices (0-based) and `coordinates` lists every input
//! point, merged duplicates included, so the document describes the input as
//! given; `elevations`, when the input had them, lists their elevations in
//! the same order.

mod decision;

pub use decision::DecisionReport;

use super::{input_elevations, Arithmetic, Input, ReadInput};
use crate::criteria::{ApproximationReport, BoundMeasure, CertifiedBound, Diagnostics, Optimality};
use crate::error::{Error, Result};
use crate::kernel::reporting::{
    area_scaled, over_power_of_ten_rounded, Rounding, Rounding::Nearest,
};
use crate::kernel::Point;
use crate::registry::{Comparison, Criterion, GraphKind, Solution};
use crate::structures::{Domain, PointSet, SimplePolygon, Stats, Triangulation};
use crate::timing::Phase;
use serde::ser::{Serialize, Serializer};
use serde_json::Value;
use std::borrow::Cow;

/// The `"schema_version"` of the documents written here. Adding a field
/// keeps the version; removing or renaming one, or changing its meaning,
/// raises it.
pub const SCHEMA_VERSION: u32 = 1;

/// A triangulation as a JSON document (`"document": "triangulation"`).
///
/// [`new`](Self::new) describes a bare triangulation; [`of_solution`](Self::of_solution)
/// adds the run fields (`criterion`, `exact`, `optimality`, `algorithm`,
/// `diagnostics`, `timing_ms`). The `.json` files [`write`](super::write())
/// makes of it are this document.
#[derive(Clone, Copy, Debug)]
pub struct TriangulationReport<'a> {
    triangulation: &'a Triangulation,
    solution: Option<&'a Solution>,
    timing: Option<&'a [Phase]>,
    input: Option<InputUnits<'a>>,
}

/// How the triangulated points relate to the user's: the arithmetic and,
/// when the algorithms ran on scaled integers, the user's values and `k`;
/// and the elevations as read.
#[derive(Clone, Copy, Debug)]
struct InputUnits<'a> {
    arithmetic: Arithmetic,
    user: Option<(&'a [Point], i32)>,
    elevations: Option<&'a [f64]>,
}

impl<'a> InputUnits<'a> {
    fn of(read: &'a ReadInput) -> Self {
        Self {
            arithmetic: read.arithmetic,
            user: read
                .scaled
                .as_ref()
                .map(|s| (read.input.points(), s.exponent)),
            elevations: read.elevations.as_deref(),
        }
    }
}

impl<'a> TriangulationReport<'a> {
    /// The document of a bare triangulation: no run fields, no timing.
    pub fn new(triangulation: &'a Triangulation) -> Self {
        Self {
            triangulation,
            solution: None,
            timing: None,
            input: None,
        }
    }

    /// The document of a [`triangulate`](crate::triangulate) result, timed by
    /// its [`phases`](Solution::phases).
    pub fn of_solution(solution: &'a Solution) -> Self {
        Self {
            triangulation: &solution.triangulation,
            solution: Some(solution),
            timing: Some(&solution.phases),
            input: None,
        }
    }

    /// Describes a triangulation of `read`'s working points
    /// ([`ReadInput::working_points`]): the document gets
    /// `coordinate_arithmetic`, and when those were scaled integers, its
    /// `coordinates` are the user's values and its measures are in the
    /// user's units (lengths divided by `10^k`, areas by `10^2k`).
    pub fn with_input(self, read: &'a ReadInput) -> Self {
        Self {
            input: Some(InputUnits::of(read)),
            ..self
        }
    }

    /// The coordinates to show: the user's values.
    pub fn coordinates(&self) -> &'a [Point] {
        match self.input.and_then(|i| i.user) {
            Some((user, _)) => user,
            None => self.triangulation.points(),
        }
    }

    /// The elevation of each input point (in the order of
    /// [`coordinates`](Self::coordinates)), when the input had them: as read
    /// ([`with_input`](Self::with_input)), else those of the triangulation's
    /// point set.
    pub fn elevations(&self) -> Option<Cow<'a, [f64]>> {
        match self.input.and_then(|i| i.elevations) {
            Some(z) => Some(Cow::Borrowed(z)),
            None => input_elevations(self.triangulation.point_set()).map(Cow::Owned),
        }
    }

    /// The quality measures, in the user's units (on scaled input, divided
    /// exactly by `10^k` or `10^2k` and rounded once).
    pub fn stats(&self) -> Stats {
        match self.input.and_then(|i| i.user) {
            Some((_, k)) => self.triangulation.stats_over_power_of_ten(k),
            None => self.triangulation.stats(),
        }
    }

    /// The solution's certified bound ([`Solution::bound`]), in the user's
    /// units.
    pub fn bound_value(&self) -> Option<f64> {
        self.solution
            .and_then(|s| s.bound.as_ref())
            .map(|b| self.bound_in_user_units(b))
    }

    /// Under a non-Euclidean metric ([`Solution::metric`]): the longest edge
    /// under it (chosen exactly) and its length in the user's units (a norm
    /// is homogeneous, so scaled input divides it by `10^k`).
    pub fn metric_longest_edge(&self) -> Option<([u32; 2], f64)> {
        let s = self.solution.filter(|s| !s.metric.is_euclidean())?;
        let (edge, length) = s.longest_edge_under_metric();
        Some(match self.input.and_then(|i| i.user) {
            Some((_, k)) => (edge, over_power_of_ten_rounded(length, k, Nearest)),
            None => (edge, length),
        })
    }

    /// A certified bound's value in the user's units: a triangle's area is
    /// measured again and rounded once (as `stats` is); a lower bound on a
    /// total length is divided by `10^k` rounding down, staying one.
    fn bound_in_user_units(&self, b: &CertifiedBound) -> f64 {
        let Some((_, k)) = self.input.and_then(|i| i.user) else {
            return b.value;
        };
        let area = b.measure == BoundMeasure::Area;
        if let (true, Some(t)) = (area, b.triangle) {
            let [p, q, r] = t.map(|i| self.triangulation.points()[i as usize]);
            return area_scaled(p, q, r, k);
        }
        let mode = if b.upper { Nearest } else { Rounding::Down };
        over_power_of_ten_rounded(b.value, if area { 2 * k } else { k }, mode)
    }

    /// Reports `phases` as `timing_ms` instead (e.g. with the reading and
    /// writing a front end timed around the library call).
    pub fn with_timing(self, phases: &'a [Phase]) -> Self {
        Self {
            timing: Some(phases),
            ..self
        }
    }

    /// The triangulation described.
    pub fn triangulation(&self) -> &'a Triangulation {
        self.triangulation
    }

    /// The criterion that made it, when the report has a run.
    pub fn criterion(&self) -> Option<Criterion> {
        self.solution.map(|s| s.criterion)
    }

    /// The document as a JSON value.
    pub fn to_json(&self) -> Value {
        to_value(self)
    }
}

impl Serialize for TriangulationReport<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        let t = self.triangulation;
        let run = self.solution;
        let optimality = run.map(|s| s.optimality);
        TriangulationDocument {
            schema_version: SCHEMA_VERSION,
            document: "triangulation",
            domain: domain_name(t.domain()),
            criterion: run.map(|s| s.criterion.name()),
            exact: run.map(|s| s.exact),
            optimality: optimality.map(Optimality::name),
            optimality_bound: optimality.and_then(bound),
            bound: run.and_then(|s| s.bound.as_ref()).map(|b| {
                let value = self.bound_in_user_units(b);
                let area = b.measure == crate::BoundMeasure::Area;
                BoundDocument {
                    kind: if b.upper { "upper" } else { "lower" },
                    measure: if area { "area" } else { "total edge length" },
                    triangle: b.triangle,
                    area: area.then_some(value),
                    weight: (!area).then_some(value),
                    // The result's weight minus the bound: how far from
                    // optimal the result can be (rounded).
                    gap: (!area).then(|| self.stats().total_edge_length - value),
                }
            }),
            algorithm: run.map(|s| s.algorithm.as_str()),
            algorithm_detail: run.map(|s| s.algorithm_detail.as_str()),
            approximation: run
                .and_then(|s| s.approximation.as_ref())
                .map(ApproximationDocument::of),
            metric: run.and_then(|s| {
                let (longest_edge, max_edge_length) = self.metric_longest_edge()?;
                Some(MetricDocument {
                    name: s.metric.name(),
                    max_edge_length,
                    longest_edge,
                })
            }),
            points: t.points().len(),
            distinct_points: t.point_set().len(),
            duplicates: t.point_set().duplicates(),
            coordinate_arithmetic: self.input.map(|i| i.arithmetic.name()),
            coordinate_scale: self.input.and_then(|i| i.user).map(|(_, k)| k),
            stats: self.stats(),
            diagnostics: run.map(|s| DiagnosticsMap(&s.diagnostics)),
            timing_ms: self.timing.map(TimingMap),
            triangles: t.triangles(),
            edges: t.edges(),
            coordinates: self.coordinates(),
            elevations: self.elevations(),
        }
        .serialize(serializer)
    }
}

/// A certified bound on the optimum (`Solution::bound`): the optimum's
/// measure is at most (`"upper"`) or at least (`"lower"`) `triangle`'s
/// `area` (area criteria), or at least `weight` (min-weight; `gap` is the
/// result's total edge length minus `weight`).
#[derive(serde::Serialize)]
struct BoundDocument {
    kind: &'static str,
    measure: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    triangle: Option<[u32; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    area: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    weight: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    gap: Option<f64>,
}

/// How a general-set area result was obtained and its guarantee
/// (`Solution::approximation`).
#[derive(serde::Serialize)]
struct ApproximationDocument<'a> {
    choice: &'static str,
    candidate: &'static str,
    candidates: &'a [&'static str],
    skipped: Vec<SkippedDocument<'a>>,
    delaunay_smallest_angle: AngleDocument,
    alpha: Option<f64>,
    flips: usize,
    guarantee: GuaranteeDocument<'a>,
}

#[derive(serde::Serialize)]
struct SkippedDocument<'a> {
    candidate: &'static str,
    reason: &'a str,
}

#[derive(serde::Serialize)]
struct AngleDocument {
    degrees: f64,
    corner: [u32; 3],
}

#[derive(serde::Serialize)]
struct GuaranteeDocument<'a> {
    kind: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    alpha: Option<f64>,
    statement: &'a str,
    smallest_angle_deg: f64,
    theorem_81: Vec<FactorDocument>,
}

#[derive(serde::Serialize)]
struct FactorDocument {
    beta: f64,
    factor: f64,
}

impl<'a> ApproximationDocument<'a> {
    fn of(r: &'a ApproximationReport) -> Self {
        let g = &r.guarantee;
        ApproximationDocument {
            choice: r.choice.name(),
            candidate: r.candidate,
            candidates: &r.candidates,
            skipped: r
                .skipped
                .iter()
                .map(|(candidate, reason)| SkippedDocument { candidate, reason })
                .collect(),
            delaunay_smallest_angle: AngleDocument {
                degrees: r.delaunay_smallest_angle_degrees,
                corner: r.delaunay_smallest_angle,
            },
            alpha: r.alpha_degrees,
            flips: r.flips,
            guarantee: GuaranteeDocument {
                kind: g.kind,
                alpha: g.alpha_degrees,
                statement: &g.statement,
                smallest_angle_deg: g.smallest_angle_degrees,
                theorem_81: g
                    .theorem_81
                    .iter()
                    .map(|&[beta, factor]| FactorDocument { beta, factor })
                    .collect(),
            },
        }
    }
}

/// Lengths under a non-Euclidean metric (`Solution::metric`); `stats` stays
/// Euclidean.
#[derive(serde::Serialize)]
struct MetricDocument {
    name: String,
    max_edge_length: f64,
    longest_edge: [u32; 2],
}

/// The fields of a triangulation document, in the order written.
#[derive(serde::Serialize)]
struct TriangulationDocument<'a> {
    schema_version: u32,
    document: &'static str,
    domain: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    criterion: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    exact: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    optimality: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    optimality_bound: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    bound: Option<BoundDocument>,
    #[serde(skip_serializing_if = "Option::is_none")]
    algorithm: Option<&'a str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    algorithm_detail: Option<&'a str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    approximation: Option<ApproximationDocument<'a>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    metric: Option<MetricDocument>,
    points: usize,
    distinct_points: usize,
    duplicates: &'a [[u32; 2]],
    #[serde(skip_serializing_if = "Option::is_none")]
    coordinate_arithmetic: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    coordinate_scale: Option<i32>,
    stats: Stats,
    #[serde(skip_serializing_if = "Option::is_none")]
    diagnostics: Option<DiagnosticsMap<'a>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    timing_ms: Option<TimingMap<'a>>,
    triangles: &'a [[u32; 3]],
    edges: Vec<[u32; 2]>,
    coordinates: &'a [Point],
    #[serde(skip_serializing_if = "Option::is_none")]
    elevations: Option<Cow<'a, [f64]>>,
}

/// A graph as a JSON document (`"document": "graph"`).
///
/// [`new`](Self::new) describes a bare edge set over points;
/// [`of_graph`](Self::of_graph) adds the graph `kind`, the distinct-point
/// count and the duplicates; [`with_timing`](Self::with_timing) adds
/// `timing_ms`. The `.json` files [`write`](super::write()) makes of it are
/// this document.
#[derive(Clone, Copy, Debug)]
pub struct GraphReport<'a> {
    points: &'a [Point],
    edges: &'a [[u32; 2]],
    distinct: Option<(usize, &'a [[u32; 2]])>,
    kind: Option<GraphKind>,
    timing: Option<&'a [Phase]>,
    arithmetic: Option<Arithmetic>,
    metric: Option<&'a crate::kernel::Metric>,
    elevations: Option<&'a [f64]>,
}

impl<'a> GraphReport<'a> {
    /// The document of `edges` (index pairs into `points`).
    pub fn new(points: &'a [Point], edges: &'a [[u32; 2]]) -> Self {
        Self {
            points,
            edges,
            distinct: None,
            kind: None,
            timing: None,
            arithmetic: None,
            metric: None,
            elevations: None,
        }
    }

    /// The document of the graph `kind` of `point_set` (edges as returned by
    /// [`graph`](crate::graph): input-index pairs).
    pub fn of_graph(point_set: &'a PointSet, kind: GraphKind, edges: &'a [[u32; 2]]) -> Self {
        Self {
            points: point_set.input_points(),
            edges,
            distinct: Some((point_set.len(), point_set.duplicates())),
            kind: Some(kind),
            timing: None,
            arithmetic: None,
            metric: None,
            elevations: None,
        }
    }

    /// The document of the graph `kind` of `points` (input order) with
    /// `distinct` distinct points and the merged `duplicates` (`[dropped,
    /// kept]`), for inputs that are no [`PointSet`] (two points, or all
    /// collinear: see [`crate::graph`]).
    pub fn of_points(
        points: &'a [Point],
        kind: GraphKind,
        edges: &'a [[u32; 2]],
        distinct: usize,
        duplicates: &'a [[u32; 2]],
    ) -> Self {
        Self {
            kind: Some(kind),
            distinct: Some((distinct, duplicates)),
            ..Self::new(points, edges)
        }
    }

    /// Describes a graph of `read`'s working points: the document gets
    /// `coordinate_arithmetic`, its `coordinates` are the user's values, and
    /// `elevations` the input's, if it had them.
    pub fn with_input(self, read: &'a ReadInput) -> Self {
        Self {
            points: read.input.points(),
            arithmetic: Some(read.arithmetic),
            elevations: read.elevations.as_deref(),
            ..self
        }
    }

    /// Reports the metric the graph was computed under (`"metric"`, written
    /// only for a non-Euclidean one).
    pub fn with_metric(self, metric: &'a crate::kernel::Metric) -> Self {
        Self {
            metric: (!metric.is_euclidean()).then_some(metric),
            ..self
        }
    }

    /// Reports `phases` as `timing_ms`.
    pub fn with_timing(self, phases: &'a [Phase]) -> Self {
        Self {
            timing: Some(phases),
            ..self
        }
    }

    /// The points (all input points).
    pub fn points(&self) -> &'a [Point] {
        self.points
    }

    /// The edges, as index pairs into [`points`](Self::points).
    pub fn edges(&self) -> &'a [[u32; 2]] {
        self.edges
    }

    /// The elevation of each point, when the input had them
    /// ([`with_input`](Self::with_input)).
    pub fn elevations(&self) -> Option<&'a [f64]> {
        self.elevations
    }

    /// The document as a JSON value.
    pub fn to_json(&self) -> Value {
        to_value(self)
    }
}

impl Serialize for GraphReport<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        GraphDocument {
            schema_version: SCHEMA_VERSION,
            document: "graph",
            kind: self.kind.map(GraphKind::name),
            metric: self.metric.map(|m| m.name()),
            points: self.points.len(),
            distinct_points: self.distinct.map(|d| d.0),
            duplicates: self.distinct.map(|d| d.1),
            coordinate_arithmetic: self.arithmetic.map(Arithmetic::name),
            timing_ms: self.timing.map(TimingMap),
            edges: self.edges,
            coordinates: self.points,
            elevations: self.elevations,
        }
        .serialize(serializer)
    }
}

/// The fields of a graph document, in the order written.
#[derive(serde::Serialize)]
struct GraphDocument<'a> {
    schema_version: u32,
    document: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    kind: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    metric: Option<String>,
    points: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    distinct_points: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    duplicates: Option<&'a [[u32; 2]]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    coordinate_arithmetic: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    timing_ms: Option<TimingMap<'a>>,
    edges: &'a [[u32; 2]],
    coordinates: &'a [Point],
    #[serde(skip_serializing_if = "Option::is_none")]
    elevations: Option<&'a [f64]>,
}

/// The results of [`compare`](crate::compare) as a JSON document
/// (`"document": "comparison"`): `{"schema_version", "document",
/// "timing_ms"?, "results": [...]}`, where each result is exactly the
/// triangulation document of [`TriangulationReport::of_solution`] (what
/// `optri triangulate --json` prints) or, for a criterion that refused the
/// input, `{"criterion", "error"}` with the library's message.
#[derive(Clone, Copy, Debug)]
pub struct ComparisonReport<'a> {
    results: &'a [Comparison],
    timing: Option<&'a [Phase]>,
    input: Option<&'a ReadInput>,
}

impl<'a> ComparisonReport<'a> {
    /// The document of `results`.
    pub fn new(results: &'a [Comparison]) -> Self {
        Self {
            results,
            timing: None,
            input: None,
        }
    }

    /// Describes results computed on `read`'s working points, as
    /// [`TriangulationReport::with_input`] does for each of them.
    pub fn with_input(self, read: &'a ReadInput) -> Self {
        Self {
            input: Some(read),
            ..self
        }
    }

    /// The document of one solution of the comparison (with the input's
    /// units when [`with_input`](Self::with_input) was given).
    pub fn report(&self, solution: &'a Solution) -> TriangulationReport<'a> {
        let report = TriangulationReport::of_solution(solution);
        match self.input {
            Some(read) => report.with_input(read),
            None => report,
        }
    }

    /// Reports `phases` (e.g. a front end's `read`, `validate` and `total`
    /// around the whole comparison) as the document's own `timing_ms`; each
    /// result keeps the phases of its own run.
    pub fn with_timing(self, phases: &'a [Phase]) -> Self {
        Self {
            timing: Some(phases),
            ..self
        }
    }

    /// The results described.
    pub fn results(&self) -> &'a [Comparison] {
        self.results
    }

    /// The document as a JSON value.
    pub fn to_json(&self) -> Value {
        to_value(self)
    }
}

impl Serialize for ComparisonReport<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        ComparisonDocument {
            schema_version: SCHEMA_VERSION,
            document: "comparison",
            timing_ms: self.timing.map(TimingMap),
            results: self
                .results
                .iter()
                .map(|c| ComparisonEntry(c, self))
                .collect(),
        }
        .serialize(serializer)
    }
}

/// The fields of a comparison document, in the order written.
#[derive(serde::Serialize)]
struct ComparisonDocument<'a> {
    schema_version: u32,
    document: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    timing_ms: Option<TimingMap<'a>>,
    results: Vec<ComparisonEntry<'a>>,
}

/// One result of a comparison: a triangulation document, or the refusal.
struct ComparisonEntry<'a>(&'a Comparison, &'a ComparisonReport<'a>);

impl Serialize for ComparisonEntry<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        match &self.0 {
            (_, Ok(solution)) => self.1.report(solution).serialize(serializer),
            (criterion, Err(e)) => ErrorDocument {
                criterion: criterion.name(),
                error: e.to_string(),
            }
            .serialize(serializer),
        }
    }
}

/// A criterion that refused the input, in a comparison document.
#[derive(serde::Serialize)]
struct ErrorDocument {
    criterion: &'static str,
    error: String,
}

/// The `"domain"` of a triangulation document: `"convex-hull"` or
/// `"polygon"` (the interior of a simple polygon whose ring is the
/// coordinates, in order).
pub(super) fn domain_name(domain: &Domain) -> &'static str {
    match domain {
        Domain::Polygon { .. } => "polygon",
        _ => "convex-hull",
    }
}

/// The guarantee of an approximation, if the result is one.
fn bound(optimality: Optimality) -> Option<&'static str> {
    match optimality {
        Optimality::Approximation { bound } => Some(bound),
        _ => None,
    }
}

/// `{"name": milliseconds, ...}` in phase order; a phase that ran more than
/// once (e.g. minmax length's `lower bound`) is reported once, with the sum.
#[derive(Clone, Copy)]
struct TimingMap<'a>(&'a [Phase]);

impl Serialize for TimingMap<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        let mut merged: Vec<(&str, f64)> = Vec::with_capacity(self.0.len());
        for phase in self.0 {
            match merged.iter_mut().find(|(name, _)| *name == phase.name) {
                Some((_, ms)) => *ms += phase.ms,
                None => merged.push((phase.name, phase.ms)),
            }
        }
        serializer.collect_map(merged)
    }
}

/// `{"counter": count, ...}` in the order the algorithm reported them.
struct DiagnosticsMap<'a>(&'a Diagnostics);

impl Serialize for DiagnosticsMap<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        serializer.collect_map(self.0.iter())
    }
}

pub(super) fn to_value(document: &impl Serialize) -> Value {
    // The documents hold strings, numbers, arrays and string-keyed maps only.
    serde_json::to_value(document).expect("an optri document always converts to a JSON value")
}

/// The member of an optri document that holds its points: `coordinates`, or
/// in documents from before schema version 1 (written by `-o x.json`) the
/// `points` array. `None` if there is neither.
pub(super) fn document_coordinates(document: &Value) -> Option<(&'static str, &Value)> {
    match (document.get("coordinates"), document.get("points")) {
        (Some(c), _) => Some(("coordinates", c)),
        (None, Some(p)) => Some(("points", p)),
        (None, None) => None,
    }
}

/// Reads a triangulation document back and validates it: the
/// [`TriangulationReport`] document, or the document of earlier versions
/// (with the coordinates as a `points` array). Only `coordinates`,
/// `triangles` and `elevations` (when present) are read; the duplicates
/// follow from the coordinates and every other field from the triangulation.
///
/// # Errors
/// [`Error::Parse`] (line 0) for a malformed object, a graph document or a
/// newer `schema_version`; the errors of [`PointSet::new`],
/// [`PointSet::with_elevations`] and [`Triangulation::from_triangles`].
pub fn triangulation_from_json(value: &Value) -> Result<Triangulation> {
    let bad = |m: &str| Error::Parse {
        line: 0,
        message: format!("triangulation JSON: {m}"),
    };
    if let Some(version) = value.get("schema_version") {
        if version
            .as_u64()
            .is_none_or(|v| v > u64::from(SCHEMA_VERSION))
        {
            return Err(bad(&format!(
                "schema_version {version} is not one this optri reads (1 to {SCHEMA_VERSION})"
            )));
        }
    }
    if let Some(document) = value.get("document").filter(|d| *d != "triangulation") {
        return Err(bad(&format!(
            "\"document\" is {document}, not \"triangulation\""
        )));
    }
    let (name, coordinates) = document_coordinates(value)
        .filter(|(_, c)| c.is_array())
        .ok_or_else(|| bad("no \"coordinates\" (nor the \"points\" array of earlier versions)"))?;
    let points: Vec<Point> = serde_json::from_value(coordinates.clone())
        .map_err(|e| bad(&format!("\"{name}\": {e}")))?;
    let elevations: Option<Vec<f64>> = match value.get("elevations") {
        None => None,
        Some(z) => Some(
            serde_json::from_value(z.clone()).map_err(|e| bad(&format!("\"elevations\": {e}")))?,
        ),
    };
    let triangles: Vec<[u32; 3]> = serde_json::from_value(
        value
            .get("triangles")
            .cloned()
            .ok_or_else(|| bad("no \"triangles\""))?,
    )
    .map_err(|e| bad(&format!("\"triangles\": {e}")))?;
    if let Some(i) = triangles
        .iter()
        .flatten()
        .find(|&&i| i as usize >= points.len())
    {
        return Err(bad(&format!("triangle index {i} out of range")));
    }
    // The document shows the user's values; when they are short decimals
    // (as every decimal-exact document's are), validate on those decimals,
    // where the writer decided, not on their doubles: points collinear as
    // written need not be collinear as doubles.
    let polygon = match value.get("domain").and_then(Value::as_str) {
        Some("polygon") => true,
        None | Some("convex-hull") => false,
        Some(other) => {
            return Err(bad(&format!(
                "\"domain\" is \"{other}\", not \"convex-hull\" or \"polygon\""
            )))
        }
    };
    let read = ReadInput::from_doubles(if polygon {
        Input::Polygon(points)
    } else {
        Input::Points(points)
    });
    let working = read.working_points();
    let triangulation = if polygon {
        Triangulation::from_polygon_triangles(&SimplePolygon::new(working)?, triangles)?
    } else {
        Triangulation::from_triangles(&PointSet::new(working)?, triangles)?
    };
    // A polygon ring may repeat its first vertex at the end, which
    // `SimplePolygon::new` dropped: keep as many user points.
    let n = triangulation.point_set().input_points().len();
    let point_set = match &read.scaled {
        Some(_) => PointSet::new(&read.input.points()[..n])?,
        None => triangulation.point_set().clone(),
    };
    Ok(match elevations {
        Some(z) => {
            // The elevation of a repeated closing vertex goes with it.
            let closing = polygon && z.len() == n + 1 && z[n] == z[0];
            let z = if closing { &z[..n] } else { &z[..] };
            triangulation.with_point_set(point_set.with_elevations(z)?)
        }
        None if read.scaled.is_some() => triangulation.with_point_set(point_set),
        None => triangulation,
    })
}

#[cfg(test)]
mod tests;
