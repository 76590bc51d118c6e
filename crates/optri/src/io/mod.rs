//! Reading point sets and writing triangulations and graphs, one file per
//! format with its reader and writer side by side:
//!
//! | module | reads | writes |
//! |---|---|---|
//! | `format` | [`InputFormat`] by extension, name or content; [`OutputFormat`] by extension | |
//! | `text` | `x y` per line | |
//! | `node` | Triangle `.node` | `.node` + `.ele` ([`triangulation_to_triangle_files`]) |
//! | `poly` | Triangle `.poly`: one closed boundary, no holes | |
//! | `tsplib` | TSPLIB `.tsp` | |
//! | `geojson` | `Point`/`MultiPoint`; one `Polygon` (outer ring) | triangulations and graphs |
//! | `json` | [`triangulation_from_json`]; its `coordinates` through the GeoJSON reader | the one result schema: [`TriangulationReport`], [`GraphReport`], [`ComparisonReport`] |
//! | `svg` | | single picture, graph, multi-panel comparison |
//!
//! [`read_points`] / [`read_points_file`] pick the reader of points,
//! [`read_polygon`] / [`read_polygon_file`] of a simple polygon's ring, and
//! [`read_input`] / [`read_input_file`] say which of the two a file holds
//! ([`Input`]);
//! [`write_triangulation`] / [`write_graph`] (and their `_report` forms, which
//! write a whole [`TriangulationReport`] / [`GraphReport`] as `.json`) the
//! writer by extension.
//!
//! Every reader returns the points in file order (so point `i` of the result
//! is input index `i` everywhere else in optri) and reports problems as
//! [`Error::Parse`] with the 1-based line number (`line: 0` when the problem
//! concerns the whole input, e.g. an empty file). Coordinates are checked
//! there, where the line is still known: a NaN, an infinity (including a
//! literal that overflows `f64`) or a value outside the exact range of
//! [`crate::kernel`] is rejected with its line.
//!
//! Every writer uses *input* indices (0-based), also in Triangle files, and
//! writes all input points (merged duplicates included, they just belong to
//! no triangle), so every index in an output means the same point as in the
//! input. Coordinates are written in Rust's shortest round-trip notation, so
//! reading an output back gives the identical `f64` values.

mod decimal;
mod format;
mod geojson;
mod json;
mod listing;
mod node;
mod poly;
mod svg;
mod text;
mod tsplib;

pub use decimal::{Arithmetic, Scaled};
pub use format::{InputFormat, OutputFormat};

pub use geojson::{graph_to_geojson, triangulation_to_geojson};
pub use json::{
    comparison_to_json, graph_to_json, solution_to_json, triangulation_from_json,
    triangulation_to_json, ComparisonReport, GraphReport, TriangulationReport, SCHEMA_VERSION,
};
pub use listing::registry_listing;
pub use node::triangulation_to_triangle_files;
pub use svg::{graph_to_svg, panels_to_svg, triangulation_to_svg};

use crate::error::{Error, Result};
use crate::kernel::{self, CoordinateProblem, Point, MAX_COORDINATE, MIN_COORDINATE};
use crate::structures::Triangulation;
use std::path::{Path, PathBuf};

/// The message of every reader for a polygon with holes.
const HOLES_UNSUPPORTED: &str = "polygons with holes are not supported yet";

/// What an input file holds: points (to triangulate their convex hull) or
/// the ring of a simple polygon (to triangulate its interior), as
/// [`read_input`] tells them apart.
#[derive(Clone, Debug, PartialEq)]
pub enum Input {
    /// The points in file order.
    Points(Vec<Point>),
    /// A polygon's vertices in boundary order (either orientation), the
    /// closing vertex not repeated; position `i` is input index `i`.
    Polygon(Vec<Point>),
}

impl Input {
    /// The points, or the polygon's vertices in ring order.
    pub fn points(&self) -> &[Point] {
        match self {
            Input::Points(p) | Input::Polygon(p) => p,
        }
    }
}

