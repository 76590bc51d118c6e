//! The command line, as clap types. Criteria and graph kinds come from the
//! library's registry ([`Criterion::ALL`], [`GraphKind::ALL`]), so `--help`
//! lists exactly what the library offers, with its descriptions.

use clap::builder::{PossibleValue, TypedValueParser};
use clap::error::ErrorKind;
use clap::{Args, Parser, Subcommand};
use optri::{Criterion, GraphKind};
use std::ffi::OsStr;
use std::path::PathBuf;

#[derive(Parser)]
#[command(
    name = "optri",
    version,
    about = "Exact optimal planar triangulations and proximity graphs"
)]
pub(crate) struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand)]
pub(crate) enum Command {
    /// Triangulate a point set (or a simple polygon's interior) by a criterion.
    Triangulate(TriangulateArgs),
    /// Compute a proximity graph (convex hull, RNG, Gabriel, MST, Delaunay edges).
    Graph(GraphArgs),
    /// Triangulate a built-in point set by every criterion and draw them side by side.
    Demo(DemoArgs),
}

#[derive(Args)]
pub(crate) struct InputArgs {
    /// Point file (text, .node, .tsp, .geojson/.json), or `-` for stdin. `triangulate` also
    /// takes a simple polygon (a Triangle .poly, or a GeoJSON Polygon without points) and
    /// triangulates its interior.
    pub input: String,
    /// Input format: text, node, poly, tsplib, geojson (default: by extension, else by content).
    #[arg(long, value_name = "FMT")]
    pub input_format: Option<String>,
}

#[derive(Args)]
pub(crate) struct TriangulateArgs {
    #[command(flatten)]
    pub input: InputArgs,
    /// Optimality criterion (case-insensitive).
    #[arg(long, default_value = "delaunay", value_parser = criterion_names())]
    pub criterion: String,
    /// Norm for lengths: euclidean | l1 | linf | lp:P (integer P ≥ 1) |
    /// polygon:x1,y1,x2,y2,... (a centrally symmetric convex unit polygon). Taken by
    /// minmax-length, and by the rng and mst graphs.
    #[arg(long, default_value = "euclidean", value_name = "METRIC")]
    pub metric: String,
    /// Write the triangulation; format by extension: .json .svg .geojson, or .ele, which
    /// also writes the points to the .node file beside it (X.ele writes X.node; refused if
    /// X.node is the input). Repeatable.
    #[arg(long, short, value_name = "FILE")]
    pub output: Vec<PathBuf>,
    /// Print one JSON object with the result to stdout instead of a summary (the same
    /// document as `-o FILE.json`; see docs/json-schema.md).
    #[arg(long)]
    pub json: bool,
}

#[derive(Args)]
pub(crate) struct GraphArgs {
    #[command(flatten)]
    pub input: InputArgs,
    /// Which graph (case-insensitive).
    #[arg(long, value_parser = graph_kinds())]
    pub kind: GraphKind,
    /// Norm for lengths: euclidean | l1 | linf | lp:P (integer P ≥ 1) |
    /// polygon:x1,y1,x2,y2,... (a centrally symmetric convex unit polygon). Taken by
    /// minmax-length, and by the rng and mst graphs.
    #[arg(long, default_value = "euclidean", value_name = "METRIC")]
    pub metric: String,
    /// Write the graph; format by extension: .svg .json .geojson. Repeatable.
    #[arg(long, short, value_name = "FILE")]
    pub output: Vec<PathBuf>,
    /// Print one JSON object with the edges to stdout instead of a summary (the same
    /// document as `-o FILE.json`; see docs/json-schema.md).
    #[arg(long)]
    pub json: bool,
}

#[derive(Args)]
pub(crate) struct DemoArgs {
    /// Where to write the multi-panel SVG.
    #[arg(long, short, value_name = "FILE", default_value = "demo.svg")]
    pub output: PathBuf,
}

/// A clap value parser over one of the library's registries: `--help` lists
/// every name with its description, and a value is looked up by `lookup`,
/// whose [`optri::Error::UnknownName`] message becomes clap's usage error.
#[derive(Clone)]
pub(crate) struct RegistryParser<T> {
    names: Vec<(&'static str, &'static str)>,
    lookup: fn(&str) -> optri::Result<T>,
}

/// `--kind`: the graph kinds of [`GraphKind::ALL`], looked up by
/// [`GraphKind::from_name`]; an unknown kind is a usage error (exit code 2).
fn graph_kinds() -> RegistryParser<GraphKind> {
    RegistryParser {
        names: GraphKind::ALL
            .iter()
            .map(|k| (k.name(), k.description()))
            .collect(),
        lookup: GraphKind::from_name,
    }
}

/// `--criterion`: the criteria of [`Criterion::ALL`], listed for `--help`.
/// The name is checked by [`Criterion::from_name`] only when the command runs,
/// so an unknown criterion is reported like the other input errors (exit
/// code 1), as it always was.
fn criterion_names() -> RegistryParser<String> {
    RegistryParser {
        names: Criterion::ALL
            .iter()
            .map(|c| (c.name(), c.description()))
            .collect(),
        lookup: |name| Ok(name.to_string()),
    }
}

impl<T: Clone + Send + Sync + 'static> TypedValueParser for RegistryParser<T> {
    type Value = T;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &OsStr,
    ) -> Result<T, clap::Error> {
        let arg = arg.map_or_else(|| "the value".to_string(), ToString::to_string);
        let Some(name) = value.to_str() else {
            return Err(cmd.clone().error(
                ErrorKind::InvalidUtf8,
                format!("invalid value for '{arg}': not UTF-8"),
            ));
        };
        (self.lookup)(name).map_err(|e| {
            cmd.clone().error(
                ErrorKind::InvalidValue,
                format!("invalid value '{name}' for '{arg}': {e}"),
            )
        })
    }

    fn possible_values(&self) -> Option<Box<dyn Iterator<Item = PossibleValue> + '_>> {
        Some(Box::new(self.names.iter().map(|&(name, description)| {
            PossibleValue::new(name).help(description)
        })))
    }
}
