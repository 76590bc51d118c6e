//! Relative neighbourhood graph (Toussaint 1980; Edelsbrunner & Tan, *A
//! quadratic time algorithm for the minmax length triangulation*, 1993, §2),
//! from the Delaunay triangulation.
//!
//! `pq` is an RNG edge iff its open lune `{x : max(|xp|, |xq|) < |pq|}`
//! contains no point. A point on the open segment `pq` lies in the lune, so
//! it blocks `pq`. RNG ⊆ every Delaunay completion, because a non-Delaunay
//! pair has a point strictly inside its diametral disc, and a Delaunay pair
//! crossed by a cocircular edge `rs` has an angle `prq` or `psq` of at least
//! 90°; either point lies in the lune.
//!
//! Testing only the Delaunay neighbours of `p` and `q` is *wrong*: a point
//! of the lune need not be adjacent to either. Instead we use the
//! greedy-routing lemma:
//! in a Delaunay triangulation every vertex `r ≠ p` has a neighbour strictly
//! closer to `p`. So from any point `x` of the *closed* disc `D(p, |pq|)`
//! there is a Delaunay path to `p` along vertices strictly closer to `p` than
//! `x`, all inside the *open* disc: a search from `p` that expands only
//! vertices of the open disc meets every point of the closed disc, hence
//! every candidate of the lune ([`empty_lune_edges`]).
//!
//! The same search serves two tie rules ([`LuneBoundary`]): the open lune
//! (the RNG of the input `S`) and the lune of the kernel's Euclidean length
//! order on its symbolic perturbation `S′` (`rng(S′)`, which the
//! minmax-length triangulation cuts its regions along). A perturbed lune
//! differs from the open one only in points on its boundary circles, all of
//! which lie in the closed disc, so the search covers them too.

use crate::error::Result;
use crate::kernel::{compare_lengths, EuclideanOrder, LengthOrder, Point};
use crate::parallel::prelude::*;
use crate::spatial::morton_order;
use crate::structures::DelaunayGraph;
use crate::structures::PointSet;
use std::cmp::Ordering::{Equal, Greater, Less};

/// Vertices per rayon task in the per-vertex lune searches: a search costs
/// O(1) comparisons on typical data, so tasks must be large for rayon's
/// overhead not to dominate.
const VERTICES_PER_TASK: usize = 4096;

/// How a lune search decides the points on the lune's boundary: at distance
/// exactly `|pq|` from `p` or `q` (and no farther from the other one).
#[derive(Clone, Copy, PartialEq, Eq)]
enum LuneBoundary {
    /// Outside: the open lune, the RNG of the input `S`.
    Open,
    /// As the kernel's Euclidean length order on `S′` decides
    /// ([`LengthOrder::in_lune`]): `rng(S′)`, which depends on the numbering
    /// of the points.
    Perturbed,
}

/// A vertex adjacency in CSR form (the layout of [`DelaunayGraph`]): the
/// neighbours of `v` are `targets[offsets[v]..offsets[v + 1]]`, and an index
/// into `targets` is an adjacency *slot*.
#[derive(Clone, Copy)]
struct Adjacency<'a> {
    offsets: &'a [u32],
    targets: &'a [u32],
}

impl<'a> Adjacency<'a> {
    /// The adjacency of a Delaunay graph.
    fn of(g: &'a DelaunayGraph) -> Self {
        Self {
            offsets: &g.offsets,
            targets: &g.adjacency,
        }
    }

    #[inline]
    fn neighbors(self, v: u32) -> &'a [u32] {
        &self.targets[self.offsets[v as usize] as usize..self.offsets[v as usize + 1] as usize]
    }
}

