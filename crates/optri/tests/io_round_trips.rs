//! Round trips through optri's readers and writers (text, `.node`, `.tsp`,
//! GeoJSON, JSON, `.ele` + `.node`) on random and degenerate point sets, and
//! the errors for bad input, with their line numbers.
//!
//! Writers print coordinates in shortest round-trip notation, so every round
//! trip must give back the identical `f64` values, in input order, with the
//! same duplicates.

use optri::io::{self, InputFormat, OutputFormat, ReadOptions, Source, WriteOptions};
use optri::kernel::{MAX_COORDINATE, MIN_COORDINATE};
use optri::{delaunay, Error, PointSet, Triangulation};
use optri_oracle::inputs::{grid, lattice_points, uniform_in_square};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use serde_json::Value;
use std::path::PathBuf;

type Point = [f64; 2];

/// The points of `text` read in `format`.
fn read_points(text: &str, format: InputFormat) -> optri::Result<Vec<Point>> {
    let options = ReadOptions::default().with_format(format);
    io::read(Source::Text(text), &options).map(|r| r.input.points().to_vec())
}

/// The points of the file at `path` (format by extension, else content).
fn read_file(path: &std::path::Path) -> Vec<Point> {
    let read = io::read(Source::Path(path), &ReadOptions::default()).unwrap();
    read.input.points().to_vec()
}

/// Writes `document` to `path` by its extension, with default options.
fn write<'a>(document: impl Into<io::Document<'a>>, path: &std::path::Path) -> Vec<PathBuf> {
    io::write(document, path, &WriteOptions::default()).unwrap()
}

const SEED_POINT_SETS: u64 = 2024;

/// Random and degenerate sets, each valid for [`PointSet::new`].
fn point_sets() -> Vec<(String, Vec<Point>)> {
    let mut rng = StdRng::seed_from_u64(SEED_POINT_SETS);
    let mut sets = Vec::new();
    for round in 0..6 {
        let n = rng.gen_range(3..60i32) as usize;
        let scale = [1.0, 1e-30, 1e40, 7.0, 2f64.powi(190), 2f64.powi(-120)][round];
        let mut pts: Vec<Point> = uniform_in_square(&mut rng, n, 1.0)
            .into_iter()
            .map(|p| [p[0] * scale, p[1] * scale])
            .collect();
        // A triangle that keeps the set non-collinear whatever n is.
        pts.extend([[0.0, 0.0], [scale, 0.0], [0.0, scale]]);
        sets.push((format!("random scale {scale:e}"), pts));
    }
    // Duplicates, also of the first and the last point.
    let mut dups = lattice_points(&mut rng, 30, -5..5, -5..5);
    dups.extend([dups[0], dups[7], dups[7], [9.0, 9.0], [-9.0, 9.0]]);
    dups.push(dups[dups.len() - 1]);
    sets.push(("integer duplicates".into(), dups));
    // A grid: collinear rows, cocircular quadruples.
    sets.push(("grid 6x5 step 0.1".into(), grid(6, 5, 0.1)));
    // The documented range limits, exactly, with zero.
    let (big, small) = (MAX_COORDINATE, MIN_COORDINATE);
    sets.push((
        "range limits".into(),
        vec![
            [-big, -big],
            [big, -big],
            [big, big],
            [-big, big],
            [0.0, 0.0],
            [small, -small],
            [-small, 3.0 * small],
            [1.0, 1.0],
        ],
    ));
    sets
}

