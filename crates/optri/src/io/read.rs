//! Readers for point sets: plain text, Triangle `.node`, TSPLIB `.tsp` and
//! GeoJSON.
//!
//! Every reader returns the points in file order (so point `i` of the result
//! is input index `i` everywhere else in optri) and reports problems as
//! [`Error::Parse`] with the 1-based line number (`line: 0` when the problem
//! concerns the whole input, e.g. an empty file). Coordinates are checked
//! here, where the line is still known: a NaN, an infinity (including a
//! literal that overflows `f64`) or a value outside the exact range of
//! [`crate::kernel`] is rejected with its line.

use crate::error::{Error, Result};
use crate::kernel::{self, CoordinateProblem, Point, MAX_COORDINATE, MIN_COORDINATE};
use serde_json::Value;
use std::path::Path;

/// The point-file formats optri reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum InputFormat {
    /// One point per line, `x y` (separated by spaces, tabs, commas or
    /// semicolons); `#` starts a comment; an optional non-numeric header line
    /// may precede the data. Every data row must have the same number of
    /// columns (at least two, all numbers). The coordinates are the columns
    /// the header names `x` and `y` (case-insensitive, e.g. `id,x,y`), else
    /// the first two; other columns are ignored. A run of spaces and tabs is
    /// one separator, but a comma or semicolon always ends a field, so an
    /// empty field (`1,,0`, or a separator at the start or end of a line) is
    /// an error rather than a silently shifted column.
    Text,
    /// Triangle's `.node`: a header `n dim attributes boundary_marker`, then
    /// `id x y [attributes…] [marker]` per vertex.
    Node,
    /// TSPLIB `.tsp` with a `NODE_COORD_SECTION` (coordinates taken as they
    /// are, also for `GEO` and `ATT` instances).
    Tsplib,
    /// GeoJSON `Point`/`MultiPoint` geometries (bare, in a `Feature`, a
    /// `FeatureCollection` or a `GeometryCollection`); the other geometry
    /// types (`LineString`, `Polygon`, their `Multi` forms) are skipped, so
    /// optri's own GeoJSON output reads back as its points. Also optri's own
    /// JSON output (an object with a `"points"` array).
    GeoJson,
}

impl InputFormat {
    /// Every format, for listings.
    pub const ALL: &'static [InputFormat] = &[
        InputFormat::Text,
        InputFormat::Node,
        InputFormat::Tsplib,
        InputFormat::GeoJson,
    ];

    /// The name accepted by [`from_name`](Self::from_name).
    pub fn name(self) -> &'static str {
        match self {
            InputFormat::Text => "text",
            InputFormat::Node => "node",
            InputFormat::Tsplib => "tsplib",
            InputFormat::GeoJson => "geojson",
        }
    }

    /// The format implied by a file's extension (case-insensitive):
    /// `.txt .xy .csv .pts` → Text, `.node` → Node, `.tsp` → Tsplib,
    /// `.geojson .json` → GeoJson; `None` otherwise.
    pub fn from_path(path: &Path) -> Option<Self> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "txt" | "xy" | "csv" | "pts" => Some(InputFormat::Text),
            "node" => Some(InputFormat::Node),
            "tsp" => Some(InputFormat::Tsplib),
            "geojson" | "json" => Some(InputFormat::GeoJson),
            _ => None,
        }
    }

    /// Looks a format up by name (`text`, `node`, `tsplib`, `geojson`; also
    /// the aliases `txt`, `tsp`, `json`).
    ///
    /// # Errors
    /// [`Error::UnknownName`] listing the available names.
    pub fn from_name(name: &str) -> Result<Self> {
        match name.to_ascii_lowercase().as_str() {
            "text" | "txt" | "xy" | "csv" => Ok(InputFormat::Text),
            "node" => Ok(InputFormat::Node),
            "tsplib" | "tsp" => Ok(InputFormat::Tsplib),
            "geojson" | "json" => Ok(InputFormat::GeoJson),
            _ => Err(Error::UnknownName {
                kind: "input format",
                name: name.to_string(),
                available: Self::ALL.iter().map(|f| f.name()).collect(),
            }),
        }
    }

    /// Guesses the format from the content (for stdin and unknown
    /// extensions): a leading `{` means GeoJSON, a TSPLIB keyword line
    /// (`NAME`, `TYPE`, `DIMENSION`, `NODE_COORD_SECTION`) means TSPLIB,
    /// anything else is read as text. `.node` files are not guessed.
    pub fn sniff(text: &str) -> Self {
        let trimmed = text.trim_start();
        if trimmed.starts_with('{') {
            return InputFormat::GeoJson;
        }
        let first = trimmed.lines().next().unwrap_or("");
        let key = first.split(':').next().unwrap_or("").trim();
        if first.contains(':') && matches!(key, "NAME" | "TYPE" | "DIMENSION" | "COMMENT")
            || text.lines().any(|l| l.trim() == "NODE_COORD_SECTION")
        {
            return InputFormat::Tsplib;
        }
        InputFormat::Text
    }
}

