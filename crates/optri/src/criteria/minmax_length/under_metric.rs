//! Minmax-length triangulation under a normed metric: Edelsbrunner & Tan,
//! *A quadratic time algorithm for the minmax length triangulation* (1991),
//! §7 (General Subgraph Theorem, General MinMax Length Theorem).
//!
//! Lengths are compared by [`Metric::compare_lengths_symbolic`]: the metric
//! simulated by a strictly convex norm on the kernel's perturbed points `S′`
//! (kernel norm docs), so §7's theorems apply to `(S′, N)` and every decision
//! comes from that one configuration.
//!
//! 1. `rng_N(S′)` by the sector approach ([`crate::graphs::rng_under`]). It is
//!    plane *exactly*: a proper crossing in `S` persists in `S′`, where the
//!    RNG of a strictly convex norm is plane, and a point on the open segment
//!    `pq` lies in `pq`'s lune. So the regions of `ch(S) ∪ rng_N(S′)` are
//!    found by the planar-graph face walk without perturbation.
//! 2. Each region of at least [`QUADRATIC_FROM`] corners:
//!    * *incomplete* (the one non-RNG edge `pq` is a hull edge, a 1-edge
//!      with the region beyond it): §5.1 with the remark's vertex choice
//!      (the lune vertex visible from `p` and `q` minimising
//!      `max(|xp|, |xq|)`, recursing on both sides) — this avoids §7's
//!      point-to-segment distance; O(k²) on convex regions (all visible),
//!      plus the O(k) visibility tests otherwise;
//!    * *complete* (every edge in `rng_N(S′)`): the Euclidean product's
//!      §5.3/§6 algorithm ([`super::rng_polygon`]) under the metric's order
//!      (the kernel's `LengthOrder` of a [`Metric`]: the simulated norm's
//!      comparisons, lunes and
//!      half-lunes, and in §5.1 the remark's choice again, its visibility
//!      checked in O(k) where the region is not convex). O(k²). Its
//!      visibility walk needs a triangulation of the region: a fan if the
//!      region is strictly convex (convex position), else the Euclidean
//!      Delaunay triangles with the metric's RNG edges marked, which tile
//!      the region only if its boundary edges are Delaunay edges; other
//!      complete regions (`complete_regions_outside_mesh`: reflex corners
//!      and an RNG chord that is not a Delaunay edge) are tiled by ear
//!      clipping, O(k·r) for `r` reflex corners
//!      ([`RngPolygon::ear_clipped`]); a failure of any step sends the
//!      region to the cubic program (`fallbacks`).
//!
//!    Every other region goes to §3's exact cubic program with the metric's
//!    chord order. **Not proven here:** §7 asserts that §5–§6 carry over to
//!    strictly convex norms "after careful re-examination" without giving
//!    it. §5.1's invariant holds for any visible lune vertex (the remark);
//!    the stack scan's half-lune classification, the Crossing-Lemma partner
//!    test and Case 2's Claims 1–5 are used as the Euclidean proofs have
//!    them and are *tested only*: against the cubic program and exhaustive
//!    enumeration under L1, L∞, L3 and a hexagonal norm
//!    (tests/minmax_length_metric.rs, tests/minmax_length_metric_complete.rs,
//!    convex position full of ties included), with the safety nets asserted
//!    silent. The nets stay: an invariant failure (`Inconsistent`) sends the
//!    region to the cubic program (`fallbacks`), a Case 2 pocket or
//!    remainder failing its check likewise (`case_2_pocket_fallbacks`,
//!    `case_2_hull_fallbacks`); a wrong step that no check detects would
//!    give a non-optimal result, which is what the tests look for.
//! 3. §5.4's repair of flat triangles: a point on segment `uw` is no farther
//!    from `y` than `max(|uy|, |wy|)` in every norm (convexity), so the
//!    longest edge does not grow.
//!
//! **Hull certificate** (before step 1, in the product only): every
//! triangulation of `S` contains the hull's boundary segments (between
//! consecutive hull points, collinear ones included), so the longest of
//! them *in the metric* is a lower bound on the optimum, in every norm.
//! The Euclidean Delaunay triangulation is a triangulation of `S`; if
//! none of its edges is longer in the metric than that bound (compared
//! exactly by [`Metric::compare_norm`], no tie-break needed: both are real
//! lengths of `S`), it is optimal and is returned. This is the hull half
//! of the Euclidean path's Length-Lemma certificate; the RNG half (§4's
//! Length Lemma) is not used, since nothing here proves it for other
//! norms. On uniform points in a square the hull has long edges and the
//! certificate holds (BENCHMARKS.md); otherwise its cost is one Delaunay
//! triangulation and one pass over its edges.

