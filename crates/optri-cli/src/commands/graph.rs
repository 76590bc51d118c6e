//! `optri graph`: one proximity graph of a point file, through the library's
//! request ([`optri::graph_of_points_with`]: also two points and collinear
//! points, and a metric for the RNG and MST).

use super::Reading;
use crate::args::GraphArgs;
use crate::report;
use crate::CliResult;
use optri::io::{self, OutputFormat};
use optri::request::Task;

pub(crate) fn run(args: GraphArgs) -> CliResult<()> {
    let options = args.run.options()?;
    let reading = Reading::start(
        &args.input,
        &args.output,
        OutputFormat::from_path_for_graph,
        false,
        args.style.quiet,
    )?;
    reading.progress.phase(args.kind.name());
    let mut run = reading.run(Task::Graph(args.kind), options)?;
    run.progress.phase("writing");
    let title = run.title(args.kind.name());
    let options = args.style.write_options(title);
    let written = run.write(&args.output, |outcome, path| {
        io::write(outcome.document(), path, &options)
    })?;
    run.finish();
    if args.json {
        return report::emit_json(&run.outcome.document());
    }
    report::emit(&report::graph_summary(&run, &written))
}
