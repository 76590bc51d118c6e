//! GT of a strictly convex polygon by recursive splitting: Thm 4.2 (and
//! Corollary 4.1 for convex point sets) of C. Levcopoulos & A. Lingas, *On
//! approximation behavior of the greedy triangulation for convex polygons*,
//! Algorithmica 2 (1987).
//!
//! `Greedy(P)`: find a shortest diagonal of `P`, split along it, recurse.
//! The subpolygons partition `P`, so an explicit stack of them takes O(n)
//! space.
//!
//! The shortest diagonal of a convex polygon `Q` is found among O(|Q|)
//! candidates instead of Thm 4.1's all-shortest-diagonals algorithm (whose
//! all-nearest-neighbour subroutine is reported flawed, literature.md §e):
//! let `e = uv` be the shortest diagonal.
//! * If one side of `e` holds a single vertex, `e` cuts off an ear: it is one
//!   of the `|Q|` ear diagonals `v_{i-1} v_{i+1}`.
//! * Otherwise no vertex `z` lies in the closed disc with diameter `uv`: such
//!   a `z` has `|uz|, |zv| < |uv|` (angle `uzv ≥ 90°`), and since its side has
//!   two or more vertices, `z` is not adjacent to both `u` and `v`, so `uz` or
//!   `zv` is a shorter diagonal. An edge with an empty closed diametral disc
//!   belongs to *every* Delaunay triangulation of `Q`'s vertices, so `e` is a
//!   diagonal of the Delaunay triangulation of `Q`, whatever completion it
//!   picks for cocircular points.
//!
//! The Delaunay triangulation of `Q` is built per subpolygon by Chew's
//! randomised algorithm for convex polygons
//! ([`convex_delaunay`](super::convex_delaunay), literature.md §e) in expected
//! O(|Q|) time; with the O(|Q|) ear scan, a subpolygon costs expected O(|Q|).
//! There are `n - 3` splits (one per diagonal), each of a subpolygon of at
//! most `n` vertices, so this implementation takes expected O(n²) time in the
//! worst case, as in Thm 4.2. The randomness only affects the time: the
//! shortest diagonal is in every Delaunay completion, so the result is GT
//! whatever triangulation is built. Space is O(n): the stack of subpolygons
//! partitions `P`, and the Delaunay buffers are O(|Q|) and reused across
//! subpolygons.

use super::convex_delaunay::ConvexDelaunay;
use crate::kernel::{compare_lengths_symbolic, Point};
use std::cmp::Ordering;

/// GT edges (hull edges and diagonals) of the strictly convex polygon
/// `polygon` (ccw indices into `points`).
pub(super) fn greedy_convex(points: &[Point], polygon: &[u32]) -> Vec<[u32; 2]> {
    let k = polygon.len();
    let mut edges: Vec<[u32; 2]> = (0..k).map(|i| [polygon[i], polygon[(i + 1) % k]]).collect();
    let mut stack: Vec<Vec<u32>> = vec![polygon.to_vec()];
    let mut scratch = ConvexDelaunay::new();
    while let Some(q) = stack.pop() {
        if q.len() <= 3 {
            continue;
        }
        let (i, j) = shortest_diagonal(points, &q, &mut scratch);
        edges.push([q[i], q[j]]);
        let first: Vec<u32> = q[i..=j].to_vec();
        let mut second: Vec<u32> = q[j..].to_vec();
        second.extend_from_slice(&q[..=i]);
        stack.push(first);
        stack.push(second);
    }
    edges
}

/// Positions `i < j` in `q` of the endpoints of its shortest diagonal.
fn shortest_diagonal(points: &[Point], q: &[u32], scratch: &mut ConvexDelaunay) -> (usize, usize) {
    let k = q.len();
    let better = |a: (usize, usize), b: (usize, usize)| {
        compare_lengths_symbolic(points, [q[a.0], q[a.1]], [q[b.0], q[b.1]]) == Ordering::Less
    };
    // Ear diagonals v_{i-1} v_{i+1}.
    let mut best = (0, 2);
    for i in 0..k {
        let (a, b) = ((i + k - 1) % k, (i + 1) % k);
        let cand = if a < b { (a, b) } else { (b, a) };
        if better(cand, best) {
            best = cand;
        }
    }
    if k >= 6 {
        // Non-ear diagonals need two vertices on each side, hence k ≥ 6.
        scratch.triangulate(points, q);
        for [a, b] in scratch.diagonals() {
            let (a, b) = (a.min(b) as usize, a.max(b) as usize);
            let gap = b - a;
            if gap < 3 || gap > k - 3 {
                continue; // polygon edge or ear diagonal
            }
            if better((a, b), best) {
                best = (a, b);
            }
        }
    }
    best
}
