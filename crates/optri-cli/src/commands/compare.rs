//! `optri compare`: every criterion (or the chosen ones) on one input, as a
//! table of quality measures, the comparison JSON document, or panels side by
//! side in one SVG. The work is the library's request ([`optri::compare`]);
//! this module only prints.

use super::Reading;
use crate::args::CompareArgs;
use crate::report;
use crate::CliResult;
use optri::io::{self, JsonStyle, OutputFormat, WriteOptions};
use optri::request::Task;
use std::path::Path;

/// The outputs `compare` writes: the panels (`.svg`) or the comparison
/// document (`.json`).
fn output_format(path: &Path) -> optri::Result<OutputFormat> {
    match OutputFormat::from_path(path)? {
        f @ (OutputFormat::Svg | OutputFormat::Json) => Ok(f),
        _ => Err(optri::Error::Io(format!(
            "cannot write '{}': optri compare writes .svg (the panels side by side) or .json \
             (the comparison document)",
            path.display()
        ))),
    }
}

pub(crate) fn run(args: CompareArgs) -> CliResult<()> {
    // Check everything the user typed before any work.
    let task = Task::compare(&args.criteria).map_err(|e| e.to_string())?;
    let options = args.run.options()?;
    let reading = Reading::start(&args.input, &args.output, output_format, true, false)?;
    reading.progress.phase("comparing");
    let mut run = reading.run(task, options)?;
    run.progress.phase("writing");
    // The panels are titled `input — criterion (exact)`; the document file
    // is indented (compare has no `--pretty`).
    let options = WriteOptions::default()
        .with_title(super::display_name(&run.source))
        .with_style(JsonStyle::Pretty);
    let written = run.write(&args.output, |outcome, path| {
        io::write(outcome.document(), path, &options)
    })?;
    run.finish();
    if args.json {
        return report::emit_json(&run.outcome.document());
    }
    let mut text = report::comparison_table(&run);
    for path in written {
        text.push_str(&format!("wrote {}\n", path.display()));
    }
    report::emit(&text)
}
