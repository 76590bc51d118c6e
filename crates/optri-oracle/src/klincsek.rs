//! Klincsek's dynamic program for optimal triangulations of a polygon
//! (Vassilev, *Optimal area triangulation*, 2005, Algorithm 21), extended to *weakly simple* polygons.
//!
//! The polygon is a counter-clockwise cycle of vertex indices in which a
//! vertex may repeat (zero-width cracks, as in the bounded faces of
//! hull ∪ RNG). Positions, not vertices, are the DP's states. A chord
//! between positions `i < j` is usable iff it is a boundary edge
//! (`j = i + 1`, or `i = 0, j = k − 1`) or a *valid diagonal*: its two
//! endpoints are different points, it leaves position `i` strictly inside that
//! corner's interior angle and likewise at `j`, and its relative interior
//! meets no boundary vertex and crosses no boundary edge. Then
//! `T[i][j] = min over i < m < j` of the combination of `T[i][m]`, `T[m][j]`,
//! triangle `(i, m, j)` and chord `(i, j)`. Chords inside the polygon split
//! it into two weakly simple polygons, so the recursion is the usual one.
//! O(k³) time after an O(k³) validity precomputation.

use crate::enumerate::{edge_length, TotalF64};
use crate::exact::{
    dot_sign, on_open_segment, orient, properly_cross, squared_length, twice_area, Point,
};
use num_rational::BigRational;
use std::cmp::Reverse;

/// A decomposable optimisation criterion: the cost of a triangulation is the
/// [`combine`](Criterion::combine) of the costs of its triangles and edges,
/// and `combine` is associative, commutative and monotone, so the optimum of
/// a polygon splits over a chord. The DP *minimises* `Value`.
pub trait Criterion {
    /// The totally ordered cost (smaller is better).
    type Value: Ord + Clone;
    /// The cost of one edge (boundary edge or diagonal), if edges count.
    fn edge(&self, points: &[Point], e: [u32; 2]) -> Option<Self::Value>;
    /// The cost of one triangle, if triangles count.
    fn triangle(&self, points: &[Point], t: [u32; 3]) -> Option<Self::Value>;
    /// Combines two partial costs.
    fn combine(&self, a: Self::Value, b: Self::Value) -> Self::Value;
}

/// Minimise the longest edge (bottleneck); value = its exact squared length.
#[derive(Clone, Copy, Debug, Default)]
pub struct MinMaxLength;
impl Criterion for MinMaxLength {
    type Value = BigRational;
    fn edge(&self, points: &[Point], e: [u32; 2]) -> Option<BigRational> {
        Some(squared_length(points[e[0] as usize], points[e[1] as usize]))
    }
    fn triangle(&self, _: &[Point], _: [u32; 3]) -> Option<BigRational> {
        None
    }
    fn combine(&self, a: BigRational, b: BigRational) -> BigRational {
        a.max(b)
    }
}

/// Minimise the total edge length; value = `f64` sum of rounded lengths
/// (see [`crate::total_length`] for the rounding caveat).
#[derive(Clone, Copy, Debug, Default)]
pub struct MinWeight;
impl Criterion for MinWeight {
    type Value = TotalF64;
    fn edge(&self, points: &[Point], e: [u32; 2]) -> Option<TotalF64> {
        Some(TotalF64(edge_length(
            points[e[0] as usize],
            points[e[1] as usize],
        )))
    }
    fn triangle(&self, _: &[Point], _: [u32; 3]) -> Option<TotalF64> {
        None
    }
    fn combine(&self, a: TotalF64, b: TotalF64) -> TotalF64 {
        TotalF64(a.0 + b.0)
    }
}

/// Maximise the smallest triangle; value = `Reverse(min twice-area)`.
#[derive(Clone, Copy, Debug, Default)]
pub struct MaxMinArea;
impl Criterion for MaxMinArea {
    type Value = Reverse<BigRational>;
    fn edge(&self, _: &[Point], _: [u32; 2]) -> Option<Self::Value> {
        None
    }
    fn triangle(&self, points: &[Point], t: [u32; 3]) -> Option<Self::Value> {
        let p = |i: u32| points[i as usize];
        Some(Reverse(twice_area(p(t[0]), p(t[1]), p(t[2]))))
    }
    fn combine(&self, a: Self::Value, b: Self::Value) -> Self::Value {
        a.max(b)
    }
}

