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
//! `gaussian-clusters N`: N points in N/1000 Gaussian clusters (at least
//! 20) with centres uniform in the unit square and σ = 0.005 (the
//! clustered input of BENCHMARKS.md; `clustered` is the older square one).
//! `uniform-integer N`: `uniform` rounded to six decimals and scaled by
//! 10⁶, i.e. the integers the CLI computes on for a file of six-decimal
//! points (equal lengths are common there; `uniform` has practically none).
//! `fan N`: `(i, 0)` for `i < N` plus the apex `(N/2, 1)`.
//! `circle N`: the regular N-gon of radius 1000 sampled with cos/sin.
//! `random-circle N`: N points at random angles on that circle (rounded to
//! `f64`, convex position as rounding decides).
//! `perturbed-circle N`: the regular N-gon on the unit circle with radii
//! jittered by up to 10⁻⁹ (perturbed convex points: convex
//! position while the jitter stays below the sagitta, 5·10⁻⁸ at N = 10⁴).
//! Degenerate families (`cliff_family`): `run2apex N` (a run of
//! N − 2 integer points with apexes on both sides), `square N` (the boundary
//! of a square, N/4 integer points a side), `tiny-cluster N` (N points in a
//! 10⁻⁹ box plus two far points), `duplicates N` (N points, 100 distinct),
//! `grid N` (the ⌊√N⌋² integer grid), `two-circles N` (N/2 on each of two
//! concentric sampled circles), `nested-cluster N` (N/3 points in each of a
//! unit box, a 10⁻⁵ box and a 10⁻¹¹ box around one centre), `offset-cluster N`
//! (N points on the lattice of step 1/8, the doubles' spacing, near 10¹⁵, plus
//! three points 10¹¹ away), `duplicates3 N` (N copies of 3 points plus 5
//! others).
//! `star-polygon N`: the greedy polygon solver on a star of N vertices.
//! `cocircular N`: in one process, GT of `circle N`, `random-circle N` and
//! `2N`, `convex N` and `2N`, `perturbed-circle N` and `2N`, with the
//! ratios of BENCHMARKS.md; each set runs `REPEAT` times (default 5, alternating
//! with the others) and its fastest run counts.
//! With `WRITE_POINTS=FILE` the points are written to `FILE` with six
//! decimals (the input of whole CLI runs) instead of timed.
//! `uniform` reports GT time as a ratio to the Delaunay time of the same
//! run; every mode reports the peak resident set size (`VmHWM`) before and
//! after GT.

use optri::{delaunay, triangulate, Criterion, PointSet};
use optri_oracle::inputs::{
    circle_at_random_angles, clustered, convex_lens, fan, gaussian_clusters, perturbed_circle,
    random_parabola, sampled_circle, uniform_in_box,
};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use std::time::Instant;

const SEED: u64 = 2024;

/// The radial jitter of `perturbed-circle` (see the module docs).
const PERTURBATION: f64 = 1e-9;

/// The standard deviation of `gaussian-clusters` (centres in the unit
/// square): with 1000 clusters of 1000 points a
/// cluster's core is 6.4 times as dense as uniform points (peak density
/// `1000 / (2πσ²)`), its tails reach its neighbours (mean nearest-centre
/// distance about 3σ), and much of the square stays empty.
const GAUSSIAN_SIGMA: f64 = 0.005;

/// Seconds for one GT of `pts`, and the algorithm that ran.
fn time_gt(pts: &[[f64; 2]]) -> (f64, String) {
    let ps = PointSet::new(pts).expect("valid points");
    let start = Instant::now();
    let solution = triangulate(&ps, Criterion::Greedy).expect("greedy");
    let s = start.elapsed().as_secs_f64();
    let algorithm = solution.algorithm.split(' ').next().unwrap_or_default();
    (s, algorithm.to_string())
}

