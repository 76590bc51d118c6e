//! The one writer entry point: [`write`](write()) puts a [`Document`] (a
//! triangulation, a graph or a comparison) into a file in the format of its
//! extension ([`OutputFormat`]), as [`WriteOptions`] say (the picture's
//! title, the JSON layout, the PLY encoding).

use super::{
    geojson, node, obj, off, ply, svg, Cells, ComparisonReport, DecisionReport, GraphReport, Mesh,
    OutputFormat, TriangulationReport,
};
use crate::error::{Error, Result};
use serde::Serialize;
use serde_json::Value;
use std::path::{Path, PathBuf};

/// One of the result documents of the JSON schema, as its report type.
#[derive(Clone, Copy, Debug)]
#[non_exhaustive]
pub enum Document<'a> {
    /// `"document": "triangulation"`.
    Triangulation(TriangulationReport<'a>),
    /// `"document": "comparison"`.
    Comparison(ComparisonReport<'a>),
    /// `"document": "graph"`.
    Graph(GraphReport<'a>),
    /// `"document": "decision"`.
    Decision(DecisionReport<'a>),
}

impl Document<'_> {
    /// The document as a JSON value.
    pub fn to_json(&self) -> Value {
        match self {
            Document::Triangulation(d) => d.to_json(),
            Document::Comparison(d) => d.to_json(),
            Document::Graph(d) => d.to_json(),
            Document::Decision(d) => d.to_json(),
        }
    }
}

impl Serialize for Document<'_> {
    fn serialize<S: serde::Serializer>(
        &self,
        serializer: S,
    ) -> std::result::Result<S::Ok, S::Error> {
        match self {
            Document::Triangulation(d) => d.serialize(serializer),
            Document::Comparison(d) => d.serialize(serializer),
            Document::Graph(d) => d.serialize(serializer),
            Document::Decision(d) => d.serialize(serializer),
        }
    }
}

impl<'a> From<TriangulationReport<'a>> for Document<'a> {
    fn from(report: TriangulationReport<'a>) -> Self {
        Document::Triangulation(report)
    }
}

impl<'a> From<GraphReport<'a>> for Document<'a> {
    fn from(report: GraphReport<'a>) -> Self {
        Document::Graph(report)
    }
}

impl<'a> From<DecisionReport<'a>> for Document<'a> {
    fn from(report: DecisionReport<'a>) -> Self {
        Document::Decision(report)
    }
}

impl<'a> From<ComparisonReport<'a>> for Document<'a> {
    fn from(report: ComparisonReport<'a>) -> Self {
        Document::Comparison(report)
    }
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

/// How `.ply` files are encoded.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum PlyEncoding {
    /// `binary_little_endian` (the default): the doubles and indices as
    /// stored, 24 bytes a vertex and 13 a triangle, nothing formatted or
    /// parsed.
    #[default]
    BinaryLittleEndian,
    /// `ascii`: the numbers in shortest round-trip notation.
    Ascii,
}

/// How [`write`](write()) writes.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct WriteOptions {
    /// The title of an SVG picture; `None` (the default): the file name. A
    /// comparison's panels are titled `title — criterion (exact)` or
    /// `(uncertified)`.
    pub title: Option<String>,
    /// The layout of JSON and GeoJSON files.
    pub style: JsonStyle,
    /// The encoding of PLY files.
    pub ply: PlyEncoding,
}

impl WriteOptions {
    /// These options with an SVG title.
    pub fn with_title(mut self, title: impl Into<String>) -> Self {
        self.title = Some(title.into());
        self
    }

    /// These options with JSON and GeoJSON laid out in `style`.
    pub fn with_style(mut self, style: JsonStyle) -> Self {
        self.style = style;
        self
    }

    /// These options with PLY files encoded as `encoding`.
    pub fn with_ply_encoding(mut self, encoding: PlyEncoding) -> Self {
        self.ply = encoding;
        self
    }
}

