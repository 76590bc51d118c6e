//! Lower-bound certificates that let a region keep its Delaunay triangles
//! without running a polygon algorithm: the Length Lemma (§4) for the whole
//! input or a region, and, for small regions, the apex lower bound (§3).

use super::counters::Counters;
use super::polygon::{ChordLengths, Region};
use super::regions::LocalMesh;
use crate::kernel::{compare_lengths, Point};
use crate::parallel::prelude::*;
use crate::structures::DelaunayGraph;
use std::cmp::Ordering::{Greater, Less};

/// The longest edge of `ch(S) ∪ rng(S′)` (of `ch(S)` alone without `rng`),
/// as its two endpoints: a lower bound on the optimum. Hull edges are in every triangulation, and by §4's
/// Length Lemma every triangulation of `S` has an edge at least as long as
/// the longest edge of `rng(S) ⊇ rng(S′)`. So a triangulation whose edges are
/// all no longer than this is optimal, and a region whose Delaunay triangles
/// are no longer than this may keep them: the assembled result's longest edge
/// is then the largest of this bound and the other regions' optima, each of
/// which is at most the global optimum. (Regions so kept are not necessarily
/// minmax triangulations *of the region*; the whole is optimal.)
pub(super) fn length_lemma_bound(
    points: &[Point],
    g: &DelaunayGraph,
    rng: Option<&[bool]>,
) -> [Point; 2] {
    let p = |v: u32| points[v as usize];
    g.edges
        .par_iter()
        .enumerate()
        .filter(|(i, (_, apex))| apex.contains(&None) || rng.is_some_and(|r| r[*i]))
        .map(|(_, &([u, v], _))| [p(u), p(v)])
        .reduce_with(|x, y| {
            if compare_lengths(x[0], x[1], y[0], y[1]) == Less {
                y
            } else {
                x
            }
        })
        .expect("a triangulation has hull edges")
}

/// The longest side of the given Delaunay triangles (exact), as a vertex pair.
pub(super) fn longest_side(
    points: &[Point],
    g: &DelaunayGraph,
    triangles: impl Iterator<Item = u32>,
) -> Option<[u32; 2]> {
    let p = |v: u32| points[v as usize];
    let longer = |x: [u32; 2], y: [u32; 2]| {
        if compare_lengths(p(x[0]), p(x[1]), p(y[0]), p(y[1])) == Less {
            y
        } else {
            x
        }
    };
    triangles
        .flat_map(|t| {
            let [a, b, c] = g.triangles[t as usize];
            [[a, b], [b, c], [c, a]]
        })
        .reduce(longer)
}

/// A region with fewer than [`SMALL_REGION`](super::SMALL_REGION) corners. A quadrilateral takes
/// its shorter diagonal. Otherwise every triangulation has an edge at least
/// as long as the apex lower bound, so a triangulation of the region whose
/// diagonals are no longer is optimal: first the region's Delaunay
/// triangles, then the same after flipping its longest diagonal while that
/// shortens it. Failing both, the cubic program runs on chords no longer
/// than the flipped triangulation's longest diagonal (a feasible solution,
/// so the optimum uses no longer chord).
pub(super) fn small_region(
    region: &Region,
    mesh: impl FnOnce() -> LocalMesh,
    counters: &Counters,
) -> Vec<[u32; 3]> {
    if let Some(t) = region.quadrilateral() {
        return t;
    }
    let lengths = ChordLengths::new(region);
    let [a, b] = region.apex_lower_bound(&lengths);
    let v = region.vertices;
    let lower = [v[a], v[b]];
    let mut mesh = mesh();
    let no_longer =
        |d: Option<[u32; 2]>| d.is_none_or(|d| region.compare_lengths(d, lower) != Greater);
    let upper = mesh.flip_longest_diagonals(region.points);
    if no_longer(upper) {
        counters.small_regions_certified.add(1);
        return mesh.triangles;
    }
    counters.small_regions_by_dp.add(1);
    region.minmax_triangulation_with(upper, &lengths)
}
