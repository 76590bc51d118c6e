//! MaxMin-area and MinMax-area triangulations of a strictly convex polygon,
//! exactly, in O(n² log n) time and O(n²) space.
//!
//! Source: T. S. Vassilev, *Optimal Area Triangulation*, PhD thesis,
//! University of Saskatchewan, 2005, Chapter 2: Algorithm 44
//! (§2.3, L1807-1864; Theorem 48, L2339) and the decision Algorithm 49
//! (§2.4, L2366-2550; Lemma 50, Theorem 51), **with its step iv repaired**.
//! The repairs, named where they are made:
//! - **T1** (§2.3.2, L2003): `k ↦ μ*(P_ik)` is only quasi-concave on `I_i`,
//!   with plateaus, so the argmax is found by a linear scan, not by the
//!   printed binary search.
//! - **T2** (L1846-1860): boundary edges are never sub-problems of step iv
//!   (only `k ∈ [i+2, j−2]`, only proper diagonals `(i, j)`): with a
//!   neutral `+∞` on an edge, a small triangle on it would pass unseen.
//! - **T4** (L2072): the MinMax objective of a triangle `(i, k, j)` keeps
//!   its own area `A(i,k,j)`, which the printed rule drops (the thesis's
//!   Fig. 2.10 has an internal triangle as the largest).
//! - **T5, T6** (L2182; Cor. 43): `λ*(P_kj)` alone has plateaus above its
//!   minimum; the search runs on the predicate `A(i,k,j) < λ*(P_kj)`,
//!   monotone by Lemma 42, which proves the unimodality of
//!   `G(k) = max(λ*(P_kj), A(i,k,j))` only.
//! - **T7** (L2072-2110, L2232): the search stays in the strip of `(i, j)`
//!   and where both pieces are solved, `[j − mccw(j), i + mcw(i)]`.
//! - **T10** (Prop. 39): `mcw`/`mccw` come straight from the exact zonality
//!   test, not from `Top` (whose tie case Property 39 misses).
//!
//! The zonality test is `z(P_ij) ≤ 2 ⟺ cross(v_{i+1} − v_i, v_{j−1} − v_j) ·
//! orient(v_i, v_j, v_{i+1}) ≥ 0` (the base angles add up to at most a half
//! turn), and zonality grows with the chain (its total turning does), which
//! steps ii–iii use. Every triangulation has a proper diagonal with both
//! pieces of zonality ≤ 2 or an internal triangle with all three (Lemma 37,
//! strengthened: a boundary-edge triangle there has another side with both
//! pieces ≤ 2-zone, as the turnings of disjoint chains add up to less than a
//! full turn), which is why step iv needs only those two kinds of candidate.
//!
//! | step | what | rests on | module |
//! |---|---|---|---|
//! | i | `mcw`/`mccw` by two-pointers on the exact zonality test (T10); `Top` by binary search, or by rotating two-pointers along a row/column | Def. 26/27/38, Property 25 | [`sleeve`] |
//! | ii–iii | sleeve program over the pieces of zonality ≤ 2, O(n²); values as ranks after one exact sort | Lemmas 31/32, Cor. 36; monotone zonality | [`sleeve`] |
//! | iv MaxMin | 2-2 diagonals, and search pairs with range-max segment trees over rows/columns, O(log n) each | Lemma 23, strengthened Lemma 37, Lemma 40/Cor. 41 (argmax by linear scan, T1), coverage; boundary edges never sub-problems (T2) | [`maxmin`] |
//! | iv MinMax | 2-2 diagonals, and for search pairs the four blocks of [`minmax`] solved on the thesis's staircases, O(log n) each | Lemma 42 on G (T5, T6), A(i,k,j) kept (T4), F_ij = strip ∩ solved range (T7) | [`minmax`] |
//! | v | follow the stored sleeve choices, O(n) | Cor. 36 | [`sleeve`] |
//! | Alg. 49 | decision M(τ) in O(n²) with prefix counts; MaxMin by sort-and-search over the table's values | Lemma 50, Theorem 51 | [`decision`] |
//!
//! # Exactness
//! Areas are never computed in floating point. Every decision is an exact
//! predicate: [`crate::kernel::compare_areas`], [`crate::kernel::orient_sign`],
//! [`crate::kernel::dot_sign`], [`crate::kernel::cross_sign`] (the sign of
//! `(b − a) × (d − c)` for the zonality test and height comparisons) and
//! [`crate::kernel::compare_doubled_area`] (an `f64` decision threshold),
//! each a floating-point filter with an exact expansion fallback. Table values are
//! bottleneck triangles, replaced by their ranks after one exact sort
//! (equal areas share a rank). Ties are normal; any optimal triangulation
//! may be returned. Exactness needs the coordinates in the kernel's range
//! (as [`crate::PointSet`] guarantees); the entry points check it.
//!
//! # Complexity
//! - [`maxmin_area_convex`], [`minmax_area_convex`]: O(n² log n) time,
//!   O(n²) space (two `n²` rank tables, row- and column-major; the MaxMin
//!   segment trees take `4n²` words more).
//! - The constant is dominated by area comparisons (the kernel's filtered
//!   `compare_areas`) and, in MinMax's step iv, by reading one row or column
//!   of the table per search pair; per pair a few exact predicates remain
//!   (the searches start from the neighbouring pair's answers).
//! - [`MaxMinTable::new`]: O(n² log n); each decision O(n²);
//!   [`maxmin_area_convex_by_search`]: O(n² log n) (O(log n) decisions).
//!
//! # Tests
//! `tests.rs` compares optimal *values* with optri-oracle's exact Klincsek
//! program on random, lattice, symmetric, regular, cocircular, huge and
//! tiny inputs and fixed polygons, checks every output is a
//! triangulation, tests the two MaxMin routes against each other, and checks
//! the lemmas as properties on every piece (zonality, Top, strips, sleeve =
//! Klincsek, quasi-concavity on I_i/J_j (T1), coverage, monotone switch
//! predicates (T5), Lemma 23 and the strengthened Lemma 37), and that the
//! +∞-edge reading of step iv (T2) does fail.

