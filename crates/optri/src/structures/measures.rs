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

/// One quality measure of a triangulation: a field of [`Stats`].
#[derive(Clone, Copy, Debug)]
#[non_exhaustive]
pub struct Measure {
    /// The [`Stats`] field (and JSON key), e.g. `"max_edge_length"`.
    pub name: &'static str,
    /// A short column heading, e.g. `"max edge"`.
    pub label: &'static str,
    /// Which values are better.
    pub better: Better,
    /// Reads the value from [`Stats`].
    pub value: fn(&Stats) -> f64,
}

impl Stats {
    /// Every quality measure, in display order.
    pub const MEASURES: &'static [Measure] = &[
        Measure {
            name: "max_edge_length",
            label: "max edge",
            better: Better::Smaller,
            value: |s| s.max_edge_length,
        },
        Measure {
            name: "total_edge_length",
            label: "total length",
            better: Better::Smaller,
            value: |s| s.total_edge_length,
        },
        Measure {
            name: "min_area",
            label: "min area",
            better: Better::Larger,
            value: |s| s.min_area,
        },
        Measure {
            name: "max_area",
            label: "max area",
            better: Better::Smaller,
            value: |s| s.max_area,
        },
        Measure {
            name: "min_angle_deg",
            label: "min angle°",
            better: Better::Larger,
            value: |s| s.min_angle_deg,
        },
        Measure {
            name: "max_angle_deg",
            label: "max angle°",
            better: Better::Smaller,
            value: |s| s.max_angle_deg,
        },
    ];
}
