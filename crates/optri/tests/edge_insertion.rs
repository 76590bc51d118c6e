//! The edge-insertion criteria (`minmax-angle`, `maxmin-height`,
//! `minmax-eccentricity`, `minmax-slope`) against independent references:
//!
//! - the optimum **value** over every triangulation
//!   (`optri_oracle::bottleneck_measures`, exact rational badness in forms
//!   independent of optri's) on random, lattice, collinear-run, cocircular,
//!   convex and duplicate sets with n ≤ 9, and on simple polygons by
//!   enumerating their triangulations;
//! - the generic loop (`internals::edge_insertion_reference`, no memory of
//!   failed pairs) on larger sets, value for value;
//! - slope with degenerate elevations (z ∈ {0..3}: coplanar lifted
//!   quadruples and equal slopes are common), including the stall example of
//!   the plain acceptance test.
//!
//! Values, not triangulations, are compared: optima are rarely unique.
//! Every result passes `validate()` and is reported exact. Each test counts
//! its cases and asserts the count.

use optri::internals::{edge_insertion_reference, edge_insertion_worst_value};
use optri::kernel::Point;
use optri::{triangulate, Criterion, Error, PointSet, SimplePolygon, UnsupportedReason};
use optri_oracle::bottleneck_measures::{
    badness, bottleneck, optimum, optimum_over, polygon_optimum, Bottleneck,
};
use optri_oracle::polygon as op;
use optri_oracle::{all_triangulations, inputs, integer_circle_points, measures, BigRational};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

const CRITERIA: [(Criterion, Bottleneck); 4] = [
    (Criterion::MinMaxAngle, Bottleneck::MinMaxAngle),
    (Criterion::MaxMinHeight, Bottleneck::MaxMinHeight),
    (
        Criterion::MinMaxEccentricity,
        Bottleneck::MinMaxEccentricity,
    ),
    (Criterion::MinMaxSlope, Bottleneck::MinMaxSlope),
];

/// Elevations in {0..3} for every input point, equal on duplicates.
fn elevations(rng: &mut StdRng, points: &[Point]) -> Vec<f64> {
    let mut z: Vec<f64> = Vec::with_capacity(points.len());
    for (i, p) in points.iter().enumerate() {
        let earlier = points[..i].iter().position(|q| q == p);
        z.push(match earlier {
            Some(j) => z[j],
            None => rng.gen_range(0..4) as f64,
        });
    }
    z
}

/// The point set with elevations, or `None` when it has no triangulation.
fn point_set(points: &[Point], z: &[f64]) -> Option<PointSet> {
    PointSet::new(points).ok()?.with_elevations(z).ok()
}

/// Solves through the registry; checks validity and exactness; returns the
/// bottleneck of the result over the distinct points.
fn solved_value(ps: &PointSet, criterion: Criterion, b: Bottleneck) -> BigRational {
    let triangles = solved_triangles(ps, criterion);
    bottleneck(b, ps.points(), ps.elevations().unwrap(), &triangles)
}

/// The worst triangle's value by the oracle, correctly rounded: the largest
/// corner in degrees, or the square root of the squared value.
fn reference_value(b: Bottleneck, ps: &PointSet, triangles: &[[u32; 3]]) -> f64 {
    let (p, z) = (ps.points(), ps.elevations().unwrap());
    let w = *triangles
        .iter()
        .max_by(|s, t| badness(b, p, z, **s).cmp(&badness(b, p, z, **t)))
        .unwrap();
    let at = |i: usize| p[w[i % 3] as usize];
    match b {
        Bottleneck::MinMaxAngle => (0..3)
            .map(|i| measures::angle_degrees(at(i), at(i + 1), at(i + 2)))
            .fold(0.0, f64::max),
        Bottleneck::MaxMinHeight => measures::nearest_sqrt(&-badness(b, p, z, w)),
        _ => measures::nearest_sqrt(&badness(b, p, z, w)),
    }
}

/// Solves through the registry; checks validity and exactness; returns the
/// triangles as distinct indices.
fn solved_triangles(ps: &PointSet, criterion: Criterion) -> Vec<[u32; 3]> {
    let solution = triangulate(ps, criterion).unwrap();
    assert!(solution.exact, "{}", criterion.name());
    solution.triangulation.validate().unwrap();
    let triangles: Vec<[u32; 3]> = solution
        .triangulation
        .triangles()
        .iter()
        .map(|t| t.map(|i| ps.distinct_index(i)))
        .collect();
    triangles
}

