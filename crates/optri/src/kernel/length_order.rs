//! One length order for every length-driven algorithm: a total order on the
//! segments of the kernel's perturbed points `S′`, with the lune tests and
//! the §5.1 vertex choice it induces (H. Edelsbrunner & T. S. Tan, *A
//! quadratic time algorithm for the minmax length triangulation*, 1991, §2,
//! §5.1, §7).
//!
//! Two orders implement it: [`EuclideanOrder`], the Euclidean length with
//! the kernel's symbolic tie-break, and a normed [`Metric`] with its
//! simulated strictly convex norm (the norm module's docs). Both are total
//! on the segments of `S′` (`Equal` only for the same segment), which is
//! what the relative neighbourhood graph of `S′`, Kruskal's algorithm and the
//! minmax-length algorithm (§5–§6) assume. Callers are generic over
//! [`LengthOrder`] and monomorphised, so the Euclidean path compiles to the
//! Euclidean predicates.
//!
//! Of the length-dependent steps of those algorithms only §5.1 step 1 (the
//! lune vertex nearest to the 1-edge `pq`) needs more than comparisons of
//! lengths; under a metric it takes the remark after §5.1 instead: the lune
//! vertex minimising `max(|xp|, |xq|)`, which the remark allows provided it
//! is visible from `p` and `q` — not automatic, so the caller checks it
//! ([`LengthOrder::CHOICE_IS_VISIBLE`]).

use super::lune::{in_half_lune_symbolic, in_lune_symbolic};
use super::norm::Metric;
use super::symbolic::{compare_lengths_symbolic, height_sign};
use super::Point;
use std::cmp::Ordering;

/// A total order on the segments of `S′` (indices into the points), with
/// the lune tests and the §5.1 choice it induces.
pub trait LengthOrder: Copy + Send + Sync {
    /// Is this the Euclidean order, which the rounded squared lengths of the
    /// squared-length module (`rounded_squared_length`, `in_one_key_run`)
    /// sort up to near-ties? A sort may then go by those keys first and
    /// call [`Self::compare`] only within runs of close keys.
    const EUCLIDEAN: bool;

    /// Is the vertex chosen by [`Self::nearer_to_edge`] visible from `p` and
    /// `q` whenever the chain is beyond the 1-edge `pq` (§5.1, proof of the
    /// Visibility Lemma for the nearest vertex)? If not, the caller checks.
    const CHOICE_IS_VISIBLE: bool;

    /// Compares `|ab|` with `|cd|` on `S′`; `Equal` only for the same segment.
    fn compare(self, points: &[Point], ab: [u32; 2], cd: [u32; 2]) -> Ordering;

    /// Is `x` strictly inside the lune of `pq` (`max(|xp|, |xq|) < |pq|`)?
    fn in_lune(self, points: &[Point], p: u32, q: u32, x: u32) -> bool;

    /// Is `x` in the half-lune `η_pq` (the lune, left of `p → q`)?
    fn in_half_lune(self, points: &[Point], p: u32, q: u32, x: u32) -> bool;

    /// §5.1 step 1: is the lune vertex `x` a better choice than `y` for the
    /// 1-edge `pq` (both on the chain's side of it)?
    fn nearer_to_edge(self, points: &[Point], p: u32, q: u32, x: u32, y: u32) -> bool;
}

/// The Euclidean order of the kernel's perturbation
/// ([`compare_lengths_symbolic`]).
#[derive(Clone, Copy, Debug, Default)]
pub struct EuclideanOrder;

impl LengthOrder for EuclideanOrder {
    const EUCLIDEAN: bool = true;
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
}

/// A normed metric's order, with its tie-break
/// ([`Metric::compare_lengths_symbolic`]). Not [`LengthOrder::EUCLIDEAN`]
/// even for [`Metric::euclidean`], whose comparisons are then the Euclidean
/// order's, only without the rounded keys.
impl LengthOrder for &Metric {
    const EUCLIDEAN: bool = false;
    const CHOICE_IS_VISIBLE: bool = false;

    #[inline]
    fn compare(self, points: &[Point], ab: [u32; 2], cd: [u32; 2]) -> Ordering {
        self.compare_lengths_symbolic(points, ab, cd)
    }

    #[inline]
    fn in_lune(self, points: &[Point], p: u32, q: u32, x: u32) -> bool {
        x != p && x != q && self.in_lune_symbolic(points, p, q, x)
    }

    #[inline]
    fn in_half_lune(self, points: &[Point], p: u32, q: u32, x: u32) -> bool {
        self.in_half_lune_symbolic(points, p, q, x)
    }

    /// The remark after §5.1: the smaller `max(|xp|, |xq|)` — comparisons
    /// only, no point-to-segment distance in the norm (§7). Not
    /// automatically visible from `p` and `q` in a non-convex region.
    fn nearer_to_edge(self, points: &[Point], p: u32, q: u32, x: u32, y: u32) -> bool {
        let longer_side = |x: u32| {
            if self.compare(points, [x, p], [x, q]) == Ordering::Less {
                [x, q]
            } else {
                [x, p]
            }
        };
        self.compare(points, longer_side(x), longer_side(y)) == Ordering::Less
    }
}
