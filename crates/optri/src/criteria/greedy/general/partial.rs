//! The partial greedy triangulation between rounds: angular neighbour lists
//! and the closed-triangle, closed-vertex and active-edge tests of the module
//! docs ("Earlier edges: only the *active* ones"). [`Partial::gap_closed`]
//! is the empty-triangle Lemma's closed triangle, [`Partial::still_open`] drops a
//! closed vertex, [`Partial::active_edges_at`] the active edges of the Claim,
//! and [`Partial::leaves_through`] the condition that a later candidate
//! leaves both endpoints through an open gap.

use crate::kernel::{compare_angles, orient_sign, Point};
use crate::parallel::prelude::*;
use std::cmp::Ordering;

/// The open gaps of a round's open vertices (indices into its `open`
/// list), as [`Partial::still_open`] finds them: one flat list.
#[derive(Default)]
pub(super) struct OpenGaps {
    flat: Vec<[u32; 2]>,
    /// Where each vertex's gaps end in `flat`.
    end: Vec<u32>,
    /// Does the vertex have fewer than two neighbours (no gaps listed)?
    few: Vec<bool>,
}

impl OpenGaps {
    /// `len` vertices without neighbours (before the first round).
    pub(super) fn none(len: usize) -> Self {
        Self {
            flat: Vec::new(),
            end: vec![0; len],
            few: vec![true; len],
        }
    }

    /// The open gaps of the `i`-th open vertex, `None` when it has fewer
    /// than two neighbours.
    #[inline]
    pub(super) fn get(&self, i: usize) -> Option<&[[u32; 2]]> {
        if self.few[i] {
            return None;
        }
        let begin = if i == 0 { 0 } else { self.end[i - 1] as usize };
        Some(&self.flat[begin..self.end[i] as usize])
    }
}

/// Not a hull vertex (no hull neighbours).
const NOT_ON_HULL: u32 = u32::MAX;

/// The partial greedy triangulation: neighbours of each vertex sorted
/// counter-clockwise from the positive x-axis.
pub(super) struct Partial<'a> {
    points: &'a [Point],
    adjacency: Vec<Vec<u32>>,
    hull_prev: Vec<u32>,
    hull_next: Vec<u32>,
    edges: usize,
}

impl<'a> Partial<'a> {
    /// No edges yet; `hull` is the convex hull cycle (ccw), whose outer gaps
    /// are closed from the start.
    pub(super) fn new(points: &'a [Point], hull: &[u32]) -> Self {
        let n = points.len();
        let mut hull_prev = vec![NOT_ON_HULL; n];
        let mut hull_next = vec![NOT_ON_HULL; n];
        for i in 0..hull.len() {
            let v = hull[i] as usize;
            hull_prev[v] = hull[(i + hull.len() - 1) % hull.len()];
            hull_next[v] = hull[(i + 1) % hull.len()];
        }
        Self {
            points,
            adjacency: vec![Vec::new(); n],
            hull_prev,
            hull_next,
            edges: 0,
        }
    }

    /// The number of edges added so far.
    #[inline]
    pub(super) fn edge_count(&self) -> usize {
        self.edges
    }

    #[inline]
    fn p(&self, v: u32) -> Point {
        self.points[v as usize]
    }

    fn has_edge(&self, u: u32, w: u32) -> bool {
        let (lu, lw) = (&self.adjacency[u as usize], &self.adjacency[w as usize]);
        if lu.len() <= lw.len() {
            lu.contains(&w)
        } else {
            lw.contains(&u)
        }
    }

    /// Is the gap between consecutive neighbours `u` then `w` (ccw) of `v`
    /// closed: a closed triangle or the outer gap of a hull vertex?
    #[inline]
    fn gap_closed(&self, v: u32, u: u32, w: u32) -> bool {
        (self.hull_prev[v as usize] == u && self.hull_next[v as usize] == w)
            || (orient_sign(self.p(v), self.p(u), self.p(w)) > 0 && self.has_edge(u, w))
    }

    /// Appends the open gaps at `v` (not closed, see [`Self::gap_closed`])
    /// to `out`, each as the neighbours `[u, w]` bounding it
    /// counter-clockwise; `false` (and nothing appended) when `v` has fewer
    /// than two neighbours, so that only the direction of its neighbour (if
    /// any) is taken.
    fn open_gaps_into(&self, v: u32, out: &mut Vec<[u32; 2]>) -> bool {
        let list = &self.adjacency[v as usize];
        let len = list.len();
        if len < 2 {
            return false;
        }
        out.extend(
            (0..len)
                .map(|i| [list[i], list[(i + 1) % len]])
                .filter(|&[u, w]| !self.gap_closed(v, u, w)),
        );
        true
    }

