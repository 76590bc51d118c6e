//! A polygonal region of `ch(S) ∪ rng(S)` as a cyclic sequence of
//! *positions* (Edelsbrunner & Tan 1991, §3): a vertex may occur at several
//! positions when the region has zero-width cracks, and each position is
//! treated as its own corner ("cracks opened up a tiny amount").
//!
//! This file holds a region's length comparisons, on the exact or the
//! perturbed points (its corners and diagonals are a
//! [`PolygonCycle`]), §3's straightforward cubic dynamic program
//! (Klincsek) used as the test reference and as the fallback, and the same
//! program on a simple polygon given as input ([`solve_polygon`]).

use crate::criteria::{solve_convex_polygon, Diagnostics, Optimality, Options, Solved};
use crate::error::Result;
use crate::kernel::{compare_lengths, compare_lengths_symbolic, Point};
use crate::polygon_program::{
    corner_point, on_simple_polygon, optimal_triangulation, LargestDiagonal,
};
use crate::structures::{PolygonCycle, SimplePolygon};
use crate::timing::Phase;
use std::cmp::Ordering;

/// A region: `vertices[i]` is the distinct-point index at position `i`, in
/// counter-clockwise order (the region is to the left of every boundary edge).
///
/// With `symbolic` set, every predicate is evaluated on the kernel's
/// perturbed points `S′` (no three collinear, no equal lengths); otherwise on
/// the exact input.
pub(crate) struct Region<'a> {
    pub points: &'a [Point],
    pub vertices: &'a [u32],
    pub symbolic: bool,
}

/// Rounded squared lengths of all position pairs of a region: they decide
/// every comparison that the error bound of [`compare_lengths`] allows, and
/// the rest go to the region's exact comparison.
pub(crate) struct ChordLengths {
    k: usize,
    squared: Vec<f64>,
}

impl ChordLengths {
    pub fn new(region: &Region) -> Self {
        let k = region.len();
        let mut squared = vec![0.0; k * k];
        for i in 0..k {
            let pi = region.points[region.vertices[i] as usize];
            for j in i + 1..k {
                let pj = region.points[region.vertices[j] as usize];
                let (dx, dy) = (pi[0] - pj[0], pi[1] - pj[1]);
                squared[i * k + j] = dx * dx + dy * dy;
                squared[j * k + i] = squared[i * k + j];
            }
        }
        Self { k, squared }
    }

    /// Rounded squared length of the chord between positions `i` and `j`.
    #[inline]
    pub fn squared(&self, [i, j]: [usize; 2]) -> f64 {
        self.squared[i * self.k + j]
    }

    /// Compares the lengths of two position pairs, exactly.
    #[inline]
    pub fn compare(&self, region: &Region, s: [usize; 2], t: [usize; 2]) -> Ordering {
        Self::filtered(self.squared(s), self.squared(t), || {
            let v = region.vertices;
            region.compare_lengths([v[s[0]], v[s[1]]], [v[t[0]], v[t[1]]])
        })
    }

    /// The rounded comparison of two squared lengths computed as
    /// `dx² + dy²`, or `exact()` where rounding could decide it wrongly
    /// (same error bound as [`compare_lengths`]).
    #[inline]
    pub fn filtered(l1: f64, l2: f64, exact: impl FnOnce() -> Ordering) -> Ordering {
        crate::kernel::compare_rounded_keys(l1, l2).unwrap_or_else(exact)
    }
}

impl<'a> Region<'a> {
    pub fn len(&self) -> usize {
        self.vertices.len()
    }

