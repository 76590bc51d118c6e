//! Fuzz targets for optri (`cargo fuzz run readers`, `cargo fuzz run
//! criteria`); the checks live in `checks.rs`, shared with the test suite.
mod checks;
pub use checks::*;
