//! The one error type of optri: every fallible function returns
//! [`Result<T, Error>`](Result), and every variant says what is wrong and
//! where (the point index, the file line, the polygon edges).

use std::fmt;

/// Everything that can go wrong in optri, with enough context to act on.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// A coordinate is NaN or infinite.
    NonFiniteCoordinate {
        /// Index of the point in the caller's input.
        index: usize,
        /// The offending value.
        value: f64,
    },
    /// A coordinate is outside the range in which optri's arithmetic is exact.
    CoordinateOutOfRange {
        /// Index of the point in the caller's input.
        index: usize,
        /// The offending value.
        value: f64,
    },
    /// Fewer than three distinct points.
    TooFewPoints {
        /// Number of distinct points after merging duplicates.
        distinct: usize,
    },
    /// Fewer than two distinct points, so no graph has an edge.
    TooFewPointsForGraph {
        /// Number of distinct points after merging duplicates.
        distinct: usize,
    },
    /// All distinct points lie on one line, so no triangle exists.
    AllCollinear {
        /// Number of distinct points.
        distinct: usize,
    },
    /// More points than `u32` indices can address.
    TooManyPoints {
        /// Number of input points.
        count: usize,
    },
    /// Elevations given with the points cannot be used
    /// ([`crate::PointSet::with_elevations`]).
    InvalidElevations(ElevationProblem),
    /// A polygon given as input is not a simple polygon.
    InvalidPolygon(PolygonProblem),
    /// A metric description or polygon norm that is not valid (not convex,
    /// not centrally symmetric, a bad exponent...).
    InvalidMetric(crate::kernel::MetricProblem),
    /// A line of an input file could not be read.
    Parse {
        /// 1-based line number (0 when the problem concerns the whole input).
        line: usize,
        /// What is wrong, in words.
        message: String,
    },
    /// Reading or writing a file failed, or an output cannot be written in
    /// the requested format.
    Io(String),
    /// A name (criterion, graph kind, file format) is not known.
    UnknownName {
        /// What was looked up: `"criterion"`, `"graph kind"`, `"input format"`.
        kind: &'static str,
        /// The name as given.
        name: String,
        /// The names that exist.
        available: Vec<&'static str>,
    },
    /// The criterion does not support this input (yet).
    Unsupported {
        /// The criterion's registry name, e.g. `"min-weight"`.
        criterion: &'static str,
        /// Why.
        reason: UnsupportedReason,
    },
    /// An option that the criterion or graph asked for does not read (see
    /// [`crate::request::Request::set_option`]).
    UnknownOption {
        /// The option as given.
        name: String,
        /// What was asked for, e.g. `"criterion delaunay"`.
        of: String,
        /// The options it reads.
        available: Vec<&'static str>,
    },
    /// An option value that cannot be used (see
    /// [`Options::set`](crate::Options::set)): names the option and says why.
    InvalidOption {
        /// The option's name, e.g. `"time_limit"`.
        option: &'static str,
        /// What is wrong with the value, in words.
        message: String,
    },
    /// The run was stopped before it finished: its time limit passed or it
    /// was cancelled ([`crate::Options::with_time_limit`],
    /// [`crate::Options::with_cancel`]).
    Interrupted(Interruption),
    /// A triangulation failed [`crate::Triangulation::validate`].
    InvalidTriangulation(String),
    /// An internal consistency check failed: this is a bug in optri, please
    /// report it with the input.
    Internal(String),
}

/// Why a criterion refused an input ([`Error::Unsupported`]).
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum UnsupportedReason {
    /// The algorithm needs a strictly convex polygon (every vertex a
    /// strictly convex corner, no three consecutive vertices collinear).
    NotStrictlyConvex,
    /// The algorithm's time or memory grows too fast for this many points.
    TooManyPoints {
        /// The largest accepted number of distinct points.
        limit: usize,
        /// Distinct points of the input.
        distinct: usize,
        /// What limits it, e.g. `"Klincsek's O(n³) program with O(n²) tables"`.
        because: &'static str,
    },
    /// The criterion does not triangulate polygons (yet).
    NoPolygonInput {
        /// The registry names of the criteria that do.
        accepted_by: Vec<&'static str>,
    },
    /// The criterion reads an elevation per point and the input has none
    /// ([`crate::PointSet::with_elevations`]).
    NeedsElevations,
    /// The criterion or graph has no meaning under a non-Euclidean metric
    /// (angles, areas) or does not implement it yet; names the metric.
    MetricNotSupported {
        /// The metric's name, e.g. `"l1"`.
        metric: String,
        /// The registry names of the criteria and graphs that take one.
        taken_by: Vec<&'static str>,
    },
}