    /// The vertices of `open` that are still open — not *closed*, i.e. with
    /// fewer than two neighbours or an open gap (module docs) — in order,
    /// with their open gaps. In parallel blocks of `per_task` vertices, each
    /// appending to one flat list (a `Vec` per vertex cost an allocation
    /// and a free per open vertex and round).
    pub(super) fn still_open(&self, open: &[u32], per_task: usize) -> (Vec<u32>, OpenGaps) {
        let parts: Vec<(Vec<u32>, OpenGaps)> = open
            .par_chunks(per_task)
            .map(|chunk| {
                let mut kept = Vec::new();
                let mut gaps = OpenGaps::default();
                for &v in chunk {
                    let mark = gaps.flat.len();
                    let many = self.open_gaps_into(v, &mut gaps.flat);
                    if many && gaps.flat.len() == mark {
                        continue; // closed
                    }
                    kept.push(v);
                    gaps.end.push(gaps.flat.len() as u32);
                    gaps.few.push(!many);
                }
                (kept, gaps)
            })
            .collect();
        let mut kept = Vec::with_capacity(parts.iter().map(|p| p.0.len()).sum());
        let mut gaps = OpenGaps::default();
        for (part_kept, part) in parts {
            let offset = gaps.flat.len() as u32;
            kept.extend_from_slice(&part_kept);
            gaps.flat.extend_from_slice(&part.flat);
            gaps.end.extend(part.end.iter().map(|&e| e + offset));
            gaps.few.extend_from_slice(&part.few);
        }
        (kept, gaps)
    }

    /// May an edge leave `a` towards `b`, given `a`'s open gaps? Not if its
    /// direction is taken (a point on the segment, or an overlapping edge —
    /// the nearest point `z` on `ab` gives a shorter `az` that was rejected
    /// for crossing an edge, which then crosses `ab` too) or falls into a
    /// closed triangle (whose third side it would cross): `b` must lie
    /// strictly inside an open gap.
    pub(super) fn leaves_through(&self, a: u32, gaps: Option<&[[u32; 2]]>, b: u32) -> bool {
        let (pa, pb) = (self.p(a), self.p(b));
        let Some(gaps) = gaps else {
            return self.adjacency[a as usize]
                .iter()
                .all(|&u| compare_angles(pa, self.p(u), pb) != Ordering::Equal);
        };
        gaps.iter().any(|&[u, w]| {
            let (pu, pw) = (self.p(u), self.p(w));
            if orient_sign(pa, pu, pw) > 0 {
                orient_sign(pa, pu, pb) > 0 && orient_sign(pa, pb, pw) > 0
            } else {
                // A gap of 180° or more: inside unless in the closed
                // complementary wedge from w to u (at most 180°).
                !(orient_sign(pa, pw, pb) >= 0 && orient_sign(pa, pb, pu) >= 0)
            }
        })
    }

    /// Edges at open `v` towards larger open vertices with a side that is not
    /// a closed triangle, given `v`'s open gaps (from [`Self::still_open`]):
    /// the sides of the edge to `u` are the gaps on either side of `u` at
    /// `v`, the only gaps `u` bounds, so a side is open iff `u` bounds an
    /// open gap (every side is open when `v` has fewer than two neighbours).
    pub(super) fn active_edges_at(
        &self,
        v: u32,
        gaps: Option<&[[u32; 2]]>,
        is_open: &[bool],
        out: &mut Vec<[u32; 2]>,
    ) {
        for &u in &self.adjacency[v as usize] {
            if u < v || !is_open[u as usize] {
                continue;
            }
            let open_side = gaps.is_none_or(|list| list.iter().any(|&[x, y]| x == u || y == u));
            if open_side {
                out.push([v, u]);
            }
        }
    }

    /// The triangles of a complete triangulation: at every vertex, each
    /// pair of consecutive neighbours with a left turn bounds a triangle
    /// (every gap but a hull vertex's outer one is a triangle, and that one
    /// turns right or is straight); each is reported by its smallest corner.
    pub(super) fn triangles(&self) -> Vec<[u32; 3]> {
        (0..self.points.len() as u32)
            .into_par_iter()
            .fold(Vec::new, |mut out, v| {
                let list = &self.adjacency[v as usize];
                for i in 0..list.len() {
                    let (u, w) = (list[i], list[(i + 1) % list.len()]);
                    if v < u && v < w && orient_sign(self.p(v), self.p(u), self.p(w)) > 0 {
                        out.push([v, u, w]);
                    }
                }
                out
            })
            .flatten()
            .collect()
    }

    /// Adds a round's accepted edges (they cross nothing and share no
    /// direction at a vertex, so the angular order is strict).
    pub(super) fn add(&mut self, accepted: &[[u32; 2]]) {
        // The new neighbours grouped by vertex (a counting sort: only the
        // grouping matters, each list is re-sorted by angle), then every
        // touched list extended and re-sorted in parallel.
        let n = self.points.len();
        let mut start = vec![0u32; n + 1];
        for &[a, b] in accepted {
            start[a as usize + 1] += 1;
            start[b as usize + 1] += 1;
        }
        for v in 0..n {
            start[v + 1] += start[v];
        }
        let mut fill = start.clone();
        let mut other = vec![0u32; 2 * accepted.len()];
        for &[a, b] in accepted {
            other[fill[a as usize] as usize] = b;
            fill[a as usize] += 1;
            other[fill[b as usize] as usize] = a;
            fill[b as usize] += 1;
        }
        drop(fill);
        let points = self.points;
        self.adjacency
            .par_iter_mut()
            .enumerate()
            .for_each(|(v, list)| {
                let new = &other[start[v] as usize..start[v + 1] as usize];
                if new.is_empty() {
                    return;
                }
                list.extend_from_slice(new);
                let pv = points[v];
                list.sort_unstable_by(|&x, &y| {
                    compare_angles(pv, points[x as usize], points[y as usize])
                });
            });
        self.edges += accepted.len();
    }
}
