//! The subcommands, and the prelude they share: check the outputs, read the
//! input, run the library's request (validation and the run, timed), write.

pub(crate) mod compare;
pub(crate) mod criteria;
pub(crate) mod decide;
pub(crate) mod demo;
pub(crate) mod graph;
pub(crate) mod serve;
pub(crate) mod triangulate;

use crate::args::InputArgs;
use crate::progress::Progress;
use crate::CliResult;
use optri::io::{self, InputFormat, OutputFormat, ReadInput, ReadOptions, Source};
use optri::request::{Outcome, Request, Task};
use optri::{Error, Options, Phase};
use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::time::Instant;

/// A command's input as read, before validation: what was read, where it
/// came from, and the phases timed so far.
pub(crate) struct Reading {
    /// The name of the input for messages: its path, or `<stdin>`.
    pub source: String,
    /// The input with the user's values, the arithmetic and the scaled
    /// points the algorithms run on.
    pub read: ReadInput,
    /// `read`, `validate`, then whatever the command adds, `write` and `total`.
    pub timing: Timing,
    /// The progress line on stderr.
    pub progress: Progress,
}

/// One command's request, run: where its input came from, what the
/// library computed (with the input as read and the phases), and the
/// progress line.
pub(crate) struct Run {
    /// The name of the input for messages: its path, or `<stdin>`.
    pub source: String,
    /// The library's outcome: the results, the input, the phases.
    pub outcome: Outcome,
    /// The progress line on stderr.
    pub progress: Progress,
}

impl Run {
    /// A picture title: the input's file name, then `what`.
    pub fn title(&self, what: &str) -> String {
        format!("{} — {what}", display_name(&self.source))
    }

    /// The input as read (the user's values, the arithmetic).
    pub fn read(&self) -> &ReadInput {
        self.outcome.input()
    }

    /// The phases so far.
    pub fn phases(&self) -> &[Phase] {
        self.outcome.phases()
    }

    /// Writes every output with `write`, timed as one `write` phase when
    /// there are outputs; returns the files written.
    pub fn write(
        &mut self,
        outputs: &[PathBuf],
        mut write: impl FnMut(&Outcome, &Path) -> optri::Result<Vec<PathBuf>>,
    ) -> CliResult<Vec<PathBuf>> {
        if outputs.is_empty() {
            return Ok(Vec::new());
        }
        let t0 = Instant::now();
        let mut written = Vec::new();
        for path in outputs {
            match write(&self.outcome, path) {
                Ok(files) => written.extend(files),
                Err(e) => {
                    self.progress.finish();
                    return Err(e.to_string());
                }
            }
        }
        self.outcome.add_phase(Phase {
            name: "write",
            ms: ms_since(t0),
        });
        Ok(written)
    }

    /// Closes the run: the progress line goes, and `total` is timed.
    pub fn finish(&mut self) {
        self.progress.finish();
        self.outcome.finish();
    }
}

impl Reading {
    /// Checks every output path with `format_for` and that it can be
    /// written (before any work, so a typo or a missing directory costs
    /// nothing), refuses outputs that would overwrite the input, then reads
    /// the input, timing `read` from the start, and reports the reader's
    /// warnings on stderr unless `quiet`. With `polygons`, a polygon input is
    /// read as one; otherwise every input is read as points.
    pub fn start(
        input: &InputArgs,
        outputs: &[PathBuf],
        format_for: fn(&Path) -> optri::Result<OutputFormat>,
        polygons: bool,
        quiet: bool,
    ) -> CliResult<Self> {
        let mut timing = Timing {
            start: Instant::now(),
            phases: Vec::new(),
        };
        let mut formats = Vec::with_capacity(outputs.len());
        for path in outputs {
            formats.push(format_for(path).map_err(|e| e.to_string())?);
        }
        refuse_overwriting_input(input, outputs, &formats)?;
        for (path, format) in outputs.iter().zip(&formats) {
            for file in format.files_written(path) {
                check_writable(&file)?;
            }
        }
        let progress = Progress::new(quiet);
        progress.phase(format!("reading {}", input.input));
        let (read, source) = read_input(input, polygons).inspect_err(|_| progress.finish())?;
        progress.phase("validating");
        if !quiet {
            for warning in &read.warnings {
                progress.suspend(|| {
                    let _ = writeln!(
                        std::io::stderr().lock(),
                        "optri: warning: {source}: {warning}"
                    );
                });
            }
        }
        timing.phases.push(Phase {
            name: "read",
            ms: ms_since(timing.start),
        });
        Ok(Self {
            source,
            read,
            timing,
            progress,
        })
    }

