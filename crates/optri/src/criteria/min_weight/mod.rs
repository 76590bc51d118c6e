//! Minimum-weight triangulation (MWT): the triangulation of minimum total
//! edge length, exact for every input.
//!
//! * **Convex position**: Klincsek's dynamic program (G. T. Klincsek,
//!   *Minimal triangulations of polygonal domains*, Ann. Discrete Math. 9,
//!   1980) — the library's [polygon program](crate::polygon_program) with
//!   total length as an additive objective, O(n³) time, O(n²) memory.
//! * **General point sets**: NP-hard (W. Mulzer & G. Rote, *Minimum-weight
//!   triangulation is NP-hard*, JACM 55, 2008), solved in practice by the
//!   pipeline of A. Haas (*Solving large-scale minimum-weight triangulation
//!   instances to provable optimality*, SoCG 2018) and of Keldenich et al.
//!   (*Hard in theory, easy in practice*): the exact diamond filter and the
//!   LMT-skeleton ([`skeleton`]), then the faces the skeleton leaves
//!   ([`faces`]): simple faces by the polygon program over candidate
//!   diagonals, faces with holes or inner points by an exact search over
//!   empty candidate triangles, priced by the certified dual of the face's
//!   triangle program and, when that is not enough, by a certified branch
//!   and bound over the program ([`faces`]). The result is `exact` only when every face
//!   was solved; otherwise the lightest of the assembled triangulation (its
//!   unsolved faces completed by constrained Delaunay triangles), the
//!   Delaunay and the greedy triangulation, compared exactly, with a
//!   certified lower bound on the optimum.
//!
//! # Exactness
//! Weights are sums of square roots. Every comparison of two weights is
//! exact: certified intervals first, then the kernel's exact comparison
//! ([`crate::kernel::compare_length_sums`]) when the intervals overlap.
//! Ties: the first best split corner (polygon program) or the first best
//! triangle in the search's order wins, so the result is deterministic.

mod face_program;
mod faces;
pub(crate) use faces::FRONT_BUDGET;
mod skeleton;

use super::{
    BoundMeasure, CertifiedBound, CriterionEntry, CriterionInfo, Diagnostics, Optimality, Options,
    Solved,
};
use crate::error::{Error, Interruption, Result};
use crate::interrupt::Stop;
use crate::kernel::{compare_length_sums, orient_sign, LengthInterval, Point};
use crate::polygon_program::{
    corner_point, on_simple_polygon, optimal_triangulation_until, Objective,
};
use crate::spatial::{bounding_box, convex_hull_cycle, PointCells};
use crate::structures::{PointSet, SimplePolygon, Triangulation};
use crate::timing::{Phase, Stopwatch};
use faces::Method;
use std::cmp::Ordering;

/// The registry's entry: this criterion's description and solvers.
pub(crate) const ENTRY: CriterionEntry = CriterionEntry {
    info: INFO,
    solve,
    solve_polygon: Some(solve_polygon),
};

pub(crate) const INFO: CriterionInfo = CriterionInfo {
    name: "min-weight",
    description: "minimises the total edge length",
    optimality: Optimality::Approximation {
        bound: "exact unless the exact pipeline cannot finish (a face beyond the exact search's \
                budget, a skeleton beyond the memory budget, convex position beyond the program, \
                or the time limit): then the lighter of greedy and Delaunay, or the best found, \
                with a certified lower bound on the optimal weight",
    },
    options: &[],
    reference: "G. T. Klincsek 1980; Dickerson, Keil & Montague 1997; Drysdale, McElfresh & Snoeyink 2001; A. Haas 2018",
    needs_elevations: false,
    measure: Some(crate::structures::Measure::TotalEdgeLength),
};

