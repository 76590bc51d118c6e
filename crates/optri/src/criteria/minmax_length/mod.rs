//! Exact minmax edge-length triangulation: a triangulation whose longest
//! edge is as short as possible, in O(n²) time (O(n log n) plus O(k²) per
//! region). After H. Edelsbrunner & T. S. Tan, *A quadratic time algorithm
//! for the minmax length triangulation*, FOCS 1991; SIAM J. Comput. 22
//! (1993). Section numbers (§) refer to that paper.
//!
//! # The algorithm (§3)
//! 0. Renumber the points along a Z-order curve (cache locality for every
//!    later phase; the perturbation `S′` below is defined on this numbering).
//! 1. Build the Delaunay triangulation, the relative neighbourhood graph
//!    (`rng_perturbed_flags`) and the convex hull.
//! 2. Cut the hull into the polygonal regions of `ch ∪ rng` (`regions`):
//!    the classes of Delaunay triangles joined across sides outside the
//!    graph, each with its boundary walk (cracks traversed on both sides);
//!    the planar-graph face walk
//!    ([`crate::structures::PlanarGraph::bounded_faces`]) is the test
//!    reference for it.
//! 3. Triangulate every region independently (rayon), assemble, and undo
//!    the perturbation (§5.4, `repair::repair_flat_triangles`).
//!
//! Before steps 2–3, the Length Lemma of §4 gives a lower bound on the
//! optimum: the longest edge of `ch(S) ∪ rng(S′)`
//! (`certificate::length_lemma_bound`).
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
//!   RNG): `rng_polygon::RngPolygon::incomplete`;
//! * §5.3 + §6 if it is *complete*: classify all diagonals with the per-corner
//!   stack scan, find `p′, p″, q′, q″`, take the shortest 2-edge passing the
//!   Crossing-Lemma test and triangulate both sides
//!   (`rng_polygon::RngPolygon::shortest_expandable_2_edge`,
//!   `rng_polygon::RngPolygon::triangulate_side`);
//! * regions with fewer than [`SMALL_REGION`] corners (most regions of
//!   typical inputs) are solved by the exact cubic program instead, which is
//!   cheaper there, restricted to chords no longer than the longest Delaunay
//!   diagonal inside the region (the Delaunay triangles are a feasible
//!   triangulation, so the optimum uses no longer chord); tests run the
//!   quadratic algorithm on every region too ([`minmax_length_with`]).
//!   Before that, a lower bound (`polygon::Region::apex_lower_bound`: every
//!   boundary edge needs an apex) often certifies the region's Delaunay
//!   triangles as optimal already (how often is measured in BENCHMARKS.md),
//!   and the program is skipped.
//!
//! # Degeneracy
//! §4–§6 assume no two equal lengths and no three collinear points. optri's
//! kernel defines one symbolic perturbation `S′` of the points
//! ([the kernel's perturbation](crate::kernel#ties-symbolic-perturbation), base-3 simulation of simplicity): every
//! orientation and length comparison is that of one real, infinitesimally
//! perturbed point set, so all decisions are mutually consistent. The
//! point-to-segment distance of §5.1 is compared by
//! [`crate::kernel::height_sign`], which expands the same perturbation.
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
//! failing the check would go to the cubic program on `S′`, reported in the
//! diagnostics `case_2_pocket_fallbacks` and `fallbacks` — zero in all
//! tests. Should the hull chain fail its boundary-order check, the whole
//! remainder goes to the cubic program (`case_2_hull_fallbacks`; zero in all
//! tests). How often each branch runs on typical inputs is measured in
//! BENCHMARKS.md.
//!
//! # Diagnostics
//! Every run counts which branches ran and how often a safety net caught
//! something (`counters::Counters`), and reports the counts as its
//! [`Diagnostics`] under stable names: `case_1`,
//! `case_2`, `case_2_remainder_vertices`, `flat_triangles`,
//! `case_2_hull_fallbacks`, `case_2_pockets_by_5_1`,
//! `case_2_pockets_by_fan_out`, `case_2_pocket_fallbacks`,
//! `small_regions_by_dp`, `small_regions_certified`,
//! `regions_certified_by_bound` and `fallbacks`.
//!
//! # Functions and the paper
//! | function | paper |
//! |---|---|
//! | [`minmax_length`] | §3 global algorithm, Subgraph Theorem (§4) |
//! | `certificate::length_lemma_bound` | §4 Length Lemma (a lower bound certifying Delaunay regions) |
//! | `rng_perturbed_flags`, `regions::Regions` | §3 steps 1–2, §5.4 (`rng(S′) ⊆ rng(S)`) |
//! | `rng_polygon::RngPolygon::incomplete` | §5.1, 1-Edge Lemma, Visibility Lemma |
//! | `rng_polygon::RngPolygon::visible_offsets` | §6 step 1 (diagonals in angular order) |
//! | `rng_polygon::RngPolygon::shortest_expandable_2_edge` | §6 steps 1–3, Containment and Crossing Lemmas |
//! | `rng_polygon::RngPolygon::triangulate_side` | §5.3 step 2, §6 Case 1, Expandability Lemma |
//! | `rng_polygon::RngPolygon::case_2` | §6 Case 2 step 1 |
//! | `rng_polygon::RngPolygon::hull_fan` | §6 Case 2 step 2, Claim 1 |
//! | `rng_polygon::RngPolygon::pocket` | §6 Case 2 steps 3.1–3.2, Claims 2–5 |
//! | `rng_polygon::RngPolygon::fan_out` | §5.2 fan-out triangulation, Fan-Out Lemma |
//! | `polygon::Region::minmax_triangulation_cubic` | §3 dynamic program (Klincsek) |
//! | `certificate::small_region`, `polygon::Region::apex_lower_bound` | §3 (a lower-bound certificate that skips the program) |
//! | `repair::repair_flat_triangles` | §5.4, Δ-Lemma |
//!
//! # Files
//! | file | holds |
//! |---|---|
//! | `mod.rs` | the driver ([`minmax_length`], `run`) and the RNG of `S′` |
//! | `regions.rs` | the regions of `ch(S) ∪ rng(S′)` read off the Delaunay triangles |
//! | `certificate.rs` | the Length Lemma and apex lower-bound certificates |
//! | `rng_polygon/` | the O(k²) rng-polygon algorithm (§5.1–§6), one file per part |
//! | `under_metric.rs` | the driver under a non-Euclidean metric (§7) |
//! | `polygon.rs` | a region's exact geometry and the cubic program |
//! | `fallback.rs` | the cubic safety net |
//! | `counters.rs` | the per-run counters behind the diagnostics |
//! | `repair.rs` | §5.4's repair of flat triangles |

