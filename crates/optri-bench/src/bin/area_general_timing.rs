//! The area criteria's approximation on point sets not in convex position
//! (Vassilev 2005, §3.4: Delaunay, Algorithms 75 and 76, the `RNG ∪ hull`
//! optimum): its quality against the exhaustive optimum, and the time of
//! each of its steps.
//!
//! ```text
//! cargo run --release -p optri-bench --bin area_general_timing -- ratios
//! cargo run --release -p optri-bench --bin area_general_timing -- steps
//! cargo run --release -p optri-bench --bin area_general_timing -- grid 300
//! ```
//! `ratios`: the approximation ratios optimum/result (MaxMin) and
//! result/optimum (MinMax), mean and worst, per candidate and for the
//! returned result, against the exhaustive optimum (n = 5..9), with the
//! improvement over Delaunay and how often each candidate wins.
//! `steps`: the running time of each step at n = 1000 and 10⁴ uniform
//! points, and of the candidates on 500 and 501 points on a circle (one
//! face, just under and over the face programs' cap).
//! `grid`: each step and both criteria on a `side × side` integer grid, as
//! multiples of Delaunay.

use optri::internals::{area_general, area_general_steps};
use optri::{Criterion, PointSet};
use optri_oracle::{inputs, BigRational};
use rand::{rngs::StdRng, SeedableRng};
use std::time::{Duration, Instant};

const SEED_RATIOS: u64 = 0xA4EA_0076;
const SEED_STEPS: u64 = 0xA4EA_1000;
const SETS_PER_SIZE: usize = 300;

const CRITERIA: [Criterion; 2] = [Criterion::MaxMinArea, Criterion::MinMaxArea];

/// The exact doubled bottleneck area of `triangles` under `criterion`.
fn value(pts: &[[f64; 2]], triangles: &[[u32; 3]], criterion: Criterion) -> BigRational {
    if criterion == Criterion::MaxMinArea {
        optri_oracle::min_twice_area(pts, triangles)
    } else {
        optri_oracle::max_twice_area(pts, triangles)
    }
}

/// Is `s` at least as good as `t` under `criterion`?
fn at_least_as_good(criterion: Criterion, s: &BigRational, t: &BigRational) -> bool {
    if criterion == Criterion::MaxMinArea {
        s >= t
    } else {
        s <= t
    }
}

fn ratios() {
    let mut rng = StdRng::seed_from_u64(SEED_RATIOS);
    let f = |r: &BigRational| optri_oracle::rational_to_f64(r);
    for family in ["real", "uniform"] {
        for criterion in CRITERIA {
            // Per candidate (+ the result): sum and worst of the ratio to
            // the optimum, sum and best of the improvement over DT.
            let mut ratio = [(0.0f64, 1.0f64); 5];
            let mut over_dt = [(0.0f64, 1.0f64); 5];
            let (mut strict_wins, mut attains_best, mut optimal) = ([0; 4], [0; 4], [0; 5]);
            let (mut cases, mut exact, mut result_optimal) = (0, 0, 0);
            for n in 5..=9 {
                for _ in 0..SETS_PER_SIZE {
                    let input = if family == "real" {
                        inputs::uniform_in_box(&mut rng, n, [0.0, 0.0], [1.0, 1.0])
                    } else {
                        inputs::lattice_points(&mut rng, n, 0..100, 0..100)
                    };
                    let Ok(ps) = PointSet::new(&input) else {
                        continue;
                    };
                    let pts = ps.points();
                    let optimum = optri_oracle::all_triangulations(pts)
                        .iter()
                        .map(|t| value(pts, t, criterion))
                        .reduce(|a, b| {
                            if at_least_as_good(criterion, &a, &b) {
                                a
                            } else {
                                b
                            }
                        })
                        .expect("a triangulation");
                    let run = area_general(&ps, criterion).expect("the approximation runs");
                    let mut values: Vec<BigRational> = run
                        .candidates
                        .iter()
                        .map(|(_, t)| value(pts, t, criterion))
                        .collect();
                    values.push(value(pts, &run.triangles, criterion));
                    let best = &values[4];
                    for k in 0..4 {
                        if &values[k] == best {
                            attains_best[k] += 1;
                            if (0..4).all(|o| o == k || &values[o] != best) {
                                strict_wins[k] += 1;
                            }
                        }
                    }
                    for (k, v) in values.iter().enumerate() {
                        let (q, d) = if criterion == Criterion::MaxMinArea {
                            (f(&(optimum.clone() / v)), f(&(v / &values[0])))
                        } else {
                            (f(&(v / &optimum)), f(&(values[0].clone() / v)))
                        };
                        ratio[k] = (ratio[k].0 + q, ratio[k].1.max(q));
                        over_dt[k] = (over_dt[k].0 + d, over_dt[k].1.max(d));
                        optimal[k] += (v == &optimum) as usize;
                    }
                    exact += run.exact as usize;
                    result_optimal += (values[4] == optimum) as usize;
                    cases += 1;
                }
            }
            let what = if criterion == Criterion::MaxMinArea {
                "MaxMin area: optimum / candidate"
            } else {
                "MinMax area: candidate / optimum"
            };
            println!("\n{what} — {family} points, n = 5..9, {cases} sets (seed {SEED_RATIOS:#x})");
            println!(
                "{:<56} {:>8} {:>8} {:>8} {:>9} {:>9} {:>7} {:>7}",
                "candidate",
                "mean",
                "worst",
                "optimal",
                "vs DT avg",
                "vs DT max",
                "attains",
                "strict"
            );
            let names = [
                "Delaunay",
                "Algorithm 75",
                "RNG ∪ hull optimum",
                "Algorithm 76",
                "returned result (best of the four)",
            ];
            for k in 0..5 {
                let (wins, strict) = if k < 4 {
                    (attains_best[k].to_string(), strict_wins[k].to_string())
                } else {
                    (String::new(), String::new())
                };
                println!(
                    "{:<56} {:>8.4} {:>8.4} {:>8} {:>9.4} {:>9.4} {:>7} {:>7}",
                    names[k],
                    ratio[k].0 / cases as f64,
                    ratio[k].1,
                    optimal[k],
                    over_dt[k].0 / cases as f64,
                    over_dt[k].1,
                    wins,
                    strict
                );
            }
            println!(
                "certified exact: {exact} of {cases}; actually optimal: {result_optimal} of {cases}"
            );
        }
    }
}

