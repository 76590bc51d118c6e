//! The threshold sweep ("modified Klincsek", T. S. Vassilev, *Optimal area
//! triangulation*, PhD thesis, 2005, Table 1.1) on a polygon of `k` corners.
//!
//! For a lower bound `L`, `U(L)` is the least largest item over the
//! triangulations whose items are all at least `L`: the bottleneck polygon
//! program with every triangle whose low rank is below `L` forbidden. Some
//! optimal triangulation `T*` has smallest item `λ*`, and `U(λ*) − λ* ≤
//! δ(T*)`, so `δ* = min_L U(L) − L` over the distinct low values.
//!
//! Pruning (a two-pointer walk over the sorted thresholds): let `M*` be
//! the least largest item over all triangulations (`U(−∞)`) and `m*` the
//! greatest smallest item (the maxmin program). No triangulation has a
//! smallest item above `m*`, so only `L ≤ m*` matters; `U` is
//! nondecreasing, so after a program at `L` found `U(L)`, a later `L′` can
//! win only if `U(L) − L′` is below the best δ so far (at first `M*` stands
//! for `U(L)`: the window `[M* − δ_ub, m*]`). The program's triangulation
//! is scored by its own smallest item `λ ≥ L`, and every `L′ ∈ (L, λ]` has
//! `U(L′) = U(L)`, so the walk resumes after `λ`. Each threshold test is an
//! exact comparison of differences, found by binary search.

use super::measure::{Item, Measure, RankedTriangles, FLAT};
use crate::error::Result;
use crate::interrupt::Stop;
use crate::kernel::Point;
use crate::polygon_program::{optimal_triangulation_until, Objective};
use std::cmp::Ordering;

/// The largest high rank of a triangulation, minimised.
struct LargestHigh<'a>(&'a RankedTriangles);

impl Objective for LargestHigh<'_> {
    type Value = u32;
    fn empty(&self) -> u32 {
        0
    }
    fn diagonal(&self, _: usize, _: usize) -> Option<u32> {
        None
    }
    fn triangle(&self, i: usize, m: usize, j: usize) -> Option<u32> {
        Some(self.0.high[self.0.slot(i, m, j)])
    }
    fn combine(&self, a: u32, b: u32) -> u32 {
        a.max(b)
    }
    fn better(&self, a: u32, b: u32) -> bool {
        a < b
    }
}

/// The smallest low rank of a triangulation, maximised.
struct SmallestLow<'a>(&'a RankedTriangles);

impl Objective for SmallestLow<'_> {
    type Value = u32;
    fn empty(&self) -> u32 {
        u32::MAX
    }
    fn diagonal(&self, _: usize, _: usize) -> Option<u32> {
        None
    }
    fn triangle(&self, i: usize, m: usize, j: usize) -> Option<u32> {
        Some(self.0.low[self.0.slot(i, m, j)])
    }
    fn combine(&self, a: u32, b: u32) -> u32 {
        a.min(b)
    }
    fn better(&self, a: u32, b: u32) -> bool {
        a > b
    }
}

/// What a sweep found: the triangles (corner triples `i < m < j`), and
/// how many polygon programs it ran.
pub(crate) struct Swept {
    pub triangles: Vec<[usize; 3]>,
    pub programs: u64,
}

/// A triangulation with its largest and smallest rank.
#[derive(Clone)]
struct Scored {
    triangles: Vec<[usize; 3]>,
    high: u32,
    low: u32,
}

