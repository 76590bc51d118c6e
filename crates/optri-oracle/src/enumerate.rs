//! Exhaustive enumeration of all triangulations of a small point set, and a
//! second, independent enumeration by breadth-first search of the flip graph.
//!
//! A triangulation of a point set (using every point) is exactly a maximal
//! set of pairwise non-crossing segments, where a segment is a pair of points
//! whose closed segment contains no third point. [`all_triangulations`]
//! enumerates those maximal sets by include/exclude backtracking.
//! [`flip_graph_triangulations`] instead starts from one triangulation and
//! applies every possible edge flip; the flip graph of a planar point set is
//! connected (Lawson 1972), so it reaches every triangulation. The crate's
//! tests check that both give the same set.

use crate::exact::{
    compare_squared_lengths, on_open_segment, orient, properly_cross, squared_length, twice_area,
    Point,
};
use num_rational::BigRational;
use num_traits::ToPrimitive;
use std::cmp::Ordering;
use std::collections::{BTreeSet, HashSet, VecDeque};

/// Largest point set [`all_triangulations`] accepts.
pub const MAX_ENUMERATION_POINTS: usize = 12;

/// A triangle with its vertices in counter-clockwise order, rotated so that
/// the smallest index comes first.
pub fn canonical_triangle(points: &[Point], t: [u32; 3]) -> [u32; 3] {
    let p = |i: u32| points[i as usize];
    let o = orient(p(t[0]), p(t[1]), p(t[2]));
    assert!(o != 0, "optri-oracle: flat triangle {t:?}");
    let t = if o > 0 { t } else { [t[0], t[2], t[1]] };
    let m = (0..3).min_by_key(|&i| t[i]).unwrap();
    [t[m], t[(m + 1) % 3], t[(m + 2) % 3]]
}

/// Canonical form of a triangulation: canonical triangles, sorted.
pub fn canonical_triangulation(points: &[Point], tris: &[[u32; 3]]) -> Vec<[u32; 3]> {
    let mut v: Vec<[u32; 3]> = tris
        .iter()
        .map(|&t| canonical_triangle(points, t))
        .collect();
    v.sort_unstable();
    v
}

/// Pairs `[i, j]`, `i < j`, whose closed segment contains no other point.
pub fn empty_segments(points: &[Point]) -> Vec<[u32; 2]> {
    let n = points.len() as u32;
    let mut out = Vec::new();
    for i in 0..n {
        for j in i + 1..n {
            let (a, b) = (points[i as usize], points[j as usize]);
            if (0..points.len()).all(|k| !on_open_segment(a, b, points[k])) {
                out.push([i, j]);
            }
        }
    }
    out
}

fn assert_distinct(points: &[Point]) {
    for i in 0..points.len() {
        for j in i + 1..points.len() {
            assert!(
                points[i] != points[j],
                "optri-oracle: points {i} and {j} coincide"
            );
        }
    }
}

/// The triangles (canonical, sorted) bounded by a maximal non-crossing edge
/// set: the empty, non-flat triangles all of whose sides are edges.
fn faces_of(points: &[Point], edges: &[[u32; 2]]) -> Vec<[u32; 3]> {
    let n = points.len();
    let set: HashSet<[u32; 2]> = edges.iter().copied().collect();
    let has = |a: u32, b: u32| set.contains(&[a.min(b), a.max(b)]);
    let mut tris = Vec::new();
    for &[a, b] in edges {
        for c in b + 1..n as u32 {
            if !(has(a, c) && has(b, c)) {
                continue;
            }
            let (pa, pb, pc) = (points[a as usize], points[b as usize], points[c as usize]);
            let o = orient(pa, pb, pc);
            if o == 0 {
                continue;
            }
            // Strictly inside: same side of all three sides.
            let covers = (0..n).any(|k| {
                let q = points[k];
                orient(pa, pb, q) == o && orient(pb, pc, q) == o && orient(pc, pa, q) == o
            });
            if !covers {
                tris.push(canonical_triangle(points, [a, b, c]));
            }
        }
    }
    tris.sort_unstable();
    // Euler's formula for a triangulated polygon with the hull as outer face.
    assert_eq!(
        tris.len() + n,
        edges.len() + 1,
        "optri-oracle: internal error, a maximal edge set did not give a triangulation"
    );
    tris
}

