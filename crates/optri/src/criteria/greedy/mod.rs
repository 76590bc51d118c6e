//! The greedy triangulation GT(S): repeatedly add the shortest segment
//! between two points that crosses no segment already added and passes
//! through no other point (C. Levcopoulos & A. Lingas, *On approximation
//! behavior of the greedy triangulation for convex polygons*, Algorithmica 2
//! (1987), §1; T. S. Vassilev, *Optimal area triangulation*, PhD thesis,
//! University of Saskatchewan (2005), Definition 16).
//!
//! # Order and ties
//! Segments are ordered by [`crate::kernel::segment_order`]: exact squared
//! length, ties broken by the simulation-of-simplicity perturbation of
//! [the kernel's perturbation](crate::kernel#ties-symbolic-perturbation). That is a total order on segments, so GT is
//! unique and every algorithm here returns the same edges. A segment with
//! another point on its open interior is never added (exact orientation plus a
//! betweenness test), so collinear points never produce overlapping edges.
//!
//! # Algorithms (dispatched by [`greedy_triangulation`])
//! | input | algorithm | module |
//! |---|---|---|
//! | a fan: all points but one on a line (weakly convex) | its only triangulation, O(n log n) | `general::single_fan` |
//! | semicircular convex polygon (§1 conditions (i), (ii)) | ear heap, Thm 4.3, O(n log n) | [`semicircular`](self) |
//! | convex position, strictly or weakly (points on hull edges) | recursive splitting, Thm 4.2, O(n) space | [`convex`](self) |
//! | anything else | length rounds with closed-vertex retirement | [`general`](self) |
//!
//! The result is the same in every case; the tests check that edge for edge.
//! Section and theorem numbers (§1, Fact 3.1, Thm 4.2, Thm 4.3) are
//! Levcopoulos & Lingas's; the general algorithm follows M. T. Dickerson,
//! R. L. S. Drysdale, S. A. McElfresh & E. Welzl, *Fast greedy triangulation
//! algorithms*, Computational Geometry 8 (1997) (see `general`).

mod convex;
mod convex_delaunay;
mod general;
pub(crate) mod polygon;
mod semicircular;

use super::{CriterionEntry, CriterionInfo, Diagnostics, Optimality, Options, Solved};
use crate::error::Result;
use crate::interrupt::Stop;
use crate::kernel::{orient_sign, Point};
use crate::spatial::convex_hull_cycle;
use crate::structures::{PlanarGraph, PointSet, Triangulation};
use crate::timing::{Phase, Stopwatch};

/// The registry's entry: this criterion's description and solvers.
pub(crate) const ENTRY: CriterionEntry = CriterionEntry {
    info: INFO,
    solve,
    solve_polygon: Some(polygon::solve),
};

pub(crate) const INFO: CriterionInfo = CriterionInfo {
    name: "greedy",
    description: "greedy: repeatedly adds the shortest segment crossing no earlier one",
    optimality: Optimality::Exact,
    options: &[],
    reference: "C. Levcopoulos & A. Lingas, On approximation behavior of the greedy \
                triangulation for convex polygons, Algorithmica 1987; M. T. Dickerson, \
                R. L. S. Drysdale, S. A. McElfresh & E. Welzl, Fast greedy triangulation \
                algorithms, 1997",
    needs_elevations: false,
    measure: None,
};

pub(crate) fn solve(
    points: &PointSet,
    options: &Options,
    phases: &mut Vec<Phase>,
) -> Result<Solved> {
    let (triangulation, algorithm) = greedy_triangulation_timed(points, options.stop(), phases)?;
    Ok(Solved {
        triangulation,
        algorithm: format!("{} ({})", algorithm.name(), algorithm.description()),
        optimality: Optimality::Exact,
        diagnostics: Diagnostics::default(),
        bound: None,
        approximation: None,
    })
}

/// Which greedy-triangulation algorithm ran.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum GreedyAlgorithm {
    /// Heap of ear diagonals for semicircular convex polygons (Thm 4.3).
    Semicircular,
    /// Recursive splitting along shortest diagonals (Thm 4.2).
    Convex,
    /// Length rounds over candidate pairs with closed-vertex retirement.
    General,
    /// All points but one on a line: the only triangulation.
    Fan,
}

