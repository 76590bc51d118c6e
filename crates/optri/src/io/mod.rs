//! Reading point sets and polygons, and writing the result documents: one
//! entry point each, [`read`] and [`write`](write()), over one file per format with
//! its reader and writer side by side:
//!
//! | module | reads | writes |
//! |---|---|---|
//! | `format` | [`InputFormat`] by extension, name or content; [`OutputFormat`] by extension | |
//! | `text` | `x y` or `x y z` per line, or CSV whose header names the coordinate columns | |
//! | `node` | Triangle `.node` | `.node` + `.ele` or `.edge` |
//! | `poly` | Triangle `.poly`: one closed boundary, no holes | |
//! | `tsplib` | TSPLIB `.tsp` | |
//! | `ply` | PLY (ASCII, binary either endian): the `vertex` element | triangulations and graphs (ASCII or binary) |
//! | `obj` | Wavefront `.obj`: the `v` statements | triangulations and graphs |
//! | `off` | | `.off`: triangulations |
//! | `geojson` | `Point`/`MultiPoint`; one `Polygon` (outer ring) | triangulations and graphs |
//! | `json` | [`triangulation_from_json`]; its `coordinates` through the GeoJSON reader | the one result schema: [`TriangulationReport`], [`GraphReport`], [`ComparisonReport`] |
//! | `svg` | | single picture, graph, multi-panel comparison |
//! | `read` | [`read`]: a [`Source`] (text, bytes or a path) with [`ReadOptions`] | |
//! | `write` | | [`write`](write()): a [`Document`] by the path's extension, with [`WriteOptions`] |
//!
//! [`read`] returns a [`ReadInput`]: the points or a polygon's ring
//! ([`Input`]), the coordinates' decimal values where they are exact
//! (`decimal` module docs), the elevations when the input has a third
//! coordinate ([`ReadInput::elevations`]) and warnings about what was
//! skipped. Front ends
//! that receive numbers rather than files build one with
//! [`ReadInput::from_doubles`] or [`ReadInput::from_json_numbers`].
//!
//! Every reader returns the points in file order (so point `i` of the result
//! is input index `i` everywhere else in optri) and reports problems as
//! [`Error::Parse`] with the 1-based line number (`line: 0` when the problem
//! concerns the whole input, e.g. an empty file; a binary PLY body has no
//! lines, so its errors have line 0 and name the byte offset, element, row
//! and property). Coordinates are checked
//! there, where the line is still known: a NaN, an infinity (including a
//! literal that overflows `f64`) or a value outside the exact range of
//! [`crate::kernel`] is rejected with its line. A message quotes at most the
//! first 40 characters of a bad token, with control and other non-printable
//! characters escaped, so a huge or binary token cannot flood a terminal.
//!
//! Input is bytes: text need not be UTF-8 where no number is read (comments,
//! a TSPLIB `COMMENT`, the names of skipped CSV columns, e.g. in Latin-1).
//! Each byte sequence that is not UTF-8 is read as U+FFFD, which is never a
//! number, a separator or `#`, so a number that holds one is an error naming
//! its line and nothing else changes.
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
mod obj;
mod off;
mod ply;
mod poly;
mod read;
mod svg;
mod text;
mod tsplib;
mod write;

pub use decimal::{Arithmetic, Scaled, Threshold};
pub use format::{InputFormat, OutputFormat};

pub use json::{
    triangulation_from_json, ComparisonReport, DecisionReport, GraphReport, TriangulationReport,
    SCHEMA_VERSION,
};
pub use listing::registry_listing;
pub use read::{read, ReadOptions, Source};
pub use svg::panels_to_svg;
pub use write::{write, Document, JsonStyle, PlyEncoding, WriteOptions};

use crate::error::{Error, Result};
use crate::kernel::{self, CoordinateProblem, Point, MAX_COORDINATE, MIN_COORDINATE};

/// The message of every reader for a polygon with holes.
const HOLES_UNSUPPORTED: &str = "polygons with holes are not supported yet";

