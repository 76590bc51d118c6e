//! The fuzz targets' properties (`fuzz/src/checks.rs`, shared source) on the
//! committed fuzz corpus and on every crash the fuzzers found
//! (`fuzz/regressions/<target>/`), so the normal suite on stable replays
//! them: readers never panic and every `Ok` validates; every criterion's
//! result validates and, for at most 7 points, is optimal against the
//! exhaustive oracle.

#[allow(dead_code)]
#[path = "../../../fuzz/src/checks.rs"]
mod checks;

use std::path::{Path, PathBuf};

fn inputs(target: &str) -> Vec<(PathBuf, Vec<u8>)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fuzz");
    let mut out = Vec::new();
    for dir in ["corpus", "regressions"] {
        let Ok(entries) = std::fs::read_dir(root.join(dir).join(target)) else {
            continue;
        };
        for e in entries.flatten() {
            let path = e.path();
            if path.is_file() {
                out.push((path.clone(), std::fs::read(&path).unwrap()));
            }
        }
    }
    out.sort();
    out
}

fn replay(target: &str, check: fn(&[u8])) -> usize {
    let inputs = inputs(target);
    for (path, data) in &inputs {
        if std::panic::catch_unwind(|| check(data)).is_err() {
            panic!("{target}: {} fails", path.display());
        }
    }
    inputs.len()
}

#[test]
fn reader_corpus_and_regressions() {
    let n = replay("readers", checks::check_readers);
    assert!(n >= 10, "the committed reader corpus has {n} inputs");
}

#[test]
fn criteria_corpus_and_regressions() {
    let n = replay("criteria", checks::check_criteria);
    assert!(n >= 10, "the committed criteria corpus has {n} inputs");
}

/// Every registered criterion has an optimality check against the oracle
/// (adding a criterion without one fails here), and each check runs on the
/// degenerate sets where ties decide: a grid, cocircular points, a
/// collinear run with an apex, duplicates, huge and negative coordinates.
#[test]
fn every_registered_criterion_has_an_oracle_check() {
    use optri::Criterion;
    use optri_oracle::inputs;
    for &c in Criterion::ALL {
        checks::optimality_check(c);
    }
    let scaled = |points: Vec<[f64; 2]>, s: f64| -> Vec<[f64; 2]> {
        points.iter().map(|p| [p[0] * s - 3.0, p[1] * s]).collect()
    };
    let mut grid = inputs::grid(3, 2, 1.0);
    grid.push([1.0, 0.0]); // a duplicate
    let sets = [
        inputs::square_with_centre(2.0),
        grid,
        inputs::circle_r5_ccw().into_iter().take(7).collect(),
        inputs::run_with_apex(5),
        scaled(inputs::square_with_centre(2.0), 2f64.powi(150)),
        scaled(
            inputs::circle_r5_ccw().into_iter().step_by(2).collect(),
            -0.5,
        ),
    ];
    let mut checked = Vec::new();
    for set in &sets {
        checked.extend(checks::check_points(set));
    }
    for &c in Criterion::ALL {
        let times = checked.iter().filter(|&&d| d == c).count();
        assert!(times >= sets.len() - 1, "{c:?} checked on {times} sets");
    }
}