/// Parses `text` in `format`.
///
/// # Errors
/// [`Error::Parse`] with the 1-based line of the first problem, or line 0 when
/// the input holds no points at all.
pub fn read_points(text: &str, format: InputFormat) -> Result<Vec<Point>> {
    // A UTF-8 byte-order mark is not part of the first token.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let points = match format {
        InputFormat::Text => read_text(text)?,
        InputFormat::Node => read_node(text)?,
        InputFormat::Tsplib => read_tsplib(text)?,
        InputFormat::GeoJson => read_geojson(text)?,
    };
    if points.is_empty() {
        return Err(parse(0, "no points found in the input"));
    }
    Ok(points)
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
    let text = std::fs::read_to_string(path)
        .map_err(|e| Error::Io(format!("cannot read '{}': {e}", path.display())))?;
    let format = format
        .or_else(|| InputFormat::from_path(path))
        .unwrap_or_else(|| InputFormat::sniff(&text));
    read_points(&text, format)
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

/// The fields of one text line. Whitespace runs separate fields, and so does
/// each comma or semicolon (with any whitespace around it); an empty field
/// between two of them, or before or after one, is an error: skipping it
/// would silently shift the columns (`1,,0` would read as `1 0`).
fn text_fields(line_text: &str, line: usize) -> Result<Vec<&str>> {
    let trimmed = line_text.trim();
    if trimmed.is_empty() {
        return Ok(Vec::new());
    }
    let mut fields = Vec::new();
    for part in trimmed.split([',', ';']) {
        let before = fields.len();
        fields.extend(part.split_whitespace());
        if fields.len() == before {
            return Err(parse(
                line,
                format!(
                    "field {} is empty (two separators in a row, or one at the start or end \
                     of the line); every field must hold a number",
                    before + 1
                ),
            ));
        }
    }
    Ok(fields)
}

fn read_text(text: &str) -> Result<Vec<Point>> {
    let mut points = Vec::new();
    // Column count of the first data row and its line, to report ragged rows.
    let mut columns: Option<(usize, usize)> = None;
    let mut seen_content = false;
    // Columns of x and y: named by the header, else the first two.
    let mut xy_columns = [0, 1];
    let mut header_columns = None;
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let tokens = text_fields(strip_comment(raw), line)?;
        if tokens.is_empty() {
            continue;
        }
        let first_content = !seen_content;
        seen_content = true;
        // A header (e.g. `x,y`) is allowed only as the first content line and
        // only when none of its tokens is a number.
        if first_content && tokens.iter().all(|t| t.parse::<f64>().is_err()) {
            let named = |name: &str| tokens.iter().position(|t| t.eq_ignore_ascii_case(name));
            if let (Some(x), Some(y)) = (named("x"), named("y")) {
                xy_columns = [x, y];
                header_columns = Some((tokens.len(), line));
            }
            continue;
        }
        match columns {
            None => {
                if tokens.len() < 2 {
                    return Err(parse(
                        line,
                        format!("expected 'x y', found a single value '{}'", tokens[0]),
                    ));
                }
                if let Some((n, header)) = header_columns.filter(|&(n, _)| n != tokens.len()) {
                    return Err(parse(
                        line,
                        format!(
                            "{} columns, but the header on line {header} names {n}",
                            tokens.len()
                        ),
                    ));
                }
                columns = Some((tokens.len(), line));
            }
            Some((n, first)) if n != tokens.len() => {
                return Err(parse(
                    line,
                    format!(
                        "{} columns, but line {first} has {n}; every row must have the same number of columns",
                        tokens.len()
                    ),
                ));
            }
            Some(_) => {}
        }
        // Extra columns must still be numbers, so a stray word is not ignored.
        for (k, t) in tokens.iter().enumerate() {
            if !xy_columns.contains(&k) {
                t.parse::<f64>()
                    .map_err(|_| parse(line, format!("'{t}' is not a number")))?;
            }
        }
        points.push([
            coordinate(tokens[xy_columns[0]], line)?,
            coordinate(tokens[xy_columns[1]], line)?,
        ]);
    }
    Ok(points)
}

