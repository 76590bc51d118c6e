//! Times the general minimum-weight pipeline against the Delaunay
//! triangulation of the same input in one process (figures in
//! BENCHMARKS.md), with its per-phase times and counters.
//!
//! ```text
//! cargo run --release -p optri-bench --bin min_weight_timing -- [N | FILE...]
//! ```
//! N (default 1 000 000) uniform points in the unit square, or the given
//! point files (TSPLIB and the other formats optri reads).

use optri::{triangulate, Criterion, PointSet};
use optri_oracle::inputs::uniform_unit_square;
use rand::{rngs::StdRng, SeedableRng};
use std::time::Instant;

const SEED_UNIFORM: u64 = 2026;

fn run(name: &str, points: &[[f64; 2]]) {
    let ps = PointSet::new(points).expect("a valid point set");
    let t = Instant::now();
    let d = triangulate(&ps, Criterion::Delaunay).unwrap();
    let delaunay = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let s = triangulate(&ps, Criterion::MinWeight).unwrap();
    let mwt = t.elapsed().as_secs_f64();
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
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.is_empty() || args[0].parse::<usize>().is_ok() {
        let n = args.first().map_or(1_000_000, |a| a.parse().unwrap());
        let mut rng = StdRng::seed_from_u64(SEED_UNIFORM);
        let pts = uniform_unit_square(&mut rng, n);
        run(&format!("uniform {n}"), &pts);
    } else {
        for path in args {
            let pts = optri::io::read_points_file(std::path::Path::new(&path), None).unwrap();
            run(&path, &pts);
        }
    }
}
