//! `optri graph`: one proximity graph of a point file, through the library's
//! registry ([`optri::graph_of_points_with`]: also two points and collinear
//! points, and a metric for the RNG and MST).

use super::{input_error, Reading};
use crate::args::GraphArgs;
use crate::report;
use crate::CliResult;
use optri::io::{self, GraphReport, OutputFormat};
use optri::kernel::Metric;
use optri::Options;

pub(crate) fn run(args: GraphArgs) -> CliResult<()> {
    let metric = Metric::parse(&args.metric).map_err(|e| format!("--metric: {e}"))?;
    let options = Options::default().with_metric(metric);
    let mut run = Reading::start(
        &args.input,
        &args.output,
        OutputFormat::from_path_for_graph,
        false,
        args.style.quiet,
    )?;
    run.progress.phase(args.kind.name());
    let graph = optri::graph_of_points_with(run.read.working_points(), args.kind, &options)
        .map_err(|e| {
            run.progress.finish();
            input_error(&run.source, e)
        })?;
    run.progress.phase("writing");
    run.timing.phases.extend(graph.phases.iter().cloned());
    let title = run.title(args.kind.name());
    let timed = run.timing.phases.clone();
    let points = run.read.input.points();
    let document = |phases| {
        GraphReport::of_points(
            points,
            args.kind,
            &graph.edges,
            graph.distinct,
            &graph.duplicates,
        )
        .with_input(&run.read)
        .with_metric(&options.metric)
        .with_timing(phases)
    };
    let style = args.style.json_style();
    let written = run.timing.write(&args.output, |path| {
        io::write_graph_report_styled(&document(&timed), path, &title, style)
    });
    run.progress.finish();
    let written = written?;
    run.timing.finish();
    let phases = run.timing.phases.clone();
    if args.json {
        return report::emit_json(&document(&phases));
    }
    report::emit(&report::graph_summary(&run, args.kind, &graph, &written))
}
