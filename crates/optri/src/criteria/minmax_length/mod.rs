//! Exact minmax edge-length triangulation (Edelsbrunner & Tan,
//! `000_5891e11f36dd26ad.txt`): a triangulation whose longest edge is as
//! short as possible, in O(n²) time (O(n log n) plus O(k²) per region).
//!
//! # The algorithm (§3)
//! 0. Renumber the points along a Z-order curve (cache locality for every
//!    later phase; the perturbation `S′` below is defined on this numbering).
//! 1. Build the Delaunay triangulation, the relative neighbourhood graph
//!    (`rng_perturbed`) and the convex hull.
//! 2. Cut the hull into the polygonal regions of `ch ∪ rng` (`regions`):
//!    the classes of Delaunay triangles joined across sides outside the
//!    graph, each with its boundary walk (cracks traversed on both sides);
//!    the planar-graph face walk
//!    ([`crate::structures::PlanarGraph::bounded_faces`]) is the test
//!    reference for it.
//! 3. Triangulate every region independently (rayon), assemble, and undo
//!    the perturbation (§5.4, `repair_flat_triangles`).
//!
//! Before steps 2–3, the Length Lemma of §4 gives a lower bound on the
//! optimum: the longest edge of `ch(S) ∪ rng(S′)` (`length_lemma_bound`).
//! If no Delaunay edge is longer — first tried with the hull edges alone,
//! before the RNG is built — the Delaunay triangulation is optimal and is
//! returned; otherwise every region whose Delaunay triangles are no longer
//! keeps them, and only the others run the polygon algorithms. On uniform
//! points and on most TSPLIB files the Delaunay triangulation is certified
//! outright (their hulls have long edges); with the boundary sampled as
//! finely as the interior, all but a fraction of a percent of the regions
//! are certified (figures in BENCHMARKS.md). Tests run the polygon
//! algorithms on every region too ([`minmax_length_with`]).
//!
//! The Subgraph Theorem (§4) says some minmax triangulation contains the RNG,
//! so optimal triangulations of the regions combine into an optimal one.
//! A region is triangulated by
//! * §5.1 if it is an *incomplete* rng-polygon (one hull edge outside the
//!   RNG): `fast::FastRegion::incomplete`;
//! * §5.3 + §6 if it is *complete*: classify all diagonals with the per-corner
//!   stack scan, find `p′, p″, q′, q″`, take the shortest 2-edge passing the
//!   Crossing-Lemma test and triangulate both sides
//!   (`fast::FastRegion::shortest_expandable_2_edge`,
//!   `fast::FastRegion::triangulate_side`);
//! * regions with fewer than [`SMALL_REGION`] corners (most regions of
//!   typical inputs) are solved by the exact cubic program instead, which is
//!   cheaper there, restricted to chords no longer than the longest Delaunay
//!   diagonal inside the region (the Delaunay triangles are a feasible
//!   triangulation, so the optimum uses no longer chord); tests run the
//!   quadratic algorithm on every region too ([`minmax_length_with`]).
//!   Before that, a lower bound (`polygon::Region::apex_lower_bound`: every
//!   boundary edge needs an apex) often certifies the region's Delaunay
//!   triangles as optimal already — 57% of the small regions of 10⁶
//!   uniform points — and the program is skipped.
//!
//! # Degeneracy
//! §4–§6 assume no two equal lengths and no three collinear points. optri's
//! kernel defines one symbolic perturbation `S′` of the points
//! ([`crate::kernel::symbolic`], base-3 simulation of simplicity): every
//! orientation and length comparison is that of one real, infinitesimally
//! perturbed point set, so all decisions are mutually consistent. The
//! point-to-segment distance of §5.1 is compared by `fast::height_sign`,
//! which expands the same perturbation.
//!
//! * The regions are cut by `ch(S) ∪ rng(S′)`. `rng(S′) ⊆ rng(S)`, because a
//!   point strictly inside a lune of `S` stays inside after an infinitesimal
//!   perturbation (§5.4), so it is found among the Delaunay edges. The graph is
//!   a subgraph of `ch(S) ∪ rng(S)`, which is plane *exactly* (both lie in every
//!   Delaunay completion), so the regions are computed without perturbation;
//!   a hull edge of `S` outside `rng(S′)` is a 1-edge of `S′` with the region
//!   beyond it (nothing lies outside the hull, and collinear hull points past
//!   its endpoints are outside its closed lune), which is what §5.1 needs.
//! * The decomposition loses nothing: by the Subgraph Theorem for `S′` there
//!   is a minmax triangulation `t(S′) ⊇ rng(S′)`; §5.4 turns it into a minmax
//!   triangulation of `S`, and that repair keeps every edge whose open segment
//!   contains no point — all of `rng(S′)` and every hull edge of `S`.
//! * Each region is triangulated optimally *for `S′`*. Any triangulation of
//!   `S` containing `ch(S) ∪ rng(S′)` is also one of `S′` (its triangles are
//!   not flat, so keep their orientation), and `|ab| < |cd|` in `S′` implies
//!   `|ab| ≤ |cd|` in `S`; so the result's longest edge is at most the optimum
//!   of `S`. §5.4's repair then replaces flat triangles (corners collinear in
//!   `S`) by fans, which by the Δ-Lemma creates no longer edge, and yields a
//!   valid triangulation of the unperturbed points — so the longest edge is
//!   exactly optimal.
//! * The cubic program (`polygon::Region::minmax_triangulation_cubic`) runs
//!   either exactly on `S` (small regions, and the test reference
//!   [`minmax_length_cubic`]) — it needs no general position — or, only as
//!   a counted safety net inside §6 Case 2 (below), on `S′`.
//!
//! # §6 Case 2
//! Case 2 (the partners `pp′` and `qq″` cross) follows the paper's three
//! steps: §5.1 beyond `qq″` (or the mirror image), the convex hull `C` of the
//! vertices inside triangle `pqq″` together with `p, q″`, fanned from `q`,
//! and for each pocket `Y_uv` behind an edge `uv` of `C`: step 3.1 finds
//! `u_L` (`v` itself if `uv` is a 1-edge with `pq` beneath, else the nearest
//! vertex past `v` meeting Claim 2's conditions), 3.2 keeps the triangles of
//! §5.1 beyond `uu_L` that lie in the pocket, and 3.3 fans the rest out from
//! `v` (§5.2). Each pocket's result is checked (triangle count, orientation,
//! every new edge shorter than `|pq|`, as Claims 1–5 promise); a pocket
//! failing the check would go to the cubic program on `S′`, counted in
//! [`CASE_2_POCKET_FALLBACKS`] and [`FALLBACKS`] — zero in all tests. On
//! 2·10⁵ uniform points: 10 913 Case 2 regions, 5 983 pockets with
//! `u_L = v`, 294 with the `u_L` search and the fan-out. Should the hull
//! chain fail its boundary-order check, the whole remainder goes to the
//! cubic program (counted in [`CASE_2_HULL_FALLBACKS`]; zero in all tests).
//!
//! # Functions and the paper
//! | function | paper |
//! |---|---|
//! | [`minmax_length`] | §3 global algorithm, Subgraph Theorem (§4) |
//! | `length_lemma_bound` | §4 Length Lemma (a lower bound certifying Delaunay regions) |
//! | `rng_perturbed_flags`, `regions::Regions` | §3 steps 1–2, §5.4 (`rng(S′) ⊆ rng(S)`) |
//! | `fast::FastRegion::incomplete` | §5.1, 1-Edge Lemma, Visibility Lemma |
//! | `fast::FastRegion::visible` | §6 step 1 (diagonals in angular order) |
//! | `fast::FastRegion::shortest_expandable_2_edge` | §6 steps 1–3, Containment and Crossing Lemmas |
//! | `fast::FastRegion::triangulate_side` | §5.3 step 2, §6 Cases 1–2, Expandability Lemma |
//! | `fast::FastRegion::hull_fan` | §6 Case 2 step 2, Claim 1 |
//! | `fast::FastRegion::pocket` | §6 Case 2 steps 3.1–3.2, Claims 2–5 |
//! | `fast::FastRegion::fan_out` | §5.2 fan-out triangulation, Fan-Out Lemma |
//! | `polygon::Region::minmax_triangulation_cubic` | §3 dynamic program (Klincsek) |
//! | `small_region`, `polygon::Region::apex_lower_bound` | §3 (a lower-bound certificate that skips the program) |
//! | `repair_flat_triangles` | §5.4, Δ-Lemma |

