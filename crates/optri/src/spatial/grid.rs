//! A grid of square cells that stores only its occupied cells, for cell
//! sizes that follow a length scale whatever the spread of the points
//! (clustered inputs). Coordinate-only: it buckets items by the cell of a
//! point and answers "which cells meet this box", so that a caller runs its
//! exact tests on fewer candidates; it never decides anything itself.
//!
//! The greedy triangulation's length rounds (`criteria::greedy::general`)
//! build them per round: for the open vertices, for the round's candidate
//! segments together with the earlier active edges, and (rebuilt only when
//! the rounds outgrow its cells) for the points.

use super::cell_geometry::{dense_budget, CellGeometry};
use crate::kernel::Point;
use crate::parallel::prelude::*;

/// A cell: its row and column.
type Key = (u64, u64);

/// An empty cell in the dense table.
const EMPTY: u32 = u32::MAX;

/// Cells per parallel task when a dense grid sorts its cells. A tuning
/// choice: a task's cells hold a few items each, so it does enough work to
/// outweigh its overhead; nothing depends on it but the time.
const CELLS_PER_TASK: usize = 1 << 16;

/// Square cells over a bounding box, for cell sizes that follow a round's
/// length scale whatever the spread of the points (clustered inputs): a
/// table over all cells when there are not many more cells than items,
/// else only the occupied cells, found by binary search. Cell lookups only
/// choose which exact tests to run; they are padded by a slack that covers
/// their rounding.
pub(crate) struct SparseGrid<T> {
    /// A cell's key is `(row, column)`, and its index in the dense table
    /// `row * columns + column`.
    geometry: CellGeometry,
    /// The occupied cells' keys, ascending, and their items' ranges.
    keys: Vec<Key>,
    start: Vec<u32>,
    /// Dense mode: the position in `keys` of every cell's key (`EMPTY` if
    /// empty). Empty in sparse mode.
    table: Vec<u32>,
    /// Sparse mode with not too many rows: where each row's keys start in
    /// `keys` (`rows + 1` entries), so that a row lookup searches only that
    /// row's keys. Empty otherwise.
    row_start: Vec<u32>,
    items: Vec<T>,
}