impl GreedyAlgorithm {
    /// Short name used in [`crate::Solution::algorithm`].
    pub fn name(self) -> &'static str {
        match self {
            GreedyAlgorithm::Semicircular => "semicircular",
            GreedyAlgorithm::Convex => "convex",
            GreedyAlgorithm::General => "general",
            GreedyAlgorithm::Fan => "fan",
        }
    }

    /// What the algorithm does, with its paper and bound.
    pub fn description(self) -> &'static str {
        match self {
            GreedyAlgorithm::Semicircular => {
                "ear heap for semicircular polygons, Levcopoulos-Lingas Thm 4.3, O(n log n)"
            }
            GreedyAlgorithm::Convex => {
                "recursive splitting for convex position, Levcopoulos-Lingas Thm 4.2, expected O(n^2) time (Chew's convex-polygon Delaunay), O(n) space"
            }
            GreedyAlgorithm::General => {
                "exact length rounds decided by crossing dependencies (DDMW-style candidates, closed-vertex retirement)"
            }
            GreedyAlgorithm::Fan => {
                "all points but one on a line: the only triangulation, O(n log n)"
            }
        }
    }
}

/// The greedy triangulation of `points`, with the algorithm chosen by the
/// shape of the input.
pub fn greedy_triangulation(points: &PointSet) -> Result<(Triangulation, GreedyAlgorithm)> {
    greedy_triangulation_timed(points, &Stop::default(), &mut Vec::new())
}

/// [`greedy_triangulation`], recording its phases; stopped by `stop`
/// ([`crate::Error::Interrupted`]) in the convex and general algorithms.
pub(crate) fn greedy_triangulation_timed(
    points: &PointSet,
    stop: &Stop,
    phases: &mut Vec<Phase>,
) -> Result<(Triangulation, GreedyAlgorithm)> {
    let mut stopwatch = Stopwatch::new(phases);
    let pts = points.points();
    // One hull for the shape test and the general algorithm's boundary.
    let hull = convex_hull_cycle(pts);
    let (triangles, algorithm) = match weakly_convex_polygon(pts, &hull) {
        Some(straight_angles) => {
            // A fan is weakly convex (its line lies on one hull edge); its
            // only triangulation is returned in O(n log n) instead of Thm
            // 4.2's expected O(n²) (10⁵ points: 3.3 s).
            let fan = straight_angles.then(|| general::single_fan(pts)).flatten();
            // Thm 4.3's ear heap assumes a strictly convex polygon.
            let rotated = (!straight_angles)
                .then(|| semicircular::base_rotation(pts, &hull))
                .flatten();
            match (fan, rotated) {
                (Some(fan), _) => (fan, GreedyAlgorithm::Fan),
                (None, Some(rotated)) => (
                    triangles_of(pts, &semicircular::greedy_semicircular(pts, &rotated)),
                    GreedyAlgorithm::Semicircular,
                ),
                (None, None) => (
                    triangles_of(
                        pts,
                        &convex::greedy_convex(pts, &hull, straight_angles, stop)?,
                    ),
                    GreedyAlgorithm::Convex,
                ),
            }
        }
        None => {
            stopwatch.lap("shape test");
            let triangles =
                stopwatch.nested(|phases| general::greedy_general(pts, &hull, stop, phases))?;
            (triangles, GreedyAlgorithm::General)
        }
    };
    let triangulation = Triangulation::from_distinct(points, triangles);
    stopwatch.lap(match algorithm {
        GreedyAlgorithm::General => "output",
        _ => "greedy",
    });
    Ok((triangulation, algorithm))
}

/// The greedy triangulation of `points` (see the module docs).
pub(crate) fn greedy(points: &PointSet) -> Result<Triangulation> {
    greedy_triangulation(points).map(|(t, _)| t)
}

