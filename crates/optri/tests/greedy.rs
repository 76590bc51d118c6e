//! The greedy triangulation against the naive reference (sort all segments,
//! add each compatible one), edge for edge, and the convex / semicircular
//! algorithms against the general one.

use optri::greedy::{greedy_edges_by, greedy_naive_edges, greedy_triangulation, GreedyAlgorithm};
use optri::kernel::Point;
use optri::{triangulate, Criterion, PointSet};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

/// Distinct-index `[min, max]` edges of a triangulation, sorted.
fn distinct_edges(ps: &PointSet, t: &optri::Triangulation) -> Vec<[u32; 2]> {
    let mut e: Vec<[u32; 2]> = t
        .edges()
        .into_iter()
        .map(|[a, b]| {
            let (a, b) = (ps.distinct_index(a), ps.distinct_index(b));
            [a.min(b), a.max(b)]
        })
        .collect();
    e.sort_unstable();
    e
}

/// Full check: dispatching entry point and the general algorithm equal the
/// reference; the triangulation validates. Returns the algorithm that ran.
fn check_against_naive(points: &[Point], what: &str) -> GreedyAlgorithm {
    let Ok(ps) = PointSet::new(points) else {
        return GreedyAlgorithm::General;
    };
    let reference = greedy_naive_edges(&ps);
    let general = greedy_edges_by(&ps, GreedyAlgorithm::General).unwrap();
    assert_eq!(general, reference, "general != naive on {what}: {points:?}");
    let (t, algorithm) = greedy_triangulation(&ps).unwrap();
    t.validate().unwrap_or_else(|e| panic!("{what}: {e}"));
    assert_eq!(distinct_edges(&ps, &t), reference, "{what} ({algorithm:?})");
    algorithm
}

fn uniform(rng: &mut StdRng, n: usize, scale: f64) -> Vec<Point> {
    (0..n)
        .map(|_| [rng.gen_range(-scale..scale), rng.gen_range(-scale..scale)])
        .collect()
}

#[test]
fn random_small_sets_match_the_naive_reference() {
    let mut rng = StdRng::seed_from_u64(3);
    for case in 0..1500 {
        let n = rng.gen_range(3..40);
        let pts = uniform(&mut rng, n, 100.0);
        check_against_naive(&pts, &format!("uniform case {case}"));
    }
}

#[test]
fn integer_grids_and_small_integer_sets_match() {
    let mut rng = StdRng::seed_from_u64(4);
    for w in 2..9 {
        for h in 1..9 {
            let pts: Vec<Point> = (0..w * h)
                .map(|i| [(i % w) as f64, (i / w) as f64])
                .collect();
            check_against_naive(&pts, &format!("grid {w}x{h}"));
        }
    }
    for case in 0..1500 {
        let n = rng.gen_range(3..30);
        let m = rng.gen_range(2..7);
        let pts: Vec<Point> = (0..n)
            .map(|_| [rng.gen_range(0..m) as f64, rng.gen_range(0..m) as f64])
            .collect();
        check_against_naive(&pts, &format!("small integer case {case}"));
    }
}
