//! Algorithm 49 (Vassilev 2005, §2.4, L2366-2550; Lemma 50, Theorem 51):
//! the MaxMin decision "is there a triangulation whose smallest triangle has
//! area at least τ?", simplified — O(n²) per query with prefix counts
//! instead of van Emde Boas queues — and the sort-and-search route to the
//! MaxMin optimum (the optimum is one of the table's values).

use super::super::AreaBottleneck;
use super::maxmin::{AdmissibilityRuns, RangeMaxSearch};
use super::sleeve::{
    first_true, sleeve_triangulation, ConvexPolygon, SleeveTable, Witness, UNSOLVED,
};
use crate::error::Result;
use crate::interrupt::Stop;
use crate::kernel::compare_doubled_area;
use crate::kernel::Point;
use std::cmp::Ordering;

/// The MaxMin sleeve table of a strictly convex polygon, ready for
/// decision queries (Algorithm 49) and for both routes to the optimum.
///
/// Building it costs O(n² log n) (the sleeve program of steps i–iii and one
/// exact sort of its values); each decision query then costs O(n²).
pub(crate) struct MaxMinTable<'a> {
    table: SleeveTable<'a>,
    runs: AdmissibilityRuns,
}

impl<'a> MaxMinTable<'a> {
    /// Steps i–iii of Algorithm 44 for MaxMin, and the intervals I_i, J_j of
    /// Lemma 40 with their peaks.
    ///
    /// # Panics
    /// If `polygon` is not a strictly convex counter-clockwise cycle of at
    /// least 3 indices into `points`.
    ///
    /// # Errors
    /// [`Error::Interrupted`](crate::Error::Interrupted) when `stop` says so.
    pub(crate) fn new(points: &'a [Point], polygon: &'a [u32], stop: &Stop) -> Result<Self> {
        let table = SleeveTable::new(points, polygon, AreaBottleneck::MaxMin, stop)?;
        let runs = AdmissibilityRuns::new(&table);
        stop.check()?;
        Ok(MaxMinTable { table, runs })
    }

    /// Is there a triangulation whose smallest triangle has doubled area at
    /// least `doubled_area`? Exact; `doubled_area ≤ 0` is always admitted.
    ///
    /// # Panics
    /// If `doubled_area` is NaN.
    pub(crate) fn admits_doubled_area(&self, doubled_area: f64) -> bool {
        self.witness_doubled_area(doubled_area).is_some()
    }

    /// Is there a triangulation whose smallest triangle is at least as large
    /// as `threshold` (any three points)?
    #[cfg(test)]
    pub(crate) fn admits_triangle(&self, threshold: [Point; 3]) -> bool {
        self.witness_triangle(threshold).is_some()
    }

    /// A triangulation (n − 2 triangles, input vertex indices) whose
    /// smallest doubled area is at least `doubled_area`, if one exists
    /// (Theorem 51's construction).
    ///
    /// # Panics
    /// If `doubled_area` is NaN.
    pub(crate) fn witness_doubled_area(&self, doubled_area: f64) -> Option<Vec<[u32; 3]>> {
        assert!(!doubled_area.is_nan(), "area threshold is NaN");
        if doubled_area == f64::INFINITY {
            return None;
        }
        let rank = self.rank_at_least(|t| compare_doubled_area(t, doubled_area.max(0.0)))?;
        self.witness_rank(rank)
    }

    /// A triangulation whose smallest triangle is at least as large as
    /// `threshold`, if one exists.
    #[cfg(test)]
    pub(crate) fn witness_triangle(&self, threshold: [Point; 3]) -> Option<Vec<[u32; 3]>> {
        let rank = self.rank_at_least(|t| crate::kernel::compare_areas(t, threshold))?;
        self.witness_rank(rank)
    }

    /// The MaxMin optimum by sorting and searching: the optimum
    /// is a table value (every candidate of the candidate theorem is one),
    /// so binary-search the sorted distinct values with the O(n²) decision.
    /// O(n² log n) in all, about 2 log₂ n decisions.
    pub(crate) fn optimum_by_search(&self) -> Vec<[u32; 3]> {
        let table = &self.table;
        // Rank 1 is admitted (the optimum is a table value, hence ≥ it); the
        // decision is monotone in the threshold.
        let last_admitted = first_true(2, table.max_rank() as usize, |r| {
            self.decide(r as u32).is_none()
        }) - 1;
        let witness = self
            .decide(last_admitted as u32)
            .expect("the smallest table value is always admitted");
        table.triangulation(witness)
    }