pub(crate) mod fast;
pub(crate) mod polygon;
pub(crate) mod regions;

use super::{CriterionInfo, Diagnostics, Optimality, Options, Requirement, Solved};
use crate::error::Result;
use crate::graphs::perturbed_rng_from_delaunay;
use crate::kernel::{compare_lengths, orient_sign, Point};
use crate::parallel::prelude::*;
use crate::spatial::morton_order;
use crate::structures::{DelaunayGraph, PointSet, Triangulation};
use crate::timing::{timed, Phase};
use fast::{FastRegion, Mesh};
use polygon::{ChordLengths, Region};
use regions::{LocalMesh, Regions};
use std::cmp::Ordering::{Greater, Less};
use std::collections::HashMap;
use std::sync::atomic::{AtomicUsize, Ordering as AtomicOrdering};

pub(crate) const INFO: CriterionInfo = CriterionInfo {
    name: "minmax-length",
    description: "minimises the longest edge",
    optimality: Optimality::Exact,
    requirement: Requirement::AnyPointSet,
    options: &[],
    reference: "H. Edelsbrunner & T. S. Tan, A quadratic time algorithm for the minmax \
                length triangulation, FOCS 1991 / SIAM J. Comput. 1993",
};

pub(crate) fn solve(points: &PointSet, _: &Options, phases: &mut Vec<Phase>) -> Result<Solved> {
    let (triangulation, algorithm) = minmax_length_timed(points, phases)?;
    Ok(Solved {
        triangulation,
        algorithm,
        optimality: Optimality::Exact,
        diagnostics: Diagnostics::default(),
    })
}

