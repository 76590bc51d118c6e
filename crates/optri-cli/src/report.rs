//! What the commands print: the human summaries, the JSON documents (built
//! by the library, [`optri::io::TriangulationReport`] and
//! [`optri::io::GraphReport`]), and the one way to write to stdout.

use crate::commands::Run;
use crate::CliResult;
use optri::io::{Arithmetic, Document};
use optri::{Criterion, Domain, Measure, Phase, PointSet, Solution};
use std::cmp::Ordering;
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

/// The summary of `optri decide`: one line with the answer, then the files
/// written.
pub(crate) fn decision_summary(document: &serde_json::Value, written: &[PathBuf]) -> String {
    let criterion = document["criterion"].as_str().unwrap_or_default();
    let threshold = document["threshold_decimal"].as_str().unwrap_or_default();
    let (which, bound) = match document["bound"].as_str() {
        Some("at_most") => ("largest", "at most"),
        _ => ("smallest", "at least"),
    };
    let question = format!("triangulation whose {which} triangle has area {bound} {threshold}");
    let mut text = match document["answer"].as_bool() {
        Some(true) => {
            let stats = &document["witness"]["stats"];
            let measure = if which == "largest" {
                "max_area"
            } else {
                "min_area"
            };
            format!(
                "yes: there is a {question} ({criterion}; the witness's {which} area is {})\n",
                stats[measure]
            )
        }
        Some(false) => format!("no: there is no {question} ({criterion})\n"),
        None => format!(
            "unknown: {criterion}'s certified approximation neither meets nor excludes {threshold} \
             on this point set\n"
        ),
    };
    wrote(&mut text, written);
    text
}

/// The summary of `optri triangulate`.
pub(crate) fn triangulation_summary(run: &Run, written: &[PathBuf]) -> String {
    let Document::Triangulation(document) = run.outcome.document() else {
        unreachable!("a triangulate request");
    };
    let solution = run.outcome.solution().expect("a triangulate request");
    let stats = document.stats();
    let points = run.outcome.point_set().expect("a validated input");
    let polygon = run.outcome.polygon();
    let domain = match (polygon, solution.triangulation.domain()) {
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
    let boundary = if polygon.is_some() {
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
        arithmetic_line(run.read()),
        timing_text(run.phases()),
    );
    if let Some(([a, b], length)) = document.metric_longest_edge() {
        text.push_str(&format!(
            "metric {}: longest edge {a}-{b}, length {length}\n",
            solution.metric
        ));
    }
    wrote(&mut text, written);
    text
}

/// The summary of `optri graph`.
pub(crate) fn graph_summary(run: &Run, written: &[PathBuf]) -> String {
    let (kind, graph) = run.outcome.graph().expect("a graph request");
    let coordinates = run.read().input.points();
    let edges = &graph.edges;
    // From the points the graph was computed on (the scaled decimals, if
    // any), divided back exactly and rounded once.
    let total = run.read().total_length(edges);
    // Under a norm the edges were chosen by metric lengths; the total
    // reported stays Euclidean, and says so.
    let metric = &run.outcome.options().metric;
    let length = if metric.is_euclidean() {
        "total length".to_string()
    } else {
        format!(
            "total Euclidean length (edges chosen under {})",
            metric.name()
        )
    };
    let mut text = format!(
        "graph: {}\npoints: {} input, {} distinct{}\nedges: {}, {length} {}\n{}time: {}\n",
        kind.name(),
        coordinates.len(),
        graph.distinct,
        merged_note(graph.duplicates.len()),
        edges.len(),
        number(total),
        arithmetic_line(run.read()),
        timing_text(run.phases()),
    );
    wrote(&mut text, written);
    text
}

/// About six significant digits, plain for everyday magnitudes, for tables.
fn significant(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 {
        "0".to_string()
    } else if (1e-3..1e7).contains(&a) {
        let decimals = (5 - a.log10().floor() as i32).max(0) as usize;
        format!("{v:.decimals$}")
    } else {
        format!("{v:.5e}")
    }
}

/// One column of the comparison table: a quality measure (exact ranking),
/// or the time (`None`, ranked on the values shown).
#[derive(Clone, Copy)]
struct Column(Option<Measure>);

impl Column {
    /// Every quality measure, in the library's order (the slope only for
    /// points with elevations), then the time.
    fn all(elevations: bool) -> impl Iterator<Item = Column> {
        Measure::ALL
            .into_iter()
            .filter(move |&m| elevations || m != Measure::MaxSlope)
            .map(Some)
            .chain([None])
            .map(Column)
    }

    fn heading(self) -> &'static str {
        self.0.map_or("time ms", Measure::label)
    }

    fn smaller_is_better(self) -> bool {
        self.0.is_none_or(|m| m.better() == optri::Better::Smaller)
    }

    fn value(self, solution: &Solution, stats: &optri::Stats) -> f64 {
        match self.0 {
            // Only the slope has no value, and only without elevations,
            // where it has no column.
            Some(m) => m.value(stats).unwrap_or(f64::NAN),
            None => solution.phases.iter().map(|p| p.ms).sum(),
        }
    }
}

/// Which solutions are best in `measure`, decided exactly (ties: all).
fn exact_best(solved: &[&Solution], measure: Measure, smaller_is_better: bool) -> Vec<bool> {
    // `Greater`: the first is better.
    let better = |a: &Solution, b: &Solution| {
        let o = a.triangulation.compare_measure(&b.triangulation, measure);
        if smaller_is_better {
            o.reverse()
        } else {
            o
        }
    };
    let Some(first) = solved.first() else {
        return Vec::new();
    };
    let best = solved[1..].iter().fold(*first, |best, &s| {
        if better(s, best) == Ordering::Greater {
            s
        } else {
            best
        }
    });
    solved
        .iter()
        .map(|s| std::ptr::eq(*s, best) || better(s, best) == Ordering::Equal)
        .collect()
}

