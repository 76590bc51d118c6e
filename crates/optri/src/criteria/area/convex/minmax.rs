//! Step iv of Algorithm 44 for MinMax area (Vassilev 2005, §2.3.3,
//! L2015-2337), repaired (T4, T5, T7 of the module docs of `convex`): the
//! thesis's staircases, O(n² log n) time and O(n²) space.
//!
//! Candidate theorem (strengthened Lemma 37): the optimum is the smaller of
//! - (A′) `max(λ*(P_ij), λ*(P_ji))` over the proper 2-2 diagonals, and
//! - (B′) `max(λ*(P_ji), min_{k ∈ F_ij} max(λ*(P_ik), λ*(P_kj), A(i,k,j)))`
//!   over the search pairs (`P_ji` solved, `P_ij` not), with
//!   `F_ij = [i+2, j−2] ∩ [j − mccw(j), i + mcw(i)] ∩ strip(i, j)`.
//!
//! Some optimal triangulation has a 2-2 diagonal or an internal 2-2-2
//! triangle (strengthened Lemma 37); taking that triangle's longest side as
//! `(i, j)` puts its apex in the strip (the vertex opposite the longest side
//! projects onto it), and both other pieces are solved (repair T7). The area
//! `A(i,k,j)` stays in the objective (repair T4: an internal triangle can be
//! the largest, Fig. 2.10).
//!
//! Minimising over `F_ij`: on the descending part
//! `D = F ∩ [Top(i,j), …]`, `A` is non-increasing and Lemma 42 (L1644, fan
//! from `v_j`) gives `λ*(P_kj) ≤ max(λ*(P_k′j), A(i,k,j))` for `k < k′`, so
//! `p(k) = [A(k) < λ*(P_kj)]` runs false…false, true…true (never a binary
//! search for a minimum: repair T5). Before the switch the objective is
//! `max(λ*(P_ik), A)`, after it `max(λ*(P_ik), λ*(P_kj))` with the column
//! non-decreasing. The ascending part `U` is the mirror image (fan from
//! `v_i`). Each of the four blocks minimises `max(f, g)` with `f` a row or
//! column of the table and `g` monotone, smallest at one end, the *anchor*:
//! only the running-minimum records of `f` from the anchor matter, and along
//! them `f` falls while `g` rises, so the optimum sits at their crossing.
//! Records of all anchors of one row (column) come from one monotone-stack
//! sweep; a block is then one binary search.
//!
//! Constant factors: a row (column) visits its search pairs in order, and
//! neighbouring pairs have nearly the same strip ends and switch point, so
//! those monotone searches gallop from the previous pair's answers (same
//! answers, a few evaluations instead of O(log n)); the outer rank is read
//! along the line being swept, not across it; a block whose smallest `f`
//! (or smallest rank `g`) cannot beat the best so far is skipped before any
//! exact comparison.

use super::sleeve::{
    first_true, first_true_near, Bottleneck, SleeveTable, TopFromEnd, TopFromStart, Witness,
};
use std::cmp::Ordering;

/// `F_ij` of the search pair `(i, i+len)` as offsets `[lo, hi]` from `i`,
/// or `None` if it is empty or no apex of it can beat `bound` (see
/// [`BlockSink::bound`]). `strip` carries the strip's ends from pair to
/// pair ([`ConvexPolygon::clip_to_strip`](super::sleeve::ConvexPolygon::clip_to_strip)).
fn pair_frame(
    table: &SleeveTable,
    i: usize,
    len: usize,
    bound: u32,
    strip: &mut (usize, usize),
) -> Option<(usize, usize)> {
    debug_assert!(i < table.n());
    let lo = len.saturating_sub(table.mccw[table.reduce(i + len)]).max(2);
    let hi = (len - 2).min(table.mcw[i]);
    if lo > hi {
        return None;
    }
    let (lo, hi) = table.poly.clip_to_strip(i, len, lo, hi, strip)?;
    // Cheap exact pruning on ranks alone: every apex costs at least
    // max(λ*(P_ik), λ*(P_kj)). Scanned only for short frames, so that the
    // bound stays O(log n) per pair.
    if hi - lo < SHORT_FRAME {
        let hopeless =
            (lo..=hi).all(|r| table.rank(i, r).max(table.rank_to(i + len, len - r)) >= bound);
        if hopeless {
            return None;
        }
    }
    Some((lo, hi))
}

/// Frames shorter than this are scanned for the rank-only pruning test.
const SHORT_FRAME: usize = 24;

