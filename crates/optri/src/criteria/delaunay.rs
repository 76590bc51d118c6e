//! The Delaunay triangulation as a criterion: it maximises the smallest
//! angle (B. Delaunay, *Sur la sphère vide*, 1934; Sibson 1978). The graph
//! itself is built in [`crate::graphs`]; this module only registers it.

use super::{CriterionEntry, CriterionInfo, Diagnostics, Optimality, Options, Solved};
use crate::error::Result;
use crate::graphs::delaunay;
use crate::structures::PointSet;
use crate::timing::{timed, Phase};

/// The registry's entry: this criterion's description and solvers.
pub(crate) const ENTRY: CriterionEntry = CriterionEntry {
    info: INFO,
    solve,
    solve_polygon: Some(super::polygon_criteria::solve_delaunay),
};

pub(crate) const INFO: CriterionInfo = CriterionInfo {
    name: "delaunay",
    description: "maximises the smallest angle (empty circumcircles)",
    optimality: Optimality::Exact,
    options: &[],
    reference: "B. Delaunay, Sur la sphère vide, 1934; bulk load by spade (exact predicates)",
};

pub(crate) fn solve(points: &PointSet, _: &Options, phases: &mut Vec<Phase>) -> Result<Solved> {
    let triangulation = timed(phases, "delaunay", || delaunay(points))?;
    Ok(Solved {
        triangulation,
        algorithm: "spade bulk-load Delaunay (exact predicates)".to_string(),
        optimality: Optimality::Exact,
        diagnostics: Diagnostics::default(),
        bound: None,
    })
}
