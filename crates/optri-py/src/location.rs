//! Exact point location for `Triangulation.find_simplex`: which triangle
//! contains a query point, decided by the kernel's exact orientation
//! (Shewchuk, 1997, *Adaptive precision floating-point arithmetic and fast
//! robust geometric predicates*, Discrete Comput. Geom. 18, §4). A query
//! walks from a triangle at a vertex near it (a uniform grid of the
//! vertices) by the remembering stochastic walk of Devillers, Pion &
//! Teillaud (2002, *Walking in a triangulation*, Int. J. Found. Comput.
//! Sci. 13(2), §2), which ends on every triangulation, Delaunay or not. A
//! walk that leaves a polygon through its boundary, or runs too long, falls
//! back to a uniform grid of bucketed triangle bounding boxes (Akman,
//! Franklin, Kankanhalli & Narayanaswami, 1989, *Geometric computing and
//! uniform grid technique*, Computer-Aided Design 21(7)).
//!
//! Containment is closed: a query on a side or a corner is in every triangle
//! that has it, and the answer is the smallest such index. The grid only
//! narrows the candidates, so its floating-point arithmetic needs no error
//! bound: a cell index is a monotone function of a coordinate (a rounded
//! subtraction, a rounded product, `floor`, a clamp), so a query inside a
//! triangle's bounding box falls in a cell the box was entered in.
//!
//! The triangles are in the working coordinates of the run: for decimal
//! input scaled to integers by `10^k` (`optri::io::ReadInput::scaled`), the
//! query `q` (the caller's doubles) is the exact point `q·10^k` there,
//! located without rounding by [`optri::kernel::orient_sign_scaled`].

use optri::kernel::{check_coordinate, orient_sign_scaled, CoordinateProblem, Point};

/// How the caller's coordinates map to the working ones: the exact
/// orientation of working vertices `a, b` and query `q` is that of
/// `a·vertex_scale, b·vertex_scale, q·query_scale` (one of them is 1).
#[derive(Clone, Copy, Debug)]
struct Scale {
    vertex: f64,
    query: f64,
}

impl Scale {
    /// Working coordinates that are the caller's.
    const UNIT: Scale = Scale {
        vertex: 1.0,
        query: 1.0,
    };

    /// The scale of decimal input multiplied by `10^exponent`, or `None`
    /// when `10^|exponent|` is not a double (|exponent| > 22).
    fn of_exponent(exponent: i32) -> Option<Self> {
        if exponent.unsigned_abs() > 22 {
            return None;
        }
        let power: f64 = format!("1e{}", exponent.unsigned_abs()).parse().ok()?;
        Some(if exponent >= 0 {
            Scale {
                vertex: 1.0,
                query: power,
            }
        } else {
            Scale {
                vertex: power,
                query: 1.0,
            }
        })
    }

    /// The query in working coordinates, rounded (monotone in each
    /// coordinate, which is all the grid needs).
    fn approximate(self, q: Point) -> Point {
        [
            q[0] * self.query / self.vertex,
            q[1] * self.query / self.vertex,
        ]
    }

    /// `q` read as the input was: when both coordinates' shortest decimals
    /// lie on the working grid, the working integers of those decimals.
    /// A coordinate's decimal is `W·10^-k` for the integer `W` nearest its
    /// scaled value when that decimal rounds back to it (one correctly
    /// rounded operation) and `|W| < 10¹⁵`: a decimal of at most 15
    /// significant digits is the only one that short rounding to its
    /// double, so it is the shortest.
    fn decimal(self, q: Point) -> Option<Point> {
        if self.vertex == 1.0 && self.query == 1.0 {
            return None;
        }
        let grid = |v: f64| {
            let w = self.approximate([v, 0.0])[0].round();
            let back = w * self.vertex / self.query;
            (w.abs() < 1e15 && back == v).then_some(w)
        };
        Some([grid(q[0])?, grid(q[1])?])
    }
}

/// A query coordinate that cannot be located exactly.
#[derive(Debug)]
pub(crate) enum QueryProblem {
    /// NaN or infinite.
    NonFinite,
    /// Non-zero and closer to zero than the kernel's exact range.
    TooSmall,
}