    /// The region's corners as a polygon cycle, decided on the perturbed
    /// points when `symbolic`.
    #[inline]
    pub fn cycle(&self) -> PolygonCycle<'a> {
        PolygonCycle::new(self.points, self.vertices, self.symbolic)
    }

    /// Orientation of three points by index (0 if two indices coincide).
    #[inline]
    pub fn orient(&self, i: u32, j: u32, k: u32) -> i32 {
        self.cycle().orient(i, j, k)
    }

    /// Compares `|ab|` with `|cd|` (indices).
    #[inline]
    pub fn compare_lengths(&self, ab: [u32; 2], cd: [u32; 2]) -> Ordering {
        if (ab[0] == cd[0] && ab[1] == cd[1]) || (ab[0] == cd[1] && ab[1] == cd[0]) {
            return Ordering::Equal; // the same segment: skip the exact fallback
        }
        if self.symbolic {
            compare_lengths_symbolic(self.points, ab, cd)
        } else {
            let p = |m: u32| self.points[m as usize];
            compare_lengths(p(ab[0]), p(ab[1]), p(cd[0]), p(cd[1]))
        }
    }

    /// Is the direction `x − o` strictly inside the counter-clockwise wedge
    /// that sweeps from ray `o → first` to ray `o → last`? Equal rays mean the
    /// full turn (a crack tip): the kernel's `strictly_inside_wedge`.
    pub fn strictly_inside_wedge(&self, o: u32, first: u32, last: u32, x: u32) -> bool {
        self.cycle().wedge_contains(o, first, last, x)
    }

    /// Is the region a strictly convex polygon (no cracks, every corner a
    /// strict left turn)? Then every pair of non-adjacent positions is a diagonal.
    pub fn is_strictly_convex(&self) -> bool {
        self.cycle().is_strictly_convex()
    }

    /// Is the segment between positions `a` and `b` a diagonal: its
    /// relatively open segment inside the region? Exact, O(k).
    pub fn is_diagonal(&self, a: usize, b: usize) -> bool {
        self.cycle().is_diagonal(a, b)
    }

    /// §3's cubic dynamic program: a triangulation of the region minimising
    /// its longest diagonal, with exact length comparisons. Returns triangles
    /// as distinct-point indices. O(k³) time, O(k²) space.
    ///
    /// The sub-problem `(i, j)` is the sub-polygon of positions `i..=j` closed
    /// by the chord `ij`; its value is the longest diagonal used inside it.
    pub fn minmax_triangulation_cubic(&self) -> Vec<[u32; 3]> {
        self.minmax_triangulation_bounded(None)
    }

    /// A lower bound on the longest edge of every triangulation of the
    /// region, as a position pair: each boundary edge `ab` is a side of a
    /// triangle `abc` with `c` a corner strictly to the left of `ab`, so some
    /// edge is at least `min_c max(|ac|, |bc|)`; the bound is the largest of
    /// these over the boundary edges, and at least the longest boundary edge.
    /// O(k²). (Requiring `ac` and `bc` to be diagonals tightens it in theory;
    /// on 10⁶ uniform points it certified no additional region.)
    pub fn apex_lower_bound(&self, lengths: &ChordLengths) -> [usize; 2] {
        let k = self.len();
        let v = self.vertices;
        let longer = |s: [usize; 2], t: [usize; 2]| {
            if lengths.compare(self, s, t) == Ordering::Less {
                t
            } else {
                s
            }
        };
        let mut bound = [0, 1];
        for i in 1..k {
            bound = longer(bound, [i, (i + 1) % k]);
        }
        for i in 0..k {
            let j = (i + 1) % k;
            let mut best: Option<[usize; 2]> = None;
            for c in 0..k {
                if c == i || c == j || self.orient(v[i], v[j], v[c]) <= 0 {
                    continue;
                }
                let cand = longer([i, c], [j, c]);
                if lengths.compare(self, cand, bound) != Ordering::Greater {
                    best = None; // this apex cannot raise the bound
                    break;
                }
                if best.is_none_or(|b| lengths.compare(self, cand, b) == Ordering::Less) {
                    best = Some(cand);
                }
            }
            if let Some(best) = best {
                bound = best;
            }
        }
        bound
    }

    /// The optimum of a simple quadrilateral (positions 0..4): a chord is a
    /// diagonal iff the other two corners lie strictly on opposite sides of
    /// it; of two diagonals the shorter wins. `None` if neither qualifies.
    pub fn quadrilateral(&self) -> Option<Vec<[u32; 3]>> {
        let [a, b, c, d] = <[u32; 4]>::try_from(self.vertices).ok()?;
        let ac = self.orient(a, c, b) < 0 && self.orient(a, c, d) > 0;
        let bd = self.orient(b, d, c) < 0 && self.orient(b, d, a) > 0;
        let use_ac = match (ac, bd) {
            (true, true) => self.compare_lengths([a, c], [b, d]) != Ordering::Greater,
            (true, false) => true,
            (false, true) => false,
            (false, false) => return None,
        };
        Some(if use_ac {
            vec![[a, b, c], [a, c, d]]
        } else {
            vec![[b, c, d], [b, d, a]]
        })
    }

    /// [`Self::minmax_triangulation_cubic`] using only chords no longer than
    /// `bound` (vertex indices), the longest diagonal of some triangulation of
    /// the region: that triangulation stays feasible, so the optimum, and
    /// every chord it uses, is no longer than `bound`. Skipping the longer
    /// chords saves their O(k) diagonal tests.
    pub fn minmax_triangulation_bounded(&self, bound: Option<[u32; 2]>) -> Vec<[u32; 3]> {
        self.minmax_triangulation_with(bound, &ChordLengths::new(self))
    }

    /// [`Self::minmax_triangulation_bounded`] with the chord lengths at hand:
    /// the library's polygon program with the longest diagonal as a
    /// bottleneck objective.
    pub fn minmax_triangulation_with(
        &self,
        bound: Option<[u32; 2]>,
        lengths: &ChordLengths,
    ) -> Vec<[u32; 3]> {
        let k = self.len();
        if k == 3 {
            return vec![[self.vertices[0], self.vertices[1], self.vertices[2]]];
        }
        let v = self.vertices;
        let convex = self.is_strictly_convex();
        let bound_squared = bound.map(|[a, b]| {
            let (pa, pb) = (self.points[a as usize], self.points[b as usize]);
            let (dx, dy) = (pa[0] - pb[0], pa[1] - pb[1]);
            dx * dx + dy * dy
        });
        let short_enough = |i: usize, j: usize| {
            bound.zip(bound_squared).is_none_or(|(b, b_squared)| {
                ChordLengths::filtered(lengths.squared([i, j]), b_squared, || {
                    self.compare_lengths([v[i], v[j]], b)
                }) != Ordering::Greater
            })
        };
        let solved = optimal_triangulation(
            k,
            |i, j| short_enough(i, j) && (convex || self.is_diagonal(i, j)),
            |i, m, j| self.orient(v[i], v[m], v[j]) > 0,
            &LargestDiagonal::new(k, |s, t| lengths.compare(self, s, t)),
        )
        .expect("a polygonal region always has a triangulation");
        solved
            .triangles
            .into_iter()
            .map(|t| t.map(|c| v[c]))
            .collect()
    }
}

/// `minmax-length` on a simple polygon ([`crate::triangulate`]):
/// the polygon program with the longest diagonal as a bottleneck, compared
/// exactly. The longest edge of a polygon triangulation is the longer of
/// the longest boundary edge, which every triangulation has, and the
/// longest diagonal; so minimising the longest diagonal minimises the
/// longest edge.
pub(crate) fn solve_polygon(
    polygon: &SimplePolygon,
    options: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    if let Some(solved) = solve_convex_polygon(polygon, options, phases, super::solve) {
        return solved;
    }
    let p = corner_point(polygon);
    let objective = LargestDiagonal::new(polygon.len(), |s: [usize; 2], t: [usize; 2]| {
        compare_lengths(p(s[0]), p(s[1]), p(t[0]), p(t[1]))
    });
    let triangulation = on_simple_polygon(polygon, "minmax-length", &objective, phases)?;
    Ok(Solved {
        triangulation,
        algorithm: "Klincsek dynamic program on the polygon, O(n^3), exact length comparisons"
            .to_string(),
        optimality: Optimality::Exact,
        diagnostics: Diagnostics::default(),
        bound: None,
        approximation: None,
    })
}
