//! Whole runs of the `optri` command line (read, solve, write the JSON
//! document) on the same files, a baseline criterion against others,
//! alternated so that a slow spell of the machine hits both: the protocol
//! of the speed targets in BENCHMARKS.md.
//!
//! ```text
//! cargo build --release -p optri-cli -p optri-bench
//! target/release/cli_ratio [--repeat K] [--baseline C] [--criteria A,B] [--optri PATH] FILE...
//! ```
//! Defaults: 5 repetitions, baseline `delaunay`, criteria `greedy`, and the
//! `optri` binary beside this one. Each repetition runs
//! `optri triangulate FILE --criterion C --quiet -o OUT.json` for the
//! baseline and for each criterion (the baseline first in odd repetitions,
//! last in even ones); it prints every run, each
//! repetition's ratios, and per criterion the median ratio and the ratio of
//! the fastest runs (machines here are noisy: a run is only ever slowed down
//! by its neighbours). Peak memory: run the same command under
//! `/usr/bin/time -f "%e s %M kB"`.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

struct Args {
    repeat: usize,
    baseline: String,
    criteria: Vec<String>,
    optri: PathBuf,
    files: Vec<String>,
}

fn usage(problem: &str) -> ! {
    eprintln!(
        "error: {problem}\nusage: cli_ratio [--repeat K] [--baseline C] [--criteria A,B] [--optri PATH] FILE..."
    );
    std::process::exit(2);
}

fn parse_args() -> Args {
    let beside = std::env::current_exe()
        .ok()
        .and_then(|exe| {
            exe.parent()
                .map(|dir| dir.join(format!("optri{}", std::env::consts::EXE_SUFFIX)))
        })
        .unwrap_or_else(|| PathBuf::from("optri"));
    let mut args = Args {
        repeat: 5,
        baseline: "delaunay".into(),
        criteria: vec!["greedy".into()],
        optri: beside,
        files: Vec::new(),
    };
    let mut it = std::env::args().skip(1);
    while let Some(arg) = it.next() {
        let mut value = |flag: &str| {
            it.next()
                .unwrap_or_else(|| usage(&format!("{flag} needs a value")))
        };
        match arg.as_str() {
            "--repeat" => {
                args.repeat = value("--repeat")
                    .parse()
                    .ok()
                    .filter(|&k| k > 0)
                    .unwrap_or_else(|| usage("--repeat K needs an integer K >= 1"));
            }
            "--baseline" => args.baseline = value("--baseline"),
            "--criteria" => {
                args.criteria = value("--criteria")
                    .split(',')
                    .filter(|c| !c.is_empty())
                    .map(str::to_owned)
                    .collect();
            }
            "--optri" => args.optri = PathBuf::from(value("--optri")),
            flag if flag.starts_with("--") => usage(&format!("unknown flag {flag}")),
            "-" => usage("standard input cannot be read twice: give a file"),
            _ => args.files.push(arg),
        }
    }
    if args.files.is_empty() {
        usage("no input file");
    }
    if args.criteria.is_empty() {
        usage("--criteria needs at least one criterion");
    }
    args
}

/// One whole run's wall time in seconds; exits with the command's error if
/// it fails.
fn whole_run(optri: &Path, file: &str, criterion: &str, out: &Path) -> f64 {
    let start = Instant::now();
    let output = Command::new(optri)
        .args([
            "triangulate",
            file,
            "--criterion",
            criterion,
            "--quiet",
            "-o",
        ])
        .arg(out)
        .output()
        .unwrap_or_else(|e| {
            eprintln!("error: cannot run {}: {e}", optri.display());
            std::process::exit(1);
        });
    let seconds = start.elapsed().as_secs_f64();
    let _ = std::fs::remove_file(out);
    if !output.status.success() {
        eprintln!(
            "error: optri triangulate {file} --criterion {criterion} failed ({}):\n{}",
            output.status,
            String::from_utf8_lossy(&output.stderr)
        );
        std::process::exit(1);
    }
    seconds
}

fn median(values: &[f64]) -> f64 {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let k = sorted.len();
    if k % 2 == 1 {
        sorted[k / 2]
    } else {
        0.5 * (sorted[k / 2 - 1] + sorted[k / 2])
    }
}

fn main() {
    let args = parse_args();
    let out = std::env::temp_dir().join(format!("optri-cli-ratio-{}.json", std::process::id()));
    for file in &args.files {
        println!("{file}: {} alternated repetitions", args.repeat);
        let mut baseline = Vec::new();
        let mut times = vec![Vec::new(); args.criteria.len()];
        for rep in 1..=args.repeat {
            // The baseline first in odd repetitions and last in even ones,
            // so that neither side always runs after the other.
            let baseline_first = rep % 2 == 1;
            let run_baseline = || whole_run(&args.optri, file, &args.baseline, &out);
            let first = baseline_first.then(run_baseline);
            let these: Vec<f64> = args
                .criteria
                .iter()
                .map(|criterion| whole_run(&args.optri, file, criterion, &out))
                .collect();
            let base = first.unwrap_or_else(run_baseline);
            baseline.push(base);
            let mut line = format!("  rep {rep}: {} {base:.2} s", args.baseline);
            for ((criterion, list), t) in args.criteria.iter().zip(&mut times).zip(these) {
                list.push(t);
                line += &format!(", {criterion} {t:.2} s ({:.2})", t / base);
            }
            println!("{line}");
        }
        let fastest = |list: &[f64]| list.iter().copied().fold(f64::INFINITY, f64::min);
        for (criterion, list) in args.criteria.iter().zip(&times) {
            let ratios: Vec<f64> = list.iter().zip(&baseline).map(|(t, b)| t / b).collect();
            let (lo, hi) = ratios.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &r| {
                (lo.min(r), hi.max(r))
            });
            println!(
                "  {criterion} / {}: median {:.2}, range {lo:.2}-{hi:.2}, fastest runs {:.2} ({:.2} s / {:.2} s)",
                args.baseline,
                median(&ratios),
                fastest(list) / fastest(&baseline),
                fastest(list),
                fastest(&baseline),
            );
        }
    }
    let _ = std::fs::remove_file(&out);
}
