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
    /// Triangulate one input by every criterion (or the chosen ones) and compare the results.
    Compare(CompareArgs),
    /// List the criteria, graphs and options, with what each takes.
    Criteria(CriteriaArgs),
    /// Decide whether a triangulation's smallest area can be at least (maxmin-area) or its
    /// largest at most (minmax-area) a threshold; exit code 0 for a yes, no or unknown answer.
    Decide(DecideArgs),
    /// Serve the web playground and its JSON API.
    Serve(ServeArgs),
    /// Triangulate a built-in point set by every criterion and draw them side by side.
    Demo(DemoArgs),
}

#[derive(Args)]
pub(crate) struct InputArgs {
    /// Point file, or `-` for stdin: text (`x y` per line, or CSV whose header names x/y,
    /// lon/lat, lng/lat, long/lat, longitude/latitude or easting/northing; other columns are
    /// skipped with a warning), .node, .tsp, .geojson/.json, .ply (ASCII or binary: the vertex
    /// element's x, y and optional z), .obj (the `v` lines). `triangulate` also takes a simple
    /// polygon (a Triangle .poly, or a GeoJSON Polygon without points) and triangulates its
    /// interior.
    pub input: String,
    /// Input format: text, node, poly, tsplib, geojson, ply, obj (default: by extension, else by
    /// content, where PLY is recognised by its `ply` first line, .node and .poly only when the
    /// whole file matches their headers and is not also a table of numbers; anything else is
    /// text).
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
    #[command(flatten)]
    pub run: RunArgs,
    /// Write the triangulation; format by extension: .json .svg .geojson, .obj .ply .off
    /// (meshes: every input point as a vertex at its elevation or 0, then the triangles), or
    /// .ele / .edge (Triangle's triangles / edges), which also write the points to the .node
    /// file beside them (X.ele writes X.node; refused if X.node is the input). Repeatable.
    #[arg(long, short, value_name = "FILE")]
    pub output: Vec<PathBuf>,
    /// Print one JSON object with the result to stdout instead of a summary (the same
    /// document as `-o FILE.json`; see docs/json-schema.md).
    #[arg(long)]
    pub json: bool,
    /// Check the result exactly (`Triangulation::validate`) before writing it, timed as
    /// the phase `check`; a failure is an error.
    #[arg(long)]
    pub validate: bool,
    #[command(flatten)]
    pub style: StyleArgs,
}

#[derive(Args)]
pub(crate) struct DecideArgs {
    #[command(flatten)]
    pub input: InputArgs,
    /// maxmin-area (with --at-least) or minmax-area (with --at-most).
    #[arg(long, value_name = "CRITERION")]
    pub criterion: String,
    /// Is there a triangulation whose every triangle has area (not doubled, in the input's
    /// units) at least this? An exact decimal.
    #[arg(long, value_name = "AREA", allow_hyphen_values = true)]
    pub at_least: Option<String>,
    /// Is there a triangulation whose every triangle has area at most this?
    #[arg(long, value_name = "AREA", allow_hyphen_values = true)]
    pub at_most: Option<String>,
    #[command(flatten)]
    pub run: RunArgs,
    /// Write the decision document (.json) or the witness triangulation (any format of
    /// `triangulate`; refused when the answer is not yes). Repeatable.
    #[arg(long, short, value_name = "FILE")]
    pub output: Vec<PathBuf>,
    /// Print the decision document (`{"document": "decision", "answer": ...}`; see
    /// docs/json-schema.md) instead of the one-line answer.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub style: StyleArgs,
}

/// Layout and chatter: shared by `triangulate` and `graph`.
#[derive(Args)]
pub(crate) struct StyleArgs {
    /// Indent JSON and GeoJSON output files (default: compact, one line).
    #[arg(long)]
    pub pretty: bool,
    /// Write .ply files in ASCII (default: binary little-endian).
    #[arg(long)]
    pub ply_ascii: bool,
    /// No warnings (e.g. about ignored columns) on stderr.
    #[arg(long, short)]
    pub quiet: bool,
}

impl StyleArgs {
    /// How output files are written: the layout of JSON and GeoJSON, the
    /// encoding of PLY, and the picture's `title`.
    pub fn write_options(&self, title: String) -> optri::io::WriteOptions {
        use optri::io::{JsonStyle, PlyEncoding, WriteOptions};
        let style = if self.pretty {
            JsonStyle::Pretty
        } else {
            JsonStyle::Compact
        };
        let ply = if self.ply_ascii {
            PlyEncoding::Ascii
        } else {
            PlyEncoding::BinaryLittleEndian
        };
        WriteOptions::default()
            .with_title(title)
            .with_style(style)
            .with_ply_encoding(ply)
    }
}

#[derive(Args)]
pub(crate) struct GraphArgs {
    #[command(flatten)]
    pub input: InputArgs,
    /// Which graph (case-insensitive).
    #[arg(long, value_parser = graph_kinds())]
    pub kind: GraphKind,
    #[command(flatten)]
    pub run: RunArgs,
    /// Write the graph; format by extension: .svg .json .geojson, .obj (`l` lines) .ply (an
    /// `edge` element), or .edge (Triangle's format), which also writes the points to the .node
    /// file beside it. Repeatable.
    #[arg(long, short, value_name = "FILE")]
    pub output: Vec<PathBuf>,
    /// Print one JSON object with the edges to stdout instead of a summary (the same
    /// document as `-o FILE.json`; see docs/json-schema.md).
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub style: StyleArgs,
}