    /// The MaxMin optimum by step iv of Algorithm 44 with range-max segment
    /// trees, O(n² log n).
    pub(crate) fn optimum_by_range_max(&self) -> Vec<[u32; 3]> {
        if self.table.n() == 3 {
            return self.table.triangulation(Witness::Whole { i: 0 });
        }
        let search = RangeMaxSearch::new(&self.table, &self.runs);
        let (_, witness) = search.optimum();
        self.table.triangulation(witness)
    }

    /// The smallest rank whose area is ≥ the threshold described by
    /// `compare` (the ordering of a triangle's area against it), by binary
    /// search over the exact sorted table values; `None` if every table
    /// value is below it. The decision for the threshold equals the decision
    /// for that table value, since only table values are ever compared.
    fn rank_at_least(&self, compare: impl Fn([Point; 3]) -> Ordering) -> Option<u32> {
        let table = &self.table;
        let max_rank = table.max_rank() as usize;
        let below = |r: usize| {
            compare(table.poly.triangle(table.representative(r as u32))) == Ordering::Less
        };
        let rank = first_true(1, max_rank, |r| !below(r));
        (rank <= max_rank).then_some(rank as u32)
    }

    fn witness_rank(&self, rank: u32) -> Option<Vec<[u32; 3]>> {
        self.decide(rank)
            .map(|witness| self.table.triangulation(witness))
    }

    /// M(τ) for the table value of rank `tau` (Lemma 50), O(n²): a witness
    /// if some triangulation has smallest area ≥ that value.
    pub(super) fn decide(&self, tau: u32) -> Option<Witness> {
        let table = &self.table;
        let n = table.n();
        let ok = |i: usize, len: usize| {
            let rank = table.rank(i, len);
            rank != UNSOLVED && rank >= tau
        };
        // The admissible part of every I_i and J_j is one interval (Lemma
        // 40): binary searches from the peaks.
        let rows: Vec<Option<(usize, usize)>> = (0..n)
            .map(|i| self.runs.rows[i].superlevel(|r| table.rank(i, r), tau))
            .collect();
        let columns: Vec<Option<(usize, usize)>> = (0..n)
            .map(|j| self.runs.columns[j].superlevel(|d| table.rank_to(j, d), tau))
            .collect();
        search_admissible(n, &table.mcw, ok, &rows, &columns)
    }

    /// The sleeve table (for tests and the range-max route).
    #[cfg(test)]
    pub(super) fn sleeve_table(&self) -> &SleeveTable<'a> {
        &self.table
    }

    /// The intervals of Lemma 40.
    #[cfg(test)]
    pub(super) fn runs(&self) -> &AdmissibilityRuns {
        &self.runs
    }
}

/// Steps 2–5 of Algorithm 49 (Lemma 50) over the admissibility predicate
/// `ok(i, len)` ("P_{i,i+len} is solved and its sleeve optimum meets the
/// threshold"), given the admissible interval of every I_i (`rows`, offsets
/// r) and J_j (`columns`, lengths d), O(n²).
fn search_admissible(
    n: usize,
    mcw: &[usize],
    ok: impl Fn(usize, usize) -> bool,
    rows: &[Option<(usize, usize)>],
    columns: &[Option<(usize, usize)>],
) -> Option<Witness> {
    if n == 3 {
        return ok(0, 2).then_some(Witness::Whole { i: 0 });
    }
    // Step 2: a proper 2-2 diagonal with both sides admissible. By the
    // strengthening of Lemma 37 (module docs of `convex`) a triangulation with
    // smallest area ≥ τ has such a diagonal or an internal 2-2-2
    // triangle with all three pieces admissible.
    for i in 0..n {
        for len in 2..=n - 2 {
            if ok(i, len) && ok(i + len, n - len) {
                return Some(Witness::Diagonal { i, len });
            }
        }
    }
    // Steps 3–4: prefix counts of `ok` along every row and column answer
    // "is some k of an interval admissible?" in O(1).
    // row_count[i * n + r]: admissible P_{i,i+r'} with r' < r; likewise
    // column_count over P_{j−d',j}.
    let mut row_count = vec![0u16; n * n];
    let mut column_count = vec![0u16; n * n];
    for line in 0..n {
        for len in 1..n {
            let at = line * n + len;
            row_count[at] = row_count[at - 1] + ok(line, len) as u16;
            column_count[at] = column_count[at - 1] + ok(line + n - len, len) as u16;
        }
    }
    let any_in = |count: &[u16], line: usize, lo: usize, hi: usize| {
        count[line * n + hi] > count[line * n + lo - 1]
    };
    // Step 5: search pairs (i, j) with P_ji admissible; the triangle
    // (i, k, j) is internal, so its own area needs no test (Lemma 23).
    for (i, admissible_row) in rows.iter().enumerate() {
        for len in mcw[i] + 1..=n - 2 {
            let j = (i + len) % n;
            if !ok(j, n - len) {
                continue;
            }
            let (first, last) = (2, len - 2);
            let found = admissible_row
                .map(|(lo, hi)| (lo.max(first), hi.min(last)))
                .is_some_and(|(lo, hi)| lo <= hi && any_in(&column_count, j, len - hi, len - lo))
                || columns[j]
                    .map(|(lo, hi)| (lo.max(first), hi.min(last)))
                    .is_some_and(|(lo, hi)| lo <= hi && any_in(&row_count, i, len - hi, len - lo));
            if found {
                let r = (2..=len - 2)
                    .find(|&r| ok(i, r) && ok(i + r, len - r))
                    .expect("a search pair that admits the threshold has an apex");
                return Some(Witness::Triangle { i, r, len });
            }
        }
    }
    None
}

