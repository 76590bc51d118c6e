//! The one error type of optri.

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
    /// A line of an input file could not be read.
    Parse {
        /// 1-based line number (0 when the problem concerns the whole input).
        line: usize,
        /// What is wrong, in words.
        message: String,
    },
    /// Reading or writing a file failed.
    Io(String),
    /// The criterion or algorithm does not support this input.
    Unsupported(String),
    /// A triangulation failed [`crate::Triangulation::validate`].
    InvalidTriangulation(String),
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
            Error::AllCollinear { distinct } => write!(
                f,
                "all {distinct} distinct points are collinear, so no triangle exists"
            ),
            Error::TooManyPoints { count } => write!(
                f,
                "{count} points exceed the u32 index range (at most {} points)",
                u32::MAX
            ),
            Error::Parse { line, message } if *line > 0 => write!(f, "line {line}: {message}"),
            Error::Parse { message, .. } => write!(f, "{message}"),
            Error::Io(message) => write!(f, "{message}"),
            Error::Unsupported(message) => write!(f, "{message}"),
            Error::InvalidTriangulation(message) => write!(f, "invalid triangulation: {message}"),
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
