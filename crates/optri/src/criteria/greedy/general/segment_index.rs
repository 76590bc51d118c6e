//! The two per-candidate tests of pass 1 (module docs, "Deciding a round
//! without following the length order"), each over a [`SparseGrid`]:
//! [`SegmentIndex`] lists the indexed segments a candidate may cross — the
//! round's shorter candidates (its dependencies) and the active earlier
//! edges (the Claim of "Earlier edges: only the *active* ones"), in one
//! index — and
//! [`PointsNear`] answers whether a point lies on it (from round 1 on;
//! round 0 finds such points in the segment scan). The grids only choose
//! which exact tests run; the tests are the kernel's.

use crate::kernel::{on_open_segment, properly_cross, Point};
use crate::parallel::prelude::*;
use crate::spatial::{fmax, fmin, SparseGrid};

/// Padding factor on a rounded half-length, `1 + 10⁻⁹`, so that cells are
/// chosen for at least the exact half-length. A chosen margin: the rounded
/// half-length is within a few units of 2⁻⁵³ of the exact one.
const HALF_LENGTH_PAD: f64 = 1.0 + 1e-9;

/// Segments bucketed by the cell of their midpoint: a segment that meets a
/// point `x` has its midpoint within `reach` (its longest half-length) of
/// `x`. Each bucket stores its segments' ids and coordinates contiguously, by
/// ascending id, so that a query reads memory in spatial order.
pub(super) struct SegmentIndex {
    grid: SparseGrid<Indexed>,
    reach: f64,
}

/// A segment in a [`SegmentIndex`]: its id and its endpoints' coordinates.
#[derive(Clone, Copy)]
pub(super) struct Indexed {
    pub(super) id: u32,
    /// The endpoint with the smaller x.
    a: Point,
    b: Point,
}

impl Indexed {
    fn new(id: u32, p: Point, q: Point) -> Self {
        let (a, b) = if p[0] <= q[0] { (p, q) } else { (q, p) };
        Self { id, a, b }
    }

    /// Do the closed bounding boxes of this segment and the query meet? One
    /// branch for the whole test (`&`, not `&&`): its outcome is
    /// unpredictable, so fewer branches mispredict less; no `min` in x
    /// because `a` is the left endpoint.
    #[inline]
    fn box_meets(&self, q: &Query) -> bool {
        (self.a[0] <= q.hi[0])
            & (self.b[0] >= q.lo[0])
            & (fmin(self.a[1], self.b[1]) <= q.hi[1])
            & (fmax(self.a[1], self.b[1]) >= q.lo[1])
    }

    /// Does this segment properly cross the query? (Exact; the box test
    /// first.)
    #[inline]
    pub(super) fn crosses(&self, q: &Query) -> bool {
        self.box_meets(q) && properly_cross(q.a, q.b, self.a, self.b)
    }

    /// How this segment meets the query: `Some(true)` if it properly
    /// crosses it, `Some(false)` if it shares an endpoint with it and its
    /// other endpoint lies on the query's open segment, `None` otherwise.
    /// (Exact; endpoints are compared by coordinates, which identify the
    /// distinct points.)
    #[inline]
    pub(super) fn crosses_or_rests_on(&self, q: &Query) -> Option<bool> {
        if !self.box_meets(q) {
            return None;
        }
        if properly_cross(q.a, q.b, self.a, self.b) {
            return Some(true);
        }
        let other = if self.a == q.a || self.a == q.b {
            self.b
        } else if self.b == q.a || self.b == q.b {
            self.a
        } else {
            return None;
        };
        (other != q.a && other != q.b && on_open_segment(other, q.a, q.b)).then_some(false)
    }
}

/// A query segment with its bounding box.
pub(super) struct Query {
    pub(super) a: Point,
    pub(super) b: Point,
    lo: Point,
    hi: Point,
}

