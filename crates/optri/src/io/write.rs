//! Writers for triangulations and graphs: JSON, GeoJSON, Triangle
//! `.node`/`.ele`, SVG; and [`write_triangulation`] / [`write_graph`], which
//! pick the format by file extension.
//!
//! Indices are always *input* indices (0-based), also in Triangle files, and
//! all input points are written (merged duplicates included, they just belong
//! to no triangle), so every index in an output means the same point as in the
//! input. Coordinates are written in Rust's shortest round-trip notation, so
//! reading an output back gives the identical `f64` values.

use super::svg::{graph_to_svg, triangulation_to_svg};
use crate::error::{Error, Result};
use crate::kernel::Point;
use crate::structures::PointSet;
use crate::structures::Triangulation;
use serde_json::{json, Value};
use std::fmt::Write;
use std::path::{Path, PathBuf};

/// The file formats optri writes, chosen by extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum OutputFormat {
    /// `.json`: [`triangulation_to_json`] / [`graph_to_json`].
    Json,
    /// `.svg`: a picture.
    Svg,
    /// `.ele` plus a sibling `.node` (Triangle's format; triangulations only).
    Triangle,
    /// `.geojson`: [`triangulation_to_geojson`] / [`graph_to_geojson`].
    GeoJson,
}

/// The supported output extensions, for messages.
const SUPPORTED_OUTPUTS: &str = ".json, .svg, .ele (writes the sibling .node too), .geojson";

impl OutputFormat {
    /// The format for `path`'s extension (case-insensitive).
    ///
    /// # Errors
    /// [`Error::Unsupported`] naming the path and listing the supported
    /// extensions.
    pub fn from_path(path: &Path) -> Result<Self> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("json") => Ok(OutputFormat::Json),
            Some("svg") => Ok(OutputFormat::Svg),
            Some("ele") => Ok(OutputFormat::Triangle),
            Some("geojson") => Ok(OutputFormat::GeoJson),
            _ => Err(Error::Io(format!(
                "cannot write '{}': unknown output extension; supported: {SUPPORTED_OUTPUTS}",
                path.display()
            ))),
        }
    }

    /// Every file that writing a triangulation to `path` in this format
    /// creates or overwrites: `path` itself and, for [`OutputFormat::Triangle`],
    /// the sibling `.node` (so callers can refuse to overwrite their input).
    pub fn files_written(self, path: &Path) -> Vec<PathBuf> {
        match self {
            OutputFormat::Triangle => vec![path.to_path_buf(), path.with_extension("node")],
            _ => vec![path.to_path_buf()],
        }
    }
}

/// `{"points": [[x, y], …], "triangles": [[i, j, k], …], "edges": [[a, b], …],
/// "duplicates": [[dropped, kept], …]}` with input indices; triangles are
/// counter-clockwise.
pub fn triangulation_to_json(t: &Triangulation) -> Value {
    json!({
        "points": t.points(),
        "triangles": t.triangles(),
        "edges": t.edges(),
        "duplicates": t.point_set().duplicates(),
    })
}

/// Reads back the output of [`triangulation_to_json`], validating it.
///
/// # Errors
/// [`Error::Parse`] (line 0) for a malformed object; the errors of
/// [`PointSet::new`] and [`Triangulation::from_triangles`].
pub fn triangulation_from_json(value: &Value) -> Result<Triangulation> {
    let bad = |m: &str| Error::Parse {
        line: 0,
        message: format!("triangulation JSON: {m}"),
    };
    let points: Vec<Point> = serde_json::from_value(
        value
            .get("points")
            .cloned()
            .ok_or_else(|| bad("no \"points\""))?,
    )
    .map_err(|e| bad(&format!("\"points\": {e}")))?;
    let triangles: Vec<[u32; 3]> = serde_json::from_value(
        value
            .get("triangles")
            .cloned()
            .ok_or_else(|| bad("no \"triangles\""))?,
    )
    .map_err(|e| bad(&format!("\"triangles\": {e}")))?;
    let point_set = PointSet::new(&points)?;
    if let Some(i) = triangles
        .iter()
        .flatten()
        .find(|&&i| i as usize >= points.len())
    {
        return Err(bad(&format!("triangle index {i} out of range")));
    }
    Triangulation::from_triangles(&point_set, triangles)
}

/// A GeoJSON `FeatureCollection` with one `Polygon` per triangle (properties:
/// `triangle` number and its input-index `vertices`) and, if
/// `include_points`, one `Point` per input point (property `index`).
pub fn triangulation_to_geojson(t: &Triangulation, include_points: bool) -> Value {
    let pts = t.points();
    let mut features: Vec<Value> = t
        .triangles()
        .iter()
        .enumerate()
        .map(|(k, tri)| {
            let ring: Vec<Point> = [tri[0], tri[1], tri[2], tri[0]]
                .iter()
                .map(|&i| pts[i as usize])
                .collect();
            json!({
                "type": "Feature",
                "geometry": {"type": "Polygon", "coordinates": [ring]},
                "properties": {"triangle": k, "vertices": tri},
            })
        })
        .collect();
    if include_points {
        features.extend(points_features(pts));
    }
    json!({"type": "FeatureCollection", "features": features})
}

