//! The geometry of a grid of square cells over a bounding box — origin,
//! cell size, columns and rows, the cell of a coordinate, and the slack that
//! makes lookups cover rounding — shared by [`super::SparseGrid`] (only the
//! occupied cells) and [`super::PointCells`] (every cell, points in cell
//! order). Coordinate-only: a cell only chooses which exact tests a caller
//! runs.

use super::grid::fmax;
use crate::kernel::Point;

/// Smallest cell, as a fraction of the bounding box's longer side: 2⁻⁶².
/// Derived bound: a cell's row and column are kept apart (no product key),
/// each below 2⁶² + 1, which `f64 → u64` conversion represents exactly. Why
/// so fine: a cluster's cells must follow its spacing however small it is
/// against the box (10⁵ points in a 10⁻⁹ box inside a unit box put the whole
/// cluster in a few cells of a 2⁻³⁰ grid, and the greedy rounds went
/// quadratic). Doubles of magnitude `m` are `m·2⁻⁵²` apart, so cells of 2⁻⁶²
/// of the box separate every cluster whose coordinates are at least 2⁻¹⁰ of
/// the box's side in magnitude; only clusters closer still to the origin (or
/// below 2⁻⁶² of the box) share cells, which costs time, never correctness.
pub(super) const MIN_CELL_FRACTION: f64 = 1.0 / (1u64 << 62) as f64;

/// The lookup slack: `SLACK_PER_CELL` (10⁻⁹) per unit of cell size plus
/// `SLACK_RELATIVE` (2·10⁻¹⁵) per unit of coordinate magnitude and of pad.
/// Derived need, chosen margins: the column of a coordinate is monotone in
/// its rounded argument, so the slack only has to cover rounding. An item
/// position the callers compute (a midpoint) is within 2⁻⁵³ of the exact one
/// relative to the magnitude `m` of the box's coordinates; the query's padded
/// box `x ± (pad + slack)` takes two roundings, each within 2⁻⁵³ relative to
/// `m + pad + slack`. That is below `4·2⁻⁵³·(m + pad)` ≈ 4.4·10⁻¹⁶·(m + pad)
/// (the slack's own share being negligible), a quarter of `SLACK_RELATIVE`.
/// The pad lengths the callers compute (half-lengths, thresholds) are within a
/// few units of 2⁻⁵³ of a pad of about one cell; `SLACK_PER_CELL` is about
/// 10⁶ times that. (A relative part of 10⁻¹³ of the magnitude alone spanned
/// 800 units in the last place at 10¹⁵, so a cluster a few hundred units wide
/// there was one lookup for each of its points.)
pub(super) const SLACK_PER_CELL: f64 = 1e-9;
pub(super) const SLACK_RELATIVE: f64 = 2e-15;

/// A table over every cell is affordable while there are at most
/// `CELLS_PER_ITEM` cells per item plus `EXTRA_CELLS` ([`dense_budget`]). A
/// tuning choice (no measurement of it is recorded): a table costs time and
/// memory per cell, so it must stay within a constant factor of the items,
/// and 65 536 cells (a 256 KiB table) are cheap at any size.
const CELLS_PER_ITEM: u64 = 4;
const EXTRA_CELLS: u64 = 65536;

/// The most cells a table over every cell may have for `items` items.
#[inline]
pub(super) fn dense_budget(items: usize) -> u64 {
    CELLS_PER_ITEM * items as u64 + EXTRA_CELLS
}

/// Square cells over a bounding box: the cell of a coordinate (a column
/// and a row, clamped to the grid) and the slack that pads lookups.
#[derive(Clone, Copy, Debug)]
pub(crate) struct CellGeometry {
    x0: f64,
    y0: f64,
    inv: f64,
    columns: u64,
    rows: u64,
    slack_x: f64,
    slack_y: f64,
}

impl CellGeometry {
    /// Cells of about `cell` over `bbox`, never below [`MIN_CELL_FRACTION`]
    /// of the box's longer side (any positive size for a box that is a
    /// point, or a NaN cell).
    pub(super) fn new(bbox: [f64; 4], cell: f64) -> Self {
        Self::with_cell(bbox, Self::clamped(bbox, cell))
    }

    /// [`CellGeometry::new`], the cell coarsened by factors of 1.5 until
    /// there are at most [`dense_budget`]`(items)` cells.
    pub(super) fn within_dense_budget(bbox: [f64; 4], cell: f64, items: usize) -> Self {
        let [x0, y0, x1, y1] = bbox;
        let (w, h) = (x1 - x0, y1 - y0);
        let mut cell = Self::clamped(bbox, cell);
        let budget = dense_budget(items) as f64;
        while (w / cell + 1.0) * (h / cell + 1.0) > budget {
            cell *= 1.5;
        }
        Self::with_cell(bbox, cell)
    }

    fn clamped([x0, y0, x1, y1]: [f64; 4], cell: f64) -> f64 {
        let cell = fmax(cell, fmax(x1 - x0, y1 - y0) * MIN_CELL_FRACTION);
        // Zero (one point, or all equal) or NaN: any positive cell will do.
        if cell > 0.0 {
            cell
        } else {
            1.0
        }
    }

