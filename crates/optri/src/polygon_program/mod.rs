//! Layer 4: Klincsek's dynamic program over a polygon (G. T. Klincsek,
//! *Minimal triangulations of polygonal domains*, Annals of Discrete
//! Mathematics 9, 1980; Algorithm 21 of T. S. Vassilev, *Optimal area
//! triangulation*, PhD thesis, 2005), generic in the [`Objective`].
//!
//! The polygon is a cycle of `k` *corners* `0..k` in counter-clockwise
//! order; the caller says which chords are allowed diagonals and which
//! triangles are allowed (e.g. not flat), so the same program serves convex
//! polygons, simple polygons and the weakly simple regions of minmax length
//! (a vertex repeated at several corners). The sub-problem `(i, j)`, `i < j`,
//! is the sub-polygon of corners `i..=j` closed by the chord `ij`; its value
//! combines the costs of the diagonals and triangles inside it, not of `ij`
//! itself (the table stores it with `ij`'s cost added, so that the O(k³)
//! split loop never evaluates a chord). A triangulation of `(i, j)` consists of a triangle `(i, m, j)` and
//! triangulations of `(i, m)` and `(m, j)`: allowed chords do not cross, so
//! the recursion is exact for every objective whose [`combine`] is associative
//! and monotone — sums (additive objectives: total length) and maxima or
//! minima (bottleneck objectives: longest edge, smallest or largest area).
//! O(k³) time after `k²/2` chord tests, O(k²) memory (two tables of k² cells).
//!
//! Ties: for each sub-problem the first split corner `m` (in increasing order)
//! whose value is strictly [`better`] than all earlier ones wins, so the
//! result is deterministic.
//!
//! [`combine`]: Objective::combine
//! [`better`]: Objective::better

mod simple_polygon;

pub use simple_polygon::MAX_POLYGON_VERTICES;
pub(crate) use simple_polygon::{check_size, corner_point, diagonal_table, on_simple_polygon};

/// A decomposable objective: the cost of a triangulation is the
/// [`combine`](Self::combine) of the costs of its diagonals and triangles.
pub(crate) trait Objective {
    /// The cost of a partial triangulation.
    type Value: Copy;
    /// The cost of a sub-polygon with nothing inside (an edge); the identity
    /// of [`combine`](Self::combine).
    fn empty(&self) -> Self::Value;
    /// The cost of the chord between corners `i < j` used as a diagonal
    /// (boundary edges are never charged), or `None` if chords cost nothing.
    fn diagonal(&self, i: usize, j: usize) -> Option<Self::Value>;
    /// The cost of the triangle of corners `i < m < j`, or `None` if
    /// triangles cost nothing.
    fn triangle(&self, i: usize, m: usize, j: usize) -> Option<Self::Value>;
    /// Combines two costs; associative, commutative and monotone.
    fn combine(&self, a: Self::Value, b: Self::Value) -> Self::Value;
    /// Is `a` strictly better than `b`?
    fn better(&self, a: Self::Value, b: Self::Value) -> bool;
    /// Objectives whose values are certified enclosures (sums of lengths)
    /// say here when `a` and `b` do not decide [`better`](Self::better);
    /// the program then asks [`better_diagonals`](Self::better_diagonals).
    fn undecided(&self, _a: Self::Value, _b: Self::Value) -> bool {
        false
    }
    /// The exact decision for an [`undecided`](Self::undecided) pair: is the
    /// candidate whose diagonals (common ones removed) are `a` strictly
    /// better than the one whose diagonals are `b`? Only for objectives
    /// that charge diagonals alone.
    fn better_diagonals(&self, _a: &[[usize; 2]], _b: &[[usize; 2]]) -> bool {
        false
    }
}

/// A bottleneck objective over diagonals: the largest diagonal under a
/// caller's total order `compare(chord, chord)` on corner pairs (exact
/// length comparisons for minmax length, under any metric). Values are chord
/// numbers `i * k + j`, or [`LargestDiagonal::NONE`] while there is none.
pub(crate) struct LargestDiagonal<F: Fn([usize; 2], [usize; 2]) -> std::cmp::Ordering> {
    k: usize,
    compare: F,
}