/// `rng(S′)` for the kernel's symbolic perturbation `S′`: the Delaunay
/// edges whose perturbed lune is empty. Every edge of `rng(S′)` is in
/// `rng(S)` (§5.4), hence in every Delaunay completion of `S`, so testing the
/// Delaunay edges suffices; the lune search is the RNG's own, with the
/// perturbation deciding the lune's boundary.
#[cfg(test)]
pub(crate) fn rng_perturbed(points: &[Point], g: &DelaunayGraph) -> Vec<[u32; 2]> {
    perturbed_rng_from_delaunay(points, g, |p, q, _| [p, q])
}

/// [`rng_perturbed`] as a flag per Delaunay edge (indexed like
/// `g.edges`); `g` must come from [`DelaunayGraph::with_topology`].
pub(crate) fn rng_perturbed_flags(points: &[Point], g: &DelaunayGraph) -> Vec<bool> {
    let mut flags = vec![false; g.edges.len()];
    for slot in perturbed_rng_from_delaunay(points, g, |_, _, slot| slot) {
        flags[g.topology.slot_edges[slot as usize] as usize] = true;
    }
    flags
}

/// §3 steps 1–2 by the planar-graph face walk: the polygonal regions of
/// `ch(S) ∪ rng(S′)` as counter-clockwise position cycles (cracks
/// repeated). The product reads them off the Delaunay triangles instead
/// ([`regions::Regions`]); this is the independent test reference.
#[cfg(test)]
pub(crate) fn regions(points: &[Point], rng: &[[u32; 2]], hull: &[u32]) -> Vec<Vec<u32>> {
    let mut edges = rng.to_vec();
    for i in 0..hull.len() {
        edges.push([hull[i], hull[(i + 1) % hull.len()]]);
    }
    for e in &mut edges {
        *e = [e[0].min(e[1]), e[0].max(e[1])];
    }
    edges.sort_unstable();
    edges.dedup();
    let graph = crate::structures::PlanarGraph::new(points, &edges);
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
    #[cfg_attr(not(any(test, feature = "internals")), allow(dead_code))]
    Cubic,
    /// §5.1, §5.3 and §6 on the perturbed points, then §5.4's repair;
    /// regions with fewer than `cubic_below` corners use the exact cubic
    /// program instead (cheaper for tiny regions, equally optimal). With
    /// `certify`, regions whose Delaunay triangles are no longer than the
    /// Length Lemma's bound keep them (see [`length_lemma_bound`]).
    Quadratic { cubic_below: usize, certify: bool },
}