pub(crate) fn solve(
    points: &PointSet,
    options: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    let pts = points.points();
    let hull = convex_hull_cycle(pts);
    let stop = options.stop();
    let mut watch = Stopwatch::new(phases);
    if hull.len() == pts.len() && pts.len() > MAX_POINTS {
        // Every pair of points in convex position passes the diamond filter
        // (the triangle towards the inside is empty), so the general
        // pipeline would hold n³ candidate triangles.
        let solved = lighter_of_greedy_and_delaunay(
            points,
            &hull,
            &format!(
                "{} points in convex position exceed the exact program's {MAX_POINTS} (O(n^3))",
                pts.len()
            ),
            stop,
        )?;
        watch.lap("min-weight");
        return Ok(solved);
    }
    if hull.len() == pts.len() {
        let solved = match convex_min_weight(points, &hull, stop) {
            Ok(triangulation) => Solved {
                triangulation,
                algorithm:
                    "Klincsek dynamic program on the convex polygon, O(n^3), exact sums of square roots"
                        .to_string(),
                optimality: Optimality::Exact,
                diagnostics: Diagnostics::default(),
                bound: None,
                approximation: None,
            },
            Err(Error::Interrupted(Interruption::TimeLimit { seconds })) => {
                lighter_of_greedy_and_delaunay(
                    points,
                    &hull,
                    &out_of_time(seconds),
                    &stop.grace(greedy_grace(seconds)),
                )?
            }
            Err(e) => return Err(e),
        };
        watch.lap("min-weight");
        return Ok(solved);
    }
    let bounds = Bounds {
        fronts: FRONT_BUDGET,
        bytes: skeleton::default_budget(pts.len()),
        stop,
    };
    match general_min_weight_within(points, phases, bounds) {
        Ok(general) => Ok(general.solved),
        Err(Error::Interrupted(Interruption::TimeLimit { seconds })) => {
            let mut watch = Stopwatch::new(phases);
            let solved = lighter_of_greedy_and_delaunay(
                points,
                &hull,
                &out_of_time(seconds),
                &stop.grace(greedy_grace(seconds)),
            )?;
            watch.lap("greedy and Delaunay");
            Ok(solved)
        }
        Err(e) => Err(e),
    }
}

/// How long the greedy triangulation may run once the time limit of
/// `seconds` is spent: a tenth of the limit, at least 10 ms (enough for a
/// few thousand points), so that a run returns soon after its limit.
fn greedy_grace(seconds: f64) -> std::time::Duration {
    std::time::Duration::from_secs_f64(seconds / 10.0).max(std::time::Duration::from_millis(10))
}

/// Why a run out of time answers without the exact result.
fn out_of_time(seconds: f64) -> String {
    format!("the time limit of {seconds} s ran out before the exact result")
}

/// Largest number of distinct points in convex position the polygon program
/// takes (O(n²) memory, O(n³) time); larger convex sets get the lighter of
/// the greedy and the Delaunay triangulation, not proven optimal, with a
/// certified lower bound.
pub const MAX_POINTS: usize = 4000;

/// `min-weight` on a simple polygon ([`crate::triangulate`]): the
/// polygon program with the total length of the diagonals (the boundary's
/// length is the same in every triangulation), exact sums of square roots
/// on undecided comparisons.
pub(crate) fn solve_polygon(
    polygon: &SimplePolygon,
    _: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    let p = corner_point(polygon);
    let triangulation =
        on_simple_polygon(polygon, "min-weight", &TotalLength { point: &p }, phases)?;
    Ok(Solved {
        triangulation,
        algorithm: "Klincsek dynamic program on the polygon, O(n^3), exact sums of square roots"
            .to_string(),
        optimality: Optimality::Exact,
        diagnostics: Diagnostics::default(),
        bound: None,
        approximation: None,
    })
}

fn convex_min_weight(points: &PointSet, polygon: &[u32], stop: &Stop) -> Result<Triangulation> {
    let pts = points.points();
    let p = |i: usize| pts[polygon[i] as usize];
    let solved = optimal_triangulation_until(
        polygon.len(),
        |_, _| true, // convex position: every chord is a diagonal
        |i, m, j| orient_sign(p(i), p(m), p(j)) != 0, // a flat triangle is not allowed
        &TotalLength { point: &p },
        stop,
    )?
    .ok_or_else(|| {
        Error::Internal("the convex polygon has no triangulation without flat triangles".into())
    })?;
    let triangles = solved
        .triangles
        .into_iter()
        .map(|t| t.map(|c| polygon[c]))
        .collect();
    Ok(Triangulation::from_distinct(points, triangles))
}