fn read_node(text: &str) -> Result<Vec<Point>> {
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| {
            (
                i + 1,
                strip_comment(l).split_whitespace().collect::<Vec<_>>(),
            )
        })
        .filter(|(_, t)| !t.is_empty());
    let Some((header_line, header)) = lines.next() else {
        return Ok(Vec::new());
    };
    let field = |k: usize, what: &str| -> Result<usize> {
        match header.get(k) {
            None if k >= 2 => Ok(0),
            None => Err(parse(header_line, format!("header lacks the {what}"))),
            Some(t) => t.parse().map_err(|_| {
                parse(
                    header_line,
                    format!("header field {what} '{t}' is not a non-negative integer"),
                )
            }),
        }
    };
    let count = field(0, "vertex count")?;
    let dimension = field(1, "dimension")?;
    let attributes = field(2, "attribute count")?;
    let markers = field(3, "boundary-marker flag")?;
    if dimension != 2 {
        return Err(parse(
            header_line,
            format!("dimension is {dimension}, only 2 is supported"),
        ));
    }
    if markers > 1 {
        return Err(parse(
            header_line,
            format!("boundary-marker flag must be 0 or 1, found {markers}"),
        ));
    }
    let columns = 3 + attributes + markers;
    let mut points = Vec::with_capacity(count.min(1 << 20));
    let mut first_id = None;
    for (line, tokens) in lines {
        if points.len() == count {
            return Err(parse(
                line,
                format!("more vertex lines than the {count} the header announces"),
            ));
        }
        if tokens.len() != columns {
            return Err(parse(
                line,
                format!(
                    "expected {columns} fields (id x y{}{}), found {}",
                    if attributes > 0 { " attributes…" } else { "" },
                    if markers > 0 { " marker" } else { "" },
                    tokens.len()
                ),
            ));
        }
        let id: usize = tokens[0]
            .parse()
            .map_err(|_| parse(line, format!("vertex id '{}' is not an integer", tokens[0])))?;
        let base = *first_id.get_or_insert(id);
        if base > 1 || id != base + points.len() {
            return Err(parse(
                line,
                format!(
                    "vertex id {id} out of sequence (expected {})",
                    if base > 1 { 0 } else { base + points.len() }
                ),
            ));
        }
        for t in &tokens[3..] {
            t.parse::<f64>()
                .map_err(|_| parse(line, format!("'{t}' is not a number")))?;
        }
        points.push([coordinate(tokens[1], line)?, coordinate(tokens[2], line)?]);
    }
    if points.len() != count {
        return Err(parse(
            header_line,
            format!(
                "the header announces {count} vertices, the file has {}",
                points.len()
            ),
        ));
    }
    Ok(points)
}

