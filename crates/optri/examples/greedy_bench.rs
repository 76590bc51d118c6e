//! Greedy-triangulation timings (seeded inputs), printed as one line each:
//!
//! ```text
//! cargo run --release -p optri --example greedy_bench -- uniform 1000000
//! cargo run --release -p optri --example greedy_bench -- convex 10000
//! cargo run --release -p optri --example greedy_bench -- semicircular 1000000
//! cargo run --release -p optri --example greedy_bench -- clustered 1000000
//! ```
//! `clustered N`: N points in N/1000 square clusters (at least 20) with
//! random centres and sizes over two orders of magnitude.
//! `uniform` reports GT time as a ratio to the Delaunay time of the same
//! run; every mode reports the peak resident set size (`VmHWM`) before and
//! after GT.

use optri::{delaunay, triangulate, Criterion, PointSet};
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

/// `n` points in strictly convex position, exactly: a lens of the integer
/// parabolas `y = x²` and `y = 2m² - x²`, `|x| ≤ m`, with distinct random
/// abscissae (not semicircular: both lens corners are sharp).
fn convex_points(rng: &mut StdRng, n: usize) -> Vec<[f64; 2]> {
    let m = 2 * n as i64;
    let side = |rng: &mut StdRng, k: usize| -> Vec<i64> {
        rand::seq::index::sample(rng, (2 * m - 1) as usize, k)
            .into_iter()
            .map(|i| i as i64 - m + 1)
            .collect()
    };
    let mut pts: Vec<[f64; 2]> = vec![[-m as f64, (m * m) as f64], [m as f64, (m * m) as f64]];
    let lower = side(rng, (n - 2) / 2);
    pts.extend(lower.iter().map(|&x| [x as f64, (x * x) as f64]));
    let upper = side(rng, n - 2 - (n - 2) / 2);
    pts.extend(
        upper
            .iter()
            .map(|&x| [x as f64, (2 * m * m - x * x) as f64]),
    );
    pts
}

/// `n` points on the integer parabola `y = x²`: semicircular (the base joins
/// the two extreme points, and every other point sees it at an obtuse angle).
fn semicircular_points(rng: &mut StdRng, n: usize) -> Vec<[f64; 2]> {
    rand::seq::index::sample(rng, 4 * n, n)
        .into_iter()
        .map(|x| [x as f64, (x as f64) * (x as f64)])
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
        "clustered" => {
            let clusters = (n / 1000).max(20);
            let mut pts = Vec::with_capacity(n);
            for c in 0..clusters {
                let centre = [rng.gen_range(-1e4..1e4), rng.gen_range(-1e4..1e4)];
                let r: f64 = rng.gen_range(10.0..2e3);
                let count = n / clusters + usize::from(c < n % clusters);
                for _ in 0..count {
                    pts.push([
                        centre[0] + rng.gen_range(-r..r),
                        centre[1] + rng.gen_range(-r..r),
                    ]);
                }
            }
            pts
        }
        other => panic!("unknown mode {other} (uniform | clustered | convex | semicircular)"),
    };
    let ps = PointSet::new(&pts).expect("valid points");
    let rss_before = peak_rss_mib();
    let start = Instant::now();
    let solution = triangulate(&ps, Criterion::Greedy).expect("greedy");
    let gt_s = start.elapsed().as_secs_f64();
    let rss_gt = peak_rss_mib();
    let t = &solution.triangulation;
    let total = t.stats().total_edge_length;
    let algorithm = solution.algorithm.split(':').next().unwrap_or_default();
    print!(
        "{mode} n={} algorithm={algorithm} gt={gt_s:.3}s total_length={total:.6e} \
         peak_rss_before={rss_before:.1}MiB peak_rss_after={rss_gt:.1}MiB",
        ps.len(),
    );
    if mode == "uniform" || mode == "clustered" {
        // This machine's timings vary by ±20% from run to run: alternate
        // Delaunay and GT runs and compare medians.
        let runs: usize = std::env::var("RUNS")
            .ok()
            .and_then(|r| r.parse().ok())
            .unwrap_or(3);
        let (mut dts, mut gts) = (Vec::new(), vec![gt_s]);
        for i in 0..runs {
            let start = Instant::now();
            let d = delaunay(&ps).expect("delaunay");
            dts.push(start.elapsed().as_secs_f64());
            assert_eq!(d.triangles().len(), t.triangles().len());
            if i + 1 < runs {
                let start = Instant::now();
                triangulate(&ps, Criterion::Greedy).expect("greedy");
                gts.push(start.elapsed().as_secs_f64());
            }
        }
        let median = |v: &mut Vec<f64>| {
            v.sort_by(f64::total_cmp);
            v[v.len() / 2]
        };
        let (d, g) = (median(&mut dts), median(&mut gts));
        print!(
            " delaunay_runs={dts:.3?} gt_runs={gts:.3?} median_delaunay={d:.3}s median_gt={g:.3}s ratio={:.2}",
            g / d
        );
    }
    println!();
    for phase in &solution.phases {
        println!("  phase {:20} {:9.1} ms", phase.name, phase.ms);
    }
}