/// The answer when the exact pipeline cannot run (`why`): points in convex
/// position beyond [`MAX_POINTS`], a skeleton over its memory budget, or
/// the time limit. The lighter (compared exactly) of the greedy
/// triangulation (within a constant factor of the optimum in convex
/// position: C. Levcopoulos & A. Lingas, *On approximation behavior of the
/// greedy triangulation for convex polygons*, Algorithmica 2, 1987) and the
/// Delaunay triangulation, not proven optimal, with a certified lower
/// bound: every triangulation of `n` points with `h` on the hull (`hull`,
/// its cycle) has the `h` hull edges and `3n − 3 − 2h` inner edges, each at
/// least the shortest pair of points not consecutive on the hull. That pair
/// is a Delaunay edge or joins the two neighbours of a hull point: if its
/// closed diametral disk held a third point, both segments to it would be
/// shorter (the angle there is at least 90°), so both would join hull
/// neighbours; otherwise it is a Gabriel edge, in every Delaunay
/// triangulation.
///
/// The greedy triangulation runs under `stop`; if its time limit stops it,
/// the answer is the Delaunay triangulation with the same bound (a
/// cancellation is an error, as everywhere).
fn lighter_of_greedy_and_delaunay(
    points: &PointSet,
    hull: &[u32],
    why: &str,
    stop: &Stop,
) -> Result<Solved> {
    let pts = points.points();
    let (n, h) = (pts.len(), hull.len());
    let delaunay = crate::graphs::delaunay(points)?;
    let delaunay_tris = distinct_triangles(points, &delaunay);
    let greedy = greedy_within(points, stop)?;
    let greedy_finished = greedy.is_some();
    let (name, best) = match greedy {
        Some(greedy) => lightest(points, [("greedy", greedy), ("Delaunay", delaunay)]),
        None => ("Delaunay", delaunay_tris.clone()),
    };
    let mut position = vec![None; n];
    for (k, &v) in hull.iter().enumerate() {
        position[v as usize] = Some(k);
    }
    let consecutive = |a: u32, b: u32| match (position[a as usize], position[b as usize]) {
        (Some(x), Some(y)) => {
            let d = x.abs_diff(y);
            d == 1 || d == h - 1
        }
        _ => false,
    };
    let ears = (0..h).map(|k| [hull[(k + h - 1) % h], hull[(k + 1) % h]]);
    let shortest_inner = edges_of(&delaunay_tris)
        .into_iter()
        .filter(|&[a, b]| !consecutive(a, b))
        .chain(ears)
        .map(|[a, b]| LengthInterval::of_segment(pts[a as usize], pts[b as usize]).lo)
        .fold(f64::INFINITY, f64::min);
    let perimeter = (0..h).fold(LengthInterval::ZERO, |sum, k| {
        sum.plus(LengthInterval::of_segment(
            pts[hull[k] as usize],
            pts[hull[(k + 1) % h] as usize],
        ))
    });
    // 3n − 3 − 2h ≤ 2⁵³: the product is rounded once, widened by an ulp.
    let inner_edges = 3 * n - 3 - 2 * h;
    let inner = (shortest_inner * inner_edges as f64).next_down().max(0.0);
    let lower_bound = perimeter
        .plus(LengthInterval {
            lo: inner,
            hi: inner,
        })
        .lo;
    let mut diagnostics = Diagnostics::default();
    diagnostics.add("exact", 0);
    let (chosen, bound) = if greedy_finished {
        (
            "the lighter of greedy and Delaunay",
            "not proven optimal: the lighter of greedy and Delaunay (the exact pipeline's size, memory or time limit); the weight is at least the reported lower bound",
        )
    } else {
        (
            "the time limit stopped the greedy triangulation",
            "not proven optimal: the Delaunay triangulation (the exact pipeline's size, memory or time limit, and the time limit stopped the greedy one); the weight is at least the reported lower bound",
        )
    };
    Ok(Solved {
        triangulation: Triangulation::from_distinct(points, best),
        algorithm: format!(
            "{name} triangulation, {chosen}, not proven optimal: {why}; \
             certified lower bound on the optimal weight: {lower_bound} \
             (hull edges + (3n - 3 - 2h) x the shortest inner edge)"
        ),
        optimality: Optimality::Approximation { bound },
        diagnostics,
        bound: Some(CertifiedBound {
            measure: BoundMeasure::TotalLength,
            triangle: None,
            value: lower_bound,
            upper: false,
        }),
        approximation: None,
    })
}

/// The greedy triangulation under `stop`, `None` if its time limit stopped
/// it.
fn greedy_within(points: &PointSet, stop: &Stop) -> Result<Option<Triangulation>> {
    match crate::criteria::greedy::greedy_triangulation_timed(points, stop, &mut Vec::new()) {
        Ok((greedy, _)) => Ok(Some(greedy)),
        Err(Error::Interrupted(Interruption::TimeLimit { .. })) => Ok(None),
        Err(e) => Err(e),
    }
}

