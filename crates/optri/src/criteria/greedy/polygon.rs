//! The greedy triangulation of a simple polygon ([`crate::triangulate`]
//! with `greedy`): shortest diagonal first, each kept unless it crosses one
//! kept earlier (the definition the greedy triangulation of a point set
//! follows; C. Levcopoulos & A. Lingas, *On approximation behavior of the
//! greedy triangulation for convex polygons*, Algorithmica 2, 1987).
//!
//! # Size
//! Every chord is listed and sorted before the scan: n(n − 3)/2 chords of 8
//! bytes (100 MB at 5000 vertices, about a minute with the crossing tests),
//! so polygons above [`MAX_GREEDY_POLYGON_VERTICES`] are refused before
//! anything is allocated, and the scan checks the run's stop token.
//!
//! # Degenerate input
//! The order is [`crate::kernel::segment_order`] on the ring positions, a
//! total order (exact squared length, ties by the kernel's perturbation), so
//! the greedy triangulation is unique.

use crate::criteria::{solve_convex_polygon, Diagnostics, Optimality, Options, Solved};
use crate::error::{Error, Result, UnsupportedReason};
use crate::interrupt::Stop;
use crate::kernel::{properly_cross, segment_order};
use crate::parallel::prelude::*;
use crate::structures::{PlanarGraph, SimplePolygon, Triangulation};
use crate::timing::{timed, Phase};

/// Largest polygon [`greedy_polygon`] takes: its chord list is
/// n(n − 3)/2 × 8 bytes, 200 MB at this size.
pub(crate) const MAX_GREEDY_POLYGON_VERTICES: usize = 7000;

/// `greedy` on a polygon: [`greedy_polygon`].
pub(crate) fn solve(
    polygon: &SimplePolygon,
    options: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    if let Some(solved) = solve_convex_polygon(polygon, options, phases, super::solve) {
        return solved;
    }
    let triangulation = timed(phases, "greedy", || greedy_polygon(polygon, options.stop()))?;
    Ok(Solved {
        triangulation,
        algorithm: "greedy on the polygon's diagonals: shortest first by the exact symbolic \
                    length order, each kept unless it crosses a kept one, O(n^3)"
            .to_string(),
        optimality: Optimality::Exact,
        diagnostics: Diagnostics::default(),
        bound: None,
        approximation: None,
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
///
/// # Errors
/// [`UnsupportedReason::TooManyPoints`] above
/// [`MAX_GREEDY_POLYGON_VERTICES`] vertices; [`Error::Interrupted`] when
/// `stop` says so (checked every 1024 chords).
pub(crate) fn greedy_polygon(polygon: &SimplePolygon, stop: &Stop) -> Result<Triangulation> {
    let pts = polygon.vertices();
    let n = pts.len();
    if n > MAX_GREEDY_POLYGON_VERTICES {
        return Err(Error::Unsupported {
            criterion: super::INFO.name,
            reason: UnsupportedReason::TooManyPoints {
                limit: MAX_GREEDY_POLYGON_VERTICES,
                distinct: n,
                because: "the list of all O(n²) chords, sorted by length",
            },
        });
    }
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
    for (k, [a, b]) in chords.into_iter().enumerate() {
        if kept.len() == n - 3 {
            break;
        }
        if k.is_multiple_of(1024) {
            stop.check()?;
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