fn points_features(points: &[Point]) -> impl Iterator<Item = Value> + '_ {
    points.iter().enumerate().map(|(i, p)| {
        json!({
            "type": "Feature",
            "geometry": {"type": "Point", "coordinates": p},
            "properties": {"index": i},
        })
    })
}

/// A coordinate in shortest round-trip notation, with an exponent for very
/// large or small magnitudes (Rust's `{}` never uses one).
fn coordinate_text(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 || (1e-5..1e16).contains(&a) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

/// Triangle's `.node` and `.ele` texts. Numbering is 0-based and equals the
/// input index; every input point is listed (duplicates too).
pub fn triangulation_to_triangle_files(t: &Triangulation) -> (String, String) {
    let pts = t.points();
    let mut node = String::with_capacity(pts.len() * 24);
    let _ = writeln!(node, "# optri: input points, 0-based (id = input index)");
    let _ = writeln!(node, "{} 2 0 0", pts.len());
    for (i, p) in pts.iter().enumerate() {
        let _ = writeln!(
            node,
            "{i} {} {}",
            coordinate_text(p[0]),
            coordinate_text(p[1])
        );
    }
    let mut ele = String::with_capacity(t.triangles().len() * 20);
    let _ = writeln!(
        ele,
        "# optri: counter-clockwise triangles over the 0-based .node ids"
    );
    let _ = writeln!(ele, "{} 3 0", t.triangles().len());
    for (k, [a, b, c]) in t.triangles().iter().enumerate() {
        let _ = writeln!(ele, "{k} {a} {b} {c}");
    }
    (node, ele)
}

/// `{"points": [[x, y], …], "edges": [[a, b], …]}` (indices into `points`).
pub fn graph_to_json(points: &[Point], edges: &[[u32; 2]]) -> Value {
    json!({"points": points, "edges": edges})
}

/// A GeoJSON `FeatureCollection`: one `LineString` per edge (property
/// `edge: [a, b]`), then one `Point` per point (property `index`).
///
/// # Panics
/// If an edge refers to an index outside `points`.
pub fn graph_to_geojson(points: &[Point], edges: &[[u32; 2]]) -> Value {
    let mut features: Vec<Value> = edges
        .iter()
        .map(|&[a, b]| {
            json!({
                "type": "Feature",
                "geometry": {"type": "LineString", "coordinates": [points[a as usize], points[b as usize]]},
                "properties": {"edge": [a, b]},
            })
        })
        .collect();
    features.extend(points_features(points));
    json!({"type": "FeatureCollection", "features": features})
}

fn write_file(path: &Path, contents: &str) -> Result<()> {
    std::fs::write(path, contents)
        .map_err(|e| Error::Io(format!("cannot write '{}': {e}", path.display())))
}

fn pretty(v: &Value) -> String {
    // Serialising a `Value` cannot fail.
    let mut s = serde_json::to_string_pretty(v).unwrap_or_default();
    s.push('\n');
    s
}

/// Writes `t` in the format given by `path`'s extension (see
/// [`OutputFormat`]); an SVG is titled with the file name. Returns the files
/// written (two for `.ele`: the `.ele` and its sibling `.node`).
///
/// # Errors
/// [`Error::Unsupported`] for an unknown extension, [`Error::Io`] naming the
/// path when writing fails.
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
    match OutputFormat::from_path(path)? {
        OutputFormat::Json => write_file(path, &pretty(&triangulation_to_json(t)))?,
        OutputFormat::GeoJson => write_file(path, &pretty(&triangulation_to_geojson(t, true)))?,
        OutputFormat::Svg => write_file(path, &triangulation_to_svg(t, title))?,
        OutputFormat::Triangle => {
            let (node, ele) = triangulation_to_triangle_files(t);
            let files = OutputFormat::Triangle.files_written(path);
            write_file(&files[0], &ele)?;
            write_file(&files[1], &node)?;
            return Ok(files);
        }
    }
    Ok(vec![path.to_path_buf()])
}