/// A triangulation's triangles in distinct indices.
fn distinct_triangles(points: &PointSet, t: &Triangulation) -> Vec<[u32; 3]> {
    t.triangles()
        .iter()
        .map(|c| c.map(|i| points.distinct_index(i)))
        .collect()
}

/// The lightest of named triangulations (weights compared exactly; the
/// earlier one wins a tie), as its name and its triangles in distinct
/// indices.
fn lightest<const K: usize>(
    points: &PointSet,
    candidates: [(&'static str, Triangulation); K],
) -> (&'static str, Vec<[u32; 3]>) {
    let mut best: Option<(&'static str, Vec<[u32; 3]>)> = None;
    for (name, t) in candidates {
        let tris = distinct_triangles(points, &t);
        if best
            .as_ref()
            .is_none_or(|(_, b)| compare_weights(points.points(), &tris, b) == Ordering::Less)
        {
            best = Some((name, tris));
        }
    }
    best.expect("at least one candidate")
}

/// Total length of the diagonals as a certified interval, decided exactly
/// when intervals overlap: an additive objective.
pub(crate) struct TotalLength<'a, P: Fn(usize) -> Point> {
    pub(crate) point: &'a P,
}

impl<P: Fn(usize) -> Point> Objective for TotalLength<'_, P> {
    type Value = LengthInterval;
    fn empty(&self) -> LengthInterval {
        LengthInterval::ZERO
    }
    fn diagonal(&self, i: usize, j: usize) -> Option<LengthInterval> {
        Some(LengthInterval::of_segment((self.point)(i), (self.point)(j)))
    }
    fn triangle(&self, _: usize, _: usize, _: usize) -> Option<LengthInterval> {
        None
    }
    fn combine(&self, a: LengthInterval, b: LengthInterval) -> LengthInterval {
        a.plus(b)
    }
    fn better(&self, a: LengthInterval, b: LengthInterval) -> bool {
        a.certainly_compare(b) == Some(Ordering::Less)
    }
    fn undecided(&self, a: LengthInterval, b: LengthInterval) -> bool {
        a.certainly_compare(b).is_none()
    }
    fn better_diagonals(&self, a: &[[usize; 2]], b: &[[usize; 2]]) -> bool {
        let segments = |s: &[[usize; 2]]| -> Vec<[Point; 2]> {
            s.iter()
                .map(|&[i, j]| [(self.point)(i), (self.point)(j)])
                .collect()
        };
        compare_length_sums(&segments(a), &segments(b)) == Ordering::Less
    }
}

/// The diamond filter's candidates, the edges the LMT loop leaves and the
/// certain edges of the general pipeline on `points` (distinct indices,
/// sorted pairs `u < v`), for the tests that compare them with brute-force
/// references.
#[cfg(feature = "internals")]
pub(crate) fn skeleton_edge_sets(points: &PointSet, loop_chunk: usize) -> [Vec<[u32; 2]>; 3] {
    let pts = points.points();
    let candidates = skeleton::diamond_candidates(pts);
    let sk = skeleton::lmt_skeleton_in_chunks(pts, candidates.clone(), loop_chunk)
        .expect("the tests' point sets are small");
    let pick = |flags: &[bool]| -> Vec<[u32; 2]> {
        sk.edges
            .iter()
            .zip(flags)
            .filter(|(_, &f)| f)
            .map(|(&e, _)| e)
            .collect()
    };
    [candidates, pick(&sk.alive), pick(&sk.certain)]
}

/// A grid of the points with about one point per cell.
pub(super) fn point_grid(pts: &[Point]) -> PointCells {
    let bbox = bounding_box(pts);
    let (w, h) = (bbox[2] - bbox[0], bbox[3] - bbox[1]);
    let n = pts.len();
    let cell = ((w * h) / n as f64).sqrt().max(w.max(h) / n as f64);
    PointCells::new(pts, bbox, cell)
}

/// The general pipeline's result with its certified lower bound.
pub(crate) struct General {
    pub solved: Solved,
    /// A certified lower bound on the optimal weight when not exact (when
    /// exact, the result's weight: see [`certified_weight_below`]).
    #[cfg_attr(not(feature = "internals"), allow(dead_code))] // read by the test hooks
    pub lower_bound: Option<f64>,
}

/// A certified lower bound on the weight of `triangulation`: the largest
/// double not above it (of an exact result, the optimum itself, rounded
/// down where `stats` rounds to nearest).
#[cfg(feature = "internals")]
pub(crate) fn certified_weight_below(triangulation: &Triangulation) -> f64 {
    crate::kernel::reporting::total_length_scaled(
        triangulation.point_set().input_points(),
        &triangulation.edges(),
        0,
        crate::kernel::reporting::Rounding::Down,
    )
}

/// The edges of triangles, each once, as sorted pairs.
fn edges_of(triangles: &[[u32; 3]]) -> Vec<[u32; 2]> {
    let mut edges: Vec<[u32; 2]> = triangles
        .iter()
        .flat_map(|t| [[t[0], t[1]], [t[1], t[2]], [t[2], t[0]]])
        .map(|[a, b]| [a.min(b), a.max(b)])
        .collect();
    edges.sort_unstable();
    edges.dedup();
    edges
}

/// Exact comparison of the total edge lengths of two triangulations of the
/// same points (common edges cancel).
fn compare_weights(pts: &[Point], a: &[[u32; 3]], b: &[[u32; 3]]) -> Ordering {
    let (ea, eb) = (edges_of(a), edges_of(b));
    let seg = |e: &[u32; 2]| [pts[e[0] as usize], pts[e[1] as usize]];
    let only_a: Vec<[Point; 2]> = ea
        .iter()
        .filter(|e| eb.binary_search(e).is_err())
        .map(seg)
        .collect();
    let only_b: Vec<[Point; 2]> = eb
        .iter()
        .filter(|e| ea.binary_search(e).is_err())
        .map(seg)
        .collect();
    compare_length_sums(&only_a, &only_b)
}

/// The general pipeline; the exact search on faces with holes memoises at
/// most `budget` fronts per face ([`faces::FRONT_BUDGET`] by default).
#[cfg_attr(not(feature = "internals"), allow(dead_code))] // the test hooks' entry
pub(crate) fn general_min_weight(
    points: &PointSet,
    phases: &mut Vec<Phase>,
    budget: usize,
) -> Result<General> {
    let bounds = Bounds {
        fronts: budget,
        bytes: skeleton::default_budget(points.len()),
        stop: &Stop::default(),
    };
    general_min_weight_within(points, phases, bounds)
}

/// What bounds a run of the general pipeline.
#[derive(Clone, Copy)]
pub(crate) struct Bounds<'a> {
    /// Fronts the exact search memoises per face.
    pub fronts: usize,
    /// Bytes the LMT-skeleton's candidate triangles may take
    /// ([`skeleton::Limits::bytes`]); beyond them the result is the lighter
    /// of greedy and Delaunay, not proven optimal.
    pub bytes: usize,
    /// The run's stop, read inside the long loops.
    pub stop: &'a Stop,
}

