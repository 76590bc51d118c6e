//! `optri compare`: every criterion (or the chosen ones) on one input, as a
//! table of quality measures, the comparison JSON document, or panels side by
//! side in one SVG. The work is [`optri::compare`]; this module only prints.

use super::{ms_since, Run};
use crate::args::CompareArgs;
use crate::report;
use crate::CliResult;
use optri::io::{self, ComparisonReport, OutputFormat};
use optri::{Comparison, Criterion, Options, Phase, Triangulation};
use std::path::{Path, PathBuf};
use std::time::Instant;

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

/// The criteria named by `--criteria` (every one when none is named).
///
/// # Errors
/// The library's message for an unknown name, which lists the valid ones.
fn criteria(names: &[String]) -> CliResult<Vec<Criterion>> {
    names
        .iter()
        .map(|n| n.trim())
        .filter(|n| !n.is_empty())
        .map(|n| Criterion::from_name(n).map_err(|e| e.to_string()))
        .collect()
}

pub(crate) fn run(args: CompareArgs) -> CliResult<()> {
    // Check everything the user typed before any work.
    let criteria = criteria(&args.criteria)?;
    let mut run = Run::start(&args.input, &args.output, output_format, true)?;
    let t0 = Instant::now();
    let options = Options::default();
    let results = match &run.polygon {
        Some(polygon) => optri::compare_polygon(polygon, &criteria, &options),
        None => optri::compare(&run.points, &criteria, &options),
    };
    run.timing.phases.push(Phase {
        name: "compare",
        ms: ms_since(t0),
    });
    let timed = run.timing.phases.clone();
    let document = ComparisonReport::new(&results)
        .with_input(&run.read)
        .with_timing(&timed);
    let titles: Vec<String> = results
        .iter()
        .map(|(c, r)| run.title(&report::label(*c, r.as_ref().is_ok_and(|s| s.exact))))
        .collect();
    let written = run.timing.write(&args.output, |path| {
        write_output(&titles, &results, &document, path)
    })?;
    run.timing.finish();
    if args.json {
        return report::emit_json(
            &ComparisonReport::new(&results)
                .with_input(&run.read)
                .with_timing(&run.timing.phases),
        );
    }
    let mut text = report::comparison_table(&run, &results);
    for path in written {
        text.push_str(&format!("wrote {}\n", path.display()));
    }
    report::emit(&text)
}

/// Writes `document` (`.json`) or the panels of the results that
/// triangulated, titled by `titles` (`.svg`).
fn write_output(
    titles: &[String],
    results: &[Comparison],
    document: &ComparisonReport,
    path: &Path,
) -> optri::Result<Vec<PathBuf>> {
    let text = match output_format(path)? {
        OutputFormat::Json => {
            let mut s = serde_json::to_string_pretty(document)
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
