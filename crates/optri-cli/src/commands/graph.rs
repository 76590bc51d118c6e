//! `optri graph`: one proximity graph of a point file, through the library's
//! registry ([`optri::graph`]).

use super::Run;
use crate::args::GraphArgs;
use crate::report;
use crate::CliResult;
use optri::io::{self, GraphReport, OutputFormat};
use optri::kernel::Metric;
use optri::Options;

pub(crate) fn run(args: GraphArgs) -> CliResult<()> {
    let metric = Metric::parse(&args.metric).map_err(|e| format!("--metric: {e}"))?;
    let options = Options::default().with_metric(metric);
    let mut run = Run::start(
        &args.input,
        &args.output,
        OutputFormat::from_path_for_graph,
        false,
    )?;
    let (edges, phases) =
        optri::graph_with(&run.points, args.kind, &options).map_err(|e| e.to_string())?;
    run.timing.phases.extend(phases);
    let title = run.title(args.kind.name());
    let timed = run.timing.phases.clone();
    let document = GraphReport::of_graph(&run.points, args.kind, &edges)
        .with_metric(&options.metric)
        .with_timing(&timed);
    let written = run.timing.write(&args.output, |path| {
        io::write_graph_report(&document, path, &title)
    })?;
    run.timing.finish();
    if args.json {
        let document = GraphReport::of_graph(&run.points, args.kind, &edges)
            .with_metric(&options.metric)
            .with_timing(&run.timing.phases);
        return report::emit_json(&document);
    }
    report::emit(&report::graph_summary(&run, args.kind, &edges, &written))
}
