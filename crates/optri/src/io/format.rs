//! Which file format: [`InputFormat`] (by extension, by name or by
//! content) and [`OutputFormat`] (by extension).

use crate::error::{Error, Result};
use std::path::{Path, PathBuf};

/// The supported input extensions, for messages.
const SUPPORTED_INPUTS: &str =
    ".txt .xy .csv .pts (text), .node, .poly (polygon), .tsp, .geojson .json, .ply, .obj";

/// The supported output extensions, for messages.
const SUPPORTED_OUTPUTS: &str =
    ".json, .svg, .ele or .edge (write the sibling .node too), .geojson, .obj, .ply, .off";

/// `path`'s extension in lower case, if it has one.
fn lowercase_extension(path: &Path) -> Option<String> {
    Some(path.extension()?.to_str()?.to_ascii_lowercase())
}

/// The input formats optri reads: point files and polygon files (see
/// [`read`](super::read)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum InputFormat {
    /// One point per line, `x y` (separated by spaces, tabs, commas or
    /// semicolons); `#` starts a comment. A line with a comma or semicolon
    /// is split at those only (outside double quotes; fields are trimmed and
    /// lose their surrounding double quotes), so a name may hold spaces, and
    /// an empty field (`1,,0`, or a separator at the start or end of a
    /// line) is never a silently shifted column; a line without is split at
    /// runs of spaces and tabs. Every row has the same number of fields.
    ///
    /// The first line may be a header (no field a number) naming the
    /// coordinate columns with one pair of `x`/`y`, `lon`/`lat`,
    /// `lng`/`lat`, `long`/`lat`, `longitude`/`latitude` or
    /// `easting`/`northing` (case-insensitive, optionally quoted; x is the
    /// longitude or easting): those columns are read, and the others are
    /// skipped with a warning naming them (they may hold anything, e.g.
    /// names). A header without such a pair, or with two, is an error.
    /// Without a header every field must be a number and x, y are the first
    /// two (a warning names the columns ignored).
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
    /// polygon, without holes) is a polygon input for [`read`](super::read)
    /// with polygons allowed: the outer ring. Also optri's own JSON
    /// documents (an object without `"type"`): their `"coordinates"`, or the
    /// `"points"` array of documents before schema version 1.
    GeoJson,
    /// PLY (the Stanford polygon format), ASCII or binary of either byte
    /// order: the `vertex` element's `x`, `y` and optional `z` properties,
    /// of any numeric type; every other element and property (faces,
    /// normals, colours, list properties) is skipped.
    Ply,
    /// Wavefront `.obj`: the `v x y [z …]` statements; every other
    /// statement (`vt`, `vn`, `f`, `l`, groups, materials) is skipped.
    Obj,
}