/// The cocircular figures of BENCHMARKS.md, all from one process.
fn cocircular(n: usize) {
    let mut rng = StdRng::seed_from_u64(SEED);
    let random_n = circle_at_random_angles(&mut rng, n, 1000.0);
    let random_2n = circle_at_random_angles(&mut rng, 2 * n, 1000.0);
    let lens_n = convex_lens(&mut rng, n);
    let lens_2n = convex_lens(&mut rng, 2 * n);
    let perturbed_n = perturbed_circle(&mut rng, n, PERTURBATION);
    let perturbed_2n = perturbed_circle(&mut rng, 2 * n, PERTURBATION);
    let sets = [
        ("circle", sampled_circle(n, 1000.0)),
        ("random-circle", random_n),
        ("random-circle-2n", random_2n),
        ("convex", lens_n),
        ("convex-2n", lens_2n),
        ("perturbed-circle", perturbed_n),
        ("perturbed-circle-2n", perturbed_2n),
    ];
    // Milliseconds-long runs are noisy: every set runs `REPEAT` times
    // (default 5), the sets alternating, and the fastest run counts.
    let repeat: usize = std::env::var("REPEAT")
        .ok()
        .and_then(|r| r.parse().ok())
        .unwrap_or(5)
        .max(1);
    let mut t = vec![f64::INFINITY; sets.len()];
    let mut algorithms = vec![String::new(); sets.len()];
    for _ in 0..repeat {
        for (i, (_, pts)) in sets.iter().enumerate() {
            let (s, algorithm) = time_gt(pts);
            t[i] = t[i].min(s);
            algorithms[i] = algorithm;
        }
    }
    for (i, (what, pts)) in sets.iter().enumerate() {
        println!(
            "{what} n={} algorithm={} gt={:.4}s (fastest of {repeat})",
            pts.len(),
            algorithms[i],
            t[i]
        );
    }
    println!(
        "circle/random-circle={:.2} circle/convex={:.2} circle/perturbed-circle={:.2} \
         random-circle 2n/n={:.2} convex 2n/n={:.2} perturbed-circle 2n/n={:.2}",
        t[0] / t[1],
        t[0] / t[3],
        t[0] / t[5],
        t[2] / t[1],
        t[4] / t[3],
        t[6] / t[5]
    );
}