fn read_tsplib(text: &str) -> Result<Vec<Point>> {
    let mut dimension: Option<(usize, usize)> = None;
    let mut in_coordinates = false;
    let mut section_line = None;
    let mut points = Vec::new();
    let mut last_id = 0usize;
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let trimmed = raw.trim();
        if trimmed.is_empty() {
            continue;
        }
        if trimmed == "EOF" {
            break;
        }
        let first = trimmed
            .split_whitespace()
            .next()
            .unwrap_or("")
            .trim_end_matches(':');
        if in_coordinates && !first.ends_with("_SECTION") {
            let tokens: Vec<&str> = trimmed.split_whitespace().collect();
            if tokens.len() != 3 {
                return Err(parse(
                    line,
                    format!(
                        "expected 'id x y' in NODE_COORD_SECTION, found {} fields",
                        tokens.len()
                    ),
                ));
            }
            let id: usize = tokens[0]
                .parse()
                .map_err(|_| parse(line, format!("node id '{}' is not an integer", tokens[0])))?;
            if id != last_id + 1 {
                return Err(parse(
                    line,
                    format!("node id {id} out of sequence (expected {})", last_id + 1),
                ));
            }
            last_id = id;
            points.push([coordinate(tokens[1], line)?, coordinate(tokens[2], line)?]);
            continue;
        }
        if in_coordinates {
            // Another section follows the coordinates (e.g. a tour); the
            // points are complete.
            break;
        }
        if first == "NODE_COORD_SECTION" {
            in_coordinates = true;
            section_line = Some(line);
            continue;
        }
        if first.ends_with("_SECTION") {
            return Err(parse(
                line,
                format!("{first} before any NODE_COORD_SECTION: the file has no coordinates"),
            ));
        }
        let Some((key, value)) = trimmed.split_once(':') else {
            return Err(parse(
                line,
                format!("expected a header line 'KEY : VALUE', found '{trimmed}'"),
            ));
        };
        let (key, value) = (key.trim(), value.trim());
        match key {
            "DIMENSION" => {
                let n = value.parse().map_err(|_| {
                    parse(
                        line,
                        format!("DIMENSION '{value}' is not a non-negative integer"),
                    )
                })?;
                dimension = Some((n, line));
            }
            "EDGE_WEIGHT_TYPE" => match value {
                "EUC_2D" | "ATT" | "GEO" | "CEIL_2D" | "MAN_2D" | "MAX_2D" => {}
                _ => {
                    return Err(parse(
                        line,
                        format!(
                            "EDGE_WEIGHT_TYPE {value} has no planar coordinates; \
                             supported: EUC_2D, CEIL_2D, MAN_2D, MAX_2D, ATT, GEO"
                        ),
                    ))
                }
            },
            "NODE_COORD_TYPE" if value != "TWOD_COORDS" => {
                return Err(parse(
                    line,
                    format!("NODE_COORD_TYPE {value} is not supported (only TWOD_COORDS)"),
                ))
            }
            _ => {}
        }
    }
    let Some(section_line) = section_line else {
        return Err(parse(
            0,
            "no NODE_COORD_SECTION found: the file has no coordinates",
        ));
    };
    if let Some((n, line)) = dimension {
        if n != points.len() {
            return Err(parse(
                line,
                format!(
                    "DIMENSION is {n}, but NODE_COORD_SECTION (line {section_line}) has {} nodes",
                    points.len()
                ),
            ));
        }
    }
    Ok(points)
}

