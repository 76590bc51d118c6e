//! The canonical graph does not depend on how the triangulation was built:
//! the randomized insertion and spade's bulk load (a circle sweep, which
//! reaches other completions of cocircular faces) give the same arrays on
//! degenerate sets.

use super::*;
use optri_oracle::inputs::{grid, integer_circle_points};
use rand::{rngs::StdRng, Rng, SeedableRng};

/// The graph built from spade's bulk load, the construction the randomized
/// insertion replaced.
fn bulk_loaded(points: &[Point]) -> DelaunayGraph {
    let dt: DelaunayTriangulation<Vertex> =
        DelaunayTriangulation::bulk_load(Vertex::numbered(points)).unwrap();
    kept_every_point(&dt, points.len()).unwrap();
    let (triangles, neighbours) = triangle_arrays(&dt);
    from_triangles(points, triangles, neighbours, true)
}

/// Both constructions agree array for array, and every side is locally
/// Delaunay (exact in-circle), so both are Delaunay triangulations.
fn assert_same_both_ways(name: &str, points: &[Point]) {
    let inserted = DelaunayGraph::with_topology(points).unwrap();
    let bulk = bulk_loaded(points);
    assert_eq!(inserted.triangles, bulk.triangles, "{name}: triangles");
    assert_eq!(inserted.edges, bulk.edges, "{name}: edges");
    assert_eq!(inserted.offsets, bulk.offsets, "{name}: offsets");
    assert_eq!(inserted.adjacency, bulk.adjacency, "{name}: adjacency");
    let (a, b) = (&inserted.topology, &bulk.topology);
    assert_eq!(a.neighbours, b.neighbours, "{name}: neighbours");
    assert_eq!(a.sides, b.sides, "{name}: sides");
    assert_eq!(a.slot_edges, b.slot_edges, "{name}: slot edges");
    let p = |v: u32| points[v as usize];
    for &([u, v], [left, right]) in &inserted.edges {
        if let (Some(l), Some(r)) = (left, right) {
            assert!(
                incircle_sign(p(u), p(v), p(l), p(r)) <= 0,
                "{name}: side {u}-{v} is not locally Delaunay"
            );
        }
    }
}

/// `points` in a random order: the numbering decides the canonical
/// completion, so the sets are tested under more than one.
fn shuffled(mut points: Vec<Point>, seed: u64) -> Vec<Point> {
    let mut rng = StdRng::seed_from_u64(seed);
    for i in (1..points.len()).rev() {
        points.swap(i, rng.gen_range(0..=i));
    }
    points
}

fn parabola(half: i32) -> Vec<Point> {
    (-half..=half)
        .map(|x| [f64::from(x), f64::from(x * x)])
        .collect()
}

#[test]
fn grids_agree() {
    for side in [2, 3, 7, 25] {
        assert_same_both_ways("grid", &grid(side, side, 1.0));
        assert_same_both_ways(
            "shuffled grid",
            &shuffled(grid(side, side, 1.0), side as u64),
        );
    }
}

#[test]
fn cocircular_sets_agree() {
    // The 180 integer points on the circle x² + y² = 5525².
    let circle = integer_circle_points(5525);
    assert_eq!(circle.len(), 180);
    assert_same_both_ways("circle", &circle);
    assert_same_both_ways("shuffled circle", &shuffled(circle.clone(), 1));
    // The centre and the points of a smaller concentric lattice circle
    // (x² + y² = 25²: 20 points) inside it.
    let mut with_inside = circle;
    with_inside.push([0.0, 0.0]);
    for [x, y] in [[0, 25], [7, 24], [15, 20], [20, 15], [24, 7], [25, 0]] {
        for (sx, sy) in [(1, 1), (-1, 1), (1, -1), (-1, -1)] {
            let q = [f64::from(sx * x), f64::from(sy * y)];
            if !with_inside.contains(&q) {
                with_inside.push(q);
            }
        }
    }
    assert_same_both_ways("circles and centre", &shuffled(with_inside, 2));
    // A regular 360-gon rounded to 6 decimals: nearly, not exactly, cocircular.
    let polygon: Vec<Point> = (0..360)
        .map(|k| {
            let a = f64::from(k).to_radians();
            [(a.cos() * 1e6).round() / 1e6, (a.sin() * 1e6).round() / 1e6]
        })
        .collect();
    assert_same_both_ways("rounded polygon", &polygon);
}

#[test]
fn parabolas_agree() {
    assert_same_both_ways("parabola", &parabola(60));
    assert_same_both_ways("shuffled parabola", &shuffled(parabola(60), 3));
    // With integer points inside (on the parabola's lattice: many
    // cocircular quadruples) and outside.
    let mut rng = StdRng::seed_from_u64(4);
    let mut points = parabola(40);
    while points.len() < 200 {
        let q = [
            f64::from(rng.gen_range(-40..=40)),
            f64::from(rng.gen_range(-10..=1600)),
        ];
        if !points.contains(&q) {
            points.push(q);
        }
    }
    assert_same_both_ways("parabola and lattice points", &points);
}

#[test]
fn collinear_runs_agree() {
    // Two parallel lines: every four consecutive points are a cocircular
    // rectangle.
    let parallel: Vec<Point> = (0..60)
        .flat_map(|x| [[f64::from(x), 0.0], [f64::from(x), 1.0]])
        .collect();
    assert_same_both_ways("two parallel lines", &parallel);
    assert_same_both_ways("shuffled lines", &shuffled(parallel, 5));
    // Two crossing lines through their common point.
    let mut crossing: Vec<Point> = vec![[0.0, 0.0]];
    for t in 1..=50 {
        let t = f64::from(t);
        crossing.extend([[t, t], [-t, -t], [t, -t], [-t, t]]);
    }
    assert_same_both_ways("two crossing lines", &shuffled(crossing, 6));
    // A long collinear run with a few points off it on both sides.
    let mut run: Vec<Point> = (0..100).map(|x| [f64::from(x), 0.0]).collect();
    run.extend([[50.0, 30.0], [10.0, -7.0], [90.0, -7.0], [49.5, 0.5]]);
    assert_same_both_ways("collinear run", &shuffled(run, 7));
}

#[test]
fn random_lattice_points_agree() {
    for seed in 0..8 {
        let mut rng = StdRng::seed_from_u64(seed);
        let mut points: Vec<Point> = Vec::new();
        while points.len() < 300 {
            let q = [
                f64::from(rng.gen_range(0..24)),
                f64::from(rng.gen_range(0..24)),
            ];
            if !points.contains(&q) {
                points.push(q);
            }
        }
        assert_same_both_ways("lattice points", &points);
    }
}