/// [`general_min_weight`] within `bounds`.
///
/// # Errors
/// [`Error::Interrupted`] when `bounds.stop` says so.
pub(crate) fn general_min_weight_within(
    points: &PointSet,
    phases: &mut Vec<Phase>,
    bounds: Bounds,
) -> Result<General> {
    let budget = bounds.fronts;
    // PointSet guarantees three distinct points not on one line.
    let mut watch = Stopwatch::new(phases);
    let mut diagnostics = Diagnostics::default();
    // Every phase runs on the points renumbered once in Z-order (their
    // searches then read nearby memory); only the triangles are mapped back.
    // The filter's candidates and the skeleton are sets defined by the
    // geometry alone, whatever the numbering; the faces break exact weight
    // ties by their search order, so a tie may resolve to another, equally
    // light triangulation, still deterministic.
    let order = crate::spatial::morton_order(points.points());
    let pts: Vec<Point> = order.iter().map(|&v| points.points()[v as usize]).collect();
    let pts = &pts[..];
    let grid = point_grid(pts);
    watch.lap("z-order");
    let candidates = skeleton::diamond_filter(pts, &grid, bounds.stop)?;
    diagnostics.add("diamond candidates", candidates.len() as u64);
    watch.lap("diamond filter");
    let n = pts.len();
    bounds.stop.check()?;
    let limits = skeleton::Limits {
        bytes: bounds.bytes,
        stop: bounds.stop,
    };
    let sk = match skeleton::z_order_skeleton(pts, &grid, candidates, skeleton::LOOP_CHUNK, limits)?
    {
        skeleton::Built::Skeleton(sk) => *sk,
        skeleton::Built::OverBudget { bytes } => {
            drop(grid);
            watch.lap("lmt skeleton");
            let why = format!(
                "the LMT-skeleton's candidate triangles would take at least {} MiB, over the \
                 memory budget of {} MiB (points in nearly convex position have about n^3/6)",
                bytes >> 20,
                bounds.bytes >> 20
            );
            let hull = convex_hull_cycle(points.points());
            let solved = lighter_of_greedy_and_delaunay(points, &hull, &why, bounds.stop)?;
            watch.lap("greedy and Delaunay");
            let lower_bound = solved.bound.as_ref().map(|b| b.value);
            return Ok(General {
                solved,
                lower_bound,
            });
        }
    };
    drop(grid);
    let alive = sk.alive.iter().filter(|&&a| a).count();
    let certain = sk.certain.iter().filter(|&&a| a).count();
    diagnostics.add("skeleton candidates left", alive as u64);
    diagnostics.add("certain edges", certain as u64);
    watch.lap("lmt skeleton");
    let regions = faces::solve_regions(pts, &sk, budget, bounds.stop)?;
    watch.lap("faces and programs");
    let mut triangles: Vec<[u32; 3]> = Vec::with_capacity(2 * n);
    let mut exact = true;
    let (mut polygons, mut searched, mut unsolved, mut largest, mut holes) =
        (0u64, 0u64, 0u64, 0u64, 0u64);
    let mut fronts = 0u64;
    let (mut programs, mut program_triangles, mut program_kept, mut program_fronts) =
        (0u64, 0u64, 0u64, 0u64);
    let mut program_nodes = 0u64;
    let mut lower = LengthInterval::ZERO;
    for r in &regions {
        match r.method {
            Method::Triangle => {}
            Method::Polygon => polygons += 1,
            Method::Search => searched += 1,
            Method::Program => programs += 1,
            Method::Fallback => {
                unsolved += 1;
                exact = false;
                lower = lower.plus(LengthInterval {
                    lo: r.lower,
                    hi: r.lower,
                });
            }
        }
        if r.method != Method::Triangle {
            largest = largest.max(r.corners as u64 + r.inner_points as u64);
        }
        if r.holes > 0 || r.inner_points > 0 {
            holes += 1;
        }
        fronts += r.fronts as u64;
        if let Some(p) = r.program {
            program_triangles += p.triangles as u64;
            program_kept += p.kept as u64;
            program_fronts += p.fronts as u64;
            program_nodes += p.nodes as u64;
        }
        triangles.extend(r.triangles.iter().map(|t| t.map(|v| order[v as usize])));
    }
    diagnostics.add("faces", regions.len() as u64);
    diagnostics.add("faces by polygon program", polygons);
    diagnostics.add("faces with holes or inner points", holes);
    diagnostics.add("faces by exact search", searched);
    diagnostics.add("faces unsolved", unsolved);
    diagnostics.add("largest face", largest);
    diagnostics.add("search fronts", fronts);
    diagnostics.add("faces by triangle program", programs);
    diagnostics.add("program triangles", program_triangles);
    diagnostics.add("program triangles kept", program_kept);
    diagnostics.add("program search fronts", program_fronts);
    diagnostics.add("program branch nodes", program_nodes);
    let mut triangulation = Triangulation::from_distinct(points, triangles);
    let mut algorithm = "diamond filter, LMT-skeleton, Klincsek program on simple faces, exact front search on the others".to_string();
    let lower_bound;
    if exact {
        lower_bound = 0.0; // unused: the bound of an exact result is its weight
    } else {
        // Keep the lightest of the result, Delaunay and greedy (exactly);
        // without greedy if the time limit stops it.
        let delaunay = crate::graphs::delaunay(points)?;
        let (name, best) = match greedy_within(points, bounds.stop)? {
            Some(greedy) => lightest(
                points,
                [
                    ("result", triangulation),
                    ("Delaunay", delaunay),
                    ("greedy", greedy),
                ],
            ),
            None => lightest(points, [("result", triangulation), ("Delaunay", delaunay)]),
        };
        if name != "result" {
            algorithm =
                format!("{algorithm}; not proven optimal, the {name} triangulation is lighter");
        }
        triangulation = Triangulation::from_distinct(points, best);
        // Lower bound: the certain edges, the solved faces' inner edges
        // (their optimum) and the unsolved faces' bounds (in Z-order, as
        // the skeleton and the regions).
        let mut solved_weight = LengthInterval::ZERO;
        for r in regions.iter().filter(|r| r.method != Method::Fallback) {
            for e in region_inner_edges(&r.triangles, &sk) {
                solved_weight = solved_weight.plus(LengthInterval::of_segment(
                    pts[e[0] as usize],
                    pts[e[1] as usize],
                ));
            }
        }
        let mut certain_weight = LengthInterval::ZERO;
        for (e, &[u, v]) in sk.edges.iter().enumerate() {
            if sk.certain[e] {
                certain_weight = certain_weight
                    .plus(LengthInterval::of_segment(pts[u as usize], pts[v as usize]));
            }
        }
        lower_bound = certain_weight.plus(solved_weight).plus(lower).lo;
        algorithm = format!(
            "{algorithm}; certified lower bound on the optimal weight: {lower_bound} \
             (certain edges, solved faces, the shortest candidates of unsolved faces)"
        );
    }
    watch.lap("assemble");
    diagnostics.add("exact", exact as u64);
    Ok(General {
        solved: Solved {
            triangulation,
            algorithm,
            optimality: if exact {
                Optimality::Exact
            } else {
                Optimality::Approximation {
                    bound: "not proven optimal: a face exceeded the exact search's budget; the weight is at least the reported lower bound",
                }
            },
            diagnostics,
            // Not proven optimal: the certified lower bound on the optimal
            // weight, so the gap to the result's weight is known.
            bound: (!exact).then_some(CertifiedBound {
                measure: BoundMeasure::TotalLength,
                triangle: None,
                value: lower_bound,
                upper: false,
            }),
            approximation: None,
        },
        // When exact the bound is the result's weight, summed only where it
        // is read (the test hooks): a sort of all edges otherwise.
        lower_bound: (!exact).then_some(lower_bound),
    })
}

