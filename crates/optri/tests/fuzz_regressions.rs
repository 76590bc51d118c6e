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
