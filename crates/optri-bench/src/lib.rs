//! Timing harnesses for optri: `src/bin/{minmax_timing,greedy_bench,proximity_timing,families}.rs`
//! (alternating runs against the Delaunay baseline in one process, medians,
//! peak memory) and criterion benchmarks in `benches/`. The commands and
//! figures are in BENCHMARKS.md. Nothing here is part of the library.

pub mod families;
