//! Times the area criteria on points in strictly convex position: Algorithm
//! 44 (the product, `optri::triangulate`) against Klincsek's cubic program on
//! the same input, alternating runs, and reports peak memory.
//!
//! ```sh
//! cargo build --release -p optri-bench --bin area_timing
//! target/release/area_timing ratio 500 1000 2000     # product vs cubic, both criteria
//! target/release/area_timing scale 2000 4000 8000    # product only
//! ```

use optri::kernel::compare_areas;
use optri::{triangulate, Criterion, PointSet};
use optri_oracle::inputs::convex_lens;
use rand::{rngs::StdRng, SeedableRng};
use std::cmp::Ordering;
use std::time::Instant;

const SEED_CONVEX: u64 = 44;

fn secs<T>(f: impl FnOnce() -> T) -> (T, f64) {
    let start = Instant::now();
    let out = f();
    (out, start.elapsed().as_secs_f64())
}

fn peak_rss_kb() -> String {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM"))
                .map(|l| l.split_whitespace().nth(1).unwrap_or("?").to_string())
        })
        .unwrap_or_else(|| "?".into())
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let mut args = std::env::args().skip(1);
    let mode = args.next().unwrap_or_else(|| "ratio".into());
    let sizes: Vec<usize> = args.map(|a| a.parse().expect("a size")).collect();
    let runs: usize = std::env::var("RUNS")
        .ok()
        .and_then(|r| r.parse().ok())
        .unwrap_or(1);
    for n in sizes {
        let points = convex_lens(&mut StdRng::seed_from_u64(SEED_CONVEX), n);
        let ps = PointSet::new(&points).unwrap();
        if mode == "search" {
            // The second MaxMin route: sort the table's values, binary-search
            // them with Algorithm 49's O(n²) decision (brief §2.5).
            let ring: Vec<[f64; 2]> = optri::convex_hull(&ps)
                .iter()
                .map(|&i| ps.input_points()[i as usize])
                .collect();
            let polygon = optri::SimplePolygon::new(&ring).unwrap();
            let (t, secs_search) =
                secs(|| optri::MaxMinAreaDecision::new(&polygon).unwrap().optimum());
            t.validate().unwrap();
            println!("n={n} maxmin-area by sort-and-search: {secs_search:.3} s");
            println!("  peak RSS so far: {} kB", peak_rss_kb());
            continue;
        }
        for (criterion, maxmin) in [
            (Criterion::MaxminArea, true),
            (Criterion::MinmaxArea, false),
        ] {
            let mut product = Vec::new();
            let mut cubic = Vec::new();
            let pts = ps.points();
            // The bottleneck triangle of a triangulation (distinct indices).
            let bottleneck = |triangles: &[[u32; 3]]| -> [[f64; 2]; 3] {
                let corners = |t: &[u32; 3]| t.map(|v| pts[v as usize]);
                let mut best = corners(&triangles[0]);
                for t in &triangles[1..] {
                    let c = compare_areas(corners(t), best);
                    if (maxmin && c == Ordering::Less) || (!maxmin && c == Ordering::Greater) {
                        best = corners(t);
                    }
                }
                best
            };
            for _ in 0..runs {
                let (solution, t) = secs(|| triangulate(&ps, criterion).unwrap());
                solution.triangulation.validate().unwrap();
                product.push(t);
                if mode == "ratio" {
                    let (reference, t) =
                        secs(|| optri::internals::area_by_polygon_program(&ps, maxmin));
                    cubic.push(t);
                    let mine: Vec<[u32; 3]> = solution
                        .triangulation
                        .triangles()
                        .iter()
                        .map(|t| t.map(|i| ps.distinct_index(i)))
                        .collect();
                    // The optimal values must be equal (exactly).
                    assert_eq!(
                        compare_areas(bottleneck(&mine), bottleneck(&reference)),
                        Ordering::Equal,
                        "n = {n}, {}: Algorithm 44 and Klincsek disagree",
                        criterion.name()
                    );
                }
            }
            if mode == "ratio" {
                let (p, c) = (median(product.clone()), median(cubic.clone()));
                println!(
                    "n={n} {}: algorithm 44 {product:.3?} s, cubic {cubic:.3?} s, median ratio cubic/product {:.1}; optimal values equal",
                    criterion.name(),
                    c / p
                );
            } else {
                println!("n={n} {}: algorithm 44 {product:.3?} s", criterion.name());
            }
        }
        println!("  peak RSS so far: {} kB", peak_rss_kb());
    }
}