/// Does some point lie in the lune of the Delaunay edge `pq`, with
/// `boundary` deciding its boundary? `inside` is scratch space (the expanded
/// vertices).
#[inline]
fn lune_is_occupied(
    points: &[Point],
    graph: Adjacency,
    boundary: LuneBoundary,
    [p, q]: [u32; 2],
    inside: &mut Vec<u32>,
) -> bool {
    let (pp, pq) = (points[p as usize], points[q as usize]);
    // The disc holds O(1) points on typical data, so a short list of the
    // expanded vertices beats an n-sized "seen" array.
    inside.clear();
    inside.push(p);
    let mut next = 0;
    while next < inside.len() {
        let w = inside[next];
        next += 1;
        for &x in graph.neighbors(w) {
            // q is a lune corner, not a candidate, and no search path needs
            // it; testing it would be an exact tie that always takes the slow
            // path of the predicate.
            if x == q {
                continue;
            }
            let px = points[x as usize];
            let to_p = compare_lengths(px, pp, pp, pq);
            let open = boundary == LuneBoundary::Open;
            if to_p == Greater || (to_p == Equal && open) || inside.contains(&x) {
                continue; // outside the (open) disc around p, or already expanded
            }
            let occupied = match (to_p, compare_lengths(px, pq, pp, pq)) {
                (Less, Less) => true,
                (_, Greater) => false,
                _ => !open && EuclideanOrder.in_lune(points, p, q, x),
            };
            if occupied {
                return true;
            }
            // Only points of the open disc are expanded (see the module
            // docs); a point on the circle may be tested twice, harmlessly.
            if to_p == Less {
                inside.push(x);
            }
        }
    }
    false
}

/// The Delaunay edges whose lune (with `boundary` deciding its boundary) is empty,
/// each as `keep(p, q, slot)`, where `slot` is the adjacency slot of `q` in
/// `p`'s list. Each edge is searched once, from its endpoint of lower degree;
/// vertices are visited in index order, so that the searches of consecutive
/// vertices share cache lines when the numbering is spatially coherent.
fn empty_lune_edges<T: Send>(
    points: &[Point],
    graph: Adjacency,
    boundary: LuneBoundary,
    keep: impl Fn(u32, u32, u32) -> T + Sync + Send,
) -> Vec<T> {
    (0..points.len() as u32)
        .into_par_iter()
        .with_min_len(VERTICES_PER_TASK)
        .fold(
            || (Vec::new(), Vec::new()),
            |(mut kept, mut inside), p| {
                let dp = graph.neighbors(p).len();
                let first = graph.offsets[p as usize];
                for (i, &q) in graph.neighbors(p).iter().enumerate() {
                    if (dp, p) < (graph.neighbors(q).len(), q)
                        && !lune_is_occupied(points, graph, boundary, [p, q], &mut inside)
                    {
                        kept.push(keep(p, q, first + i as u32));
                    }
                }
                (kept, inside)
            },
        )
        .map(|(kept, _)| kept)
        .reduce(Vec::new, |mut a, mut b| {
            a.append(&mut b);
            a
        })
}

/// RNG edges as distinct-index pairs, from a Delaunay graph.
///
/// The graph is first renumbered along a Z-order curve, so that points close
/// in the plane are close in memory: the lune searches are memory-bound, and
/// input order scatters neighbours across the whole point array.
pub(crate) fn rng_from_delaunay(points: &[Point], g: &DelaunayGraph) -> Vec<[u32; 2]> {
    // `original[local]` is the index in the caller's numbering.
    let original = morton_order(points);
    let mut local = vec![0u32; points.len()];
    for (l, &o) in original.iter().enumerate() {
        local[o as usize] = l as u32;
    }
    let mut offsets = Vec::with_capacity(points.len() + 1);
    let mut targets = Vec::with_capacity(g.adjacency.len());
    offsets.push(0);
    for &o in &original {
        targets.extend(g.neighbors(o).iter().map(|&x| local[x as usize]));
        offsets.push(targets.len() as u32);
    }
    let local_points: Vec<Point> = original.iter().map(|&o| points[o as usize]).collect();
    let graph = Adjacency {
        offsets: &offsets,
        targets: &targets,
    };
    empty_lune_edges(&local_points, graph, LuneBoundary::Open, |p, q, _| {
        [original[p as usize], original[q as usize]]
    })
}