/// The triangles, their adjacency, a grid of the vertices to start walks
/// from and the grid over the triangles' bounding boxes.
pub(crate) struct Locator {
    points: Vec<Point>,
    triangles: Vec<[u32; 3]>,
    /// `neighbors[i][j]`: the triangle across the side opposite corner `j`.
    neighbors: Vec<[i64; 3]>,
    /// Whether the domain is convex (the hull of the points): a walk that
    /// leaves it through a side then proves the query outside.
    convex: bool,
    /// Per point, the smallest index of a triangle with it as a corner.
    corner_triangle: Vec<i64>,
    /// The walks' starts: about one cell per point, each with the smallest
    /// point index in it (`u32::MAX` for none).
    vertex_cells: [usize; 2],
    vertex_density: [f64; 2],
    cell_vertex: Vec<u32>,
    scale: Scale,
    /// The bounding box of every triangle corner: `[min, max]` per axis.
    low: Point,
    high: Point,
    cells: [usize; 2],
    /// Cells per unit length, per axis.
    density: [f64; 2],
    /// The triangles entered in cell `c` are `entries[starts[c]..starts[c + 1]]`,
    /// by increasing index.
    starts: Vec<usize>,
    entries: Vec<u32>,
}

/// The grid is coarsened until it holds at most this many entries per
/// triangle (plus a constant): thin triangles with long bounding boxes (a
/// fan over a collinear run) would otherwise be entered in a whole row of
/// cells each.
const ENTRIES_PER_TRIANGLE: usize = 8;

impl Locator {
    /// The locator of `triangles` (counter-clockwise, indices into
    /// `points`, the working coordinates, with their `neighbors`; `convex`
    /// when they cover the points' hull), for queries in coordinates that
    /// are the working ones divided by `10^exponent`. `None` when
    /// `|exponent| > 22`.
    pub(crate) fn new(
        points: &[Point],
        triangles: &[[u32; 3]],
        neighbors: &[[i64; 3]],
        convex: bool,
        exponent: i32,
    ) -> Option<Self> {
        let scale = Scale::of_exponent(exponent)?;
        let mut low = [f64::INFINITY; 2];
        let mut high = [f64::NEG_INFINITY; 2];
        for &v in triangles.iter().flatten() {
            for axis in 0..2 {
                low[axis] = low[axis].min(points[v as usize][axis]);
                high[axis] = high[axis].max(points[v as usize][axis]);
            }
        }
        let mut locator = Locator {
            points: points.to_vec(),
            triangles: triangles.to_vec(),
            neighbors: neighbors.to_vec(),
            convex,
            corner_triangle: crate::adjacency::vertex_to_simplex(triangles, points.len(), &[]),
            vertex_cells: [1, 1],
            vertex_density: [0.0; 2],
            cell_vertex: Vec::new(),
            scale,
            low,
            high,
            cells: [1, 1],
            density: [0.0; 2],
            starts: Vec::new(),
            entries: Vec::new(),
        };
        locator.bucket();
        locator.grid_vertices();
        Some(locator)
    }

    /// About one cell per corner point, square in shape, each holding its
    /// smallest point index.
    fn grid_vertices(&mut self) {
        let n = self.points.len().max(1);
        let [columns, rows] = square_cells(n, self.low, self.high);
        self.vertex_cells = [columns, rows];
        self.vertex_density = [
            columns as f64 / (self.high[0] - self.low[0]).max(f64::MIN_POSITIVE),
            rows as f64 / (self.high[1] - self.low[1]).max(f64::MIN_POSITIVE),
        ];
        self.cell_vertex = vec![u32::MAX; columns * rows];
        for (v, p) in self.points.iter().enumerate().rev() {
            if self.corner_triangle[v] >= 0 {
                let [column, row] = self.vertex_cell(*p);
                self.cell_vertex[row * self.vertex_cells[0] + column] = v as u32;
            }
        }
    }

    /// The vertex grid's cell of a point in working coordinates, as
    /// `[column, row]`.
    fn vertex_cell(&self, p: Point) -> [usize; 2] {
        [0, 1].map(|axis| {
            let c = ((p[axis] - self.low[axis]) * self.vertex_density[axis]).floor();
            (c as usize).min(self.vertex_cells[axis] - 1)
        })
    }

    /// A vertex in the vertex grid's cell of `p` or, when that is empty, in
    /// the nearest non-empty ring of cells around it, up to
    /// [`START_SEARCH_RINGS`] rings out.
    fn vertex_near(&self, p: Point) -> Option<u32> {
        let [column, row] = self.vertex_cell(p);
        let [columns, rows] = self.vertex_cells;
        for r in 0..=START_SEARCH_RINGS {
            let (c0, c1) = (column.saturating_sub(r), (column + r).min(columns - 1));
            let (r0, r1) = (row.saturating_sub(r), (row + r).min(rows - 1));
            for y in r0..=r1 {
                for x in c0..=c1 {
                    let on_ring = x.abs_diff(column) == r || y.abs_diff(row) == r;
                    let v = self.cell_vertex[y * columns + x];
                    if on_ring && v != u32::MAX {
                        return Some(v);
                    }
                }
            }
        }
        None
    }