/// Algorithm 49 in one shot: is there a triangulation of the strictly
/// convex polygon whose every triangle `t` has `at_least(t) != Less`
/// (its area at least the threshold)? A triangulation proving it, or `None`.
///
/// Vassilev's decision runs steps ii–iii of Algorithm 44 against the
/// threshold instead of computing optima: a piece is *admissible* when
/// one of its two base-adjacent ears meets the threshold and the rest of
/// its sleeve is admissible (Corollary 36 makes "some sleeve meets it" the
/// same as "the optimal sleeve does"), a boolean program with one area
/// comparison per ear, O(n²). No value is ranked or sorted, so the
/// O(n² log n) sort of [`MaxMinTable::new`] (and the thesis's van Emde Boas
/// queues, O(n² log log n)) are not needed: the admissible part of every
/// I_i and J_j is one interval (Lemma 40) found by a scan, O(n) per line,
/// and steps 2–5 are those of [`MaxMinTable`]'s decision. O(n²) time and
/// space in all.
///
/// # Panics
/// As [`super::maxmin_area_convex`].
///
/// # Errors
/// [`Error::Interrupted`](crate::Error::Interrupted) when `stop` says so.
pub(crate) fn maxmin_admits(
    points: &[Point],
    polygon: &[u32],
    at_least: impl Fn([Point; 3]) -> Ordering,
    stop: &Stop,
) -> Result<Option<Vec<[u32; 3]>>> {
    let poly = ConvexPolygon::new(points, polygon);
    let n = poly.n;
    let mcw = poly.max_clockwise();
    let mccw = poly.max_counter_clockwise();
    let meets = |t: [usize; 3]| at_least(poly.triangle(t)) != Ordering::Less;
    // admissible[i * n + len] for the solved pieces (2 ≤ len ≤ mcw[i]);
    // uses_first_ear as in the sleeve table, for the admissible sleeve.
    let mut admissible = vec![false; n * n];
    let mut uses_first_ear = vec![false; n * n];
    for len in 2..n {
        stop.check()?;
        for i in 0..n {
            if len > mcw[i] {
                continue;
            }
            let entry = i * n + len;
            let j = i + len;
            if len == 2 {
                admissible[entry] = meets([i, i + 1, j]);
                uses_first_ear[entry] = true;
                continue;
            }
            // The sub-piece first: it is a table lookup, the ear an area
            // comparison.
            let via_first = admissible[((i + 1) % n) * n + len - 1] && meets([i, i + 1, j]);
            admissible[entry] = via_first || (admissible[entry - 1] && meets([j - 1, j, i]));
            uses_first_ear[entry] = via_first;
        }
    }
    stop.check()?;
    let ok = |i: usize, len: usize| len < n && admissible[(i % n) * n + len];
    // The first and last admissible offset of a run: the admissible ones
    // form an interval (Lemma 40).
    let interval = |lo: usize, hi: usize, ok_at: &dyn Fn(usize) -> bool| {
        let first = (lo..=hi).find(|&r| ok_at(r))?;
        let last = (first..=hi).rev().find(|&r| ok_at(r))?;
        Some((first, last))
    };
    let rows: Vec<Option<(usize, usize)>> = (0..n)
        .map(|i| {
            let a = mcw[i];
            let lo = poly.top_offset(i, a).max(2);
            interval(lo, a, &|r| ok(i, r))
        })
        .collect();
    let columns: Vec<Option<(usize, usize)>> = (0..n)
        .map(|j| {
            let b = mccw[j];
            let top = poly.top_offset(j + n - b, b);
            interval((b - top).max(2), b, &|d| ok(j + n - d, d))
        })
        .collect();
    Ok(search_admissible(n, &mcw, ok, &rows, &columns)
        .map(|witness| sleeve_triangulation(&poly, &uses_first_ear, witness)))
}
