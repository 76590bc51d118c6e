//! Times the area criteria on points in strictly convex position: Algorithm
//! 44 (the product, `optri::triangulate`) against Klincsek's cubic program on
//! the same input, alternating runs, and reports peak memory.
//!
//! ```sh
//! cargo build --release -p optri-bench --bin area_timing
//! target/release/area_timing ratio 500 1000 2000     # product vs cubic, both criteria
//! target/release/area_timing scale 2000 4000 8000    # product only
//! target/release/area_timing routes 500 1000 2000    # the routes' CPU times
//! target/release/area_timing decide 500 1000 2000    # one-shot decision vs the table's
//! ```
//! `decide`: one MaxMin decision at the optimum (a yes) and just above it (a
//! no), by Algorithm 49 in one shot (`decide_area`) and by building the
//! sorted table first (`maxmin_area_at_least`), alternating `RUNS` times.
//! `routes`: both MaxMin routes of Algorithm 44 (range-max and
//! sort-and-search) and MinMax on ellipse polygons, CPU (wall) seconds and
//! their growth against `n² log n`.

use optri::kernel::compare_areas;
use optri::{triangulate, Criterion, PointSet};
use optri_bench::peak_rss_kb;
use optri_oracle::inputs::{convex_lens, ellipse_polygon};
use rand::{rngs::StdRng, SeedableRng};
use std::cmp::Ordering;
use std::time::Instant;

const SEED_CONVEX: u64 = 44;
const SEED_ROUTES: u64 = 0x5449_4d45_0000_000a;

fn secs<T>(f: impl FnOnce() -> T) -> (T, f64) {
    let start = Instant::now();
    let out = f();
    (out, start.elapsed().as_secs_f64())
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// CPU seconds of this thread so far (Linux), if readable.
fn thread_cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    let nanos: f64 = stat.split_whitespace().next()?.parse().ok()?;
    Some(nanos * 1e-9)
}

/// Runs `f`, returning its result, wall-clock seconds and CPU seconds.
fn timed<T>(f: impl FnOnce() -> T) -> (T, f64, f64) {
    let (wall, cpu) = (Instant::now(), thread_cpu_seconds());
    let out = f();
    let cpu = match (cpu, thread_cpu_seconds()) {
        (Some(a), Some(b)) => b - a,
        _ => f64::NAN,
    };
    (out, wall.elapsed().as_secs_f64(), cpu)
}

/// The two MaxMin routes and MinMax on strictly convex ellipse polygons:
/// CPU (wall) seconds, the routes' optima equal, and the growth of the CPU
/// times against `n² log n`.
fn routes(sizes: &[usize]) {
    let mut rng = StdRng::seed_from_u64(SEED_ROUTES);
    let mut previous: Option<(usize, [f64; 3])> = None;
    for &n in sizes {
        let points = ellipse_polygon(&mut rng, n, 1e12, 1.0);
        let m = points.len();
        let polygon = optri::SimplePolygon::new(&points).expect("a convex polygon");
        assert!(polygon.is_strictly_convex());
        let (a, wall_a, cpu_a) = timed(|| triangulate(&polygon, Criterion::MaxMinArea));
        let (b, wall_b, cpu_b) = timed(|| {
            optri::MaxMinAreaDecision::new(&polygon)
                .expect("a strictly convex polygon")
                .optimum()
        });
        let (c, wall_c, cpu_c) = timed(|| triangulate(&polygon, Criterion::MinMaxArea));
        let (a, c) = (
            a.expect("range-max").triangulation,
            c.expect("minmax").triangulation,
        );
        for t in [&a, &b, &c] {
            t.validate().expect("a triangulation");
        }
        assert_eq!(
            optri_oracle::min_twice_area(&points, a.triangles()),
            optri_oracle::min_twice_area(&points, b.triangles()),
            "n = {m}: the MaxMin routes disagree"
        );
        println!(
            "n = {m:5}  CPU (wall) seconds: maxmin range-max {cpu_a:7.3} ({wall_a:7.3}), \
             maxmin sort-and-search {cpu_b:7.3} ({wall_b:7.3}), minmax {cpu_c:7.3} ({wall_c:7.3})"
        );
        let times = [cpu_a, cpu_b, cpu_c];
        if let Some((m0, t0)) = previous {
            let model = (m * m) as f64 * (m as f64).ln() / ((m0 * m0) as f64 * (m0 as f64).ln());
            println!(
                "  CPU ratio to n = {m0}: {:.2} / {:.2} / {:.2}  (n² log n predicts {model:.2}, n³ {:.2})",
                times[0] / t0[0],
                times[1] / t0[1],
                times[2] / t0[2],
                (m as f64 / m0 as f64).powi(3)
            );
        }
        previous = Some((m, times));
    }
}