/// Writes `document` in the format of `path`'s extension ([`OutputFormat`]):
///
/// - `.json`: the whole document (with its run fields, e.g. from
///   [`TriangulationReport::of_solution`]), streamed, with a final newline;
/// - `.geojson`: a triangulation's triangles or a graph's edges, then the
///   points;
/// - `.svg`: a picture (a comparison: its triangulations side by side);
/// - `.ele` (triangulations) and `.edge` (triangulations and graphs):
///   Triangle's files, with the points in the `.node` beside them;
/// - `.obj`, `.ply` (triangulations and graphs) and `.off`
///   (triangulations): every input point as a vertex `x y z` (`z` its
///   elevation, 0 without), then the triangles or the edges; PLY in
///   binary little-endian unless [`WriteOptions::ply`] says ASCII.
///
/// Coordinates are the document's (the user's values, see
/// [`TriangulationReport::coordinates`]). Returns the files written (two for
/// `.ele` and `.edge`: that file and its sibling `.node`).
///
/// # Errors
/// [`Error::Io`] naming the path for an unknown extension, a format the
/// document has no form in (`.ele` and `.off` for a graph; anything but `.svg` and
/// `.json` for a comparison, or `.svg` when every criterion refused the
/// input; anything but `.json` for a decision without a witness), or when
/// writing fails.
///
/// # Panics
/// If a graph's edge refers to an index outside its points.
pub fn write<'a>(
    document: impl Into<Document<'a>>,
    path: &Path,
    options: &WriteOptions,
) -> Result<Vec<PathBuf>> {
    let title = match &options.title {
        Some(title) => title.clone(),
        None => path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default(),
    };
    match document.into() {
        Document::Triangulation(report) => write_triangulation(&report, path, &title, options),
        Document::Graph(report) => write_graph(&report, path, &title, options),
        Document::Comparison(report) => write_comparison(&report, path, &title, options),
        Document::Decision(report) => write_decision(&report, path, &title, options),
    }
}

fn write_triangulation(
    report: &TriangulationReport,
    path: &Path,
    title: &str,
    options: &WriteOptions,
) -> Result<Vec<PathBuf>> {
    let t = report.triangulation();
    let points = report.coordinates();
    let elevations = report.elevations();
    let elevations = elevations.as_deref();
    let format = OutputFormat::from_path(path)?;
    match format {
        OutputFormat::Json => write_json_file(path, report, options.style)?,
        OutputFormat::GeoJson => write_json_file(
            path,
            &geojson::TriangulationFeatures {
                points,
                elevations,
                triangles: t.triangles(),
                include_points: true,
            },
            options.style,
        )?,
        OutputFormat::Svg => write_file(path, &svg::report_to_svg(report, title))?,
        OutputFormat::Triangle => {
            let ele = node::ele_text(t.triangles());
            return write_triangle_files(format, path, &ele, points, elevations);
        }
        OutputFormat::TriangleEdges => {
            let edges = node::edge_text(&t.edges());
            return write_triangle_files(format, path, &edges, points, elevations);
        }
        OutputFormat::Obj | OutputFormat::Ply | OutputFormat::Off => {
            let cells = Cells::Triangles(t.triangles());
            let mesh = Mesh {
                points,
                elevations,
                cells,
            };
            write_mesh_file(format, path, &mesh, options)?
        }
    }
    Ok(vec![path.to_path_buf()])
}

fn write_graph(
    report: &GraphReport,
    path: &Path,
    title: &str,
    options: &WriteOptions,
) -> Result<Vec<PathBuf>> {
    let (points, edges) = (report.points(), report.edges());
    let elevations = report.elevations();
    let format = OutputFormat::from_path_for_graph(path)?;
    match format {
        OutputFormat::Json => write_json_file(path, report, options.style)?,
        OutputFormat::GeoJson => write_json_file(
            path,
            &geojson::GraphFeatures {
                points,
                elevations,
                edges,
            },
            options.style,
        )?,
        OutputFormat::TriangleEdges => {
            let text = node::edge_text(edges);
            return write_triangle_files(format, path, &text, points, elevations);
        }
        OutputFormat::Obj | OutputFormat::Ply => {
            let cells = Cells::Edges(edges);
            let mesh = Mesh {
                points,
                elevations,
                cells,
            };
            write_mesh_file(format, path, &mesh, options)?
        }
        // `.ele` (Triangle) and `.off` were refused by `from_path_for_graph`.
        OutputFormat::Svg | OutputFormat::Triangle | OutputFormat::Off => {
            write_file(path, &svg::graph_to_svg(points, edges, title))?
        }
    }
    Ok(vec![path.to_path_buf()])
}

/// A decision: its document as `.json`; any other format is its witness's
/// (a "no" or "unknown" answer has nothing to draw).
fn write_decision(
    report: &DecisionReport,
    path: &Path,
    title: &str,
    options: &WriteOptions,
) -> Result<Vec<PathBuf>> {
    if OutputFormat::from_path(path)? == OutputFormat::Json {
        write_json_file(path, report, options.style)?;
        return Ok(vec![path.to_path_buf()]);
    }
    match report.witness() {
        Some(witness) => write_triangulation(&witness, path, title, options),
        None => Err(write_error(
            path,
            &"the answer is not yes, there is no witness triangulation to write",
        )),
    }
}