/// Why a run stopped early ([`Error::Interrupted`]).
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Interruption {
    /// The time limit passed.
    TimeLimit {
        /// The limit, seconds.
        seconds: f64,
    },
    /// The run's [`Cancel`](crate::Cancel) flag was raised.
    Cancelled,
}

/// What is wrong with the elevations of a point set
/// ([`Error::InvalidElevations`]); points are named by their input index.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum ElevationProblem {
    /// There is not exactly one elevation per input point.
    CountMismatch {
        /// Input points, duplicates included.
        points: usize,
        /// Elevations given.
        elevations: usize,
    },
    /// An elevation is NaN or infinite.
    NonFinite {
        /// The point's input index.
        index: usize,
        /// The offending value.
        value: f64,
    },
    /// An elevation is outside the exact range of coordinates.
    OutOfRange {
        /// The point's input index.
        index: usize,
        /// The offending value.
        value: f64,
    },
    /// A duplicate of an earlier point carries another elevation.
    ConflictingDuplicate {
        /// The duplicate's input index.
        index: usize,
        /// The input index of the point it duplicates.
        kept: usize,
    },
}

/// What makes a vertex cycle not a simple polygon ([`Error::InvalidPolygon`]).
/// Vertices and edges are named by their position in the input ring; edge
/// `i` joins vertex `i` to vertex `i + 1` (mod n).
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum PolygonProblem {
    /// Fewer than three vertices.
    TooFewVertices {
        /// Number of vertices given.
        count: usize,
    },
    /// Two vertices are the same point.
    RepeatedVertex {
        /// The earlier position.
        first: usize,
        /// The later position.
        second: usize,
    },
    /// The polygon has holes (interior rings), which are not supported yet.
    HasHoles {
        /// Number of interior rings.
        holes: usize,
    },
    /// Two edges meet other than at the vertex that adjacent edges share.
    EdgesIntersect {
        /// The first edge, as `[i, i + 1]` positions.
        first: [usize; 2],
        /// The second edge.
        second: [usize; 2],
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use crate::kernel::{MAX_COORDINATE, MIN_COORDINATE};
        match self {
            Error::NonFiniteCoordinate { index, value } => write!(
                f,
                "point {index} has a non-finite coordinate ({value}); every coordinate must be a finite number"
            ),
            Error::CoordinateOutOfRange { index, value } => write!(
                f,
                "point {index} has coordinate {value:e}, outside the exact range: |v| must be 0 or between \
                 2^-142 ({MIN_COORDINATE:e}) and 2^201 ({MAX_COORDINATE:e}); rescale the input"
            ),
            Error::TooFewPoints { distinct } => write!(
                f,
                "a triangulation needs at least 3 distinct points, the input has {distinct}"
            ),
            Error::TooFewPointsForGraph { distinct } => write!(
                f,
                "a graph needs at least 2 distinct points, the input has {distinct}"
            ),
            Error::AllCollinear { distinct } => write!(
                f,
                "all {distinct} distinct points are collinear, so no triangle exists"
            ),
            Error::TooManyPoints { count } => write!(
                f,
                "{count} points exceed the u32 index range (at most {} points)",
                u32::MAX
            ),
            Error::InvalidElevations(problem) => write!(f, "invalid elevations: {problem}"),
            Error::InvalidPolygon(problem) => write!(f, "not a simple polygon: {problem}"),
            Error::InvalidMetric(problem) => write!(f, "invalid metric: {problem}"),
            Error::Parse { line, message } if *line > 0 => write!(f, "line {line}: {message}"),
            Error::Parse { message, .. } => write!(f, "{message}"),
            Error::Io(message) => write!(f, "{message}"),
            Error::UnknownName {
                kind,
                name,
                available,
            } => write!(
                f,
                "unknown {kind} '{name}'; available: {}",
                available.join(", ")
            ),
            Error::Unsupported { criterion, reason } => match reason {
                UnsupportedReason::NotStrictlyConvex => write!(
                    f,
                    "{criterion} here needs a strictly convex polygon (every vertex a strictly \
                     convex corner)"
                ),
                UnsupportedReason::TooManyPoints {
                    limit,
                    distinct,
                    because,
                } => write!(
                    f,
                    "{criterion} ({because}) is limited to {limit} points; this input has \
                     {distinct} distinct points"
                ),
                UnsupportedReason::MetricNotSupported { metric, taken_by } => write!(
                    f,
                    "{criterion} does not take a metric other than euclidean (got {metric}); \
                     what takes one: {}",
                    taken_by.join(", ")
                ),
                UnsupportedReason::NeedsElevations => write!(
                    f,
                    "{criterion} needs an elevation (z) for every point, and the input has none"
                ),
                UnsupportedReason::NoPolygonInput { accepted_by } => write!(
                    f,
                    "{criterion} does not triangulate polygons yet; criteria that do: {}",
                    accepted_by.join(", ")
                ),
            },
            Error::UnknownOption {
                name,
                of,
                available,
            } => write!(
                f,
                "unknown option '{name}' for {of}; available: {}",
                if available.is_empty() {
                    "none".to_string()
                } else {
                    available.join(", ")
                }
            ),
            Error::InvalidOption { option, message } => write!(f, "option {option}: {message}"),
            Error::Interrupted(Interruption::TimeLimit { seconds }) => write!(
                f,
                "stopped: the time limit of {seconds} s passed before the run finished"
            ),
            Error::Interrupted(Interruption::Cancelled) => {
                write!(f, "stopped: the run was cancelled")
            }
            Error::InvalidTriangulation(message) => write!(f, "invalid triangulation: {message}"),
            Error::Internal(message) => write!(
                f,
                "internal error (a bug in optri; please report it with the input): {message}"
            ),
        }
    }
}

