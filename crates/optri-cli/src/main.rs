//! `optri`: exact optimal planar triangulations and proximity graphs from the
//! command line.
//!
//! Every failure is reported as `optri: error: <message>` on stderr with exit
//! code 1 (clap's usage errors exit with 2); input errors name the file and,
//! where there is one, the line (`FILE:LINE: message`). Output goes through
//! [`emit`], never `print!`, so a closed pipe or a full disk is such a
//! failure too rather than a panic.
#![forbid(unsafe_code)]

use clap::{Args, Parser, Subcommand, ValueEnum};
use optri::io::{self, InputFormat, OutputFormat};
use optri::kernel::Point;
use optri::{Criterion, Error, PointSet, Triangulation};
use serde_json::{json, Map, Value};
use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

/// The built-in point set of `optri demo`.
const DEMO_POINTS: &str = include_str!("demo_points.txt");
/// The demo's second, strictly convex point set, for criteria that need
/// convex position (min-weight, for now).
const DEMO_CONVEX_POINTS: &str = include_str!("demo_convex_points.txt");

#[derive(Parser)]
#[command(
    name = "optri",
    version,
    about = "Exact optimal planar triangulations and proximity graphs"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Triangulate a point set by a criterion.
    Triangulate(TriangulateArgs),
    /// Compute a proximity graph (convex hull, RNG, Gabriel, MST, Delaunay edges).
    Graph(GraphArgs),
    /// Triangulate a built-in point set by every criterion and draw them side by side.
    Demo(DemoArgs),
}

#[derive(Args)]
struct InputArgs {
    /// Point file (text, .node, .tsp, .geojson/.json), or `-` for stdin.
    input: String,
    /// Input format: text, node, tsplib, geojson (default: by extension, else by content).
    #[arg(long, value_name = "FMT")]
    input_format: Option<String>,
}

#[derive(Args)]
struct TriangulateArgs {
    #[command(flatten)]
    input: InputArgs,
    /// Optimality criterion (see `Criterion::ALL`).
    #[arg(long, default_value = "delaunay")]
    criterion: String,
    /// Write the triangulation; format by extension: .json .svg .geojson, or .ele, which
    /// also writes the points to the .node file beside it (X.ele writes X.node; refused if
    /// X.node is the input). Repeatable.
    #[arg(long, short, value_name = "FILE")]
    output: Vec<PathBuf>,
    /// Print one JSON object with the result to stdout instead of a summary.
    #[arg(long)]
    json: bool,
}

#[derive(Clone, Copy, ValueEnum)]
enum GraphKind {
    /// Convex hull boundary (collinear hull points included).
    Hull,
    /// Relative neighbourhood graph.
    Rng,
    /// Gabriel graph.
    Gabriel,
    /// Euclidean minimum spanning tree.
    Mst,
    /// Delaunay triangulation edges.
    Delaunay,
}

impl GraphKind {
    fn name(self) -> &'static str {
        match self {
            GraphKind::Hull => "hull",
            GraphKind::Rng => "rng",
            GraphKind::Gabriel => "gabriel",
            GraphKind::Mst => "mst",
            GraphKind::Delaunay => "delaunay",
        }
    }
}

#[derive(Args)]
struct GraphArgs {
    #[command(flatten)]
    input: InputArgs,
    /// Which graph.
    #[arg(long, value_enum)]
    kind: GraphKind,
    /// Write the graph; format by extension: .svg .json .geojson. Repeatable.
    #[arg(long, short, value_name = "FILE")]
    output: Vec<PathBuf>,
    /// Print one JSON object with the edges to stdout instead of a summary.
    #[arg(long)]
    json: bool,
}

#[derive(Args)]
struct DemoArgs {
    /// Where to write the multi-panel SVG.
    #[arg(long, short, value_name = "FILE", default_value = "demo.svg")]
    output: PathBuf,
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return clap_exit(&e),
    };
    let result = match cli.command {
        Command::Triangulate(args) => triangulate(args),
        Command::Graph(args) => graph(args),
        Command::Demo(args) => demo(args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => fail(&message),
    }
}

/// How a result is labelled: `exact` when every decision was exact, else
/// `uncertified` (e.g. min-weight, optimal up to rounded sums of lengths).
fn exactness(exact: bool) -> &'static str {
    if exact {
        "exact"
    } else {
        "uncertified"
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
        Err(w) => fail(&output_error(
            if e.use_stderr() { "stderr" } else { "stdout" },
            &w,
        )),
    }
}