impl<F: Fn([usize; 2], [usize; 2]) -> std::cmp::Ordering> LargestDiagonal<F> {
    /// No diagonal yet (a sub-polygon with nothing inside).
    pub(crate) const NONE: u32 = u32::MAX;

    /// The objective on a polygon of `k` corners ordered by `compare`.
    pub(crate) fn new(k: usize, compare: F) -> Self {
        Self { k, compare }
    }

    fn order(&self, c: u32, d: u32) -> std::cmp::Ordering {
        if c == d {
            return std::cmp::Ordering::Equal;
        }
        let chord = |c: u32| [c as usize / self.k, c as usize % self.k];
        (self.compare)(chord(c), chord(d))
    }
}

impl<F: Fn([usize; 2], [usize; 2]) -> std::cmp::Ordering> Objective for LargestDiagonal<F> {
    type Value = u32;
    fn empty(&self) -> u32 {
        Self::NONE
    }
    fn diagonal(&self, i: usize, j: usize) -> Option<u32> {
        Some((i * self.k + j) as u32)
    }
    fn triangle(&self, _: usize, _: usize, _: usize) -> Option<u32> {
        None
    }
    fn combine(&self, s: u32, t: u32) -> u32 {
        if s == Self::NONE {
            return t;
        }
        if t == Self::NONE || self.order(s, t) != std::cmp::Ordering::Less {
            s
        } else {
            t
        }
    }
    fn better(&self, s: u32, t: u32) -> bool {
        if t == Self::NONE {
            return false;
        }
        s == Self::NONE || self.order(s, t) == std::cmp::Ordering::Less
    }
}

/// An optimal triangulation: triangles as corner triples `[i, m, j]` with
/// `i < m < j`, and its cost.
pub(crate) struct Triangulated<V> {
    pub triangles: Vec<[usize; 3]>,
    #[allow(dead_code)] // min-weight and minmax length need only the triangles
    pub value: V,
}

/// The diagonals inside sub-polygon `(i, j)` when its triangle on `ij` is
/// `(i, m, j)` and the sub-problems `(i, m)`, `(m, j)` are solved in `cells`.
fn diagonals_of<V>(
    cells: &[(V, u32)],
    k: usize,
    i: usize,
    m: usize,
    j: usize,
    out: &mut Vec<[usize; 2]>,
) {
    let mut stack = vec![(i, m, j)];
    while let Some((i, m, j)) = stack.pop() {
        for (a, b) in [(i, m), (m, j)] {
            if b > a + 1 {
                out.push([a, b]);
                stack.push((a, cells[a * k + b].1 as usize, b));
            }
        }
    }
}

/// Removes the chords `a` and `b` have in common (as multisets).
fn cancel_common(a: &mut Vec<[usize; 2]>, b: &mut Vec<[usize; 2]>) {
    a.sort_unstable();
    b.sort_unstable();
    let (mut x, mut y) = (Vec::new(), Vec::new());
    let (mut i, mut j) = (0, 0);
    while i < a.len() || j < b.len() {
        if j == b.len() || (i < a.len() && a[i] < b[j]) {
            x.push(a[i]);
            i += 1;
        } else if i == a.len() || b[j] < a[i] {
            y.push(b[j]);
            j += 1;
        } else {
            i += 1;
            j += 1;
        }
    }
    *a = x;
    *b = y;
}

/// The optimal triangulation of the polygon with corners `0..k` under
/// `objective`, using only chords for which `is_diagonal(i, j)` holds
/// (`i < j`, not a boundary edge) and triangles for which
/// `is_triangle(i, m, j)` holds. `None` if no triangulation uses only those.
pub(crate) fn optimal_triangulation<O: Objective>(
    k: usize,
    is_diagonal: impl Fn(usize, usize) -> bool,
    is_triangle: impl Fn(usize, usize, usize) -> bool,
    objective: &O,
) -> Option<Triangulated<O::Value>> {
    let never = crate::interrupt::Stop::default();
    optimal_triangulation_until(k, is_diagonal, is_triangle, objective, &never)
        .expect("a default stop never stops")
}

