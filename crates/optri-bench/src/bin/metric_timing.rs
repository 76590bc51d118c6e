//! Times minmax-length under normed metrics against the Euclidean Delaunay
//! triangulation of the same input, for the figures in BENCHMARKS.md.
//!
//! ```text
//! cargo run --release -p optri-bench --bin metric_timing -- uniform N [METRIC...]
//! cargo run --release -p optri-bench --bin metric_timing -- framed N [METRIC...]
//! cargo run --release -p optri-bench --bin metric_timing -- arc METRIC N...
//! cargo run --release -p optri-bench --bin metric_timing -- circle METRIC N...
//! cargo run --release -p optri-bench --bin metric_timing -- regular METRIC N...
//! ```
//! * `uniform N` (default 1 000 000; metrics default `l1 linf`): Delaunay
//!   alone, then minmax-length under each metric with its phases, and the
//!   ratio to the Delaunay time.
//! * `framed N`: the same N uniform points plus 4·⌈√N⌉ evenly spaced points on
//!   the square's sides (the boundary sampled as finely as the interior): the hull
//!   segments are short, so the hull certificate fails and every phase runs.
//! * `arc METRIC N…`: N points in convex position on a 120° circular arc
//!   (radius jittered by 1e-9 relative): one incomplete region, solved by
//!   §5.1; time per N and time / N².
//! * `circle METRIC N…`: the same on the whole circle: complete regions
//!   (every hull segment is an RNG edge), solved by §5.3/§6 where they are
//!   strictly convex or tiled by the Delaunay triangles; from n ≈ 4000 the
//!   jitter puts points inside the hull, and regions cut by non-Delaunay RNG
//!   chords go to the cubic program (`complete_regions_outside_mesh`).
//! * `regular METRIC N…`: the regular N-gon of radius 1000 (strictly convex).
//!
//! Both convex modes also time the Euclidean minmax-length triangulation of
//! the same points in the same process, and print the ratio to the previous
//! N (≈ 4 per doubling for O(n²)).

use optri::kernel::Metric;
use optri::{triangulate_with, Criterion, Options, PointSet};
use optri_oracle::inputs::uniform_unit_square;
use rand::{rngs::StdRng, Rng, SeedableRng};
use std::time::Instant;

const SEED_UNIFORM: u64 = 1;
const SEED_ARC: u64 = 2;

fn secs<T>(f: impl FnOnce() -> T) -> (T, f64) {
    let t = Instant::now();
    let out = f();
    (out, t.elapsed().as_secs_f64())
}

fn arc(n: usize, turn: f64) -> Vec<[f64; 2]> {
    let mut rng = StdRng::seed_from_u64(SEED_ARC);
    (0..n)
        .map(|_| {
            let a: f64 = rng.gen_range(0.0..2.0 * std::f64::consts::PI * turn);
            let r = 1e3 * (1.0 + rng.gen_range(-1e-9..1e-9));
            [r * a.cos(), r * a.sin()]
        })
        .collect()
}

/// The regular `n`-gon of radius 1000 as `f64` samples: strictly convex
/// position (the sagitta stays far above the rounding), every chord length
/// repeated n times (ties for every norm).
fn regular(n: usize) -> Vec<[f64; 2]> {
    (0..n)
        .map(|i| {
            let a = 2.0 * std::f64::consts::PI * i as f64 / n as f64;
            [1e3 * a.cos(), 1e3 * a.sin()]
        })
        .collect()
}

fn minmax(points: &PointSet, metric: &Metric) -> optri::Solution {
    let options = Options::default().with_metric(metric.clone());
    triangulate_with(points, Criterion::MinMaxLength, &options).expect("minmax-length")
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some(kind @ ("arc" | "circle" | "regular")) => {
            let turn = if kind == "arc" { 1.0 / 3.0 } else { 1.0 };
            let metric = Metric::parse(&args[1]).expect("metric");
            let mut previous: Option<f64> = None;
            for n in args[2..].iter().map(|s| s.parse::<usize>().expect("N")) {
                let pts = if kind == "regular" {
                    regular(n)
                } else {
                    arc(n, turn)
                };
                let ps = PointSet::new(&pts).unwrap();
                let (_, euclidean) = secs(|| minmax(&ps, &Metric::euclidean()));
                let (s, t) = secs(|| minmax(&ps, &metric));
                let d: Vec<String> = s
                    .diagnostics
                    .iter()
                    .map(|(k, v)| format!("{k}={v}"))
                    .collect();
                let doubling =
                    previous.map_or(String::new(), |p| format!(", {:.2}× previous", t / p));
                previous = Some(t);
                println!(
                    "{kind} {metric} n={n}: {t:.3} s{doubling}, {:.3e} s/n², Euclidean {euclidean:.3} s ({:.2}×), {}",
                    t / (n as f64 * n as f64),
                    t / euclidean,
                    d.join(" ")
                );
            }
        }
        _ => {
            let n = args.get(1).map_or(1_000_000, |s| s.parse().expect("N"));
            let metrics: Vec<Metric> = if args.len() > 2 {
                args[2..]
                    .iter()
                    .map(|m| Metric::parse(m).expect("metric"))
                    .collect()
            } else {
                vec![Metric::l1(), Metric::linf()]
            };
            let mut rng = StdRng::seed_from_u64(SEED_UNIFORM);
            let mut pts = uniform_unit_square(&mut rng, n);
            let framed = args.first().map(String::as_str) == Some("framed");
            if framed {
                let side = (n as f64).sqrt().ceil() as usize;
                for i in 0..side {
                    let t = i as f64 / side as f64;
                    pts.extend([[t, 0.0], [1.0, t], [1.0 - t, 1.0], [0.0, 1.0 - t]]);
                }
            }
            let ps = PointSet::new(&pts).unwrap();
            let (_, delaunay) = secs(|| optri::delaunay(&ps).expect("delaunay"));
            let kind = if framed { "framed" } else { "uniform" };
            println!("{kind} n={}: Delaunay {delaunay:.3} s", pts.len());
            for metric in &metrics {
                let (s, t) = secs(|| minmax(&ps, metric));
                let phases: Vec<String> = s
                    .phases
                    .iter()
                    .map(|p| format!("{} {:.3}", p.name, p.ms / 1e3))
                    .collect();
                let (_, longest) = s.longest_edge_under_metric();
                println!(
                    "  minmax-length {metric}: {t:.3} s = {:.2}× Delaunay; longest edge {longest:.6e}; phases (s): {}; {}",
                    t / delaunay,
                    phases.join(", "),
                    s.diagnostics
                        .iter()
                        .map(|(k, v)| format!("{k}={v}"))
                        .collect::<Vec<_>>()
                        .join(" ")
                );
            }
        }
    }
}
