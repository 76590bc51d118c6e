//! Criterion benchmarks: Delaunay crates (spade via optri, delaunator) and
//! optri's proximity graphs on uniform random points.
//!
//! `cargo bench -p optri --bench proximity`

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use optri::PointSet;
use optri_oracle::inputs::uniform_unit_square;
use rand::{rngs::StdRng, SeedableRng};

const SEED_UNIFORM: u64 = 1;

fn proximity(c: &mut Criterion) {
    let mut group = c.benchmark_group("proximity");
    group.sample_size(10);
    for &n in &[10_000usize, 100_000] {
        let points = uniform_unit_square(&mut StdRng::seed_from_u64(SEED_UNIFORM), n);
        let ps = PointSet::new(&points).unwrap();
        group.bench_with_input(BenchmarkId::new("spade_delaunay", n), &ps, |b, ps| {
            b.iter(|| optri::delaunay(ps).unwrap())
        });
        let dpts: Vec<delaunator::Point> = points
            .iter()
            .map(|p| delaunator::Point { x: p[0], y: p[1] })
            .collect();
        group.bench_with_input(BenchmarkId::new("delaunator", n), &dpts, |b, d| {
            b.iter(|| delaunator::triangulate(d))
        });
        group.bench_with_input(BenchmarkId::new("delaunay_edges", n), &ps, |b, ps| {
            b.iter(|| optri::delaunay(ps).unwrap().edges())
        });
        group.bench_with_input(
            BenchmarkId::new("relative_neighborhood_graph", n),
            &ps,
            |b, ps| b.iter(|| optri::relative_neighborhood_graph(ps).unwrap()),
        );
        group.bench_with_input(BenchmarkId::new("gabriel_graph", n), &ps, |b, ps| {
            b.iter(|| optri::gabriel_graph(ps).unwrap())
        });
        group.bench_with_input(
            BenchmarkId::new("minimum_spanning_tree", n),
            &ps,
            |b, ps| b.iter(|| optri::minimum_spanning_tree(ps).unwrap()),
        );
    }
    group.finish();
}

criterion_group!(benches, proximity);
criterion_main!(benches);