/// GT by one named algorithm, as distinct-index edges `[min, max]`, sorted.
/// `Convex` returns `None` when the input is not in (weakly) convex
/// position, `Semicircular` when it is not a semicircular strictly convex
/// polygon, `Fan` when not all points but one lie on a line. For tests and benchmarks.
#[cfg(any(test, feature = "internals"))]
pub fn greedy_edges_by(points: &PointSet, algorithm: GreedyAlgorithm) -> Option<Vec<[u32; 2]>> {
    let pts = points.points();
    // `Triangulation::edges` works on input indices; map them back.
    let distinct_edges = |triangles: Vec<[u32; 3]>| -> Vec<[u32; 2]> {
        Triangulation::from_distinct(points, triangles)
            .edges()
            .into_iter()
            .map(|e| e.map(|i| points.distinct_index(i)))
            .collect()
    };
    let edges = match algorithm {
        GreedyAlgorithm::General => distinct_edges(
            general::greedy_general(
                pts,
                &convex_hull_cycle(pts),
                &Stop::default(),
                &mut Vec::new(),
            )
            .ok()?,
        ),
        GreedyAlgorithm::Convex => {
            let polygon = convex_hull_cycle(pts);
            let straight_angles = weakly_convex_polygon(pts, &polygon)?;
            convex::greedy_convex(pts, &polygon, straight_angles, &Stop::default()).ok()?
        }
        GreedyAlgorithm::Semicircular => {
            let rotated = semicircular::base_rotation(pts, &convex_polygon(pts)?)?;
            semicircular::greedy_semicircular(pts, &rotated)
        }
        GreedyAlgorithm::Fan => distinct_edges(general::single_fan(pts)?),
    };
    Some(normalized(edges))
}

/// Test reference: sort all segments by the global order and add each one
/// that crosses no added segment and contains no point, checking against
/// every added segment. O(n³) worst case, O(n²) memory; distinct-index edges,
/// sorted. Not for production use.
#[cfg(any(test, feature = "internals"))]
pub fn greedy_naive_edges(points: &PointSet) -> Vec<[u32; 2]> {
    use crate::kernel::{on_open_segment, properly_cross};
    let pts = points.points();
    let n = pts.len() as u32;
    let mut segments: Vec<[u32; 2]> = Vec::with_capacity((n as usize) * (n as usize - 1) / 2);
    for a in 0..n {
        for b in a + 1..n {
            segments.push([a, b]);
        }
    }
    crate::spatial::sort_by_length(pts, crate::kernel::EuclideanOrder, &mut segments);
    let p = |i: u32| pts[i as usize];
    let mut added: Vec<[u32; 2]> = Vec::new();
    for [a, b] in segments {
        // Most long segments cross a recent short edge; scan newest first.
        let crossing = added
            .iter()
            .rev()
            .any(|&[c, d]| properly_cross(p(a), p(b), p(c), p(d)));
        if crossing {
            continue;
        }
        if (0..n).any(|z| z != a && z != b && on_open_segment(p(z), p(a), p(b))) {
            continue;
        }
        added.push([a, b]);
    }
    normalized(added)
}

/// Edges as sorted `[min, max]` pairs, sorted.
#[cfg(any(test, feature = "internals"))]
pub(crate) fn normalized(mut edges: Vec<[u32; 2]>) -> Vec<[u32; 2]> {
    for e in &mut edges {
        if e[0] > e[1] {
            e.swap(0, 1);
        }
    }
    edges.sort_unstable();
    edges
}

/// The triangles of a full triangulation given by its edges.
pub(crate) fn triangles_of(points: &[Point], edges: &[[u32; 2]]) -> Vec<[u32; 3]> {
    PlanarGraph::new(points, edges)
        .bounded_faces(points)
        .into_iter()
        .map(|f| {
            debug_assert_eq!(f.vertices.len(), 3, "a greedy face is not a triangle");
            [f.vertices[0], f.vertices[1], f.vertices[2]]
        })
        .collect()
}

/// The hull as a strictly convex polygon (ccw), or `None` if some point is
/// not a hull vertex or three hull vertices are collinear (the inputs of the
/// semicircular algorithm, Levcopoulos & Lingas §1).
#[cfg(any(test, feature = "internals"))]
pub(crate) fn convex_polygon(points: &[Point]) -> Option<Vec<u32>> {
    let hull = convex_hull_cycle(points);
    if hull.len() != points.len() {
        return None;
    }
    crate::spatial::is_strictly_convex_cycle(points, &hull).then_some(hull)
}

/// Given `hull`, the [`convex_hull_cycle`] of `points` (ccw, points on hull
/// edges included): when every point is on it and they are not all
/// collinear, whether some vertex has a straight angle (weakly, not
/// strictly, convex position). The convex algorithm's module docs explain
/// why GT is then still the splitting of this polygon.
fn weakly_convex_polygon(points: &[Point], hull: &[u32]) -> Option<bool> {
    let k = hull.len();
    if k < 3 || k != points.len() {
        return None;
    }
    let p = |c: usize| points[hull[c % k] as usize];
    let (mut left, mut straight) = (false, false);
    for c in 0..k {
        match orient_sign(p(c), p(c + 1), p(c + 2)) {
            1.. => left = true,
            0 => straight = true,
            // A hull cycle never turns right; keep the general algorithm
            // if it ever did.
            _ => return None,
        }
    }
    left.then_some(straight)
}

