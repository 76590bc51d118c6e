//! The density guard of the module docs ("Length rounds"): it picks a
//! round's threshold so that the round's candidate pairs stay linear in the
//! number of open vertices, in total and near every cell. It only affects
//! the running time; rounds stay disjoint length ranges whatever it picks.

use crate::kernel::Point;
use crate::parallel::prelude::*;
use crate::spatial::SparseGrid;

/// Not on a line chain (see `line_classes` in the parent module).
pub(super) const NO_LINE: u32 = u32::MAX;

/// Pairs of items of `a` and `b` (cells sorted by class) in the same line
/// class: never candidates, so the guard does not count them.
fn same_line_pairs(a: &[u32], b: &[u32], class: &[u32]) -> usize {
    let (mut i, mut j, mut pairs) = (0, 0, 0);
    while i < a.len() && j < b.len() {
        let (ca, cb) = (class[a[i] as usize], class[b[j] as usize]);
        if ca == NO_LINE || cb == NO_LINE {
            break; // NO_LINE sorts last
        }
        if ca < cb {
            i += 1;
        } else if cb < ca {
            j += 1;
        } else {
            let ra = a[i..]
                .iter()
                .take_while(|&&x| class[x as usize] == ca)
                .count();
            let rb = b[j..]
                .iter()
                .take_while(|&&x| class[x as usize] == ca)
                .count();
            pairs += ra * rb;
            i += ra;
            j += rb;
        }
    }
    pairs
}

/// The guard's pair budget is `PAIRS_PER_OPEN_VERTEX` per open vertex plus
/// `EXTRA_PAIRS`. A tuning choice (no measurement of it is recorded, commit
/// 752d473). For scale: uniform points at the first threshold have about 2.6
/// points a cell and 23 in a cell's block of nine, so about 23 pairs per
/// vertex, half the budget; the constant lets the few open vertices of late
/// rounds take their pairs without halving the step.
const PAIRS_PER_OPEN_VERTEX: usize = 48;
const EXTRA_PAIRS: usize = 4096;

/// The guard's bound on the pairs a cell and its neighbours make (uniform
/// points at the first threshold stay well below it).
const MAX_CELL_PAIRS: usize = 1024;

/// Grid cells are this much wider than the threshold, so that pairs shorter
/// than it sit in neighbouring cells despite rounding. A chosen margin
/// (rounding is a few units of 2⁻⁵³).
const CELL_WIDENING: f64 = 1.001;

/// A computed cell narrower than `FINEST_CELL` times the requested one means
/// the grid clamped it to its finest cells (a chosen margin below 1 for the
/// rounding of `inv · cell`).
const FINEST_CELL: f64 = 0.999;

/// The guard stops halving once the step above the last threshold is below
/// a fraction of the threshold, the *floor*, which starts at this value. A
/// chosen floor: after round 0, where the step starts at the last
/// threshold, it bounds the halvings at about log₂ 1000 ≈ 10 a round.
pub(super) const MIN_RELATIVE_STEP: f64 = 1e-3;

/// The largest floor: a stretch of quiet rounds still grows the threshold
/// by at least 4/3 a round. A chosen cap below 1 (where the guard would not
/// shrink the step at all), so that the guard keeps bounding a round's pairs
/// to within a constant factor of the step it wants.
const MAX_FLOOR: f64 = 0.25;

/// A round is *quiet* when its candidates times this are fewer than its open
/// vertices. A chosen ratio: the crawls below had no candidates at all in
/// most rounds; a busier round is real work, which the guard must bound.
const QUIET_ROUND_RATIO: usize = 4;

/// The floor of the next round after one with `candidates` candidates among
/// `open` open vertices: doubled after a quiet round (up to [`MAX_FLOOR`]),
/// else halved (down to [`MIN_RELATIVE_STEP`]).
///
/// Why: the guard counts every pair in neighbouring cells, including pairs
/// shorter than the last threshold and pairs no edge can join. Where those
/// dominate (a regular polygon's chords come in lengths a spacing apart)
/// a fixed floor made thousands of rounds with no candidate at relative
/// steps of 10⁻³ (2400 rounds for two concentric circles of 1000
/// points each). Growing the floor geometrically makes such a stretch
/// O(log) rounds, and a busy round brings the guard back. Only the running
/// time depends on it.
pub(super) fn next_floor(floor: f64, candidates: usize, open: usize) -> f64 {
    if QUIET_ROUND_RATIO * candidates < open {
        (2.0 * floor).min(MAX_FLOOR)
    } else {
        (0.5 * floor).max(MIN_RELATIVE_STEP)
    }
}

/// `T_k = growth · T_{k-1}` before the guard (module docs), with `growth`
/// from [`next_growth`]: `THRESHOLD_GROWTH` after a busy round.
pub(super) const THRESHOLD_GROWTH: f64 = 2.0;

