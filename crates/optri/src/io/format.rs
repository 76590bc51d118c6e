//! Which file format: [`InputFormat`] (by extension, by name or by
//! content) and [`OutputFormat`] (by extension).

use crate::error::{Error, Result};
use std::path::{Path, PathBuf};

/// The supported input extensions, for messages.
const SUPPORTED_INPUTS: &str =
    ".txt .xy .csv .pts (text), .node, .poly (polygon), .tsp, .geojson .json";

/// The supported output extensions, for messages.
const SUPPORTED_OUTPUTS: &str =
    ".json, .svg, .ele or .edge (write the sibling .node too), .geojson";

/// `path`'s extension in lower case, if it has one.
fn lowercase_extension(path: &Path) -> Option<String> {
    Some(path.extension()?.to_str()?.to_ascii_lowercase())
}

/// The input formats optri reads: point files and, for
/// [`read_input`](super::read_input), polygon files.
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
    /// Triangle's `.poly` holding one simple polygon: a `.node` vertex
    /// section, a segment section whose segments form exactly one closed
    /// cycle through every vertex, and an empty (or no) hole section. Always
    /// a polygon input ([`Input::Polygon`](super::Input::Polygon)); read as
    /// points, it gives the ring's vertices in boundary order.
    Poly,
    /// TSPLIB `.tsp` with a `NODE_COORD_SECTION` (coordinates taken as they
    /// are, also for `GEO` and `ATT` instances).
    Tsplib,
    /// GeoJSON `Point`/`MultiPoint` geometries (bare, in a `Feature`, a
    /// `FeatureCollection` or a `GeometryCollection`); the other geometry
    /// types (`LineString`, `Polygon`, their `Multi` forms) are skipped, so
    /// optri's own GeoJSON output reads back as its points. A document with
    /// no `Point`/`MultiPoint` but one `Polygon` (or a `MultiPolygon` of one
    /// polygon, without holes) is a polygon input for
    /// [`read_input`](super::read_input): the outer ring. Also optri's own
    /// JSON documents (an object without `"type"`): their `"coordinates"`, or
    /// the `"points"` array of documents before schema version 1.
    GeoJson,
}

