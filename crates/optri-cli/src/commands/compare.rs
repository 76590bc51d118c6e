//! `optri compare`: every criterion (or the chosen ones) on one input, as a
//! table of quality measures, the comparison JSON document, or panels side by
//! side in one SVG. The work is the library's request ([`optri::compare`]);
//! this module only prints.

use super::Reading;
use crate::args::CompareArgs;
use crate::report;
use crate::CliResult;
use optri::io::{self, OutputFormat};
use optri::request::{Outcome, Task};
use optri::Triangulation;
use std::path::{Path, PathBuf};

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
    let results = run.outcome.comparison().expect("a compare request");
    let titles: Vec<String> = results
        .iter()
        .map(|(c, r)| run.title(&report::label(*c, r.as_ref().is_ok_and(|s| s.exact))))
        .collect();
    let written = run.write(&args.output, |outcome, path| {
        write_output(&titles, outcome, path)
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

/// Writes `document` (`.json`) or the panels of the results that
/// triangulated, titled by `titles` (`.svg`).
fn write_output(titles: &[String], outcome: &Outcome, path: &Path) -> optri::Result<Vec<PathBuf>> {
    let results = outcome.comparison().unwrap_or_default();
    let text = match output_format(path)? {
        OutputFormat::Json => {
            let mut s = serde_json::to_string_pretty(&outcome.document())
                .map_err(|e| optri::Error::Io(format!("cannot write '{}': {e}", path.display())))?;
            s.push('\n');
            s
        }
        _ => {
            let panels: Vec<(&str, &Triangulation)> = titles
                .iter()
                .zip(results)
                .filter_map(|(t, (_, r))| r.as_ref().ok().map(|s| (t.as_str(), &s.triangulation)))
                .collect();
            if panels.is_empty() {
                return Err(optri::Error::Io(format!(
                    "cannot write '{}': every criterion refused the input, there is nothing to draw",
                    path.display()
                )));
            }
            io::panels_to_svg(&panels)
        }
    };
    std::fs::write(path, text)
        .map_err(|e| optri::Error::Io(format!("cannot write '{}': {e}", path.display())))?;
    Ok(vec![path.to_path_buf()])
}