/// A fresh directory for one test's files.
fn scratch(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "optri-io-round-trips-{}-{test}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `points` as a text file: `sep` between the columns, an optional header,
/// comment lines, and plain or exponent notation.
fn to_text(points: &[Point], sep: &str, header: Option<&str>, exponent: bool) -> String {
    let mut text = String::from("# written by io_round_trips\n\n");
    if let Some(h) = header {
        text.push_str(h);
        text.push('\n');
    }
    for (i, p) in points.iter().enumerate() {
        let (x, y) = if exponent {
            (format!("{:e}", p[0]), format!("{:E}", p[1]))
        } else {
            (format!("{}", p[0]), format!("{}", p[1]))
        };
        if header.is_some_and(|h| h.starts_with("id")) {
            text.push_str(&format!("{i}{sep}{x}{sep}{y}"));
        } else {
            text.push_str(&format!("{x}{sep}{y}"));
        }
        text.push_str(if i % 3 == 0 { "  # a note\n" } else { "\n" });
        if i % 5 == 0 {
            text.push_str("# between the rows\n");
        }
    }
    text
}

/// A TSPLIB `.tsp` text with 1-based node ids.
fn to_tsp(points: &[Point]) -> String {
    let mut text = format!(
        "NAME : roundtrip\nTYPE : TSP\nCOMMENT : io_round_trips\nDIMENSION : {}\n\
         EDGE_WEIGHT_TYPE : EUC_2D\nNODE_COORD_SECTION\n",
        points.len()
    );
    for (i, p) in points.iter().enumerate() {
        text.push_str(&format!("{} {:e} {:e}\n", i + 1, p[0], p[1]));
    }
    text.push_str("EOF\n");
    text
}

/// Reads an `.ele` file written by optri: `m 3 0`, then `k a b c` per triangle.
fn read_ele(text: &str) -> Vec<[u32; 3]> {
    let rows: Vec<Vec<u32>> = text
        .lines()
        .filter(|l| !l.trim_start().starts_with('#') && !l.trim().is_empty())
        .map(|l| l.split_whitespace().map(|t| t.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows[0][1..], [3, 0], "ele header {:?}", rows[0]);
    assert_eq!(rows[0][0] as usize, rows.len() - 1, "ele triangle count");
    rows[1..]
        .iter()
        .enumerate()
        .map(|(k, r)| {
            assert_eq!(r.len(), 4, "ele row {k}");
            assert_eq!(r[0] as usize, k, "ele ids are 0-based and in order");
            [r[1], r[2], r[3]]
        })
        .collect()
}

fn parse_error(e: Error) -> (usize, String) {
    match e {
        Error::Parse { line, message } => (line, message),
        other => panic!("expected a parse error, got {other:?}"),
    }
}

#[test]
fn text_files_in_every_style_read_back_exactly() {
    for (name, pts) in point_sets() {
        let styles = [
            (" ", None),
            ("\t", Some("x y")),
            (",", Some("x,y")),
            (", ", Some("X, Y")),
            (";", Some("id;x;y")),
            ("   ", Some("id x y")),
        ];
        for (sep, header) in styles {
            for exponent in [false, true] {
                let text = to_text(&pts, sep, header, exponent);
                let back = read_points(&text, InputFormat::Text)
                    .unwrap_or_else(|e| panic!("{name} sep {sep:?}: {e}\n{text}"));
                assert_eq!(back, pts, "{name} sep {sep:?} header {header:?}");
                // CRLF line ends read the same.
                let crlf = text.replace('\n', "\r\n");
                assert_eq!(read_points(&crlf, InputFormat::Text).unwrap(), pts);
            }
        }
        // Sniffed as text without an extension.
        let text = to_text(&pts, ",", Some("x,y"), false);
        assert_eq!(InputFormat::sniff(&text), InputFormat::Text);
    }
}

#[test]
fn node_and_tsp_files_read_back_exactly() {
    let dir = scratch("node");
    for (name, pts) in point_sets() {
        let t = delaunay(&PointSet::new(&pts).unwrap()).unwrap();
        write(io::TriangulationReport::new(&t), &dir.join("t.ele"));
        let node = std::fs::read_to_string(dir.join("t.node")).unwrap();
        assert_eq!(
            read_points(&node, InputFormat::Node).unwrap(),
            pts,
            "{name}"
        );
        let tsp = to_tsp(&pts);
        assert_eq!(InputFormat::sniff(&tsp), InputFormat::Tsplib);
        assert_eq!(
            read_points(&tsp, InputFormat::Tsplib).unwrap(),
            pts,
            "{name}"
        );
    }
    // A hand-written .node: 1-based ids, an attribute and boundary markers.
    let node = "# square\n4 2 1 1\n1 0 0 0.5 1\n2 1 0 0.5 1\n3 1 1 0.5 1\n4 0 1 0.5 1\n";
    assert_eq!(
        read_points(node, InputFormat::Node).unwrap(),
        vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn geojson_and_json_outputs_read_back_as_their_points() {
    let dir = scratch("geojson");
    for (k, (name, pts)) in point_sets().into_iter().enumerate() {
        let ps = PointSet::new(&pts).unwrap();
        let t = delaunay(&ps).unwrap();
        // GeoJSON: triangles (Polygons) are skipped, the Points are the input.
        let geojson = dir.join(format!("t{k}.geojson"));
        write(io::TriangulationReport::new(&t), &geojson);
        let back = read_file(&geojson);
        assert_eq!(back, pts, "{name}");
        assert_eq!(PointSet::new(&back).unwrap().duplicates(), ps.duplicates());
        // A graph's GeoJSON (LineStrings and Points) as well.
        let graph = dir.join(format!("g{k}.geojson"));
        let edges = t.edges();
        write(io::GraphReport::new(&pts, &edges), &graph);
        assert_eq!(read_file(&graph), pts, "{name}");
        // JSON: parses back to the same triangulation, and its points read as
        // a point file.
        let json = dir.join(format!("t{k}.json"));
        write(io::TriangulationReport::new(&t), &json);
        let text = std::fs::read_to_string(&json).unwrap();
        let value: Value = serde_json::from_str(&text).unwrap();
        let again = io::triangulation_from_json(&value).unwrap();
        assert_eq!(again.points(), t.points(), "{name}");
        assert_eq!(again.triangles(), t.triangles(), "{name}");
        assert_eq!(again.point_set().duplicates(), ps.duplicates(), "{name}");
        assert_eq!(value["duplicates"], serde_json::json!(ps.duplicates()));
        assert_eq!(read_file(&json), pts, "{name}");
    }
    // Polygons alone hold no points: the error says what the document has.
    let pts = &point_sets()[0].1;
    let t = delaunay(&PointSet::new(pts).unwrap()).unwrap();
    let with_points = dir.join("points.geojson");
    write(io::TriangulationReport::new(&t), &with_points);
    let mut document: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&with_points).unwrap()).unwrap();
    let features = document["features"].as_array_mut().unwrap();
    features.retain(|f| f["geometry"]["type"] == "Polygon");
    let polygons_only = document.to_string();
    let (_, m) = parse_error(read_points(&polygons_only, InputFormat::GeoJson).unwrap_err());
    assert!(
        m.contains("no Point or MultiPoint")
            && m.contains(&format!("{} Polygon", t.triangles().len())),
        "{m}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn ele_and_node_files_read_back_with_consistent_indices() {
    let dir = scratch("ele");
    let with_duplicates = point_sets()
        .iter()
        .filter(|(_, p)| !PointSet::new(p).unwrap().duplicates().is_empty())
        .count();
    assert!(with_duplicates > 0, "no set exercises duplicates");
    for (k, (name, pts)) in point_sets().into_iter().enumerate() {
        let ps = PointSet::new(&pts).unwrap();
        let t = delaunay(&ps).unwrap();
        let ele = dir.join(format!("t{k}.ele"));
        let written = write(io::TriangulationReport::new(&t), &ele);
        assert_eq!(written, OutputFormat::Triangle.files_written(&ele));
        let node_points = read_file(&written[1]);
        assert_eq!(node_points, pts, "{name}");
        let triangles = read_ele(&std::fs::read_to_string(&ele).unwrap());
        assert_eq!(triangles, t.triangles(), "{name}");
        // The .ele indices are .node ids: every one is in range, no merged
        // duplicate is used, and together they validate as a triangulation.
        assert!(triangles
            .iter()
            .flatten()
            .all(|&i| (i as usize) < node_points.len()));
        let dropped: Vec<u32> = ps.duplicates().iter().map(|d| d[0]).collect();
        assert!(
            triangles.iter().flatten().all(|i| !dropped.contains(i)),
            "{name}"
        );
        let node_set = PointSet::new(&node_points).unwrap();
        assert_eq!(node_set.duplicates(), ps.duplicates());
        let back = Triangulation::from_triangles(&node_set, triangles).unwrap();
        assert_eq!(back.edges(), t.edges(), "{name}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_shared_tsplib_file_survives_the_round_trip_with_its_duplicate() {
    let tsp = optri_oracle::data_dir().join("tsplib/a280.tsp");
    let pts = read_file(&tsp);
    let ps = PointSet::new(&pts).unwrap();
    // Nodes 171 and 172 coincide (input indices 170, 171).
    assert_eq!(ps.duplicates(), &[[171, 170]]);
    let t = delaunay(&ps).unwrap();
    let dir = scratch("a280");
    let written = write(io::TriangulationReport::new(&t), &dir.join("a280.ele"));
    let back = read_file(&written[1]);
    assert_eq!(back, pts);
    assert_eq!(PointSet::new(&back).unwrap().duplicates(), &[[171, 170]]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_text_inputs_name_their_line() {
    let cases: &[(&str, usize, &str)] = &[
        ("0 0\n1 0\nNaN 1\n", 3, "finite"),
        ("0 0\n1 inf\n0 1\n", 2, "finite"),
        ("0 0\n-inf 1\n", 2, "finite"),
        ("0 0\n1 0\n0 1\nhello world\n", 4, "'hello'"),
        ("0 0\n1 0\n0 1 5\n", 3, "columns"),
        ("x,y\n0,0\n1,0,2\n", 3, "columns"),
        ("0,0\n1,,0\n0,1\n", 2, "empty"),
        ("0,0\n1,0,\n", 2, "empty"),
        ("0 0\n1 0\n0 1e300\n", 3, "range"),
        ("0 0\n1 0\n1e-300 1\n", 3, "range"),
        ("0 0\n1e400 0\n", 2, "finite"),
        ("", 0, "no points"),
        ("# only a comment\n\n", 0, "no points"),
        ("x y\n", 0, "no points"),
    ];
    for &(text, line, needle) in cases {
        let (got, m) = parse_error(read_points(text, InputFormat::Text).unwrap_err());
        assert_eq!(got, line, "{text:?}: {m}");
        assert!(m.contains(needle), "{text:?}: {m}");
    }
    // The other formats reject out-of-range values too, with their line where
    // there is one.
    let (line, m) = parse_error(
        read_points("3 2 0 0\n0 0 0\n1 1e300 0\n2 0 1\n", InputFormat::Node).unwrap_err(),
    );
    assert_eq!(line, 3);
    assert!(m.contains("range"), "{m}");
    let (line, m) = parse_error(
        read_points(
            "NODE_COORD_SECTION\n1 0 0\n2 1e-300 0\n",
            InputFormat::Tsplib,
        )
        .unwrap_err(),
    );
    assert_eq!(line, 3);
    assert!(m.contains("range"), "{m}");
    let (_, m) = parse_error(
        read_points(
            r#"{"type":"MultiPoint","coordinates":[[0,0],[1e300,1]]}"#,
            InputFormat::GeoJson,
        )
        .unwrap_err(),
    );
    assert!(m.contains("range") && m.contains("[1]"), "{m}");
    for format in InputFormat::ALL {
        let (line, m) = parse_error(read_points("", *format).unwrap_err());
        assert_eq!(line, 0, "{format:?}");
        assert!(
            m.contains("no points") || m.contains("no coordinates"),
            "{format:?}: {m}"
        );
    }
}

#[test]
fn the_coordinate_range_is_exactly_the_documented_one() {
    let above = f64::from_bits(MAX_COORDINATE.to_bits() + 1);
    let below = f64::from_bits(MIN_COORDINATE.to_bits() - 1);
    for (value, ok) in [
        (MAX_COORDINATE, true),
        (-MAX_COORDINATE, true),
        (MIN_COORDINATE, true),
        (-MIN_COORDINATE, true),
        (0.0, true),
        (above, false),
        (-above, false),
        (below, false),
        (1e300, false),
        (1e-300, false),
    ] {
        let text = format!("1 1\n2 1\n{value:e} 3\n");
        let read = read_points(&text, InputFormat::Text);
        assert_eq!(read.is_ok(), ok, "{value:e}: {read:?}");
        if let Err(e) = read {
            let (line, m) = parse_error(e);
            assert_eq!(line, 3);
            assert!(m.contains("range") && m.contains("rescale"), "{m}");
        }
        let direct = PointSet::new(&[[1.0, 1.0], [2.0, 1.0], [value, 3.0]]);
        match direct {
            Ok(_) => assert!(ok, "{value:e}"),
            Err(e) => {
                assert!(!ok, "{value:e}: {e}");
                assert_eq!(e, Error::CoordinateOutOfRange { index: 2, value });
            }
        }
    }
    assert!(matches!(
        PointSet::new(&[[0.0, 0.0], [f64::NAN, 1.0], [1.0, 0.0]]),
        Err(Error::NonFiniteCoordinate { index: 1, .. })
    ));
}

#[test]
fn too_few_and_collinear_points_read_but_do_not_triangulate() {
    let cases: &[(&str, Error)] = &[
        ("0 0\n1 1\n", Error::TooFewPoints { distinct: 2 }),
        ("0 0\n1 1\n0 0\n", Error::TooFewPoints { distinct: 2 }),
        (
            "0 0\n1 1\n2 2\n3 3\n1 1\n",
            Error::AllCollinear { distinct: 4 },
        ),
        (
            "1e-30 5\n2e-30 5\n3e-30 5\n",
            Error::AllCollinear { distinct: 3 },
        ),
    ];
    for (text, expected) in cases {
        let pts = read_points(text, InputFormat::Text).unwrap();
        let e = PointSet::new(&pts).unwrap_err();
        assert_eq!(&e, expected, "{text:?}");
        // The message says what is wrong and how many points there are.
        let m = e.to_string();
        assert!(m.contains("distinct") || m.contains("collinear"), "{m}");
    }
}

#[test]
fn a_50_mb_token_gives_a_short_escaped_message_in_every_reader() {
    let long = "7".repeat(50 << 20);
    // A bell and an escape first: they must not reach a terminal raw.
    let token = format!("\u{7}\u{1b}{long}");
    let cases: Vec<(InputFormat, String)> = vec![
        (InputFormat::Text, format!("0 0\n1 {token}\n")),
        (InputFormat::Text, format!("{token}\n")),
        (InputFormat::Text, format!("id,a{token}\n1,2\n")),
        (
            InputFormat::Node,
            format!("3 2 0 0\n0 0 0\n1 {token} 0\n2 0 1\n"),
        ),
        (InputFormat::Node, format!("{token} 2 0 0\n")),
        (
            InputFormat::Poly,
            format!("3 2\n0 0 0\n1 1 0\n2 0 1\n{token} 0\n"),
        ),
        (
            InputFormat::Tsplib,
            format!("NODE_COORD_SECTION\n1 0 0\n2 {token} 1\n"),
        ),
        (InputFormat::Tsplib, format!("NAME: x\n{token}\n")),
        (InputFormat::Tsplib, format!("EDGE_WEIGHT_TYPE: {token}\n")),
        (
            InputFormat::GeoJson,
            format!(r#"{{"type":"\u0007{long}","coordinates":[0,0]}}"#),
        ),
        (
            InputFormat::GeoJson,
            format!(r#"{{"type":"Point","coordinates":"\u0007{long}"}}"#),
        ),
    ];
    for (format, text) in cases {
        let e = read_points(&text, format).unwrap_err();
        let message = e.to_string();
        assert!(
            message.len() < 300 && !message.chars().any(char::is_control),
            "{format:?}: {message}"
        );
        // The prefix is shown, then how long the whole token is.
        assert!(message.contains("7777…"), "{format:?}: {message}");
        let before = message.split(" bytes)").next().unwrap();
        let bytes: usize = before.rsplit('(').next().unwrap().parse().unwrap();
        assert!(bytes >= long.len(), "{format:?}: {message}");
    }
}

/// The points and elevations of the file at `path` (format by extension).
fn read_with_elevations(path: &std::path::Path) -> (Vec<Point>, Option<Vec<f64>>) {
    let read = io::read(Source::Path(path), &ReadOptions::default()).unwrap();
    (read.input.points().to_vec(), read.elevations)
}

#[test]
fn elevations_survive_every_format_that_holds_them() {
    use optri::request::{Request, Task};
    let dir = scratch("elevations");
    let mut rng = StdRng::seed_from_u64(SEED_POINT_SETS);
    for (k, (name, pts)) in point_sets().into_iter().enumerate() {
        // One elevation per distinct point, so duplicates agree; awkward
        // magnitudes and signs.
        let ps = PointSet::new(&pts).unwrap();
        let per_distinct: Vec<f64> = (0..ps.len())
            .map(|_| rng.gen_range(-1.0..1.0) * [1.0, 1e-30, 1e40, 3.0][rng.gen_range(0..4)])
            .collect();
        let z: Vec<f64> = (0..pts.len() as u32)
            .map(|i| per_distinct[ps.distinct_index(i) as usize])
            .collect();
        // An `x y z` text file reads with its elevations ...
        let text: String = pts
            .iter()
            .zip(&z)
            .map(|(p, z)| format!("{:e} {:e} {z:e}\n", p[0], p[1]))
            .collect();
        let input = dir.join(format!("p{k}.txt"));
        std::fs::write(&input, text).unwrap();
        let read = io::read(Source::Path(&input), &ReadOptions::default()).unwrap();
        assert_eq!(read.elevations.as_deref(), Some(&z[..]), "{name}");
        // ... the request carries them to the point set and the document ...
        let outcome = Request::new(read, Task::triangulate("delaunay").unwrap())
            .run()
            .unwrap();
        let distinct: Vec<f64> = (0..ps.len() as u32)
            .map(|d| z[ps.input_index(d) as usize])
            .collect();
        assert_eq!(
            outcome.point_set().unwrap().elevations(),
            Some(&distinct[..]),
            "{name}"
        );
        let value = outcome.to_json();
        assert_eq!(value["elevations"], serde_json::json!(z), "{name}");
        // ... and every output that holds them reads back to the same values.
        for extension in ["json", "geojson", "ele", "edge"] {
            let path = dir.join(format!("t{k}.{extension}"));
            let written = write(outcome.document(), &path);
            let points_file = written.last().unwrap();
            let (back, back_z) = read_with_elevations(points_file);
            assert_eq!(back, pts, "{name} .{extension}");
            assert_eq!(back_z.as_deref(), Some(&z[..]), "{name} .{extension}");
        }
        let again = io::triangulation_from_json(&value).unwrap();
        assert_eq!(
            again.point_set().elevations(),
            Some(&distinct[..]),
            "{name}"
        );
        let document = io::TriangulationReport::new(&again).to_json();
        assert_eq!(document["elevations"], value["elevations"], "{name}");
    }
    // Without elevations no output invents them.
    let pts = &point_sets()[0].1;
    let t = delaunay(&PointSet::new(pts).unwrap()).unwrap();
    for extension in ["json", "geojson", "ele"] {
        let path = dir.join(format!("plain.{extension}"));
        let written = write(io::TriangulationReport::new(&t), &path);
        assert_eq!(read_with_elevations(written.last().unwrap()).1, None);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_file_mixing_two_and_three_columns_names_the_line() {
    for (text, line) in [("0 0 1\n1 0 2\n# c\n0 1\n", 4), ("0 0\n1 0\n0 1 5\n", 3)] {
        let (at, m) = parse_error(read_points(text, InputFormat::Text).unwrap_err());
        assert_eq!(at, line, "{text}: {m}");
        assert!(
            m.contains("every row must have the same number of columns"),
            "{m}"
        );
    }
}