/// The triangulation of corners `0..k` (corner `c` at `point(c)`, chords
/// allowed by `is_diagonal`) with the least δ of `measure`, exactly; flat
/// triangles are never used. `None` if the polygon has no triangulation.
///
/// # Errors
/// [`crate::Error::Interrupted`] when `stop` says so.
pub(crate) fn least_delta(
    measure: Measure,
    k: usize,
    point: &impl Fn(usize) -> Point,
    is_diagonal: &impl Fn(usize, usize) -> bool,
    stop: &Stop,
) -> Result<Option<Swept>> {
    let ranked = RankedTriangles::new(measure, k, point);
    stop.check()?;
    let score = |triangles: Vec<[usize; 3]>| {
        let (high, low) = triangles
            .iter()
            .map(|&[i, m, j]| ranked.slot(i, m, j))
            .fold((0, u32::MAX), |(h, l), s| {
                (h.max(ranked.high[s]), l.min(ranked.low[s]))
            });
        Scored {
            triangles,
            high,
            low,
        }
    };
    let item = |rank: u32| -> Item { ranked.representative[rank as usize] };
    let difference = |s: &Scored| [item(s.high), item(s.low)];
    let allowed_from = |threshold: u32| {
        let ranked = &ranked;
        move |i: usize, m: usize, j: usize| {
            let low = ranked.low[ranked.slot(i, m, j)];
            low != FLAT && low >= threshold
        }
    };
    let diagonal = |i: usize, j: usize| is_diagonal(i, j);
    // U(L) for the threshold rank L.
    let least_largest = |threshold: u32| -> Result<Option<Scored>> {
        let objective = LargestHigh(&ranked);
        let solved =
            optimal_triangulation_until(k, diagonal, allowed_from(threshold), &objective, stop)?;
        Ok(solved.map(|t| score(t.triangles)))
    };
    // M* (the least largest item) and m* (the greatest smallest item).
    let Some(unconstrained) = least_largest(0)? else {
        return Ok(None);
    };
    let greatest_smallest = {
        let objective = SmallestLow(&ranked);
        let solved = optimal_triangulation_until(k, diagonal, allowed_from(0), &objective, stop)?
            .expect("the unconstrained program found a triangulation");
        score(solved.triangles)
    };
    let mut programs = 2;
    let least_largest_rank = unconstrained.high; // M*
    let better = |s: &Scored, t: &Scored| {
        measure.compare_differences(point, difference(s), difference(t)) == Ordering::Less
    };
    let mut best = if better(&greatest_smallest, &unconstrained) {
        greatest_smallest.clone()
    } else {
        unconstrained
    };
    // The candidate thresholds: the distinct low ranks up to m*, upwards.
    let mut thresholds: Vec<u32> = ranked
        .low
        .iter()
        .copied()
        .filter(|&l| l != FLAT && l <= greatest_smallest.low)
        .collect();
    thresholds.sort_unstable();
    thresholds.dedup();
    // The first threshold at or after `from` that can still win when every
    // U(L) from here on is at least the rank `high`: U(L) − L decreases
    // with L, so the thresholds that fail `high − L < δ_best` are a prefix.
    let first_winning = |from: usize, high: u32, best: &Scored| {
        from + thresholds[from..].partition_point(|&threshold| {
            measure.compare_differences(point, [item(high), item(threshold)], difference(best))
                != Ordering::Less
        })
    };
    // U(L) is nondecreasing: after the program at L found U(L) and a
    // triangulation whose smallest item is λ ≥ L, every L' ≤ λ has
    // U(L') − L' ≥ U(L) − λ (already scored), and every later L' needs
    // U(L) − L' < δ_best.
    // The program at m* first: its δ is often near the optimum and narrows
    // the window before the walk starts.
    let top = least_largest(greatest_smallest.low)?.expect("m* has a triangulation");
    programs += 1;
    if better(&top, &best) {
        best = top;
    }
    let mut next = first_winning(0, least_largest_rank, &best);
    while next < thresholds.len() {
        programs += 1;
        // Every candidate is at most m*, so a triangulation exists.
        let candidate =
            least_largest(thresholds[next])?.expect("a threshold at most m* has a triangulation");
        let past = thresholds.partition_point(|&t| t <= candidate.low);
        let high = candidate.high;
        if better(&candidate, &best) {
            best = candidate;
        }
        next = first_winning(past.max(next + 1), high, &best);
    }
    Ok(Some(Swept {
        triangles: best.triangles,
        programs,
    }))
}
