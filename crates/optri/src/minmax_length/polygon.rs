//! A polygonal region of `ch(S) ∪ rng(S)` as a cyclic sequence of
//! *positions* (000_5891e11f36dd26ad.txt §3): a vertex may occur at several
//! positions when the region has zero-width cracks, and each position is
//! treated as its own corner ("cracks opened up a tiny amount").
//!
//! This file holds the exact (unperturbed) geometry of a region: which
//! position pairs are diagonals, and §3's straightforward cubic dynamic
//! program (Klincsek) used as the test reference and as the fallback.

use crate::kernel::{compare_lengths, dot_sign, orient_sign, Point};
use std::cmp::Ordering;

/// A region: `vertices[i]` is the distinct-point index at position `i`, in
/// counter-clockwise order (the region is to the left of every boundary edge).
pub(crate) struct Region<'a> {
    pub points: &'a [Point],
    pub vertices: &'a [u32],
}

/// Counter-clockwise angle class of direction `x − o` relative to the ray
/// `o → r`: 0 on the ray, 1 in (0, π), 2 opposite, 3 in (π, 2π).
fn angle_class(o: Point, r: Point, x: Point) -> u8 {
    match orient_sign(o, r, x) {
        1 => 1,
        -1 => 3,
        _ => {
            if dot_sign(o, r, x) > 0 {
                0
            } else {
                2
            }
        }
    }
}

/// Exact comparison of the counter-clockwise angles from ray `o → r` to rays
/// `o → x` and `o → y` (each in `[0, 2π)`).
fn compare_ccw_from(o: Point, r: Point, x: Point, y: Point) -> Ordering {
    let (cx, cy) = (angle_class(o, r, x), angle_class(o, r, y));
    cx.cmp(&cy).then_with(|| {
        if cx == 1 || cx == 3 {
            match orient_sign(o, x, y) {
                1 => Ordering::Less,
                -1 => Ordering::Greater,
                _ => Ordering::Equal,
            }
        } else {
            Ordering::Equal
        }
    })
}

/// Is the direction `x − o` strictly inside the counter-clockwise wedge that
/// sweeps from ray `o → first` to ray `o → last`? Equal rays mean the full
/// turn (a crack tip).
fn strictly_inside_wedge(o: Point, first: Point, last: Point, x: Point) -> bool {
    if angle_class(o, first, x) == 0 {
        return false;
    }
    if angle_class(o, first, last) == 0 {
        return true;
    }
    compare_ccw_from(o, first, x, last) == Ordering::Less
}

/// Is `x` strictly inside the open segment `ab`?
fn strictly_between(a: Point, b: Point, x: Point) -> bool {
    orient_sign(a, b, x) == 0 && dot_sign(x, a, b) < 0
}

impl<'a> Region<'a> {
    pub fn len(&self) -> usize {
        self.vertices.len()
    }

    #[inline]
    pub fn point(&self, pos: usize) -> Point {
        self.points[self.vertices[pos] as usize]
    }

    /// Is the region a strictly convex polygon (no cracks, every corner a
    /// strict left turn)? Then every pair of non-adjacent positions is a diagonal.
    pub fn is_strictly_convex(&self) -> bool {
        let k = self.len();
        (0..k).all(|i| {
            orient_sign(
                self.point(i),
                self.point((i + 1) % k),
                self.point((i + 2) % k),
            ) > 0
        })
    }

    /// Is the segment between positions `a` and `b` (not adjacent) a diagonal:
    /// its relatively open segment inside the region? Exact, O(k).
    ///
    /// It leaves both corners into the region's wedge, contains no vertex and
    /// crosses no boundary edge; then it cannot leave the region.
    pub fn is_diagonal(&self, a: usize, b: usize) -> bool {
        let k = self.len();
        let (va, vb) = (self.vertices[a], self.vertices[b]);
        if va == vb {
            return false;
        }
        let (pa, pb) = (self.point(a), self.point(b));
        let wedge_ok = |pos: usize, target: Point| {
            let o = self.point(pos);
            strictly_inside_wedge(
                o,
                self.point((pos + 1) % k),
                self.point((pos + k - 1) % k),
                target,
            )
        };
        if !wedge_ok(a, pb) || !wedge_ok(b, pa) {
            return false;
        }
        for i in 0..k {
            let (u, w) = (self.vertices[i], self.vertices[(i + 1) % k]);
            let (pu, pw) = (self.point(i), self.point((i + 1) % k));
            if u != va && u != vb && strictly_between(pa, pb, pu) {
                return false;
            }
            if u == va || u == vb || w == va || w == vb {
                continue;
            }
            let s1 = orient_sign(pa, pb, pu) * orient_sign(pa, pb, pw);
            let s2 = orient_sign(pu, pw, pa) * orient_sign(pu, pw, pb);
            if s1 < 0 && s2 < 0 {
                return false;
            }
        }
        true
    }

