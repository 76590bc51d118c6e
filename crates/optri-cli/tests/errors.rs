//! Every user-facing error message of the `optri` binary, verbatim, with its
//! exit code: each reader error with its line, each unsupported
//! combination, each I/O failure. Nothing prints a backtrace, even with
//! `RUST_BACKTRACE=1`.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

const BIN: &str = env!("CARGO_BIN_EXE_optri");

fn scratch(test: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("errors-{test}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs `optri args` in `dir` (so messages name relative paths), with
/// backtraces requested: none may appear.
fn run_in(dir: &Path, args: &[&str], stdin: Option<&str>) -> Output {
    use std::io::Write;
    let mut child = Command::new(BIN)
        .args(args)
        .current_dir(dir)
        .env("RUST_BACKTRACE", "1")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let input = child.stdin.take().unwrap();
    if let Some(text) = stdin {
        let mut input = input;
        let _ = input.write_all(text.as_bytes());
    }
    child.wait_with_output().unwrap()
}

/// Asserts that `optri args` fails with exit code 1 and exactly `message`
/// (one line, after `optri: error: `) on stderr, and writes nothing to
/// stdout.
fn assert_error(dir: &Path, args: &[&str], stdin: Option<&str>, message: &str) {
    let out = run_in(dir, args, stdin);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{args:?}: {err}");
    assert_eq!(err, format!("optri: error: {message}\n"), "{args:?}");
    assert!(out.stdout.is_empty(), "{args:?}");
}

/// Reader errors: (file, contents, message). Each is tried with
/// `triangulate`, and with `graph` unless the file is a polygon.
const READER_ERRORS: &[(&str, &str, &str)] = &[
    (
        "mixed.txt",
        "0 0 1\n1 0 2\n0 1\n",
        "mixed.txt:3: 2 columns, but line 1 has 3; every row must have the same number of columns",
    ),
    (
        "z.txt",
        "0 0 1\n1 0 nan\n0 1 2\n",
        "z.txt:2: elevation 'nan' is not a finite number",
    ),
    ("nan.txt", "0 0\n1 0\nNaN 1\n", "nan.txt:3: coordinate 'NaN' is not a finite number"),
    ("word.txt", "0 0\n1 0\n0 oops\n", "word.txt:3: 'oops' is not a number"),
    (
        "range.txt",
        "0 0\n1 0\n0 1e300\n",
        "range.txt:3: coordinate '1e300' is outside the exact range (|v| must be 0 or between \
         1.793662034335766e-43 and 3.2138760885179806e60); rescale the input",
    ),
    (
        "single.txt",
        "0 0\n5\n",
        "single.txt:2: 1 column, but line 1 has 2; every row must have the same number of columns",
    ),
    ("first.txt", "5\n0 0\n", "first.txt:1: expected 'x y', found a single value '5'"),
    (
        "ragged.txt",
        "0 0\n1 0\n0 1 5\n",
        "ragged.txt:3: 3 columns, but line 1 has 2; every row must have the same number of columns",
    ),
    ("header.txt", "id,x,y\n1,2\n", "header.txt:2: 2 columns, but the header on line 1 names 3"),
    (
        "emptyfield.txt",
        "0,0\n1,,0\n",
        "emptyfield.txt:2: field 2 is empty (two separators in a row, or one at the start or end \
         of the line); every field must hold a number",
    ),
    ("empty.txt", "", "empty.txt: no points found in the input"),
    ("comments.txt", "# x y\n\n", "comments.txt: no points found in the input"),
    ("dim.node", "2 3 0 0\n0 0 0 0\n1 1 0 0\n", "dim.node:1: dimension is 3, only 2 is supported"),
    ("nodim.node", "3\n", "nodim.node:1: header lacks the dimension"),
    (
        "marker.node",
        "1 2 0 2\n0 0 0 1\n",
        "marker.node:1: boundary-marker flag must be 0 or 1, found 2",
    ),
    (
        "fields.node",
        "3 2 0 0\n0 0 0\n1 1 0 5\n2 0 1\n",
        "fields.node:3: expected 3 fields (id x y), found 4",
    ),
    ("seq.node", "3 2 0 0\n0 0 0\n5 1 0\n2 0 1\n", "seq.node:3: vertex id 5 out of sequence (expected 1)"),
    ("count.node", "3 2 0 0\n0 0 0\n1 1 0\n", "count.node:1: the header announces 3 vertices, the file has 2"),
    (
        "attrs.node",
        "3 2 18446744073709551615 0\n0 0 0\n",
        "attrs.node:1: attribute count 18446744073709551615 is too large",
    ),
    (
        "more.node",
        "2 2 0 0\n0 0 0\n1 1 0\n2 0 1\n",
        "more.node:4: more vertex lines than the 2 the header announces",
    ),
    (
        "dim.tsp",
        "DIMENSION: 4\nNODE_COORD_SECTION\n1 0 0\n2 1 0\n3 0 1\nEOF\n",
        "dim.tsp:1: DIMENSION is 4, but NODE_COORD_SECTION (line 2) has 3 nodes",
    ),
    (
        "ewt.tsp",
        "DIMENSION: 2\nEDGE_WEIGHT_TYPE: EXPLICIT\nEDGE_WEIGHT_SECTION\n0 1\n",
        "ewt.tsp:2: EDGE_WEIGHT_TYPE EXPLICIT has no planar coordinates; supported: EUC_2D, \
         CEIL_2D, MAN_2D, MAX_2D, ATT, GEO",
    ),
    (
        "fields.tsp",
        "NODE_COORD_SECTION\n1 0 0\n2 1\n",
        "fields.tsp:3: expected 'id x y' in NODE_COORD_SECTION, found 2 fields",
    ),
    ("id.tsp", "NODE_COORD_SECTION\n1 0 0\n3 1 0\n", "id.tsp:3: node id 3 out of sequence (expected 2)"),
    ("x.tsp", "NODE_COORD_SECTION\n1 0 0\n2 x 1\n", "x.tsp:3: 'x' is not a number"),
    (
        "nosection.tsp",
        "NAME: x\nTYPE: TSP\n",
        "nosection.tsp: no NODE_COORD_SECTION found: the file has no coordinates",
    ),
    (
        "headerline.tsp",
        "NAME: x\nhello\n",
        "headerline.tsp:2: expected a header line 'KEY : VALUE', found 'hello'",
    ),
    (
        "coordtype.tsp",
        "NODE_COORD_TYPE: THREED_COORDS\nNODE_COORD_SECTION\n",
        "coordtype.tsp:1: NODE_COORD_TYPE THREED_COORDS is not supported (only TWOD_COORDS)",
    ),
    ("bad.geojson", "{\n\"type\":\n}", "bad.geojson:3: invalid JSON: expected value at line 3 column 1"),
    (
        "type.geojson",
        r#"{"type":"Pointy","coordinates":[0,0]}"#,
        "type.geojson: GeoJSON: the document: \"Pointy\" is not a GeoJSON geometry type (points \
         are read from Point and MultiPoint; LineString, Polygon and their Multi forms are skipped)",
    ),
    (
        "line.geojson",
        r#"{"type":"LineString","coordinates":[[0,0],[1,1]]}"#,
        "line.geojson: GeoJSON: no Point or MultiPoint geometry found (the document has only 1 \
         LineString)",
    ),
    (
        "position.geojson",
        r#"{"type":"MultiPoint","coordinates":[[0,0],[1]]}"#,
        "position.geojson: GeoJSON: the document[1]: expected a position [x, y], found [1]",
    ),
    (
        "lacks.geojson",
        r#"{"type":"Feature"}"#,
        "lacks.geojson: GeoJSON: the document: Feature lacks \"geometry\"",
    ),
];

/// Polygon errors (only `triangulate` reads polygons).
const POLYGON_ERRORS: &[(&str, &str, &str)] = &[
    (
        "holes.geojson",
        r#"{"type":"Polygon","coordinates":[[[0,0],[4,0],[0,4],[0,0]],[[1,1],[2,1],[1,2],[1,1]]]}"#,
        "holes.geojson: GeoJSON: the document: polygons with holes are not supported yet (the \
         polygon has 1 hole ring(s))",
    ),
    (
        "two.geojson",
        r#"{"type":"MultiPolygon","coordinates":[[[[0,0],[1,0],[0,1],[0,0]]],[[[5,5],[6,5],[5,6],[5,5]]]]}"#,
        "two.geojson: GeoJSON: the document has 2 polygons (the document.coordinates[0], the \
         document.coordinates[1]) and no points; optri triangulates one simple polygon per file",
    ),
    (
        "self.geojson",
        r#"{"type":"Polygon","coordinates":[[[0,0],[2,2],[2,0],[0,2],[0,0]]]}"#,
        "self.geojson: not a simple polygon: edge 0-1 meets edge 2-3 (the boundary must not touch \
         itself)",
    ),
    (
        "zero.poly",
        "0 2 0 0\n",
        "zero.poly:1: the vertex count is 0 (vertices in a separate .node file); optri reads .poly \
         files that list their vertices",
    ),
    (
        "noseg.poly",
        "3 2\n1 0 0\n2 1 0\n3 0 1\n",
        "noseg.poly: the file ends after the vertices: a .poly file needs a segment section (the \
         boundary)",
    ),
    (
        "endpoint.poly",
        "3 2\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 7\n3 3 1\n",
        "endpoint.poly:7: segment endpoint 7 is not a vertex (ids run from 1 to 3)",
    ),
    (
        "third.poly",
        "4 2\n1 0 0\n2 1 0\n3 0 1\n4 1 1\n4 0\n1 1 2\n2 1 3\n3 1 4\n4 2 3\n",
        "third.poly:9: segment 3 is the third at vertex 1 (the boundary must be one closed cycle, \
         two segments per vertex)",
    ),
    (
        "holes.poly",
        "3 2\n1 0 0\n2 4 0\n3 0 4\n3 0\n1 1 2\n2 2 3\n3 3 1\n1\n1 1 1\n",
        "holes.poly:9: polygons with holes are not supported yet: the file lists 1 hole(s)",
    ),
    (
        "repeat.poly",
        "4 2\n1 0 0\n2 1 0\n3 0 1\n4 1 1\n4 0\n1 1 2\n2 2 1\n3 3 4\n4 4 3\n",
        "repeat.poly:8: segment 2 repeats the segment 2-1 of line 7",
    ),
];

#[test]
fn every_reader_error_names_its_file_and_line() {
    let dir = scratch("readers");
    for (name, contents, message) in READER_ERRORS {
        std::fs::write(dir.join(name), contents).unwrap();
        assert_error(&dir, &["triangulate", name], None, message);
        assert_error(&dir, &["triangulate", name, "--json"], None, message);
        assert_error(&dir, &["graph", name, "--kind", "rng"], None, message);
        // The same text on stdin is named `<stdin>` (the format forced, as
        // stdin has no extension).
        let format = match Path::new(name).extension().unwrap().to_str().unwrap() {
            "txt" => "text",
            "tsp" => "tsplib",
            other => other,
        };
        let stdin_message = message.replacen(name, "<stdin>", 1);
        assert_error(
            &dir,
            &["triangulate", "-", "--input-format", format],
            Some(contents),
            &stdin_message,
        );
    }
    for (name, contents, message) in POLYGON_ERRORS {
        std::fs::write(dir.join(name), contents).unwrap();
        assert_error(
            &dir,
            &["triangulate", name, "--criterion", "greedy"],
            None,
            message,
        );
    }
}

#[test]
fn every_unsupported_combination_says_what_would_work() {
    let dir = scratch("unsupported");
    std::fs::write(dir.join("square.txt"), "0 0\n4 0\n4 4\n0 4\n1 1\n").unwrap();
    std::fs::write(dir.join("two.txt"), "0 0\n1 1\n").unwrap();
    std::fs::write(dir.join("line.txt"), "0 0\n1 1\n2 2\n").unwrap();
    std::fs::write(dir.join("one.txt"), "3 3\n3 3\n").unwrap();
    let cases: &[(&[&str], &str)] = &[
        (
            &[
                "triangulate",
                "square.txt",
                "--criterion",
                "delaunay",
                "--metric",
                "l1",
            ],
            "square.txt: delaunay does not take a metric other than euclidean (got l1); what \
             takes one: minmax-length, hull, rng, mst",
        ),
        (
            &[
                "triangulate",
                "square.txt",
                "--criterion",
                "minmax-length",
                "--metric",
                "lp:0",
            ],
            "--metric: invalid metric: lp:0: the exponent must be an integer 1 ≤ P ≤ 64",
        ),
        (
            &["graph", "square.txt", "--kind", "gabriel", "--metric", "l1"],
            "square.txt: gabriel does not take a metric other than euclidean (got l1); what takes \
             one: minmax-length, hull, rng, mst",
        ),
        (
            &["triangulate", "square.txt", "--criterion", "prettiest"],
            "unknown criterion 'prettiest'; available: delaunay, minmax-length, greedy, \
             min-weight, maxmin-area, minmax-area, minmax-angle, maxmin-height, \
             minmax-eccentricity, minmax-slope, minmax-delta-area, minmax-delta-angle, \
             minmax-delta-length",
        ),
        (
            &["triangulate", "square.txt", "--input-format", "xml"],
            "unknown input format 'xml'; available: text, node, poly, tsplib, geojson, ply, obj",
        ),
        (
            &["triangulate", "two.txt"],
            "two.txt: a triangulation needs at least 3 distinct points, the input has 2",
        ),
        (
            &["triangulate", "line.txt"],
            "line.txt: all 3 distinct points are collinear, so no triangle exists",
        ),
        (
            &["graph", "one.txt", "--kind", "mst"],
            "one.txt: a graph needs at least 2 distinct points, the input has 1",
        ),
        (
            &["graph", "square.txt", "--kind", "mst", "-o", "g.ele"],
            "cannot write 'g.ele': a graph is not a triangulation; use .svg, .json, .geojson, \
             .edge, .obj or .ply",
        ),
    ];
    for (args, message) in cases {
        assert_error(&dir, args, None, message);
    }
    // A usage error is clap's, exit code 2, without a backtrace.
    let out = run_in(&dir, &["graph", "square.txt", "--kind", "voronoi"], None);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.starts_with(
            "error: invalid value 'voronoi' for '--kind <KIND>': unknown graph kind 'voronoi'; \
             available: hull, delaunay, rng, gabriel, mst\n"
        ),
        "{err}"
    );
}

#[test]
fn every_io_failure_is_reported_before_any_work() {
    let dir = scratch("io");
    std::fs::write(dir.join("square.txt"), "0 0\n4 0\n4 4\n0 4\n1 1\n").unwrap();
    std::fs::write(dir.join("afile"), "").unwrap();
    std::fs::create_dir_all(dir.join("d.json")).unwrap();
    std::fs::write(dir.join("c.node"), "3 2 0 0\n0 0 0\n1 4 0\n2 0 4\n").unwrap();
    let cases: &[(&[&str], &str)] = &[
        (
            &["triangulate", "missing.txt"],
            "cannot read 'missing.txt': No such file or directory (os error 2)",
        ),
        (
            &["graph", "missing.txt", "--kind", "hull"],
            "cannot read 'missing.txt': No such file or directory (os error 2)",
        ),
        (
            &["triangulate", "square.txt", "-o", "out.png"],
            "cannot write 'out.png': unknown output extension; supported: .json, .svg, .ele or \
             .edge (write the sibling .node too), .geojson, .obj, .ply, .off",
        ),
        (
            &["triangulate", "square.txt", "-o", "no/such/dir/out.json"],
            "cannot write 'no/such/dir/out.json': the directory 'no/such/dir' does not exist",
        ),
        (
            &["triangulate", "square.txt", "-o", "afile/out.json"],
            "cannot write 'afile/out.json': 'afile' is not a directory",
        ),
        (
            &["triangulate", "square.txt", "-o", "d.json"],
            "cannot write 'd.json': it is a directory",
        ),
        (
            &["graph", "square.txt", "--kind", "rng", "-o", "no/g.edge"],
            "cannot write 'no/g.edge': the directory 'no' does not exist",
        ),
        (
            &["triangulate", "square.txt", "-o", "/proc/optri-test.json"],
            "cannot write '/proc/optri-test.json': No such file or directory (os error 2)",
        ),
        (
            &["triangulate", "c.node", "-o", "c.ele"],
            "refusing to overwrite the input file 'c.node' (writing 'c.ele' also writes the \
             .node beside it); choose another output name",
        ),
    ];
    for (args, message) in cases {
        assert_error(&dir, args, None, message);
    }
    // A bad output path costs no work and leaves the other outputs unwritten.
    assert_error(
        &dir,
        &[
            "triangulate",
            "square.txt",
            "-o",
            "a.svg",
            "-o",
            "no/b.json",
        ],
        None,
        "cannot write 'no/b.json': the directory 'no' does not exist",
    );
    assert!(!dir.join("a.svg").exists());
    // An output path that is checked is not left behind.
    let out = run_in(&dir, &["triangulate", "square.txt", "-o", "ok.json"], None);
    assert!(out.status.success());
    assert!(dir.join("ok.json").exists());
}

#[test]
fn warnings_name_what_is_ignored_and_quiet_silences_them() {
    let dir = scratch("warnings");
    std::fs::write(dir.join("xyzw.txt"), "0 0 7 1\n4 0 7 1\n0 4 7 1\n1 1 7 1\n").unwrap();
    let out = run_in(&dir, &["triangulate", "xyzw.txt"], None);
    assert!(out.status.success());
    assert_eq!(
        String::from_utf8_lossy(&out.stderr),
        "optri: warning: xyzw.txt: line 1: rows have 4 columns and no header names them; reading \
         columns 1 and 2 as x y and ignoring columns 3 to 4 (a header line such as `x y z` names \
         them; a column named z is read as the elevation)\n"
    );
    let out = run_in(
        &dir,
        &["triangulate", "xyzw.txt", "--quiet", "--json"],
        None,
    );
    assert!(out.status.success() && out.stderr.is_empty());
    let out = run_in(
        &dir,
        &["graph", "-", "--kind", "mst", "-q"],
        Some("0 0 1 2\n1 0 1 2\n"),
    );
    assert!(out.status.success() && out.stderr.is_empty());
    let out = run_in(
        &dir,
        &["graph", "-", "--kind", "mst"],
        Some("0 0 1 2\n1 0 1 2\n"),
    );
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("<stdin>: line 1: rows have 4 columns")
            && String::from_utf8_lossy(&out.stderr).contains("ignoring columns 3 to 4"),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn an_xyz_file_triangulates_with_its_elevations_and_writes_them_back() {
    let dir = scratch("xyz");
    std::fs::write(
        dir.join("xyz.txt"),
        "0 0 7\n4 0 7.5\n0 4 -1\n1 1 0\n4 0 7.5\n",
    )
    .unwrap();
    let out = run_in(
        &dir,
        &[
            "triangulate",
            "xyz.txt",
            "--json",
            "-o",
            "t.geojson",
            "-o",
            "t.ele",
        ],
        None,
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success() && err.is_empty(), "{err}");
    let document: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(
        document["elevations"],
        serde_json::json!([7.0, 7.5, -1.0, 0.0, 7.5])
    );
    assert_eq!(document["coordinates"][1], serde_json::json!([4.0, 0.0]));
    let geojson = std::fs::read_to_string(dir.join("t.geojson")).unwrap();
    assert!(geojson.contains("[4.0,0.0,7.5]"), "{geojson}");
    let node = std::fs::read_to_string(dir.join("t.node")).unwrap();
    assert!(
        node.contains("\n5 2 1 0\n") && node.contains("\n2 0 4 -1\n"),
        "{node}"
    );
    // Written files read back as input with the same elevations.
    for written in ["t.geojson", "t.node"] {
        let out = run_in(&dir, &["triangulate", written, "--json", "-q"], None);
        assert!(out.status.success(), "{written}");
        let again: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(again["elevations"], document["elevations"], "{written}");
    }
    // Duplicates with different elevations are refused, naming them.
    std::fs::write(dir.join("conflict.txt"), "0 0 7\n4 0 7.5\n0 4 -1\n4 0 8\n").unwrap();
    let out = run_in(&dir, &["triangulate", "conflict.txt"], None);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(
        err.contains("point 3 repeats point 1 with another elevation"),
        "{err}"
    );
}

/// The coordinates of `optri triangulate INPUT --json` run in `dir`.
fn coordinates(dir: &Path, input: &str, stdin: Option<&str>) -> serde_json::Value {
    let out = run_in(dir, &["triangulate", input, "--json", "-q"], stdin);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{input}: {err}");
    let document: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    document["coordinates"].clone()
}

#[test]
fn stdin_and_unknown_extensions_are_text_unless_the_structure_is_triangles() {
    let dir = scratch("sniff");
    let cloud = "3 2 0\n1 0 0\n2 1 0\n3 0 1\n";
    let zero = "0 2\n1 3\n5 6\n4 0\n";
    let node = "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n";
    let cases = [
        (cloud, "[[3.0,2.0],[1.0,0.0],[2.0,1.0],[3.0,0.0]]"),
        (zero, "[[0.0,2.0],[1.0,3.0],[5.0,6.0],[4.0,0.0]]"),
        (node, "[[0.0,0.0],[1.0,0.0],[0.0,1.0]]"),
    ];
    for (k, (text, expected)) in cases.into_iter().enumerate() {
        let expected: serde_json::Value = serde_json::from_str(expected).unwrap();
        assert_eq!(coordinates(&dir, "-", Some(text)), expected, "{text}");
        let name = format!("cloud{k}.dat");
        std::fs::write(dir.join(&name), text).unwrap();
        assert_eq!(coordinates(&dir, &name, None), expected, "{text}");
    }
}

#[test]
fn csv_headers_name_the_columns_and_comments_may_be_latin1() {
    let dir = scratch("csv");
    std::fs::write(
        dir.join("cities.csv"),
        "name,lat,lon\nBern,46.95,7.45\nZürich,47.37,8.54\nGenève,46.2,6.14\n",
    )
    .unwrap();
    let out = run_in(&dir, &["triangulate", "cities.csv", "--json"], None);
    assert!(out.status.success());
    assert_eq!(
        String::from_utf8_lossy(&out.stderr),
        "optri: warning: cities.csv: line 1: skipping 1 column 'name' (column 1); x and y are \
         'lon' and 'lat' (columns 3 and 2)\n"
    );
    let document: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(
        document["coordinates"],
        serde_json::json!([[7.45, 46.95], [8.54, 47.37], [6.14, 46.2]])
    );
    assert_error(
        &dir,
        &["triangulate", "-"],
        Some("id,a,b\n1,0,0\n"),
        "<stdin>:1: the header names no coordinate columns (found 'id', 'a', 'b'); it must name \
         one pair of: x/y, lon/lat, lng/lat, long/lat, longitude/latitude, easting/northing \
         (case-insensitive; x is the longitude or easting)",
    );
    // Latin-1 bytes in a comment are fine; in a number they name the line.
    let latin1 = b"# Gen\xe8ve\n0 0\n1 0 # caf\xe9\n0 1\n";
    std::fs::write(dir.join("latin1.txt"), latin1).unwrap();
    assert_eq!(
        coordinates(&dir, "latin1.txt", None),
        serde_json::json!([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    );
    std::fs::write(dir.join("bad.txt"), b"0 0\n1 0\n0 1\xe9\n").unwrap();
    assert_error(
        &dir,
        &["triangulate", "bad.txt"],
        None,
        "bad.txt:3: '1�' is not a number (� stands for bytes that are not UTF-8)",
    );
}

#[test]
fn a_huge_or_binary_token_is_quoted_short_and_escaped() {
    let dir = scratch("huge");
    let token = "\u{1b}[31m".to_string() + &"9".repeat(1 << 20);
    std::fs::write(dir.join("huge.txt"), format!("0 0\n1 {token}\n")).unwrap();
    assert_error(
        &dir,
        &["triangulate", "huge.txt"],
        None,
        &format!(
            "huge.txt:2: '\\u{{1b}}[31m{}…' ({} bytes) is not a number",
            "9".repeat(35),
            token.len()
        ),
    );
}
