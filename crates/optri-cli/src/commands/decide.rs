//! `optri decide`: the area decision problems (is there a triangulation
//! whose smallest triangle has area at least T, or whose largest has area at
//! most T?), answered yes, no or unknown with exit code 0.

use super::Reading;
use crate::args::DecideArgs;
use crate::report;
use crate::CliResult;
use optri::io::{self, OutputFormat, Threshold};
use optri::request::Task;

pub(crate) fn run(args: DecideArgs) -> CliResult<()> {
    // Check everything the user typed before any work.
    let parse = |option, text: &Option<String>| {
        text.as_deref()
            .map(|t| Threshold::parse(option, t))
            .transpose()
            .map_err(flag_error)
    };
    let at_least = parse("at_least", &args.at_least)?;
    let at_most = parse("at_most", &args.at_most)?;
    let task = Task::decide(&args.criterion, at_least, at_most).map_err(flag_error)?;
    let options = args.run.options()?;
    let reading = Reading::start(
        &args.input,
        &args.output,
        OutputFormat::from_path,
        true,
        args.style.quiet,
    )?;
    let mut run = reading.run(task, options)?;
    run.progress.phase("writing");
    let title = run.title("decision witness");
    let options = args.style.write_options(title);
    let written = run.write(&args.output, |outcome, path| {
        io::write(outcome.document(), path, &options)
    })?;
    run.finish();
    if args.json {
        return report::emit_json(&run.outcome.document());
    }
    report::emit(&report::decision_summary(&run.outcome.to_json(), &written))
}

/// The library names the request's options (`option at_least: …`); the
/// user typed flags.
fn flag_error(e: optri::Error) -> String {
    let text = e.to_string();
    for (option, flag) in [
        ("option at_least", "--at-least"),
        ("option at_most", "--at-most"),
        ("option criterion", "--criterion"),
    ] {
        if let Some(rest) = text.strip_prefix(option) {
            return format!("{flag}{rest}");
        }
    }
    text
}