#[derive(Args)]
pub(crate) struct CompareArgs {
    #[command(flatten)]
    pub input: InputArgs,
    /// Comma-separated criteria to compare, in this order (case-insensitive; default: every
    /// criterion). Criteria that refuse the input are listed with the reason.
    #[arg(long, value_delimiter = ',', value_name = "A,B,...")]
    pub criteria: Vec<String>,
    /// Write the panels side by side (.svg) or the comparison document (.json). Repeatable.
    #[arg(long, short, value_name = "FILE")]
    pub output: Vec<PathBuf>,
    /// Print the comparison document (`{"results": [...]}`, one triangulation document per
    /// criterion; see docs/json-schema.md) instead of the table.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub run: RunArgs,
}

/// The library's options (`optri criteria` lists them): shared by
/// `triangulate`, `graph` and `compare`.
#[derive(Args)]
pub(crate) struct RunArgs {
    /// Norm for lengths: euclidean | l1 | linf | lp:P (integer 1 ≤ P ≤ 64) |
    /// polygon:x1,y1,x2,y2,... (a centrally symmetric convex unit polygon). Taken by
    /// minmax-length, and by the rng and mst graphs (`optri criteria` lists what takes it).
    #[arg(long, default_value = "euclidean", value_name = "METRIC")]
    pub metric: String,
    /// maxmin-area / minmax-area on general point sets: every angle of the result at least
    /// DEG degrees (at most the Delaunay triangulation's smallest angle).
    #[arg(long, value_name = "DEG")]
    pub alpha: Option<String>,
    /// maxmin-area / minmax-area on general point sets: thesis-75 | thesis-76 | rng-hull |
    /// best (the default: the best of all).
    #[arg(long, value_name = "NAME")]
    pub approximation: Option<String>,
    /// Stop a run after this many seconds: it fails with exit code 1, or returns its best
    /// certified result marked not exact where the criterion has one. In `compare`, each
    /// criterion has the whole limit.
    #[arg(long, value_name = "SECONDS")]
    pub time_limit: Option<String>,
}

impl RunArgs {
    /// The library's options these arguments name.
    pub fn options(&self) -> Result<optri::Options, String> {
        let mut options = optri::Options::default();
        options
            .set("metric", &self.metric)
            .map_err(|e| format!("--metric: {e}"))?;
        for (name, flag, value) in [
            ("alpha", "--alpha", &self.alpha),
            ("approximation", "--approximation", &self.approximation),
        ] {
            if let Some(value) = value {
                options
                    .set(name, value)
                    .map_err(|e| format!("{flag}: {e}"))?;
            }
        }
        if let Some(limit) = &self.time_limit {
            options
                .set("time_limit", limit)
                .map_err(|e| format!("--time-limit: {e}"))?;
        }
        Ok(options)
    }
}

/// `optri criteria`.
#[derive(Args)]
pub(crate) struct CriteriaArgs {
    /// Print the registry listing document (the same JSON as Python's `optri.registry()` and
    /// the web API's `GET /api/criteria`; see docs/json-schema.md) instead of the table.
    #[arg(long)]
    pub json: bool,
}

/// `optri serve`. The limits are checked when the server starts: a value that overflows is
/// refused with a message.
#[derive(Args)]
#[command(after_help = "\
API: GET / (the page), GET /api/criteria, GET /api/limits, POST /api/triangulate, \
POST /api/compare, POST /api/graph, POST /api/read; every GET also answers HEAD. \
Errors are JSON {\"error\": message}: 400 bad request, 403 Host or Origin not this \
server (when bound to a loopback address), 408 stalled body, 413 body too large, \
422 input refused, 503 time limit passed or busy.

Requests with at most 2000 points (and /api/read) are small: they run beside the large \
ones on threads of their own and never wait for them; --max-running counts the large \
ones only.")]
pub(crate) struct ServeArgs {
    /// Address to listen on (use 0.0.0.0 to accept other machines; there is no authentication,
    /// and Host and Origin are checked only on a loopback address).
    #[arg(long, default_value = "127.0.0.1")]
    pub host: String,
    /// Port to listen on (0 picks a free one, printed on startup).
    #[arg(long, default_value_t = 8000)]
    pub port: u16,
    /// Refuse requests with more points than this (422).
    #[arg(long, default_value_t = 20_000, value_name = "N")]
    pub max_points: usize,
    /// Answer 503 when a request takes longer than this many seconds, from its headers to its
    /// answer (reading, waiting and computing), and stop its computation. A comparison answers
    /// with the criteria it finished instead.
    #[arg(long, default_value_t = 20.0, value_name = "SECONDS")]
    pub time_limit: f64,
    /// Refuse request bodies larger than this many MiB (413).
    #[arg(long, default_value_t = 8, value_name = "MIB")]
    pub max_body_mib: usize,
    /// Most computations of more than 2000 points running at once; more get 503.
    #[arg(long, default_value_t = 2, value_name = "N")]
    pub max_running: usize,
    /// Drop a client that takes longer than this many seconds to send request headers (or to
    /// send the next request on a kept-alive connection), and answer 408 to one whose body
    /// stalls this long.
    #[arg(long, default_value_t = 5.0, value_name = "SECONDS")]
    pub read_timeout: f64,
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
