//! Z-order (Morton) numbering: points close in the plane get close indices,
//! so the memory-bound searches of the graph and criterion modules touch
//! nearby memory. The order only schedules work; it never decides anything.

use crate::kernel::Point;

/// Indices of `points` sorted by the Z-order (Morton) key of a 2¹⁶ × 2¹⁶ grid.
pub(crate) fn morton_order(points: &[Point]) -> Vec<u32> {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in points {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let spread = |mut v: u64| {
        v = (v | (v << 8)) & 0x00FF_00FF;
        v = (v | (v << 4)) & 0x0F0F_0F0F;
        v = (v | (v << 2)) & 0x3333_3333;
        (v | (v << 1)) & 0x5555_5555
    };
    let cell = |p: &Point, k: usize| {
        // Scale by the extent; the result only orders the work, never decides.
        let t = (p[k] - lo[k]) / (hi[k] - lo[k]);
        ((t * 65535.0) as u64).min(65535)
    };
    let mut keyed: Vec<u64> = points
        .iter()
        .enumerate()
        .map(|(i, p)| ((spread(cell(p, 0)) | (spread(cell(p, 1)) << 1)) << 32) | i as u64)
        .collect();
    keyed.sort_unstable();
    keyed.into_iter().map(|k| k as u32).collect()
}