impl fmt::Display for PolygonProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PolygonProblem::TooFewVertices { count } => {
                write!(
                    f,
                    "a polygon needs at least 3 vertices, this one has {count}"
                )
            }
            PolygonProblem::RepeatedVertex { first, second } => write!(
                f,
                "vertices {first} and {second} are the same point (a vertex may occur once)"
            ),
            PolygonProblem::HasHoles { holes } => write!(
                f,
                "polygons with holes are not supported yet (this one has {holes})"
            ),
            PolygonProblem::EdgesIntersect { first, second } => write!(
                f,
                "edge {}-{} meets edge {}-{} (the boundary must not touch itself)",
                first[0], first[1], second[0], second[1]
            ),
        }
    }
}

impl fmt::Display for ElevationProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use crate::kernel::{MAX_COORDINATE, MIN_COORDINATE};
        match self {
            ElevationProblem::CountMismatch { points, elevations } => write!(
                f,
                "{elevations} elevations for {points} points (one per input point is needed)"
            ),
            ElevationProblem::NonFinite { index, value } => {
                write!(f, "point {index} has a non-finite elevation ({value})")
            }
            ElevationProblem::OutOfRange { index, value } => write!(
                f,
                "point {index} has elevation {value:e}, outside the exact range: |z| must be 0 or \
                 between 2^-142 ({MIN_COORDINATE:e}) and 2^201 ({MAX_COORDINATE:e})"
            ),
            ElevationProblem::ConflictingDuplicate { index, kept } => write!(
                f,
                "point {index} repeats point {kept} with another elevation"
            ),
        }
    }
}

impl std::error::Error for Error {}

impl From<std::io::Error> for Error {
    fn from(e: std::io::Error) -> Self {
        Error::Io(e.to_string())
    }
}

/// `Result` with optri's [`Error`].
pub type Result<T, E = Error> = std::result::Result<T, E>;