impl InputFormat {
    /// Every format, for listings.
    pub const ALL: &'static [InputFormat] = &[
        InputFormat::Text,
        InputFormat::Node,
        InputFormat::Poly,
        InputFormat::Tsplib,
        InputFormat::GeoJson,
        InputFormat::Ply,
        InputFormat::Obj,
    ];

    /// The name accepted by [`from_name`](Self::from_name).
    pub fn name(self) -> &'static str {
        match self {
            InputFormat::Text => "text",
            InputFormat::Node => "node",
            InputFormat::Poly => "poly",
            InputFormat::Tsplib => "tsplib",
            InputFormat::GeoJson => "geojson",
            InputFormat::Ply => "ply",
            InputFormat::Obj => "obj",
        }
    }

    /// The format implied by `path`'s extension (case-insensitive):
    /// `.txt .xy .csv .pts` → Text, `.node` → Node, `.poly` → Poly, `.tsp` → Tsplib,
    /// `.geojson .json` → GeoJson, `.ply` → Ply, `.obj` → Obj.
    ///
    /// # Errors
    /// [`Error::Io`] naming the path and listing the supported extensions
    /// (as [`OutputFormat::from_path`]); [`read`](super::read) then picks
    /// the format by content instead ([`sniff`](Self::sniff)).
    pub fn from_path(path: &Path) -> Result<Self> {
        match lowercase_extension(path).as_deref() {
            Some("txt" | "xy" | "csv" | "pts") => Ok(InputFormat::Text),
            Some("node") => Ok(InputFormat::Node),
            Some("poly") => Ok(InputFormat::Poly),
            Some("tsp") => Ok(InputFormat::Tsplib),
            Some("geojson" | "json") => Ok(InputFormat::GeoJson),
            Some("ply") => Ok(InputFormat::Ply),
            Some("obj") => Ok(InputFormat::Obj),
            _ => Err(Error::Io(format!(
                "cannot read '{}' by its extension: unknown input extension; supported: \
                 {SUPPORTED_INPUTS}",
                path.display()
            ))),
        }
    }

    /// Looks a format up by name (`text`, `node`, `poly`, `tsplib`, `geojson`,
    /// `ply`, `obj`; also
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
            "ply" => Ok(InputFormat::Ply),
            "obj" => Ok(InputFormat::Obj),
            _ => Err(Error::UnknownName {
                kind: "input format",
                name: name.to_string(),
                available: Self::ALL.iter().map(|f| f.name()).collect(),
            }),
        }
    }

    /// Picks the format by content (for stdin and files without a known
    /// extension), on evidence that no other format could be meant: a
    /// first line `ply` means PLY (its magic line; OBJ has none and is read
    /// only by extension or name); a leading `{` means GeoJSON; a line `NODE_COORD_SECTION`, or a first
    /// line `NAME`, `TYPE`, `DIMENSION` or `COMMENT` followed by `:`, means
    /// TSPLIB; Triangle's `.node` and `.poly` are recognised only when the
    /// whole file has their structure (counts, ids and columns as the
    /// headers announce) and could not also be a table of numbers; anything
    /// else is text. A point cloud whose first row reads as a `.node`
    /// header (`3 2 0` over rows `1 0 0`, `2 1 0`, `3 0 1`) is therefore
    /// text; so is a `.node` whose header has as many fields as its vertex
    /// lines (`n 2 0 1` over `id x y marker`), or one that breaks its own
    /// counts: name the format (or use the extension) to read those.
    pub fn sniff(text: &str) -> Self {
        let text = text.trim_start_matches('\u{feff}');
        if super::ply::has_magic(text.as_bytes()) {
            return InputFormat::Ply;
        }
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
        triangle_structure(text).unwrap_or(InputFormat::Text)
    }
}

/// `.node` or `.poly` if the whole of `text` has that structure, on which
/// the counts of the headers decide (the values are left to the readers,
/// which name the line of a bad one):
///
/// - a vertex section: a header `n 2 [attributes [marker]]` of integers
///   with `n ≥ 1` and a marker flag of 0 or 1, then exactly `n` lines of
///   `3 + attributes + marker` fields whose first is the id, counting up
///   from 0 or 1;
/// - for `.node`, nothing after it, and a header whose field count differs
///   from the vertex lines' (otherwise the file is also a table of numbers,
///   e.g. the cloud `3 2 0 / 1 0 0 / 2 1 0 / 3 0 1`, and is read as text);
/// - for `.poly`, then a segment section: a header `m [marker]` with
///   `m ≥ 1`, then exactly `m` lines `id a b [marker]` with ids counting up
///   from the vertices' first id and endpoints that are vertex ids, then
///   nothing or a hole count (what follows it is left to the reader).
fn triangle_structure(text: &str) -> Option<InputFormat> {
    let mut lines = super::node::token_lines(text).map(|(_, tokens)| tokens);
    let integers =
        |tokens: &[&str]| -> Option<Vec<usize>> { tokens.iter().map(|t| t.parse().ok()).collect() };
    let header = lines.next()?;
    let counts = integers(&header)?;
    if !(2..=4).contains(&counts.len()) || counts[0] == 0 || counts[1] != 2 {
        return None;
    }
    let (vertices, attributes) = (counts[0], counts.get(2).copied().unwrap_or(0));
    let marker = counts.get(3).copied().unwrap_or(0);
    if marker > 1 {
        return None;
    }
    let columns = attributes.checked_add(3 + marker)?;
    let mut first_id = None;
    for k in 0..vertices {
        let tokens = lines.next()?;
        let id: usize = tokens.first()?.parse().ok()?;
        let base = *first_id.get_or_insert(id);
        if tokens.len() != columns || base > 1 || id != base + k {
            return None;
        }
    }
    let base = first_id?;
    let Some(segment_header) = lines.next() else {
        return (header.len() != columns).then_some(InputFormat::Node);
    };
    let counts = integers(&segment_header)?;
    let (segments, marker) = match counts[..] {
        [m] => (m, 0),
        [m, marker @ (0 | 1)] => (m, marker),
        _ => return None,
    };
    if segments == 0 {
        return None;
    }
    let vertex_ids = base..base + vertices;
    for k in 0..segments {
        let segment = lines.next()?;
        if segment.len() != 3 + marker {
            return None;
        }
        let ids = integers(&segment[..3])?;
        if ids[0] != base + k || !ids[1..].iter().all(|v| vertex_ids.contains(v)) {
            return None;
        }
    }
    match lines.next() {
        None => Some(InputFormat::Poly),
        Some(holes) => (integers(&holes)?.len() == 1).then_some(InputFormat::Poly),
    }
}