impl Query {
    pub(super) fn new(a: Point, b: Point) -> Self {
        Self {
            a,
            b,
            lo: [fmin(a[0], b[0]), fmin(a[1], b[1])],
            hi: [fmax(a[0], b[0]), fmax(a[1], b[1])],
        }
    }
}

impl SegmentIndex {
    /// Indexes `segments`, tagging each with its entry of `ids`.
    pub(super) fn new(
        points: &[Point],
        bbox: [f64; 4],
        segments: &[[u32; 2]],
        ids: &[u32],
    ) -> Self {
        let p = |v: u32| points[v as usize];
        let reach = segments
            .par_iter()
            .map(|&[a, b]| half_length(p(a), p(b)))
            .reduce(|| 0.0, fmax)
            * HALF_LENGTH_PAD;
        let midpoint = |i: usize| {
            let [a, b] = segments[i];
            let (pa, pb) = (p(a), p(b));
            [0.5 * pa[0] + 0.5 * pb[0], 0.5 * pa[1] + 0.5 * pb[1]]
        };
        let item = |i: usize| {
            let [a, b] = segments[i];
            Indexed::new(ids[i], p(a), p(b))
        };
        Self {
            grid: SparseGrid::new(bbox, reach, segments.len(), midpoint, item, |i| ids[i]),
            reach,
        }
    }

    /// Calls `f` on every segment *no longer than `ab`* that may meet `ab`
    /// (and others), cell by cell, in ascending id within a cell, until `f`
    /// says [`Step::Stop`]. (Their midpoints lie within `|ab| / 2` of `ab`.)
    #[inline]
    pub(super) fn scan_near(&self, a: Point, b: Point, mut f: impl FnMut(&Indexed) -> Step) {
        let pad = fmin(self.reach, half_length(a, b) * HALF_LENGTH_PAD);
        self.grid.any_cell_near(a, b, pad, |cell| {
            for s in cell {
                match f(s) {
                    Step::Next => {}
                    Step::NextCell => return false,
                    Step::Stop => return true,
                }
            }
            false
        });
    }
}

/// What a [`SegmentIndex::scan_near`] does after a segment.
pub(super) enum Step {
    /// Go on with the next segment of the cell.
    Next,
    /// Skip the rest of the cell.
    NextCell,
    /// End the scan.
    Stop,
}

/// Half the length of `ab`, rounded (only ever used, padded, to choose cells).
#[inline]
fn half_length(a: Point, b: Point) -> f64 {
    0.5 * ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt()
}

/// Do the closed bounding boxes of `ab` and `cd` meet? (Exact: comparisons only.)
#[inline]
fn boxes_meet(a: Point, b: Point, c: Point, d: Point) -> bool {
    fmax(a[0], b[0]) >= fmin(c[0], d[0])
        && fmax(c[0], d[0]) >= fmin(a[0], b[0])
        && fmax(a[1], b[1]) >= fmin(c[1], d[1])
        && fmax(c[1], d[1]) >= fmin(a[1], b[1])
}

/// The points, bucketed by a grid of about one point per cell.
pub(super) struct PointsNear<'a> {
    points: &'a [Point],
    grid: SparseGrid<u32>,
}

impl<'a> PointsNear<'a> {
    pub(super) fn new(points: &'a [Point], bbox: [f64; 4], cell: f64) -> Self {
        Self {
            points,
            grid: SparseGrid::new(
                bbox,
                cell,
                points.len(),
                |i| points[i],
                |i| i as u32,
                |i| i as u32,
            ),
        }
    }

    /// The inverse of the grid's cell size.
    pub(super) fn inverse_cell(&self) -> f64 {
        self.grid.inverse_cell()
    }

    /// Does some point lie on the open segment `ab`? (Exact.)
    pub(super) fn on_segment(&self, a: Point, b: Point) -> bool {
        self.grid.any_cell_near(a, b, 0.0, |cell| {
            cell.iter().any(|&z| {
                let pz = self.points[z as usize];
                boxes_meet(a, b, pz, pz) && pz != a && pz != b && on_open_segment(pz, a, b)
            })
        })
    }
}