use super::counters::{Count, Counters};
use super::fallback::cubic_program;
use super::polygon::Region;
use super::repair::repair_flat_triangles;
use super::rng_polygon::{Mesh, RngPolygon};
use crate::criteria::Diagnostics;
use crate::error::Result;
use crate::graphs::rng_under;
use crate::interrupt::Stop;
use crate::kernel::Metric;
use crate::parallel::prelude::*;
use crate::spatial::convex_hull_cycle;
use crate::structures::{DelaunayGraph, PlanarGraph, PointSet, Triangulation};
use crate::timing::{timed, Phase};
use std::cmp::Ordering;
use std::collections::HashSet;

/// Which polygon method the regions use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum MetricMethod {
    /// On regions of at least `quadratic_from` corners: §5.1 if incomplete,
    /// §5.3/§6 if complete (where the Delaunay triangles tile the region);
    /// the cubic program on the rest. With `certify`, the hull certificate
    /// first (module docs, hull certificate).
    Product {
        quadratic_from: usize,
        certify: bool,
    },
    /// The cubic program on every region (test reference).
    #[cfg_attr(not(any(test, feature = "internals")), allow(dead_code))]
    Cubic,
}

/// Regions of at least this many corners use §5.1 or §5.3/§6.
pub(crate) const QUADRATIC_FROM: usize = 16;

/// Does the face's boundary walk visit every corner once?
fn distinct_corners(face: &[u32]) -> bool {
    let mut seen = HashSet::with_capacity(face.len());
    face.iter().all(|&w| seen.insert(w))
}

/// Regions per check of the stop in the polygon phase (and before every
/// region of at least [`LARGE_REGION`] corners).
const REGIONS_PER_CHECK: usize = 1024;

/// Regions from this many corners read the stop before they start.
const LARGE_REGION: usize = 64;

