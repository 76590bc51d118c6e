//! Step iv of Algorithm 44 for MaxMin area (Vassilev 2005, §2.3.2,
//! L1919-2013), repaired (T1, T2 of the module docs of `convex`), with a
//! range maximum for its 3-sided query: O(log n) per search pair with
//! range-max segment trees over the rows and columns of the sleeve table,
//! O(n² log n) time and O(n²) space in all.
//!
//! The candidate theorem: by the strengthening of Lemma 37,
//! some optimal triangulation has a proper 2-2 diagonal — candidate (A),
//! `min(μ*(P_ij), μ*(P_ji))` — or an internal 2-2-2 triangle `(i, k, j)`.
//! Orient that triangle so that its weakest piece is `P_ji`; if `P_ij` is
//! ≤2-zone (A) covers it, otherwise `(i, j)` is a *search pair* and the
//! candidate is `τ = μ*(P_ji)` as soon as some `k ∈ [i+2, j−2]` has
//! `μ*(P_ik) ≥ τ` and `μ*(P_kj) ≥ τ`. The triangle itself never matters:
//! it is internal, hence larger than its smallest neighbour (Lemma 23).

use super::sleeve::{first_true, SleeveTable, Witness, UNSOLVED};

/// Where `k ↦ μ*(P_ik)` (a row) or `k ↦ μ*(P_kj)` (a column) is
/// quasi-concave (Lemma 40 / Corollary 41, L1560-1640): every superlevel
/// set is an interval. Offsets are lengths of the varying piece, clipped to
/// `≥ 2` so that boundary edges never count (repair T2).
#[derive(Clone, Copy, Debug)]
pub(super) struct QuasiConcaveRun {
    /// Smallest offset of the run.
    pub(super) lo: usize,
    /// An offset where the maximum is attained (linear scan, repair T1: the
    /// function has plateaus, so a binary search can miss the maximum).
    pub(super) peak: usize,
    /// Largest offset of the run.
    pub(super) hi: usize,
}

impl QuasiConcaveRun {
    /// Scans `value` over `[lo, hi]` for the peak.
    fn scan(lo: usize, hi: usize, value: impl Fn(usize) -> u32) -> Self {
        let mut peak = lo;
        for r in lo + 1..=hi {
            if value(r) > value(peak) {
                peak = r;
            }
        }
        QuasiConcaveRun { lo, peak, hi }
    }

    /// The superlevel interval `{r : value(r) ≥ tau}` of the run, or `None`.
    /// Up to the peak the values are non-decreasing, after it
    /// non-increasing, so both ends are binary searches that start inside
    /// the superlevel set.
    pub(super) fn superlevel(
        &self,
        value: impl Fn(usize) -> u32,
        tau: u32,
    ) -> Option<(usize, usize)> {
        if value(self.peak) < tau {
            return None;
        }
        let lo = first_true(self.lo, self.peak, |r| value(r) >= tau);
        let hi = first_true(self.peak, self.hi, |r| value(r) < tau) - 1;
        Some((lo, hi))
    }
}

/// The intervals I_i of every row and J_j of every column (Lemma 40,
/// Cor. 41).
pub(super) struct AdmissibilityRuns {
    /// `rows[i]`: offsets `r` of I_i = [Top(i, a), a], `a = i + mcw(i)`,
    /// over `r ↦ μ*(P_{i,i+r})`.
    pub(super) rows: Vec<QuasiConcaveRun>,
    /// `columns[j]`: lengths `d = j − k` of J_j = [b, Top(b, j)],
    /// `b = j − mccw(j)`, over `d ↦ μ*(P_{j−d,j})`.
    pub(super) columns: Vec<QuasiConcaveRun>,
}

impl AdmissibilityRuns {
    /// O(n²): one `Top` search and one linear scan per row and column.
    pub(super) fn new(table: &SleeveTable) -> Self {
        let n = table.n();
        let poly = &table.poly;
        let rows = (0..n)
            .map(|i| {
                let a = table.mcw[i];
                let lo = poly.top_offset(i, a).max(2);
                QuasiConcaveRun::scan(lo, a, |r| table.rank(i, r))
            })
            .collect();
        let columns = (0..n)
            .map(|j| {
                let b = table.mccw[j];
                let top = poly.top_offset(j + n - b, b);
                // k = Top(b, j) has d = b − top; k = b has d = b.
                QuasiConcaveRun::scan((b - top).max(2), b, |d| table.rank_to(j, d))
            })
            .collect();
        AdmissibilityRuns { rows, columns }
    }
}

/// Bottom-up segment trees for range maxima, one per line (row or column),
/// all of the same size `n`, in one flat array of `2n` words per line.
struct RangeMax {
    size: usize,
    nodes: Vec<u32>,
}

impl RangeMax {
    /// `lines` lines; `value(line, x)` for `x < size`.
    fn new(lines: usize, size: usize, value: impl Fn(usize, usize) -> u32) -> Self {
        let mut nodes = vec![0; lines * 2 * size];
        for (line, tree) in nodes.chunks_exact_mut(2 * size).enumerate() {
            for x in 0..size {
                tree[size + x] = value(line, x);
            }
            for p in (1..size).rev() {
                tree[p] = tree[2 * p].max(tree[2 * p + 1]);
            }
        }
        RangeMax { size, nodes }
    }

