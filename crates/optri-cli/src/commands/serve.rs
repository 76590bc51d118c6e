//! `optri serve`: the web playground (placeholder).
use crate::args::ServeArgs;
use crate::CliResult;
pub(crate) fn run(_args: ServeArgs) -> CliResult<()> {
    Err("not yet".into())
}