impl InputFormat {
    /// Every format, for listings.
    pub const ALL: &'static [InputFormat] = &[
        InputFormat::Text,
        InputFormat::Node,
        InputFormat::Poly,
        InputFormat::Tsplib,
        InputFormat::GeoJson,
    ];

    /// The name accepted by [`from_name`](Self::from_name).
    pub fn name(self) -> &'static str {
        match self {
            InputFormat::Text => "text",
            InputFormat::Node => "node",
            InputFormat::Poly => "poly",
            InputFormat::Tsplib => "tsplib",
            InputFormat::GeoJson => "geojson",
        }
    }

    /// The format implied by `path`'s extension (case-insensitive):
    /// `.txt .xy .csv .pts` → Text, `.node` → Node, `.poly` → Poly, `.tsp` → Tsplib,
    /// `.geojson .json` → GeoJson.
    ///
    /// # Errors
    /// [`Error::Io`] naming the path and listing the supported extensions
    /// (as [`OutputFormat::from_path`]); [`read_points_file`] then guesses
    /// the format from the content instead ([`sniff`](Self::sniff)).
    ///
    /// [`read_points_file`]: super::read_points_file
    pub fn from_path(path: &Path) -> Result<Self> {
        match lowercase_extension(path).as_deref() {
            Some("txt" | "xy" | "csv" | "pts") => Ok(InputFormat::Text),
            Some("node") => Ok(InputFormat::Node),
            Some("poly") => Ok(InputFormat::Poly),
            Some("tsp") => Ok(InputFormat::Tsplib),
            Some("geojson" | "json") => Ok(InputFormat::GeoJson),
            _ => Err(Error::Io(format!(
                "cannot read '{}' by its extension: unknown input extension; supported: \
                 {SUPPORTED_INPUTS}",
                path.display()
            ))),
        }
    }

    /// Looks a format up by name (`text`, `node`, `poly`, `tsplib`, `geojson`; also
    /// the aliases `txt`, `tsp`, `json`).
    ///
    /// # Errors
    /// [`Error::UnknownName`] listing the available names.
    pub fn from_name(name: &str) -> Result<Self> {
        match name.to_ascii_lowercase().as_str() {
            "text" | "txt" | "xy" | "csv" => Ok(InputFormat::Text),
            "node" => Ok(InputFormat::Node),
            "poly" => Ok(InputFormat::Poly),
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
    /// (`NAME`, `TYPE`, `DIMENSION`, `NODE_COORD_SECTION`) means TSPLIB, a
    /// Triangle vertex section (a header `n 2 [attributes [marker]]` of
    /// integers followed by at least `n` vertex lines numbered from 0 or 1
    /// with the header's column count) means `.node`, or `.poly` when more
    /// lines follow the vertices (the segments); anything else is read as
    /// text.
    pub fn sniff(text: &str) -> Self {
        let trimmed = text.trim_start_matches('\u{feff}').trim_start();
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
        sniff_triangle(text).unwrap_or(InputFormat::Text)
    }
}

/// `.node` or `.poly` if `text` starts with a Triangle vertex section (see
/// [`InputFormat::sniff`]).
fn sniff_triangle(text: &str) -> Option<InputFormat> {
    let mut lines = super::node::token_lines(text).map(|(_, tokens)| tokens);
    let header = lines.next()?;
    let numbers: Vec<usize> = header
        .iter()
        .map(|t| t.parse().ok())
        .collect::<Option<_>>()?;
    if !(2..=4).contains(&numbers.len()) || numbers[1] != 2 {
        return None;
    }
    let columns = 3 + numbers.get(2).copied().unwrap_or(0) + numbers.get(3).copied().unwrap_or(0);
    let mut base = None;
    for k in 0..numbers[0] {
        let tokens = lines.next()?;
        let id: usize = tokens.first()?.parse().ok()?;
        let base = *base.get_or_insert(id);
        if tokens.len() != columns || base > 1 || id != base + k {
            return None;
        }
    }
    Some(if lines.next().is_some() {
        InputFormat::Poly
    } else {
        InputFormat::Node
    })
}

/// The file formats optri writes, chosen by extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum OutputFormat {
    /// `.json`: [`triangulation_to_json`](super::triangulation_to_json) /
    /// [`graph_to_json`](super::graph_to_json).
    Json,
    /// `.svg`: a picture.
    Svg,
    /// `.ele` plus a sibling `.node` (Triangle's format; triangulations only).
    Triangle,
    /// `.edge` plus a sibling `.node` (Triangle's format): the edges of a
    /// graph or a triangulation.
    TriangleEdges,
    /// `.geojson`: [`triangulation_to_geojson`](super::triangulation_to_geojson) /
    /// [`graph_to_geojson`](super::graph_to_geojson).
    GeoJson,
}

impl OutputFormat {
    /// The format for `path`'s extension (case-insensitive).
    ///
    /// # Errors
    /// [`Error::Io`] naming the path and listing the supported extensions
    /// (as [`InputFormat::from_path`]).
    pub fn from_path(path: &Path) -> Result<Self> {
        match lowercase_extension(path).as_deref() {
            Some("json") => Ok(OutputFormat::Json),
            Some("svg") => Ok(OutputFormat::Svg),
            Some("ele") => Ok(OutputFormat::Triangle),
            Some("edge") => Ok(OutputFormat::TriangleEdges),
            Some("geojson") => Ok(OutputFormat::GeoJson),
            _ => Err(Error::Io(format!(
                "cannot write '{}': unknown output extension; supported: {SUPPORTED_OUTPUTS}",
                path.display()
            ))),
        }
    }