fn write_comparison(
    report: &ComparisonReport,
    path: &Path,
    title: &str,
    options: &WriteOptions,
) -> Result<Vec<PathBuf>> {
    match OutputFormat::from_path(path)? {
        OutputFormat::Json => write_json_file(path, report, options.style)?,
        OutputFormat::Svg => {
            let titled: Vec<(String, &crate::Triangulation, Option<crate::Measure>)> = report
                .results()
                .iter()
                .filter_map(|(criterion, result)| {
                    let solution = result.as_ref().ok()?;
                    let exactness = if solution.exact {
                        "exact"
                    } else {
                        "uncertified"
                    };
                    let panel = format!("{title} — {} ({exactness})", criterion.name());
                    Some((panel, &solution.triangulation, criterion.info().measure))
                })
                .collect();
            if titled.is_empty() {
                return Err(write_error(
                    path,
                    &"every criterion refused the input, there is nothing to draw",
                ));
            }
            let panels: Vec<_> = titled
                .iter()
                .map(|(t, tri, measure)| (t.as_str(), *tri, *measure))
                .collect();
            write_file(path, &svg::criterion_panels_to_svg(&panels))?
        }
        _ => {
            return Err(write_error(
                path,
                &"a comparison is written as .svg (the panels side by side) or .json (the \
                  comparison document)",
            ))
        }
    }
    Ok(vec![path.to_path_buf()])
}

/// Writes Triangle's `first` file (`.ele` or `.edge`) at `path` and the
/// `.node` of `points` (with their `elevations`) beside it.
fn write_triangle_files(
    format: OutputFormat,
    path: &Path,
    first: &str,
    points: &[crate::kernel::Point],
    elevations: Option<&[f64]>,
) -> Result<Vec<PathBuf>> {
    let files = format.files_written(path);
    write_file(&files[0], first)?;
    write_file(&files[1], &node::node_text(points, elevations))?;
    Ok(files)
}

fn write_file(path: &Path, contents: &str) -> Result<()> {
    std::fs::write(path, contents).map_err(|e| write_error(path, &e))
}

fn write_error(path: &Path, e: &dyn std::fmt::Display) -> Error {
    Error::Io(format!("cannot write '{}': {e}", path.display()))
}

/// Writes the file at `path` as a stream: `contents` writes into a buffer
/// that goes to the file as it fills, so no whole-file text is held.
fn write_streamed(
    path: &Path,
    contents: impl FnOnce(&mut std::io::BufWriter<std::fs::File>) -> std::io::Result<()>,
) -> Result<()> {
    use std::io::Write;
    let file = std::fs::File::create(path).map_err(|e| write_error(path, &e))?;
    let mut out = std::io::BufWriter::with_capacity(1 << 16, file);
    contents(&mut out)
        .and_then(|()| out.flush())
        .map_err(|e| write_error(path, &e))
}

/// Serialises `document` straight into the file at `path` (no string or
/// value tree in between, so the memory is that of the document's own
/// data), with a final newline.
fn write_json_file(path: &Path, document: &impl Serialize, style: JsonStyle) -> Result<()> {
    use std::io::Write;
    write_streamed(path, |out| {
        match style {
            JsonStyle::Compact => serde_json::to_writer(&mut *out, document),
            JsonStyle::Pretty => serde_json::to_writer_pretty(&mut *out, document),
        }?;
        out.write_all(b"\n")
    })
}

