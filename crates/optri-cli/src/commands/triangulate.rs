//! `optri triangulate`: one criterion over a point file (its convex hull) or
//! a polygon file (the polygon's interior).

use super::Reading;
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
    let mut run = Reading::start(
        &args.input,
        &args.output,
        OutputFormat::from_path,
        true,
        args.style.quiet,
    )?
    .validate()?;
    let options = Options::default()
        .with_progress(run.progress.hook())
        .with_metric(metric);
    let solution = match &run.polygon {
        Some(polygon) => {
            if !criterion.supports_polygons() {
                let supported: Vec<&str> = Criterion::ALL
                    .iter()
                    .filter(|c| c.supports_polygons())
                    .map(|c| c.name())
                    .collect();
                run.progress.finish();
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
    .map_err(|e| {
        run.progress.finish();
        e.to_string()
    })?;
    run.progress.phase("writing");
    run.timing.phases.extend(solution.phases.iter().cloned());
    if args.validate {
        let t0 = std::time::Instant::now();
        solution
            .triangulation
            .validate()
            .map_err(|e| format!("{}: the result failed validation: {e}", run.source))?;
        run.timing.phases.push(optri::Phase {
            name: "check",
            ms: super::ms_since(t0),
        });
    }
    let title = run.title(&report::label(criterion, solution.exact));
    // A JSON output holds the phases timed so far (the write and the total
    // are still running).
    let timed = run.timing.phases.clone();
    let style = args.style.json_style();
    let document = TriangulationReport::of_solution(&solution)
        .with_input(&run.read)
        .with_timing(&timed);
    let written = run.timing.write(&args.output, |path| {
        io::write_triangulation_report_styled(&document, path, &title, style)
    });
    run.progress.finish();
    let written = written?;
    run.timing.finish();
    let document = TriangulationReport::of_solution(&solution)
        .with_input(&run.read)
        .with_timing(&run.timing.phases);
    if args.json {
        return report::emit_json(&document);
    }
    let mut summary = report::triangulation_summary(&run, &document, &solution, &written);
    if let Some(([a, b], length)) = document.metric_longest_edge() {
        summary.push_str(&format!(
            "metric {}: longest edge {a}-{b}, length {length}\n",
            solution.metric
        ));
    }
    report::emit(&summary)
}