/// The pipeline of the module docs with `method` on the regions; stopped by
/// `stop` ([`crate::Error::Interrupted`]) between the phases, in the RNG's
/// searches and in the region loop.
pub(crate) fn run_under(
    points: &PointSet,
    metric: &Metric,
    method: MetricMethod,
    stop: &Stop,
    phases: &mut Vec<Phase>,
) -> Result<(Triangulation, Diagnostics)> {
    let pts = points.points();
    if matches!(method, MetricMethod::Product { certify: true, .. }) {
        if let Some(t) = hull_certificate(points, metric, phases) {
            let mut diagnostics = Counters::default().into_diagnostics_for_metric();
            diagnostics.add("regions_certified_by_bound", 1);
            return Ok((t, diagnostics));
        }
    }
    stop.check()?;
    let rng = timed(phases, "rng", || rng_under(pts, metric, stop))?;
    let hull = timed(phases, "hull", || convex_hull_cycle(pts));
    let (faces, rng_set) = timed(phases, "regions", || {
        let rng_set: HashSet<[u32; 2]> = rng.iter().map(|e| key(e[0], e[1])).collect();
        let mut edges = rng.clone();
        for i in 0..hull.len() {
            edges.push(key(hull[i], hull[(i + 1) % hull.len()]));
        }
        edges.sort_unstable();
        edges.dedup();
        let faces: Vec<Vec<u32>> = PlanarGraph::new(pts, &edges)
            .bounded_faces(pts)
            .into_iter()
            .map(|f| f.vertices)
            .collect();
        (faces, rng_set)
    });
    stop.check()?;
    let quadratic_from = match method {
        MetricMethod::Product { quadratic_from, .. } => Some(quadratic_from.max(4)),
        MetricMethod::Cubic => None,
    };
    // The boundary positions `i` whose edge `v[i] v[i+1]` is not in the RNG.
    let missing = |face: &[u32]| -> Vec<usize> {
        let k = face.len();
        (0..k)
            .filter(|&i| !rng_set.contains(&key(face[i], face[(i + 1) % k])))
            .collect()
    };
    // The Delaunay triangles with the metric's RNG edges marked, for §6's
    // visibility walk; only if some large complete region needs them.
    let delaunay = timed(phases, "mesh", || {
        let needed = quadratic_from.is_some_and(|from| {
            faces.iter().any(|f| {
                f.len() >= from
                    && missing(f).is_empty()
                    && !Region {
                        points: pts,
                        vertices: f,
                        symbolic: true,
                    }
                    .is_strictly_convex()
            })
        });
        let g = needed.then(|| DelaunayGraph::with_topology(pts).ok())??;
        let flags: Vec<bool> = g
            .edges
            .iter()
            .map(|(e, _)| rng_set.contains(&key(e[0], e[1])))
            .collect();
        Some((g, flags))
    });
    let mesh = delaunay.as_ref().map(|(g, flags)| Mesh::new(g, flags));
    let counters = Counters::default();
    let (by_5_1, by_5_3, outside_mesh) = (Count::default(), Count::default(), Count::default());
    let order = metric;
    let triangles: Vec<[u32; 3]> = timed(phases, "polygons", || {
        faces
            .par_iter()
            .enumerate()
            .flat_map_iter(|(f, face)| {
                let k = face.len();
                // A stopped run skips the rest and fails after the phase.
                if (f.is_multiple_of(REGIONS_PER_CHECK) || k >= LARGE_REGION)
                    && stop.reason().is_some()
                {
                    return Vec::new();
                }
                let region = Region {
                    points: pts,
                    vertices: face,
                    symbolic: true,
                };
                if quadratic_from.is_some_and(|from| k >= from) {
                    match missing(face)[..] {
                        [i] => {
                            let convex = region.is_strictly_convex();
                            if let Some(t) = incomplete(&region, metric, convex, (i + 1) % k) {
                                by_5_1.add(1);
                                return t;
                            }
                            counters.fallbacks.add(1);
                        }
                        [] => {
                            let polygon = if region.is_strictly_convex() {
                                RngPolygon::convex_fan(pts, face, &counters, order)
                            } else {
                                match mesh.as_ref().filter(|m| m.tiles(face)) {
                                    Some(m) => {
                                        RngPolygon::with_order(pts, face, m, &counters, order)
                                    }
                                    // A dangling edge walked twice repeats a
                                    // corner: no simple polygon to clip.
                                    None if !distinct_corners(face) => {
                                        return cubic_program(order, &region)
                                    }
                                    None => {
                                        outside_mesh.add(1);
                                        RngPolygon::ear_clipped(pts, face, &counters, order)
                                    }
                                }
                            };
                            if let Ok(t) = polygon.and_then(|f| f.triangulate()) {
                                by_5_3.add(1);
                                return t;
                            }
                            counters.fallbacks.add(1);
                        }
                        _ => {}
                    }
                }
                cubic_program(order, &region)
            })
            .collect()
    });
    stop.check()?;
    let triangles = timed(phases, "repair", || {
        repair_flat_triangles(pts, triangles, &counters)
    });
    let mut diagnostics = counters.into_diagnostics_for_metric();
    diagnostics.add("regions", faces.len() as u64);
    diagnostics.add("regions_by_5_1", by_5_1.get());
    diagnostics.add("regions_by_5_3", by_5_3.get());
    diagnostics.add("complete_regions_outside_mesh", outside_mesh.get());
    Ok((Triangulation::from_distinct(points, triangles), diagnostics))
}

/// An undirected edge as a sorted pair.
fn key(a: u32, b: u32) -> [u32; 2] {
    [a.min(b), a.max(b)]
}

/// The hull certificate of the module docs: the Euclidean Delaunay triangulation if none
/// of its edges is longer in `metric` than the longest hull segment (a lower
/// bound on every triangulation's longest edge). `None` when the bound is
/// not met, or the points have no Delaunay triangulation (all collinear).
fn hull_certificate(
    points: &PointSet,
    metric: &Metric,
    phases: &mut Vec<Phase>,
) -> Option<Triangulation> {
    let pts = points.points();
    let g = timed(phases, "delaunay", || DelaunayGraph::new(pts)).ok()?;
    let certified = timed(phases, "lower bound", || {
        let p = |v: u32| pts[v as usize];
        // Delaunay edges with a missing apex are exactly the hull segments.
        let longest_hull = g
            .edges
            .par_iter()
            .filter(|(_, apex)| apex.contains(&None))
            .map(|&(e, _)| e)
            .reduce_with(|a, b| {
                if metric.compare_norm(p(a[0]), p(a[1]), p(b[0]), p(b[1])) == Ordering::Less {
                    b
                } else {
                    a
                }
            })?;
        let (h0, h1) = (p(longest_hull[0]), p(longest_hull[1]));
        g.edges
            .par_iter()
            .all(|&([u, v], _)| metric.compare_norm(p(u), p(v), h0, h1) != Ordering::Greater)
            .then_some(())
    });
    certified?;
    Some(Triangulation::from_distinct(points, g.triangles))
}