/// Writes `mesh` at `path` in the mesh format `format` (OBJ, PLY or OFF).
fn write_mesh_file(
    format: OutputFormat,
    path: &Path,
    mesh: &Mesh,
    options: &WriteOptions,
) -> Result<()> {
    write_streamed(path, |out| match format {
        OutputFormat::Obj => obj::write(out, mesh),
        OutputFormat::Ply => ply::write(out, mesh, options.ply == PlyEncoding::Ascii),
        _ => off::write(out, mesh),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::{awkward_points, points_of, InputFormat};
    use crate::{compare, delaunay, Criterion, Options, PointSet};

    #[test]
    fn write_by_extension() {
        let dir = std::env::temp_dir().join(format!("optri-io-write-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let t = delaunay(&PointSet::new(&awkward_points()).unwrap()).unwrap();
        let report = TriangulationReport::new(&t);
        let options = WriteOptions::default();
        let written = write(report, &dir.join("t.ele"), &options).unwrap();
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
        assert_eq!(points_of(&node, InputFormat::Node).unwrap(), t.points());
        for name in ["t.json", "t.geojson", "t.SVG"] {
            write(report, &dir.join(name), &options).unwrap();
        }
        let svg = std::fs::read_to_string(dir.join("t.SVG")).unwrap();
        assert_eq!(svg.matches("<line class=\"edge\"").count(), t.edges().len());
        assert!(svg.contains(">t.SVG"), "the file name is the default title");
        write(
            report,
            &dir.join("titled.svg"),
            &options.clone().with_title("my <title>"),
        )
        .unwrap();
        let svg = std::fs::read_to_string(dir.join("titled.svg")).unwrap();
        assert!(svg.contains("my &lt;title&gt;"));
        let e = write(report, &dir.join("t.png"), &options)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("t.png") && e.contains(".svg") && e.contains(".ele"),
            "{e}"
        );
        let e = write(report, &dir.join("missing/t.json"), &options).unwrap_err();
        assert!(
            matches!(&e, Error::Io(m) if m.contains("missing/t.json")),
            "{e:?}"
        );
        // JSON in either style is the document, with a final newline.
        for style in [JsonStyle::Compact, JsonStyle::Pretty] {
            let path = dir.join("styled.json");
            write(report, &path, &options.clone().with_style(style)).unwrap();
            let text = std::fs::read_to_string(&path).unwrap();
            assert_eq!(text.lines().count() > 1, style == JsonStyle::Pretty);
            assert!(text.ends_with("}\n"));
            let value: Value = serde_json::from_str(&text).unwrap();
            assert_eq!(value, report.to_json());
        }
        let edges = t.edges();
        let graph = GraphReport::new(t.points(), &edges);
        write(graph, &dir.join("g.geojson"), &options).unwrap();
        let g: Value =
            serde_json::from_str(&std::fs::read_to_string(dir.join("g.geojson")).unwrap()).unwrap();
        assert_eq!(
            g["features"].as_array().unwrap().len(),
            edges.len() + t.points().len()
        );
        assert!(write(graph, &dir.join("g.ele"), &options).is_err());
        let written = write(graph, &dir.join("g.edge"), &options).unwrap();
        assert_eq!(written, vec![dir.join("g.edge"), dir.join("g.node")]);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_comparison_is_written_as_panels_or_its_document() {
        let dir = std::env::temp_dir().join(format!("optri-io-compare-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.5, 0.4]];
        let ps = PointSet::new(&square).unwrap();
        let results = compare(
            &ps,
            &[Criterion::Delaunay, Criterion::MinWeight],
            &Options::default(),
        );
        let report = ComparisonReport::new(&results);
        let options = WriteOptions::default().with_title("sq");
        write(report, &dir.join("c.svg"), &options).unwrap();
        let svg = std::fs::read_to_string(dir.join("c.svg")).unwrap();
        assert_eq!(svg.matches("<g class=\"panel\"").count(), 2);
        assert!(svg.contains("sq — delaunay (exact)"), "{svg}");
        // Each panel shades the worst triangle of its criterion's measure.
        let shaded = |svg: &str| -> Vec<String> {
            svg.split("data-triangle=\"")
                .skip(1)
                .map(|s| s.split('"').next().unwrap().to_string())
                .collect()
        };
        let criteria = [
            Criterion::MinMaxAngle,
            Criterion::MaxMinArea,
            Criterion::Greedy,
        ];
        let results = compare(&ps, &criteria, &Options::default());
        write(
            ComparisonReport::new(&results),
            &dir.join("w.svg"),
            &options,
        )
        .unwrap();
        let svg = std::fs::read_to_string(dir.join("w.svg")).unwrap();
        let expected: Vec<String> = results
            .iter()
            .map(|(c, r)| {
                let t = &r.as_ref().unwrap().triangulation;
                let m = match c {
                    Criterion::MinMaxAngle => crate::Measure::MaxAngle,
                    Criterion::MaxMinArea => crate::Measure::MinArea,
                    // Greedy optimises no measure: the smallest angle.
                    _ => crate::Measure::MinAngle,
                };
                let [a, b, c] = t.worst_triangle(m).unwrap();
                format!("{a},{b},{c}")
            })
            .collect();
        assert_eq!(shaded(&svg), expected);
        for legend in [
            "largest-angle triangle",
            "smallest triangle",
            "smallest-angle triangle",
        ] {
            assert!(svg.contains(&format!(">{legend}</text>")), "{legend}");
        }
        write(report, &dir.join("c.json"), &options).unwrap();
        let value: Value =
            serde_json::from_str(&std::fs::read_to_string(dir.join("c.json")).unwrap()).unwrap();
        assert_eq!(value, report.to_json());
        for name in ["c.geojson", "c.ele", "c.edge"] {
            let e = write(report, &dir.join(name), &options).unwrap_err();
            assert!(e.to_string().contains("a comparison"), "{e}");
        }
        // Every criterion refused (a metric only minmax-length reads): no panel.
        let l1 = Options::default().with_metric(crate::kernel::Metric::parse("l1").unwrap());
        let refused = compare(&ps, &[Criterion::Delaunay], &l1);
        assert!(refused[0].1.is_err());
        let e = write(
            ComparisonReport::new(&refused),
            &dir.join("r.svg"),
            &options,
        )
        .unwrap_err();
        assert!(e.to_string().contains("nothing to draw"), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
