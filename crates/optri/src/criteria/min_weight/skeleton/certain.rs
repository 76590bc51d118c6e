//! The certain edges of the LMT-skeleton (module docs of `skeleton`): the
//! edges left by the loop that no other edge left crosses, by the local
//! test of [`certain_edges`]; and, for the faces with holes, the crossing
//! lists of the edges left.

use super::Skeleton;
use crate::kernel::{compare_angles, dot_sign, orient_sign, segments_intersect, Point};
use crate::parallel::prelude::*;
use crate::spatial::{bounding_box, SparseGrid};
use crate::structures::Csr;
use std::sync::atomic::{AtomicBool, Ordering::SeqCst};

/// The certain edges: those left by the loop that are hull edges or that no
/// other edge left crosses, by a local test.
///
/// **Lemma.** After the loop, an edge `pq` left (not a hull edge) is crossed
/// by another edge left iff a kept triangle with corner `p` has the
/// direction `p → q` strictly inside its angle at `p`. *Proof.* If such a
/// triangle `pab` exists, `q` is not in it (it is empty), so `pq` leaves it
/// through the inside of `ab`, an edge left. Conversely, let `rs` (left)
/// cross `pq` at `X`; `rs` is no hull edge, and no edge left has a point
/// inside it (its closed triangles would all hold the point, so it would
/// have no valid pair). Every edge left that is not a hull edge has a
/// kept triangle on each side (its locally minimal pair). Walk along `pq`
/// from `X` towards `p`: start in a kept triangle of `rs` on `p`'s side;
/// the walk leaves each triangle through the inside of another side (not
/// through a corner: none lies on `pq`), an edge left, into a kept triangle
/// on that side's other side, always closer to `p`, until a triangle has
/// `p` as a corner — with `p → q` strictly inside its angle at `p`. ∎
///
/// So the test reads, per vertex, its edges left in angular order and its
/// kept triangles; debug builds check that both endpoints of every edge
/// agree, as the lemma says they must.
pub(super) fn certain_edges(pts: &[Point], sk: &Skeleton) -> Vec<bool> {
    let n = pts.len();
    let m = sk.edges.len();
    // Kept triangles per corner (CSR).
    let at = Csr::from_pairs(
        n,
        sk.triangles
            .iter()
            .enumerate()
            .flat_map(|(t, (corners, _))| corners.map(|c| (c, t as u32))),
    );
    // Per endpoint (smaller, larger): is the edge inside a kept triangle's
    // angle there?
    let flags = || -> Vec<AtomicBool> { (0..m).map(|_| AtomicBool::new(false)).collect() };
    let (from_smaller, from_larger) = (flags(), flags());
    (0..n).into_par_iter().with_min_len(256).for_each(|p| {
        let a = pts[p];
        let mut around: Vec<(u32, u32)> = sk
            .neighbours(p as u32)
            .iter()
            .copied()
            .filter(|&(_, e)| sk.alive[e as usize])
            .collect();
        around.sort_unstable_by(|x, y| compare_angles(a, pts[x.0 as usize], pts[y.0 as usize]));
        let d = around.len();
        // Angular positions by neighbour, and the triangles' open angular
        // ranges as a difference array: O(log d + 1) a triangle, where a
        // scan of `around` and a walk over the range cost O(d) (points in
        // nearly convex position: Θ(n) neighbours and Θ(n²) triangles a
        // vertex).
        let mut by_neighbour: Vec<(u32, u32)> = around
            .iter()
            .enumerate()
            .map(|(i, &(w, _))| (w, i as u32))
            .collect();
        by_neighbour.sort_unstable();
        let position = |w: u32| {
            let i = by_neighbour
                .binary_search_by(|x| x.0.cmp(&w))
                .expect("a kept triangle's sides are edges left");
            by_neighbour[i].1 as usize
        };
        let mut starts = vec![0i32; d + 1];
        for &t in at.row(p as u32) {
            let c = sk.triangles[t as usize].0;
            let k = c.iter().position(|&x| x as usize == p).unwrap_or(0);
            // Counter-clockwise corners p, b, c: the angle at p runs
            // counter-clockwise from p → b to p → c (below π); the
            // directions strictly inside are positions first + 1 .. last,
            // cyclically.
            let (first, last) = (position(c[(k + 1) % 3]), position(c[(k + 2) % 3]));
            let from = (first + 1) % d;
            starts[from] += 1;
            starts[last] -= 1;
            if from > last {
                starts[0] += 1; // wraps around
            }
        }
        let mut depth = 0;
        let inside: Vec<bool> = starts[..d]
            .iter()
            .map(|&s| {
                depth += s;
                depth > 0
            })
            .collect();
        for (&(w, e), &crossed) in around.iter().zip(&inside) {
            if crossed {
                let flag = if (p as u32) < w {
                    &from_smaller
                } else {
                    &from_larger
                };
                flag[e as usize].store(true, SeqCst);
            }
        }
    });
    (0..m)
        .map(|e| {
            let (s, l) = (from_smaller[e].load(SeqCst), from_larger[e].load(SeqCst));
            debug_assert!(
                !sk.alive[e] || sk.hull[e] || s == l,
                "the crossing lemma: both endpoints of edge {e} must agree"
            );
            sk.alive[e] && (sk.hull[e] || !s)
        })
        .collect()
}

