//! Times Delaunay and every criterion of the registry on the input families
//! of `optri_bench::families`, each run in a child process of its own (so a
//! run's peak resident memory, `VmHWM`, is its own and a run past its limit
//! can be stopped), and prints a table: per family and size, each
//! criterion's time, its ratio to Delaunay on the same input, and its peak
//! memory.
//!
//! ```text
//! cargo run --release -p optri-bench --bin families -- \
//!     [--sizes 1000,10000] [--limit 2] [--families uniform,grid] [--criteria delaunay,greedy]
//! ```
//! A run gets `Options::with_time_limit(limit)`; one that returns
//! `Interrupted` (or that the harness stops at `2 · limit + 5 s`, for a
//! phase that does not poll the limit) is printed as `> limit`; one that
//! returns a result past the limit is marked `†`. Polygon
//! families run the criteria that take polygons. Times are of the
//! `triangulate` call alone (input generation excluded).

use optri::{Criterion, Error, InputKind, Options, PointSet, SimplePolygon};
use optri_bench::families::{family, generate, Shape, FAMILIES};
use optri_bench::peak_rss_kb;
use std::io::Read;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const USAGE: &str = "families [--sizes N,N,...] [--limit SECONDS] [--families NAME,...] \
[--criteria NAME,...]";

/// What a child process reports for one run.
enum Outcome {
    /// Seconds, peak memory in kB, distinct input size.
    Done(f64, u64, usize),
    /// Past the time limit.
    OverLimit,
    /// The criterion does not take this input (the reason).
    Refused(String),
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("--case") {
        child(&args[1..]);
        return;
    }
    let mut sizes = vec![1_000usize, 10_000];
    let mut limit = 2.0f64;
    let mut families: Vec<&str> = FAMILIES.iter().map(|f| f.name).collect();
    let mut criteria: Vec<Criterion> = Criterion::ALL.to_vec();
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        let mut value = || {
            it.next()
                .unwrap_or_else(|| panic!("{flag} needs a value\n{USAGE}"))
        };
        match flag.as_str() {
            "--sizes" => {
                sizes = value()
                    .split(',')
                    .map(|s| s.parse().expect("a size"))
                    .collect()
            }
            "--limit" => limit = value().parse().expect("seconds"),
            "--families" => {
                families = value()
                    .split(',')
                    .map(|name| family(name).expect("a family").name)
                    .collect()
            }
            "--criteria" => {
                criteria = value()
                    .split(',')
                    .map(|name| Criterion::from_name(name).expect("a criterion"))
                    .collect();
                if !criteria.contains(&Criterion::Delaunay) {
                    criteria.insert(0, Criterion::Delaunay);
                }
            }
            "--help" | "-h" => {
                println!("{USAGE}\nfamilies:");
                for f in FAMILIES {
                    println!("  {:14} {}", f.name, f.description);
                }
                return;
            }
            _ => panic!("unknown flag {flag}\n{USAGE}"),
        }
    }
    println!(
        "time limit {limit} s per run; ratio = time / Delaunay's on the same input; \
         † = finished past the limit"
    );
    println!(
        "| family | n | {} |",
        criteria
            .iter()
            .map(|c| c.name())
            .collect::<Vec<_>>()
            .join(" | ")
    );
    println!("|---|---:|{}", "---:|".repeat(criteria.len()));
    for name in families {
        let shape = family(name).expect("a family").shape;
        for &n in &sizes {
            let mut delaunay = None;
            let mut distinct = n;
            let mut cells = Vec::new();
            for &criterion in &criteria {
                let input = match shape {
                    Shape::Points => InputKind::PointSet,
                    Shape::Polygon => InputKind::SimplePolygon,
                };
                if !criterion.accepts(input) {
                    cells.push("—".to_string());
                    continue;
                }
                cells.push(match run_child(name, n, criterion, limit) {
                    Outcome::Done(secs, kb, m) => {
                        distinct = m;
                        if criterion == Criterion::Delaunay {
                            delaunay = Some(secs);
                        }
                        let ratio = delaunay
                            .map(|d| format!(" ({:.1}×)", secs / d.max(1e-9)))
                            .unwrap_or_default();
                        // The limit is polled between phases: a long phase can overrun it.
                        let overran = if secs > limit { " †" } else { "" };
                        format!(
                            "{}{ratio}{overran}, {} MB",
                            seconds(secs),
                            kb.div_ceil(1024)
                        )
                    }
                    Outcome::OverLimit => format!("> {limit} s"),
                    Outcome::Refused(reason) => reason,
                });
            }
            println!("| {name} | {distinct} | {} |", cells.join(" | "));
        }
    }
}