/// Receives the block optima of the search pairs.
pub(super) trait BlockSink {
    /// A rank `b` such that no candidate whose value is at least the table
    /// value of rank `b` can improve the answer (pruning only; `u32::MAX`
    /// disables it).
    fn bound(&self) -> u32;
    /// The search pair `(i, i+len)`, whose outer piece `P_ji` has rank
    /// `block.outer`, attains `value` = max(λ*(P_ik), λ*(P_kj), A(i,k,j))
    /// at `k = i + r`, the optimum of one block.
    fn offer(&mut self, table: &SleeveTable, block: &Block, i: usize, r: usize, value: Bottleneck);
}

/// The best candidate so far, seeded with the best (A′) candidate.
struct BestCandidate {
    best: Option<(Bottleneck, Witness)>,
    /// The smallest rank whose value is ≥ the best value (or `u32::MAX`), so
    /// that comparing a table value with the best is a `u32` comparison.
    bound: u32,
}

impl BestCandidate {
    fn new(table: &SleeveTable, best: Option<(Bottleneck, Witness)>) -> Self {
        let mut sink = BestCandidate {
            best,
            bound: u32::MAX,
        };
        sink.update_bound(table);
        sink
    }

    fn update_bound(&mut self, table: &SleeveTable) {
        self.bound = match self.best {
            None => u32::MAX,
            Some((Bottleneck::Ranked(r), _)) => r,
            Some((Bottleneck::Triangle(t), _)) => {
                let max_rank = table.max_rank() as usize;
                first_true(1, max_rank, |r| {
                    table
                        .poly
                        .compare_triangles(table.representative(r as u32), t)
                        != Ordering::Less
                }) as u32
            }
        };
    }
}

impl BlockSink for BestCandidate {
    fn bound(&self) -> u32 {
        self.bound
    }

    fn offer(&mut self, table: &SleeveTable, block: &Block, i: usize, r: usize, value: Bottleneck) {
        let (outer, len) = (block.outer, block.len);
        if outer >= self.bound {
            return;
        }
        let improves = match (value, self.best) {
            (_, None) => true,
            (Bottleneck::Ranked(v), _) => v < self.bound,
            (Bottleneck::Triangle(_), Some((best, _))) => {
                table.compare(value, best) == Ordering::Less
            }
        };
        if improves {
            let candidate = table.max(Bottleneck::Ranked(outer), value);
            self.best = Some((candidate, Witness::Triangle { i, r, len }));
            self.update_bound(table);
        }
    }
}

/// The MinMax optimum (step iv), as a witness for step v. Needs n ≥ 4.
pub(super) fn minmax_witness(table: &SleeveTable) -> Witness {
    let n = table.n();
    debug_assert!(n >= 4);
    // (A′) proper 2-2 diagonals. There may be none (a polygon like a
    // triangle with three rounded corners has only internal 2-2-2
    // triangles); then (B′) alone decides.
    let mut best: Option<(u32, Witness)> = None;
    for i in 0..n {
        for len in 2..=table.mcw[i].min(n - 2) {
            if table.solved(i + len, n - len) {
                let value = table.rank(i, len).max(table.rank(i + len, n - len));
                if best.is_none_or(|(b, _)| value < b) {
                    best = Some((value, Witness::Diagonal { i, len }));
                }
            }
        }
    }
    let seed = best.map(|(value, witness)| (Bottleneck::Ranked(value), witness));
    let mut sink = BestCandidate::new(table, seed);
    search_pairs(table, &mut sink);
    sink.best
        .expect("the candidate theorem covers some triangulation")
        .1
}

/// Runs all four blocks of every search pair into `sink`: the descending
/// blocks row by row, the ascending blocks column by column.
pub(super) fn search_pairs(table: &SleeveTable, sink: &mut impl BlockSink) {
    for i in 0..table.n() {
        descending_blocks_of_row(table, i, sink);
    }
    for j in 0..table.n() {
        ascending_blocks_of_column(table, j, sink);
    }
}

/// One block of a line (row or column) in line coordinates `x`: the anchor
/// (where `g` is smallest) and the far end, the search pair's `len` and the
/// rank of its outer piece `P_ji` (carried along: reading it again from the
/// table would cost a cache miss per block).
#[derive(Clone, Copy, Debug)]
pub(super) struct Block {
    anchor: usize,
    far: usize,
    pub(super) len: usize,
    pub(super) outer: u32,
}