/// The inner (non-certain) edges of a region's triangles.
fn region_inner_edges(triangles: &[[u32; 3]], sk: &skeleton::Skeleton) -> Vec<[u32; 2]> {
    edges_of(triangles)
        .into_iter()
        .filter(|&[u, v]| !sk.edge_id(u, v).is_some_and(|e| sk.certain[e as usize]))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::Interruption;

    /// Integer points rounded from a circle (nearly convex: some fall
    /// inside the hull), and a few inside.
    fn rounded_circle(n: usize, radius: f64) -> PointSet {
        let mut pts: Vec<Point> = (0..n)
            .map(|k| {
                let t = std::f64::consts::TAU * k as f64 / n as f64;
                [(radius * t.cos()).round(), (radius * t.sin()).round()]
            })
            .collect();
        pts.extend([[0.0, 0.0], [3.0, 1.0], [-2.0, 5.0]]);
        PointSet::new(&pts).unwrap()
    }

    fn weight(t: &Triangulation) -> f64 {
        t.stats().total_edge_length
    }

    /// The answer without the exact result: valid, not exact, no heavier
    /// than greedy (unless the stop ended greedy first, which the algorithm
    /// text says: a loaded machine may spend the grace) and Delaunay
    /// (compared exactly), with a lower bound.
    fn check_fallback(points: &PointSet, solved: &Solved) {
        solved.triangulation.validate().unwrap();
        assert!(!solved.optimality.is_exact());
        let tris = distinct_triangles(points, &solved.triangulation);
        let greedy_stopped = solved
            .algorithm
            .starts_with("Delaunay triangulation, the time limit stopped");
        let mut others = vec![crate::graphs::delaunay(points).unwrap()];
        if !greedy_stopped {
            others.push(crate::criteria::greedy::greedy(points).unwrap());
        }
        for other in others {
            let o = distinct_triangles(points, &other);
            assert_ne!(
                compare_weights(points.points(), &tris, &o),
                Ordering::Greater
            );
        }
        let bound = solved.bound.as_ref().expect("a lower bound").value;
        assert!(0.0 < bound && bound <= weight(&solved.triangulation));
    }

    #[test]
    fn a_skeleton_over_its_memory_budget_answers_greedy_or_delaunay() {
        let points = rounded_circle(60, 40.0);
        let exact = general_min_weight(&points, &mut Vec::new(), FRONT_BUDGET).unwrap();
        assert!(exact.solved.optimality.is_exact());
        let bounds = Bounds {
            fronts: FRONT_BUDGET,
            bytes: 0,
            stop: &Stop::default(),
        };
        let refused = general_min_weight_within(&points, &mut Vec::new(), bounds).unwrap();
        check_fallback(&points, &refused.solved);
        assert!(refused.solved.algorithm.contains("memory budget"));
        assert!(refused.lower_bound.unwrap() <= weight(&exact.solved.triangulation));
        // The default budget takes this set.
        let bounds = Bounds {
            bytes: skeleton::default_budget(points.len()),
            ..bounds
        };
        let within = general_min_weight_within(&points, &mut Vec::new(), bounds).unwrap();
        assert_eq!(
            within.solved.triangulation.triangles(),
            exact.solved.triangulation.triangles()
        );
    }

    #[test]
    fn a_spent_time_limit_answers_greedy_or_delaunay_and_a_cancel_stops() {
        let general = rounded_circle(40, 30.0);
        let convex = PointSet::new(
            &(0..30)
                .map(|x| [x as f64, (x * x) as f64])
                .collect::<Vec<Point>>(),
        )
        .unwrap();
        for points in [&general, &convex] {
            let out_of_time = Options::default()
                .with_time_limit(std::time::Duration::ZERO)
                .started();
            let solved = solve(points, &out_of_time, &mut Vec::new()).unwrap();
            check_fallback(points, &solved);
            assert!(solved.algorithm.contains("time limit"));
            let cancel = crate::Cancel::new();
            let cancelled = Options::default().with_cancel(cancel.clone()).started();
            cancel.cancel();
            assert!(matches!(
                solve(points, &cancelled, &mut Vec::new()),
                Err(Error::Interrupted(Interruption::Cancelled))
            ));
            let unbounded = Options::default().started();
            assert!(solve(points, &unbounded, &mut Vec::new())
                .unwrap()
                .optimality
                .is_exact());
        }
    }

    /// A spent stop stops the greedy triangulation of the fallback, which
    /// then answers the Delaunay triangulation with the same bound.
    #[test]
    fn a_spent_stop_leaves_the_fallback_with_delaunay() {
        let points = rounded_circle(200, 100.0);
        let hull = convex_hull_cycle(points.points());
        let spent = Stop::starting_now(None, Some(std::time::Duration::ZERO));
        let solved = lighter_of_greedy_and_delaunay(&points, &hull, "why", &spent).unwrap();
        solved.triangulation.validate().unwrap();
        assert!(!solved.optimality.is_exact());
        assert!(solved
            .algorithm
            .starts_with("Delaunay triangulation, the time limit stopped"));
        assert_eq!(
            distinct_triangles(&points, &solved.triangulation),
            distinct_triangles(&points, &crate::graphs::delaunay(&points).unwrap())
        );
        let running =
            lighter_of_greedy_and_delaunay(&points, &hull, "why", &Stop::default()).unwrap();
        check_fallback(&points, &running);
        assert_eq!(solved.bound, running.bound);
        // A cancellation is an error.
        let cancel = crate::Cancel::new();
        cancel.cancel();
        let cancelled = Stop::starting_now(Some(cancel), None);
        assert!(matches!(
            lighter_of_greedy_and_delaunay(&points, &hull, "why", &cancelled),
            Err(Error::Interrupted(Interruption::Cancelled))
        ));
    }

    /// A time limit of 1 ms on 20 000 points in convex position, not
    /// semicircular (beyond the program: the fallback at once, whose greedy
    /// triangulation takes seconds) and on 20 000 points near a circle with a few inside (the
    /// general pipeline) returns a result that is not exact.
    #[test]
    fn a_tiny_time_limit_returns_on_large_sets() {
        let convex = optri_oracle::inputs::convex_lens_evenly_spaced(20_000);
        for points in [PointSet::new(&convex).unwrap(), rounded_circle(20_000, 1e6)] {
            let limited = Options::default()
                .with_time_limit(std::time::Duration::from_millis(1))
                .started();
            match solve(&points, &limited, &mut Vec::new()) {
                Ok(solved) => {
                    assert!(!solved.optimality.is_exact());
                    solved.triangulation.validate().unwrap();
                }
                Err(e) => assert!(matches!(e, Error::Interrupted(_)), "{e}"),
            }
        }
    }
}