/// The JSON type name of `v`, for messages.
fn json_type(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

fn read_geojson(text: &str) -> Result<Vec<Point>> {
    if text.trim().is_empty() {
        return Ok(Vec::new());
    }
    let root: Value =
        serde_json::from_str(text).map_err(|e| parse(e.line(), format!("invalid JSON: {e}")))?;
    let mut found = GeoJsonPoints::default();
    // optri's own JSON output: {"points": [[x, y], ...], ...} without a type.
    if let Some(list) = root.get("points").filter(|_| root.get("type").is_none()) {
        collect_positions(list, "points", &mut found.points)?;
        return Ok(found.points);
    }
    collect_geojson(&root, "the document", &mut found)?;
    if found.points.is_empty() {
        let what = if found.skipped.is_empty() {
            "no geometries at all".to_string()
        } else {
            let counts: Vec<String> = found
                .skipped
                .iter()
                .map(|(kind, n)| format!("{n} {kind}"))
                .collect();
            format!("only {}", counts.join(", "))
        };
        return Err(parse(
            0,
            format!("GeoJSON: no Point or MultiPoint geometry found (the document has {what})"),
        ));
    }
    Ok(found.points)
}

/// What [`collect_geojson`] gathers: the points, and how many geometries of
/// each point-less type were skipped (in first-seen order, for the message
/// when nothing else is found).
#[derive(Default)]
struct GeoJsonPoints {
    points: Vec<Point>,
    skipped: Vec<(&'static str, usize)>,
}

/// Appends the points of a GeoJSON object; `at` describes where it is, for
/// messages (JSON values carry no line numbers, so errors name the path).
fn collect_geojson(v: &Value, at: &str, found: &mut GeoJsonPoints) -> Result<()> {
    /// Valid GeoJSON geometries that hold no points of their own.
    const POINTLESS: [&str; 4] = ["LineString", "MultiLineString", "Polygon", "MultiPolygon"];
    let bad = |m: String| Err(parse(0, format!("GeoJSON: {at}: {m}")));
    let Some(kind) = v.get("type").and_then(Value::as_str) else {
        return bad(format!(
            "expected an object with a \"type\", found {}",
            json_type(v)
        ));
    };
    let member = |name: &str| match v.get(name) {
        Some(x) => Ok(x),
        None => Err(parse(0, format!("GeoJSON: {at}: {kind} lacks \"{name}\""))),
    };
    match kind {
        "FeatureCollection" => {
            let Some(features) = member("features")?.as_array() else {
                return bad("\"features\" is not an array".into());
            };
            for (k, f) in features.iter().enumerate() {
                collect_geojson(f, &format!("features[{k}]"), found)?;
            }
        }
        "Feature" => match member("geometry")? {
            Value::Null => {}
            g => collect_geojson(g, &format!("{at}.geometry"), found)?,
        },
        "GeometryCollection" => {
            let Some(geometries) = member("geometries")?.as_array() else {
                return bad("\"geometries\" is not an array".into());
            };
            for (k, g) in geometries.iter().enumerate() {
                collect_geojson(g, &format!("{at}.geometries[{k}]"), found)?;
            }
        }
        "Point" => found.points.push(position(member("coordinates")?, at)?),
        "MultiPoint" => collect_positions(member("coordinates")?, at, &mut found.points)?,
        other => {
            // Skipping lines and polygons lets a triangulation's GeoJSON be
            // read back as its points; an unknown type is more likely a
            // typo, which must not silently drop points.
            let Some(&kind) = POINTLESS.iter().find(|&&k| k == other) else {
                return bad(format!(
                    "\"{other}\" is not a GeoJSON geometry type (points are read from Point \
                     and MultiPoint; LineString, Polygon and their Multi forms are skipped)"
                ));
            };
            match found.skipped.iter_mut().find(|(k, _)| *k == kind) {
                Some((_, n)) => *n += 1,
                None => found.skipped.push((kind, 1)),
            }
        }
    }
    Ok(())
}

fn collect_positions(list: &Value, at: &str, out: &mut Vec<Point>) -> Result<()> {
    let Some(list) = list.as_array() else {
        return Err(parse(
            0,
            format!(
                "GeoJSON: {at}: expected an array of positions, found {}",
                json_type(list)
            ),
        ));
    };
    for (k, p) in list.iter().enumerate() {
        out.push(position(p, &format!("{at}[{k}]"))?);
    }
    Ok(())
}

/// A GeoJSON position `[x, y]` or `[x, y, z]` (the third value is ignored).
fn position(v: &Value, at: &str) -> Result<Point> {
    let bad = || {
        parse(
            0,
            format!("GeoJSON: {at}: expected a position [x, y], found {v}"),
        )
    };
    let a = v.as_array().ok_or_else(bad)?;
    if !(2..=3).contains(&a.len()) {
        return Err(bad());
    }
    let mut p = [0.0; 2];
    for (k, c) in p.iter_mut().enumerate() {
        let value = a[k].as_f64().ok_or_else(bad)?;
        *c = check_coordinate(value, &a[k].to_string(), 0)
            .map_err(|e| parse(0, format!("GeoJSON: {at}: {e}")))?;
    }
    Ok(p)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line_of(e: Error) -> (usize, String) {
        match e {
            Error::Parse { line, message } => (line, message),
            other => panic!("expected a parse error, got {other:?}"),
        }
    }

    #[test]
    fn text_accepts_separators_comments_and_a_header() {
        let text = "x,y\n# a comment\n1 2\n\n3,4 # trailing\n5\t6\n7;8\n";
        assert_eq!(
            read_points(text, InputFormat::Text).unwrap(),
            vec![[1.0, 2.0], [3.0, 4.0], [5.0, 6.0], [7.0, 8.0]]
        );
        // Consistent extra columns are allowed; x, y are the first two.
        assert_eq!(
            read_points("1 2 9\n3 4 9\n", InputFormat::Text).unwrap(),
            vec![[1.0, 2.0], [3.0, 4.0]]
        );
        assert_eq!(
            read_points("\u{feff}-1e3 2.5E-2\r\n", InputFormat::Text).unwrap(),
            vec![[-1000.0, 0.025]]
        );
        // A header naming x and y picks those columns.
        assert_eq!(
            read_points("id;Y;X\n1;2;3\n2;5;6\n", InputFormat::Text).unwrap(),
            vec![[3.0, 2.0], [6.0, 5.0]]
        );
        let (line, m) = line_of(read_points("id,x,y\n1,2\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 2);
        assert!(m.contains("header on line 1"), "{m}");
    }

    #[test]
    fn text_errors_name_the_line_and_the_token() {
        let (line, m) = line_of(read_points("0 0\n1 1\n2 oops\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 3);
        assert!(m.contains("'oops'"), "{m}");
        let (line, m) = line_of(read_points("0 0\n1 1 1\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 2);
        assert!(m.contains("line 1"), "{m}");
        let (line, _) = line_of(read_points("0 0\n1 nan\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 2);
        let (line, m) = line_of(read_points("0 0\n\n-inf 1\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 3);
        assert!(m.contains("finite"), "{m}");
        // Overflowing literals become infinite and are rejected, as are values
        // outside the exact range.
        let (line, _) = line_of(read_points("1e400 0\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 1);
        let (line, m) = line_of(read_points("1 2\n1e100 0\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 2);
        assert!(m.contains("range"), "{m}");
        let (line, _) = line_of(read_points("1\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 1);
        // A header is only allowed at the top.
        let (line, _) = line_of(read_points("1 2\nx y\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 2);
        let (line, m) = line_of(read_points("# only\n\nx y\n", InputFormat::Text).unwrap_err());
        assert_eq!(line, 0);
        assert!(m.contains("no points"), "{m}");
        assert_eq!(
            line_of(read_points("", InputFormat::Text).unwrap_err()).0,
            0
        );
    }

    #[test]
    fn empty_fields_are_errors_but_whitespace_runs_are_one_separator() {
        for (text, bad_line) in [
            ("0,0\n1,,0\n0,1\n", 2),
            ("0,0\n1,0,\n0,1\n", 2),
            ("0;0\n1;0\n;0;1\n", 3),
            ("0 , 0\n1 , , 0\n", 2),
            ("x,,y\n0,0\n", 1),
        ] {
            let (line, m) = line_of(read_points(text, InputFormat::Text).unwrap_err());
            assert_eq!(line, bad_line, "{text:?}: {m}");
            assert!(m.contains("empty"), "{m}");
        }
        assert_eq!(
            read_points("0 \t 0\n\t1   0  \n0,\t1 # c,,\n", InputFormat::Text).unwrap(),
            vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]
        );
    }

    #[test]
    fn random_text_files_read_back_exactly_and_a_corruption_is_located() {
        use rand::{rngs::StdRng, Rng, SeedableRng};
        let mut rng = StdRng::seed_from_u64(11);
        for round in 0..200 {
            let n = rng.gen_range(1..30);
            let points: Vec<Point> = (0..n)
                .map(|_| {
                    let scale = [1.0, 1e-30, 1e40, 3.0][rng.gen_range(0..4)];
                    [
                        rng.gen_range(-1.0..1.0) * scale,
                        rng.gen_range(-5i32..5) as f64,
                    ]
                })
                .collect();
            let separators = [" ", "\t", ",", ";", " , ", "  "];
            let mut lines: Vec<String> = Vec::new();
            let mut data_lines = Vec::new();
            if rng.gen_bool(0.3) {
                lines.push("x y".into());
            }
            for p in &points {
                while rng.gen_bool(0.2) {
                    lines.push(["", "# comment 1 2", "   "][rng.gen_range(0..3)].into());
                }
                let sep = separators[rng.gen_range(0..separators.len())];
                let (x, y) = if rng.gen_bool(0.5) {
                    (format!("{}", p[0]), format!("{}", p[1]))
                } else {
                    (format!("{:e}", p[0]), format!("{:E}", p[1]))
                };
                let comment = if rng.gen_bool(0.2) { " # note" } else { "" };
                lines.push(format!("{x}{sep}{y}{comment}"));
                data_lines.push(lines.len());
            }
            let text = lines.join(if round % 2 == 0 { "\n" } else { "\r\n" });
            assert_eq!(
                read_points(&text, InputFormat::Text).unwrap(),
                points,
                "{text}"
            );
            // Corrupt one data line: the error names exactly that line.
            let k = rng.gen_range(0..data_lines.len());
            let bad = ["1.2.3", "nan", "-inf", "x1", "1e999", "0x10"][rng.gen_range(0..6)];
            let mut corrupted = lines.clone();
            corrupted[data_lines[k] - 1] = format!("{bad} 0");
            let (line, m) =
                line_of(read_points(&corrupted.join("\n"), InputFormat::Text).unwrap_err());
            assert_eq!(line, data_lines[k], "{m}");
            assert!(m.contains(bad), "{m}");
        }
    }

    #[test]
    fn node_files() {
        let text = "# comment\n4 2 1 1\n1 0 0 7 1\n2 1 0 7 1\n3 1 1 7 0\n4 0 1 7 1\n";
        assert_eq!(
            read_points(text, InputFormat::Node).unwrap(),
            vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
        );
        assert_eq!(
            read_points("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n", InputFormat::Node).unwrap(),
            vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]
        );
        let (line, _) = line_of(
            read_points("3 2 0 0\n0 0 0\n1 1 0 5\n2 0 1\n", InputFormat::Node).unwrap_err(),
        );
        assert_eq!(line, 3);
        let (line, m) =
            line_of(read_points("3 2 0 0\n0 0 0\n1 1 0\n", InputFormat::Node).unwrap_err());
        assert_eq!(line, 1);
        assert!(m.contains("3 vertices"), "{m}");
        let (line, _) =
            line_of(read_points("2 3 0 0\n0 0 0 0\n1 1 0 0\n", InputFormat::Node).unwrap_err());
        assert_eq!(line, 1);
        let (line, _) = line_of(read_points("2 2\n0 0 0\n5 1 0\n", InputFormat::Node).unwrap_err());
        assert_eq!(line, 3);
    }

    #[test]
    fn tsplib_headers_sections_and_errors() {
        let text = "NAME : t\nTYPE: TSP\nDIMENSION : 3\nEDGE_WEIGHT_TYPE : EUC_2D\n\
                    NODE_COORD_SECTION\n 1 0 0\n2 1.5e+01 0\n3 0 -2\nEOF\n\n";
        assert_eq!(
            read_points(text, InputFormat::Tsplib).unwrap(),
            vec![[0.0, 0.0], [15.0, 0.0], [0.0, -2.0]]
        );
        // No EOF line is fine (pr1002 has none).
        let text = "DIMENSION: 1\nNODE_COORD_SECTION\n1 4 5\n";
        assert_eq!(
            read_points(text, InputFormat::Tsplib).unwrap(),
            vec![[4.0, 5.0]]
        );
        let (line, m) = line_of(
            read_points(
                "DIMENSION: 3\nNODE_COORD_SECTION\n1 0 0\n2 1 1\nEOF\n",
                InputFormat::Tsplib,
            )
            .unwrap_err(),
        );
        assert_eq!(line, 1);
        assert!(m.contains("DIMENSION is 3"), "{m}");
        let (line, m) = line_of(
            read_points(
                "DIMENSION: 2\nEDGE_WEIGHT_TYPE: EXPLICIT\nEDGE_WEIGHT_SECTION\n0 1\n",
                InputFormat::Tsplib,
            )
            .unwrap_err(),
        );
        assert_eq!(line, 2);
        assert!(m.contains("EXPLICIT"), "{m}");
        let (line, _) = line_of(
            read_points("NODE_COORD_SECTION\n1 0 0\n2 x 1\n", InputFormat::Tsplib).unwrap_err(),
        );
        assert_eq!(line, 3);
        let (line, _) = line_of(read_points("NAME: x\n", InputFormat::Tsplib).unwrap_err());
        assert_eq!(line, 0);
    }

    #[test]
    fn every_shared_tsplib_file_reads_with_its_dimension() {
        // (file, DIMENSION) from shared/data/tsplib/README.md.
        let expected = [
            ("berlin52", 52),
            ("kroA100", 100),
            ("ch150", 150),
            ("a280", 280),
            ("lin318", 318),
            ("pr1002", 1002),
            ("u1060", 1060),
            ("vm1084", 1084),
            ("pcb3038", 3038),
            ("fl1577", 1577),
            ("fnl4461", 4461),
            ("att532", 532),
            ("ali535", 535),
            ("ts225", 225),
        ];
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/data/tsplib");
        for (name, n) in expected {
            let path = dir.join(format!("{name}.tsp"));
            let points = read_points_file(&path, None).unwrap();
            assert_eq!(points.len(), n, "{name}");
            assert_eq!(
                InputFormat::sniff(&std::fs::read_to_string(&path).unwrap()),
                InputFormat::Tsplib
            );
        }
        // Spot checks against the files' text.
        let a280 = read_points_file(&dir.join("a280.tsp"), None).unwrap();
        assert_eq!(a280[170], a280[171]);
        let ali = read_points_file(&dir.join("ali535.tsp"), None).unwrap();
        assert_eq!(ali[3], [5.15, -3.56]);
        let berlin = read_points_file(&dir.join("berlin52.tsp"), None).unwrap();
        assert_eq!(berlin[51], [1740.0, 245.0]);
    }

    #[test]
    fn geojson_points_and_errors() {
        let text = r#"{"type":"FeatureCollection","features":[
            {"type":"Feature","geometry":{"type":"Point","coordinates":[1,2]},"properties":{}},
            {"type":"Feature","geometry":{"type":"MultiPoint","coordinates":[[3,4],[5,6,7]]}},
            {"type":"Feature","geometry":null}]}"#;
        assert_eq!(
            read_points(text, InputFormat::GeoJson).unwrap(),
            vec![[1.0, 2.0], [3.0, 4.0], [5.0, 6.0]]
        );
        assert_eq!(
            read_points(
                r#"{"type":"Point","coordinates":[0.5,-1]}"#,
                InputFormat::GeoJson
            )
            .unwrap(),
            vec![[0.5, -1.0]]
        );
        // Lines and polygons are skipped; a document without any point names
        // what it holds instead.
        assert_eq!(
            read_points(
                r#"{"type":"GeometryCollection","geometries":[
                    {"type":"LineString","coordinates":[[0,0],[1,1]]},
                    {"type":"Point","coordinates":[2,3]}]}"#,
                InputFormat::GeoJson
            )
            .unwrap(),
            vec![[2.0, 3.0]]
        );
        let e = read_points(
            r#"{"type":"FeatureCollection","features":[
                {"type":"Feature","geometry":{"type":"LineString","coordinates":[[0,0],[1,1]]}},
                {"type":"Feature","geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[0,1],[0,0]]]}},
                {"type":"Feature","geometry":{"type":"LineString","coordinates":[[0,0],[1,1]]}}]}"#,
            InputFormat::GeoJson,
        )
        .unwrap_err()
        .to_string();
        assert!(
            e.contains("no Point or MultiPoint") && e.contains("2 LineString, 1 Polygon"),
            "{e}"
        );
        let e = read_points(
            r#"{"type":"FeatureCollection","features":[]}"#,
            InputFormat::GeoJson,
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("no geometries"), "{e}");
        let e = read_points(
            r#"{"type":"Piont","coordinates":[1,2]}"#,
            InputFormat::GeoJson,
        )
        .unwrap_err()
        .to_string();
        assert!(
            e.contains("\"Piont\" is not a GeoJSON geometry type"),
            "{e}"
        );
        let (line, _) = line_of(read_points("{\n\"type\":\n}", InputFormat::GeoJson).unwrap_err());
        assert_eq!(line, 3);
        let e = read_points(
            r#"{"type":"Point","coordinates":[1]}"#,
            InputFormat::GeoJson,
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("position"), "{e}");
        assert_eq!(
            read_points(
                r#"{"points":[[1,2],[3,4]],"triangles":[]}"#,
                InputFormat::GeoJson
            )
            .unwrap(),
            vec![[1.0, 2.0], [3.0, 4.0]]
        );
    }

    #[test]
    fn formats_by_extension_name_and_content() {
        assert_eq!(
            InputFormat::from_path(Path::new("a/b.CSV")),
            Some(InputFormat::Text)
        );
        assert_eq!(
            InputFormat::from_path(Path::new("b.node")),
            Some(InputFormat::Node)
        );
        assert_eq!(
            InputFormat::from_path(Path::new("b.tsp")),
            Some(InputFormat::Tsplib)
        );
        assert_eq!(
            InputFormat::from_path(Path::new("b.json")),
            Some(InputFormat::GeoJson)
        );
        assert_eq!(InputFormat::from_path(Path::new("b")), None);
        assert_eq!(InputFormat::from_name("tsp").unwrap(), InputFormat::Tsplib);
        let e = InputFormat::from_name("xml").unwrap_err().to_string();
        assert!(e.contains("geojson") && e.contains("node"), "{e}");
        assert_eq!(InputFormat::sniff(" {\"type\":1}"), InputFormat::GeoJson);
        assert_eq!(InputFormat::sniff("1 2\n3 4\n"), InputFormat::Text);
        let e = read_points_file(Path::new("/nonexistent/x.txt"), None).unwrap_err();
        assert!(
            matches!(&e, Error::Io(m) if m.contains("/nonexistent/x.txt")),
            "{e:?}"
        );
    }
}
