//! Criterion benchmarks for the minmax-length triangulation
//! (Edelsbrunner–Tan): uniform random points, alone and with the square's
//! boundary sampled at the mean spacing ("boxed": short hull edges, so the
//! Length-Lemma certificate keeps fewer regions), against Delaunay alone in
//! the same group and against the polygon algorithm run on every region
//! (certificate off); and points in convex position (one complete
//! rng-polygon, the O(n²) worst case of §6) against the cubic reference. The larger series
//! (10⁶ uniform points, convex n = 5k…40k) is in `examples/minmax_timing.rs`.
//!
//! `cargo bench -p optri --bench minmax_length`

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use optri::PointSet;
use optri_oracle::inputs::{boxed, perturbed_circle, uniform_unit_square};
use rand::{rngs::StdRng, SeedableRng};

const SEED_UNIFORM: u64 = 1;
const SEED_CONVEX: u64 = 2;

fn uniform_points(c: &mut Criterion) {
    let n = 100_000;
    // The same uniform points, with and without the boundary.
    for (name, pts) in [
        (
            "uniform",
            uniform_unit_square(&mut StdRng::seed_from_u64(SEED_UNIFORM), n),
        ),
        ("boxed", boxed(&mut StdRng::seed_from_u64(SEED_UNIFORM), n)),
    ] {
        let mut group = c.benchmark_group(format!("minmax_length_{name}"));
        group.sample_size(10);
        let ps = PointSet::new(&pts).unwrap();
        group.bench_with_input(BenchmarkId::new("delaunay", n), &ps, |b, ps| {
            b.iter(|| optri::delaunay(ps).unwrap())
        });
        group.bench_with_input(BenchmarkId::new("minmax_length", n), &ps, |b, ps| {
            b.iter(|| optri::triangulate(ps, optri::Criterion::MinMaxLength).unwrap())
        });
        group.bench_with_input(
            BenchmarkId::new("polygon_algorithm_on_every_region", n),
            &ps,
            |b, ps| {
                b.iter(|| {
                    optri::internals::minmax_length_with(ps, optri::internals::SMALL_REGION)
                        .unwrap()
                })
            },
        );
        group.finish();
    }
}

fn convex_position(c: &mut Criterion) {
    let mut group = c.benchmark_group("minmax_length_convex");
    group.sample_size(10);
    // The cubic reference takes ~40 s at n = 1000; the example
    // `minmax_timing cubic 1000` measures that point once.
    for &n in &[300usize, 600] {
        let pts = perturbed_circle(&mut StdRng::seed_from_u64(SEED_CONVEX), n, 1e-3);
        let ps = PointSet::new(&pts).unwrap();
        group.bench_with_input(BenchmarkId::new("quadratic", n), &ps, |b, ps| {
            b.iter(|| optri::triangulate(ps, optri::Criterion::MinMaxLength).unwrap())
        });
        group.bench_with_input(BenchmarkId::new("cubic_reference", n), &ps, |b, ps| {
            b.iter(|| optri::internals::minmax_length_cubic(ps).unwrap())
        });
    }
    for &n in &[1_000usize, 2_000] {
        let pts = perturbed_circle(&mut StdRng::seed_from_u64(SEED_CONVEX), n, 1e-3);
        let ps = PointSet::new(&pts).unwrap();
        group.bench_with_input(BenchmarkId::new("quadratic", n), &ps, |b, ps| {
            b.iter(|| optri::triangulate(ps, optri::Criterion::MinMaxLength).unwrap())
        });
    }
    group.finish();
}

criterion_group!(benches, uniform_points, convex_position);
criterion_main!(benches);