/// The edges of `rng(S′)`, the RNG of the kernel's symbolic perturbation
/// `S′` of `points` (which depends on their numbering), each as
/// `keep(p, q, slot)` with `slot` the adjacency slot of `q` in `p`'s list of
/// `g`. They are Delaunay edges of `S` (`rng(S′) ⊆ rng(S)`), so the search is
/// [`rng_from_delaunay`]'s with the perturbation deciding the lunes'
/// boundaries. No renumbering: the caller's numbering defines `S′`.
pub(crate) fn perturbed_rng_from_delaunay<T: Send>(
    points: &[Point],
    g: &DelaunayGraph,
    keep: impl Fn(u32, u32, u32) -> T + Sync + Send,
) -> Vec<T> {
    empty_lune_edges(points, Adjacency::of(g), LuneBoundary::Perturbed, keep)
}

/// The relative neighbourhood graph: edges as sorted `[min, max]` input-index pairs.
///
/// Runs in O(n log n) for the Delaunay triangulation plus, per Delaunay edge,
/// a search over the points of one disc (O(1) on typical data, O(n) worst case).
pub fn relative_neighborhood_graph(points: &PointSet) -> Result<Vec<[u32; 2]>> {
    let g = DelaunayGraph::new(points.points())?;
    let e = rng_from_delaunay(points.points(), &g);
    Ok(points.to_input_edges(e.into_iter()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::{in_lune, in_lune_symbolic};
    use rand::{rngs::StdRng, Rng, SeedableRng};

    /// Seed of the degenerate grids below.
    const GRID_SEED: u64 = 11;

    /// Random points on a small integer grid (many ties), sorted and distinct.
    fn grid_points(rng: &mut StdRng, n: usize, width: u32) -> Vec<Point> {
        let mut pts: Vec<Point> = (0..n)
            .map(|_| {
                [
                    rng.gen_range(0..width) as f64,
                    rng.gen_range(0..width) as f64,
                ]
            })
            .collect();
        pts.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
        pts.dedup();
        pts
    }

    /// Both tie rules of the Delaunay search equal their brute-force
    /// definitions (no point in the open lune; no perturbed point in the
    /// perturbed lune) on degenerate grids.
    #[test]
    fn lune_searches_match_brute_force() {
        let mut rng = StdRng::seed_from_u64(GRID_SEED);
        let mut differ = 0;
        for round in 0..200 {
            let pts = grid_points(&mut rng, 12, if round % 2 == 0 { 4 } else { 7 });
            let Ok(g) = DelaunayGraph::new(&pts) else {
                continue;
            };
            if pts.len() < 3 || g.triangles.is_empty() {
                continue;
            }
            let sorted = |mut e: Vec<[u32; 2]>| {
                for e in &mut e {
                    *e = [e[0].min(e[1]), e[0].max(e[1])];
                }
                e.sort_unstable();
                e
            };
            let n = pts.len() as u32;
            let brute = |empty: &dyn Fn(u32, u32) -> bool| {
                let mut want = Vec::new();
                for p in 0..n {
                    for q in p + 1..n {
                        if empty(p, q) {
                            want.push([p, q]);
                        }
                    }
                }
                want
            };
            let p = |v: u32| pts[v as usize];
            let open = sorted(rng_from_delaunay(&pts, &g));
            let open_want = brute(&|a, b| (0..n).all(|x| !in_lune(p(a), p(b), p(x))));
            assert_eq!(open, open_want, "open lune: {pts:?}");
            let symbolic = sorted(perturbed_rng_from_delaunay(&pts, &g, |p, q, _| [p, q]));
            let symbolic_want = brute(&|a, b| (0..n).all(|x| !in_lune_symbolic(&pts, a, b, x)));
            assert_eq!(symbolic, symbolic_want, "symbolic lune: {pts:?}");
            differ += usize::from(open != symbolic);
        }
        assert!(differ > 0, "the grids should have lune ties");
    }
}