/// Parses `text` in `format` as points or a polygon: a `.poly` is always a
/// polygon; a GeoJSON document is points if it has any `Point`/`MultiPoint`
/// geometry (its polygons are then skipped, as [`read_points`] does) and
/// otherwise a polygon if it has exactly one `Polygon` (or a `MultiPolygon`
/// of one polygon); the other formats are points.
///
/// # Errors
/// As [`read_points`]; for a GeoJSON polygon input, [`Error::Parse`] naming
/// the geometry when it has holes ("polygons with holes are not supported
/// yet") or when there is more than one polygon.
pub fn read_input(text: &str, format: InputFormat) -> Result<Input> {
    read_input_exact(text, format).map(|read| read.input)
}

/// What [`read_input_exact`] read: the input with the user's values (the
/// nearest doubles of the decimals written), how the algorithms should
/// compute with it, the scaled integers when they differ from those doubles,
/// and warnings about what was ignored.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct ReadInput {
    /// The points or the polygon, with the user's values.
    pub input: Input,
    /// [`Arithmetic::DecimalExact`] when every coordinate times one common
    /// `10^k` is an integer below 2⁵³ (see the `decimal` module docs).
    pub arithmetic: Arithmetic,
    /// Those integers when `k ≠ 0` (with `k == 0` they are the user's
    /// doubles), in the order of [`Input::points`].
    pub scaled: Option<Scaled>,
    /// What the reader ignored, for the user (e.g. the third column of a
    /// headerless `x y z` file).
    pub warnings: Vec<String>,
}

impl ReadInput {
    /// The points the algorithms should run on: the scaled integers when
    /// there are any, else the user's values.
    pub fn working_points(&self) -> &[Point] {
        match &self.scaled {
            Some(scaled) => &scaled.points,
            None => self.input.points(),
        }
    }

    /// `k` of the scaling (0 when the algorithms run on the user's values).
    pub fn scale_exponent(&self) -> i32 {
        self.scaled.as_ref().map_or(0, |s| s.exponent)
    }
}

/// Reads `text` as [`read_input`] does, keeping each coordinate's decimal
/// value: when every coordinate scaled by one common `10^k` is an integer of
/// magnitude below 2⁵³, [`ReadInput::scaled`] holds those integers, on which
/// every predicate decides the decimals as written.
///
/// # Errors
/// As [`read_input`].
pub fn read_input_exact(text: &str, format: InputFormat) -> Result<ReadInput> {
    read_any(text, format, true)
}

/// `input` given as doubles by a front end (Python floats, the numbers of a
/// web request) read at the decimals they were written as: each coordinate's
/// shortest round-trip decimal, when every one has at most 15 significant
/// digits (each such decimal is the only one of at most 15 digits with that
/// nearest double, so the reading is unambiguous). Otherwise, or when the
/// decimals do not scale to integers below 2⁵³, the input stays binary64.
/// `0.1`, `0.2`, `0.3` typed in Python are then collinear with `0`, as
/// written.
pub fn doubles_as_decimals(input: Input) -> ReadInput {
    let mut decimal = decimal::DecimalScaler::default();
    for p in input.points() {
        decimal.push_shortest(p[0]);
        decimal.push_shortest(p[1]);
    }
    let (arithmetic, scaled) = decimal.finish();
    ReadInput {
        input,
        arithmetic,
        scaled,
        warnings: Vec::new(),
    }
}

/// [`doubles_as_decimals`] for numbers parsed from the JSON `text`: only
/// when no number literal of `text` has more than 15 significant digits (a
/// longer literal is not its double's shortest decimal, so its value is
/// lost; the input then stays binary64).
pub fn json_numbers_as_decimals(input: Input, text: &str) -> ReadInput {
    if decimal::json_literals_are_short(text) {
        doubles_as_decimals(input)
    } else {
        ReadInput {
            input,
            arithmetic: Arithmetic::Binary64,
            scaled: None,
            warnings: Vec::new(),
        }
    }
}

/// Reads `text` as points ([`read_points`]) with their decimal values, as
/// [`read_input_exact`] does.
///
/// # Errors
/// As [`read_points`].
pub fn read_points_exact(text: &str, format: InputFormat) -> Result<ReadInput> {
    read_any(text, format, false)
}