mod certificate;
mod counters;
mod fallback;
pub(crate) mod polygon;
pub(crate) mod regions;
mod repair;
mod rng_polygon;
mod under_metric;

use super::{CriterionEntry, CriterionInfo, Diagnostics, Optimality, Options, Solved};
use crate::error::Result;
use crate::graphs::perturbed_rng_from_delaunay;
use crate::interrupt::Stop;
use crate::kernel::{compare_lengths, EuclideanOrder, Point};
use crate::parallel::prelude::*;
use crate::spatial::morton_order;
use crate::structures::{DelaunayGraph, PointSet, Triangulation};
use crate::timing::{timed, Phase};
use certificate::{length_lemma_bound, longest_side, small_region};
use counters::Counters;
use fallback::{cubic_fallback, Fallback};
use polygon::Region;
use regions::Regions;
use repair::repair_flat_triangles;
use rng_polygon::{Mesh, RngPolygon};
use std::cmp::Ordering::Greater;

/// The registry's entry: this criterion's description and solvers.
pub(crate) const ENTRY: CriterionEntry = CriterionEntry {
    info: INFO,
    solve,
    solve_polygon: Some(polygon::solve_polygon),
};

pub(crate) const INFO: CriterionInfo = CriterionInfo {
    name: "minmax-length",
    description: "minimises the longest edge",
    optimality: Optimality::Exact,
    options: &["metric"],
    reference: "H. Edelsbrunner & T. S. Tan, A quadratic time algorithm for the minmax \
                length triangulation, FOCS 1991 / SIAM J. Comput. 1993",
    needs_elevations: false,
    measure: Some(crate::structures::Measure::MaxEdgeLength),
};