fn main() {
    let mut args = std::env::args().skip(1);
    let mode = args.next().unwrap_or_else(|| "ratio".into());
    let sizes: Vec<usize> = args.map(|a| a.parse().expect("a size")).collect();
    if mode == "routes" {
        routes(&sizes);
        return;
    }
    if mode == "decide" {
        decide(&sizes);
        return;
    }
    let runs: usize = std::env::var("RUNS")
        .ok()
        .and_then(|r| r.parse().ok())
        .unwrap_or(1);
    for n in sizes {
        let points = convex_lens(&mut StdRng::seed_from_u64(SEED_CONVEX), n);
        let ps = PointSet::new(&points).unwrap();
        if mode == "search" {
            // The second MaxMin route: sort the table's values, binary-search
            // them with Algorithm 49's O(n²) decision.
            let ring: Vec<[f64; 2]> = optri::convex_hull(&ps)
                .iter()
                .map(|&i| ps.input_points()[i as usize])
                .collect();
            let polygon = optri::SimplePolygon::new(&ring).unwrap();
            let (t, secs_search) =
                secs(|| optri::MaxMinAreaDecision::new(&polygon).unwrap().optimum());
            t.validate().unwrap();
            println!("n={n} maxmin-area by sort-and-search: {secs_search:.3} s");
            println!(
                "  peak RSS so far: {} kB",
                peak_rss_kb().map_or("?".to_string(), |kb| kb.to_string())
            );
            continue;
        }
        for (criterion, maxmin) in [
            (Criterion::MaxMinArea, true),
            (Criterion::MinMaxArea, false),
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
                        secs(|| optri::internals::area_by_polygon_program(&ps, criterion).unwrap());
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
        println!(
            "  peak RSS so far: {} kB",
            peak_rss_kb().map_or("?".to_string(), |kb| kb.to_string())
        );
    }
}

/// One-shot decisions against the table route, alternating, on lenses.
fn decide(sizes: &[usize]) {
    use optri::kernel::AreaThreshold;
    use optri::{decide_area, maxmin_area_at_least, AreaQuestion, Options};
    let runs: usize = std::env::var("RUNS")
        .ok()
        .and_then(|r| r.parse().ok())
        .unwrap_or(3);
    for &n in sizes {
        let points = convex_lens(&mut StdRng::seed_from_u64(SEED_CONVEX), n);
        let ps = PointSet::new(&points).unwrap();
        let optimum = triangulate(&ps, Criterion::MaxMinArea).unwrap();
        let [a, b, c] = optimum
            .triangulation
            .stats()
            .smallest_triangle
            .map(|i| points[i as usize]);
        // Integer coordinates well below 2^26: the doubled area is an exact
        // integer below 2^53.
        let doubled = ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).abs();
        for (label, value) in [("at the optimum", doubled), ("above it", doubled + 1.0)] {
            let threshold = AreaThreshold::new(value as u128, 0);
            let (mut one_shot, mut table) = (Vec::new(), Vec::new());
            for _ in 0..runs {
                let (d, t) = secs(|| {
                    decide_area(
                        &ps,
                        AreaQuestion::SmallestAtLeast,
                        &threshold,
                        &Options::default(),
                    )
                    .unwrap()
                });
                one_shot.push(t);
                let (answer, t) = secs(|| maxmin_area_at_least(&ps, value).unwrap());
                table.push(t);
                assert_eq!(d.answer, Some(answer));
            }
            let (o, t) = (median(one_shot), median(table));
            println!(
                "n={n} {label}: one-shot {o:.4} s, table {t:.4} s, table/one-shot {:.2}",
                t / o
            );
        }
    }
}