/// What an input holds: points (to triangulate their convex hull) or the
/// ring of a simple polygon (to triangulate its interior).
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

/// What [`read`] read: the input with the user's values (the nearest
/// doubles of the decimals written), how the algorithms should compute with
/// it, the scaled integers when they differ from those doubles, and warnings
/// about what was skipped.
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
    /// What the reader skipped, for the user (e.g. the columns 3 and on of
    /// a headerless file of four or more columns, or the columns a CSV
    /// header names besides the coordinates).
    pub warnings: Vec<String>,
    /// The format the input was read in; `None` for numbers a front end
    /// received ([`from_doubles`](Self::from_doubles)).
    pub format: Option<InputFormat>,
    /// An elevation per point, in the order of [`Input::points`] (input
    /// order), when the input carried a third coordinate: a text file's `z`
    /// column, GeoJSON's 3-D positions, a Triangle file's first vertex
    /// attribute. Readers check each value as they check a coordinate;
    /// [`crate::PointSet::with_elevations`] checks the rest (the count, and
    /// that duplicates agree) when a request builds its input.
    pub elevations: Option<Vec<f64>>,
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

    /// The total Euclidean length of `edges` (indices into
    /// [`Self::working_points`]) in the user's units: the exact sum over the
    /// points the algorithms ran on, divided back by `10^k` and rounded once.
    pub fn total_length(&self, edges: &[[u32; 2]]) -> f64 {
        kernel::reporting::total_length_scaled(
            self.working_points(),
            edges,
            self.scale_exponent(),
            kernel::reporting::Rounding::Nearest,
        )
    }

    /// This input with an elevation per point (in the order of
    /// [`Input::points`]), e.g. the third column a front end received.
    /// Elevations are never scaled: they stay the user's values (the
    /// scaling of `x` and `y` is a uniform factor, see [`Self::scaled`]).
    /// They are checked when a request builds its input
    /// ([`crate::PointSet::with_elevations`]).
    pub fn with_elevations(self, elevations: Vec<f64>) -> Self {
        Self {
            elevations: Some(elevations),
            ..self
        }
    }

    /// `input` given as doubles by a front end (Python floats, the numbers
    /// of a web request) read at the decimals they were written as: each
    /// coordinate's shortest round-trip decimal, when every one has at most
    /// 15 significant digits (each such decimal is the only one of at most
    /// 15 digits with that nearest double, so the reading is unambiguous).
    /// Otherwise, or when the decimals do not scale to integers below 2⁵³,
    /// the input stays binary64. `0.1`, `0.2`, `0.3` typed in Python are
    /// then collinear with `0`, as written.
    pub fn from_doubles(input: Input) -> Self {
        Self::from_shortest_decimals(input, decimal::DecimalScaler::default())
    }

    /// [`from_doubles`](Self::from_doubles) for numbers parsed from the JSON
    /// `text`: only when no number literal of `text` has more than 15
    /// significant digits (a longer literal is not its double's shortest
    /// decimal, so its value is lost; the input then stays binary64).
    pub fn from_json_numbers(input: Input, text: &str) -> Self {
        let scaler = if decimal::json_literals_are_short(text) {
            decimal::DecimalScaler::default()
        } else {
            decimal::DecimalScaler::given_up()
        };
        Self::from_shortest_decimals(input, scaler)
    }

    /// `input` with the decimals `scaler` finds in its doubles' shortest
    /// round-trip forms.
    fn from_shortest_decimals(input: Input, mut scaler: decimal::DecimalScaler) -> Self {
        for p in input.points() {
            scaler.push_shortest(p[0]);
            scaler.push_shortest(p[1]);
        }
        let (arithmetic, scaled) = scaler.finish();
        ReadInput {
            input,
            arithmetic,
            scaled,
            warnings: Vec::new(),
            format: None,
            elevations: None,
        }
    }
}

