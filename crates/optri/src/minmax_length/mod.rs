//! Exact minmax edge-length triangulation (Edelsbrunner & Tan,
//! `000_5891e11f36dd26ad.txt`).
//!
//! # The algorithm (§3)
//! 1. Build the Delaunay triangulation, the relative neighbourhood graph and
//!    the convex hull ([`regions`]).
//! 2. Cut the hull into the polygonal regions of `ch ∪ rng`, cracks traversed
//!    on both sides ([`crate::planar_graph::PlanarGraph::bounded_faces`]).
//! 3. Triangulate every region independently (rayon) with a minmax-optimal
//!    polygon triangulation, and assemble.
//!
//! The Subgraph Theorem (§4) says some minmax triangulation contains `rng(S)`,
//! so optimal triangulations of the regions combine into an optimal one.
//!
//! # Degeneracy
//! §4–§6 assume no two equal lengths and no three collinear points. optri's
//! kernel defines one symbolic perturbation `S′` of the points
//! ([`crate::kernel::symbolic`], base-3 simulation of simplicity): every
//! orientation and length comparison is that of a real, infinitesimally
//! perturbed point set, so the decisions are mutually consistent.
//!
//! * The regions are cut by `ch(S) ∪ rng(S′)`. `rng(S′) ⊆ rng(S)` because a
//!   point strictly inside a lune in `S` stays inside after an infinitesimal
//!   perturbation (§5.4); the extra edges of `rng(S)` are removed by an exact
//!   test of the few points on the lune boundary ([`rng_perturbed`]). The graph
//!   is a subgraph of `ch(S) ∪ rng(S)`, which is plane *exactly* (both are in
//!   every Delaunay completion), so the regions are computed without
//!   perturbation.
//! * Why that decomposition is safe: by the Subgraph Theorem for `S′` there is
//!   a minmax triangulation `t(S′) ⊇ rng(S′) ∪ ch(S′)`; §5.4 turns it into a
//!   minmax triangulation of `S` by replacing flat triangles, and that repair
//!   keeps every edge whose open segment contains no point — in particular
//!   all of `rng(S′)` and all (collinear-split) hull edges of `S`. Hence some
//!   minmax triangulation of `S` contains `ch(S) ∪ rng(S′)`, and triangulating
//!   each region optimally (for the *unperturbed* points) is optimal.
//! * Within a region, [`polygon::Region::minmax_triangulation_cubic`] is
//!   exact on the unperturbed points directly (it needs no general position).
//!
//! # Functions and the paper
//! | function | paper |
//! |---|---|
//! | [`minmax_length`] | §3 global algorithm |
//! | [`regions`], [`rng_perturbed`] | §3 steps 1–2, §5.4 (perturbed RNG) |
//! | [`polygon::Region::minmax_triangulation_cubic`] | §3 dynamic program (Klincsek) |

pub(crate) mod polygon;

use crate::convex_hull::hull_distinct;
use crate::criterion::{timed, Phase};
use crate::delaunay::{delaunay_graph, DelaunayGraph};
use crate::error::Result;
use crate::kernel::{compare_lengths, in_lune_symbolic, Point};
use crate::planar_graph::PlanarGraph;
use crate::point_set::PointSet;
use crate::relative_neighborhood_graph::rng_from_delaunay;
use crate::triangulation::Triangulation;
use polygon::Region;
use rayon::prelude::*;
use std::cmp::Ordering::Greater;

/// Is some perturbed point inside the perturbed lune of the `rng(S)` edge
/// `pq`? Such a point lies in the *closed* disc `D(p, |pq|)`; by the
/// greedy-routing lemma (every vertex `r ≠ p` has a Delaunay neighbour
/// strictly closer to `p`, `shared/notes/literature.md` §a) the closed disc's
/// points with `p` induce a connected Delaunay subgraph, searched from `p`.
fn perturbed_lune_is_occupied(
    points: &[Point],
    g: &DelaunayGraph,
    p: u32,
    q: u32,
    seen: &mut Vec<u32>,
    stamp: u32,
    stack: &mut Vec<u32>,
) -> bool {
    let (pp, pq) = (points[p as usize], points[q as usize]);
    stack.clear();
    stack.push(p);
    seen[p as usize] = stamp;
    while let Some(w) = stack.pop() {
        for &x in g.neighbors(w) {
            if seen[x as usize] == stamp {
                continue;
            }
            seen[x as usize] = stamp;
            if compare_lengths(points[x as usize], pp, pp, pq) == Greater {
                continue;
            }
            if x != q && in_lune_symbolic(points, p, q, x) {
                return true;
            }
            stack.push(x);
        }
    }
    false
}

