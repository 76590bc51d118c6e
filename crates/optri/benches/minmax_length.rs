//! Criterion benchmarks for the minmax-length triangulation
//! (Edelsbrunner–Tan): uniform random points against Delaunay alone in the
//! same group, and points in convex position (one complete rng-polygon, the
//! O(n²) worst case of §6) against the cubic reference. The larger series
//! (10⁶ uniform points, convex n = 5k…40k) is in `examples/minmax_timing.rs`.
//!
//! `cargo bench -p optri --bench minmax_length`

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use optri::PointSet;
use rand::{rngs::StdRng, Rng, SeedableRng};

fn uniform(n: usize, seed: u64) -> Vec<[f64; 2]> {
    let mut rng = StdRng::seed_from_u64(seed);
    (0..n)
        .map(|_| [rng.gen::<f64>(), rng.gen::<f64>()])
        .collect()
}

/// Points on the unit circle with the radius perturbed by up to 1e-3.
fn perturbed_circle(n: usize, seed: u64) -> Vec<[f64; 2]> {
    let mut rng = StdRng::seed_from_u64(seed);
    (0..n)
        .map(|i| {
            let a = i as f64 / n as f64 * std::f64::consts::TAU;
            let r = 1.0 + 1e-3 * rng.gen::<f64>();
            [r * a.cos(), r * a.sin()]
        })
        .collect()
}

fn uniform_points(c: &mut Criterion) {
    let mut group = c.benchmark_group("minmax_length_uniform");
    group.sample_size(10);
    let n = 100_000;
    let ps = PointSet::new(&uniform(n, 1)).unwrap();
    group.bench_with_input(BenchmarkId::new("delaunay", n), &ps, |b, ps| {
        b.iter(|| optri::delaunay(ps).unwrap())
    });
    group.bench_with_input(BenchmarkId::new("minmax_length", n), &ps, |b, ps| {
        b.iter(|| optri::minmax_length(ps).unwrap())
    });
    group.finish();
}

fn convex_position(c: &mut Criterion) {
    let mut group = c.benchmark_group("minmax_length_convex");
    group.sample_size(10);
    // The cubic reference takes ~40 s at n = 1000; the example
    // `minmax_timing cubic 1000` measures that point once.
    for &n in &[300usize, 600] {
        let ps = PointSet::new(&perturbed_circle(n, 2)).unwrap();
        group.bench_with_input(BenchmarkId::new("quadratic", n), &ps, |b, ps| {
            b.iter(|| optri::minmax_length(ps).unwrap())
        });
        group.bench_with_input(BenchmarkId::new("cubic_reference", n), &ps, |b, ps| {
            b.iter(|| optri::minmax_length_cubic(ps).unwrap())
        });
    }
    for &n in &[1_000usize, 2_000] {
        let ps = PointSet::new(&perturbed_circle(n, 2)).unwrap();
        group.bench_with_input(BenchmarkId::new("quadratic", n), &ps, |b, ps| {
            b.iter(|| optri::minmax_length(ps).unwrap())
        });
    }
    group.finish();
}

criterion_group!(benches, uniform_points, convex_position);
criterion_main!(benches);