mod decision;
mod maxmin;
mod minmax;
mod sleeve;
#[cfg(test)]
mod tests;

pub(crate) use decision::{maxmin_admits, MaxMinTable};

use super::AreaBottleneck;
use crate::error::Result;
use crate::interrupt::Stop;
use crate::kernel::Point;
use sleeve::{SleeveTable, Witness};

/// A MaxMin-area triangulation of a strictly convex polygon: the smallest
/// triangle is as large as possible.
///
/// `polygon` is the vertex cycle (indices into `points`) of a strictly
/// convex polygon in counter-clockwise order, n ≥ 3. Returns its n − 2
/// triangles as vertex indices. Algorithm 44 with step iv by range-max
/// segment trees up to [`RANGE_MAX_UP_TO`] vertices, and above that the
/// sort-and-search route over the same table ([`MaxMinTable`]); both
/// O(n² log n) time, O(n²) space, and tested against each other.
///
/// # Panics
/// If `polygon` is not strictly convex and counter-clockwise, has fewer
/// than 3 or more than 65535 vertices, or uses a coordinate outside the
/// kernel's exact range ([`crate::kernel::MAX_COORDINATE`]).
///
/// # Errors
/// [`Error::Interrupted`](crate::Error::Interrupted) when `stop` says so
/// (checked while the table is built).
pub(crate) fn maxmin_area_convex(
    points: &[Point],
    polygon: &[u32],
    stop: &Stop,
) -> Result<Vec<[u32; 3]>> {
    let table = MaxMinTable::new(points, polygon, stop)?;
    Ok(if polygon.len() <= RANGE_MAX_UP_TO {
        table.optimum_by_range_max()
    } else {
        table.optimum_by_search()
    })
}

/// Where the MaxMin routes cross (measured, `area_timing`, quiet machine):
/// at 4000 vertices range-max took 0.66–0.71 s and sort-and-search
/// 0.79–0.87 s; at 8000 range-max took 3.9–5.2 s (its segment trees, 4n²
/// words, outgrow the caches: 1.6 GB peak) and sort-and-search 2.5 s
/// (0.8 GB peak: sequential prefix-count scans).
const RANGE_MAX_UP_TO: usize = 5000;

/// A MaxMin-area triangulation by the other route: binary search over the
/// sorted table values with the O(n²) decision of Algorithm 49.
/// Same contract and bounds as [`maxmin_area_convex`].
#[cfg(test)]
pub(crate) fn maxmin_area_convex_by_search(points: &[Point], polygon: &[u32]) -> Vec<[u32; 3]> {
    MaxMinTable::new(points, polygon, &Stop::default())
        .expect("never stopped")
        .optimum_by_search()
}

/// A MinMax-area triangulation of a strictly convex polygon: the largest
/// triangle is as small as possible.
///
/// Same input contract as [`maxmin_area_convex`]. Algorithm 44 with step iv
/// of [`minmax`] (staircases); O(n² log n) time, O(n²) space.
///
/// # Panics
/// As [`maxmin_area_convex`].
///
/// # Errors
/// As [`maxmin_area_convex`].
pub(crate) fn minmax_area_convex(
    points: &[Point],
    polygon: &[u32],
    stop: &Stop,
) -> Result<Vec<[u32; 3]>> {
    let table = SleeveTable::new(points, polygon, AreaBottleneck::MinMax, stop)?;
    if table.n() == 3 {
        return Ok(table.triangulation(Witness::Whole { i: 0 }));
    }
    let witness = minmax::minmax_witness(&table);
    Ok(table.triangulation(witness))
}

/// The MaxMin decision (Algorithm 49): is there a triangulation of the
/// polygon whose smallest triangle has doubled area at least
/// `doubled_area`? Exact. Builds a [`MaxMinTable`] (O(n² log n)) and asks
/// once (O(n²)); keep the table for repeated queries.
///
/// # Panics
/// As [`maxmin_area_convex`], or if `doubled_area` is NaN.
#[cfg(test)]
pub(crate) fn maxmin_area_at_least(points: &[Point], polygon: &[u32], doubled_area: f64) -> bool {
    MaxMinTable::new(points, polygon, &Stop::default())
        .expect("never stopped")
        .admits_doubled_area(doubled_area)
}