/// A small set of one of several kinds (n ≤ 9 distinct points).
fn small_set(rng: &mut StdRng, kind: usize) -> Vec<Point> {
    match kind % 6 {
        0 => {
            let n = rng.gen_range(4..9);
            inputs::lattice_points(rng, n, 0..5, 0..5)
        }
        1 => {
            let n = rng.gen_range(4..9);
            inputs::lattice_points(rng, n, 0..1000, 0..1000)
        }
        2 => inputs::grid_subset(rng, 3, 3, 0.8),
        3 => inputs::collinear_runs(rng, 1..3, 2..5, 1..3),
        4 => {
            let circle = integer_circle_points(5);
            let mut pts: Vec<Point> = circle
                .iter()
                .filter(|_| rng.gen_bool(0.6))
                .copied()
                .collect();
            if rng.gen_bool(0.5) {
                pts.push([0.0, 0.0]);
            }
            pts
        }
        _ => {
            // Duplicates and negative, offset coordinates.
            let n = rng.gen_range(4..8);
            let mut pts = inputs::lattice_points(rng, n, -3..3, -3..3);
            let shift = 2f64.powi(30);
            for p in &mut pts {
                p[0] = p[0] * 3.0 - shift;
            }
            let first = pts[0];
            pts.push(first);
            pts
        }
    }
}

#[test]
fn small_sets_reach_the_exhaustive_optimum() {
    let mut rng = StdRng::seed_from_u64(0x5eed_e1a9);
    let mut cases = [0usize; 4];
    let mut kinds = 0;
    while cases.iter().any(|&c| c < 300) {
        let pts = small_set(&mut rng, kinds);
        kinds += 1;
        let z = elevations(&mut rng, &pts);
        let Some(ps) = point_set(&pts, &z) else {
            continue;
        };
        if ps.len() > 9 {
            continue;
        }
        let all = all_triangulations(ps.points());
        for (k, &(criterion, b)) in CRITERIA.iter().enumerate() {
            let triangles = solved_triangles(&ps, criterion);
            let got = bottleneck(b, ps.points(), ps.elevations().unwrap(), &triangles);
            let best = optimum_over(b, ps.points(), ps.elevations().unwrap(), &all);
            assert_eq!(got, best, "{} on {pts:?} z {z:?}", criterion.name());
            assert_eq!(
                edge_insertion_worst_value(&ps, criterion, &triangles).unwrap(),
                reference_value(b, &ps, &triangles),
                "{} on {pts:?}",
                criterion.name()
            );
            cases[k] += 1;
        }
    }
    assert!(cases.iter().all(|&c| c >= 300), "{cases:?}");
}

#[test]
fn slope_escapes_a_tie_between_coplanar_worst_triangles() {
    // Six points whose plain acceptance test stalls at slope² 20 (the
    // optimum is 10): two adjacent worst triangles are coplanar.
    let pts = [
        [3.0, 2.0],
        [3.0, 4.0],
        [4.0, 4.0],
        [5.0, 5.0],
        [4.0, 3.0],
        [5.0, 3.0],
    ];
    let z = [0.0, 0.0, 0.0, 2.0, 2.0, 1.0];
    let ps = point_set(&pts, &z).unwrap();
    let b = Bottleneck::MinMaxSlope;
    let best = optimum(b, ps.points(), ps.elevations().unwrap());
    assert_eq!(best, BigRational::from_integer(10.into()));
    assert_eq!(solved_value(&ps, Criterion::MinMaxSlope, b), best);
}

#[test]
fn a_grid_of_tied_right_angles_terminates_at_the_optimum() {
    // Every Delaunay triangle has a right angle: many worst triangles share
    // anchors, and a pair that failed from one of them must not count as a
    // skipped pair of another.
    let pts = [
        [2.0, 2.0],
        [0.0, 0.0],
        [0.0, 1.0],
        [2.0, 0.0],
        [0.0, 2.0],
        [1.0, 2.0],
        [1.0, 1.0],
        [2.0, 1.0],
    ];
    let ps = point_set(&pts, &[0.0; 8]).unwrap();
    for &(criterion, b) in &CRITERIA {
        let best = optimum(b, ps.points(), ps.elevations().unwrap());
        assert_eq!(
            solved_value(&ps, criterion, b),
            best,
            "{}",
            criterion.name()
        );
    }
}

/// On a lattice every Delaunay triangle is a tied worst one; the hull's
/// lower bound proves Delaunay optimal at once (Pick's theorem: every empty
/// lattice triangle on a unit hull edge has its apex on the next row, so it
/// has an angle of at least 90° and a height of at most 1/√2; no triangle
/// can beat eccentricity 0).
#[test]
fn a_lattice_is_certified_by_the_hull_bound() {
    for (w, h) in [(12, 12), (30, 7), (2, 40)] {
        let pts: Vec<Point> = (0..w * h)
            .map(|k| [(k % w) as f64 * 3.0 - 7.0, (k / w) as f64 * 3.0 + 1.0])
            .collect();
        let ps = PointSet::new(&pts).unwrap();
        for criterion in [
            Criterion::MinMaxAngle,
            Criterion::MaxMinHeight,
            Criterion::MinMaxEccentricity,
        ] {
            let s = triangulate(&ps, criterion).unwrap();
            assert!(s.exact, "{}", criterion.name());
            assert_eq!(s.diagnostics.get("met the hull bound"), Some(1));
            assert_eq!(s.diagnostics.get("insertion attempts"), Some(0));
            let stats = s.triangulation.stats();
            match criterion {
                Criterion::MinMaxAngle => assert_eq!(stats.max_angle_deg, 90.0),
                Criterion::MaxMinHeight => assert_eq!(stats.min_height, 4.5f64.sqrt()),
                _ => assert_eq!(stats.max_eccentricity, 0.0),
            }
        }
    }
}

