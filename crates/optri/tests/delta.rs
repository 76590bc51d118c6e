//! The δ-triangulations (`minmax-delta-area`, `-angle`, `-length`) against
//! the oracle's exhaustive optimum (`optri_oracle::delta`, exact rational
//! comparisons independent of the kernel): convex polygons (random, regular
//! by cos/sin, lattice, cocircular, with collinear boundary points), simple
//! polygons, and general point sets, where the answer must be a valid
//! triangulation no better than the optimum (it is not claimed optimal).

use optri::{triangulate, Criterion, Error, PointSet, SimplePolygon, UnsupportedReason};
use optri_oracle::inputs::{convex_by_construction, ConvexShape};
use optri_oracle::polygon::{polygon_triangulations, star_polygon, two_opt_polygon};
use optri_oracle::{all_triangulations, canonical_triangulation, DeltaMeasure, Point};
use rand::{rngs::StdRng, Rng, SeedableRng};
use std::cmp::Ordering;

const CRITERIA: [(Criterion, DeltaMeasure); 3] = [
    (Criterion::MinMaxDeltaArea, DeltaMeasure::Area),
    (Criterion::MinMaxDeltaAngle, DeltaMeasure::Angle),
    (Criterion::MinMaxDeltaLength, DeltaMeasure::Length),
];

/// Runs every δ criterion on the point set and compares with the optimum
/// over all triangulations; in convex position the result must be optimal
/// and reported exact. Returns how many were optimal.
fn check_points(points: &[Point], what: &str) -> usize {
    let set = PointSet::new(points).unwrap();
    let every = all_triangulations(points);
    let mut optimal = 0;
    for (criterion, measure) in CRITERIA {
        let s = triangulate(&set, criterion).unwrap();
        s.triangulation.validate().unwrap();
        let got = canonical_triangulation(points, s.triangulation.triangles());
        assert!(
            every.contains(&got),
            "{what}: {} not a triangulation",
            criterion.name()
        );
        let best = measure.optimum(points, &every).unwrap();
        let order = measure.compare(points, &got, best);
        assert_ne!(order, Ordering::Less, "{what}: better than the optimum?");
        if s.exact {
            assert_eq!(
                order,
                Ordering::Equal,
                "{what}: {} δ {} but the optimum is {}",
                criterion.name(),
                measure.approximate(points, &got),
                measure.approximate(points, best)
            );
        }
        optimal += (order == Ordering::Equal) as usize;
    }
    optimal
}

/// The same on a simple polygon (always exact).
fn check_polygon(ring: &[Point], what: &str) {
    let polygon = SimplePolygon::new(ring).unwrap();
    let every: Vec<Vec<[u32; 3]>> = polygon_triangulations(ring)
        .into_iter()
        .map(|t| canonical_triangulation(ring, &t))
        .collect();
    for (criterion, measure) in CRITERIA {
        let s = triangulate(&polygon, criterion).unwrap();
        s.triangulation.validate().unwrap();
        assert!(s.exact);
        let got = canonical_triangulation(ring, s.triangulation.triangles());
        assert!(
            every.contains(&got),
            "{what}: {} not a triangulation",
            criterion.name()
        );
        let best = measure.optimum(ring, &every).unwrap();
        assert_eq!(
            measure.compare(ring, &got, best),
            Ordering::Equal,
            "{what}: {} δ {} but the optimum is {}",
            criterion.name(),
            measure.approximate(ring, &got),
            measure.approximate(ring, best)
        );
    }
}

/// Every point is a hull vertex (collinear boundary points count).
fn is_convex_position(points: &[Point]) -> bool {
    let edges = optri_oracle::convex_hull_edges(points);
    edges.len() == points.len()
}

#[test]
fn random_convex_polygons_are_optimal() {
    let mut rng = StdRng::seed_from_u64(0x000D_E17A_0001);
    let mut cases = 0;
    for n in 3..=8 {
        for round in 0..5 {
            let shape = [ConvexShape::Parabola, ConvexShape::Lens][round % 2];
            let shape = if n < 4 { ConvexShape::Parabola } else { shape };
            let points = convex_by_construction(&mut rng, n, shape, round % 3 == 2);
            if points.len() > 9 {
                continue;
            }
            assert!(is_convex_position(&points));
            assert_eq!(check_points(&points, &format!("convex n={n}")), 3);
            cases += 1;
        }
    }
    assert_eq!(cases, 29);
}

