//! Where the shared test data lives.

use std::path::{Path, PathBuf};

/// The folder of the shared test data, the one holding `tsplib/`:
/// `$OPTRI_DATA` when it is set, else `shared/data` beside the repository
/// (`<repo>/../shared/data`).
///
/// # Panics
/// When that folder has no `tsplib/`, with a message naming the folder and
/// saying how to set `OPTRI_DATA`.
#[track_caller]
pub fn data_dir() -> PathBuf {
    let (dir, origin) = match std::env::var_os("OPTRI_DATA") {
        Some(dir) => (PathBuf::from(dir), "$OPTRI_DATA"),
        None => {
            let repo = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
            let repo = repo.canonicalize().unwrap_or(repo);
            (
                repo.join("../shared/data"),
                "the default beside the repository",
            )
        }
    };
    assert!(
        dir.join("tsplib").is_dir(),
        "test data not found: {} ({origin}) has no tsplib/ folder; set OPTRI_DATA to the \
         folder that contains tsplib/, e.g. OPTRI_DATA=/path/to/shared/data cargo test",
        dir.display()
    );
    dir
}
