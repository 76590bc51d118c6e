//! Minimum-weight triangulation of convex inputs against the exhaustive
//! oracle (n ≤ 9) and the oracle's Klincsek DP; the greedy triangulation
//! against the oracle's independent greedy; the approximation ratio.

use optri::kernel::Point;
use optri::{min_weight, triangulate, Criterion, Error, PointSet};
use optri_oracle::{
    all_triangulations, canonical_triangulation, klincsek, optimum_by, total_length, MinWeight,
    TotalF64,
};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

/// Triangles of a triangulation as distinct indices.
fn distinct_triangles(ps: &PointSet, t: &optri::Triangulation) -> Vec<[u32; 3]> {
    t.triangles()
        .iter()
        .map(|tri| tri.map(|i| ps.distinct_index(i)))
        .collect()
}

/// Random points in convex position: integer points on a circle of radius r
/// (rounded), plus collinear boundary points now and then.
fn convex_points(rng: &mut StdRng, n: usize, with_collinear: bool) -> Vec<Point> {
    let r = rng.gen_range(5.0..60.0);
    let mut pts: Vec<Point> = (0..n)
        .map(|_| {
            let a: f64 = rng.gen_range(0.0..std::f64::consts::TAU);
            [(r * a.cos()).round(), (r * a.sin()).round()]
        })
        .collect();
    if with_collinear && n >= 2 {
        // Midpoint of two points doubled: stays on the hull only if it is a
        // hull edge; the convex-position check filters the rest.
        pts.push([pts[0][0] + pts[1][0], pts[0][1] + pts[1][1]].map(|v| v / 2.0));
    }
    pts
}

fn in_convex_position(ps: &PointSet) -> bool {
    optri::convex_hull(ps).len() == ps.len()
}

fn relative_eq(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * a.abs().max(b.abs())
}

#[test]
fn min_weight_equals_the_exhaustive_optimum_on_small_convex_sets() {
    let mut rng = StdRng::seed_from_u64(11);
    let mut checked = 0;
    for case in 0..600 {
        let n = rng.gen_range(3..10);
        let pts = convex_points(&mut rng, n, case % 3 == 0);
        let Ok(ps) = PointSet::new(&pts) else {
            continue;
        };
        if !in_convex_position(&ps) || ps.len() > 9 {
            continue;
        }
        let d = ps.points();
        let t = min_weight(&ps).unwrap();
        t.validate().unwrap();
        let mine = distinct_triangles(&ps, &t);
        let (best, optimal) = optimum_by(d, |tris| TotalF64(total_length(d, tris)));
        let weight = total_length(d, &mine);
        assert!(
            relative_eq(weight, best.0),
            "case {case}: {weight} vs {}",
            best.0
        );
        // Unless two optima tie within rounding, the triangulation is the optimum.
        let near_optimal = all_triangulations(d)
            .iter()
            .filter(|tris| relative_eq(total_length(d, tris), best.0))
            .count();
        if near_optimal == 1 {
            assert_eq!(canonical_triangulation(d, &mine), optimal[0], "case {case}");
        }
        checked += 1;
    }
    assert!(checked > 300, "{checked}");
}

#[test]
fn min_weight_equals_the_oracle_dp_and_bounds_the_greedy_triangulation() {
    let mut rng = StdRng::seed_from_u64(12);
    for case in 0..60 {
        let n = rng.gen_range(10..120);
        let pts = convex_points(&mut rng, n, case % 2 == 0);
        let Ok(ps) = PointSet::new(&pts) else {
            continue;
        };
        if !in_convex_position(&ps) {
            continue;
        }
        let d = ps.points();
        let polygon: Vec<u32> = optri::convex_hull(&ps)
            .into_iter()
            .map(|i| ps.distinct_index(i))
            .collect();
        let (oracle, _) = klincsek(d, &polygon, MinWeight).expect("convex polygon");
        let t = min_weight(&ps).unwrap();
        t.validate().unwrap();
        let weight = total_length(d, &distinct_triangles(&ps, &t));
        assert!(
            relative_eq(weight, oracle.0),
            "case {case}: {weight} vs {}",
            oracle.0
        );
        // GT is a triangulation too, so it cannot be lighter than the MWT;
        // and the solutions report the total length in their stats.
        let gt = triangulate(&ps, Criterion::Greedy).unwrap().triangulation;
        let gt_weight = gt.stats().total_edge_length;
        assert!(gt_weight >= weight * (1.0 - 1e-12), "case {case}");
        let s = triangulate(&ps, Criterion::MinWeight).unwrap();
        assert!(!s.exact, "sums of square roots are compared in f64");
        assert!(relative_eq(
            s.triangulation.stats().total_edge_length,
            weight
        ));
    }
}

#[test]
fn greedy_matches_the_oracle_greedy_on_small_sets() {
    let mut rng = StdRng::seed_from_u64(13);
    for case in 0..300 {
        let n = rng.gen_range(3..11);
        let m = if case % 2 == 0 { 5 } else { 1000 };
        let pts: Vec<Point> = (0..n)
            .map(|_| [rng.gen_range(0..m) as f64, rng.gen_range(0..m) as f64])
            .collect();
        let Ok(ps) = PointSet::new(&pts) else {
            continue;
        };
        let d = ps.points();
        let t = optri::greedy(&ps).unwrap();
        assert_eq!(
            canonical_triangulation(d, &distinct_triangles(&ps, &t)),
            optri_oracle::greedy_triangulation(d),
            "case {case}: {pts:?}"
        );
    }
}

#[test]
fn min_weight_rejects_non_convex_input_clearly() {
    let ps = PointSet::new(&[[0.0, 0.0], [4.0, 0.0], [0.0, 4.0], [1.0, 1.0]]).unwrap();
    match min_weight(&ps) {
        Err(Error::Unsupported(msg)) => {
            assert!(msg.contains("convex position"), "{msg}");
        }
        other => panic!("expected Unsupported, got {other:?}"),
    }
    assert!(matches!(
        triangulate(&ps, Criterion::MinWeight),
        Err(Error::Unsupported(_))
    ));
}
