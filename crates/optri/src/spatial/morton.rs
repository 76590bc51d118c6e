//! Z-order (Morton) numbering: points close in the plane get close indices,
//! so the memory-bound searches of the graph and criterion modules touch
//! nearby memory. The order only schedules work; it never decides anything.
//!
//! The grid is adaptive: points sharing a cell of the 2¹⁶ × 2¹⁶ grid over
//! their bounding box, when more than a few, are ordered again by a grid over
//! their own bounding box (a quadtree-like refinement, as in the Z-order of
//! Samet, *Foundations of Multidimensional and Metric Data Structures*, 2006,
//! §1.6, with the levels chosen by the data). Why: a cluster far below the
//! box's resolution (10⁶ points in a 10⁻⁹ box inside a unit box)
//! otherwise keeps the input's order, and the greedy rounds over it read
//! memory at random (16.8 s of round 0 at 10⁶ points against 1.0 s at 10⁵).

use crate::kernel::Point;

/// Runs of more than this many points in one cell are ordered again over
/// their own bounding box. A chosen value: far above the points a cell of
/// uniform inputs ever holds (10⁶ points in 2³² cells), so their order does
/// not change, and small enough that a cluster's run is split.
const REFINED_RUN: usize = 32;

/// Indices of `points` sorted by the Z-order (Morton) key of a 2¹⁶ × 2¹⁶ grid,
/// ties (more than [`REFINED_RUN`] points in a cell) by the same order over
/// their own bounding box, then by index.
pub(crate) fn morton_order(points: &[Point]) -> Vec<u32> {
    let mut order: Vec<u32> = (0..points.len() as u32).collect();
    order_by_cells(points, &mut order);
    order
}

/// Sorts `order` (indices into `points`) by Z-order over the bounding box of
/// its points, refining crowded cells. Terminates: a refined run lies in one
/// cell, 2⁻¹⁶ of the box in each direction, so every level shrinks the box by
/// 2¹⁶ (about 130 levels span the doubles), and a run of equal points stops.
fn order_by_cells(points: &[Point], order: &mut [u32]) {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for &v in order.iter() {
        let p = points[v as usize];
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    if lo == hi {
        return; // all equal (or empty): any order will do
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
    let mut keyed: Vec<u64> = order
        .iter()
        .map(|&v| {
            let p = &points[v as usize];
            ((spread(cell(p, 0)) | (spread(cell(p, 1)) << 1)) << 32) | v as u64
        })
        .collect();
    keyed.sort_unstable();
    for (slot, &k) in order.iter_mut().zip(&keyed) {
        *slot = k as u32;
    }
    let mut start = 0;
    while start < keyed.len() {
        let cell_key = keyed[start] >> 32;
        let end = start + keyed[start..].partition_point(|&k| k >> 32 == cell_key);
        if end - start > REFINED_RUN {
            order_by_cells(points, &mut order[start..end]);
        }
        start = end;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cluster 10⁻¹² wide in a unit box is ordered in Z-order within
    /// itself: its four quadrants come one after the other.
    #[test]
    fn a_cluster_below_the_grid_is_ordered_within_itself() {
        let mut points: Vec<Point> = vec![[0.0, 0.0], [1.0, 1.0]];
        // 400 points on a 20 × 20 lattice of step 10⁻¹⁴ at (0.5, 0.5), listed
        // in an order far from Z-order (column by column, odd rows first).
        for i in 0..20 {
            for j in (1..20).step_by(2).chain((0..20).step_by(2)) {
                points.push([0.5 + 1e-14 * i as f64, 0.5 + 1e-14 * j as f64]);
            }
        }
        let order = morton_order(&points);
        let mut sorted = order.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, (0..points.len() as u32).collect::<Vec<_>>());
        // Quadrant of a cluster point (lower/upper half in x and y).
        let quadrant = |v: u32| {
            let p = points[v as usize];
            let half = 0.5 + 9.5e-14;
            (p[0] > half) as u8 | (((p[1] > half) as u8) << 1)
        };
        let cluster: Vec<u8> = order
            .iter()
            .filter(|&&v| v >= 2)
            .map(|&v| quadrant(v))
            .collect();
        let changes = cluster.windows(2).filter(|w| w[0] != w[1]).count();
        assert_eq!(changes, 3, "{cluster:?}");
    }

    /// Equal points and a run of them do not recurse forever; every index
    /// comes once.
    #[test]
    fn equal_points_keep_every_index() {
        let mut points: Vec<Point> = vec![[0.25, 0.75]; 100];
        points.push([0.0, 0.0]);
        points.push([1.0, 1.0]);
        let mut order = morton_order(&points);
        order.sort_unstable();
        assert_eq!(order, (0..102).collect::<Vec<u32>>());
    }
}
