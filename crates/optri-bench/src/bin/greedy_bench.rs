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
use optri_oracle::inputs::{clustered, convex_lens, random_parabola, uniform_in_box};
use rand::rngs::StdRng;
use rand::SeedableRng;
use std::time::Instant;

const SEED: u64 = 2024;

fn peak_rss_mib() -> f64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    status
        .lines()
        .find(|l| l.starts_with("VmHWM:"))
        .and_then(|l| l.split_whitespace().nth(1))
        .and_then(|kb| kb.parse::<f64>().ok())
        .map_or(f64::NAN, |kb| kb / 1024.0)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let mode = args.get(1).map_or("uniform", String::as_str);
    let n: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(100_000);
    let mut rng = StdRng::seed_from_u64(SEED);
    let pts = match mode {
        "uniform" => uniform_in_box(&mut rng, n, [0.0, 0.0], [1.0, 1.0]),
        // A lens of two integer parabolas: strictly convex, not semicircular.
        "convex" => convex_lens(&mut rng, n),
        // Integer points on `y = x²`: semicircular.
        "semicircular" => random_parabola(&mut rng, n, 4 * n),
        "clustered" => clustered(&mut rng, n, (n / 1000).max(20)),
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