pub(crate) fn solve(
    points: &PointSet,
    options: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    if !options.metric.is_euclidean() {
        let method = under_metric::MetricMethod::Product {
            quadratic_from: under_metric::QUADRATIC_FROM,
            certify: true,
        };
        let (triangulation, diagnostics) =
            under_metric::run_under(points, &options.metric, method, options.stop(), phases)?;
        let algorithm = if phases.iter().any(|p| p.name == "regions") {
            format!("{ALGORITHM_UNDER_METRIC} (metric {})", options.metric)
        } else {
            format!(
                "{ALGORITHM_UNDER_METRIC} (metric {}); here the Delaunay triangulation met the hull lower bound in the metric, so it is optimal",
                options.metric
            )
        };
        return Ok(Solved {
            triangulation,
            algorithm,
            optimality: Optimality::Exact,
            diagnostics,
            bound: None,
            approximation: None,
        });
    }
    let (triangulation, diagnostics) = run(points, PRODUCT, options.stop(), phases)?;
    let algorithm = if phases.iter().any(|p| p.name == "regions") {
        ALGORITHM.to_string()
    } else {
        format!("{ALGORITHM}; here the Delaunay triangulation met the Length-Lemma lower bound, so it is optimal")
    };
    Ok(Solved {
        triangulation,
        algorithm,
        optimality: Optimality::Exact,
        diagnostics,
        bound: None,
        approximation: None,
    })
}

/// The method's name, as reported by [`crate::triangulate`].
const ALGORITHM: &str = "Edelsbrunner–Tan O(n²): Length-Lemma lower bound (longest hull/RNG edge) certifies Delaunay regions; hull ∪ RNG(S′) regions; §5.1 incomplete and §5.3/§6 complete rng-polygons on the symbolic perturbation (exact cubic DP, pruned by the regions' Delaunay diagonals, for regions under 32 corners; §6 Case 2 pockets by u_L search, clipped §5.1 and §5.2 fan-out); §5.4 flat-triangle repair";

/// The method's name under a non-Euclidean metric.
const ALGORITHM_UNDER_METRIC: &str = "Edelsbrunner–Tan §7: the longest hull segment in the metric (a lower bound) certifies the Delaunay triangulation when no edge of it is longer; otherwise hull ∪ RNG regions under the simulated strictly convex norm (RNG by nearest neighbours in sectors, exact lunes); §5.1 (visible lune vertex minimising the longer side) on large incomplete regions, §5.3/§6 (the Euclidean rng-polygon algorithm under the metric's order, cubic safety net) on large complete ones, the exact cubic program on the others; §5.4 flat-triangle repair";

/// Minmax-length under `metric` with the cubic program on every region
/// (`quadratic_from = None`), or with §5.1 on every incomplete and §5.3/§6 on
/// every complete region of at least `quadratic_from` corners (0: all of
/// them; complete regions only where the Delaunay triangles tile them), and
/// the diagnostics. No hull certificate. For tests and benchmarks.
#[cfg(any(test, feature = "internals"))]
pub fn minmax_length_under_with(
    points: &PointSet,
    metric: &crate::kernel::Metric,
    quadratic_from: Option<usize>,
) -> Result<(Triangulation, Diagnostics)> {
    let method = match quadratic_from {
        None => under_metric::MetricMethod::Cubic,
        Some(k) => under_metric::MetricMethod::Product {
            quadratic_from: k,
            certify: false,
        },
    };
    under_metric::run_under(points, metric, method, &Stop::default(), &mut Vec::new())
}