/// The product's method. Regions of up to 31 corners (nearly all regions of
/// typical inputs) are solved by the exact cubic program with the Delaunay
/// bound (quadrilaterals by one comparison), which measured faster there
/// than the quadratic algorithm (2·10⁵ uniform points, whole run: 1.04 s with
/// the quadratic algorithm from 12 corners, 0.85 s from 30); the quadratic
/// algorithm handles the larger ones.
const PRODUCT: PolygonMethod = PolygonMethod::Quadratic {
    cubic_below: SMALL_REGION,
    certify: true,
};

/// Regions with fewer corners than this use the cubic program in the product.
#[doc(hidden)]
pub const SMALL_REGION: usize = 32;

/// How often the quadratic algorithm met an inconsistency and fell back to
/// the cubic program for a region (a bug indicator; tests assert it stays 0).
#[doc(hidden)]
pub static FALLBACKS: AtomicUsize = AtomicUsize::new(0);

/// Diagnostics for tests and benchmarks: how often §6 Case 1 and Case 2
/// occurred, how their pockets were triangulated, the total size of Case 2
/// parts handed to the cubic safety net, how many flat triangles §5.4
/// removed, and the safety nets' use.
#[doc(hidden)]
pub static COUNTERS: [AtomicUsize; 11] = [const { AtomicUsize::new(0) }; 11];
/// Index into [`COUNTERS`].
#[doc(hidden)]
pub const CASE_1: usize = 0;
/// Index into [`COUNTERS`].
#[doc(hidden)]
pub const CASE_2: usize = 1;
/// Index into [`COUNTERS`].
#[doc(hidden)]
pub const CASE_2_REMAINDER_VERTICES: usize = 2;
/// Index into [`COUNTERS`].
#[doc(hidden)]
pub const FLAT_TRIANGLES: usize = 3;
/// Index into [`COUNTERS`]: §6 Case 2 hull constructions that failed a check
/// and were replaced by the cubic program on the whole remainder.
#[doc(hidden)]
pub const CASE_2_HULL_FALLBACKS: usize = 4;
/// Index into [`COUNTERS`]: §6 Case 2 pockets closed by a 1-edge with `pq`
/// beneath it, triangulated by §5.1 (step 3.1 with `u_L = v`).
#[doc(hidden)]
pub const CASE_2_POCKETS_BY_5_1: usize = 5;
/// Index into [`COUNTERS`]: §6 Case 2 pockets triangulated by steps 3.1–3.3
/// (a `u_L ≠ v`, §5.1 clipped to the pocket, the §5.2 fan-out).
#[doc(hidden)]
pub const CASE_2_POCKETS_BY_FAN_OUT: usize = 6;
/// Index into [`COUNTERS`]: §6 Case 2 pockets whose step-3 triangulation
/// failed a check and were handed to the cubic program on `S′` (also counted
/// in [`FALLBACKS`]; a bug indicator, asserted zero in tests).
#[doc(hidden)]
pub const CASE_2_POCKET_FALLBACKS: usize = 7;

/// Index into [`COUNTERS`]: small regions (fewer than [`SMALL_REGION`]
/// corners, more than four) handed to the cubic program.
#[doc(hidden)]
pub const SMALL_REGIONS_BY_DP: usize = 8;
/// Index into [`COUNTERS`]: small regions whose Delaunay triangles were
/// certified optimal by [`polygon::Region::apex_lower_bound`].
#[doc(hidden)]
pub const SMALL_REGIONS_CERTIFIED: usize = 9;
/// Index into [`COUNTERS`]: regions (or, counted once, whole inputs) whose
/// Delaunay triangles met the Length Lemma bound (`length_lemma_bound`).
#[doc(hidden)]
pub const REGIONS_CERTIFIED_BY_BOUND: usize = 10;