/// Minimise the largest triangle; value = max twice-area.
#[derive(Clone, Copy, Debug, Default)]
pub struct MinMaxArea;
impl Criterion for MinMaxArea {
    type Value = BigRational;
    fn edge(&self, _: &[Point], _: [u32; 2]) -> Option<BigRational> {
        None
    }
    fn triangle(&self, points: &[Point], t: [u32; 3]) -> Option<BigRational> {
        let p = |i: u32| points[i as usize];
        Some(twice_area(p(t[0]), p(t[1]), p(t[2])))
    }
    fn combine(&self, a: BigRational, b: BigRational) -> BigRational {
        a.max(b)
    }
}

/// Which half-turn direction `u − v` falls in, measured counter-clockwise
/// from direction `b − v`: 0 for angles in [0, π), 1 for [π, 2π).
fn half(v: Point, b: Point, u: Point) -> u8 {
    let o = orient(v, b, u);
    if o > 0 || (o == 0 && dot_sign(v, b, u) > 0) {
        0
    } else {
        1
    }
}

/// Is the counter-clockwise angle from `b − v` to `u − v` smaller than to `w − v`?
fn angle_less(v: Point, b: Point, u: Point, w: Point) -> bool {
    let (hu, hw) = (half(v, b, u), half(v, b, w));
    if hu != hw {
        return hu < hw;
    }
    orient(v, u, w) > 0
}

/// Does direction `w − v` point strictly into the interior angle at corner
/// `prev → v → next` of a counter-clockwise polygon (interior on the left)?
/// The interior angle sweeps counter-clockwise from `next` to `prev`; when
/// they point the same way (a crack tip) it is the full turn.
pub fn strictly_inside_corner(prev: Point, v: Point, next: Point, w: Point) -> bool {
    let same_direction = |a: Point, b: Point| orient(v, a, b) == 0 && dot_sign(v, a, b) > 0;
    if same_direction(next, w) {
        return false;
    }
    if same_direction(next, prev) {
        return true;
    }
    angle_less(v, next, w, prev)
}

/// Is the chord between positions `i` and `j` of `polygon` a valid diagonal
/// (see the module docs)?
pub fn is_valid_diagonal(points: &[Point], polygon: &[u32], i: usize, j: usize) -> bool {
    let k = polygon.len();
    let p = |pos: usize| points[polygon[pos % k] as usize];
    let (u, w) = (p(i), p(j));
    if u == w {
        return false;
    }
    if !strictly_inside_corner(p(i + k - 1), u, p(i + 1), w)
        || !strictly_inside_corner(p(j + k - 1), w, p(j + 1), u)
    {
        return false;
    }
    (0..k).all(|t| !on_open_segment(u, w, p(t)) && !properly_cross(u, w, p(t), p(t + 1)))
}

/// Optimal triangulation of the weakly simple polygon `polygon` (a
/// counter-clockwise cycle of indices into `points`, vertices may repeat)
/// under `criterion`: the optimal value and one optimal set of triangles
/// (canonical, sorted; ties broken towards the smallest middle position).
/// `None` if the polygon has fewer than three positions or admits no
/// triangulation by valid diagonals (e.g. it is not a valid weakly simple
/// counter-clockwise polygon).
pub fn klincsek<C: Criterion>(
    points: &[Point],
    polygon: &[u32],
    criterion: C,
) -> Option<(C::Value, Vec<[u32; 3]>)> {
    let table = Table::solve(points, polygon, &criterion)?;
    Some((table.value()?, table.triangles()))
}

/// [`klincsek()`] plus a certificate of uniqueness: the third value is `true`
/// iff, in every sub-polygon the returned optimum is assembled from, every
/// other feasible apex gives a value `v` with `clearly_worse(&v, &best)`.
/// Then every other triangulation is clearly worse than the returned one (at
/// the first such sub-polygon where it differs, its apex is worse, and its
/// halves are at best optimal), so with a `clearly_worse` that allows for
/// rounding (e.g. `v > best · (1 + 10⁻¹²)` for [`MinWeight`]) the returned
/// triangles are *the* optimum although the values are rounded.
pub fn klincsek_unique<C: Criterion>(
    points: &[Point],
    polygon: &[u32],
    criterion: C,
    clearly_worse: impl Fn(&C::Value, &C::Value) -> bool,
) -> Option<(C::Value, Vec<[u32; 3]>, bool)> {
    let table = Table::solve(points, polygon, &criterion)?;
    let value = table.value()?;
    let k = table.k;
    let mut unique = true;
    let mut stack = vec![(0, k - 1)];
    while let Some((i, j)) = stack.pop() {
        if j == i + 1 {
            continue;
        }
        let best_m = table.split[i * k + j];
        let best = table.candidate(&criterion, i, best_m, j).flatten();
        for m in (i + 1..j).filter(|&m| m != best_m) {
            if let Some(v) = table.candidate(&criterion, i, m, j) {
                match (&v, &best) {
                    (Some(v), Some(b)) if clearly_worse(v, b) => {}
                    _ => unique = false,
                }
            }
        }
        stack.push((i, best_m));
        stack.push((best_m, j));
    }
    Some((value, table.triangles(), unique))
}

