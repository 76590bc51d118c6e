//! Times the general minimum-weight pipeline against the Delaunay
//! triangulation of the same input in one process (figures in
//! BENCHMARKS.md), with its per-phase times and counters.
//!
//! ```text
//! cargo run --release -p optri-bench --bin min_weight_timing -- [--repeat K] [N | FILE...]
//! ```
//! N (default 1 000 000) uniform points in the unit square, or the given
//! point files (TSPLIB and the other formats optri reads). With `--repeat
//! K` the two are run alternately K times (Delaunay first); each pair is
//! printed, and the ratio of the fastest runs (the machines here are noisy:
//! a run is only ever slowed down by the neighbours).

use optri::io::{self, ReadOptions, Source};
use optri::{triangulate, Criterion, PointSet};
use optri_oracle::inputs::uniform_unit_square;
use rand::{rngs::StdRng, SeedableRng};
use std::time::Instant;

const SEED_UNIFORM: u64 = 2026;

fn run(name: &str, points: &[[f64; 2]], repeat: usize) {
    let ps = PointSet::new(points).expect("a valid point set");
    let (mut delaunay, mut mwt) = (f64::INFINITY, f64::INFINITY);
    let mut last = None;
    for round in 1..=repeat {
        let t = Instant::now();
        let d = triangulate(&ps, Criterion::Delaunay).unwrap();
        let td = t.elapsed().as_secs_f64();
        drop(last.take());
        let t = Instant::now();
        let s = triangulate(&ps, Criterion::MinWeight).unwrap();
        let tm = t.elapsed().as_secs_f64();
        if repeat > 1 {
            println!(
                "  round {round}: delaunay {td:.3} s, min-weight {tm:.3} s, ratio {:.2}",
                tm / td
            );
        }
        delaunay = delaunay.min(td);
        mwt = mwt.min(tm);
        last = Some((d, s));
    }
    let (d, s) = last.expect("at least one round");
    s.triangulation.validate().unwrap();
    let (wd, wm) = (
        d.triangulation.stats().total_edge_length,
        s.triangulation.stats().total_edge_length,
    );
    println!(
        "{name}: n = {}, delaunay {delaunay:.3} s, min-weight {mwt:.3} s, ratio {:.2}, exact {}, weight {wm:.6} (Delaunay {wd:.6}, {:.4}% lighter)",
        ps.len(),
        mwt / delaunay,
        s.exact,
        100.0 * (wd - wm) / wd
    );
    let phases: Vec<String> = s
        .phases
        .iter()
        .map(|p| format!("{} {:.0} ms", p.name, p.ms))
        .collect();
    println!("  phases: {}", phases.join(", "));
    let counters: Vec<String> = s
        .diagnostics
        .iter()
        .map(|(k, v)| format!("{k} {v}"))
        .collect();
    println!("  counters: {}", counters.join(", "));
    println!("  algorithm: {}", s.algorithm);
}

fn main() {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let mut repeat = 1;
    if args.first().is_some_and(|a| a == "--repeat") {
        repeat = args
            .get(1)
            .and_then(|k| k.parse().ok())
            .filter(|&k| k > 0)
            .expect("--repeat K, K >= 1");
        args.drain(..2);
    }
    if args.is_empty() || args[0].parse::<usize>().is_ok() {
        let n = args.first().map_or(1_000_000, |a| a.parse().unwrap());
        let mut rng = StdRng::seed_from_u64(SEED_UNIFORM);
        let pts = uniform_unit_square(&mut rng, n);
        run(&format!("uniform {n}"), &pts, repeat);
    } else {
        for path in args {
            let source = Source::Path(std::path::Path::new(&path));
            let read = io::read(source, &ReadOptions::default()).unwrap();
            run(&path, read.input.points(), repeat);
        }
    }
}
