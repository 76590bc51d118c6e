//! What the commands print: the human summaries, the JSON documents (built
//! by the library, [`optri::io::TriangulationReport`] and
//! [`optri::io::GraphReport`]), and the one way to write to stdout.

use crate::commands::{Reading, Run};
use crate::CliResult;
use optri::io::{Arithmetic, TriangulationReport};
use optri::{Criterion, Domain, GraphKind, Phase, PointGraph, PointSet, Solution};
use std::io::Write;
use std::path::PathBuf;

/// How a result is labelled: `exact` when every decision was exact, else
/// `uncertified` (e.g. min-weight, optimal up to rounded sums of lengths).
pub(crate) fn exactness(exact: bool) -> &'static str {
    if exact {
        "exact"
    } else {
        "uncertified"
    }
}

/// `criterion (exact)` or `criterion (uncertified)`, for titles and tables.
pub(crate) fn label(criterion: Criterion, exact: bool) -> String {
    format!("{} ({})", criterion.name(), exactness(exact))
}

/// The message for a failed write to `stream`.
pub(crate) fn output_error(stream: &str, e: &std::io::Error) -> String {
    if e.kind() == std::io::ErrorKind::BrokenPipe {
        format!("cannot write to {stream}: the reading end of the pipe was closed")
    } else {
        format!("cannot write to {stream}: {e}")
    }
}

/// Writes `text` to stdout. Any failure, a closed pipe included, is an error:
/// output that did not arrive must not look like success to a script.
pub(crate) fn emit(text: &str) -> CliResult<()> {
    let mut out = std::io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(|e| output_error("stdout", &e))
}

/// Writes one JSON document as one line to stdout.
pub(crate) fn emit_json(document: &impl serde::Serialize) -> CliResult<()> {
    let mut line = serde_json::to_string(document)
        .map_err(|e| format!("cannot write the JSON document: {e}"))?;
    line.push('\n');
    emit(&line)
}

/// A rounded measure for the summary: plain notation for everyday
/// magnitudes, scientific otherwise (so 1e60 and 1e-30 stay readable).
fn number(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 || (1e-4..1e9).contains(&a) {
        format!("{v}")
    } else {
        format!("{v:.6e}")
    }
}

/// `; merged N duplicate point(s)`, or nothing.
pub(crate) fn duplicates_note(points: &PointSet) -> String {
    merged_note(points.duplicates().len())
}

fn merged_note(duplicates: usize) -> String {
    match duplicates {
        0 => String::new(),
        1 => "; merged 1 duplicate point".to_string(),
        n => format!("; merged {n} duplicate points"),
    }
}

fn timing_text(phases: &[Phase]) -> String {
    phases
        .iter()
        .map(|p| format!("{} {:.3} ms", p.name, p.ms))
        .collect::<Vec<_>>()
        .join(", ")
}

fn wrote(text: &mut String, written: &[PathBuf]) {
    for path in written {
        text.push_str(&format!("wrote {}\n", path.display()));
    }
}

/// The `arithmetic:` line: how the coordinates were computed with.
fn arithmetic_line(read: &optri::io::ReadInput) -> String {
    match (read.arithmetic, &read.scaled) {
        (Arithmetic::DecimalExact, Some(s)) => format!(
            "arithmetic: decimal-exact (the decimals as written, times 10^{})\n",
            s.exponent
        ),
        (Arithmetic::DecimalExact, None) => {
            "arithmetic: decimal-exact (the decimals as written)\n".to_string()
        }
        (Arithmetic::Binary64, _) => {
            "arithmetic: binary64 (the nearest doubles of the \
                                      decimals written; they do not scale to integers below 2^53)\n"
                .to_string()
        }
    }
}

/// The summary of `optri triangulate`.
pub(crate) fn triangulation_summary(
    run: &Run,
    document: &TriangulationReport,
    solution: &Solution,
    written: &[PathBuf],
) -> String {
    let stats = document.stats();
    let points = &run.points;
    let domain = match (&run.polygon, solution.triangulation.domain()) {
        (Some(p), Domain::Polygon { .. }) => format!(
            "polygon interior ({} vertices, given {})",
            p.len(),
            if p.is_clockwise_input() {
                "clockwise"
            } else {
                "counter-clockwise"
            }
        ),
        _ => "convex hull".to_string(),
    };
    let boundary = if run.polygon.is_some() {
        "boundary points"
    } else {
        "hull points"
    };
    let mut text = format!(
        "criterion: {} ({}) via {}\n\
         domain: {domain}\n\
         points: {} input, {} distinct{}\n\
         triangles: {}, edges: {}, {boundary}: {}\n\
         edge length: max {}, total {}\n\
         angles: min {}°, max {}°\n\
         areas: min {}, max {}\n\
         {}\
         time: {}\n",
        solution.criterion.name(),
        exactness(solution.exact),
        solution.algorithm,
        points.input_points().len(),
        points.len(),
        duplicates_note(points),
        stats.triangles,
        stats.edges,
        stats.hull_points,
        number(stats.max_edge_length),
        number(stats.total_edge_length),
        number(stats.min_angle_deg),
        number(stats.max_angle_deg),
        number(stats.min_area),
        number(stats.max_area),
        arithmetic_line(&run.read),
        timing_text(&run.timing.phases),
    );
    wrote(&mut text, written);
    text
}

/// The summary of `optri graph`.
pub(crate) fn graph_summary(
    run: &Reading,
    kind: GraphKind,
    graph: &PointGraph,
    written: &[PathBuf],
) -> String {
    let coordinates = run.read.input.points();
    let edges = &graph.edges;
    let total: f64 = edges
        .iter()
        .map(|&[a, b]| {
            optri::kernel::metrics::length(coordinates[a as usize], coordinates[b as usize])
        })
        .sum();
    let mut text = format!(
        "graph: {}\npoints: {} input, {} distinct{}\nedges: {}, total length {}\n{}time: {}\n",
        kind.name(),
        coordinates.len(),
        graph.distinct,
        merged_note(graph.duplicates.len()),
        edges.len(),
        number(total),
        arithmetic_line(&run.read),
        timing_text(&run.timing.phases),
    );
    wrote(&mut text, written);
    text
}