/// Writes a graph (edges as index pairs into `points`) as `.svg`, `.json` or
/// `.geojson`, by extension.
///
/// # Errors
/// [`Error::Unsupported`] for `.ele` and unknown extensions, [`Error::Io`]
/// naming the path when writing fails.
///
/// # Panics
/// If an edge refers to an index outside `points`.
pub fn write_graph(points: &[Point], edges: &[[u32; 2]], title: &str, path: &Path) -> Result<()> {
    match OutputFormat::from_path(path)? {
        OutputFormat::Json => write_file(path, &pretty(&graph_to_json(points, edges))),
        OutputFormat::GeoJson => write_file(path, &pretty(&graph_to_geojson(points, edges))),
        OutputFormat::Svg => write_file(path, &graph_to_svg(points, edges, title)),
        OutputFormat::Triangle => Err(Error::Io(format!(
            "cannot write '{}': a graph is not a triangulation; use .svg, .json or .geojson",
            path.display()
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::{read_points, InputFormat};
    use crate::{delaunay, PointSet};
    use rand::{rngs::StdRng, Rng, SeedableRng};

    /// Points with awkward values: random doubles, a duplicate, negative and
    /// tiny/huge magnitudes, and a collinear run on the hull.
    fn awkward_points() -> Vec<Point> {
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

    #[test]
    fn json_round_trip_gives_the_same_triangulation() {
        let ps = PointSet::new(&awkward_points()).unwrap();
        let t = delaunay(&ps).unwrap();
        let text = serde_json::to_string(&triangulation_to_json(&t)).unwrap();
        let back = triangulation_from_json(&serde_json::from_str(&text).unwrap()).unwrap();
        assert_eq!(back.points(), t.points());
        assert_eq!(back.triangles(), t.triangles());
        assert_eq!(back.point_set().duplicates(), &[[46, 3]]);
        // The points alone read back through the GeoJSON reader.
        assert_eq!(
            read_points(&text, InputFormat::GeoJson).unwrap(),
            t.points()
        );
        // Tampering is caught: a flipped triangle no longer validates.
        let mut v = triangulation_to_json(&t);
        v["triangles"][0] = json!([
            t.triangles()[0][1],
            t.triangles()[0][0],
            t.triangles()[0][2]
        ]);
        assert!(triangulation_from_json(&v).is_err());
        v["triangles"][0] = json!([0, 1, 999]);
        assert!(triangulation_from_json(&v).is_err());
    }

    #[test]
    fn geojson_round_trip() {
        let pts = awkward_points();
        let t = delaunay(&PointSet::new(&pts).unwrap()).unwrap();
        let v = triangulation_to_geojson(&t, true);
        let features = v["features"].as_array().unwrap();
        assert_eq!(features.len(), t.triangles().len() + pts.len());
        // Each polygon ring maps back, coordinate by coordinate, to its triangle.
        for (k, tri) in t.triangles().iter().enumerate() {
            let ring: Vec<Point> =
                serde_json::from_value(features[k]["geometry"]["coordinates"][0].clone()).unwrap();
            assert_eq!(ring.len(), 4);
            assert_eq!(ring[0], ring[3]);
            for c in 0..3 {
                assert_eq!(ring[c], pts[tri[c] as usize]);
            }
        }
        // The point features, read by the GeoJSON reader, give the input.
        let points_only =
            json!({"type": "FeatureCollection", "features": features[t.triangles().len()..]});
        assert_eq!(
            read_points(&points_only.to_string(), InputFormat::GeoJson).unwrap(),
            pts
        );
        // The whole collection reads back as the points: polygons are skipped.
        assert_eq!(
            read_points(&v.to_string(), InputFormat::GeoJson).unwrap(),
            pts
        );
        // Without the point features there are no points, and the reader
        // says what it found instead.
        let e = read_points(
            &triangulation_to_geojson(&t, false).to_string(),
            InputFormat::GeoJson,
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("Polygon"), "{e}");
    }

    #[test]
    fn triangle_files_round_trip() {
        let mut pts = awkward_points();
        pts.push([3e40, -5e-20]);
        let t = delaunay(&PointSet::new(&pts).unwrap()).unwrap();
        let (node, ele) = triangulation_to_triangle_files(&t);
        assert_eq!(read_points(&node, InputFormat::Node).unwrap(), pts);
        let rows: Vec<Vec<u32>> = ele
            .lines()
            .filter(|l| !l.starts_with('#'))
            .map(|l| l.split_whitespace().map(|x| x.parse().unwrap()).collect())
            .collect();
        assert_eq!(rows[0], vec![t.triangles().len() as u32, 3, 0]);
        let triangles: Vec<[u32; 3]> = rows[1..]
            .iter()
            .enumerate()
            .map(|(k, r)| {
                assert_eq!(r[0], k as u32);
                [r[1], r[2], r[3]]
            })
            .collect();
        assert_eq!(triangles, t.triangles());
    }

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
        let g: Value =
            serde_json::from_str(&std::fs::read_to_string(dir.join("g.geojson")).unwrap()).unwrap();
        assert_eq!(
            g["features"].as_array().unwrap().len(),
            edges.len() + t.points().len()
        );
        assert!(write_graph(t.points(), &edges, "g", &dir.join("g.ele")).is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
