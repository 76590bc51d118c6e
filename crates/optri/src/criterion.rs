//! The registry of triangulation criteria, so front ends (CLI, demo, later
//! Python and web) can list, select and compare them uniformly.

use crate::error::{Error, Result};
use crate::point_set::PointSet;
use crate::triangulation::Triangulation;
use serde::Serialize;
use std::time::Instant;

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
    /// Minimum total edge length (convex position only, for now).
    MinWeight,
}

/// One timed phase of an algorithm run.
#[derive(Clone, Debug, Serialize)]
pub struct Phase {
    /// Phase name, e.g. `"delaunay"`.
    pub name: &'static str,
    /// Wall-clock milliseconds.
    pub ms: f64,
}

/// The result of [`triangulate`]: the triangulation and how it was obtained.
#[derive(Clone, Debug)]
pub struct Solution {
    /// The criterion that was optimised.
    pub criterion: Criterion,
    /// Whether the result is provably optimal for the criterion.
    pub exact: bool,
    /// The algorithm that ran (e.g. `"spade bulk load"`).
    pub algorithm: String,
    /// The triangulation.
    pub triangulation: Triangulation,
    /// Timed phases, in order.
    pub phases: Vec<Phase>,
}

impl Criterion {
    /// Every implemented criterion, in display order.
    pub const ALL: &'static [Criterion] = &[
        Criterion::Delaunay,
        Criterion::MinmaxLength,
        Criterion::Greedy,
        Criterion::MinWeight,
    ];

    /// The command-line name, e.g. `"delaunay"`, `"minmax-length"`.
    pub fn name(self) -> &'static str {
        match self {
            Criterion::Delaunay => "delaunay",
            Criterion::MinmaxLength => "minmax-length",
            Criterion::Greedy => "greedy",
            Criterion::MinWeight => "min-weight",
        }
    }

    /// One line describing what is optimised.
    pub fn description(self) -> &'static str {
        match self {
            Criterion::Delaunay => "maximises the smallest angle (empty circumcircles)",
            Criterion::MinmaxLength => "minimises the longest edge",
            Criterion::Greedy => {
                "greedy: repeatedly adds the shortest segment crossing no earlier one"
            }
            Criterion::MinWeight => {
                "minimises the total edge length (points in convex position only)"
            }
        }
    }

    /// Looks a criterion up by its [`name`](Self::name), ignoring ASCII case
    /// (as input-format names do), so `DELAUNAY` is `delaunay`.
    ///
    /// # Errors
    /// [`Error::Unsupported`] listing the available names.
    pub fn from_name(name: &str) -> Result<Self> {
        Self::ALL
            .iter()
            .copied()
            .find(|c| c.name().eq_ignore_ascii_case(name))
            .ok_or_else(|| {
                let names: Vec<&str> = Self::ALL.iter().map(|c| c.name()).collect();
                Error::Unsupported(format!(
                    "unknown criterion '{name}'; available: {}",
                    names.join(", ")
                ))
            })
    }
}

/// Times `f` as a phase named `name`.
pub(crate) fn timed<T>(phases: &mut Vec<Phase>, name: &'static str, f: impl FnOnce() -> T) -> T {
    let start = Instant::now();
    let out = f();
    phases.push(Phase {
        name,
        ms: start.elapsed().as_secs_f64() * 1e3,
    });
    out
}

/// Records consecutive phases: each [`lap`](Self::lap) closes the phase
/// that started at the previous lap (or at creation).
pub(crate) struct Stopwatch<'a> {
    phases: &'a mut Vec<Phase>,
    start: Instant,
}

impl<'a> Stopwatch<'a> {
    pub(crate) fn new(phases: &'a mut Vec<Phase>) -> Self {
        Self {
            phases,
            start: Instant::now(),
        }
    }

    /// Runs `f`, which records its own phases; the next lap starts when it
    /// returns.
    pub(crate) fn nested<T>(&mut self, f: impl FnOnce(&mut Vec<Phase>) -> T) -> T {
        let out = f(self.phases);
        self.start = Instant::now();
        out
    }

    pub(crate) fn lap(&mut self, name: &'static str) {
        let now = Instant::now();
        self.phases.push(Phase {
            name,
            ms: (now - self.start).as_secs_f64() * 1e3,
        });
        self.start = now;
    }
}

/// Triangulates `points` by `criterion`.
pub fn triangulate(points: &PointSet, criterion: Criterion) -> Result<Solution> {
    let mut phases = Vec::new();
    let (triangulation, exact, algorithm) = match criterion {
        Criterion::Delaunay => {
            let t = timed(&mut phases, "delaunay", || crate::delaunay(points))?;
            (
                t,
                true,
                "spade bulk-load Delaunay (exact predicates)".to_string(),
            )
        }
        Criterion::MinmaxLength => {
            let (t, algorithm) = crate::minmax_length::minmax_length_timed(points, &mut phases)?;
            (t, true, algorithm)
        }
        Criterion::Greedy => {
            let (t, algorithm) = crate::greedy::greedy_triangulation_timed(points, &mut phases)?;
            let how = match algorithm {
                crate::greedy::GreedyAlgorithm::Semicircular => {
                    "ear heap for semicircular polygons, Levcopoulos-Lingas Thm 4.3, O(n log n)"
                }
                crate::greedy::GreedyAlgorithm::Convex => {
                    "recursive splitting for convex position, Levcopoulos-Lingas Thm 4.2, expected O(n^2) time (Chew's convex-polygon Delaunay), O(n) space"
                }
                crate::greedy::GreedyAlgorithm::General => {
                    "exact length rounds decided by crossing dependencies (DDMW-style candidates, closed-vertex retirement)"
                }
            };
            (t, true, format!("{} ({how})", algorithm.name()))
        }
        Criterion::MinWeight => {
            let t = timed(&mut phases, "min-weight", || crate::min_weight(points))?;
            (
                t,
                false,
                "Klincsek dynamic program, O(n^3); optimal up to floating-point rounding of sums"
                    .to_string(),
            )
        }
    };
    Ok(Solution {
        criterion,
        exact,
        algorithm,
        triangulation,
        phases,
    })
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
}