    fn with_cell(bbox: [f64; 4], cell: f64) -> Self {
        let [x0, y0, x1, y1] = bbox;
        let (mag_x, mag_y) = (fmax(x0.abs(), x1.abs()), fmax(y0.abs(), y1.abs()));
        Self {
            x0,
            y0,
            inv: 1.0 / cell,
            columns: ((x1 - x0) / cell) as u64 + 1,
            rows: ((y1 - y0) / cell) as u64 + 1,
            slack_x: SLACK_PER_CELL * cell + SLACK_RELATIVE * mag_x,
            slack_y: SLACK_PER_CELL * cell + SLACK_RELATIVE * mag_y,
        }
    }

    #[inline]
    pub(crate) fn columns(&self) -> u64 {
        self.columns
    }

    #[inline]
    pub(crate) fn rows(&self) -> u64 {
        self.rows
    }

    /// The number of cells (saturating).
    #[inline]
    pub(crate) fn cells(&self) -> u64 {
        self.columns.saturating_mul(self.rows)
    }

    /// The inverse of the cell size (after the clamp to
    /// [`MIN_CELL_FRACTION`] and any coarsening).
    #[inline]
    pub(crate) fn inverse_cell(&self) -> f64 {
        self.inv
    }

    /// The side of a cell.
    #[inline]
    pub(crate) fn cell_size(&self) -> f64 {
        1.0 / self.inv
    }

    /// The column of the coordinate `x`, clamped to the grid.
    #[inline]
    pub(crate) fn column(&self, x: f64) -> u64 {
        clamped_floor((x - self.x0) * self.inv, self.columns)
    }

    /// The row of the coordinate `y`, clamped to the grid.
    #[inline]
    pub(crate) fn row(&self, y: f64) -> u64 {
        clamped_floor((y - self.y0) * self.inv, self.rows)
    }

    /// The half-widths of the box a lookup with `pad` scans around its
    /// query: `pad` plus the slack (see [`SLACK_RELATIVE`]).
    #[inline]
    pub(crate) fn padding(&self, pad: f64) -> (f64, f64) {
        let pad = pad + SLACK_RELATIVE * pad;
        (pad + self.slack_x, pad + self.slack_y)
    }

    /// The largest slack of a lookup, in either direction: how far a point
    /// may lie outside the box of the cell it is bucketed in
    /// ([`CellGeometry::cell_box`]).
    #[inline]
    pub(crate) fn slack(&self) -> f64 {
        fmax(self.slack_x, self.slack_y)
    }

    /// The box of the cell `[column, row]` widened by the slack, which
    /// contains every point bucketed in that cell (the slack covers the
    /// rounding of [`CellGeometry::column`] and [`CellGeometry::row`] as it
    /// covers a lookup's, see [`SLACK_RELATIVE`]).
    #[inline]
    pub(crate) fn cell_box(&self, [column, row]: [u64; 2]) -> [f64; 4] {
        let size = self.cell_size();
        let (x, y) = (self.x0 + column as f64 * size, self.y0 + row as f64 * size);
        [
            x - self.slack_x,
            y - self.slack_y,
            x + size + self.slack_x,
            y + size + self.slack_y,
        ]
    }

    /// The cell `[column, row]` of a point.
    #[inline]
    pub(crate) fn cell_of(&self, p: Point) -> [u64; 2] {
        [self.column(p[0]), self.row(p[1])]
    }
}

/// `⌊c⌋` clamped to `0..count`.
#[inline]
fn clamped_floor(c: f64, count: u64) -> u64 {
    // Truncation is the floor for c ≥ 1 (and avoids a libm call).
    if c >= 1.0 {
        (c as u64).min(count - 1)
    } else {
        0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{rngs::StdRng, Rng, SeedableRng};

    #[test]
    fn the_smallest_cell_fraction_is_two_to_the_minus_sixty_two() {
        assert_eq!(MIN_CELL_FRACTION, 2f64.powi(-62));
    }

    /// Every point lies in the widened box of its cell, for boxes at
    /// several offsets and scales and cells from far below to far above
    /// the spread, near cell boundaries in particular.
    #[test]
    fn points_lie_in_the_box_of_their_cell() {
        let mut rng = StdRng::seed_from_u64(43);
        let mut checked = 0;
        for case in 0..48 {
            let offset = [0.0, 1.0, -3e7, 1e15][case % 4];
            let side = [1.0, 1e3, 1e11][case / 4 % 3];
            let bbox = [offset, offset, offset + side, offset + 0.4 * side];
            let cell = side * [1e-6, 1e-3, 0.07, 3.0][case / 12];
            let geometry = CellGeometry::new(bbox, cell);
            let size = geometry.cell_size();
            for _ in 0..2000 {
                // A point near a cell boundary, or anywhere.
                let x = if rng.gen_bool(0.5) {
                    let k = rng.gen_range(0..=geometry.columns()) as f64;
                    offset + k * size + size * 1e-12 * rng.gen_range(-1.0..1.0)
                } else {
                    offset + side * rng.gen_range(0.0..1.0)
                };
                let y = offset + 0.4 * side * rng.gen_range(0.0..1.0);
                let p = [x.clamp(bbox[0], bbox[2]), y];
                let b = geometry.cell_box(geometry.cell_of(p));
                assert!(
                    b[0] <= p[0] && p[0] <= b[2] && b[1] <= p[1] && p[1] <= b[3],
                    "case {case}: {p:?} outside {b:?}"
                );
                checked += 1;
            }
        }
        assert_eq!(checked, 48 * 2000);
    }
}