/// Sub-problems between two reads of the stop (each costs up to `k` splits).
const STOP_CADENCE: usize = 64;

/// [`optimal_triangulation`] that reads `stop` every [`STOP_CADENCE`]
/// sub-problems.
///
/// # Errors
/// [`crate::Error::Interrupted`] when `stop` says so.
pub(crate) fn optimal_triangulation_until<O: Objective>(
    k: usize,
    is_diagonal: impl Fn(usize, usize) -> bool,
    is_triangle: impl Fn(usize, usize, usize) -> bool,
    objective: &O,
    stop: &crate::interrupt::Stop,
) -> crate::error::Result<Option<Triangulated<O::Value>>> {
    if k < 3 {
        return Ok(None);
    }
    // A cell per chord (i, j), i < j: the best value of sub-problem (i, j)
    // and its split corner. The inner loop walks row i (cells (i, m)) and
    // column j (cells (m, j)); the column is kept a second time, transposed,
    // so both walks are sequential in memory (a strided column walk misses
    // the cache on every step once k² cells exceed it).
    const INFEASIBLE: u32 = u32::MAX; // not usable, or no allowed triangulation
    const EDGE: u32 = u32::MAX - 1; // a boundary edge: nothing inside
    let at = |i: usize, j: usize| i * k + j;
    let mut cells = vec![(objective.empty(), INFEASIBLE); k * k];
    let mut by_end = vec![(objective.empty(), INFEASIBLE); k * k]; // by_end[j*k + i] = cells[i*k + j]
    for i in 0..k - 1 {
        cells[at(i, i + 1)].1 = EDGE;
        by_end[at(i + 1, i)].1 = EDGE;
    }
    let with = |v: O::Value, extra: Option<O::Value>| match extra {
        Some(e) => objective.combine(v, e),
        None => v,
    };
    for gap in 2..k {
        for i in 0..k - gap {
            if i % STOP_CADENCE == 0 {
                stop.check()?;
            }
            let j = i + gap;
            let closes_polygon = i == 0 && j == k - 1;
            if !closes_polygon && !is_diagonal(i, j) {
                continue; // stays INFEASIBLE, so no parent uses it
            }
            let mut best = objective.empty();
            let mut best_m = INFEASIBLE;
            let (row, column) = (
                &cells[at(i, 0)..at(i, 0) + k],
                &by_end[at(j, 0)..at(j, 0) + k],
            );
            for m in i + 1..j {
                let (left, right) = (row[m], column[m]);
                if left.1 == INFEASIBLE || right.1 == INFEASIBLE || !is_triangle(i, m, j) {
                    continue;
                }
                // The cells hold their chord's own cost already.
                let v = with(
                    objective.combine(left.0, right.0),
                    objective.triangle(i, m, j),
                );
                let better = best_m == INFEASIBLE
                    || if objective.undecided(v, best) {
                        // Reconstruct both candidates' diagonals from the
                        // finished sub-problems and let the objective decide
                        // exactly (common diagonals cancel).
                        let mut a = Vec::new();
                        let mut b = Vec::new();
                        diagonals_of(&cells, k, i, m, j, &mut a);
                        diagonals_of(&cells, k, i, best_m as usize, j, &mut b);
                        cancel_common(&mut a, &mut b);
                        objective.better_diagonals(&a, &b)
                    } else {
                        objective.better(v, best)
                    };
                if better {
                    best = v;
                    best_m = m as u32;
                }
            }
            // Charged once here with the chord's own cost (as a diagonal of
            // the parents), not in every parent's split loop: a sum or a
            // maximum may be regrouped (`combine` is associative), and
            // every decision is exact whatever the grouping (certified
            // enclosures decide, or the exact comparison of the diagonals).
            let charged = if closes_polygon || best_m == INFEASIBLE {
                best
            } else {
                with(best, objective.diagonal(i, j))
            };
            cells[at(i, j)] = (charged, best_m);
            by_end[at(j, i)] = (charged, best_m);
        }
    }
    let mut triangles = Vec::with_capacity(k - 2);
    let mut stack = vec![(0usize, k - 1)];
    while let Some((i, j)) = stack.pop() {
        if j < i + 2 {
            continue;
        }
        let m = cells[at(i, j)].1;
        if m == INFEASIBLE {
            return Ok(None);
        }
        let m = m as usize;
        triangles.push([i, m, j]);
        stack.push((i, m));
        stack.push((m, j));
    }
    Ok(Some(Triangulated {
        triangles,
        value: cells[at(0, k - 1)].0,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Counts diagonals: every triangulation of a convex k-gon has k − 3.
    struct DiagonalCount;
    impl Objective for DiagonalCount {
        type Value = u32;
        fn empty(&self) -> u32 {
            0
        }
        fn diagonal(&self, _: usize, _: usize) -> Option<u32> {
            Some(1)
        }
        fn triangle(&self, _: usize, _: usize, _: usize) -> Option<u32> {
            None
        }
        fn combine(&self, a: u32, b: u32) -> u32 {
            a + b
        }
        fn better(&self, a: u32, b: u32) -> bool {
            a < b
        }
    }

    /// Bottleneck: the largest corner index sum of a triangle (an arbitrary
    /// but checkable cost).
    struct LargestTriangleKey;
    impl Objective for LargestTriangleKey {
        type Value = usize;
        fn empty(&self) -> usize {
            0
        }
        fn diagonal(&self, _: usize, _: usize) -> Option<usize> {
            None
        }
        fn triangle(&self, i: usize, m: usize, j: usize) -> Option<usize> {
            Some(i * i + m * m + j * j)
        }
        fn combine(&self, a: usize, b: usize) -> usize {
            a.max(b)
        }
        fn better(&self, a: usize, b: usize) -> bool {
            a < b
        }
    }

    /// Every triangulation of corners `i..=j` as sorted triangle lists.
    fn all(i: usize, j: usize, ok: &dyn Fn(usize, usize) -> bool) -> Vec<Vec<[usize; 3]>> {
        if j < i + 2 {
            return vec![Vec::new()];
        }
        let mut out = Vec::new();
        for m in i + 1..j {
            if (m > i + 1 && !ok(i, m)) || (j > m + 1 && !ok(m, j)) {
                continue;
            }
            for a in all(i, m, ok) {
                for b in all(m, j, ok) {
                    let mut t = vec![[i, m, j]];
                    t.extend(a.iter().copied());
                    t.extend(b.iter().copied());
                    out.push(t);
                }
            }
        }
        out
    }

    #[test]
    fn additive_and_bottleneck_optima_match_enumeration() {
        for k in 3..=9 {
            // Forbid every chord (i, j) with (i + 2 j) % 5 == 0, except that
            // the fan from 0 stays allowed, so a triangulation always exists.
            let ok = |i: usize, j: usize| i == 0 || !(i + 2 * j).is_multiple_of(5);
            let every = all(0, k - 1, &ok);
            let got = optimal_triangulation(k, ok, |_, _, _| true, &DiagonalCount).unwrap();
            assert_eq!(got.value as usize, k - 3);
            assert_eq!(got.triangles.len(), k - 2);
            let got = optimal_triangulation(k, ok, |_, _, _| true, &LargestTriangleKey).unwrap();
            let best = every
                .iter()
                .map(|t| {
                    t.iter()
                        .map(|&[i, m, j]| i * i + m * m + j * j)
                        .max()
                        .unwrap()
                })
                .min()
                .unwrap();
            assert_eq!(got.value, best, "k = {k}");
            let worst_of_got = got
                .triangles
                .iter()
                .map(|&[i, m, j]| i * i + m * m + j * j)
                .max()
                .unwrap();
            assert_eq!(worst_of_got, best);
        }
    }

    #[test]
    fn no_allowed_triangulation_is_none() {
        assert!(optimal_triangulation(5, |_, _| false, |_, _, _| true, &DiagonalCount).is_none());
        assert!(
            optimal_triangulation(4, |_, _| true, |_, m, _| m != 1 && m != 2, &DiagonalCount)
                .is_none()
        );
        assert!(optimal_triangulation(2, |_, _| true, |_, _, _| true, &DiagonalCount).is_none());
    }
}
