//! `optri demo`: every criterion on a built-in point set, drawn side by side.

use super::{input_error, ms_since};
use crate::args::DemoArgs;
use crate::report;
use crate::CliResult;
use optri::io::{self, InputFormat, OutputFormat, ReadOptions, Source};
use optri::kernel::Point;
use optri::{Criterion, InputKind, PointSet, SimplePolygon, Triangulation};
use std::time::Instant;

/// The built-in point set of `optri demo`.
const DEMO_POINTS: &str = include_str!("../demo_points.txt");

/// The demo's simple polygon (a notched, star-like outline, counter-clockwise),
/// triangulated inside by the criteria of [`DEMO_POLYGON_CRITERIA`].
const DEMO_POLYGON: [Point; 12] = [
    [0.0, 0.0],
    [4.0, 1.0],
    [8.0, 0.0],
    [7.0, 4.0],
    [9.0, 7.0],
    [6.0, 6.5],
    [5.0, 9.0],
    [3.5, 5.5],
    [1.0, 8.0],
    [1.5, 5.0],
    [-1.0, 3.5],
    [2.0, 2.5],
];
/// The criteria drawn on [`DEMO_POLYGON`] (those that support polygons).
const DEMO_POLYGON_CRITERIA: [Criterion; 2] = [Criterion::MinWeight, Criterion::MinMaxArea];

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
    let options = ReadOptions::default().with_format(InputFormat::Text);
    let read = io::read(Source::Text(text), &options).map_err(|e| input_error(name, e))?;
    let points = read.input.points().to_vec();
    // A saddle z = x·y for the criteria that read elevations; the others
    // ignore it.
    let saddle: Vec<f64> = points.iter().map(|p| p[0] * p[1]).collect();
    let point_set = PointSet::new(&points)
        .and_then(|set| set.with_elevations(&saddle))
        .map_err(|e| input_error(name, e))?;
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
    let label = report::label(criterion, solution.exact);
    Ok(DemoResult {
        set,
        title: format!("{label} — {set} set"),
        label,
        triangulation: solution.triangulation,
        ms,
    })
}

pub(crate) fn run(args: DemoArgs) -> CliResult<()> {
    if OutputFormat::from_path(&args.output).map_err(|e| e.to_string())? != OutputFormat::Svg {
        return Err(format!(
            "cannot write '{}': the demo draws an SVG; use a .svg path",
            args.output.display()
        ));
    }
    let (points, point_set) = builtin_points(DEMO_POINTS, "built-in demo points")?;
    let mut results: Vec<DemoResult> = Vec::new();
    for &criterion in Criterion::ALL {
        let r = demo_result(&point_set, criterion, "demo")
            .map_err(|e| format!("{}: {e}", criterion.name()))?;
        results.push(r);
    }
    let mut text = format!(
        "demo set: {} points ({} distinct{})\n",
        points.len(),
        point_set.len(),
        report::duplicates_note(&point_set),
    );
    let polygon =
        SimplePolygon::new(&DEMO_POLYGON).map_err(|e| input_error("built-in demo polygon", e))?;
    text.push_str(&format!(
        "polygon set: a simple polygon of {} vertices, triangulated inside by {}\n",
        polygon.len(),
        DEMO_POLYGON_CRITERIA.map(Criterion::name).join(" and ")
    ));
    for criterion in DEMO_POLYGON_CRITERIA
        .into_iter()
        .filter(|c| c.accepts(InputKind::SimplePolygon))
    {
        let t0 = Instant::now();
        let solution = optri::triangulate(&polygon, criterion)
            .map_err(|e| format!("{} on the demo polygon: {e}", criterion.name()))?;
        let ms = ms_since(t0);
        let label = report::label(criterion, solution.exact);
        results.push(DemoResult {
            set: "polygon",
            title: format!("{label} — polygon set"),
            label,
            triangulation: solution.triangulation,
            ms,
        });
    }
    let panels: Vec<(&str, &Triangulation)> = results
        .iter()
        .map(|r| (r.title.as_str(), &r.triangulation))
        .collect();
    let svg = io::panels_to_svg(&panels);
    std::fs::write(&args.output, svg)
        .map_err(|e| format!("cannot write '{}': {e}", args.output.display()))?;
    // The label column fits the longest label ("maxmin-area (uncertified)").
    let width = results
        .iter()
        .map(|r| r.label.len())
        .max()
        .unwrap_or(0)
        .max(9);
    text.push_str(&format!(
        "\n{:<width$} {:<7} {:>10} {:>12} {:>10} {:>10} {:>10} {:>10}\n",
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
            "{:<width$} {:<7} {:>10.4} {:>12.4} {:>10.4} {:>10.4} {:>10.4} {:>10.3}\n",
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
    report::emit(&text)
}
