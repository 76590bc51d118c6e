//! The greedy triangulation of a simple polygon ([`crate::triangulate`]
//! with `greedy`): shortest diagonal first, each kept unless it crosses one
//! kept earlier (the definition the greedy triangulation of a point set
//! follows; C. Levcopoulos & A. Lingas, *On approximation behavior of the
//! greedy triangulation for convex polygons*, Algorithmica 2, 1987).
//!
//! # Degenerate input
//! The order is [`crate::kernel::segment_order`] on the ring positions, a
//! total order (exact squared length, ties by the kernel's perturbation), so
//! the greedy triangulation is unique.

use crate::criteria::{Diagnostics, Optimality, Options, Solved};
use crate::error::{Error, Result};
use crate::kernel::{properly_cross, segment_order};
use crate::parallel::prelude::*;
use crate::structures::{PlanarGraph, SimplePolygon, Triangulation};
use crate::timing::{timed, Phase};

/// `greedy` on a polygon: [`greedy_polygon`].
pub(crate) fn solve(
    polygon: &SimplePolygon,
    _: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    let triangulation = timed(phases, "greedy", || greedy_polygon(polygon))?;
    Ok(Solved {
        triangulation,
        algorithm: "greedy on the polygon's diagonals: shortest first by the exact symbolic \
                    length order, each kept unless it crosses a kept one, O(n^3)"
            .to_string(),
        optimality: Optimality::Exact,
        diagnostics: Diagnostics::default(),
        bound: None,
    })
}

/// The greedy triangulation of a simple polygon: its diagonals
/// ([`SimplePolygon::is_diagonal`]) in the order of
/// [`crate::kernel::segment_order`] (exact squared length, ties by the
/// kernel's perturbation of the ring positions), each kept unless it crosses
/// one kept earlier. Two diagonals conflict only by crossing properly: their
/// open segments contain no vertex, so they cannot overlap or touch
/// elsewhere. Chords are tested for crossings first and for being diagonals
/// only then; O(n³) worst case.
pub(crate) fn greedy_polygon(polygon: &SimplePolygon) -> Result<Triangulation> {
    let pts = polygon.vertices();
    let n = pts.len();
    let mut chords: Vec<[u32; 2]> = Vec::with_capacity(n * (n - 1) / 2);
    for a in 0..n as u32 {
        for b in a + 2..n as u32 {
            if !(a == 0 && b as usize == n - 1) {
                chords.push([a, b]);
            }
        }
    }
    let order = segment_order(pts);
    chords.par_sort_unstable_by(|s, t| order(s, t));
    let p = |i: u32| pts[i as usize];
    let mut kept: Vec<[u32; 2]> = Vec::with_capacity(n.saturating_sub(3));
    for [a, b] in chords {
        if kept.len() == n - 3 {
            break;
        }
        let crossing = kept
            .iter()
            .rev()
            .any(|&[c, d]| properly_cross(p(a), p(b), p(c), p(d)));
        if !crossing && polygon.is_diagonal(a as usize, b as usize) {
            kept.push([a, b]);
        }
    }
    if kept.len() != n - 3 {
        return Err(Error::Internal(format!(
            "the greedy diagonals of a {n}-gon are {} (not n - 3)",
            kept.len()
        )));
    }
    let mut edges = kept;
    edges.extend((0..n as u32).map(|i| [i, (i + 1) % n as u32]));
    let mut triangles = Vec::with_capacity(n - 2);
    for face in PlanarGraph::new(pts, &edges).bounded_faces(pts) {
        match face.vertices[..] {
            [a, b, c] => triangles.push([a, b, c]),
            _ => {
                return Err(Error::Internal(format!(
                    "a face of the greedy polygon triangulation has {} corners",
                    face.vertices.len()
                )))
            }
        }
    }
    Ok(Triangulation::from_polygon_positions(polygon, triangles))
}
