//! Where the test data lives.
//!
//! The TSPLIB95 point sets (G. Reinelt, "TSPLIB - A Traveling Salesman
//! Problem Library", ORSA Journal on Computing 3(4), 1991) are vendored in
//! this crate's `data/tsplib/`, so a fresh clone runs the whole test suite;
//! `$OPTRI_DATA` or a `shared/data` folder beside the repository take
//! precedence, so a larger local collection can replace them.

use std::path::{Path, PathBuf};

/// The folder of the test data, the one holding `tsplib/`, in this order:
/// `$OPTRI_DATA` when it is set; else `shared/data` beside the repository
/// (`<repo>/../shared/data`) when it holds `tsplib/`; else the copy vendored
/// in this crate (`crates/optri-oracle/data`).
///
/// # Panics
/// When `$OPTRI_DATA` is set to a folder without `tsplib/` (a mistyped path
/// is an error, not a silent fall-back), or when the vendored copy is
/// missing.
#[track_caller]
pub fn data_dir() -> PathBuf {
    let (dir, origin) = match std::env::var_os("OPTRI_DATA") {
        Some(dir) => (PathBuf::from(dir), "$OPTRI_DATA"),
        None => {
            let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
            let repo = crate_dir.join("../..");
            let repo = repo.canonicalize().unwrap_or(repo);
            let beside = repo.join("../shared/data");
            if beside.join("tsplib").is_dir() {
                (beside, "the folder beside the repository")
            } else {
                (crate_dir.join("data"), "the copy vendored in optri-oracle")
            }
        }
    };
    assert!(
        dir.join("tsplib").is_dir(),
        "test data not found: {} ({origin}) has no tsplib/ folder; unset OPTRI_DATA to use the \
         vendored copy, or set it to the folder that contains tsplib/",
        dir.display()
    );
    dir
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The vendored copy holds every file the default tests read.
    #[test]
    fn vendored_copy_holds_the_fourteen_tsplib_files() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("data/tsplib");
        let mut names: Vec<String> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .filter(|n| n.ends_with(".tsp"))
            .collect();
        names.sort();
        assert_eq!(
            names,
            [
                "a280.tsp",
                "ali535.tsp",
                "att532.tsp",
                "berlin52.tsp",
                "ch150.tsp",
                "fl1577.tsp",
                "fnl4461.tsp",
                "kroA100.tsp",
                "lin318.tsp",
                "pcb3038.tsp",
                "pr1002.tsp",
                "ts225.tsp",
                "u1060.tsp",
                "vm1084.tsp",
            ]
        );
    }
}