/// The message for a failed write to `stream`.
fn output_error(stream: &str, e: &std::io::Error) -> String {
    if e.kind() == std::io::ErrorKind::BrokenPipe {
        format!("cannot write to {stream}: the reading end of the pipe was closed")
    } else {
        format!("cannot write to {stream}: {e}")
    }
}

/// A CLI failure, already phrased for the user.
type CliResult<T> = Result<T, String>;

/// Milliseconds since `start`.
fn ms_since(start: Instant) -> f64 {
    start.elapsed().as_secs_f64() * 1e3
}

/// Prefixes an input error with the source name, as `FILE:LINE: message`
/// for parse errors.
fn input_error(source: &str, e: Error) -> String {
    match e {
        Error::Parse { line, message } if line > 0 => format!("{source}:{line}: {message}"),
        Error::Parse { message, .. } => format!("{source}: {message}"),
        // I/O messages already name the path.
        Error::Io(message) => message,
        other => format!("{source}: {other}"),
    }
}

/// Reads the input points; returns them with the name to use in messages.
fn read_input(args: &InputArgs) -> CliResult<(Vec<Point>, String)> {
    let format = args
        .input_format
        .as_deref()
        .map(InputFormat::from_name)
        .transpose()
        .map_err(|e| e.to_string())?;
    if args.input == "-" {
        let source = "<stdin>".to_string();
        let mut text = String::new();
        std::io::stdin()
            .read_to_string(&mut text)
            .map_err(|e| format!("cannot read stdin: {e}"))?;
        let format = format.unwrap_or_else(|| InputFormat::sniff(&text));
        let points = io::read_points(&text, format).map_err(|e| input_error(&source, e))?;
        Ok((points, source))
    } else {
        let points = io::read_points_file(Path::new(&args.input), format)
            .map_err(|e| input_error(&args.input, e))?;
        Ok((points, args.input.clone()))
    }
}

/// The file name of `source` (a path or `<stdin>`), for picture titles.
fn display_name(source: &str) -> String {
    Path::new(source)
        .file_name()
        .map_or_else(|| source.to_string(), |n| n.to_string_lossy().into_owned())
}

/// Writes `text` to stdout. Any failure, a closed pipe included, is an error:
/// output that did not arrive must not look like success to a script.
fn emit(text: &str) -> CliResult<()> {
    let mut out = std::io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(|e| output_error("stdout", &e))
}

