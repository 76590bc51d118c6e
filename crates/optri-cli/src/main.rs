//! `optri`: exact optimal planar triangulations and proximity graphs from the
//! command line.
//!
//! Every failure is reported as `optri: error: <message>` on stderr with exit
//! code 1 (clap's usage errors exit with 2); input errors name the file and,
//! where there is one, the line (`FILE:LINE: message`). Output goes through
//! [`report::emit`], never `print!`, so a closed pipe or a full disk is such
//! a failure too rather than a panic.
//!
//! - `args`: the clap types (criteria and graph kinds from the library's
//!   registry);
//! - `commands`: `triangulate`, `graph`, `compare`, `criteria`, `decide`, `serve`, `demo`, and
//!   their shared prelude;
//! - `progress`: the progress line on stderr (terminals only);
//! - `report`: the summaries and the JSON documents on stdout;
//! - `web`: the playground page and JSON API that `serve` answers with.
#![forbid(unsafe_code)]

mod args;
mod commands;
mod progress;
mod report;
mod web;

use args::{Cli, Command};
use clap::Parser;
use std::io::Write;
use std::process::ExitCode;

/// A CLI failure, already phrased for the user.
type CliResult<T> = Result<T, String>;

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return clap_exit(&e),
    };
    let result = match cli.command {
        Command::Triangulate(args) => commands::triangulate::run(args),
        Command::Graph(args) => commands::graph::run(args),
        Command::Compare(args) => commands::compare::run(args),
        Command::Criteria(args) => commands::criteria::run(args),
        Command::Decide(args) => commands::decide::run(args),
        Command::Serve(args) => commands::serve::run(args),
        Command::Demo(args) => commands::demo::run(args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => fail(&message),
    }
}

/// Reports `message` on stderr and returns the failure exit code. A failing
/// stderr is ignored: there is nowhere left to report it, and the exit code
/// still says something went wrong.
fn fail(message: &str) -> ExitCode {
    let _ = writeln!(std::io::stderr().lock(), "optri: error: {message}");
    ExitCode::FAILURE
}

/// Prints clap's help, version or usage error like `Error::exit` would, but
/// a failed write (e.g. `optri --help > /dev/full`) exits with 1 and a
/// message instead of exit code 0.
fn clap_exit(e: &clap::Error) -> ExitCode {
    let written = e.print().and_then(|()| {
        if e.use_stderr() {
            std::io::stderr().flush()
        } else {
            std::io::stdout().flush()
        }
    });
    match written {
        Ok(()) => ExitCode::from(u8::try_from(e.exit_code()).unwrap_or(1)),
        Err(w) => fail(&report::output_error(
            if e.use_stderr() { "stderr" } else { "stdout" },
            &w,
        )),
    }
}