/// Reads a file as [`read_input_exact`] (`polygons`) or
/// [`read_points_exact`] does; `format: None` picks the format as
/// [`read_points_file`] does.
///
/// # Errors
/// As [`read_points_file`] and [`read_input`].
pub fn read_file_exact(
    path: &Path,
    format: Option<InputFormat>,
    polygons: bool,
) -> Result<ReadInput> {
    let (text, format) = read_text(path, format)?;
    read_any(&text, format, polygons)
}

/// Points as a reader collects them: the user's doubles, the decimal values
/// so far, and warnings.
#[derive(Default)]
pub(super) struct Collected {
    pub(super) points: Vec<Point>,
    pub(super) decimal: decimal::DecimalScaler,
    pub(super) warnings: Vec<String>,
}

impl Collected {
    /// Parses and appends the point written as `x y` on `line`.
    pub(super) fn push(&mut self, x: &str, y: &str, line: usize) -> Result<()> {
        let p = [coordinate(x, line)?, coordinate(y, line)?];
        self.decimal.push(x);
        self.decimal.push(y);
        self.points.push(p);
        Ok(())
    }

    /// The collected points as input: in the order `order` (positions into
    /// the file order) when given.
    fn finish(self, polygon: bool, order: Option<&[usize]>) -> ReadInput {
        let (arithmetic, scaled) = self.decimal.finish();
        let reorder = |points: Vec<Point>| match order {
            Some(order) => order.iter().map(|&v| points[v]).collect(),
            None => points,
        };
        let points = reorder(self.points);
        let scaled = scaled.map(|s| Scaled {
            exponent: s.exponent,
            points: reorder(s.points),
        });
        ReadInput {
            input: if polygon {
                Input::Polygon(points)
            } else {
                Input::Points(points)
            },
            arithmetic,
            scaled,
            warnings: self.warnings,
        }
    }
}

fn read_any(text: &str, format: InputFormat, polygons: bool) -> Result<ReadInput> {
    // A UTF-8 byte-order mark is not part of the first token.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let read = match format {
        InputFormat::Text => text::read_text(text)?.finish(false, None),
        InputFormat::Node => node::read_node(text)?.finish(false, None),
        InputFormat::Poly => {
            let (collected, ring) = poly::read_poly(text)?;
            collected.finish(polygons, Some(&ring))
        }
        InputFormat::Tsplib => tsplib::read_tsplib(text)?.finish(false, None),
        InputFormat::GeoJson => geojson::read_geojson_exact(text, polygons)?,
    };
    if read.input.points().is_empty() {
        return Err(parse(0, "no points found in the input"));
    }
    Ok(read)
}

/// Reads an input file as [`read_input`] does; `format: None` picks the
/// format as [`read_points_file`] does.
///
/// # Errors
/// As [`read_points_file`] and [`read_input`].
pub fn read_input_file(path: &Path, format: Option<InputFormat>) -> Result<Input> {
    let (text, format) = read_text(path, format)?;
    read_input(&text, format)
}

/// Parses a simple polygon's ring (boundary order, closing vertex dropped)
/// from a `.poly` or a GeoJSON `Polygon` (see [`read_input`]). The ring is
/// not validated: [`crate::SimplePolygon::new`] does that.
///
/// # Errors
/// As [`read_input`], and [`Error::Parse`] (line 0) when the input holds
/// points rather than a polygon.
pub fn read_polygon(text: &str, format: InputFormat) -> Result<Vec<Point>> {
    match read_input(text, format)? {
        Input::Polygon(ring) => Ok(ring),
        Input::Points(_) => Err(not_a_polygon(format)),
    }
}

/// Reads a polygon file as [`read_polygon`] does; `format: None` picks the
/// format as [`read_points_file`] does.
///
/// # Errors
/// As [`read_points_file`] and [`read_polygon`].
pub fn read_polygon_file(path: &Path, format: Option<InputFormat>) -> Result<Vec<Point>> {
    let (text, format) = read_text(path, format)?;
    read_polygon(&text, format)
}