/// Refuses outputs that would overwrite the input file, before any work: an
/// `.ele` output also writes the `.node` beside it, which is easily the
/// input. Paths are compared canonicalized, so `./x.node` and `x.node` match.
fn refuse_overwriting_input(input: &InputArgs, outputs: &[PathBuf]) -> CliResult<()> {
    if input.input == "-" {
        return Ok(());
    }
    // A missing input cannot be overwritten; reading it reports the problem.
    let Ok(input_path) = std::fs::canonicalize(&input.input) else {
        return Ok(());
    };
    for output in outputs {
        let format = OutputFormat::from_path(output).map_err(|e| e.to_string())?;
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

/// A rounded measure for the summary: plain notation for everyday
/// magnitudes, scientific otherwise (so 1e60 and 1e-30 stay readable).
fn number(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 || (1e-4..1e9).contains(&a) {
        format!("{v}")
    } else {
        format!("{v:.6e}")
    }
}

fn duplicates_note(points: &PointSet) -> String {
    match points.duplicates().len() {
        0 => String::new(),
        1 => "; merged 1 duplicate point".to_string(),
        n => format!("; merged {n} duplicate points"),
    }
}

fn timing_json(phases: &[(String, f64)]) -> Value {
    let mut map = Map::new();
    for (name, ms) in phases {
        map.insert(name.clone(), json!(ms));
    }
    Value::Object(map)
}

fn timing_text(phases: &[(String, f64)]) -> String {
    phases
        .iter()
        .map(|(name, ms)| format!("{name} {ms:.3} ms"))
        .collect::<Vec<_>>()
        .join(", ")
}

fn triangulate(args: TriangulateArgs) -> CliResult<()> {
    let start = Instant::now();
    // Check everything the user typed before any work.
    let criterion = Criterion::from_name(&args.criterion).map_err(|e| e.to_string())?;
    for path in &args.output {
        OutputFormat::from_path(path).map_err(|e| e.to_string())?;
    }
    refuse_overwriting_input(&args.input, &args.output)?;
    let mut phases: Vec<(String, f64)> = Vec::new();
    let (points, source) = read_input(&args.input)?;
    phases.push(("read".into(), ms_since(start)));
    let t0 = Instant::now();
    let point_set = PointSet::new(&points).map_err(|e| input_error(&source, e))?;
    phases.push(("validate".into(), ms_since(t0)));
    let solution = optri::triangulate(&point_set, criterion).map_err(|e| e.to_string())?;
    phases.extend(solution.phases.iter().map(|p| (p.name.to_string(), p.ms)));
    let t = &solution.triangulation;
    let t0 = Instant::now();
    let mut written = Vec::new();
    for path in &args.output {
        let title = format!(
            "{} — {} ({})",
            display_name(&source),
            criterion.name(),
            exactness(solution.exact)
        );
        written.extend(io::write_triangulation_titled(t, path, &title).map_err(|e| e.to_string())?);
    }
    if !args.output.is_empty() {
        phases.push(("write".into(), ms_since(t0)));
    }
    phases.push(("total".into(), ms_since(start)));
    let stats = t.stats();
    if args.json {
        let out = json!({
            "criterion": criterion.name(),
            "exact": solution.exact,
            "algorithm": solution.algorithm,
            "points": points.len(),
            "distinct_points": point_set.len(),
            "duplicates": point_set.duplicates(),
            "triangles": t.triangles(),
            "stats": stats,
            "timing_ms": timing_json(&phases),
        });
        return emit(&format!("{out}\n"));
    }
    let mut text = format!(
        "criterion: {} ({}) via {}\n\
         points: {} input, {} distinct{}\n\
         triangles: {}, edges: {}, hull points: {}\n\
         edge length: max {}, total {}\n\
         angles: min {}°, max {}°\n\
         areas: min {}, max {}\n\
         time: {}\n",
        criterion.name(),
        exactness(solution.exact),
        solution.algorithm,
        points.len(),
        point_set.len(),
        duplicates_note(&point_set),
        stats.triangles,
        stats.edges,
        stats.hull_points,
        number(stats.max_edge_length),
        number(stats.total_edge_length),
        number(stats.min_angle_deg),
        number(stats.max_angle_deg),
        number(stats.min_area),
        number(stats.max_area),
        timing_text(&phases),
    );
    for path in &written {
        text.push_str(&format!("wrote {}\n", path.display()));
    }
    emit(&text)
}

fn graph(args: GraphArgs) -> CliResult<()> {
    let start = Instant::now();
    for path in &args.output {
        if OutputFormat::from_path(path).map_err(|e| e.to_string())? == OutputFormat::Triangle {
            return Err(format!(
                "cannot write '{}': a graph is not a triangulation; use .svg, .json or .geojson",
                path.display()
            ));
        }
    }
    refuse_overwriting_input(&args.input, &args.output)?;
    let mut phases: Vec<(String, f64)> = Vec::new();
    let (points, source) = read_input(&args.input)?;
    phases.push(("read".into(), ms_since(start)));
    let t0 = Instant::now();
    let point_set = PointSet::new(&points).map_err(|e| input_error(&source, e))?;
    phases.push(("validate".into(), ms_since(t0)));
    let t0 = Instant::now();
    let edges = match args.kind {
        GraphKind::Hull => Ok(optri::convex_hull_edges(&point_set)),
        GraphKind::Rng => optri::relative_neighborhood_graph(&point_set),
        GraphKind::Gabriel => optri::gabriel_graph(&point_set),
        GraphKind::Mst => optri::minimum_spanning_tree(&point_set),
        GraphKind::Delaunay => optri::delaunay_edges(&point_set),
    }
    .map_err(|e| e.to_string())?;
    phases.push((args.kind.name().into(), ms_since(t0)));
    let t0 = Instant::now();
    for path in &args.output {
        let title = format!("{} — {}", display_name(&source), args.kind.name());
        io::write_graph(&points, &edges, &title, path).map_err(|e| e.to_string())?;
    }
    if !args.output.is_empty() {
        phases.push(("write".into(), ms_since(t0)));
    }
    phases.push(("total".into(), ms_since(start)));
    if args.json {
        let out = json!({
            "kind": args.kind.name(),
            "points": points.len(),
            "distinct_points": point_set.len(),
            "duplicates": point_set.duplicates(),
            "edges": edges,
            "timing_ms": timing_json(&phases),
        });
        return emit(&format!("{out}\n"));
    }
    let total: f64 = edges
        .iter()
        .map(|&[a, b]| optri::kernel::metrics::length(points[a as usize], points[b as usize]))
        .sum();
    let mut text = format!(
        "graph: {}\npoints: {} input, {} distinct{}\nedges: {}, total length {}\ntime: {}\n",
        args.kind.name(),
        points.len(),
        point_set.len(),
        duplicates_note(&point_set),
        edges.len(),
        number(total),
        timing_text(&phases),
    );
    for path in &args.output {
        text.push_str(&format!("wrote {}\n", path.display()));
    }
    emit(&text)
}

/// One triangulation of the demo: which point set, the criterion with
/// `(exact)` or `(uncertified)`, the panel title (both of those), the result
/// and its time.
struct DemoResult {
    set: &'static str,
    label: String,
    title: String,
    triangulation: Triangulation,
    ms: f64,
}

/// Reads a built-in point set (valid by construction; errors are still
/// reported, not unwrapped).
fn builtin_points(text: &str, name: &str) -> CliResult<(Vec<Point>, PointSet)> {
    let points = io::read_points(text, InputFormat::Text).map_err(|e| input_error(name, e))?;
    let point_set = PointSet::new(&points).map_err(|e| input_error(name, e))?;
    Ok((points, point_set))
}

/// Triangulates `point_set` (the demo's point set named `set`) by
/// `criterion`, timed and titled.
fn demo_result(
    point_set: &PointSet,
    criterion: Criterion,
    set: &'static str,
) -> optri::Result<DemoResult> {
    let t0 = Instant::now();
    let solution = optri::triangulate(point_set, criterion)?;
    let ms = ms_since(t0);
    let label = format!("{} ({})", criterion.name(), exactness(solution.exact));
    Ok(DemoResult {
        set,
        title: format!("{label} — {set} set"),
        label,
        triangulation: solution.triangulation,
        ms,
    })
}

fn demo(args: DemoArgs) -> CliResult<()> {
    if OutputFormat::from_path(&args.output).map_err(|e| e.to_string())? != OutputFormat::Svg {
        return Err(format!(
            "cannot write '{}': the demo draws an SVG; use a .svg path",
            args.output.display()
        ));
    }
    let (points, point_set) = builtin_points(DEMO_POINTS, "built-in demo points")?;
    let mut results: Vec<DemoResult> = Vec::new();
    // Criteria the demo set does not suit (min-weight needs convex position),
    // with the reason; they are drawn on the convex set instead.
    let mut convex_only: Vec<(Criterion, String)> = Vec::new();
    for &criterion in Criterion::ALL {
        match demo_result(&point_set, criterion, "demo") {
            Ok(r) => results.push(r),
            Err(e @ Error::Unsupported { .. }) => convex_only.push((criterion, e.to_string())),
            Err(e) => return Err(format!("{}: {e}", criterion.name())),
        }
    }
    let mut text = format!(
        "demo set: {} points ({} distinct{})\n",
        points.len(),
        point_set.len(),
        duplicates_note(&point_set),
    );
    if !convex_only.is_empty() {
        let (convex_points, convex_set) =
            builtin_points(DEMO_CONVEX_POINTS, "built-in convex demo points")?;
        text.push_str(&format!(
            "convex set: {} points in convex position (a jittered ellipse)\n",
            convex_points.len()
        ));
        for (criterion, why) in &convex_only {
            text.push_str(&format!(
                "  {} is drawn on the convex set: {why}\n",
                criterion.name()
            ));
        }
        // Greedy is the classic heuristic for minimum weight: draw it on the
        // same set for comparison.
        text.push_str("  greedy is drawn on the convex set too, for comparison\n");
        let shown = Criterion::ALL
            .iter()
            .copied()
            .filter(|&c| c == Criterion::Greedy || convex_only.iter().any(|(o, _)| *o == c));
        for criterion in shown {
            let r = demo_result(&convex_set, criterion, "convex")
                .map_err(|e| format!("{} on the convex demo set: {e}", criterion.name()))?;
            results.push(r);
        }
    }
    let panels: Vec<(&str, &Triangulation)> = results
        .iter()
        .map(|r| (r.title.as_str(), &r.triangulation))
        .collect();
    let svg = io::panels_to_svg(&panels);
    std::fs::write(&args.output, svg)
        .map_err(|e| format!("cannot write '{}': {e}", args.output.display()))?;
    text.push_str(&format!(
        "\n{:<24} {:<7} {:>10} {:>12} {:>10} {:>10} {:>10} {:>10}\n",
        "criterion",
        "set",
        "max edge",
        "total length",
        "min angle",
        "min area",
        "max area",
        "time ms"
    ));
    for r in &results {
        let s = r.triangulation.stats();
        text.push_str(&format!(
            "{:<24} {:<7} {:>10.4} {:>12.4} {:>10.4} {:>10.4} {:>10.4} {:>10.3}\n",
            r.label,
            r.set,
            s.max_edge_length,
            s.total_edge_length,
            s.min_angle_deg,
            s.min_area,
            s.max_area,
            r.ms
        ));
    }
    text.push_str(&format!("\nwrote {}\n", args.output.display()));
    emit(&text)
}