/// Every maximal set of pairwise compatible items (include/exclude search
/// with pruning), given for each item the items it conflicts with
/// (`conflicts[s]`, ascending). The triangulations of a point set or a
/// polygon are the maximal sets of pairwise non-crossing segments or
/// diagonals.
pub fn maximal_compatible_sets(conflicts: &[Vec<usize>]) -> Vec<Vec<usize>> {
    // An excluded item must end up in conflict with a chosen one
    // (maximality); once the search passes its last conflict without that,
    // prune.
    let last_conflict: Vec<Option<usize>> = conflicts.iter().map(|c| c.last().copied()).collect();
    struct Search<'a> {
        conflicts: &'a [Vec<usize>],
        last_conflict: &'a [Option<usize>],
        chosen: Vec<bool>,
        excluded: Vec<usize>,
        out: Vec<Vec<usize>>,
    }
    impl Search<'_> {
        fn covered(&self, s: usize) -> bool {
            self.conflicts[s].iter().any(|&t| self.chosen[t])
        }
        fn run(&mut self, idx: usize) {
            for &s in &self.excluded {
                if !self.covered(s) && !matches!(self.last_conflict[s], Some(l) if l >= idx) {
                    return;
                }
            }
            if idx == self.chosen.len() {
                self.out
                    .push((0..idx).filter(|&s| self.chosen[s]).collect());
                return;
            }
            if self.covered(idx) {
                // Conflicts with a chosen item: excluded, and already covered.
                self.run(idx + 1);
                return;
            }
            self.chosen[idx] = true;
            self.run(idx + 1);
            self.chosen[idx] = false;
            self.excluded.push(idx);
            self.run(idx + 1);
            self.excluded.pop();
        }
    }
    let mut search = Search {
        conflicts,
        last_conflict: &last_conflict,
        chosen: vec![false; conflicts.len()],
        excluded: Vec::new(),
        out: Vec::new(),
    };
    search.run(0);
    search.out
}

/// Every triangulation of the distinct points `points` (at most
/// [`MAX_ENUMERATION_POINTS`]), each as canonical triangles (counter-clockwise,
/// smallest index first) in sorted order; the list itself is sorted.
///
/// # Panics
/// On more than [`MAX_ENUMERATION_POINTS`] points, coincident points, or
/// fewer than three non-collinear points.
pub fn all_triangulations(points: &[Point]) -> Vec<Vec<[u32; 3]>> {
    assert!(
        points.len() <= MAX_ENUMERATION_POINTS,
        "optri-oracle: at most {MAX_ENUMERATION_POINTS} points"
    );
    assert_distinct(points);
    let segs = empty_segments(points);
    let m = segs.len();
    let p = |i: u32| points[i as usize];
    let crossers: Vec<Vec<usize>> = (0..m)
        .map(|s| {
            (0..m)
                .filter(|&t| {
                    let ([a, b], [c, d]) = (segs[s], segs[t]);
                    properly_cross(p(a), p(b), p(c), p(d))
                })
                .collect()
        })
        .collect();
    let sets = maximal_compatible_sets(&crossers);
    let mut all: Vec<Vec<[u32; 3]>> = sets
        .iter()
        .map(|chosen| {
            let edges: Vec<[u32; 2]> = chosen.iter().map(|&s| segs[s]).collect();
            faces_of(points, &edges)
        })
        .collect();
    all.sort();
    all
}

/// Every triangulation reachable from `start` by edge flips (breadth-first),
/// canonical and sorted like [`all_triangulations`]. An edge `ab` shared by
/// triangles `abc` and `bad` flips to `cd` iff `cd` properly crosses `ab`
/// (the quadrilateral is strictly convex).
pub fn flip_graph_triangulations(points: &[Point], start: &[[u32; 3]]) -> Vec<Vec<[u32; 3]>> {
    let p = |i: u32| points[i as usize];
    let start = canonical_triangulation(points, start);
    let mut seen: BTreeSet<Vec<[u32; 3]>> = BTreeSet::new();
    let mut queue = VecDeque::new();
    seen.insert(start.clone());
    queue.push_back(start);
    while let Some(t) = queue.pop_front() {
        for x in 0..t.len() {
            for y in x + 1..t.len() {
                let shared: Vec<u32> = t[x].iter().copied().filter(|v| t[y].contains(v)).collect();
                if shared.len() != 2 {
                    continue;
                }
                let (a, b) = (shared[0], shared[1]);
                let c = *t[x].iter().find(|v| !shared.contains(v)).unwrap();
                let d = *t[y].iter().find(|v| !shared.contains(v)).unwrap();
                if !properly_cross(p(a), p(b), p(c), p(d)) {
                    continue;
                }
                let mut next: Vec<[u32; 3]> = t
                    .iter()
                    .enumerate()
                    .filter(|&(i, _)| i != x && i != y)
                    .map(|(_, &tri)| tri)
                    .collect();
                next.push(canonical_triangle(points, [a, c, d]));
                next.push(canonical_triangle(points, [b, c, d]));
                next.sort_unstable();
                if seen.insert(next.clone()) {
                    queue.push_back(next);
                }
            }
        }
    }
    seen.into_iter().collect()
}

/// The minimum of `key` over all triangulations of `points` (see
/// [`all_triangulations`]) and every triangulation attaining it.
pub fn optimum_by<K: Ord + Clone>(
    points: &[Point],
    key: impl Fn(&[[u32; 3]]) -> K,
) -> (K, Vec<Vec<[u32; 3]>>) {
    let mut best: Option<(K, Vec<Vec<[u32; 3]>>)> = None;
    for t in all_triangulations(points) {
        let k = key(&t);
        match &mut best {
            Some((bk, ts)) => match k.cmp(bk) {
                Ordering::Less => best = Some((k, vec![t])),
                Ordering::Equal => ts.push(t),
                Ordering::Greater => {}
            },
            None => best = Some((k, vec![t])),
        }
    }
    best.expect("a point set with three non-collinear points has a triangulation")
}