    /// Chooses about one cell per triangle, square in shape, and enters each
    /// triangle in the cells of its bounding box, coarsening the grid while
    /// that makes too many entries.
    fn bucket(&mut self) {
        let m = self.triangles.len().max(1);
        let width = (self.high[0] - self.low[0]).max(f64::MIN_POSITIVE);
        let height = (self.high[1] - self.low[1]).max(f64::MIN_POSITIVE);
        self.cells = square_cells(m, self.low, self.high);
        loop {
            self.density = [self.cells[0] as f64 / width, self.cells[1] as f64 / height];
            let total: usize = (0..self.triangles.len())
                .map(|i| {
                    let [c0, c1, r0, r1] = self.cell_range(i);
                    (c1 - c0 + 1) * (r1 - r0 + 1)
                })
                .sum();
            if total <= ENTRIES_PER_TRIANGLE * m + 64 || self.cells == [1, 1] {
                break;
            }
            self.cells = [self.cells[0].div_ceil(2), self.cells[1].div_ceil(2)];
        }
        let [columns, rows] = self.cells;
        let mut counts = vec![0usize; columns * rows + 1];
        for i in 0..self.triangles.len() {
            let [c0, c1, r0, r1] = self.cell_range(i);
            for r in r0..=r1 {
                for c in c0..=c1 {
                    counts[r * columns + c + 1] += 1;
                }
            }
        }
        for c in 1..counts.len() {
            counts[c] += counts[c - 1];
        }
        let mut fill = counts.clone();
        let mut entries = vec![0u32; counts[columns * rows]];
        for i in 0..self.triangles.len() {
            let [c0, c1, r0, r1] = self.cell_range(i);
            for r in r0..=r1 {
                for c in c0..=c1 {
                    entries[fill[r * columns + c]] = i as u32;
                    fill[r * columns + c] += 1;
                }
            }
        }
        self.starts = counts;
        self.entries = entries;
    }

    /// The cell index along `axis` of coordinate `v`: monotone in `v`.
    fn cell(&self, axis: usize, v: f64) -> usize {
        let c = ((v - self.low[axis]) * self.density[axis]).floor();
        // A negative or NaN `c` saturates to 0 in the cast.
        (c as usize).min(self.cells[axis] - 1)
    }

    /// Triangle `i`'s bounding box as cells: `[column0, column1, row0, row1]`.
    fn cell_range(&self, i: usize) -> [usize; 4] {
        let corners = self.triangles[i].map(|v| self.points[v as usize]);
        let (low, high) = bounding_box(&corners);
        [
            self.cell(0, low[0]),
            self.cell(0, high[0]),
            self.cell(1, low[1]),
            self.cell(1, high[1]),
        ]
    }

    /// The smallest index of a triangle that contains `q` (the caller's
    /// coordinates), sides and corners included; `-1` when none does.
    pub(crate) fn locate(&self, q: Point) -> Result<i64, QueryProblem> {
        for v in q {
            match check_coordinate(v) {
                Ok(_) => {}
                Err(CoordinateProblem::NonFinite) => return Err(QueryProblem::NonFinite),
                // Beyond every corner (all are in the range), so outside.
                Err(CoordinateProblem::OutOfRange) if v.abs() > 1.0 => return Ok(-1),
                Err(CoordinateProblem::OutOfRange) => return Err(QueryProblem::TooSmall),
            }
        }
        // A query on the input's decimal grid is located at its decimal,
        // exactly; any other at its binary value.
        let (q, scale) = match self.scale.decimal(q) {
            Some(w) => (w, Scale::UNIT),
            None => (q, self.scale),
        };
        // A rounded coordinate outside `[low, high]` (doubles) means the
        // exact one is outside too: rounding is monotone.
        let w = scale.approximate(q);
        if (0..2).any(|axis| w[axis] < self.low[axis] || w[axis] > self.high[axis]) {
            return Ok(-1);
        }
        let cell = self.cell(1, w[1]) * self.cells[0] + self.cell(0, w[0]);
        let candidates = &self.entries[self.starts[cell]..self.starts[cell + 1]];
        // No triangle's box reaches the query's cell: outside them all.
        let Some(&first) = candidates.first() else {
            return Ok(-1);
        };
        let start = match self.vertex_near(w) {
            Some(v) => self.corner_triangle[v as usize] as usize,
            None => first as usize,
        };
        Ok(match self.walk(start, q, scale) {
            Walk::Inside(t) => self.smallest_holding(t, q, scale),
            Walk::Outside if self.convex => -1,
            Walk::Outside | Walk::TooLong => self.scan(candidates, q, w, scale),
        })
    }

