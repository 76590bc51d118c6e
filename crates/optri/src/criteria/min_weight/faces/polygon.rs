//! Klincsek's program on a simple region of the skeleton (module docs of
//! `faces`), over the candidate diagonals inside it.

use super::super::skeleton::Skeleton;
use super::super::TotalLength;
use crate::interrupt::Stop;
use crate::kernel::{orient_sign, Point};
use crate::polygon_program::optimal_triangulation_until;
use crate::structures::PolygonCycle;

/// Klincsek's program on a simple region (one boundary walk, no inner
/// point), over the candidate diagonals inside it; `None` for a region
/// beyond `limit` corners.
///
/// # Errors
/// [`crate::Error::Interrupted`] when `stop` says so.
pub(super) fn solve_polygon(
    pts: &[Point],
    sk: &Skeleton,
    cycle: &[u32],
    limit: usize,
    stop: &Stop,
) -> crate::error::Result<Option<Vec<[u32; 3]>>> {
    let k = cycle.len();
    if k > limit {
        return Ok(None); // O(k²) tables: the region keeps its fallback
    }
    let corners = PolygonCycle::exact(pts, cycle);
    let p = |i: usize| pts[cycle[i] as usize];
    let Some(solved) = optimal_triangulation_until(
        k,
        |i, j| {
            let (u, w) = (cycle[i], cycle[j]);
            u != w
                && sk.edge_id(u, w).is_some_and(|e| sk.alive[e as usize])
                && corners.leaves_corner_into(i, w)
                && corners.leaves_corner_into(j, u)
        },
        |i, m, j| orient_sign(p(i), p(m), p(j)) != 0,
        &TotalLength { point: &p },
        stop,
    )?
    else {
        return Ok(None);
    };
    Ok(Some(
        solved
            .triangles
            .into_iter()
            .map(|t| {
                let t = t.map(|c| cycle[c]);
                if orient_sign(pts[t[0] as usize], pts[t[1] as usize], pts[t[2] as usize]) > 0 {
                    t
                } else {
                    [t[0], t[2], t[1]]
                }
            })
            .collect(),
    ))
}
