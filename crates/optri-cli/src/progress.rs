//! The progress line on stderr: a spinner naming the running phase (read,
//! validate, the criterion, write) with the elapsed time, drawn by
//! indicatif only when stderr is a terminal and `--quiet` is not given, so
//! pipes, logs and tests never see it. The library reports its phases
//! through [`optri::Progress`] (a hook in the run's `Options`).

use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;
use std::time::Duration;

/// The progress line of one command.
#[derive(Clone)]
pub(crate) struct Progress {
    bar: ProgressBar,
}

impl Progress {
    /// A spinner on stderr, or a hidden one when stderr is not a terminal or
    /// `quiet`.
    pub fn new(quiet: bool) -> Self {
        let bar = if quiet || !std::io::stderr().is_terminal() {
            ProgressBar::hidden()
        } else {
            let bar = ProgressBar::new_spinner();
            if let Ok(style) = ProgressStyle::with_template("{spinner} {msg} [{elapsed}]") {
                bar.set_style(style);
            }
            bar.enable_steady_tick(Duration::from_millis(120));
            bar
        };
        Self { bar }
    }

    /// Shows that `phase` is running.
    pub fn phase(&self, phase: impl Into<std::borrow::Cow<'static, str>>) {
        self.bar.set_message(phase);
    }

    /// The hook for the library's [`optri::Options`]: shows each phase it
    /// reports, with its fraction while it is under way.
    pub fn hook(&self) -> optri::Progress {
        let bar = self.bar.clone();
        optri::Progress::new(move |phase, fraction| {
            if fraction > 0.0 && fraction < 1.0 {
                bar.set_message(format!("{phase} {:.0}%", fraction * 100.0));
            } else {
                bar.set_message(phase.to_string());
            }
        })
    }

    /// Runs `f` (which writes to stderr) with the line cleared.
    pub fn suspend(&self, f: impl FnOnce()) {
        self.bar.suspend(f);
    }

    /// Removes the line (before the summary is printed).
    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}
