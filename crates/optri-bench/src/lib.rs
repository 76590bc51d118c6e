//! Timing harnesses for optri: `src/bin/{minmax_timing,greedy_bench,proximity_timing,families}.rs`
//! (alternating runs against the Delaunay baseline in one process, medians,
//! peak memory) and criterion benchmarks in `benches/`. The commands and
//! figures are in BENCHMARKS.md. Nothing here is part of the library.

pub mod families;

/// The process's peak resident set size in kB (`VmHWM` in
/// `/proc/self/status`), `None` where there is no such file.
pub fn peak_rss_kb() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}