fn seconds(s: f64) -> String {
    if s < 1.0 {
        format!("{:.1} ms", s * 1e3)
    } else {
        format!("{s:.2} s")
    }
}

/// Runs one case in a child process and reads its one-line report.
fn run_child(name: &str, n: usize, criterion: Criterion, limit: f64) -> Outcome {
    let mut child = Command::new(std::env::current_exe().expect("this binary"))
        .args([
            "--case",
            name,
            &n.to_string(),
            criterion.name(),
            &limit.to_string(),
        ])
        .stdout(Stdio::piped())
        .spawn()
        .expect("a child process");
    let deadline = Instant::now() + Duration::from_secs_f64(2.0 * limit + 5.0);
    loop {
        match child.try_wait().expect("the child's status") {
            Some(_) => break,
            None if Instant::now() > deadline => {
                // A phase that does not poll the limit: stop it here.
                child.kill().ok();
                child.wait().ok();
                return Outcome::OverLimit;
            }
            None => std::thread::sleep(Duration::from_millis(10)),
        }
    }
    let mut report = String::new();
    child
        .stdout
        .take()
        .expect("piped")
        .read_to_string(&mut report)
        .ok();
    let words: Vec<&str> = report.split_whitespace().collect();
    match words.as_slice() {
        ["done", secs, kb, m] => Outcome::Done(
            secs.parse().expect("seconds"),
            kb.parse().expect("kB"),
            m.parse().expect("a size"),
        ),
        ["limit"] => Outcome::OverLimit,
        _ => Outcome::Refused(
            report
                .trim()
                .trim_start_matches("refused ")
                .chars()
                .take(40)
                .collect(),
        ),
    }
}

/// The child: `--case FAMILY N CRITERION LIMIT`. Prints `done SECONDS KB
/// DISTINCT`, `limit`, or `refused REASON`.
fn child(args: &[String]) {
    let [name, n, criterion, limit] = args else {
        panic!("--case FAMILY N CRITERION LIMIT");
    };
    let family = family(name).expect("a family");
    let n: usize = n.parse().expect("a size");
    let criterion = Criterion::from_name(criterion).expect("a criterion");
    let options =
        Options::default().with_time_limit(Duration::from_secs_f64(limit.parse().expect("secs")));
    let points = generate(family, n);
    let start = Instant::now();
    let (result, distinct) = match family.shape {
        Shape::Points => {
            let set = PointSet::new(&points).expect("valid points");
            (
                optri::triangulate_with(&set, criterion, &options).map(drop),
                set.len(),
            )
        }
        Shape::Polygon => {
            let polygon = SimplePolygon::new(&points).expect("a simple polygon");
            (
                optri::triangulate_with(&polygon, criterion, &options).map(drop),
                points.len(),
            )
        }
    };
    let secs = start.elapsed().as_secs_f64();
    match result {
        Ok(()) => println!("done {secs} {} {distinct}", peak_rss_kb().unwrap_or(0)),
        Err(Error::Interrupted(_)) => println!("limit"),
        Err(Error::Unsupported { reason, .. }) => {
            // The reason's name: `TooManyPoints { .. }` prints `TooManyPoints`.
            let reason = format!("{reason:?}");
            println!(
                "refused {}",
                reason
                    .split([' ', '(', '{'])
                    .next()
                    .unwrap_or("unsupported")
            );
        }
        Err(e) => println!("refused error: {e}"),
    }
}
