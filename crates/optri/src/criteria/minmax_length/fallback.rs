//! The cubic safety net of the quadratic algorithm: where it met an
//! inconsistency that the paper rules out (none in any test; the counters
//! say so), the exact cubic program triangulates the polygon instead.

use super::counters::Counters;
use super::length_order::LengthOrder;
use super::polygon::Region;
use crate::kernel::Point;

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
    out.extend(order.cubic(&region));
}