impl<T: Copy + Send + Sync> SparseGrid<T> {
    /// Buckets items `0..len` (`item(i)`, at `point(i)`) by cell, cells of
    /// about `cell` (never below the geometry's smallest cell, a fraction of
    /// the box); within a cell, by ascending `order`.
    pub(crate) fn new(
        bbox: [f64; 4],
        cell: f64,
        len: usize,
        point: impl Fn(usize) -> Point + Sync,
        item: impl Fn(usize) -> T + Sync,
        order: impl Fn(usize) -> u32 + Sync,
    ) -> Self {
        let geometry = CellGeometry::new(bbox, cell);
        let (columns, rows) = (geometry.columns(), geometry.rows());
        let mut grid = Self {
            geometry,
            keys: Vec::new(),
            start: Vec::new(),
            table: Vec::new(),
            row_start: Vec::new(),
            items: Vec::new(),
        };
        let cells = geometry.cells();
        if cells <= dense_budget(len) {
            // Counting sort over all cells, then each cell by `order`.
            let cells = cells as usize;
            let keys: Vec<u64> = (0..len)
                .into_par_iter()
                .map(|i| {
                    let (r, c) = grid.key(point(i));
                    r * columns + c
                })
                .collect();
            let mut count = vec![0u32; cells + 1];
            for &k in &keys {
                count[k as usize + 1] += 1;
            }
            for c in 0..cells {
                count[c + 1] += count[c];
            }
            let mut fill = count.clone();
            let mut slots = vec![0u32; len];
            for (i, &k) in keys.iter().enumerate() {
                slots[fill[k as usize] as usize] = i as u32;
                fill[k as usize] += 1;
            }
            drop((keys, fill));
            // The cells in blocks of `CELLS_PER_TASK`, in parallel: each
            // block sorts its cells' slots and lists its occupied cells,
            // numbering them from zero in its part of the table; the
            // blocks' offsets then make the numbers global.
            let mut table = vec![EMPTY; cells];
            let mut slot_blocks: Vec<&mut [u32]> = Vec::with_capacity(cells / CELLS_PER_TASK + 1);
            let mut rest = slots.as_mut_slice();
            for block in 0..cells.div_ceil(CELLS_PER_TASK) {
                let end = ((block + 1) * CELLS_PER_TASK).min(cells);
                let taken = (count[end] - count[block * CELLS_PER_TASK]) as usize;
                let (head, tail) = rest.split_at_mut(taken);
                slot_blocks.push(head);
                rest = tail;
            }
            let occupied: Vec<Vec<usize>> = table
                .par_chunks_mut(CELLS_PER_TASK)
                .zip(slot_blocks)
                .enumerate()
                .map(|(block, (table, slots))| {
                    let first = block * CELLS_PER_TASK;
                    let base = count[first] as usize;
                    let mut occupied = Vec::new();
                    for (offset, entry) in table.iter_mut().enumerate() {
                        let c = first + offset;
                        let (a, b) = (count[c] as usize - base, count[c + 1] as usize - base);
                        if a < b {
                            slots[a..b].sort_unstable_by_key(|&i| order(i as usize));
                            *entry = occupied.len() as u32;
                            occupied.push(c);
                        }
                    }
                    occupied
                })
                .collect();
            let mut offsets = Vec::with_capacity(occupied.len());
            let mut total = 0u32;
            for block in &occupied {
                offsets.push(total);
                total += block.len() as u32;
            }
            table
                .par_chunks_mut(CELLS_PER_TASK)
                .zip(&offsets)
                .for_each(|(table, &offset)| {
                    if offset > 0 {
                        for entry in table.iter_mut().filter(|e| **e != EMPTY) {
                            *entry += offset;
                        }
                    }
                });
            let occupied: Vec<usize> = occupied.concat();
            grid.keys = occupied
                .par_iter()
                .map(|&c| (c as u64 / columns, c as u64 % columns))
                .collect();
            grid.start = occupied.par_iter().map(|&c| count[c]).collect();
            grid.start.push(len as u32);
            grid.table = table;
            grid.items = slots.par_iter().map(|&i| item(i as usize)).collect();
        } else {
            let mut keyed: Vec<(Key, u32, u32)> = (0..len)
                .into_par_iter()
                .map(|i| (grid.key(point(i)), order(i), i as u32))
                .collect();
            keyed.par_sort_unstable();
            grid.items = keyed
                .par_iter()
                .map(|&(_, _, i)| item(i as usize))
                .collect();
            for (i, &(k, _, _)) in keyed.iter().enumerate() {
                if grid.keys.last() != Some(&k) {
                    grid.keys.push(k);
                    grid.start.push(i as u32);
                }
            }
            grid.start.push(keyed.len() as u32);
            if rows <= dense_budget(len) {
                // A binary search over all keys per row of a lookup was a
                // fifth of greedy's time on Gaussian clusters (the active
                // edges' index); a row's keys are few and close together.
                let mut row_start = vec![0u32; rows as usize + 1];
                for &(r, _) in &grid.keys {
                    row_start[r as usize + 1] += 1;
                }
                for r in 0..rows as usize {
                    row_start[r + 1] += row_start[r];
                }
                grid.row_start = row_start;
            }
        }
        grid
    }

    /// The inverse of the cell size actually used (after the clamp to the
    /// geometry's smallest cell).
    #[inline]
    pub(crate) fn inverse_cell(&self) -> f64 {
        self.geometry.inverse_cell()
    }

    /// The number of occupied cells.
    #[inline]
    pub(crate) fn occupied(&self) -> usize {
        self.keys.len()
    }

    #[inline]
    fn key(&self, p: Point) -> Key {
        (self.geometry.row(p[1]), self.geometry.column(p[0]))
    }