pub(crate) fn count(which: usize, by: usize) {
    COUNTERS[which].fetch_add(by, AtomicOrdering::Relaxed);
}

fn run(points: &PointSet, method: PolygonMethod, phases: &mut Vec<Phase>) -> Result<Triangulation> {
    // Renumber along a Z-order curve so that every phase (lune searches,
    // face walks, region flood fills) touches nearby memory. The symbolic
    // perturbation S′ depends on the numbering; any numbering gives one
    // consistent S′, which is all the argument above needs.
    let order = timed(phases, "z-order", || morton_order(points.points()));
    let local: Vec<Point> = order.iter().map(|&o| points.points()[o as usize]).collect();
    let pts = local.as_slice();
    let g = timed(phases, "delaunay", || DelaunayGraph::with_topology(pts))?;
    let certify = matches!(method, PolygonMethod::Quadratic { certify: true, .. });
    // The Delaunay triangulation is optimal outright if no edge of it is
    // longer than the hull's longest edge, a lower bound needing no RNG.
    let delaunay_meets = |bound: [Point; 2]| {
        let p = |v: u32| pts[v as usize];
        g.edges
            .par_iter()
            .all(|&([u, v], _)| compare_lengths(p(u), p(v), bound[0], bound[1]) != Greater)
    };
    let delaunay_result = || {
        count(REGIONS_CERTIFIED_BY_BOUND, 1);
        let mut t = g.triangles.clone();
        for c in t.iter_mut().flatten() {
            *c = order[*c as usize];
        }
        Ok(Triangulation::from_distinct(points, t))
    };
    if certify
        && timed(phases, "lower bound", || {
            delaunay_meets(length_lemma_bound(pts, &g, None))
        })
    {
        return delaunay_result();
    }
    let rng = timed(phases, "rng", || rng_perturbed_flags(pts, &g));
    let bound = if certify {
        let bound = timed(phases, "lower bound", || {
            length_lemma_bound(pts, &g, Some(&rng))
        });
        if delaunay_meets(bound) {
            return delaunay_result();
        }
        Some(bound)
    } else {
        None
    };
    let regions = timed(phases, "regions", || Regions::new(&g, &rng));
    let mesh = Mesh::new(&g, &rng);
    let triangles: Vec<[u32; 3]> = timed(phases, "polygons", || {
        (0..regions.len())
            .into_par_iter()
            .with_min_len(64)
            .flat_map_iter(|r| {
                if let [t] = regions.triangles(r) {
                    return vec![g.triangles[*t as usize]];
                }
                if let Some(bound) = bound {
                    let members = regions.triangles(r);
                    let e = longest_side(pts, &g, members.iter().copied())
                        .expect("a region has triangles");
                    let (a, b) = (pts[e[0] as usize], pts[e[1] as usize]);
                    if compare_lengths(a, b, bound[0], bound[1]) != Greater {
                        count(REGIONS_CERTIFIED_BY_BOUND, 1);
                        return members.iter().map(|&t| g.triangles[t as usize]).collect();
                    }
                }
                let boundary = regions.boundary(&g, &rng, r);

                let vertices = &boundary.corners[..];
                let region = Region {
                    points: pts,
                    vertices,
                    symbolic: false,
                };
                match method {
                    PolygonMethod::Quadratic { cubic_below, .. }
                        if vertices.len() >= cubic_below =>
                    {
                        match FastRegion::new(pts, vertices, &mesh).and_then(|f| f.triangulate()) {
                            Ok(t) => t,
                            Err(e) => {
                                if std::env::var_os("OPTRI_DEBUG").is_some() {
                                    eprintln!("fallback ({}) on {vertices:?}", e.0);
                                }
                                FALLBACKS.fetch_add(1, AtomicOrdering::Relaxed);
                                region.minmax_triangulation_cubic()
                            }
                        }
                    }
                    PolygonMethod::Quadratic { .. } => {
                        small_region(&region, || regions.local_mesh(&g, &rng, r))
                    }
                    PolygonMethod::Cubic => region.minmax_triangulation_cubic(),
                }
            })
            .collect()
    });
    let triangles = timed(phases, "repair", || {
        let mut t = repair_flat_triangles(pts, triangles);
        for c in t.iter_mut().flatten() {
            *c = order[*c as usize];
        }
        t
    });
    Ok(Triangulation::from_distinct(points, triangles))
}