fn steps() {
    let mut rng = StdRng::seed_from_u64(SEED_STEPS);
    for n in [1000, 10_000] {
        let input = inputs::uniform_in_box(&mut rng, n, [0.0, 0.0], [1.0, 1.0]);
        let ps = PointSet::new(&input).expect("a valid point set");
        let steps = area_general_steps(&ps).expect("the steps run");
        let t = |name: &str| {
            let ms = steps
                .phases
                .iter()
                .find(|p| p.name == name)
                .map_or(f64::NAN, |p| p.ms);
            Duration::from_secs_f64(ms / 1e3)
        };
        println!(
            "n = {n}: Delaunay {:.2?}; RNG ∪ hull faces {:.2?} ({} faces, largest {} corners, Σk³ = {}); \
             face programs MaxMin {:.2?}, MinMax {:.2?}; Algorithm 76 {:.2?} ({} flips); \
             bound MaxMin {:.2?}, MinMax {:.2?} (h = {})",
            t("Delaunay"),
            t("RNG ∪ hull faces"),
            steps.faces,
            steps.largest_face,
            steps.cubed_corners,
            t("face programs MaxMin"),
            t("face programs MinMax"),
            t("Algorithm 76"),
            steps.flips,
            t("bound MaxMin"),
            t("bound MinMax"),
            steps.hull_points
        );
        for criterion in CRITERIA {
            let clock = Instant::now();
            let run = area_general(&ps, criterion).expect("the approximation runs");
            let objective = if criterion == Criterion::MaxMinArea {
                "MaxMin"
            } else {
                "MinMax"
            };
            println!(
                "  area_general {objective}: {:.2?}, winner: {}, exact: {}",
                clock.elapsed(),
                run.algorithm,
                run.exact
            );
        }
    }
    for n in [500, 501] {
        let ps = PointSet::new(&inputs::sampled_circle(n, 1e6)).expect("a valid point set");
        let clock = Instant::now();
        let run = area_general(&ps, Criterion::MaxMinArea).expect("the approximation runs");
        println!(
            "{n} points on a circle: candidates {:.2?} (largest face {} corners, {} candidates, {} flips)",
            clock.elapsed(),
            run.largest_face,
            run.candidates.len(),
            run.flips
        );
    }
}

/// Every step on a `side × side` integer grid (massively degenerate: equal
/// areas, collinear triples, cocircular quadruples), against Delaunay.
fn grid(side: usize) {
    let ps = PointSet::new(&inputs::grid(side, side, 1.0)).expect("a valid point set");
    let clock = Instant::now();
    optri::triangulate(&ps, Criterion::Delaunay).expect("Delaunay runs");
    let delaunay = clock.elapsed();
    let steps = area_general_steps(&ps).expect("the steps run");
    println!("{side}x{side} grid: Delaunay {delaunay:.2?}");
    for p in &steps.phases {
        println!("  {:<24} {:>10.1} ms", p.name, p.ms);
    }
    for criterion in CRITERIA {
        let clock = Instant::now();
        optri::triangulate(&ps, criterion).expect("the criterion runs");
        let t = clock.elapsed();
        println!(
            "  {:<24} {t:>10.2?} ({:.1}x Delaunay)",
            criterion.name(),
            t.as_secs_f64() / delaunay.as_secs_f64()
        );
    }
}

fn main() {
    match std::env::args().nth(1).as_deref() {
        Some("ratios") => ratios(),
        Some("grid") => grid(
            std::env::args()
                .nth(2)
                .map_or(300, |s| s.parse().expect("a side")),
        ),
        Some("steps") | None => steps(),
        Some(other) => panic!("unknown mode {other:?}: ratios or steps"),
    }
}
