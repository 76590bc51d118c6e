//! Points bucketed by the square cells of a grid, their coordinates stored
//! in cell order (row by row), so that a box query reads one contiguous run
//! of coordinates per row of cells: no per-cell indirection and no gather
//! through an index array. Coordinate-only, like [`super::SparseGrid`]: it
//! only chooses which points a caller tests exactly.
//!
//! Every cell is in the table (dense), so the cell must not be far below
//! the points' spacing: [`PointCells::new`] coarsens it until there are at
//! most about four cells per point. The minimum-weight pipeline's searches
//! (the diamond filter, triangle emptiness) read a few hundred points around
//! each point; through [`super::SparseGrid`] each cell of about one point
//! cost a table entry, a key, a range and the gather of the point.

use super::cell_geometry::CellGeometry;
use super::grid::{fmax, fmin};
use crate::kernel::Point;
use crate::parallel::prelude::*;

/// Points in the cells of a grid over their bounding box, in row-major cell
/// order, each cell's points by ascending index.
pub(crate) struct PointCells {
    geometry: CellGeometry,
    /// The slots of cell `row · columns + column` are
    /// `start[cell]..start[cell + 1]`.
    start: Vec<u32>,
    /// Coordinates and point indices, slot by slot.
    coords: Vec<Point>,
    ids: Vec<u32>,
}

/// A block of cells, inclusive: columns `c0..=c1`, rows `r0..=r1`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct CellBlock {
    c0: u64,
    c1: u64,
    r0: u64,
    r1: u64,
}

impl PointCells {
    /// Buckets `pts` (finite) into cells of about `cell` over `bbox` (their
    /// bounding box), coarsened to at most about four cells per point (the
    /// geometry's dense budget).
    pub(crate) fn new(pts: &[Point], bbox: [f64; 4], cell: f64) -> Self {
        let geometry = CellGeometry::within_dense_budget(bbox, cell, pts.len());
        let columns = geometry.columns();
        let cells = geometry.cells() as usize;
        let keys: Vec<u32> = pts
            .par_iter()
            .map(|&p| (geometry.row(p[1]) * columns + geometry.column(p[0])) as u32)
            .collect();
        let mut start = vec![0u32; cells + 1];
        for &k in &keys {
            start[k as usize + 1] += 1;
        }
        for c in 0..cells {
            start[c + 1] += start[c];
        }
        let mut fill = start.clone();
        let mut ids = vec![0u32; pts.len()];
        for (i, &k) in keys.iter().enumerate() {
            ids[fill[k as usize] as usize] = i as u32;
            fill[k as usize] += 1;
        }
        PointCells {
            geometry,
            coords: ids.par_iter().map(|&i| pts[i as usize]).collect(),
            start,
            ids,
        }
    }

    /// The cells' geometry.
    #[inline]
    pub(crate) fn geometry(&self) -> &CellGeometry {
        &self.geometry
    }

    /// The side of a cell.
    pub(crate) fn cell_size(&self) -> f64 {
        self.geometry.cell_size()
    }

    /// The point indices in cell order.
    pub(crate) fn ids(&self) -> &[u32] {
        &self.ids
    }

    /// The points' coordinates in cell order (`coords()[i]` is the point
    /// `ids()[i]`).
    pub(crate) fn coords(&self) -> &[Point] {
        &self.coords
    }

    /// The cells meeting the box `[lo, hi]` widened by `pad` and the slack
    /// (which covers the rounding of computed query boxes, as in
    /// [`super::SparseGrid`]); the block grows with the box.
    #[inline]
    pub(crate) fn block(&self, lo: Point, hi: Point, pad: f64) -> CellBlock {
        let g = &self.geometry;
        let (px, py) = g.padding(pad);
        CellBlock {
            c0: g.column(lo[0] - px),
            c1: g.column(hi[0] + px),
            r0: g.row(lo[1] - py),
            r1: g.row(hi[1] + py),
        }
    }

