//! Greedy-triangulation timings (seeded inputs), printed as one line each:
//!
//! ```text
//! cargo run --release -p optri --example greedy_bench -- uniform 1000000
//! cargo run --release -p optri --example greedy_bench -- convex 100000
//! cargo run --release -p optri --example greedy_bench -- semicircular 1000000
//! ```
//! `uniform` reports GT time as a ratio to the Delaunay time of the same
//! run; every mode reports the peak resident set size (`VmHWM`).

use optri::greedy::greedy_triangulation;
use optri::{delaunay, PointSet};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use std::time::Instant;

fn peak_rss_mib() -> f64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    status
        .lines()
        .find(|l| l.starts_with("VmHWM:"))
        .and_then(|l| l.split_whitespace().nth(1))
        .and_then(|kb| kb.parse::<f64>().ok())
        .map_or(f64::NAN, |kb| kb / 1024.0)
}

/// `n` points on a circle-like strictly convex curve (an ellipse, rounded).
fn convex_points(rng: &mut StdRng, n: usize) -> Vec<[f64; 2]> {
    let mut angles: Vec<f64> = (0..n)
        .map(|_| rng.gen_range(0.0..std::f64::consts::TAU))
        .collect();
    angles.sort_by(f64::total_cmp);
    angles
        .iter()
        .map(|a| [1e6 * a.cos(), 6e5 * a.sin()])
        .collect()
}

/// `n` points on a flat arc: semicircular (base = the chord's endpoints).
fn semicircular_points(rng: &mut StdRng, n: usize) -> Vec<[f64; 2]> {
    let mut angles: Vec<f64> = (0..n).map(|_| rng.gen_range(0.2..2.9)).collect();
    angles.sort_by(f64::total_cmp);
    angles
        .iter()
        .map(|a| [1e6 * a.cos(), 1e6 * a.sin()])
        .collect()
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let mode = args.get(1).map_or("uniform", String::as_str);
    let n: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(100_000);
    let mut rng = StdRng::seed_from_u64(2024);
    let pts = match mode {
        "uniform" => (0..n)
            .map(|_| [rng.gen_range(0.0..1.0), rng.gen_range(0.0..1.0)])
            .collect(),
        "convex" => convex_points(&mut rng, n),
        "semicircular" => semicircular_points(&mut rng, n),
        other => panic!("unknown mode {other}"),
    };
    let ps = PointSet::new(&pts).expect("valid points");
    let rss_before = peak_rss_mib();
    let start = Instant::now();
    let (t, algorithm) = greedy_triangulation(&ps).expect("greedy");
    let gt_s = start.elapsed().as_secs_f64();
    let rss_gt = peak_rss_mib();
    let total = t.stats().total_edge_length;
    print!(
        "{mode} n={} algorithm={} gt={gt_s:.3}s total_length={total:.6e} peak_rss_before={rss_before:.1}MiB peak_rss_after={rss_gt:.1}MiB",
        ps.len(),
        algorithm.name()
    );
    if mode == "uniform" {
        let start = Instant::now();
        let d = delaunay(&ps).expect("delaunay");
        let dt_s = start.elapsed().as_secs_f64();
        assert_eq!(d.triangles().len(), t.triangles().len());
        print!(" delaunay={dt_s:.3}s ratio={:.2}", gt_s / dt_s);
    }
    println!();
}
