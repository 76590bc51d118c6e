//! The Delaunay triangulation as a criterion: it maximises the smallest
//! angle (B. Delaunay, *Sur la sphère vide*, 1934; Sibson 1978). The graph
//! itself is built in [`crate::graphs`]; this module registers it, and on a
//! simple polygon takes the constrained Delaunay triangulation of its
//! interior ([`constrained_delaunay_polygon`]).
//!
//! # Degenerate input
//! Cocircular points: the Delaunay graph and the constrained Delaunay
//! triangulation both fan every face of four or more cocircular points from
//! its smallest index (the regular triangulation of an infinitesimal
//! lifting perturbation), so the answer does not depend on how spade built
//! it. A polygon's vertices are numbered in lexicographic order of their
//! coordinates for this, so its triangles depend on the polygon alone, not
//! on where its ring starts.

use super::{CriterionEntry, CriterionInfo, Diagnostics, Optimality, Options, Solved};
use crate::error::{Error, Result};
use crate::graphs::delaunay;
use crate::kernel::Point;
use crate::structures::{ConstrainedDelaunay, PointSet, SimplePolygon, Triangulation};
use crate::timing::{timed, Phase};

/// The registry's entry: this criterion's description and solvers.
pub(crate) const ENTRY: CriterionEntry = CriterionEntry {
    info: INFO,
    solve,
    solve_polygon: Some(solve_polygon),
};

pub(crate) const INFO: CriterionInfo = CriterionInfo {
    name: "delaunay",
    description: "maximises the smallest angle (empty circumcircles)",
    optimality: Optimality::Exact,
    options: &[],
    reference: "B. Delaunay, Sur la sphère vide, 1934; bulk load by spade (exact predicates)",
    needs_elevations: false,
    measure: Some(crate::structures::Measure::MinAngle),
};

pub(crate) fn solve(points: &PointSet, _: &Options, phases: &mut Vec<Phase>) -> Result<Solved> {
    let triangulation = timed(phases, "delaunay", || delaunay(points))?;
    Ok(Solved {
        triangulation,
        algorithm: "spade bulk-load Delaunay (exact predicates)".to_string(),
        optimality: Optimality::Exact,
        diagnostics: Diagnostics::default(),
        bound: None,
        approximation: None,
    })
}

/// `delaunay` on a simple polygon: [`constrained_delaunay_polygon`].
pub(crate) fn solve_polygon(
    polygon: &SimplePolygon,
    _: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    let triangulation = timed(phases, "constrained delaunay", || {
        constrained_delaunay_polygon(polygon)
    })?;
    Ok(Solved {
        triangulation,
        algorithm: "spade constrained Delaunay triangulation of the polygon's interior (exact \
                    predicates)"
            .to_string(),
        optimality: Optimality::Exact,
        diagnostics: Diagnostics::default(),
        bound: None,
        approximation: None,
    })
}

/// The constrained Delaunay triangulation of a simple polygon's interior
/// (D. T. Lee & A. K. Lin, *Generalized Delaunay triangulation for planar
/// graphs*, 1986; L. P. Chew, *Constrained Delaunay triangulations*, 1989):
/// every interior edge is locally Delaunay, which among the triangulations of
/// the polygon maximises the smallest angle. The vertices, numbered in
/// lexicographic order of their coordinates, are triangulated with the
/// boundary edges as constraints ([`ConstrainedDelaunay`], canonical on
/// cocircular vertices); the triangles inside the polygon are found
/// combinatorially, from those on the left of the counter-clockwise
/// boundary edges across sides that are not boundary edges (no constraint
/// is crossed, so none leaves the polygon).
pub(crate) fn constrained_delaunay_polygon(polygon: &SimplePolygon) -> Result<Triangulation> {
    let pts = polygon.vertices();
    let n = pts.len();
    // Ring positions in lexicographic order (distinct points: a total order
    // that exact scalings, translations and the ring's start all keep).
    let mut order: Vec<u32> = (0..n as u32).collect();
    order.sort_unstable_by(|&a, &b| {
        let (p, q) = (pts[a as usize], pts[b as usize]);
        // `-0.0 == 0.0`, as a translation sees them.
        (p[0], p[1])
            .partial_cmp(&(q[0], q[1]))
            .expect("finite coordinates")
    });
    let mut rank = vec![0u32; n];
    for (r, &v) in order.iter().enumerate() {
        rank[v as usize] = r as u32;
    }
    let sorted: Vec<Point> = order.iter().map(|&v| pts[v as usize]).collect();
    let boundary: Vec<[u32; 2]> = (0..n).map(|i| [rank[i], rank[(i + 1) % n]]).collect();
    let cdt = ConstrainedDelaunay::new(&sorted, &boundary)?;
    let mut side_of: std::collections::HashMap<(u32, u32), (usize, usize)> =
        std::collections::HashMap::with_capacity(3 * cdt.triangles.len());
    for (t, tri) in cdt.triangles.iter().enumerate() {
        for j in 0..3 {
            side_of.insert((tri[j], tri[(j + 1) % 3]), (t, j));
        }
    }
    let ccw = polygon.counter_clockwise();
    let mut inside = vec![false; cdt.triangles.len()];
    let mut stack = Vec::with_capacity(n);
    for c in 0..n {
        let (u, v) = (rank[ccw[c] as usize], rank[ccw[(c + 1) % n] as usize]);
        let Some(&(t, _)) = side_of.get(&(u, v)) else {
            return Err(Error::Internal(format!(
                "no constrained Delaunay triangle on the inner side of boundary edge ({}, {})",
                ccw[c],
                ccw[(c + 1) % n]
            )));
        };
        stack.push(t);
    }
    while let Some(t) = stack.pop() {
        if inside[t] {
            continue;
        }
        inside[t] = true;
        for j in 0..3 {
            if !cdt.is_barrier(t, j) {
                stack.push(cdt.neighbours[t][j] as usize);
            }
        }
    }
    let kept: Vec<[u32; 3]> = cdt
        .triangles
        .iter()
        .zip(inside)
        .filter_map(|(t, keep)| keep.then_some(t.map(|r| order[r as usize])))
        .collect();
    if kept.len() != n - 2 {
        return Err(Error::Internal(format!(
            "{} constrained Delaunay triangles inside a {n}-gon",
            kept.len()
        )));
    }
    Ok(Triangulation::from_polygon_positions(polygon, kept))
}