/// Row `i`, line coordinate `x = r − 2` for `r ∈ [2, mcw(i)]`, `f = λ*(P_{i,i+r})`.
/// Blocks D1 (objective max(f, A), A non-increasing: anchored right) and D2
/// (objective max(f, λ*(P_kj)), non-decreasing: anchored left).
fn descending_blocks_of_row(table: &SleeveTable, i: usize, sink: &mut impl BlockSink) {
    let n = table.n();
    let width = table.mcw[i] - 1;
    let mut tops = TopFromStart::new(&table.poly, i);
    let (mut right_anchored, mut left_anchored) = (Vec::new(), Vec::new());
    // Offsets from `i` of the last strip's ends and switch: the starting
    // guesses for the next pair of the row.
    let (mut strip, mut last_switch) = ((0, 0), 0);
    for len in table.mcw[i] + 1..=n - 2 {
        let j = i + len;
        if !table.solved(j, n - len) {
            continue;
        }
        // P_ji ends at i: read along column i, not across the rows j.
        let outer = table.rank_to(i, n - len);
        if outer >= sink.bound() {
            continue;
        }
        let Some((lo, hi)) = pair_frame(table, i, len, sink.bound(), &mut strip) else {
            continue;
        };
        // Top(i, j) clamped to F splits it into the ascending part
        // [lo, top] and the descending part [top, hi]. Clamping suffices: if
        // Top < lo all of F descends and the ascending part is [lo, lo]; if
        // Top > hi the descending part is [hi, hi]. A one-vertex part is
        // evaluated exactly whatever the monotonicity, since its switch
        // predicate says which objective applies there.
        let lo = tops.offset(len).clamp(lo, hi);
        let switch = first_true_near(lo, hi, last_switch, |r| {
            let area = Bottleneck::Triangle([i, i + r, j]);
            let column = Bottleneck::Ranked(table.rank_to(j, len - r));
            table.compare(area, column) == Ordering::Less
        });
        last_switch = switch;
        if lo < switch {
            right_anchored.push(Block {
                anchor: switch - 1 - 2,
                far: lo - 2,
                len,
                outer,
            });
        }
        if switch <= hi {
            left_anchored.push(Block {
                anchor: switch - 2,
                far: hi - 2,
                len,
                outer,
            });
        }
    }
    let f = |x: usize| table.rank(i, x + 2);
    sweep(
        width,
        f,
        &right_anchored,
        Anchor::Right,
        |block, records| {
            let j = i + block.len;
            let area = |x: usize| Bottleneck::Triangle([i, i + x + 2, j]);
            offer_crossing(table, sink, block, records, f, area, |x| (i, x + 2));
        },
    );
    sweep(width, f, &left_anchored, Anchor::Left, |block, records| {
        let len = block.len;
        let column = |x: usize| Bottleneck::Ranked(table.rank_to(i + len, len - x - 2));
        offer_crossing(table, sink, block, records, f, column, |x| (i, x + 2));
    });
}

/// Column `j`, line coordinate `x` for `k = j − mccw(j) + x`, i.e. the
/// piece `P_kj` of length `d = mccw(j) − x ∈ [2, mccw(j)]`, `f = λ*(P_kj)`.
/// Blocks U1 (objective max(f, λ*(P_ik)), non-increasing: anchored right)
/// and U2 (objective max(f, A), A non-decreasing: anchored left).
fn ascending_blocks_of_column(table: &SleeveTable, j: usize, sink: &mut impl BlockSink) {
    let n = table.n();
    let reach = table.mccw[j];
    let width = reach - 1;
    let mut tops = TopFromEnd::new(&table.poly, j);
    let (mut right_anchored, mut left_anchored) = (Vec::new(), Vec::new());
    // Distances from `j` of the last strip's ends and switch: the starting
    // guesses for the next pair of the column.
    let (mut strip_from_end, mut last_switch_from_end) = ((0, 0), 0);
    for len in reach + 1..=n - 2 {
        let i = table.reduce(j + n - len);
        if !table.solved(j, n - len) {
            continue;
        }
        let outer = table.rank(j, n - len);
        if outer >= sink.bound() {
            continue;
        }
        let from_end = |d: usize| len.saturating_sub(d);
        let mut strip = (from_end(strip_from_end.0), from_end(strip_from_end.1));
        let frame = pair_frame(table, i, len, sink.bound(), &mut strip);
        strip_from_end = (len - strip.0.min(len), len - strip.1.min(len));
        let Some((lo, hi)) = frame else {
            continue;
        };
        // Top clamped to F (see the row case).
        let hi = tops.offset(len).clamp(lo, hi);
        let switch = first_true_near(lo, hi, from_end(last_switch_from_end), |r| {
            let area = Bottleneck::Triangle([i, i + r, i + len]);
            let row = Bottleneck::Ranked(table.rank(i, r));
            table.compare(area, row) != Ordering::Less
        });
        last_switch_from_end = len - switch.min(len);
        // Offset r sits at x = r + reach − len (≥ 0 since r ≥ len − reach).
        let x = |r: usize| r + reach - len;
        if lo < switch {
            right_anchored.push(Block {
                anchor: x(switch - 1),
                far: x(lo),
                len,
                outer,
            });
        }
        if switch <= hi {
            left_anchored.push(Block {
                anchor: x(switch),
                far: x(hi),
                len,
                outer,
            });
        }
    }
    let f = |x: usize| table.rank_to(j, reach - x);
    sweep(
        width,
        f,
        &right_anchored,
        Anchor::Right,
        |block, records| {
            let len = block.len;
            let i = (j + n - len) % n;
            let r = |x: usize| x + len - reach;
            let row = |x: usize| Bottleneck::Ranked(table.rank(i, r(x)));
            offer_crossing(table, sink, block, records, f, row, |x| (i, r(x)));
        },
    );
    sweep(width, f, &left_anchored, Anchor::Left, |block, records| {
        let len = block.len;
        let i = (j + n - len) % n;
        let r = |x: usize| x + len - reach;
        let area = |x: usize| Bottleneck::Triangle([i, i + r(x), i + len]);
        offer_crossing(table, sink, block, records, f, area, |x| (i, r(x)));
    });
}