    /// The format for writing a graph to `path`: [`from_path`](Self::from_path),
    /// except that `.ele` is refused (a graph is not a triangulation).
    ///
    /// # Errors
    /// As [`from_path`](Self::from_path), and [`Error::Io`] for `.ele`.
    pub fn from_path_for_graph(path: &Path) -> Result<Self> {
        match Self::from_path(path)? {
            OutputFormat::Triangle => Err(Error::Io(format!(
                "cannot write '{}': a graph is not a triangulation; use .svg, .json, .geojson \
                 or .edge",
                path.display()
            ))),
            format => Ok(format),
        }
    }

    /// Every file that writing a triangulation to `path` in this format
    /// creates or overwrites: `path` itself and, for [`OutputFormat::Triangle`],
    /// the sibling `.node` (so callers can refuse to overwrite their input).
    pub fn files_written(self, path: &Path) -> Vec<PathBuf> {
        match self {
            OutputFormat::Triangle | OutputFormat::TriangleEdges => {
                vec![path.to_path_buf(), path.with_extension("node")]
            }
            _ => vec![path.to_path_buf()],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::read_points_file;

    #[test]
    fn formats_by_extension_name_and_content() {
        for (path, format) in [
            ("a/b.CSV", InputFormat::Text),
            ("b.node", InputFormat::Node),
            ("b.POLY", InputFormat::Poly),
            ("b.tsp", InputFormat::Tsplib),
            ("b.json", InputFormat::GeoJson),
        ] {
            assert_eq!(InputFormat::from_path(Path::new(path)).unwrap(), format);
        }
        // Unknown or missing extensions are errors on both sides, naming the
        // path and what is supported.
        for path in ["b", "b.dat"] {
            let e = InputFormat::from_path(Path::new(path)).unwrap_err();
            assert!(
                matches!(&e, Error::Io(m) if m.contains(&format!("'{path}'")) && m.contains(".tsp")),
                "{e:?}"
            );
            let e = OutputFormat::from_path(Path::new(path)).unwrap_err();
            assert!(
                matches!(&e, Error::Io(m) if m.contains(&format!("'{path}'")) && m.contains(".svg")),
                "{e:?}"
            );
        }
        assert_eq!(
            OutputFormat::from_path_for_graph(Path::new("g.SVG")).unwrap(),
            OutputFormat::Svg
        );
        let e = OutputFormat::from_path_for_graph(Path::new("g.ele"))
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("g.ele") && e.contains("not a triangulation"),
            "{e}"
        );
        assert_eq!(InputFormat::from_name("tsp").unwrap(), InputFormat::Tsplib);
        let e = InputFormat::from_name("xml").unwrap_err().to_string();
        assert!(e.contains("geojson") && e.contains("node"), "{e}");
        assert_eq!(InputFormat::sniff(" {\"type\":1}"), InputFormat::GeoJson);
        assert_eq!(InputFormat::sniff("1 2\n3 4\n"), InputFormat::Text);
        // Triangle files by their vertex section; an `x y z` cloud whose
        // first row looks like a header is still text.
        assert_eq!(
            InputFormat::sniff("# c\n3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n"),
            InputFormat::Node
        );
        assert_eq!(
            InputFormat::sniff("3 2\n0 0 0\n1 1 0\n2 0 1\n3 0\n0 0 1\n1 1 2\n2 2 0\n"),
            InputFormat::Poly
        );
        assert_eq!(
            InputFormat::sniff("3 2 0\n1 0 0\n5 1 0\n3 0 1\n"),
            InputFormat::Text
        );
        assert_eq!(InputFormat::sniff("3 2\n1 0\n2 1\n"), InputFormat::Text);
        let e = read_points_file(Path::new("/nonexistent/x.txt"), None).unwrap_err();
        assert!(
            matches!(&e, Error::Io(m) if m.contains("/nonexistent/x.txt")),
            "{e:?}"
        );
    }
}