/// A spent time limit keeps the triangulation the loop reached: valid, not
/// exact, never worse than Delaunay's under the measure (the oracle's
/// values); a cancel is an error.
#[test]
fn a_time_limit_keeps_the_triangulation_reached() {
    let side = 60;
    let pts: Vec<Point> = (0..side * side)
        .map(|k| [(k % side) as f64, (k / side) as f64])
        .collect();
    let mut rng = StdRng::seed_from_u64(7);
    let z = elevations(&mut rng, &pts);
    let ps = point_set(&pts, &z).unwrap();
    let delaunay: Vec<[u32; 3]> = triangulate(&ps, Criterion::Delaunay)
        .unwrap()
        .triangulation
        .triangles()
        .to_vec();
    let mut stopped = 0;
    for &(criterion, b) in &CRITERIA {
        // The limit must pass inside the loop, not before it starts (then
        // the run is `Interrupted`): double it from 1 ms until a run
        // answers. Every Delaunay triangle of the grid is a tied worst one
        // (or nearly), so a pass of the loop is long.
        let mut limit = std::time::Duration::from_millis(1);
        let solution = loop {
            let options = optri::Options::default().with_time_limit(limit);
            match optri::triangulate_with(&ps, criterion, &options) {
                Ok(solution) => break solution,
                Err(Error::Interrupted(_)) if limit.as_secs() < 60 => limit *= 2,
                Err(e) => panic!("{}: {e}", criterion.name()),
            }
        };
        stopped += usize::from(!solution.exact);
        solution.triangulation.validate().unwrap();
        let (p, zs) = (ps.points(), ps.elevations().unwrap());
        let worst = |ts: &[[u32; 3]]| {
            ts.iter()
                .map(|t| badness(b, p, zs, t.map(|i| ps.distinct_index(i))))
                .max()
                .unwrap()
        };
        assert!(worst(solution.triangulation.triangles()) <= worst(&delaunay));
        let cancel = optri::Cancel::new();
        cancel.cancel();
        let cancelled = optri::Options::default().with_cancel(cancel);
        assert!(matches!(
            optri::triangulate_with(&ps, criterion, &cancelled),
            Err(Error::Interrupted(_))
        ));
    }
    assert!(stopped > 0, "no run was stopped inside the loop");
}

#[test]
fn larger_sets_match_the_generic_loop() {
    let mut rng = StdRng::seed_from_u64(0x5eed_e1b0);
    let mut cases = 0;
    for round in 0..8 {
        let n = [30, 40, 60][round % 3];
        let pts = if round % 2 == 0 {
            inputs::lattice_points(&mut rng, n, 0..30, 0..30)
        } else {
            inputs::uniform_in_square(&mut rng, n, 1000.0)
        };
        let z = elevations(&mut rng, &pts);
        let ps = point_set(&pts, &z).unwrap();
        for &(criterion, b) in &CRITERIA {
            let got = solved_value(&ps, criterion, b);
            let (reference, _) = edge_insertion_reference(&ps, criterion).unwrap();
            let want = bottleneck(b, ps.points(), ps.elevations().unwrap(), &reference);
            assert_eq!(got, want, "{} round {round}", criterion.name());
            cases += 1;
        }
    }
    assert_eq!(cases, 32);
}

#[test]
fn polygons_reach_the_exhaustive_optimum() {
    let mut rng = StdRng::seed_from_u64(0x5eed_e1c1);
    let mut cases = 0;
    for round in 0..80 {
        let n = rng.gen_range(4..9);
        let ring = match round % 3 {
            0 => op::star_polygon(&mut rng, n, 100.0),
            1 => op::two_opt_polygon(&mut rng, n, 20),
            _ => op::histogram(&mut rng, n / 3 + 1, 4, true),
        };
        if ring.len() > 10 {
            continue;
        }
        let z: Vec<f64> = (0..ring.len())
            .map(|_| rng.gen_range(0..4) as f64)
            .collect();
        let polygon = SimplePolygon::new(&ring)
            .unwrap()
            .with_elevations(&z)
            .unwrap();
        for &(criterion, b) in &CRITERIA {
            let solution = triangulate(&polygon, criterion).unwrap();
            assert!(solution.exact);
            solution.triangulation.validate().unwrap();
            let got = bottleneck(b, &ring, &z, solution.triangulation.triangles());
            assert_eq!(
                got,
                polygon_optimum(b, &ring, &z),
                "{} {ring:?}",
                criterion.name()
            );
            cases += 1;
        }
    }
    assert!(cases >= 200, "{cases}");
}

#[test]
fn slope_needs_elevations() {
    let ps = PointSet::new(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]).unwrap();
    assert!(matches!(
        triangulate(&ps, Criterion::MinMaxSlope),
        Err(Error::Unsupported {
            reason: UnsupportedReason::NeedsElevations,
            ..
        })
    ));
    for (criterion, _) in &CRITERIA[..3] {
        assert_eq!(
            triangulate(&ps, *criterion)
                .unwrap()
                .triangulation
                .triangles()
                .len(),
            1
        );
    }
}