/// The longest edge of `ch(S) ∪ rng(S′)` (of `ch(S)` alone without `rng`),
/// as its two endpoints: a lower bound on the optimum. Hull edges are in every triangulation, and by §4's
/// Length Lemma every triangulation of `S` has an edge at least as long as
/// the longest edge of `rng(S) ⊇ rng(S′)`. So a triangulation whose edges are
/// all no longer than this is optimal, and a region whose Delaunay triangles
/// are no longer than this may keep them: the assembled result's longest edge
/// is then the largest of this bound and the other regions' optima, each of
/// which is at most the global optimum. (Regions so kept are not necessarily
/// minmax triangulations *of the region*; the whole is optimal.)
fn length_lemma_bound(points: &[Point], g: &DelaunayGraph, rng: Option<&[bool]>) -> [Point; 2] {
    let p = |v: u32| points[v as usize];
    g.edges
        .par_iter()
        .enumerate()
        .filter(|(i, (_, apex))| apex.contains(&None) || rng.is_some_and(|r| r[*i]))
        .map(|(_, &([u, v], _))| [p(u), p(v)])
        .reduce_with(|x, y| {
            if compare_lengths(x[0], x[1], y[0], y[1]) == Less {
                y
            } else {
                x
            }
        })
        .expect("a triangulation has hull edges")
}

/// The longest side of the given Delaunay triangles (exact), as a vertex pair.
fn longest_side(
    points: &[Point],
    g: &DelaunayGraph,
    triangles: impl Iterator<Item = u32>,
) -> Option<[u32; 2]> {
    let p = |v: u32| points[v as usize];
    let longer = |x: [u32; 2], y: [u32; 2]| {
        if compare_lengths(p(x[0]), p(x[1]), p(y[0]), p(y[1])) == Less {
            y
        } else {
            x
        }
    };
    triangles
        .flat_map(|t| {
            let [a, b, c] = g.triangles[t as usize];
            [[a, b], [b, c], [c, a]]
        })
        .reduce(longer)
}

/// A region with fewer than [`SMALL_REGION`] corners. A quadrilateral takes
/// its shorter diagonal. Otherwise every triangulation has an edge at least
/// as long as the apex lower bound, so a triangulation of the region whose
/// diagonals are no longer is optimal: first the region's Delaunay
/// triangles, then the same after flipping its longest diagonal while that
/// shortens it. Failing both, the cubic program runs on chords no longer
/// than the flipped triangulation's longest diagonal (a feasible solution,
/// so the optimum uses no longer chord).
fn small_region(region: &Region, mesh: impl FnOnce() -> LocalMesh) -> Vec<[u32; 3]> {
    if let Some(t) = region.quadrilateral() {
        return t;
    }
    let lengths = ChordLengths::new(region);
    let [a, b] = region.apex_lower_bound(&lengths);
    let v = region.vertices;
    let lower = [v[a], v[b]];
    let mut mesh = mesh();
    let no_longer =
        |d: Option<[u32; 2]>| d.map_or(true, |d| region.compare_lengths(d, lower) != Greater);
    let upper = mesh.flip_longest_diagonals(region.points);
    if no_longer(upper) {
        count(SMALL_REGIONS_CERTIFIED, 1);
        return mesh.triangles;
    }
    count(SMALL_REGIONS_BY_DP, 1);
    region.minmax_triangulation_with(upper, &lengths)
}

