//! §3's cubic program under any length order, and the cubic safety net of
//! the quadratic algorithm: where it met an inconsistency that the paper
//! rules out (none in any test; the counters say so), the exact cubic
//! program triangulates the polygon instead.

use super::counters::Counters;
use super::polygon::Region;
use crate::kernel::{LengthOrder, Point};
use crate::polygon_program::{optimal_triangulation, LargestDiagonal};

/// A polygon that the cubic program triangulates because the quadratic
/// algorithm met an inconsistency, which the paper rules out (none in any
/// test).
#[derive(Clone, Copy, Debug)]
pub(crate) enum Fallback {
    /// A whole region. Triangulated on the input points `S`: the cubic
    /// program needs no general position.
    Region,
    /// The part of a §6 Case 2 side left after step 1, when the hull chain of
    /// step 2 fails its check. On the perturbed points `S′`, whose diagonals
    /// cut it out.
    Case2Remainder,
    /// One pocket `Y_uv` of §6 Case 2 step 3 that failed its check; on `S′`.
    Case2Pocket,
}

/// The cubic safety net: counts the `part`, drops what `out` gained since
/// `mark` and appends the cubic program's triangulation of the polygon
/// `vertices` (counter-clockwise), with chords compared by `order`.
pub(crate) fn cubic_fallback(
    points: &[Point],
    order: impl LengthOrder,
    part: Fallback,
    vertices: &[u32],
    counters: &Counters,
    out: &mut Vec<[u32; 3]>,
    mark: usize,
) {
    match part {
        Fallback::Region => counters.fallbacks.add(1),
        Fallback::Case2Remainder => {
            counters.case_2_hull_fallbacks.add(1);
            counters.case_2_remainder_vertices.add(vertices.len());
        }
        Fallback::Case2Pocket => {
            counters.fallbacks.add(1);
            counters.case_2_pocket_fallbacks.add(1);
            counters.case_2_remainder_vertices.add(vertices.len());
        }
    }
    out.truncate(mark);
    let region = Region {
        points,
        vertices,
        symbolic: !matches!(part, Fallback::Region),
    };
    out.extend(cubic_program(order, &region));
}

/// §3's cubic program on `region` (Edelsbrunner & Tan 1991): a triangulation
/// minimising the longest diagonal, its chords compared by `order`.
///
/// The Euclidean order runs the region's own program, whose rounded chord
/// keys filter the comparisons and whose lengths are those of the region's
/// point set (`S`, or `S′` for a symbolic region); any other order runs the
/// polygon program with the order's comparisons (always on `S′`).
pub(crate) fn cubic_program<O: LengthOrder>(order: O, region: &Region) -> Vec<[u32; 3]> {
    if O::EUCLIDEAN {
        return region.minmax_triangulation_cubic();
    }
    let v = region.vertices;
    let k = v.len();
    if k == 3 {
        return vec![[v[0], v[1], v[2]]];
    }
    let convex = region.is_strictly_convex();
    optimal_triangulation(
        k,
        |i, j| convex || region.is_diagonal(i, j),
        |i, m, j| region.orient(v[i], v[m], v[j]) > 0,
        &LargestDiagonal::new(k, |s: [usize; 2], t: [usize; 2]| {
            order.compare(region.points, [v[s[0]], v[s[1]]], [v[t[0]], v[t[1]]])
        }),
    )
    .expect("a polygonal region always has a triangulation")
    .triangles
    .into_iter()
    .map(|t| t.map(|c| v[c]))
    .collect()
}
