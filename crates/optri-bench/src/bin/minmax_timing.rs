//! Times the minmax-length triangulation against Delaunay in one process,
//! for the figures in BENCHMARKS.md.
//!
//! ```text
//! cargo run --release -p optri --example minmax_timing [-- uniform N | convex N... | cubic N...]
//! ```
//! * `uniform N` (default N = 1 000 000): Delaunay alone, then minmax-length
//!   (with its phases), and the ratio; then the same with the Length-Lemma
//!   certificate off, so that every region runs the paper's polygon
//!   algorithm (unless `SKIP_PURE` is set).
//! * `boxed N`: N uniform points plus the unit square's boundary sampled at
//!   the mean spacing (a meshing domain): the hull edges are short, so the
//!   Length-Lemma bound comes from the RNG and certifies less.
//! * `tsp FILE…`: the same comparison on TSPLIB files.
//! * `convex N…`: points on a circle with radius perturbed by 1e-3 (one
//!   complete rng-polygon), minmax-length time per N and time / N².
//! * `cubic N…`: the same convex sets, quadratic vs the cubic reference.
//!
//! Peak resident memory (VmHWM) is printed at the end.

use optri::internals::SMALL_REGION;
use optri::io::{self, InputFormat, ReadOptions, Source};
use optri::{Criterion, Diagnostics, PointSet};
use optri_oracle::inputs::{boxed, perturbed_circle, uniform_unit_square};
use rand::{rngs::StdRng, SeedableRng};
use std::path::Path;
use std::time::Instant;

const SEED_UNIFORM: u64 = 1;
const SEED_CONVEX: u64 = 2;

/// Points on the unit circle with the radius perturbed by up to 1e-3.
fn convex(n: usize) -> Vec<[f64; 2]> {
    perturbed_circle(&mut StdRng::seed_from_u64(SEED_CONVEX), n, 1e-3)
}

fn secs<T>(f: impl FnOnce() -> T) -> (T, f64) {
    let t = Instant::now();
    let out = f();
    (out, t.elapsed().as_secs_f64())
}

/// A run's diagnostics (see `optri::minmax_length`'s module docs) as
/// `name=value` pairs.
fn counters(d: &Diagnostics) -> String {
    d.iter()
        .map(|(name, value)| format!("{name}={value}"))
        .collect::<Vec<_>>()
        .join(" ")
}

