//! GT of semicircular polygons in O(n log n): Thm 4.3 of C. Levcopoulos &
//! A. Lingas, *On approximation behavior of the greedy triangulation for
//! convex polygons*, Algorithmica 2 (1987).
//!
//! By Fact 3.1 (a nearest neighbour of a vertex of a semicircular polygon is
//! one of its two polygon neighbours), applied to the polygon with a vertex's
//! two neighbours removed, the shortest diagonal at `v_j` is `v_{j-2} v_j` or
//! `v_j v_{j+2}`: it cuts off one ear `v_{j±1}` that is not a base endpoint.
//! Cutting an ear off a semicircular polygon leaves a semicircular polygon
//! with the same base, so GT is: repeatedly cut off the ear whose diagonal is
//! shortest. A heap of the current ear diagonals makes that O(n log n).
//!
//! Ties: Fact 3.1 holds for *every* nearest neighbour, so exactly tied
//! non-ear diagonals cannot exist at `v_j`, and the heap uses the same
//! symbolic order as every other algorithm.

use crate::kernel::{
    compare_lengths, compare_lengths_symbolic, compare_rounded_keys, dot_sign,
    rounded_squared_length, Point,
};
use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// If the convex polygon `polygon` (ccw) is semicircular, returns it rotated
/// so that its base is the closing edge `polygon[k-1] → polygon[0]`.
pub(super) fn base_rotation(points: &[Point], polygon: &[u32]) -> Option<Vec<u32>> {
    let k = polygon.len();
    let p = |i: usize| points[polygon[i % k] as usize];
    // Only the longest edge can be the base: every other vertex strictly
    // inside its diametral circle makes it strictly longer than any segment.
    let base = (0..k).max_by(|&i, &j| compare_lengths(p(i), p(i + 1), p(j), p(j + 1)))?;
    let (a, b) = (p(base), p(base + 1));
    let inside = (0..k)
        .filter(|&i| i != base && i != (base + 1) % k)
        .all(|i| dot_sign(p(i), a, b) < 0);
    if !inside {
        return None;
    }
    // Start right after the base: polygon[base+1], ..., polygon[base].
    Some((1..=k).map(|i| polygon[(base + i) % k]).collect())
}

struct Ear<'a> {
    points: &'a [Point],
    /// Rounded squared length: decides unless two keys are within rounding.
    key: f64,
    diagonal: [u32; 2],
    /// Position (in the rotated polygon) of the vertex the diagonal cuts off.
    apex: u32,
}

impl PartialEq for Ear<'_> {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for Ear<'_> {}
impl PartialOrd for Ear<'_> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Ear<'_> {
    /// Reversed, so the max-heap pops the shortest diagonal.
    fn cmp(&self, other: &Self) -> Ordering {
        // The rounded keys decide clear cases (the kernel's filter).
        let by_key = compare_rounded_keys(self.key, other.key).unwrap_or_else(|| {
            compare_lengths_symbolic(self.points, self.diagonal, other.diagonal)
        });
        by_key.reverse().then(other.apex.cmp(&self.apex))
    }
}

/// GT edges (polygon edges and diagonals) of a semicircular polygon given
/// ccw with its base as the closing edge (see [`base_rotation`]).
pub(super) fn greedy_semicircular(points: &[Point], polygon: &[u32]) -> Vec<[u32; 2]> {
    let k = polygon.len();
    let mut edges: Vec<[u32; 2]> = (0..k).map(|i| [polygon[i], polygon[(i + 1) % k]]).collect();
    if k <= 3 {
        return edges;
    }
    // Linked list over positions; positions 0 and k-1 are the base endpoints
    // and are never cut off.
    let mut prev: Vec<u32> = (0..k as u32).map(|i| i.wrapping_sub(1)).collect();
    let mut next: Vec<u32> = (1..=k as u32).collect();
    let mut alive = vec![true; k];
    // Coordinates in polygon order, so the heap work touches memory locally.
    let local: Vec<Point> = polygon.iter().map(|&v| points[v as usize]).collect();
    let ear = |prev: &[u32], next: &[u32], i: u32| {
        let (l, r) = (prev[i as usize] as usize, next[i as usize] as usize);
        Ear {
            points,
            key: rounded_squared_length(local[l], local[r]),
            diagonal: [polygon[l], polygon[r]],
            apex: i,
        }
    };
    let mut heap: BinaryHeap<Ear> = (1..k as u32 - 1).map(|i| ear(&prev, &next, i)).collect();
    let mut remaining = k;
    while remaining > 3 {
        let Some(top) = heap.pop() else { break };
        let i = top.apex as usize;
        // Lazy deletion: skip ears whose vertex is gone or whose neighbours changed.
        let current = [polygon[prev[i] as usize], polygon[next[i] as usize]];
        if !alive[i] || current != top.diagonal {
            continue;
        }
        edges.push(top.diagonal);
        alive[i] = false;
        remaining -= 1;
        let (l, r) = (prev[i], next[i]);
        next[l as usize] = r;
        prev[r as usize] = l;
        for v in [l, r] {
            if v != 0 && v != k as u32 - 1 {
                heap.push(ear(&prev, &next, v));
            }
        }
    }
    edges
}