/// Which end of its blocks `g` is smallest at.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Anchor {
    Left,
    Right,
}

/// One monotone-stack sweep over the line `x ∈ [0, width)` towards the
/// anchors: at each anchor the stack holds, from its top, the anchor and the
/// successive strict running minima of `f` moving away from it. Each block
/// gets the records inside it, outermost first, anchor last. O(width) plus
/// O(log width) per block; blocks are bucketed by anchor (counting sort).
fn sweep(
    width: usize,
    f: impl Fn(usize) -> u32,
    blocks: &[Block],
    anchor_side: Anchor,
    mut answer: impl FnMut(&Block, &[usize]),
) {
    if blocks.is_empty() {
        return;
    }
    let mut start = vec![0usize; width + 1];
    for b in blocks {
        start[b.anchor + 1] += 1;
    }
    for x in 0..width {
        start[x + 1] += start[x];
    }
    let mut fill = start.clone();
    let mut order = vec![0usize; blocks.len()];
    for (index, b) in blocks.iter().enumerate() {
        order[fill[b.anchor]] = index;
        fill[b.anchor] += 1;
    }
    let mut stack: Vec<usize> = Vec::with_capacity(width);
    let mut visit = |x: usize| {
        while stack.last().is_some_and(|&top| f(top) >= f(x)) {
            stack.pop();
        }
        stack.push(x);
        for &index in &order[start[x]..start[x + 1]] {
            let block = &blocks[index];
            let inside = match anchor_side {
                Anchor::Right => stack.partition_point(|&y| y < block.far),
                Anchor::Left => stack.partition_point(|&y| y > block.far),
            };
            answer(block, &stack[inside..]);
        }
    };
    match anchor_side {
        Anchor::Right => (0..width).for_each(&mut visit),
        Anchor::Left => (0..width).rev().for_each(&mut visit),
    }
}

/// Minimises `max(f, g)` over one block from its records (outermost first,
/// anchor last): from the anchor outwards `f` strictly falls and `g` does
/// not fall, so `[g ≥ f]` is false…false, true…true and the optimum is the
/// last record before the crossing (value `f`) or the first at it (value
/// `g`). Both are offered; the sink keeps the smaller. `apex` maps `x` to
/// the search pair's `(i, r)`.
fn offer_crossing(
    table: &SleeveTable,
    sink: &mut impl BlockSink,
    block: &Block,
    records: &[usize],
    f: impl Fn(usize) -> u32,
    g: impl Fn(usize) -> Bottleneck,
    apex: impl Fn(usize) -> (usize, usize),
) {
    // The outermost record is the block's smallest `f`, a lower bound of
    // every candidate in it: a block that cannot beat the bound needs no
    // exact comparison.
    if f(records[0]) >= sink.bound() {
        return;
    }
    let count = records.len();
    let at = |t: usize| records[count - 1 - t];
    // Likewise `g` at the anchor, where it is smallest, when it is a rank.
    if matches!(g(at(0)), Bottleneck::Ranked(v) if v >= sink.bound()) {
        return;
    }
    let crossing = first_true(0, count - 1, |t| {
        let x = at(t);
        table.compare(g(x), Bottleneck::Ranked(f(x))) != Ordering::Less
    });
    if crossing > 0 {
        let x = at(crossing - 1);
        let (i, r) = apex(x);
        sink.offer(table, block, i, r, Bottleneck::Ranked(f(x)));
    }
    if crossing < count {
        let x = at(crossing);
        let (i, r) = apex(x);
        sink.offer(table, block, i, r, g(x));
    }
}
