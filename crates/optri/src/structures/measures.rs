//! The quality measures of [`Stats`] as a table, so that every front end
//! (the CLI's comparison table, the web page, Python) lists the same
//! measures with the same names and knows which direction is better.

use super::Stats;

/// Which values of a measure are better.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Better {
    /// Smaller is better (e.g. the longest edge).
    Smaller,
    /// Larger is better (e.g. the smallest angle).
    Larger,
}

impl Better {
    /// `"smaller"` or `"larger"`.
    pub fn name(self) -> &'static str {
        match self {
            Better::Smaller => "smaller",
            Better::Larger => "larger",
        }
    }
}

/// A quality measure of a triangulation: a field of [`Stats`], for the
/// listing every front end shows and for exact comparisons between
/// triangulations ([`crate::Triangulation::compare_measure`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Measure {
    /// [`Stats::max_edge_length`].
    MaxEdgeLength,
    /// [`Stats::total_edge_length`].
    TotalEdgeLength,
    /// [`Stats::min_area`].
    MinArea,
    /// [`Stats::max_area`].
    MaxArea,
    /// [`Stats::min_angle_deg`].
    MinAngle,
    /// [`Stats::max_angle_deg`].
    MaxAngle,
    /// [`Stats::min_height`].
    MinHeight,
    /// [`Stats::max_eccentricity`].
    MaxEccentricity,
    /// [`Stats::max_slope`] (only for points with elevations).
    MaxSlope,
}

impl Measure {
    /// Every quality measure, in display order.
    pub const ALL: [Measure; 9] = [
        Measure::MaxEdgeLength,
        Measure::TotalEdgeLength,
        Measure::MinArea,
        Measure::MaxArea,
        Measure::MinAngle,
        Measure::MaxAngle,
        Measure::MinHeight,
        Measure::MaxEccentricity,
        Measure::MaxSlope,
    ];

    /// The [`Stats`] field (and JSON key), e.g. `"max_edge_length"`.
    pub fn name(self) -> &'static str {
        match self {
            Measure::MaxEdgeLength => "max_edge_length",
            Measure::TotalEdgeLength => "total_edge_length",
            Measure::MinArea => "min_area",
            Measure::MaxArea => "max_area",
            Measure::MinAngle => "min_angle_deg",
            Measure::MaxAngle => "max_angle_deg",
            Measure::MinHeight => "min_height",
            Measure::MaxEccentricity => "max_eccentricity",
            Measure::MaxSlope => "max_slope",
        }
    }

    /// A short column heading, e.g. `"max edge"`.
    pub fn label(self) -> &'static str {
        match self {
            Measure::MaxEdgeLength => "max edge",
            Measure::TotalEdgeLength => "total length",
            Measure::MinArea => "min area",
            Measure::MaxArea => "max area",
            Measure::MinAngle => "min angle°",
            Measure::MaxAngle => "max angle°",
            Measure::MinHeight => "min height",
            Measure::MaxEccentricity => "max eccentricity",
            Measure::MaxSlope => "max slope",
        }
    }

    /// Which values are better.
    pub fn better(self) -> Better {
        match self {
            Measure::MinArea | Measure::MinAngle | Measure::MinHeight => Better::Larger,
            _ => Better::Smaller,
        }
    }

    /// The measure's value in `stats` (correctly rounded); `None` only for
    /// the slope of points without elevations.
    pub fn value(self, stats: &Stats) -> Option<f64> {
        Some(match self {
            Measure::MaxEdgeLength => stats.max_edge_length,
            Measure::TotalEdgeLength => stats.total_edge_length,
            Measure::MinArea => stats.min_area,
            Measure::MaxArea => stats.max_area,
            Measure::MinAngle => stats.min_angle_deg,
            Measure::MaxAngle => stats.max_angle_deg,
            Measure::MinHeight => stats.min_height,
            Measure::MaxEccentricity => stats.max_eccentricity,
            Measure::MaxSlope => return stats.max_slope,
        })
    }
}