fn not_a_polygon(format: InputFormat) -> Error {
    parse(
        0,
        format!(
            "the {} input holds points, not a polygon (polygons are read from a GeoJSON \
             Polygon or a Triangle .poly)",
            format.name()
        ),
    )
}

/// Parses `text` in `format`.
///
/// # Errors
/// [`Error::Parse`] with the 1-based line of the first problem, or line 0 when
/// the input holds no points at all.
pub fn read_points(text: &str, format: InputFormat) -> Result<Vec<Point>> {
    match read_any(text, format, false)?.input {
        Input::Points(points) | Input::Polygon(points) => Ok(points),
    }
}

/// Reads a point file; `format: None` picks it by extension
/// ([`InputFormat::from_path`]) and otherwise by content
/// ([`InputFormat::sniff`]).
///
/// # Errors
/// [`Error::Io`] naming the path when the file cannot be read; the parse
/// errors of [`read_points`] (with their line numbers; callers prefix the
/// path).
pub fn read_points_file(path: &Path, format: Option<InputFormat>) -> Result<Vec<Point>> {
    let (text, format) = read_text(path, format)?;
    read_points(&text, format)
}

/// A file's text and its format (given, else by extension, else by content).
fn read_text(path: &Path, format: Option<InputFormat>) -> Result<(String, InputFormat)> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| Error::Io(format!("cannot read '{}': {e}", path.display())))?;
    let format = format
        .or_else(|| InputFormat::from_path(path).ok())
        .unwrap_or_else(|| InputFormat::sniff(&text));
    Ok((text, format))
}

fn write_file(path: &Path, contents: &str) -> Result<()> {
    std::fs::write(path, contents).map_err(|e| write_error(path, &e))
}

fn write_error(path: &Path, e: &dyn std::fmt::Display) -> Error {
    Error::Io(format!("cannot write '{}': {e}", path.display()))
}

/// How JSON and GeoJSON files are laid out.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum JsonStyle {
    /// One line, no spaces (the default: a tenth of the size at 10⁶ points).
    #[default]
    Compact,
    /// Indented, one value per line.
    Pretty,
}

/// Serialises `document` straight into the file at `path` (no string or
/// value tree in between, so the memory is that of the document's own
/// data), with a final newline.
fn write_json_file(path: &Path, document: &impl serde::Serialize, style: JsonStyle) -> Result<()> {
    use std::io::Write;
    let file = std::fs::File::create(path).map_err(|e| write_error(path, &e))?;
    let mut out = std::io::BufWriter::with_capacity(1 << 16, file);
    match style {
        JsonStyle::Compact => serde_json::to_writer(&mut out, document),
        JsonStyle::Pretty => serde_json::to_writer_pretty(&mut out, document),
    }
    .map_err(|e| write_error(path, &e))?;
    out.write_all(b"\n")
        .and_then(|()| out.flush())
        .map_err(|e| write_error(path, &e))
}

/// Writes `t` in the format given by `path`'s extension (see
/// [`OutputFormat`]); an SVG is titled with the file name, a `.json` file is
/// the bare [`TriangulationReport`]. Returns the files written (two for
/// `.ele` and `.edge`: that file and its sibling `.node`).
///
/// # Errors
/// [`Error::Io`] naming the path for an unknown extension or when writing
/// fails.
pub fn write_triangulation(t: &Triangulation, path: &Path) -> Result<Vec<PathBuf>> {
    let title = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    write_triangulation_titled(t, path, &title)
}

/// [`write_triangulation`] with an explicit SVG title.
///
/// # Errors
/// As [`write_triangulation`].
pub fn write_triangulation_titled(
    t: &Triangulation,
    path: &Path,
    title: &str,
) -> Result<Vec<PathBuf>> {
    write_triangulation_report(&TriangulationReport::new(t), path, title)
}

/// Writes the triangulation of `report` by `path`'s extension, as
/// [`write_triangulation_titled`] does, compact JSON; a `.json` file is the
/// whole `report` (with its run fields, e.g. from
/// [`TriangulationReport::of_solution`]).
///
/// # Errors
/// As [`write_triangulation`].
pub fn write_triangulation_report(
    report: &TriangulationReport,
    path: &Path,
    title: &str,
) -> Result<Vec<PathBuf>> {
    write_triangulation_report_styled(report, path, title, JsonStyle::Compact)
}