    /// The exact orientation of the side opposite corner `j` of triangle
    /// `t` and the query.
    fn side_sign(&self, t: usize, j: usize, q: Point, scale: Scale) -> i32 {
        let [a, b] = [(j + 1) % 3, (j + 2) % 3].map(|k| self.points[self.triangles[t][k] as usize]);
        orient_sign_scaled(a, b, q, scale.vertex, scale.query)
    }

    /// The remembering stochastic walk from triangle `t` towards `q`: cross
    /// a side that has `q` strictly on its far side, never back through the
    /// side just crossed (`q` is strictly inside it), trying the sides from
    /// a pseudo-random one. Ends in a triangle with `q` on no side's far
    /// side (it contains `q`), or at a boundary side with `q` beyond.
    fn walk(&self, mut t: usize, q: Point, scale: Scale) -> Walk {
        let mut state = (q[0].to_bits() ^ q[1].to_bits().rotate_left(29)) | 1;
        let mut came_from = -1i64;
        for _ in 0..(3 * self.triangles.len() + 64) {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let first = (state % 3) as usize;
            let exit = (0..3).map(|k| (first + k) % 3).find(|&j| {
                let across = self.neighbors[t][j];
                (came_from < 0 || across != came_from) && self.side_sign(t, j, q, scale) < 0
            });
            match exit {
                None => return Walk::Inside(t),
                Some(j) if self.neighbors[t][j] < 0 => return Walk::Outside,
                Some(j) => {
                    came_from = t as i64;
                    t = self.neighbors[t][j] as usize;
                }
            }
        }
        Walk::TooLong
    }

    /// The smallest index of a triangle containing `q`, given triangle `t`
    /// that does: `t` when `q` is inside it, the smaller of the two
    /// triangles of the side `q` is on, or the smallest triangle at the
    /// corner `q` is (no corner lies inside another triangle's side).
    fn smallest_holding(&self, t: usize, q: Point, scale: Scale) -> i64 {
        let signs = [0, 1, 2].map(|j| self.side_sign(t, j, q, scale));
        let on: Vec<usize> = (0..3).filter(|&j| signs[j] == 0).collect();
        match on.as_slice() {
            [] => t as i64,
            [j] => match self.neighbors[t][*j] {
                across if across >= 0 => across.min(t as i64),
                _ => t as i64,
            },
            _ => {
                // On two sides: the corner they share, opposite the third.
                let corner = (0..3).find(|&j| signs[j] != 0).unwrap_or(0);
                self.corner_triangle[self.triangles[t][corner] as usize]
            }
        }
    }

    /// The smallest index of a triangle among `candidates` (the query's
    /// cell) that contains `q`, `-1` for none.
    fn scan(&self, candidates: &[u32], q: Point, w: Point, scale: Scale) -> i64 {
        for &i in candidates {
            let corners = self.triangles[i as usize].map(|v| self.points[v as usize]);
            let (low, high) = bounding_box(&corners);
            if (0..2).any(|axis| w[axis] < low[axis] || w[axis] > high[axis]) {
                continue;
            }
            if (0..3).all(|j| self.side_sign(i as usize, j, q, scale) >= 0) {
                return i64::from(i);
            }
        }
        -1
    }
}

/// How far around an empty vertex cell a walk's start is looked for: a
/// start is only a heuristic, so a short search is enough.
const START_SEARCH_RINGS: usize = 4;

/// How a walk ended.
enum Walk {
    /// In this triangle, which contains the query.
    Inside(usize),
    /// Through a boundary side with the query strictly beyond it.
    Outside,
    /// After more steps than a walk that ends needs in all likelihood.
    TooLong,
}

/// About `count` cells over the box from `low` to `high`, square in shape:
/// `[columns, rows]`.
fn square_cells(count: usize, low: Point, high: Point) -> [usize; 2] {
    let width = (high[0] - low[0]).max(f64::MIN_POSITIVE);
    let height = (high[1] - low[1]).max(f64::MIN_POSITIVE);
    let columns = ((count as f64 * width / height).sqrt().ceil() as usize).clamp(1, count);
    [columns, count.div_ceil(columns).max(1)]
}

/// The `[min x, min y]` and `[max x, max y]` of `corners`.
fn bounding_box(corners: &[Point; 3]) -> (Point, Point) {
    let mut low = corners[0];
    let mut high = corners[0];
    for p in &corners[1..] {
        for axis in 0..2 {
            low[axis] = low[axis].min(p[axis]);
            high[axis] = high[axis].max(p[axis]);
        }
    }
    (low, high)
}