/// A triangulation of `points` whose longest edge is as short as possible.
///
/// Exact for every input, degenerate ones included (see the module docs).
///
/// # Errors
/// Propagates failures of the Delaunay construction.
pub fn minmax_length(points: &PointSet) -> Result<Triangulation> {
    run(points, PRODUCT, &mut Vec::new())
}

/// [`minmax_length`] with phase timings, and the algorithm's name.
pub(crate) fn minmax_length_timed(
    points: &PointSet,
    phases: &mut Vec<Phase>,
) -> Result<(Triangulation, String)> {
    let t = run(points, PRODUCT, phases)?;
    let algorithm = if phases.iter().any(|p| p.name == "regions") {
        ALGORITHM.to_string()
    } else {
        format!("{ALGORITHM}; here the Delaunay triangulation met the Length-Lemma lower bound, so it is optimal")
    };
    Ok((t, algorithm))
}

/// The method's name, as reported by [`crate::triangulate`].
const ALGORITHM: &str = "Edelsbrunner–Tan O(n²): Length-Lemma lower bound (longest hull/RNG edge) certifies Delaunay regions; hull ∪ RNG(S′) regions; §5.1 incomplete and §5.3/§6 complete rng-polygons on the symbolic perturbation (exact cubic DP, pruned by the regions' Delaunay diagonals, for regions under 32 corners; §6 Case 2 pockets by u_L search, clipped §5.1 and §5.2 fan-out); §5.4 flat-triangle repair";

/// The quadratic algorithm on every region with at least `cubic_below`
/// corners (0 or 4: on all of them). For tests and benchmarks.
#[cfg(any(test, feature = "internals"))]
#[doc(hidden)]
pub fn minmax_length_with(points: &PointSet, cubic_below: usize) -> Result<Triangulation> {
    run(
        points,
        PolygonMethod::Quadratic {
            cubic_below,
            certify: false,
        },
        &mut Vec::new(),
    )
}

/// Test reference, not the product: §3's straightforward method, the cubic
/// dynamic program on every region of `ch(S) ∪ rng(S′)`, exact comparisons.
#[cfg(any(test, feature = "internals"))]
#[doc(hidden)]
pub fn minmax_length_cubic(points: &PointSet) -> Result<Triangulation> {
    run(points, PolygonMethod::Cubic, &mut Vec::new())
}