    /// The points of row `r`, columns `c0..=c1`.
    #[inline]
    fn run(&self, r: u64, c0: u64, c1: u64) -> (&[Point], &[u32]) {
        let base = r * self.geometry.columns();
        let (a, b) = (
            self.start[(base + c0) as usize] as usize,
            self.start[(base + c1 + 1) as usize] as usize,
        );
        (&self.coords[a..b], &self.ids[a..b])
    }

    /// The points (coordinates, indices) of the cell `[column, row]`.
    #[inline]
    pub(crate) fn cell(&self, [column, row]: [u64; 2]) -> (&[Point], &[u32]) {
        self.run(row, column, column)
    }

    /// Calls `f` on every cell `[column, row]` of the grid, empty ones
    /// included, at Chebyshev distance exactly `k` (in cells) from `centre`:
    /// the rings `k = 0, 1, …` visit each cell once.
    pub(crate) fn for_each_cell_in_ring(
        &self,
        centre: [u64; 2],
        k: u64,
        mut f: impl FnMut([u64; 2]),
    ) {
        let (columns, rows) = (self.geometry.columns(), self.geometry.rows());
        let [c, r] = centre;
        let (c0, c1) = (c.saturating_sub(k), (c + k).min(columns - 1));
        for row in r.saturating_sub(k)..=(r + k).min(rows - 1) {
            if row + k == r || row == r + k {
                for column in c0..=c1 {
                    f([column, row]);
                }
            } else {
                if k <= c {
                    f([c - k, row]);
                }
                if c + k < columns {
                    f([c + k, row]);
                }
            }
        }
    }

    /// Calls `f` on the points (coordinates, indices) of the cells meeting
    /// the box around `a, b` widened by `pad`, a run of cells at a time;
    /// stops and returns `true` when `f` does.
    #[inline]
    pub(crate) fn any_near(
        &self,
        a: Point,
        b: Point,
        pad: f64,
        mut f: impl FnMut(&[Point], &[u32]) -> bool,
    ) -> bool {
        let block = self.block(
            [fmin(a[0], b[0]), fmin(a[1], b[1])],
            [fmax(a[0], b[0]), fmax(a[1], b[1])],
            pad,
        );
        (block.r0..=block.r1).any(|r| {
            let (coords, ids) = self.run(r, block.c0, block.c1);
            !coords.is_empty() && f(coords, ids)
        })
    }