/// The sorted `[min, max]` edges of a set of triangles.
pub fn triangle_edges(tris: &[[u32; 3]]) -> Vec<[u32; 2]> {
    let mut e: Vec<[u32; 2]> = tris
        .iter()
        .flat_map(|t| [[t[0], t[1]], [t[1], t[2]], [t[2], t[0]]])
        .map(|[a, b]| [a.min(b), a.max(b)])
        .collect();
    e.sort_unstable();
    e.dedup();
    e
}

/// The longest edge's squared length (the minmax-length key), exact.
pub fn max_edge_squared(points: &[Point], tris: &[[u32; 3]]) -> BigRational {
    let p = |i: u32| points[i as usize];
    let longest = triangle_edges(tris)
        .into_iter()
        .max_by(|e, f| compare_squared_lengths(p(e[0]), p(e[1]), p(f[0]), p(f[1])))
        .expect("no triangles");
    squared_length(p(longest[0]), p(longest[1]))
}

/// The smallest triangle's doubled area (maximise it: maxmin area), exact.
pub fn min_twice_area(points: &[Point], tris: &[[u32; 3]]) -> BigRational {
    let p = |i: u32| points[i as usize];
    tris.iter()
        .map(|t| twice_area(p(t[0]), p(t[1]), p(t[2])))
        .min()
        .expect("no triangles")
}

/// The largest triangle's doubled area (minimise it: minmax area), exact.
pub fn max_twice_area(points: &[Point], tris: &[[u32; 3]]) -> BigRational {
    let p = |i: u32| points[i as usize];
    tris.iter()
        .map(|t| twice_area(p(t[0]), p(t[1]), p(t[2])))
        .max()
        .expect("no triangles")
}

/// The length of segment `pq`, rounded: the exact squared length is rounded
/// to the nearest `f64`, then `sqrt` (correctly rounded) is applied, so the
/// result is within about one ulp of the true length.
pub fn edge_length(p: Point, q: Point) -> f64 {
    squared_length(p, q).to_f64().expect("finite").sqrt()
}

/// Total edge length (the min-weight key) as `f64`: the sum of
/// [`edge_length`] over the sorted edges, left to right.
///
/// **Rounding:** each term is within ~1 ulp and the sum adds at most one
/// rounding per term, so the relative error is below `(E + 1) · 2^-52` for
/// `E` edges. Two triangulations whose exact weights differ by less than
/// that may be ordered wrongly; compare optima with a relative tolerance
/// (e.g. `1e-12`) rather than for equality.
pub fn total_length(points: &[Point], tris: &[[u32; 3]]) -> f64 {
    let p = |i: u32| points[i as usize];
    triangle_edges(tris)
        .iter()
        .map(|e| edge_length(p(e[0]), p(e[1])))
        .sum()
}

/// An `f64` with a total order (`f64::total_cmp`), to use
/// [`total_length`] as an [`optimum_by`] key.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TotalF64(pub f64);
impl Eq for TotalF64 {}
impl PartialOrd for TotalF64 {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for TotalF64 {
    fn cmp(&self, other: &Self) -> Ordering {
        self.0.total_cmp(&other.0)
    }
}

/// The segments of [`empty_segments`] sorted by length under the symbolic
/// perturbation of [`crate::symbolic`] (ties between equal lengths broken as
/// optri's `kernel::symbolic` specifies, with the indices into `points` as
/// the perturbation ranks), shortest first.
pub fn segments_by_perturbed_length(points: &[Point]) -> Vec<[u32; 2]> {
    let mut segs = empty_segments(points);
    segs.sort_by(|s, t| crate::symbolic::compare_lengths_perturbed(points, *s, *t));
    segs
}

/// The greedy triangulation by its definition: scan the segments that
/// contain no other point, shortest first (equal lengths in the order of the
/// symbolic perturbation, see [`segments_by_perturbed_length`]), and keep
/// each one that does not properly cross a kept one. The kept set is a
/// maximal non-crossing set, hence a triangulation. Returned like
/// [`all_triangulations`]' entries. O(n⁴); for small sets.
///
/// Unlike a greedy run on the perturbed points, a segment through a third
/// point is never a candidate (it would bound a flat triangle). For segments
/// that contain no point, exact proper crossing and crossing after the
/// perturbation coincide, so no other decision depends on ε.
pub fn greedy_triangulation(points: &[Point]) -> Vec<[u32; 3]> {
    assert_distinct(points);
    let p = |i: u32| points[i as usize];
    let mut kept: Vec<[u32; 2]> = Vec::new();
    for s in segments_by_perturbed_length(points) {
        if kept
            .iter()
            .all(|t| !properly_cross(p(s[0]), p(s[1]), p(t[0]), p(t[1])))
        {
            kept.push(s);
        }
    }
    kept.sort_unstable();
    faces_of(points, &kept)
}