/// Delaunay alone, the product, and (unless `SKIP_PURE`) the paper's
/// polygon algorithm on every region (no Length-Lemma certificate).
fn compare_with_delaunay(name: &str, ps: &PointSet) {
    // Timings here vary by ±20% from run to run: alternate the runs and
    // compare medians (RUNS of each, default 3).
    let runs: usize = std::env::var("RUNS")
        .ok()
        .and_then(|r| r.parse().ok())
        .unwrap_or(3);
    let median = |mut v: Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let (mut dts, mut ms, mut qs) = (Vec::new(), Vec::new(), Vec::new());
    let (mut solution, mut pure) = (None, None);
    for _ in 0..runs {
        dts.push(secs(|| optri::delaunay(ps).unwrap()).1);
        let (s, m) = secs(|| optri::triangulate(ps, Criterion::MinMaxLength).unwrap());
        ms.push(m);
        solution = Some(s);
        if std::env::var_os("SKIP_PURE").is_none() {
            let ((_, d), q) =
                secs(|| optri::internals::minmax_length_with(ps, SMALL_REGION).unwrap());
            qs.push(q);
            pure = Some(d);
        }
    }
    let s = solution.expect("at least one run");
    let (d, m) = (median(dts.clone()), median(ms.clone()));
    println!(
        "{name} n={}: delaunay {dts:.3?} minmax-length {ms:.3?}; medians {d:.3} s and {m:.3} s, ratio {:.2}",
        ps.len(),
        m / d
    );
    for p in &s.phases {
        println!("  phase {:12} {:9.1} ms", p.name, p.ms);
    }
    println!("  {}", counters(&s.diagnostics));
    let Some(pure) = pure else {
        return;
    };
    let q = median(qs.clone());
    println!(
        "  without the certificate (every region by the polygon algorithm): {qs:.3?}, median {q:.3} s, ratio {:.2}",
        q / d
    );
    println!("  {}", counters(&pure));
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mode = args.first().map(String::as_str).unwrap_or("uniform");
    let sizes: Vec<usize> = args.iter().skip(1).filter_map(|a| a.parse().ok()).collect();
    match mode {
        "uniform" => {
            let n = sizes.first().copied().unwrap_or(1_000_000);
            let pts = uniform_unit_square(&mut StdRng::seed_from_u64(SEED_UNIFORM), n);
            compare_with_delaunay("uniform", &PointSet::new(&pts).unwrap());
        }
        "boxed" => {
            let n = sizes.first().copied().unwrap_or(1_000_000);
            let pts = boxed(&mut StdRng::seed_from_u64(SEED_UNIFORM), n);
            compare_with_delaunay("boxed", &PointSet::new(&pts).unwrap());
        }
        "tsp" => {
            for path in args.iter().skip(1) {
                let options = ReadOptions::default().with_format(InputFormat::Tsplib);
                let read = io::read(Source::Path(Path::new(path)), &options).unwrap();
                compare_with_delaunay(path, &PointSet::new(read.input.points()).unwrap());
            }
        }
        "convex" => {
            for &n in &sizes {
                let ps = PointSet::new(&convex(n)).unwrap();
                let (s, m) = secs(|| optri::triangulate(&ps, Criterion::MinMaxLength).unwrap());
                let poly = s
                    .phases
                    .iter()
                    .find(|p| p.name == "polygons")
                    .map_or(0.0, |p| p.ms);
                println!(
                    "convex n={n}: minmax-length {m:.3} s (polygons {:.3} s), polygons/n² = {:.2} ns",
                    poly / 1e3,
                    poly * 1e6 / (n as f64 * n as f64)
                );
                println!("  {}", counters(&s.diagnostics));
            }
        }
        "cubic" => {
            for &n in &sizes {
                let ps = PointSet::new(&convex(n)).unwrap();
                let (t, q) = secs(|| {
                    optri::triangulate(&ps, optri::Criterion::MinMaxLength)
                        .unwrap()
                        .triangulation
                });
                let (r, c) = secs(|| optri::internals::minmax_length_cubic(&ps).unwrap());
                let le = |t: &optri::Triangulation| {
                    let e = t.longest_edge();
                    let p = ps.input_points();
                    [p[e[0] as usize], p[e[1] as usize]]
                };
                let (a, b) = (le(&t), le(&r));
                let same = optri::kernel::compare_lengths(a[0], a[1], b[0], b[1]).is_eq();
                println!(
                    "convex n={n}: quadratic {q:.3} s, cubic {c:.3} s, cubic/quadratic {:.1}, same optimum: {same}",
                    c / q
                );
            }
        }
        "cutoff" => {
            // cutoff N c…: the product's polygon phase with the quadratic
            // algorithm on regions of at least c corners.
            let n = sizes.first().copied().unwrap_or(200_000);
            let pts = uniform_unit_square(&mut StdRng::seed_from_u64(SEED_UNIFORM), n);
            let ps = PointSet::new(&pts).unwrap();
            for &c in &sizes[1..] {
                let (_, t) = secs(|| optri::internals::minmax_length_with(&ps, c).unwrap());
                println!("uniform n={n}, quadratic from {c} corners: {t:.3} s");
            }
        }
        _ => eprintln!("modes: uniform N | tsp FILE... | convex N... | cubic N... | cutoff N c..."),
    }
    println!(
        "peak memory: {}",
        optri_bench::peak_rss_kb().map_or("VmHWM unavailable".to_string(), |kb| format!(
            "VmHWM: {kb} kB"
        ))
    );
}