/// `rng(S′)` for the kernel's symbolic perturbation `S′`: the edges of
/// `rng(S)` whose perturbed lune is empty (§5.4: `rng(S′) ⊆ rng(S)`).
pub(crate) fn rng_perturbed(points: &[Point], g: &DelaunayGraph) -> Vec<[u32; 2]> {
    let rng = rng_from_delaunay(points, g);
    let n = points.len();
    rng.into_par_iter()
        .map_init(
            || (vec![0u32; n], 0u32, Vec::new()),
            |(seen, stamp, stack), [u, v]| {
                *stamp += 1;
                (!perturbed_lune_is_occupied(points, g, u, v, seen, *stamp, stack))
                    .then_some([u, v])
            },
        )
        .flatten()
        .collect()
}

/// §3 steps 1–2: the polygonal regions of `ch(S) ∪ rng(S′)` as
/// counter-clockwise position cycles (cracks repeated).
pub(crate) fn regions(points: &[Point], rng: Vec<[u32; 2]>) -> Vec<Vec<u32>> {
    let mut edges = rng;
    let hull = hull_distinct(points);
    for i in 0..hull.len() {
        edges.push([hull[i], hull[(i + 1) % hull.len()]]);
    }
    for e in &mut edges {
        *e = [e[0].min(e[1]), e[0].max(e[1])];
    }
    edges.sort_unstable();
    edges.dedup();
    let graph = PlanarGraph::new(points, &edges);
    graph
        .bounded_faces(points)
        .into_iter()
        .map(|f| f.vertices)
        .collect()
}

/// Which polygon algorithm triangulates the regions.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum PolygonMethod {
    /// §3's cubic dynamic program.
    Cubic,
}

fn run(points: &PointSet, method: PolygonMethod, phases: &mut Vec<Phase>) -> Result<Triangulation> {
    let pts = points.points();
    let g = timed(phases, "delaunay", || delaunay_graph(pts))?;
    let rng = timed(phases, "rng", || rng_perturbed(pts, &g));
    let regions = timed(phases, "regions", || regions(pts, rng));
    let triangles: Vec<[u32; 3]> = timed(phases, "polygons", || {
        regions
            .par_iter()
            .flat_map_iter(|vertices| {
                let region = Region {
                    points: pts,
                    vertices,
                    symbolic: false,
                };
                match method {
                    PolygonMethod::Cubic => region.minmax_triangulation_cubic(),
                }
            })
            .collect()
    });
    Ok(Triangulation::from_distinct(points, triangles))
}

/// A triangulation of `points` whose longest edge is as short as possible.
///
/// Exact for every input, degenerate ones included (see the module docs).
///
/// # Errors
/// Propagates failures of the Delaunay construction.
pub fn minmax_length(points: &PointSet) -> Result<Triangulation> {
    run(points, PolygonMethod::Cubic, &mut Vec::new())
}

/// [`minmax_length`] with phase timings, and the algorithm's name.
pub(crate) fn minmax_length_timed(
    points: &PointSet,
    phases: &mut Vec<Phase>,
) -> Result<(Triangulation, String)> {
    let t = run(points, PolygonMethod::Cubic, phases)?;
    Ok((t, ALGORITHM.to_string()))
}

/// The method's name, as reported by [`crate::triangulate`].
const ALGORITHM: &str =
    "Edelsbrunner–Tan: hull ∪ RNG(perturbed) decomposition, cubic DP per region";

/// Test reference, not the product: §3's straightforward method, the cubic
/// dynamic program on every region of `ch(S) ∪ rng(S′)`, exact comparisons.
#[doc(hidden)]
pub fn minmax_length_cubic(points: &PointSet) -> Result<Triangulation> {
    run(points, PolygonMethod::Cubic, &mut Vec::new())
}
