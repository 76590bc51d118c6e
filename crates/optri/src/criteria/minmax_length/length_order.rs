//! The length order that the rng-polygon algorithm (`rng_polygon/`) and its
//! cubic safety net compare by: Euclidean, or a normed metric simulated by a
//! strictly convex norm (Edelsbrunner & Tan, *A quadratic time algorithm for
//! the minmax length triangulation*, 1991, §7; kernel norm docs). Both are
//! total orders on the segments of the kernel's perturbed points `S′`
//! (`Equal` only for the same segment), which is what §5–§6 assume.
//!
//! The algorithm is generic over [`LengthOrder`] and monomorphised, so the
//! Euclidean path compiles to the code it had before the metric one existed.
//!
//! Of the algorithm's length-dependent steps only §5.1 step 1 (the lune
//! vertex nearest to the 1-edge `pq`) needs more than comparisons of
//! lengths; under a metric it takes the remark after §5.1 instead: the lune
//! vertex minimising `max(|xp|, |xq|)`, which the remark allows provided it
//! is visible from `p` and `q` — not automatic, so the caller checks it
//! ([`LengthOrder::CHOICE_IS_VISIBLE`]).

use super::polygon::Region;
use crate::kernel::{
    compare_lengths_symbolic, height_sign, in_half_lune_symbolic, in_lune_symbolic,
};
use crate::kernel::{Metric, Point};
use crate::polygon_program::{optimal_triangulation, LargestDiagonal};
use std::cmp::Ordering;

/// A total order on the segments of `S′`, with the lune tests and the §5.1
/// choice it induces, and §3's cubic program under it.
pub(crate) trait LengthOrder: Copy + Send + Sync {
    /// Is the vertex chosen by [`Self::nearer_to_edge`] visible from `p` and
    /// `q` whenever the chain is beyond the 1-edge `pq` (§5.1, proof of the
    /// Visibility Lemma for the nearest vertex)? If not, the caller checks.
    const CHOICE_IS_VISIBLE: bool;

    /// Compares `|ab|` with `|cd|` on `S′`; `Equal` only for the same segment.
    fn compare(self, points: &[Point], ab: [u32; 2], cd: [u32; 2]) -> Ordering;

    /// Is `x` strictly inside the lune of `pq`?
    fn in_lune(self, points: &[Point], p: u32, q: u32, x: u32) -> bool;

    /// Is `x` in the half-lune `η_pq` (the lune, left of `p → q`)?
    fn in_half_lune(self, points: &[Point], p: u32, q: u32, x: u32) -> bool;

    /// §5.1 step 1: is the lune vertex `x` a better choice than `y` for the
    /// 1-edge `pq` (both on the chain's side of it)?
    fn nearer_to_edge(self, points: &[Point], p: u32, q: u32, x: u32, y: u32) -> bool;

    /// §3's cubic program on `region` with this order on its chords.
    fn cubic(self, region: &Region) -> Vec<[u32; 3]>;
}

/// The Euclidean order of the kernel's perturbation.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct EuclideanOrder;

impl LengthOrder for EuclideanOrder {
    const CHOICE_IS_VISIBLE: bool = true;

    #[inline]
    fn compare(self, points: &[Point], ab: [u32; 2], cd: [u32; 2]) -> Ordering {
        if (ab[0] == cd[0] && ab[1] == cd[1]) || (ab[0] == cd[1] && ab[1] == cd[0]) {
            return Ordering::Equal; // the same segment: skip the exact fallback
        }
        compare_lengths_symbolic(points, ab, cd)
    }

    #[inline]
    fn in_lune(self, points: &[Point], p: u32, q: u32, x: u32) -> bool {
        in_lune_symbolic(points, p, q, x)
    }

    #[inline]
    fn in_half_lune(self, points: &[Point], p: u32, q: u32, x: u32) -> bool {
        in_half_lune_symbolic(points, p, q, x)
    }

    /// The paper's choice: the smaller distance from the line `pq`
    /// (equivalently from the segment, for lune vertices on one side).
    #[inline]
    fn nearer_to_edge(self, points: &[Point], p: u32, q: u32, x: u32, y: u32) -> bool {
        height_sign(points, p, q, x, y) > 0
    }

    fn cubic(self, region: &Region) -> Vec<[u32; 3]> {
        region.minmax_triangulation_cubic()
    }
}

/// A normed metric's order, with its tie-break ([`Metric::compare_lengths_symbolic`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct MetricOrder<'a>(pub &'a Metric);

impl MetricOrder<'_> {
    /// The longer of `xp` and `xq`.
    fn longer_side(self, points: &[Point], p: u32, q: u32, x: u32) -> [u32; 2] {
        if self.compare(points, [x, p], [x, q]) == Ordering::Less {
            [x, q]
        } else {
            [x, p]
        }
    }
}

impl LengthOrder for MetricOrder<'_> {
    const CHOICE_IS_VISIBLE: bool = false;

    #[inline]
    fn compare(self, points: &[Point], ab: [u32; 2], cd: [u32; 2]) -> Ordering {
        self.0.compare_lengths_symbolic(points, ab, cd)
    }

    #[inline]
    fn in_lune(self, points: &[Point], p: u32, q: u32, x: u32) -> bool {
        x != p && x != q && self.0.in_lune_symbolic(points, p, q, x)
    }

    #[inline]
    fn in_half_lune(self, points: &[Point], p: u32, q: u32, x: u32) -> bool {
        self.0.in_half_lune_symbolic(points, p, q, x)
    }

    /// The remark after §5.1: the smaller `max(|xp|, |xq|)` — comparisons
    /// only, no point-to-segment distance in the norm (§7). Not
    /// automatically visible from `p` and `q` in a non-convex region.
    fn nearer_to_edge(self, points: &[Point], p: u32, q: u32, x: u32, y: u32) -> bool {
        let (sx, sy) = (
            self.longer_side(points, p, q, x),
            self.longer_side(points, p, q, y),
        );
        self.compare(points, sx, sy) == Ordering::Less
    }

    fn cubic(self, region: &Region) -> Vec<[u32; 3]> {
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
                self.compare(region.points, [v[s[0]], v[s[1]]], [v[t[0]], v[t[1]]])
            }),
        )
        .expect("a polygonal region always has a triangulation")
        .triangles
        .into_iter()
        .map(|t| t.map(|c| v[c]))
        .collect()
    }
}