/// `rng(S′)` for the kernel's symbolic perturbation `S′`, as a flag per
/// Delaunay edge (indexed like `g.edges`; `g` must come from
/// [`DelaunayGraph::with_topology`]). Every edge of `rng(S′)` is in `rng(S)`
/// (§5.4), hence in every Delaunay completion of `S`, so testing the Delaunay
/// edges suffices; the lune search is the RNG's own, with the perturbation
/// deciding the lune's boundary.
pub(crate) fn rng_perturbed_flags(points: &[Point], g: &DelaunayGraph) -> Vec<bool> {
    let mut flags = vec![false; g.edges.len()];
    for slot in perturbed_rng_from_delaunay(points, g, |_, _, slot| slot) {
        flags[g.topology.slot_edges[slot as usize] as usize] = true;
    }
    flags
}

/// [`rng_perturbed_flags`] as a list of edges.
#[cfg(test)]
pub(crate) fn rng_perturbed(points: &[Point], g: &DelaunayGraph) -> Vec<[u32; 2]> {
    perturbed_rng_from_delaunay(points, g, |p, q, _| [p, q])
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
/// than the quadratic algorithm (figures in BENCHMARKS.md); the quadratic
/// algorithm handles the larger ones.
const PRODUCT: PolygonMethod = PolygonMethod::Quadratic {
    cubic_below: SMALL_REGION,
    certify: true,
};

/// Regions with fewer corners than this use the cubic program in the product.
pub const SMALL_REGION: usize = 32;

/// Regions per rayon task in the polygon phase: most regions take
/// microseconds, so single-region tasks would cost more than they do.
const REGIONS_PER_TASK: usize = 64;

/// The pipeline of the module docs with `method` on the regions; stopped by
/// `stop` ([`crate::Error::Interrupted`]) in the region loop.
fn run(
    points: &PointSet,
    method: PolygonMethod,
    stop: &Stop,
    phases: &mut Vec<Phase>,
) -> Result<(Triangulation, Diagnostics)> {
    let counters = Counters::default();
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
    let delaunay_result = |counters: Counters| {
        counters.regions_certified_by_bound.add(1);
        let mut t = g.triangles.clone();
        for c in t.iter_mut().flatten() {
            *c = order[*c as usize];
        }
        Ok((
            Triangulation::from_distinct(points, t),
            counters.into_diagnostics(),
        ))
    };
    if certify
        && timed(phases, "lower bound", || {
            delaunay_meets(length_lemma_bound(pts, &g, None))
        })
    {
        return delaunay_result(counters);
    }
    let rng = timed(phases, "rng", || rng_perturbed_flags(pts, &g));
    let bound = if certify {
        let bound = timed(phases, "lower bound", || {
            length_lemma_bound(pts, &g, Some(&rng))
        });
        if delaunay_meets(bound) {
            return delaunay_result(counters);
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
            .with_min_len(REGIONS_PER_TASK)
            .flat_map_iter(|r| {
                // Once per task and before each large region; a stopped
                // run skips the rest and fails after the phase.
                let large = regions.triangles(r).len() >= SMALL_REGION;
                if (r.is_multiple_of(REGIONS_PER_TASK) || large) && stop.reason().is_some() {
                    return Vec::new();
                }
                if let [t] = regions.triangles(r) {
                    return vec![g.triangles[*t as usize]];
                }
                if let Some(bound) = bound {
                    let members = regions.triangles(r);
                    let e = longest_side(pts, &g, members.iter().copied())
                        .expect("a region has triangles");
                    let (a, b) = (pts[e[0] as usize], pts[e[1] as usize]);
                    if compare_lengths(a, b, bound[0], bound[1]) != Greater {
                        counters.regions_certified_by_bound.add(1);
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
                        RngPolygon::new(pts, vertices, &mesh, &counters)
                            .and_then(|f| f.triangulate())
                            .unwrap_or_else(|_| {
                                let mut out = Vec::new();
                                cubic_fallback(
                                    pts,
                                    EuclideanOrder,
                                    Fallback::Region,
                                    vertices,
                                    &counters,
                                    &mut out,
                                    0,
                                );
                                out
                            })
                    }
                    PolygonMethod::Quadratic { .. } => {
                        small_region(&region, || regions.local_mesh(&g, &rng, r), &counters)
                    }
                    PolygonMethod::Cubic => region.minmax_triangulation_cubic(),
                }
            })
            .collect()
    });
    stop.check()?;
    let triangles = timed(phases, "repair", || {
        let mut t = repair_flat_triangles(pts, triangles, &counters);
        for c in t.iter_mut().flatten() {
            *c = order[*c as usize];
        }
        t
    });
    Ok((
        Triangulation::from_distinct(points, triangles),
        counters.into_diagnostics(),
    ))
}

/// A triangulation of `points` whose longest edge is as short as possible.
///
/// Exact for every input, degenerate ones included (see the module docs).
///
/// # Errors
/// Propagates failures of the Delaunay construction.
pub(crate) fn minmax_length(points: &PointSet) -> Result<Triangulation> {
    run(points, PRODUCT, &Stop::default(), &mut Vec::new()).map(|(t, _)| t)
}

/// The quadratic algorithm on every region with at least `cubic_below`
/// corners (0 or 4: on all of them), without the Length-Lemma certificate,
/// and the run's diagnostics (see the module docs). For tests and
/// benchmarks.
#[cfg(any(test, feature = "internals"))]
pub fn minmax_length_with(
    points: &PointSet,
    cubic_below: usize,
) -> Result<(Triangulation, Diagnostics)> {
    run(
        points,
        PolygonMethod::Quadratic {
            cubic_below,
            certify: false,
        },
        &Stop::default(),
        &mut Vec::new(),
    )
}

/// Test reference, not the product: §3's straightforward method, the cubic
/// dynamic program on every region of `ch(S) ∪ rng(S′)`, exact comparisons.
#[cfg(any(test, feature = "internals"))]
pub fn minmax_length_cubic(points: &PointSet) -> Result<Triangulation> {
    run(
        points,
        PolygonMethod::Cubic,
        &Stop::default(),
        &mut Vec::new(),
    )
    .map(|(t, _)| t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spatial::convex_hull_cycle;
    use rand::{rngs::StdRng, Rng, SeedableRng};

    /// Seed of the random point sets of the region test.
    const REGIONS_SEED: u64 = 5;

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
        let mut rng = StdRng::seed_from_u64(REGIONS_SEED);
        let mut cracks = 0;
        for round in 0..300 {
            let (n, grid) = [(12, 4), (30, 7), (60, 1 << 20), (40, 12)][round % 4];
            let mut pts: Vec<Point> = (0..n)
                .map(|_| [rng.gen_range(0..grid) as f64, rng.gen_range(0..grid) as f64])
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

    /// A raised cancel flag or a time limit of 0 s stops the region loop
    /// (run without the Delaunay certificate, so the regions are solved).
    #[test]
    fn a_stopped_run_stops_in_the_region_loop() {
        let mut rng = StdRng::seed_from_u64(REGIONS_SEED);
        let input: Vec<Point> = (0..300)
            .map(|_| [rng.gen_range(0..1000) as f64, rng.gen_range(0..1000) as f64])
            .collect();
        let points = PointSet::new(&input).unwrap();
        let method = PolygonMethod::Quadratic {
            cubic_below: SMALL_REGION,
            certify: false,
        };
        let cancel = crate::Cancel::new();
        cancel.cancel();
        let stops = [
            Options::default().with_cancel(cancel),
            Options::default().with_time_limit(std::time::Duration::ZERO),
        ];
        for options in stops {
            let options = options.started();
            let result = run(&points, method, options.stop(), &mut Vec::new());
            assert!(
                matches!(result, Err(crate::Error::Interrupted(_))),
                "{:?}",
                result.map(|_| ())
            );
        }
        assert!(run(&points, method, &Stop::default(), &mut Vec::new()).is_ok());
    }
}