    /// §3's cubic dynamic program: a triangulation of the region minimising
    /// its longest diagonal, with exact length comparisons. Returns triangles
    /// as distinct-point indices. O(k³) time, O(k²) space.
    ///
    /// The sub-problem `(i, j)` is the sub-polygon of positions `i..=j` closed
    /// by the chord `ij`; its value is the longest diagonal used inside it.
    pub fn minmax_triangulation_cubic(&self) -> Vec<[u32; 3]> {
        let k = self.len();
        if k == 3 {
            return vec![[self.vertices[0], self.vertices[1], self.vertices[2]]];
        }
        let convex = self.is_strictly_convex();
        // usable[i][j]: chord between positions i < j is an edge or a diagonal.
        let idx = |i: usize, j: usize| i * k + j;
        let mut usable = vec![false; k * k];
        for i in 0..k {
            for j in i + 1..k {
                usable[idx(i, j)] =
                    j == i + 1 || (i == 0 && j == k - 1) || convex || self.is_diagonal(i, j);
            }
        }
        const NONE: u32 = u32::MAX;
        // value: the longest diagonal as a position pair (NONE = no diagonal yet).
        let mut value = vec![[NONE, NONE]; k * k];
        let mut split = vec![NONE; k * k];
        let longer = |s: [u32; 2], t: [u32; 2]| -> [u32; 2] {
            if s[0] == NONE {
                return t;
            }
            if t[0] == NONE {
                return s;
            }
            let p = |x: u32| self.point(x as usize);
            if compare_lengths(p(s[0]), p(s[1]), p(t[0]), p(t[1])) == Ordering::Less {
                t
            } else {
                s
            }
        };
        let is_less = |s: [u32; 2], t: [u32; 2]| -> bool {
            if t[0] == NONE {
                return false;
            }
            if s[0] == NONE {
                return true;
            }
            let p = |x: u32| self.point(x as usize);
            compare_lengths(p(s[0]), p(s[1]), p(t[0]), p(t[1])) == Ordering::Less
        };
        for gap in 2..k {
            for i in 0..k - gap {
                let j = i + gap;
                if !usable[idx(i, j)] {
                    continue;
                }
                let mut best = [NONE, NONE];
                let mut best_m = NONE;
                for m in i + 1..j {
                    if !usable[idx(i, m)] || !usable[idx(m, j)] {
                        continue;
                    }
                    if (m > i + 1 && split[idx(i, m)] == NONE)
                        || (j > m + 1 && split[idx(m, j)] == NONE)
                    {
                        continue; // that side cannot be triangulated
                    }
                    if orient_sign(self.point(i), self.point(m), self.point(j)) <= 0 {
                        continue;
                    }
                    let mut v = longer(value[idx(i, m)], value[idx(m, j)]);
                    if m > i + 1 {
                        v = longer(v, [i as u32, m as u32]);
                    }
                    if j > m + 1 {
                        v = longer(v, [m as u32, j as u32]);
                    }
                    if best_m == NONE || is_less(v, best) {
                        best = v;
                        best_m = m as u32;
                    }
                }
                value[idx(i, j)] = best;
                split[idx(i, j)] = best_m;
            }
        }
        let mut triangles = Vec::with_capacity(k - 2);
        let mut stack = vec![(0usize, k - 1)];
        while let Some((i, j)) = stack.pop() {
            if j < i + 2 {
                continue;
            }
            let m = split[idx(i, j)];
            assert!(m != NONE, "a polygonal region always has a triangulation");
            let m = m as usize;
            triangles.push([self.vertices[i], self.vertices[m], self.vertices[j]]);
            stack.push((i, m));
            stack.push((m, j));
        }
        triangles
    }
}