#[test]
fn regular_and_cocircular_polygons_are_optimal() {
    let mut cases = 0;
    for n in 4..=9 {
        // As a user samples them: near-ties everywhere.
        let regular: Vec<Point> = (0..n)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / n as f64;
                [1e3 * a.cos(), 1e3 * a.sin()]
            })
            .collect();
        if is_convex_position(&regular) {
            assert_eq!(check_points(&regular, &format!("regular {n}")), 3);
            check_polygon(&optri_oracle::inputs::strict_hull(regular), "regular ring");
            cases += 1;
        }
    }
    // Exact ties: the 12 lattice points of x² + y² = 25, a lattice octagon,
    // a square.
    let r5 = optri_oracle::inputs::circle_r5_ccw();
    let octagon = vec![
        [1.0, 0.0],
        [2.0, 0.0],
        [3.0, 1.0],
        [3.0, 2.0],
        [2.0, 3.0],
        [1.0, 3.0],
        [0.0, 2.0],
        [0.0, 1.0],
    ];
    let square = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    for (ring, what) in [(&octagon, "octagon"), (&square, "square")] {
        assert_eq!(check_points(ring, what), 3);
        check_polygon(ring, what);
        cases += 1;
    }
    // Twelve points is above the enumeration's comfort: the first 9 of the
    // ring (a convex chain closed by a chord).
    check_polygon(&r5[..9], "r5 arc");
    cases += 1;
    assert!(cases >= 8, "{cases}");
}

#[test]
fn simple_polygons_are_optimal() {
    let mut rng = StdRng::seed_from_u64(0x000D_E17A_0002);
    let mut cases = 0;
    for n in 4..=9 {
        for _ in 0..4 {
            check_polygon(&star_polygon(&mut rng, n, 20.0), &format!("star {n}"));
            check_polygon(&two_opt_polygon(&mut rng, n, 8), &format!("2-opt {n}"));
            cases += 2;
        }
    }
    assert_eq!(cases, 48);
}

#[test]
fn general_point_sets_are_valid_and_not_below_the_optimum() {
    let mut rng = StdRng::seed_from_u64(0x000D_E17A_0003);
    let (mut cases, mut optimal) = (0, 0);
    while cases < 30 {
        let n = rng.gen_range(5..=8);
        let points: Vec<Point> = (0..n)
            .map(|_| [rng.gen_range(0..6) as f64, rng.gen_range(0..6) as f64])
            .collect();
        let Ok(set) = PointSet::new(&points) else {
            continue;
        };
        if set.points().len() != n || is_convex_position(&points) {
            continue;
        }
        for (criterion, _) in CRITERIA {
            let s = triangulate(&set, criterion).unwrap();
            assert!(!s.exact);
        }
        optimal += check_points(&points, "general");
        cases += 1;
    }
    // Not a guarantee, but the candidates are often optimal on tiny sets.
    assert!(optimal > 0);
}

#[test]
fn limits_and_registry() {
    for (criterion, _) in CRITERIA {
        assert_eq!(Criterion::from_name(criterion.name()).unwrap(), criterion);
        assert!(criterion.info().reference.contains("Vassilev"));
    }
    let big: Vec<Point> = (0..300)
        .map(|i| {
            let x = i as f64 - 150.0;
            [x, x * x]
        })
        .collect();
    let set = PointSet::new(&big).unwrap();
    assert!(matches!(
        triangulate(&set, Criterion::MinMaxDeltaArea),
        Err(Error::Unsupported {
            reason: UnsupportedReason::TooManyPoints { .. },
            ..
        })
    ));
}

/// Larger convex polygons (n = 9, 10): slower enumeration.
#[test]
#[ignore]
fn larger_convex_polygons_are_optimal() {
    let mut rng = StdRng::seed_from_u64(0x000D_E17A_0004);
    for n in 9..=10 {
        for round in 0..5 {
            let shape = [ConvexShape::Parabola, ConvexShape::Lens][round % 2];
            let points = convex_by_construction(&mut rng, n, shape, false);
            assert_eq!(check_points(&points, &format!("convex n={n}")), 3);
        }
    }
}