/// The largest growth of the threshold from one round to the next. A chosen
/// cap: when it overshoots, the guard halves back in at most 8 grids.
const MAX_GROWTH: f64 = 256.0;

/// The growth of the next round's proposed threshold after one with
/// `candidates` candidates among `open` open vertices: squared after a quiet
/// round (up to [`MAX_GROWTH`]), else [`THRESHOLD_GROWTH`].
///
/// Why: points at several length scales (a tiny cluster inside a cluster
/// inside a box) leave most vertices open and without candidates
/// while the threshold doubles from one scale to the next, a round over all
/// of them for each doubling (2¹⁹ between scales 10⁻¹⁴ and 10⁻⁸: 19 rounds).
/// Squaring the growth crosses such a gap in O(log log) rounds; the guard
/// still bounds a round's pairs, and a busy round brings the growth back.
/// Only the running time depends on it.
pub(super) fn next_growth(growth: f64, candidates: usize, open: usize) -> f64 {
    if QUIET_ROUND_RATIO * candidates < open {
        (growth * growth).min(MAX_GROWTH)
    } else {
        THRESHOLD_GROWTH
    }
}

/// The threshold of the next round, at most `proposed` and with a step above
/// `lower` of at least about `floor` times the threshold, and the grid of the
/// open vertices (indices into `open`) with cells a little wider than it,
/// each cell sorted by `class` (the line classes of the parent module;
/// pairs within one class are not counted).
///
/// Guard: a round enumerates the pairs of open vertices in neighbouring
/// cells, and its candidates' crossings grow with their square; where points
/// are much denser than average (clustered inputs) a threshold scaled to the
/// mean spacing would make that quadratic. So the step above `lower` is
/// halved until the pair count is linear in the number of open vertices
/// (only the running time depends on this choice; rounds stay disjoint
/// length ranges).
pub(super) fn round_grid(
    points: &[Point],
    bbox: [f64; 4],
    open: &[u32],
    class: &[u32],
    lower: f64,
    proposed: f64,
    floor: f64,
) -> (f64, SparseGrid<u32>) {
    let any_line = class.iter().any(|&c| c != NO_LINE);
    let budget = PAIRS_PER_OPEN_VERTEX * open.len() + EXTRA_PAIRS;
    let mut threshold = proposed;
    loop {
        let grid = SparseGrid::new(
            bbox,
            threshold * CELL_WIDENING,
            open.len(),
            |j| points[open[j] as usize],
            |j| j as u32,
            |j| class[j],
        );
        let (pairs, worst) = (0..grid.occupied())
            .into_par_iter()
            .map(|k| {
                let cell = grid.cell(k);
                let pairs = if any_line {
                    let mut pairs = 0;
                    grid.for_block(k, |other| {
                        pairs += cell.len() * other.len() - same_line_pairs(cell, other, class);
                    });
                    pairs
                } else {
                    cell.len() * grid.block_len(k)
                };
                (pairs, pairs)
            })
            .reduce(|| (0, 0), |(s1, m1), (s2, m2)| (s1 + s2, m1.max(m2)));
        let step = threshold - lower;
        // Both in total and in every cell: one dense cluster's pairs would
        // cross each other quadratically often. Stop shrinking once the step
        // is tiny or the grid has reached its finest cells (points closer
        // than that stay together whatever the threshold).
        let finest = grid.inverse_cell() * threshold * CELL_WIDENING < FINEST_CELL;
        if (pairs <= budget && worst <= MAX_CELL_PAIRS) || step <= floor * threshold || finest {
            return (threshold, grid);
        }
        threshold = lower + 0.5 * step;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_floor_grows_after_quiet_rounds_and_shrinks_after_busy_ones() {
        let mut floor = MIN_RELATIVE_STEP;
        for _ in 0..7 {
            floor = next_floor(floor, 249, 1000);
        }
        assert_eq!(floor, MIN_RELATIVE_STEP * 128.0);
        floor = next_floor(floor, 0, 1000);
        assert_eq!(floor, MAX_FLOOR);
        assert_eq!(next_floor(floor, 249, 1000), MAX_FLOOR);
        assert_eq!(next_floor(floor, 250, 1000), 0.5 * MAX_FLOOR);
        assert_eq!(next_floor(MIN_RELATIVE_STEP, 5000, 1000), MIN_RELATIVE_STEP);
    }

    #[test]
    fn the_growth_squares_after_quiet_rounds_and_resets_after_busy_ones() {
        let mut growth = THRESHOLD_GROWTH;
        for expected in [4.0, 16.0, 256.0, MAX_GROWTH] {
            growth = next_growth(growth, 249, 1000);
            assert_eq!(growth, expected);
        }
        assert_eq!(next_growth(growth, 250, 1000), THRESHOLD_GROWTH);
    }
}