    /// Calls `f` on the points of the cells of `outer` not in `inner`
    /// (`inner` inside `outer`, or `None`), a run of cells at a time: growing
    /// blocks visit each cell once.
    pub(crate) fn for_each_between(
        &self,
        outer: CellBlock,
        inner: Option<CellBlock>,
        mut f: impl FnMut(&[Point], &[u32]),
    ) {
        let mut visit = |r: u64, c0: u64, c1: u64| {
            if c0 <= c1 {
                let (coords, ids) = self.run(r, c0, c1);
                if !coords.is_empty() {
                    f(coords, ids);
                }
            }
        };
        for r in outer.r0..=outer.r1 {
            match inner {
                Some(i) if (i.r0..=i.r1).contains(&r) => {
                    if i.c0 > outer.c0 {
                        visit(r, outer.c0, i.c0 - 1);
                    }
                    visit(r, i.c1 + 1, outer.c1);
                }
                _ => visit(r, outer.c0, outer.c1),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{rngs::StdRng, Rng, SeedableRng};

    /// Every point within `pad` of a query box is visited, against brute
    /// force, for clusters at several scales and offsets and cells from far
    /// below to far above the spacing; and growing blocks visit each point
    /// once.
    #[test]
    fn queries_find_every_point_within_the_pad_and_blocks_each_point_once() {
        let mut rng = StdRng::seed_from_u64(41);
        let mut checked = 0;
        for case in 0..96 {
            let offset = [0.0, 1.0, -3e7, 1e15][case % 4];
            let side = [1.0, 1e3, 1e11][case / 4 % 3];
            let spread = side * [1.0, 1e-3, 1e-9, 1e-17][case / 12 % 4];
            let mut pts: Vec<Point> = vec![[offset, offset], [offset + side, offset + 0.3 * side]];
            for _ in 0..300 {
                pts.push([
                    offset + 0.4 * side + spread * rng.gen_range(-0.4..0.4),
                    offset + 0.2 * side + spread * rng.gen_range(-0.2..0.2),
                ]);
            }
            let bbox = crate::spatial::bounding_box(&pts);
            let cell = spread * [0.001, 0.05, 1.0, 20.0][(case + case / 4) % 4];
            let grid = PointCells::new(&pts, bbox, cell);
            assert!(grid.ids().len() == pts.len());
            for _ in 0..40 {
                let a = pts[rng.gen_range(0..pts.len())];
                let b = pts[rng.gen_range(0..pts.len())];
                let pad = spread * rng.gen_range(0.0..0.1);
                let mut seen = vec![0u32; pts.len()];
                grid.any_near(a, b, pad, |coords, ids| {
                    for (c, &i) in coords.iter().zip(ids) {
                        assert_eq!(*c, pts[i as usize]);
                        seen[i as usize] += 1;
                    }
                    false
                });
                for (i, p) in pts.iter().enumerate() {
                    let inside = p[0] >= fmin(a[0], b[0]) - pad
                        && p[0] <= fmax(a[0], b[0]) + pad
                        && p[1] >= fmin(a[1], b[1]) - pad
                        && p[1] <= fmax(a[1], b[1]) + pad;
                    assert!(
                        seen[i] == 1 || (seen[i] == 0 && !inside),
                        "case {case}: point {i}"
                    );
                    checked += usize::from(inside);
                }
                // Growing blocks around a: each point at most once, and
                // every point of the last block exactly once.
                let mut count = vec![0u32; pts.len()];
                let mut previous = None;
                let mut block = grid.block(a, a, 0.0);
                for k in 0..6 {
                    let r = spread * 0.05 * (1 << k) as f64;
                    block = grid.block([a[0] - 0.6 * r, a[1] - r], [a[0] + r, a[1] + r], 0.0);
                    grid.for_each_between(block, previous, |_, ids| {
                        for &i in ids {
                            count[i as usize] += 1;
                        }
                    });
                    previous = Some(block);
                }
                let mut last = vec![0u32; pts.len()];
                grid.for_each_between(block, None, |_, ids| {
                    for &i in ids {
                        last[i as usize] += 1;
                    }
                });
                assert_eq!(count, last, "case {case}");
            }
        }
        assert!(checked > 50_000, "{checked}");
    }

    /// The rings around any cell visit every cell of the grid once, in
    /// order of Chebyshev distance, and `cell` lists each point in its own.
    #[test]
    fn rings_visit_every_cell_once() {
        let mut rng = StdRng::seed_from_u64(42);
        let pts: Vec<Point> = (0..500)
            .map(|_| [rng.gen_range(0.0..3.0), rng.gen_range(0.0..1.0)])
            .collect();
        let grid = PointCells::new(&pts, crate::spatial::bounding_box(&pts), 0.1);
        let g = grid.geometry();
        let (columns, rows) = (g.columns(), g.rows());
        assert!(columns > 20 && rows > 5, "{columns} × {rows}");
        for centre in [
            [0, 0],
            [columns / 2, rows / 3],
            [columns - 1, rows - 1],
            [3, 0],
        ] {
            let mut seen = vec![0u32; (columns * rows) as usize];
            let mut points = 0;
            for k in 0..columns.max(rows) {
                grid.for_each_cell_in_ring(centre, k, |[c, r]| {
                    let distance = c.abs_diff(centre[0]).max(r.abs_diff(centre[1]));
                    assert_eq!(distance, k);
                    seen[(r * columns + c) as usize] += 1;
                    let (coords, ids) = grid.cell([c, r]);
                    for (p, &i) in coords.iter().zip(ids) {
                        assert_eq!(g.cell_of(*p), [c, r]);
                        assert_eq!(*p, pts[i as usize]);
                    }
                    points += ids.len();
                });
            }
            assert!(seen.iter().all(|&v| v == 1), "{centre:?}");
            assert_eq!(points, pts.len());
        }
    }
}
