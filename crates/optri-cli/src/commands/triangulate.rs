//! `optri triangulate`: one criterion over a point file (its convex hull) or
//! a polygon file (the polygon's interior).

use super::Run;
use crate::args::TriangulateArgs;
use crate::report;
use crate::CliResult;
use optri::io::{self, OutputFormat, TriangulationReport};
use optri::kernel::Metric;
use optri::{Criterion, Options};

pub(crate) fn run(args: TriangulateArgs) -> CliResult<()> {
    // Check everything the user typed before any work.
    let criterion = Criterion::from_name(&args.criterion).map_err(|e| e.to_string())?;
    let metric = Metric::parse(&args.metric).map_err(|e| format!("--metric: {e}"))?;
    let options = Options::default().with_metric(metric);
    let mut run = Run::start(&args.input, &args.output, OutputFormat::from_path, true)?;
    let solution = match &run.polygon {
        Some(polygon) => {
            if !criterion.supports_polygons() {
                let supported: Vec<&str> = Criterion::ALL
                    .iter()
                    .filter(|c| c.supports_polygons())
                    .map(|c| c.name())
                    .collect();
                return Err(format!(
                    "{}: the input is a polygon, and criterion {} does not triangulate \
                     polygons; criteria that do: {}",
                    run.source,
                    criterion.name(),
                    supported.join(", ")
                ));
            }
            optri::triangulate_polygon_with(polygon, criterion, &options)
        }
        None => optri::triangulate_with(&run.points, criterion, &options),
    }
    .map_err(|e| e.to_string())?;
    run.timing.phases.extend(solution.phases.iter().cloned());
    let title = run.title(&report::label(criterion, solution.exact));
    // A JSON output holds the phases timed so far (the write and the total
    // are still running).
    let timed = run.timing.phases.clone();
    let document = TriangulationReport::of_solution(&solution).with_timing(&timed);
    let written = run.timing.write(&args.output, |path| {
        io::write_triangulation_report(&document, path, &title)
    })?;
    run.timing.finish();
    if args.json {
        let document = TriangulationReport::of_solution(&solution).with_timing(&run.timing.phases);
        return report::emit_json(&document);
    }
    let mut summary = report::triangulation_summary(&run, &solution, &written);
    if !solution.metric.is_euclidean() {
        let ([a, b], length) = solution.longest_edge_under_metric();
        summary.push_str(&format!(
            "metric {}: longest edge {a}-{b}, length {length}\n",
            solution.metric
        ));
    }
    report::emit(&summary)
}