/// [`write_triangulation_report`] with JSON and GeoJSON laid out in `style`.
/// Coordinates are the report's ([`TriangulationReport::coordinates`]: the
/// user's values).
///
/// # Errors
/// As [`write_triangulation`].
pub fn write_triangulation_report_styled(
    report: &TriangulationReport,
    path: &Path,
    title: &str,
    style: JsonStyle,
) -> Result<Vec<PathBuf>> {
    let t = report.triangulation();
    let points = report.coordinates();
    let format = OutputFormat::from_path(path)?;
    match format {
        OutputFormat::Json => write_json_file(path, report, style)?,
        OutputFormat::GeoJson => write_json_file(
            path,
            &geojson::TriangulationFeatures {
                points,
                triangles: t.triangles(),
                include_points: true,
            },
            style,
        )?,
        OutputFormat::Svg => write_file(path, &svg::report_to_svg(report, title))?,
        OutputFormat::Triangle | OutputFormat::TriangleEdges => {
            let files = format.files_written(path);
            let first = if format == OutputFormat::Triangle {
                node::ele_text(t.triangles())
            } else {
                node::edge_text(&t.edges())
            };
            write_file(&files[0], &first)?;
            write_file(&files[1], &node::node_text(points))?;
            return Ok(files);
        }
    }
    Ok(vec![path.to_path_buf()])
}

/// Writes a graph (edges as index pairs into `points`) as `.svg`, `.json` (the
/// bare [`GraphReport`]), `.geojson` or `.edge` (with the `.node` beside it),
/// by extension.
///
/// # Errors
/// [`Error::Io`] naming the path for `.ele` and unknown extensions
/// ([`OutputFormat::from_path_for_graph`]) or when writing fails.
///
/// # Panics
/// If an edge refers to an index outside `points`.
pub fn write_graph(points: &[Point], edges: &[[u32; 2]], title: &str, path: &Path) -> Result<()> {
    write_graph_report(&GraphReport::new(points, edges), path, title).map(drop)
}

/// Writes the graph of `report` by `path`'s extension, as [`write_graph`]
/// does, compact JSON; a `.json` file is the whole `report` (e.g. with the
/// kind and duplicates of [`GraphReport::of_graph`]). Returns the files
/// written.
///
/// # Errors
/// As [`write_graph`].
///
/// # Panics
/// If an edge refers to an index outside the points.
pub fn write_graph_report(report: &GraphReport, path: &Path, title: &str) -> Result<Vec<PathBuf>> {
    write_graph_report_styled(report, path, title, JsonStyle::Compact)
}

/// [`write_graph_report`] with JSON and GeoJSON laid out in `style`.
///
/// # Errors
/// As [`write_graph`].
///
/// # Panics
/// If an edge refers to an index outside the points.
pub fn write_graph_report_styled(
    report: &GraphReport,
    path: &Path,
    title: &str,
    style: JsonStyle,
) -> Result<Vec<PathBuf>> {
    let (points, edges) = (report.points(), report.edges());
    let format = OutputFormat::from_path_for_graph(path)?;
    match format {
        OutputFormat::Json => write_json_file(path, report, style)?,
        OutputFormat::GeoJson => {
            write_json_file(path, &geojson::GraphFeatures { points, edges }, style)?
        }
        OutputFormat::TriangleEdges => {
            let files = format.files_written(path);
            write_file(&files[0], &node::edge_text(edges))?;
            write_file(&files[1], &node::node_text(points))?;
            return Ok(files);
        }
        // `.ele` (Triangle) was refused by `from_path_for_graph`.
        OutputFormat::Svg | OutputFormat::Triangle => {
            write_file(path, &graph_to_svg(points, edges, title))?
        }
    }
    Ok(vec![path.to_path_buf()])
}