    /// Runs `task` with `options` on what was read (the library's
    /// [`Request`]: validation, the run, its phases after `read`).
    pub fn run(self, task: Task, options: Options) -> CliResult<Run> {
        let Reading {
            source,
            read,
            timing,
            progress,
        } = self;
        let outcome = Request::new(read, task)
            .with_options(options)
            .after(timing.start, timing.phases)
            .run()
            .map_err(|e| {
                progress.finish();
                input_error(&source, e)
            })?;
        Ok(Run {
            source,
            outcome,
            progress,
        })
    }
}

/// Fails unless `file` can be written: its directory exists, it is not a
/// directory, and it can be opened for writing (an existing file is opened
/// without truncating it; a new one is created and removed again).
fn check_writable(file: &Path) -> CliResult<()> {
    let fail = |why: String| Err(format!("cannot write '{}': {why}", file.display()));
    let parent = match file.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    if !parent.is_dir() {
        return if parent.exists() {
            fail(format!("'{}' is not a directory", parent.display()))
        } else {
            fail(format!(
                "the directory '{}' does not exist",
                parent.display()
            ))
        };
    }
    if file.is_dir() {
        return fail("it is a directory".to_string());
    }
    let existed = file.exists();
    match std::fs::OpenOptions::new()
        .write(true)
        .create(true)
        .truncate(false)
        .open(file)
    {
        Ok(_) => {
            if !existed {
                let _ = std::fs::remove_file(file);
            }
            Ok(())
        }
        Err(e) => fail(e.to_string()),
    }
}

/// The phases of a command, measured from its start.
pub(crate) struct Timing {
    start: Instant,
    /// The phases timed so far, in order.
    pub phases: Vec<Phase>,
}

/// Milliseconds since `start`.
pub(crate) fn ms_since(start: Instant) -> f64 {
    start.elapsed().as_secs_f64() * 1e3
}

/// Prefixes an input error with the source name, as `FILE:LINE: message`
/// for parse errors.
pub(crate) fn input_error(source: &str, e: Error) -> String {
    match e {
        Error::Parse { line, message } if line > 0 => format!("{source}:{line}: {message}"),
        Error::Parse { message, .. } => format!("{source}: {message}"),
        // I/O messages already name the path.
        Error::Io(message) => message,
        other => format!("{source}: {other}"),
    }
}

/// Reads the input (points, or with `polygons` possibly a polygon) with its
/// decimal values; returns it with the name to use in messages.
fn read_input(args: &InputArgs, polygons: bool) -> CliResult<(ReadInput, String)> {
    let format = args
        .input_format
        .as_deref()
        .map(InputFormat::from_name)
        .transpose()
        .map_err(|e| e.to_string())?;
    let options = ReadOptions::default()
        .with_format(format)
        .with_polygons(polygons);
    if args.input == "-" {
        let source = "<stdin>".to_string();
        let mut bytes = Vec::new();
        std::io::stdin()
            .read_to_end(&mut bytes)
            .map_err(|e| format!("cannot read stdin: {e}"))?;
        let read = io::read(Source::Bytes(&bytes), &options);
        Ok((read.map_err(|e| input_error(&source, e))?, source))
    } else {
        let read = io::read(Source::Path(Path::new(&args.input)), &options);
        Ok((
            read.map_err(|e| input_error(&args.input, e))?,
            args.input.clone(),
        ))
    }
}

/// The file name of `source` (a path or `<stdin>`), for picture titles.
fn display_name(source: &str) -> String {
    Path::new(source)
        .file_name()
        .map_or_else(|| source.to_string(), |n| n.to_string_lossy().into_owned())
}

/// Refuses outputs that would overwrite the input file, before any work: an
/// `.ele` output also writes the `.node` beside it, which is easily the
/// input. Paths are compared canonicalized, so `./x.node` and `x.node` match.
fn refuse_overwriting_input(
    input: &InputArgs,
    outputs: &[PathBuf],
    formats: &[OutputFormat],
) -> CliResult<()> {
    if input.input == "-" {
        return Ok(());
    }
    // A missing input cannot be overwritten; reading it reports the problem.
    let Ok(input_path) = std::fs::canonicalize(&input.input) else {
        return Ok(());
    };
    for (output, format) in outputs.iter().zip(formats) {
        for file in format.files_written(output) {
            if std::fs::canonicalize(&file).is_ok_and(|f| f == input_path) {
                let companion = if &file == output {
                    String::new()
                } else {
                    format!(
                        " (writing '{}' also writes the .node beside it)",
                        output.display()
                    )
                };
                return Err(format!(
                    "refusing to overwrite the input file '{}'{companion}; choose another output name",
                    input.input
                ));
            }
        }
    }
    Ok(())
}