/// §5.4: turns a triangulation of the perturbed points into one of the
/// input points. A triangle whose corners are collinear in `S` is *flat*.
/// The flat triangles, joined across shared edges, form components, each on
/// one line; every input point on the open segment `uw` of a non-flat
/// triangle `uwy` lies in the flat component across `uw` (it cannot be inside
/// the empty perturbed triangle). Replacing each such triangle by the fan
/// from `y` over the points of `uw` in order along the line, and dropping the
/// flat triangles, gives a triangulation of `S`; by the Δ-Lemma the new edges
/// are shorter than `max(|uy|, |wy|)`, so the longest edge does not grow.
fn repair_flat_triangles(points: &[Point], triangles: Vec<[u32; 3]>) -> Vec<[u32; 3]> {
    let p = |m: u32| points[m as usize];
    let is_flat = |t: &[u32; 3]| orient_sign(p(t[0]), p(t[1]), p(t[2])) == 0;
    if !triangles.iter().any(is_flat) {
        return triangles;
    }
    count(
        FLAT_TRIANGLES,
        triangles.iter().filter(|t| is_flat(t)).count(),
    );
    let key = |u: u32, w: u32| (u.min(w), u.max(w));
    // Flat triangles by edge, and their components (union-find).
    let flat: Vec<[u32; 3]> = triangles.iter().copied().filter(is_flat).collect();
    let mut parent: Vec<usize> = (0..flat.len()).collect();
    fn find(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    let mut by_edge: HashMap<(u32, u32), usize> = HashMap::new();
    for (i, t) in flat.iter().enumerate() {
        for j in 0..3 {
            let e = key(t[j], t[(j + 1) % 3]);
            if let Some(&other) = by_edge.get(&e) {
                let (a, b) = (find(&mut parent, i), find(&mut parent, other));
                parent[a] = b;
            } else {
                by_edge.insert(e, i);
            }
        }
    }
    // Points of each component, sorted along its line (lexicographic order
    // is an order along any line).
    let root: Vec<usize> = (0..flat.len()).map(|i| find(&mut parent, i)).collect();
    let mut members: HashMap<usize, Vec<u32>> = HashMap::new();
    for (i, t) in flat.iter().enumerate() {
        members.entry(root[i]).or_default().extend_from_slice(t);
    }
    let lex = |a: &u32, b: &u32| {
        let (pa, pb) = (p(*a), p(*b));
        pa[0].total_cmp(&pb[0]).then(pa[1].total_cmp(&pb[1]))
    };
    for list in members.values_mut() {
        list.sort_by(lex);
        list.dedup();
    }
    let mut out = Vec::with_capacity(triangles.len());
    let mut work: Vec<[u32; 3]> = triangles.into_iter().filter(|t| !is_flat(t)).collect();
    while let Some(t) = work.pop() {
        let split = (0..3).find_map(|j| {
            let (u, w, y) = (t[j], t[(j + 1) % 3], t[(j + 2) % 3]);
            let &f = by_edge.get(&key(u, w))?;
            let line = &members[&root[f]];
            let iu = line.iter().position(|&m| m == u)?;
            let iw = line.iter().position(|&m| m == w)?;
            (iu.abs_diff(iw) > 1).then(|| {
                let inner: Vec<u32> = if iu < iw {
                    line[iu..=iw].to_vec()
                } else {
                    line[iw..=iu].iter().rev().copied().collect()
                };
                (inner, y)
            })
        });
        match split {
            None => out.push(t),
            Some((chain, y)) => {
                for w in chain.windows(2) {
                    work.push([w[0], w[1], y]);
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spatial::convex_hull_cycle;
    use crate::structures::DelaunayGraph;

    /// Canonical form of a cyclic corner sequence: its smallest rotation.
    fn canonical(cycle: &[u32]) -> Vec<u32> {
        (0..cycle.len())
            .map(|r| {
                cycle[r..]
                    .iter()
                    .chain(&cycle[..r])
                    .copied()
                    .collect::<Vec<u32>>()
            })
            .min()
            .unwrap_or_default()
    }

    /// The regions read off the Delaunay triangles (the product) equal the
    /// faces of the planar graph `ch ∪ rng(S′)` (the reference), cracks and
    /// pinch points included (each region has `corners − 2` triangles).
    #[test]
    fn triangle_regions_match_planar_graph_faces() {
        let mut s = 5u64;
        let mut next = |m: u64| {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (s >> 33) % m
        };
        let mut cracks = 0;
        for round in 0..300 {
            let (n, grid) = [(12, 4), (30, 7), (60, 1 << 20), (40, 12)][round % 4];
            let mut pts: Vec<Point> = (0..n)
                .map(|_| [next(grid) as f64, next(grid) as f64])
                .collect();
            pts.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
            pts.dedup();
            let Ok(g) = DelaunayGraph::with_topology(&pts) else {
                continue;
            };
            if g.triangles.is_empty() {
                continue;
            }
            let flags = rng_perturbed_flags(&pts, &g);
            let edges = rng_perturbed(&pts, &g);
            let mut want: Vec<Vec<u32>> = regions(&pts, &edges, &convex_hull_cycle(&pts))
                .iter()
                .map(|c| canonical(c))
                .collect();
            let product = Regions::new(&g, &flags);
            let mut got = Vec::new();
            for r in 0..product.len() {
                let b = product.boundary(&g, &flags, r);
                assert_eq!(
                    product.triangles(r).len() + 2,
                    b.corners.len(),
                    "Euler: {pts:?}"
                );
                let mut distinct = b.corners.clone();
                distinct.sort_unstable();
                distinct.dedup();
                cracks += b.corners.len() - distinct.len();
                got.push(canonical(&b.corners));
            }
            want.sort();
            got.sort();
            assert_eq!(got, want, "{pts:?}");
        }
        assert!(
            cracks > 0,
            "the inputs should include cracks or pinch points"
        );
    }
}