    /// The items of the `k`-th occupied cell.
    #[inline]
    pub(crate) fn cell(&self, k: usize) -> &[T] {
        &self.items[self.start[k] as usize..self.start[k + 1] as usize]
    }

    /// Calls `f` on the occupied cells (positions in `keys`) of row `r`
    /// between columns `c0` and `c1`; stops early and returns `true` when
    /// `f` does.
    #[inline]
    fn any_cell_in_row(&self, r: u64, c0: u64, c1: u64, mut f: impl FnMut(usize) -> bool) -> bool {
        if !self.row_start.is_empty() {
            let (a, b) = (
                self.row_start[r as usize] as usize,
                self.row_start[r as usize + 1] as usize,
            );
            let row = &self.keys[a..b];
            let mut k = row.partition_point(|&(_, c)| c < c0);
            while k < row.len() && row[k].1 <= c1 {
                if f(a + k) {
                    return true;
                }
                k += 1;
            }
        } else if self.table.is_empty() {
            let (lo, hi) = ((r, c0), (r, c1));
            let mut k = self.keys.partition_point(|&key| key < lo);
            while k < self.keys.len() && self.keys[k] <= hi {
                if f(k) {
                    return true;
                }
                k += 1;
            }
        } else {
            let columns = self.geometry.columns();
            let (lo, hi) = (r * columns + c0, r * columns + c1);
            for &k in &self.table[lo as usize..=hi as usize] {
                if k != EMPTY && f(k as usize) {
                    return true;
                }
            }
        }
        false
    }

    /// Calls `f` on the items of every occupied cell meeting the box around
    /// `a, b` widened by `pad` (and the slack); stops early and returns
    /// `true` when `f` does.
    #[inline]
    pub(crate) fn any_cell_near(
        &self,
        a: Point,
        b: Point,
        pad: f64,
        mut f: impl FnMut(&[T]) -> bool,
    ) -> bool {
        let g = &self.geometry;
        let (px, py) = g.padding(pad);
        let (c0, c1) = (
            g.column(fmin(a[0], b[0]) - px),
            g.column(fmax(a[0], b[0]) + px),
        );
        let (r0, r1) = (g.row(fmin(a[1], b[1]) - py), g.row(fmax(a[1], b[1]) + py));
        if self.table.is_empty() && r1 - r0 >= self.keys.len() as u64 {
            // More rows than occupied cells (a long query on a fine sparse
            // grid): scan the occupied cells in the key range instead.
            let (lo, hi) = ((r0, c0), (r1, c1));
            let first = self.keys.partition_point(|&key| key < lo);
            return self.keys[first..]
                .iter()
                .take_while(|&&key| key <= hi)
                .enumerate()
                .any(|(i, &(_, column))| (c0..=c1).contains(&column) && f(self.cell(first + i)));
        }
        (r0..=r1).any(|r| self.any_cell_in_row(r, c0, c1, |k| f(self.cell(k))))
    }

    /// Calls `f` on the items of the occupied cell `k` and of each of its
    /// occupied neighbours.
    pub(crate) fn for_block(&self, k: usize, mut f: impl FnMut(&[T])) {
        let (row, column) = self.keys[k];
        let (columns, rows) = (self.geometry.columns(), self.geometry.rows());
        let (c0, c1) = (column.saturating_sub(1), (column + 1).min(columns - 1));
        for r in row.saturating_sub(1)..=(row + 1).min(rows - 1) {
            self.any_cell_in_row(r, c0, c1, |m| {
                f(self.cell(m));
                false
            });
        }
    }

    /// The number of items in the occupied cell `k` and its eight
    /// neighbours.
    pub(crate) fn block_len(&self, k: usize) -> usize {
        let mut len = 0;
        self.for_block(k, |items| len += items.len());
        len
    }
}

/// `min` and `max` of finite numbers (one instruction each; `f64::min`
/// also handles NaN).
#[inline]
pub(crate) fn fmin(a: f64, b: f64) -> f64 {
    if a < b {
        a
    } else {
        b
    }
}