/// The tables of Klincsek's program.
struct Table<'a, C: Criterion> {
    points: &'a [Point],
    polygon: &'a [u32],
    k: usize,
    /// `cost[i*k + j]`: `Some(Some(v))` solved with value `v`, `Some(None)`
    /// solved with no cost term yet, `None` infeasible.
    cost: Vec<Option<Option<C::Value>>>,
    /// The apex of the optimum of `i..=j`.
    split: Vec<usize>,
    /// `edge[i*k + j]`: the criterion's cost of the chord `(i, j)`, `i < j`.
    edge: Vec<Option<C::Value>>,
}

impl<'a, C: Criterion> Table<'a, C> {
    fn solve(points: &'a [Point], polygon: &'a [u32], criterion: &C) -> Option<Self> {
        let k = polygon.len();
        if k < 3 {
            return None;
        }
        let usable = |i: usize, j: usize| -> bool {
            j == i + 1 || (i == 0 && j == k - 1) || is_valid_diagonal(points, polygon, i, j)
        };
        let mut ok = vec![false; k * k];
        for i in 0..k {
            for j in i + 1..k {
                ok[i * k + j] = usable(i, j);
            }
        }
        let mut edge = vec![None; k * k];
        for i in 0..k {
            for j in i + 1..k {
                if ok[i * k + j] {
                    edge[i * k + j] = criterion.edge(points, [polygon[i], polygon[j]]);
                }
            }
        }
        let mut t = Table {
            points,
            polygon,
            k,
            cost: vec![None; k * k],
            split: vec![usize::MAX; k * k],
            edge,
        };
        for i in 0..k - 1 {
            t.cost[i * k + i + 1] = Some(t.edge[i * k + i + 1].clone());
        }
        for len in 2..k {
            for i in 0..k - len {
                let j = i + len;
                if !ok[i * k + j] {
                    continue;
                }
                let mut best: Option<(Option<C::Value>, usize)> = None;
                for m in i + 1..j {
                    let Some(value) = t.candidate(criterion, i, m, j) else {
                        continue;
                    };
                    let better = match &best {
                        None => true,
                        Some((b, _)) => value < *b,
                    };
                    if better {
                        best = Some((value, m));
                    }
                }
                if let Some((value, m)) = best {
                    t.cost[i * k + j] = Some(value);
                    t.split[i * k + j] = m;
                }
            }
        }
        Some(t)
    }

    /// The value of sub-polygon `i..=j` (chord `(i, j)` included) with apex
    /// `m`, or `None` if a half is infeasible or the triangle is not
    /// counter-clockwise.
    fn candidate(&self, criterion: &C, i: usize, m: usize, j: usize) -> Option<Option<C::Value>> {
        let (k, points) = (self.k, self.points);
        let v = |pos: usize| self.polygon[pos];
        let join = |a: Option<C::Value>, b: Option<C::Value>| match (a, b) {
            (Some(a), Some(b)) => Some(criterion.combine(a, b)),
            (a, None) => a,
            (None, b) => b,
        };
        let (Some(left), Some(right)) = (&self.cost[i * k + m], &self.cost[m * k + j]) else {
            return None;
        };
        let (a, b, c) = (
            points[v(i) as usize],
            points[v(m) as usize],
            points[v(j) as usize],
        );
        if orient(a, b, c) <= 0 {
            return None;
        }
        let mut value = join(left.clone(), right.clone());
        value = join(value, criterion.triangle(points, [v(i), v(m), v(j)]));
        value = join(value, self.edge[i * k + j].clone());
        Some(value)
    }

    fn value(&self) -> Option<C::Value> {
        self.cost[self.k - 1].clone()?
    }

    fn triangles(&self) -> Vec<[u32; 3]> {
        let k = self.k;
        let v = |pos: usize| self.polygon[pos];
        let mut tris = Vec::with_capacity(k - 2);
        let mut stack = vec![(0, k - 1)];
        while let Some((i, j)) = stack.pop() {
            if j == i + 1 {
                continue;
            }
            let m = self.split[i * k + j];
            tris.push(crate::enumerate::canonical_triangle(
                self.points,
                [v(i), v(m), v(j)],
            ));
            stack.push((i, m));
            stack.push((m, j));
        }
        tris.sort_unstable();
        tris
    }
}