/// The file formats optri writes, chosen by extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum OutputFormat {
    /// `.json`: the whole [`Document`](super::Document).
    Json,
    /// `.svg`: a picture.
    Svg,
    /// `.ele` plus a sibling `.node` (Triangle's format; triangulations only).
    Triangle,
    /// `.edge` plus a sibling `.node` (Triangle's format): the edges of a
    /// graph or a triangulation.
    TriangleEdges,
    /// `.geojson`: a triangulation's triangles or a graph's edges as
    /// features, then the points.
    GeoJson,
    /// `.obj` (Wavefront): the points as `v x y z`, then a triangulation's
    /// faces `f a b c` or a graph's lines `l a b`, 1-based.
    Obj,
    /// `.ply`: an element `vertex` (`x y z`), then `face` (a triangulation)
    /// or `edge` (a graph); binary little-endian unless
    /// [`WriteOptions::ply`](super::WriteOptions::ply) asks for ASCII.
    Ply,
    /// `.off` (Object File Format): the points as `x y z`, then the faces
    /// `3 a b c` (triangulations only: OFF has no edges).
    Off,
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
            Some("obj") => Ok(OutputFormat::Obj),
            Some("ply") => Ok(OutputFormat::Ply),
            Some("off") => Ok(OutputFormat::Off),
            _ => Err(Error::Io(format!(
                "cannot write '{}': unknown output extension; supported: {SUPPORTED_OUTPUTS}",
                path.display()
            ))),
        }
    }

    /// The format for writing a graph to `path`: [`from_path`](Self::from_path),
    /// except that `.ele` and `.off` are refused (a graph is not a
    /// triangulation, and OFF holds faces only).
    ///
    /// # Errors
    /// As [`from_path`](Self::from_path), and [`Error::Io`] for `.ele` and
    /// `.off`.
    pub fn from_path_for_graph(path: &Path) -> Result<Self> {
        const GRAPH_OUTPUTS: &str = "use .svg, .json, .geojson, .edge, .obj or .ply";
        match Self::from_path(path)? {
            OutputFormat::Triangle => Err(Error::Io(format!(
                "cannot write '{}': a graph is not a triangulation; {GRAPH_OUTPUTS}",
                path.display()
            ))),
            OutputFormat::Off => Err(Error::Io(format!(
                "cannot write '{}': OFF holds faces, not a graph's edges; {GRAPH_OUTPUTS}",
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
    use crate::io::{read, ReadOptions, Source};

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
    }

    /// The points `text` reads as with the format picked by content.
    fn sniffed_points(text: &str) -> Vec<[f64; 2]> {
        read(Source::Text(text), &ReadOptions::default())
            .unwrap()
            .input
            .points()
            .to_vec()
    }

    #[test]
    fn triangle_files_are_recognised_only_by_their_whole_structure() {
        // A cloud of three numbers per line whose first row reads as a
        // `.node` header with an attribute count: also a table, so text.
        let cloud = "3 2 0\n1 0 0\n2 1 0\n3 0 1\n";
        assert_eq!(InputFormat::sniff(cloud), InputFormat::Text);
        assert_eq!(
            sniffed_points(cloud),
            [[3.0, 2.0], [1.0, 0.0], [2.0, 1.0], [3.0, 0.0]]
        );
        // A first row `0 2` is a point, not an empty `.poly`.
        let zero = "0 2\n1 3\n5 6\n";
        assert_eq!(InputFormat::sniff(zero), InputFormat::Text);
        assert_eq!(sniffed_points(zero), [[0.0, 2.0], [1.0, 3.0], [5.0, 6.0]]);
        // Real Triangle files: a header whose field count differs from the
        // vertex lines', ids in sequence, the announced columns.
        for node in [
            "# c\n3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n",
            "3 2\n0 0 0\n1 1 0\n2 0 1\n",
            "3 2 1 1\n0 0 0 7 1\n1 1 0 7 0\n2 0 1 7 1\n",
        ] {
            assert_eq!(InputFormat::sniff(node), InputFormat::Node, "{node}");
            assert_eq!(sniffed_points(node), [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
        }
        let poly = "3 2 0\n0 0 0\n1 1 0\n2 0 1\n3 0\n0 0 1\n1 1 2\n2 2 0\n";
        for poly in [
            poly.to_string(),
            format!("{poly}0\n"),
            "3 2\n1 0 0\n2 1 0\n3 0 1\n3 1\n1 1 2 5\n2 2 3 5\n3 3 1 5\n0\n".to_string(),
        ] {
            assert_eq!(InputFormat::sniff(&poly), InputFormat::Poly, "{poly}");
            assert_eq!(sniffed_points(&poly), [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
        }
        // Near misses are text: one vertex line too few or too many, an id
        // out of sequence or from 2, a column too many, a marker flag of 2,
        // dimension 3, a header whose fields are not integers; a segment
        // section with a wrong count, id, endpoint or column count, or
        // followed by more than a hole count.
        for near in [
            "3 2 0 0\n1 0 0\n2 1 0\n",
            "2 2 0 0\n1 0 0\n2 1 0\n3 0 1\n",
            "3 2 0 0\n1 0 0\n3 1 0\n2 0 1\n",
            "3 2 0 0\n2 0 0\n3 1 0\n4 0 1\n",
            "3 2 0 0\n1 0 0 9\n2 1 0 9\n3 0 1 9\n",
            "3 2 0 2\n1 0 0 1 \n2 1 0 1\n3 0 1 1\n",
            "3 3 0 0\n1 0 0\n2 1 0\n3 0 1\n",
            "3 2.0 0 0\n1 0 0\n2 1 0\n3 0 1\n",
            "3 2\n0 0 0\n1 1 0\n2 0 1\n0 0\n",
            "3 2\n0 0 0\n1 1 0\n2 0 1\n3 0\n0 0 1\n1 1 2\n",
            "3 2\n0 0 0\n1 1 0\n2 0 1\n3 0\n0 0 1\n2 1 2\n2 2 0\n",
            "3 2\n0 0 0\n1 1 0\n2 0 1\n3 0\n0 0 1\n1 1 3\n2 2 0\n",
            "3 2\n0 0 0\n1 1 0\n2 0 1\n3 0\n0 0 1 1\n1 1 2 1\n2 2 0 1\n",
            "3 2\n0 0 0\n1 1 0\n2 0 1\n3 0\n0 0 1\n1 1 2\n2 2 0\n0 1\n",
        ] {
            assert_eq!(InputFormat::sniff(near), InputFormat::Text, "{near}");
        }
        // A `.node` with markers and no attributes has as many fields in
        // its header as in its vertex lines: it is also a table of four
        // columns, so it is text unless named (or by its extension).
        let markers = "3 2 0 1\n1 0 0 1\n2 1 0 1\n3 0 1 0\n";
        assert_eq!(InputFormat::sniff(markers), InputFormat::Text);
        assert_eq!(sniffed_points(markers).len(), 4);
        // Named, the format is read as named.
        let node = read(
            Source::Text(cloud),
            &ReadOptions::default().with_format(InputFormat::Node),
        )
        .unwrap();
        assert_eq!(node.input.points(), [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
    }
}
