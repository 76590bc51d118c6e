//! `optri triangulate`: one criterion over a point file (its convex hull) or
//! a polygon file (the polygon's interior).

use super::Reading;
use crate::args::TriangulateArgs;
use crate::report;
use crate::CliResult;
use optri::io::{self, OutputFormat};
use optri::request::Task;

pub(crate) fn run(args: TriangulateArgs) -> CliResult<()> {
    // Check everything the user typed before any work.
    let task = Task::triangulate(&args.criterion).map_err(|e| e.to_string())?;
    let options = args.run.options()?;
    let reading = Reading::start(
        &args.input,
        &args.output,
        OutputFormat::from_path,
        true,
        args.style.quiet,
    )?;
    let options = options.with_progress(reading.progress.hook());
    let mut run = reading.run(task, options)?;
    run.progress.phase("writing");
    if args.validate {
        let t0 = std::time::Instant::now();
        let solution = run.outcome.solution().expect("a triangulate request");
        let checked = solution.triangulation.validate();
        if let Err(e) = checked {
            run.progress.finish();
            return Err(format!("{}: the result failed validation: {e}", run.source));
        }
        run.outcome.add_phase(optri::Phase {
            name: "check",
            ms: super::ms_since(t0),
        });
    }
    let solution = run.outcome.solution().expect("a triangulate request");
    let title = run.title(&report::label(solution.criterion, solution.exact));
    // A JSON output holds the phases timed so far (the write and the total
    // are still running).
    let options = args.style.write_options(title);
    let written = run.write(&args.output, |outcome, path| {
        io::write(outcome.document(), path, &options)
    })?;
    run.finish();
    if args.json {
        return report::emit_json(&run.outcome.document());
    }
    report::emit(&report::triangulation_summary(&run, &written))
}