/// §5.1 on a region whose only non-RNG edge ends at position `start` (the
/// edge from `start − 1` to `start`): the chain `c₀ = v[start], …,
/// c_{k−1} = v[start − 1]` with the 1-edge `c₀ c_{k−1}`. Step 1 takes, among
/// the vertices in the lune of `pq` that are visible from `p` and `q`, the
/// one minimising `max(|xp|, |xq|)` (the remark after §5.1: any visible lune
/// vertex keeps the recursion's invariant; in a convex region every vertex
/// is visible). `None` if no such vertex exists (an inconsistency: the
/// caller falls back to the cubic program).
fn incomplete(
    region: &Region,
    metric: &Metric,
    convex: bool,
    start: usize,
) -> Option<Vec<[u32; 3]>> {
    let points = region.points;
    let face = region.vertices;
    let k = face.len();
    let pos = |m: usize| (start + m) % k;
    let c: Vec<u32> = (0..k).map(|i| face[pos(i)]).collect();
    // Visible along the chain: a boundary edge, or a diagonal of the region
    // (which, sharing an endpoint with the sub-polygon's chord, stays inside
    // the sub-polygon).
    let sees = |a: usize, b: usize| {
        convex || b == a + 1 || a == b + 1 || region.is_diagonal(pos(a), pos(b))
    };
    let mut out = Vec::with_capacity(k - 2);
    let mut stack = vec![(0usize, k - 1)];
    let mut lune: Vec<(usize, [u32; 2])> = Vec::new();
    while let Some((i, j)) = stack.pop() {
        if j - i < 2 {
            continue;
        }
        let (p, q) = (c[i], c[j]);
        lune.clear();
        for (m, &x) in c.iter().enumerate().take(j).skip(i + 1) {
            if !metric.in_lune_symbolic(points, p, q, x) {
                continue;
            }
            let far = if metric.compare_lengths_symbolic(points, [x, p], [x, q]) == Ordering::Less {
                [x, q]
            } else {
                [x, p]
            };
            lune.push((m, far));
        }
        lune.sort_by(|a, b| metric.compare_lengths_symbolic(points, a.1, b.1));
        let &(m, _) = lune.iter().find(|&&(m, _)| sees(i, m) && sees(m, j))?;
        out.push([p, c[m], q]);
        stack.push((i, m));
        stack.push((m, j));
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::{Error, Interruption};
    use crate::interrupt::Cancel;
    use std::time::Duration;

    /// 20 000 points near a circle under L1 (the hull certificate fails:
    /// every chord is longer than the hull edges; the regions take minutes
    /// in a debug build): a time limit of 1 ms and a raised flag stop the
    /// run with [`Error::Interrupted`].
    #[test]
    fn a_tiny_time_limit_or_a_cancel_stops_the_run() {
        let points = PointSet::new(&optri_oracle::inputs::sampled_circle(20_000, 1e6)).unwrap();
        let method = MetricMethod::Product {
            quadratic_from: QUADRATIC_FROM,
            certify: true,
        };
        let limited = Stop::starting_now(None, Some(Duration::from_millis(1)));
        let result = run_under(&points, &Metric::l1(), method, &limited, &mut Vec::new());
        assert!(matches!(
            result,
            Err(Error::Interrupted(Interruption::TimeLimit { .. }))
        ));
        let cancel = Cancel::new();
        cancel.cancel();
        let cancelled = Stop::starting_now(Some(cancel), None);
        let result = run_under(&points, &Metric::l1(), method, &cancelled, &mut Vec::new());
        assert!(matches!(
            result,
            Err(Error::Interrupted(Interruption::Cancelled))
        ));
    }
}