    /// Maximum of `value(line, x)` over `x ∈ [lo, hi]`, O(log n).
    fn max(&self, line: usize, lo: usize, hi: usize) -> u32 {
        let tree = &self.nodes[line * 2 * self.size..(line + 1) * 2 * self.size];
        let (mut l, mut r) = (lo + self.size, hi + self.size + 1);
        let mut best = 0;
        while l < r {
            if l & 1 == 1 {
                best = best.max(tree[l]);
                l += 1;
            }
            if r & 1 == 1 {
                r -= 1;
                best = best.max(tree[r]);
            }
            l /= 2;
            r /= 2;
        }
        best
    }
}

/// Step iv for MaxMin with range-max structures.
pub(super) struct RangeMaxSearch<'t, 'a> {
    table: &'t SleeveTable<'a>,
    runs: &'t AdmissibilityRuns,
    /// Row `i`, position `r`: μ*(P_{i,i+r}) (0 if unsolved).
    rows: RangeMax,
    /// Column `j`, position `d`: μ*(P_{j−d,j}) (0 if unsolved).
    columns: RangeMax,
}

/// A rank as a maximisation value: unsolved pieces are −∞ (0).
#[inline]
fn or_minus_infinity(rank: u32) -> u32 {
    if rank == UNSOLVED {
        0
    } else {
        rank
    }
}

impl<'t, 'a> RangeMaxSearch<'t, 'a> {
    /// O(n²) time and `4n²` words.
    pub(super) fn new(table: &'t SleeveTable<'a>, runs: &'t AdmissibilityRuns) -> Self {
        let n = table.n();
        let value_or_zero = |rank: u32, len: usize| {
            if len >= 2 {
                or_minus_infinity(rank)
            } else {
                0
            }
        };
        let rows = RangeMax::new(n, n, |i, r| value_or_zero(table.rank(i, r.max(1)), r));
        let columns = RangeMax::new(n, n, |j, d| value_or_zero(table.rank_to(j, d.max(1)), d));
        RangeMaxSearch {
            table,
            runs,
            rows,
            columns,
        }
    }

    /// Does the search pair `(i, i+len)` admit its outer value `tau`, i.e.
    /// is there `r ∈ [2, len−2]` with μ*(P_{i,i+r}) ≥ τ and
    /// μ*(P_{i+r,j}) ≥ τ? O(log n).
    ///
    /// Both pieces solved forces `len − mccw(j) ≤ r ≤ mcw(i)`, and that
    /// range is covered by I_i ∪ J_j (coverage, L1598-1612: the chords
    /// `v_i v_a` and `v_b v_j` cross, so `Top(i, a) ≤ Top(b, j)`), so
    /// every feasible `r` is in the row half's or the column half's
    /// superlevel interval.
    pub(super) fn pair_admits(&self, i: usize, len: usize, tau: u32) -> bool {
        let table = self.table;
        let j = (i + len) % table.n();
        let (first, last) = (2, len - 2);
        let row = |r: usize| table.rank(i, r);
        if let Some((lo, hi)) = self.runs.rows[i].superlevel(row, tau) {
            let (lo, hi) = (lo.max(first), hi.min(last));
            if lo <= hi && self.columns.max(j, len - hi, len - lo) >= tau {
                return true;
            }
        }
        let column = |d: usize| table.rank_to(j, d);
        if let Some((lo, hi)) = self.runs.columns[j].superlevel(column, tau) {
            let (lo, hi) = (lo.max(first), hi.min(last));
            if lo <= hi && self.rows.max(i, len - hi, len - lo) >= tau {
                return true;
            }
        }
        false
    }

    /// The optimum: the best candidate of (A) and (B) and its witness.
    /// Pairs whose outer value cannot beat the best so far are skipped.
    pub(super) fn optimum(&self) -> (u32, Witness) {
        let table = self.table;
        let n = table.n();
        // Ranks start at 1, so 0 is below every candidate.
        let mut best = (0, None);
        // (A) proper 2-2 diagonals.
        for i in 0..n {
            for len in 2..=n - 2 {
                if table.solved(i, len) && table.solved(i + len, n - len) {
                    let value = table.rank(i, len).min(table.rank(i + len, n - len));
                    if value > best.0 {
                        best = (value, Some(Witness::Diagonal { i, len }));
                    }
                }
            }
        }
        // (B) search pairs: P_ji solved, P_ij not.
        for i in 0..n {
            for len in table.mcw[i] + 1..=n - 2 {
                if !table.solved(i + len, n - len) {
                    continue;
                }
                let tau = table.rank(i + len, n - len);
                if tau > best.0 && self.pair_admits(i, len, tau) {
                    best = (tau, Some(self.witness_triangle(i, len, tau)));
                }
            }
        }
        let witness = best
            .1
            .expect("the candidate theorem covers some triangulation");
        (best.0, witness)
    }

    /// Step v for a (B) winner: the apex by a linear scan (L2357).
    pub(super) fn witness_triangle(&self, i: usize, len: usize, tau: u32) -> Witness {
        witness_apex(self.table, i, len, tau)
    }
}

/// An apex `r ∈ [2, len−2]` of the search pair `(i, i+len)` whose two pieces
/// are solved with value ≥ `tau`, found by a linear scan.
///
/// # Panics
/// If there is none.
fn witness_apex(table: &SleeveTable, i: usize, len: usize, tau: u32) -> Witness {
    let ok = |rank: u32| rank != UNSOLVED && rank >= tau;
    let r = (2..=len - 2)
        .find(|&r| ok(table.rank(i, r)) && ok(table.rank(i + r, len - r)))
        .expect("a search pair that admits its value has an apex");
    Witness::Triangle { i, r, len }
}