fn parse(line: usize, message: impl Into<String>) -> Error {
    Error::Parse {
        line,
        message: message.into(),
    }
}

/// Parses one coordinate token, rejecting non-numbers, non-finite values and
/// values outside the exact range (which [`crate::PointSet`] would refuse
/// anyway, but without the line).
fn coordinate(token: &str, line: usize) -> Result<f64> {
    let value: f64 = token
        .parse()
        .map_err(|_| parse(line, format!("'{token}' is not a number")))?;
    check_coordinate(value, token, line)
}

fn check_coordinate(value: f64, token: &str, line: usize) -> Result<f64> {
    kernel::check_coordinate(value).map_err(|problem| match problem {
        CoordinateProblem::NonFinite => {
            parse(line, format!("coordinate '{token}' is not a finite number"))
        }
        CoordinateProblem::OutOfRange => parse(
            line,
            format!(
                "coordinate '{token}' is outside the exact range (|v| must be 0 or between \
                 {MIN_COORDINATE:e} and {MAX_COORDINATE:e}); rescale the input"
            ),
        ),
    })
}

/// The part of a line before any `#` comment.
fn strip_comment(line: &str) -> &str {
    line.split('#').next().unwrap_or("")
}

/// The error of a parse test, as `(line, message)`.
#[cfg(test)]
fn line_of(e: Error) -> (usize, String) {
    match e {
        Error::Parse { line, message } => (line, message),
        other => panic!("expected a parse error, got {other:?}"),
    }
}

/// Points with awkward values: random doubles, a duplicate, negative and
/// tiny/huge magnitudes, and a collinear run on the hull.
#[cfg(test)]
fn awkward_points() -> Vec<Point> {
    use rand::{rngs::StdRng, Rng, SeedableRng};
    let mut rng = StdRng::seed_from_u64(7);
    let mut pts: Vec<Point> = (0..40)
        .map(|_| [rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0)])
        .collect();
    pts.extend([
        [2.0, 2.0],
        [2.0, -2.0],
        [2.0, 0.0],
        [2.0, 1.0],
        [-2.0, -2.0],
        [-2.0, 2.0],
    ]);
    pts.push(pts[3]);
    pts.push([1e-30, 3e-40]);
    pts
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{delaunay, PointSet};

    #[test]
    fn write_by_extension() {
        let dir = std::env::temp_dir().join(format!("optri-io-write-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let t = delaunay(&PointSet::new(&awkward_points()).unwrap()).unwrap();
        let written = write_triangulation(&t, &dir.join("t.ele")).unwrap();
        assert_eq!(written, vec![dir.join("t.ele"), dir.join("t.node")]);
        assert_eq!(
            OutputFormat::Triangle.files_written(&dir.join("t.ele")),
            written
        );
        assert_eq!(
            OutputFormat::Json.files_written(&dir.join("t.json")),
            vec![dir.join("t.json")]
        );
        let node = std::fs::read_to_string(dir.join("t.node")).unwrap();
        assert_eq!(read_points(&node, InputFormat::Node).unwrap(), t.points());
        for name in ["t.json", "t.geojson", "t.SVG"] {
            write_triangulation(&t, &dir.join(name)).unwrap();
        }
        let svg = std::fs::read_to_string(dir.join("t.SVG")).unwrap();
        assert_eq!(svg.matches("<line class=\"edge\"").count(), t.edges().len());
        let e = write_triangulation(&t, &dir.join("t.png"))
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("t.png") && e.contains(".svg") && e.contains(".ele"),
            "{e}"
        );
        let e = write_triangulation(&t, &dir.join("missing/t.json")).unwrap_err();
        assert!(
            matches!(&e, Error::Io(m) if m.contains("missing/t.json")),
            "{e:?}"
        );
        let edges = t.edges();
        write_graph(t.points(), &edges, "g", &dir.join("g.geojson")).unwrap();
        let g: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(dir.join("g.geojson")).unwrap()).unwrap();
        assert_eq!(
            g["features"].as_array().unwrap().len(),
            edges.len() + t.points().len()
        );
        assert!(write_graph(t.points(), &edges, "g", &dir.join("g.ele")).is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