/// Which of the values `shown` are best (ties: all), on the text shown.
fn best_shown(shown: &[String], smaller_is_better: bool) -> Vec<bool> {
    let parsed: Vec<f64> = shown
        .iter()
        .map(|t| t.parse().unwrap_or(f64::NAN))
        .collect();
    let best = parsed
        .iter()
        .copied()
        .filter(|v| !v.is_nan())
        .reduce(if smaller_is_better {
            f64::min
        } else {
            f64::max
        });
    parsed.iter().map(|v| Some(*v) == best).collect()
}

/// The table of `optri compare`: one row per criterion that triangulated the
/// input, one column per measure with the best value of each column marked
/// `*` (decided by exact comparison of the measures, not of the rounded
/// values shown, and the time on the values shown; ties are all marked),
/// results that are not provably optimal flagged in the `guarantee` column,
/// and the criteria that refused the input listed with the library's
/// reason.
pub(crate) fn comparison_table(run: &Run) -> String {
    let results = run.outcome.comparison().expect("a compare request");
    let points = run.outcome.point_set().expect("a validated input");
    let mut text = format!(
        "{}: {} points ({} distinct{}), {}\n\n",
        run.source,
        points.input_points().len(),
        points.len(),
        duplicates_note(points),
        if run.outcome.polygon().is_some() {
            "polygon interior"
        } else {
            "convex hull"
        },
    );
    let solved: Vec<&Solution> = results
        .iter()
        .filter_map(|(_, r)| r.as_ref().ok())
        .collect();
    // Stats walk every triangle: once per solution. They and the bounds are
    // in the user's units (the run may have scaled decimal input).
    let units = optri::io::ComparisonReport::new(results).with_input(run.read());
    let stats: Vec<optri::Stats> = solved.iter().map(|s| units.report(s).stats()).collect();
    // Each cell's text; the best (by the value shown) gets a `*`.
    let mut cells: Vec<Vec<String>> = solved
        .iter()
        .map(|s| {
            let flag = if s.exact { "" } else { " (!)" };
            vec![
                s.criterion.name().to_string(),
                format!("{}{flag}", s.optimality.name()),
            ]
        })
        .collect();
    let elevations = points.elevations().is_some();
    for column in Column::all(elevations) {
        let shown: Vec<String> = solved
            .iter()
            .zip(&stats)
            .map(|(s, st)| significant(column.value(s, st)))
            .collect();
        let best = match column.0 {
            Some(measure) => exact_best(&solved, measure, column.smaller_is_better()),
            None => best_shown(&shown, column.smaller_is_better()),
        };
        for (row, (t, best)) in cells.iter_mut().zip(shown.iter().zip(best)) {
            let mark = if best && solved.len() > 1 { " *" } else { "  " };
            row.push(format!("{t}{mark}"));
        }
    }
    let headings: Vec<&str> = ["criterion", "guarantee"]
        .into_iter()
        .chain(Column::all(elevations).map(Column::heading))
        .collect();
    let widths: Vec<usize> = (0..headings.len())
        .map(|k| {
            cells
                .iter()
                .map(|r| r[k].chars().count())
                .chain([headings[k].chars().count() + if k >= 2 { 2 } else { 0 }])
                .max()
                .unwrap_or(0)
        })
        .collect();
    let line = |row: &[String]| -> String {
        let mut l = String::new();
        for (k, cell) in row.iter().enumerate() {
            let pad = widths[k] - cell.chars().count();
            if k < 2 {
                l.push_str(cell);
                l.push_str(&" ".repeat(pad + 2));
            } else {
                l.push_str(&" ".repeat(pad));
                l.push_str(cell);
                l.push(' ');
            }
        }
        l.trim_end().to_string() + "\n"
    };
    let heading_row: Vec<String> = headings
        .iter()
        .enumerate()
        .map(|(k, h)| {
            if k >= 2 {
                format!("{h}  ")
            } else {
                h.to_string()
            }
        })
        .collect();
    if !solved.is_empty() {
        text.push_str(&line(&heading_row));
        for row in &cells {
            text.push_str(&line(row));
        }
        text.push_str("\n* best in its column (smallest, or largest for min area, min angle and min height)\n");
    }
    for s in solved.iter().filter(|s| !s.exact) {
        let why = match s.optimality {
            optri::Optimality::Approximation { bound } => format!("an approximation ({bound})"),
            optri::Optimality::UpToRounding => {
                "optimal up to floating-point rounding of sums".to_string()
            }
            _ => s.optimality.name().to_string(),
        };
        let bound = s.bound.as_ref().map_or(String::new(), |b| {
            format!(
                "; the optimum is {} {} (certified)",
                if b.upper { "at most" } else { "at least" },
                significant(units.report(s).bound_value().unwrap_or(b.value))
            )
        });
        text.push_str(&format!(
            "(!) {} is not proven optimal here: {why}{bound}\n",
            s.criterion.name()
        ));
    }
    for (criterion, result) in results {
        if let Err(e) = result {
            text.push_str(&format!("refused: {}: {e}\n", criterion.name()));
        }
    }
    text.push_str(&format!("time: {}\n", timing_text(run.phases())));
    text
}
