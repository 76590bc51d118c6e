//! Criterion benchmarks of the greedy triangulation: uniform and clustered
//! points (general algorithm, beside the Delaunay triangulation of the same
//! set), a convex lens (convex algorithm) and a parabola (semicircular
//! algorithm).
//!
//! `cargo bench -p optri --bench greedy`; the 10⁶-point figures come from
//! `cargo run --release -p optri --example greedy_bench -- <mode> <n>`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use optri::internals::greedy_triangulation;
use optri::PointSet;
use rand::{rngs::StdRng, Rng, SeedableRng};

fn uniform(n: usize) -> PointSet {
    let mut rng = StdRng::seed_from_u64(1);
    let pts: Vec<[f64; 2]> = (0..n).map(|_| [rng.gen(), rng.gen()]).collect();
    PointSet::new(&pts).unwrap()
}

/// 100 square clusters with random centres and sizes over two orders of
/// magnitude.
fn clustered(n: usize) -> PointSet {
    let mut rng = StdRng::seed_from_u64(2);
    let mut pts: Vec<[f64; 2]> = Vec::with_capacity(n);
    for _ in 0..100 {
        let c = [rng.gen_range(-1e4..1e4), rng.gen_range(-1e4..1e4)];
        let r: f64 = rng.gen_range(10.0..2e3);
        for _ in 0..n / 100 {
            pts.push([c[0] + rng.gen_range(-r..r), c[1] + rng.gen_range(-r..r)]);
        }
    }
    PointSet::new(&pts).unwrap()
}

/// Strictly convex, exactly: integer points on `y = x²` and `y = 2m² - x²`.
fn lens(n: usize) -> PointSet {
    let m = 2 * n as i64;
    let mut pts: Vec<[f64; 2]> = Vec::with_capacity(n);
    for k in 0..n as i64 {
        let x = -m + 1 + (k / 2) * ((2 * m - 2) / (n as i64 / 2));
        let y = if k % 2 == 0 { x * x } else { 2 * m * m - x * x };
        pts.push([x as f64, y as f64]);
    }
    PointSet::new(&pts).unwrap()
}

/// Semicircular: integer points on `y = x²`.
fn parabola(n: usize) -> PointSet {
    let pts: Vec<[f64; 2]> = (0..n).map(|x| [x as f64, (x * x) as f64]).collect();
    PointSet::new(&pts).unwrap()
}

fn greedy(c: &mut Criterion) {
    let mut group = c.benchmark_group("greedy");
    group.sample_size(10);
    for &n in &[10_000usize, 100_000] {
        let ps = uniform(n);
        group.bench_with_input(BenchmarkId::new("general_uniform", n), &ps, |b, ps| {
            b.iter(|| greedy_triangulation(ps).unwrap())
        });
        group.bench_with_input(BenchmarkId::new("delaunay_uniform", n), &ps, |b, ps| {
            b.iter(|| optri::delaunay(ps).unwrap())
        });
    }
    let ps = clustered(100_000);
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
    let ps = lens(2_000);
    assert!(optri::internals::is_convex_position(&ps));
    group.bench_with_input(BenchmarkId::new("convex_lens", 2_000), &ps, |b, ps| {
        b.iter(|| greedy_triangulation(ps).unwrap())
    });
    let ps = parabola(100_000);
    assert!(optri::internals::is_semicircular(&ps));
    group.bench_with_input(
        BenchmarkId::new("semicircular_parabola", 100_000),
        &ps,
        |b, ps| b.iter(|| greedy_triangulation(ps).unwrap()),
    );
    group.finish();
}

criterion_group!(benches, greedy);
criterion_main!(benches);