/// The candidate edges each edge left by the loop intersects, among the
/// edges left, each list sorted; for the faces with holes only, so
/// computed on first use.
pub(super) fn crossing_lists(pts: &[Point], skeleton: &Skeleton) -> Csr<u32> {
    let m = skeleton.edges.len();
    // Edges in length classes of powers of two, each class in a
    // grid of its midpoints; an edge of class k (length < 2^(k+1)·base)
    // meeting segment e has its midpoint within 2^k·base of e.
    let length = |e: &[u32; 2]| {
        let (a, b) = (pts[e[0] as usize], pts[e[1] as usize]);
        (a[0] - b[0]).hypot(a[1] - b[1])
    };
    let alive_ids: Vec<u32> = (0..m as u32)
        .filter(|&e| skeleton.alive[e as usize])
        .collect();
    // Any positive base is correct (shorter edges join class 0, whose reach
    // still covers their half-length); a quarter of the median length keeps
    // the finest grid from being far finer than the typical edge.
    let mut lengths: Vec<f64> = alive_ids
        .iter()
        .map(|&e| length(&skeleton.edges[e as usize]))
        .collect();
    let base = if lengths.is_empty() {
        f64::MIN_POSITIVE
    } else {
        let middle = lengths.len() / 2;
        let (_, median, _) = lengths.select_nth_unstable_by(middle, f64::total_cmp);
        (0.25 * *median).max(f64::MIN_POSITIVE)
    };
    drop(lengths);
    let class_of = |e: &[u32; 2]| ((length(e) / base).log2().floor().max(0.0)) as usize;
    let classes = alive_ids
        .iter()
        .map(|&e| class_of(&skeleton.edges[e as usize]))
        .max()
        .unwrap_or(0)
        + 1;
    let mut members: Vec<Vec<u32>> = vec![Vec::new(); classes];
    for &id in &alive_ids {
        members[class_of(&skeleton.edges[id as usize])].push(id);
    }
    let mid = |id: u32| {
        let e = skeleton.edges[id as usize];
        let (a, b) = (pts[e[0] as usize], pts[e[1] as usize]);
        [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]
    };
    let bbox = bounding_box(pts);
    // A crossing pair is looked for from its edge of the larger class, in
    // the grid of the other's class (whose reach covers it), or from the
    // smaller id within a class: each edge queries the grids of its own and
    // the shorter classes only, not the sparse grids of the few long edges
    // (2·10⁵ uniform points have 11 classes, and every query of a grid has
    // its cost, whatever the grid holds).
    let grids: Vec<(usize, f64, SparseGrid<u32>)> = members
        .par_iter()
        .enumerate()
        .filter(|(_, list)| !list.is_empty())
        .map(|(k, list)| {
            let reach = 2f64.powi(k as i32) * base * 1.0000001;
            let grid = SparseGrid::new(
                bbox,
                2.0 * reach,
                list.len(),
                |i| mid(list[i]),
                |i| list[i],
                |i| list[i],
            );
            (k, reach, grid)
        })
        .collect();
    let sk = &skeleton;
    // Per surviving edge only (a list header for every filter candidate
    // cost 24 bytes each, about a third of them survive).
    let crossings: Vec<Vec<u32>> = alive_ids
        .par_iter()
        .with_min_len(256)
        .map(|&e| {
            let ends = sk.edges[e as usize];
            let (a, b) = (pts[ends[0] as usize], pts[ends[1] as usize]);
            let own = class_of(&ends);
            // Each conflicting pair once; the lists are mirrored below.
            let mut out = Vec::new();
            for (k, reach, g) in grids.iter().take_while(|(k, _, _)| *k <= own) {
                g.any_cell_near(a, b, *reach, |items| {
                    for &f in items {
                        if (*k < own || f > e) && edges_conflict(pts, ends, sk.edges[f as usize]) {
                            out.push(f);
                        }
                    }
                    false
                });
            }
            out.sort_unstable();
            out.dedup();
            out
        })
        .collect();
    // Each pair was found from one end: recorded at both, then each list
    // sorted.
    let mut lists = Csr::from_pairs(
        m,
        alive_ids
            .iter()
            .zip(&crossings)
            .flat_map(|(&e, list)| list.iter().flat_map(move |&f| [(e, f), (f, e)])),
    );
    drop(crossings);
    lists.sort_rows();
    lists
}

/// Do the candidate edges `e = [a, b]` and `f` intersect other than in a
/// shared endpoint (collinear overlap at a shared endpoint counts)?
fn edges_conflict(pts: &[Point], e: [u32; 2], f: [u32; 2]) -> bool {
    let p = |i: u32| pts[i as usize];
    let ([a, b], [c, d]) = ([p(e[0]), p(e[1])], [p(f[0]), p(f[1])]);
    // Disjoint bounding boxes (exact coordinate comparisons): no contact.
    for k in 0..2 {
        if a[k].max(b[k]) < c[k].min(d[k]) || c[k].max(d[k]) < a[k].min(b[k]) {
            return false;
        }
    }
    let shared = e.iter().find(|&&x| f.contains(&x)).copied();
    match shared {
        None => segments_intersect(a, b, c, d),
        Some(s) => {
            let u = if e[0] == s { e[1] } else { e[0] };
            let v = if f[0] == s { f[1] } else { f[0] };
            u != v && orient_sign(p(s), p(u), p(v)) == 0 && dot_sign(p(s), p(u), p(v)) > 0
        }
    }
}