/// Are all points on the boundary of their convex hull, not all on one line
/// (weakly convex position: [`greedy_triangulation`] runs the convex
/// algorithm)?
#[cfg(any(test, feature = "internals"))]
pub fn is_weakly_convex_position(points: &PointSet) -> bool {
    let points = points.points();
    weakly_convex_polygon(points, &convex_hull_cycle(points)).is_some()
}

/// Is every point a vertex of a strictly convex polygon (no three collinear)?
#[cfg(any(test, feature = "internals"))]
pub fn is_convex_position(points: &PointSet) -> bool {
    convex_polygon(points.points()).is_some()
}

/// Is the input a semicircular convex polygon (Levcopoulos & Lingas §1: the two farthest
/// vertices are the endpoints of an edge, and every other vertex lies strictly
/// inside the circle with that edge as diameter)?
#[cfg(any(test, feature = "internals"))]
pub fn is_semicircular(points: &PointSet) -> bool {
    let pts = points.points();
    convex_polygon(pts).is_some_and(|poly| semicircular::base_rotation(pts, &poly).is_some())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::{Error, Interruption};
    use crate::structures::SimplePolygon;
    use rand::{rngs::StdRng, Rng, SeedableRng};

    /// A star polygon: `2k` vertices alternating between radius `scale`
    /// and `0.4 scale`, rounded to integers.
    fn star(k: usize, scale: f64) -> Vec<Point> {
        (0..2 * k)
            .map(|i| {
                let r = if i % 2 == 0 { scale } else { 0.4 * scale };
                let a = std::f64::consts::PI * i as f64 / k as f64;
                [(r * a.cos()).round(), (r * a.sin()).round()]
            })
            .collect()
    }

    /// The general rounds, the convex splitting and the polygon scan stop
    /// when the cancel flag is raised or the time limit is 0 s (the registry
    /// checks before a run starts; these call the solvers directly).
    #[test]
    fn a_stopped_run_stops_each_greedy_solver() {
        let mut rng = StdRng::seed_from_u64(0x6EED_5709);
        let scattered: Vec<Point> = (0..300)
            .map(|_| [rng.gen_range(0..1000) as f64, rng.gen_range(0..1000) as f64])
            .collect();
        let scattered = PointSet::new(&scattered).unwrap();
        // A full circle is in convex position but not semicircular.
        let circle = PointSet::new(&optri_oracle::inputs::sampled_circle(64, 1e6)).unwrap();
        assert!(is_weakly_convex_position(&circle) && !is_semicircular(&circle));
        let star = SimplePolygon::new(&star(30, 1000.0)).unwrap();
        let cancel = crate::Cancel::new();
        cancel.cancel();
        let stops = [
            (
                Options::default().with_cancel(cancel),
                Interruption::Cancelled,
            ),
            (
                Options::default().with_time_limit(std::time::Duration::ZERO),
                Interruption::TimeLimit { seconds: 0.0 },
            ),
        ];
        for (options, why) in stops {
            let options = options.started();
            let stopped = Err(Error::Interrupted(why));
            for points in [&scattered, &circle] {
                assert_eq!(
                    solve(points, &options, &mut Vec::new()).map(|_| ()),
                    stopped
                );
            }
            assert_eq!(
                polygon::solve(&star, &options, &mut Vec::new()).map(|_| ()),
                stopped
            );
        }
        let never = Options::default();
        assert!(solve(&scattered, &never, &mut Vec::new()).is_ok());
        assert!(polygon::solve(&star, &never, &mut Vec::new()).is_ok());
    }

    /// Polygons above the chord list's limit are refused before anything is
    /// allocated.
    #[test]
    fn polygons_above_the_chord_limit_are_refused() {
        let n = polygon::MAX_GREEDY_POLYGON_VERTICES / 2 + 1;
        let star = SimplePolygon::new(&star(n, 1e6)).unwrap();
        let result = polygon::solve(&star, &Options::default(), &mut Vec::new()).map(|_| ());
        assert!(
            matches!(
                result,
                Err(Error::Unsupported {
                    reason: crate::error::UnsupportedReason::TooManyPoints { .. },
                    ..
                })
            ),
            "{result:?}"
        );
    }
}