/// Points as a reader collects them: the user's doubles, the decimal values
/// so far, the elevations (none, or one per point), and warnings.
#[derive(Default)]
pub(super) struct Collected {
    pub(super) points: Vec<Point>,
    pub(super) decimal: decimal::DecimalScaler,
    pub(super) elevations: Vec<f64>,
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

    /// Appends a point stored as binary numbers (a binary PLY's), read at
    /// its coordinates' shortest round-trip decimals as front ends read
    /// doubles ([`ReadInput::from_doubles`]); `point` is already checked.
    pub(super) fn push_binary(&mut self, point: Point) {
        self.decimal.push_shortest(point[0]);
        self.decimal.push_shortest(point[1]);
        self.points.push(point);
    }

    /// Parses and appends the elevation of the point just pushed, written as
    /// `z` on `line`. A reader calls it for every point or for none.
    pub(super) fn push_elevation(&mut self, z: &str, line: usize) -> Result<()> {
        self.elevations.push(elevation(z, line)?);
        Ok(())
    }

    /// The collected points as input in `format`: in the order `order`
    /// (positions into the file order) when given.
    fn finish(self, format: InputFormat, polygon: bool, order: Option<&[usize]>) -> ReadInput {
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
        debug_assert!(self.elevations.is_empty() || self.elevations.len() == points.len());
        let elevations = (!self.elevations.is_empty()).then(|| match order {
            Some(order) => order.iter().map(|&v| self.elevations[v]).collect(),
            None => self.elevations,
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
            format: Some(format),
            elevations,
        }
    }
}

/// What the mesh writers (OBJ, PLY, OFF) write: every input point as a
/// vertex, at its elevation (0 without), and the triangles or the edges over
/// those vertices' input indices.
pub(super) struct Mesh<'a> {
    pub(super) points: &'a [Point],
    pub(super) elevations: Option<&'a [f64]>,
    pub(super) cells: Cells<'a>,
}

/// The cells of a [`Mesh`].
#[derive(Clone, Copy)]
pub(super) enum Cells<'a> {
    /// A triangulation's counter-clockwise triangles.
    Triangles(&'a [[u32; 3]]),
    /// A graph's edges.
    Edges(&'a [[u32; 2]]),
}

impl Mesh<'_> {
    /// Each vertex as `[x, y, z]`, in input order.
    pub(super) fn vertices(&self) -> impl Iterator<Item = [f64; 3]> + '_ {
        self.points.iter().enumerate().map(|(i, p)| {
            let z = self.elevations.map_or(0.0, |z| z[i]);
            [p[0], p[1], z]
        })
    }
}

/// A number in shortest round-trip notation, with an exponent for very
/// large or small magnitudes (Rust's `{}` never uses one, so `1e300` would
/// take 301 digits): reading it back gives the identical `f64`.
pub(super) struct Shortest(pub(super) f64);

impl std::fmt::Display for Shortest {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let a = self.0.abs();
        if a == 0.0 || (1e-5..1e16).contains(&a) {
            write!(f, "{}", self.0)
        } else {
            write!(f, "{:e}", self.0)
        }
    }
}

/// The elevations of `point_set` in input order (duplicates included), if
/// it has any: what the writers write beside the input points.
fn input_elevations(point_set: &crate::PointSet) -> Option<Vec<f64>> {
    let z = point_set.elevations()?;
    let n = point_set.input_points().len() as u32;
    Some(
        (0..n)
            .map(|i| z[point_set.distinct_index(i) as usize])
            .collect(),
    )
}

fn parse(line: usize, message: impl Into<String>) -> Error {
    Error::Parse {
        line,
        message: message.into(),
    }
}

/// How many characters of a token a message quotes.
const QUOTED_CHARACTERS: usize = 40;

/// `token` for a message: in single quotes, its first
/// [`QUOTED_CHARACTERS`] characters (then `…` and its length in bytes), with
/// control and other non-printable characters escaped (`\n`, `\u{1b}`), so
/// that a 50 MB or binary token gives a one-line message.
fn quoted(token: &str) -> String {
    shown(token, "'")
}

