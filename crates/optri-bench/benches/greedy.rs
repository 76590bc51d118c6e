//! Criterion benchmarks of the greedy triangulation: uniform and clustered
//! points (general algorithm, beside the Delaunay triangulation of the same
//! set), a convex lens (convex algorithm) and a parabola (semicircular
//! algorithm); the inputs that once made it quadratic: a fan, a circle sampled with
//! cos/sin and points at random angles on a circle.
//!
//! `cargo bench -p optri --bench greedy`; the 10⁶-point figures come from
//! `cargo run --release -p optri --example greedy_bench -- <mode> <n>`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use optri::internals::greedy_triangulation;
use optri::PointSet;
use optri_oracle::inputs::{
    circle_at_random_angles, clustered, convex_lens_evenly_spaced, fan, parabola, sampled_circle,
    uniform_unit_square,
};
use rand::{rngs::StdRng, SeedableRng};

const SEED_UNIFORM: u64 = 1;
const SEED_CLUSTERED: u64 = 2;
const SEED_RANDOM_CIRCLE: u64 = 3;

fn point_set(points: Vec<[f64; 2]>) -> PointSet {
    PointSet::new(&points).unwrap()
}

fn greedy(c: &mut Criterion) {
    let mut group = c.benchmark_group("greedy");
    group.sample_size(10);
    for &n in &[10_000usize, 100_000] {
        let ps = point_set(uniform_unit_square(
            &mut StdRng::seed_from_u64(SEED_UNIFORM),
            n,
        ));
        group.bench_with_input(BenchmarkId::new("general_uniform", n), &ps, |b, ps| {
            b.iter(|| greedy_triangulation(ps).unwrap())
        });
        group.bench_with_input(BenchmarkId::new("delaunay_uniform", n), &ps, |b, ps| {
            b.iter(|| optri::delaunay(ps).unwrap())
        });
    }
    // 100 square clusters with sizes over two orders of magnitude.
    let ps = point_set(clustered(
        &mut StdRng::seed_from_u64(SEED_CLUSTERED),
        100_000,
        100,
    ));
    group.bench_with_input(
        BenchmarkId::new("general_clustered", 100_000),
        &ps,
        |b, ps| b.iter(|| greedy_triangulation(ps).unwrap()),
    );
    group.bench_with_input(
        BenchmarkId::new("delaunay_clustered", 100_000),
        &ps,
        |b, ps| b.iter(|| optri::delaunay(ps).unwrap()),
    );
    let ps = point_set(convex_lens_evenly_spaced(2_000));
    assert!(optri::internals::is_convex_position(&ps));
    group.bench_with_input(BenchmarkId::new("convex_lens", 2_000), &ps, |b, ps| {
        b.iter(|| greedy_triangulation(ps).unwrap())
    });
    let ps = point_set(parabola(100_000));
    assert!(optri::internals::is_semicircular(&ps));
    group.bench_with_input(
        BenchmarkId::new("semicircular_parabola", 100_000),
        &ps,
        |b, ps| b.iter(|| greedy_triangulation(ps).unwrap()),
    );
    // Inputs that once took minutes each (long equal-length runs, cocircular points).
    let ps = point_set(fan(100_000));
    group.bench_with_input(BenchmarkId::new("fan", 100_000), &ps, |b, ps| {
        b.iter(|| greedy_triangulation(ps).unwrap())
    });
    let ps = point_set(sampled_circle(10_000, 1000.0));
    group.bench_with_input(BenchmarkId::new("sampled_circle", 10_000), &ps, |b, ps| {
        b.iter(|| greedy_triangulation(ps).unwrap())
    });
    let ps = point_set(circle_at_random_angles(
        &mut StdRng::seed_from_u64(SEED_RANDOM_CIRCLE),
        10_000,
        1000.0,
    ));
    group.bench_with_input(BenchmarkId::new("random_circle", 10_000), &ps, |b, ps| {
        b.iter(|| greedy_triangulation(ps).unwrap())
    });
    group.finish();
}

criterion_group!(benches, greedy);
criterion_main!(benches);