#[inline]
pub(crate) fn fmax(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use rand::{rngs::StdRng, Rng, SeedableRng};

    /// A cluster 10⁻⁹ wide in a unit box (below cells of 2⁻³⁰) spreads over
    /// many cells of 10⁻¹¹.
    #[test]
    fn cells_follow_a_cluster_far_below_the_box() {
        let mut points: Vec<Point> = vec![[0.0, 0.0], [1.0, 1.0]];
        for i in 0..20 {
            for j in 0..20 {
                points.push([0.5 + 5e-11 * i as f64, 0.5 + 5e-11 * j as f64]);
            }
        }
        let grid = SparseGrid::new(
            [0.0, 0.0, 1.0, 1.0],
            1e-11,
            points.len(),
            |i| points[i],
            |i| i as u32,
            |i| i as u32,
        );
        assert_eq!(grid.occupied(), 402);
    }

    /// Every item within `pad` of a query box is in a cell the lookup
    /// visits, against brute force, for clusters at several scales (down to
    /// below the finest cells), at offsets up to 10¹⁵ and near the origin,
    /// in dense mode and in sparse mode with and without the row directory,
    /// with items that are computed midpoints.
    #[test]
    fn lookups_find_every_item_within_the_pad() {
        let mut rng = StdRng::seed_from_u64(31);
        let mut checked = 0;
        // Grids seen in each mode: dense, sparse by rows, sparse.
        let mut modes = [0; 3];
        for case in 0..120 {
            let offset = [0.0, 1.0, -3e7, 1e15][case % 4];
            let box_side = [1.0, 1e3, 1e11][case / 4 % 3];
            let cluster = box_side * [1e-3, 1e-9, 1e-17, 1e-25][case / 12 % 4];
            let mut points: Vec<Point> = vec![
                [offset, offset],
                [offset + box_side, offset + 0.3 * box_side],
            ];
            let centre = [offset + 0.4 * box_side, offset + 0.2 * box_side];
            for _ in 0..200 {
                points.push([
                    centre[0] + cluster * rng.gen_range(-1.0..1.0),
                    centre[1] + cluster * rng.gen_range(-1.0..1.0),
                ]);
            }
            let bbox = crate::spatial::bounding_box(&points);
            // Items are midpoints of consecutive points (computed, rounded).
            let m = points.len() - 1;
            let midpoint = |i: usize| {
                let (a, b) = (points[i], points[i + 1]);
                [0.5 * a[0] + 0.5 * b[0], 0.5 * a[1] + 0.5 * b[1]]
            };
            let cell = cluster * [0.01, 0.1, 1.0, 30.0][(case + case / 4) % 4];
            let grid = SparseGrid::new(bbox, cell, m, midpoint, |i| i as u32, |i| i as u32);
            modes[match (grid.table.is_empty(), grid.row_start.is_empty()) {
                (false, _) => 0,
                (true, false) => 1,
                (true, true) => 2,
            }] += 1;
            for _ in 0..50 {
                let a = points[rng.gen_range(0..points.len())];
                let b = points[rng.gen_range(0..points.len())];
                let pad = cluster * rng.gen_range(0.0..0.2);
                let mut found = vec![false; m];
                grid.any_cell_near(a, b, pad, |items| {
                    for &i in items {
                        found[i as usize] = true;
                    }
                    false
                });
                for (i, &seen) in found.iter().enumerate() {
                    let p = midpoint(i);
                    let inside = p[0] >= fmin(a[0], b[0]) - pad
                        && p[0] <= fmax(a[0], b[0]) + pad
                        && p[1] >= fmin(a[1], b[1]) - pad
                        && p[1] <= fmax(a[1], b[1]) + pad;
                    assert!(seen || !inside, "case {case}: item {i} missed");
                    checked += usize::from(inside);
                }
            }
        }
        assert!(checked > 100_000, "{checked}");
        assert!(modes.iter().all(|&k| k >= 5), "{modes:?}");
    }
}