/// [`quoted`] between `quote` marks (`""` for none, where the token is a
/// keyword the message names, e.g. a TSPLIB `EDGE_WEIGHT_TYPE`).
fn shown(token: &str, quote: &str) -> String {
    let mut out = String::from(quote);
    let mut chars = token.chars();
    for c in chars.by_ref().take(QUOTED_CHARACTERS) {
        match c {
            // Quotes stay as they are: the message is for a reader, not a parser.
            '\'' | '"' => out.push(c),
            _ => out.extend(c.escape_debug()),
        }
    }
    if chars.next().is_some() {
        out.push_str(&format!("…{quote} ({} bytes)", token.len()));
    } else {
        out.push_str(quote);
    }
    out
}

/// What a token that should be a number is, for messages: the quoted
/// token, with a note when it holds U+FFFD (what the readers make of bytes
/// that are not UTF-8).
fn not_a_number(token: &str) -> String {
    let note = if token.contains('\u{fffd}') {
        " (� stands for bytes that are not UTF-8)"
    } else {
        ""
    };
    format!("{} is not a number{note}", quoted(token))
}

/// Parses one coordinate token, rejecting non-numbers, non-finite values and
/// values outside the exact range (which [`crate::PointSet`] would refuse
/// anyway, but without the line).
fn coordinate(token: &str, line: usize) -> Result<f64> {
    let value: f64 = token
        .parse()
        .map_err(|_| parse(line, not_a_number(token)))?;
    check_coordinate(value, token, line)
}

fn check_coordinate(value: f64, token: &str, line: usize) -> Result<f64> {
    check_value(value, "coordinate", token, line)
}

/// Parses one elevation token, checked as a coordinate is (the range that
/// [`crate::PointSet::with_elevations`] accepts).
fn elevation(token: &str, line: usize) -> Result<f64> {
    let value: f64 = token
        .parse()
        .map_err(|_| parse(line, format!("elevation {}", not_a_number(token))))?;
    check_value(value, "elevation", token, line)
}

/// `value` (written as `token` on `line`) if it is finite and in the exact
/// range; `what` names it in the message (`coordinate`, `elevation`).
fn check_value(value: f64, what: &str, token: &str, line: usize) -> Result<f64> {
    kernel::check_coordinate(value).map_err(|problem| match problem {
        CoordinateProblem::NonFinite => parse(
            line,
            format!("{what} {} is not a finite number", quoted(token)),
        ),
        CoordinateProblem::OutOfRange => parse(
            line,
            format!(
                "{what} {} is outside the exact range (|v| must be 0 or between \
                 {MIN_COORDINATE:e} and {MAX_COORDINATE:e}); rescale the input",
                quoted(token)
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

/// `text` read in `format` (points only), for the readers' tests.
#[cfg(test)]
fn read_str(text: &str, format: InputFormat) -> Result<ReadInput> {
    read(
        Source::Text(text),
        &ReadOptions::default().with_format(format),
    )
}

/// The points of `text` read in `format`, for the readers' tests.
#[cfg(test)]
fn points_of(text: &str, format: InputFormat) -> Result<Vec<Point>> {
    read_str(text, format).map(|r| r.input.points().to_vec())
}

/// The points or polygon `text` holds in `format`, for the readers' tests.
#[cfg(test)]
fn input_of(text: &str, format: InputFormat) -> Result<Input> {
    let options = ReadOptions::default()
        .with_format(format)
        .with_polygons(true);
    read(Source::Text(text), &options).map(|r| r.input)
}

/// The ring of the polygon `text` holds in `format`, for the readers' tests.
#[cfg(test)]
fn ring_of(text: &str, format: InputFormat) -> Result<Vec<Point>> {
    match input_of(text, format)? {
        Input::Polygon(ring) => Ok(ring),
        Input::Points(_) => Err(parse(
            0,
            format!("the {} input holds points, not a polygon", format.name()),
        )),
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