/// GT of a star polygon of `n` vertices (radii alternating 10⁶ and
/// 4·10⁵, integer coordinates): the polygon solver, or its refusal.
fn star_polygon(n: usize) {
    let ring: Vec<[f64; 2]> = (0..n)
        .map(|i| {
            let r = if i % 2 == 0 { 1e6 } else { 4e5 };
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            [(r * a.cos()).round(), (r * a.sin()).round()]
        })
        .collect();
    let polygon = optri::SimplePolygon::new(&ring).expect("a simple star polygon");
    let clock = Instant::now();
    let result = optri::triangulate(&polygon, optri::Criterion::Greedy);
    let outcome = match &result {
        Ok(s) => format!("{} triangles", s.triangulation.triangles().len()),
        Err(e) => format!("refused: {e}"),
    };
    println!("star-polygon {n}: {:.2?}, {outcome}", clock.elapsed());
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let mode = args.get(1).map_or("uniform", String::as_str);
    let n: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(100_000);
    if mode == "cocircular" {
        return cocircular(n);
    }
    if mode == "star-polygon" {
        return star_polygon(n);
    }
    let mut rng = StdRng::seed_from_u64(SEED);
    let pts = match mode {
        "uniform" => uniform_in_box(&mut rng, n, [0.0, 0.0], [1.0, 1.0]),
        "uniform-integer" => uniform_in_box(&mut rng, n, [0.0, 0.0], [1.0, 1.0])
            .into_iter()
            .map(|p| p.map(|x| (x * 1e6).round()))
            .collect(),
        // A lens of two integer parabolas: strictly convex, not semicircular.
        "convex" => convex_lens(&mut rng, n),
        // Integer points on `y = x²`: semicircular.
        "semicircular" => random_parabola(&mut rng, n, 4 * n),
        "clustered" => clustered(&mut rng, n, (n / 1000).max(20)),
        "gaussian-clusters" => gaussian_clusters(&mut rng, n, (n / 1000).max(20), GAUSSIAN_SIGMA),
        "fan" => fan(n),
        "circle" => sampled_circle(n, 1000.0),
        "random-circle" => circle_at_random_angles(&mut rng, n, 1000.0),
        "perturbed-circle" => perturbed_circle(&mut rng, n, PERTURBATION),
        other if cliff_family(other, n).is_some() => cliff_family(other, n).expect("checked"),
        other => panic!(
            "unknown mode {other} (uniform | uniform-integer | clustered \
             | gaussian-clusters (sigma 0.005) | convex | semicircular | fan \
             | circle | random-circle | perturbed-circle | cocircular | run2apex | square | tiny-cluster | duplicates \
             | grid | two-circles | nested-cluster | offset-cluster | duplicates3)"
        ),
    };
    if let Ok(path) = std::env::var("WRITE_POINTS") {
        // The input for whole CLI runs: six decimals, one point a line.
        let text: String = pts
            .iter()
            .map(|p| format!("{:.6} {:.6}\n", p[0], p[1]))
            .collect();
        std::fs::write(&path, text).expect("write the points");
        println!("wrote {} points to {path}", pts.len());
        return;
    }
    let ps = PointSet::new(&pts).expect("valid points");
    let rss_before = optri_bench::peak_rss_kb().map_or(f64::NAN, |kb| kb as f64 / 1024.0);
    let start = Instant::now();
    let solution = triangulate(&ps, Criterion::Greedy).expect("greedy");
    let gt_s = start.elapsed().as_secs_f64();
    let rss_gt = optri_bench::peak_rss_kb().map_or(f64::NAN, |kb| kb as f64 / 1024.0);
    let t = &solution.triangulation;
    let total = t.stats().total_edge_length;
    let algorithm = solution.algorithm.split(':').next().unwrap_or_default();
    print!(
        "{mode} n={} algorithm={algorithm} gt={gt_s:.3}s total_length={total:.6e} \
         peak_rss_before={rss_before:.1}MiB peak_rss_after={rss_gt:.1}MiB",
        ps.len(),
    );
    if matches!(
        mode,
        "uniform" | "uniform-integer" | "clustered" | "gaussian-clusters" | "fan"
    ) {
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

/// The degenerate families by name (module docs), `None` for other
/// names.
fn cliff_family(mode: &str, n: usize) -> Option<Vec<[f64; 2]>> {
    let mut rng = StdRng::seed_from_u64(SEED);
    Some(match mode {
        "run2apex" => {
            let k = n.saturating_sub(2).max(3);
            let mut pts: Vec<[f64; 2]> = (0..k).map(|i| [i as f64, 0.0]).collect();
            pts.extend([[(k / 3) as f64, 1.0], [(2 * k / 3) as f64, -1.0]]);
            pts
        }
        "square" => {
            let side = (n / 4).max(2) as f64;
            (0..(n / 4).max(2))
                .flat_map(|i| {
                    let t = i as f64;
                    [[t, 0.0], [side, t], [side - t, side], [0.0, side - t]]
                })
                .collect()
        }
        "tiny-cluster" => {
            let mut pts = uniform_in_box(&mut rng, n, [0.5, 0.5], [0.5 + 1e-9, 0.5 + 1e-9]);
            pts.extend([[0.0, 0.0], [1.0, 0.3]]);
            pts
        }
        "nested-cluster" => {
            let c = [0.3, 0.7];
            let mut pts = Vec::with_capacity(n);
            for side in [1.0, 1e-5, 1e-11] {
                let h = 0.5 * side;
                pts.extend(uniform_in_box(
                    &mut rng,
                    n / 3,
                    [c[0] - h, c[1] - h],
                    [c[0] + h, c[1] + h],
                ));
            }
            pts
        }
        "offset-cluster" => {
            let o = 1e15;
            let side = (n as f64).sqrt() as i64 * 2;
            let mut pts: Vec<[f64; 2]> = (0..n)
                .map(|_| {
                    let mut lattice = || o + 0.125 * rng.gen_range(0..side) as f64;
                    [lattice(), lattice()]
                })
                .collect();
            pts.extend([[o - 1e11, o - 3e10], [o + 1e11, o + 2e10], [o, o + 1e11]]);
            pts
        }
        "duplicates3" => {
            let three = uniform_in_box(&mut rng, 3, [0.0, 0.0], [1.0, 1.0]);
            let mut pts: Vec<[f64; 2]> = (0..n).map(|i| three[i % 3]).collect();
            pts.extend(uniform_in_box(&mut rng, 5, [-1.0, -1.0], [2.0, 2.0]));
            pts
        }
        "duplicates" => {
            let distinct = uniform_in_box(&mut rng, 100, [0.0, 0.0], [1.0, 1.0]);
            (0..n).map(|i| distinct[i % distinct.len()]).collect()
        }
        "grid" => {
            let side = (n as f64).sqrt() as usize;
            (0..side * side)
                .map(|i| [(i % side) as f64, (i / side) as f64])
                .collect()
        }
        "two-circles" => {
            let mut pts = sampled_circle(n / 2, 1000.0);
            pts.extend(sampled_circle(n - n / 2, 500.0));
            pts
        }
        _ => return None,
    })
}
