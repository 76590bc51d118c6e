//! End-to-end tests of the `optri` binary: results are checked against the
//! library (triangles re-validated exactly), errors for their message, line
//! and exit code.

use optri::{PointSet, Triangulation};
use serde_json::Value;
use std::io::Write;
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};

const BIN: &str = env!("CARGO_BIN_EXE_optri");
/// The TSPLIB file `name.tsp` (see `optri_oracle::data_dir`).
fn tsplib(name: &str) -> String {
    let path = optri_oracle::data_dir().join(format!("tsplib/{name}.tsp"));
    path.to_str().unwrap().to_string()
}

/// The points of the file at `path`, read by the library (format by
/// extension, else by content).
fn file_points(path: impl AsRef<std::path::Path>) -> Vec<[f64; 2]> {
    let source = optri::io::Source::Path(path.as_ref());
    let read = optri::io::read(source, &optri::io::ReadOptions::default()).unwrap();
    read.input.points().to_vec()
}

/// The points of `text` in `format`, read by the library.
fn text_points(text: &str, format: optri::io::InputFormat) -> Vec<[f64; 2]> {
    let options = optri::io::ReadOptions::default().with_format(format);
    let read = optri::io::read(optri::io::Source::Text(text), &options).unwrap();
    read.input.points().to_vec()
}

/// A fresh directory for one test's files.
fn scratch(test: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("cli-{test}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn write(dir: &std::path::Path, name: &str, contents: &str) -> String {
    let path = dir.join(name);
    std::fs::write(&path, contents).unwrap();
    path.to_str().unwrap().to_string()
}

fn run(args: &[&str]) -> Output {
    Command::new(BIN).args(args).output().unwrap()
}

fn run_stdin(args: &[&str], input: &str) -> Output {
    let mut child = Command::new(BIN)
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // The child may fail (e.g. on a bad argument) before reading stdin.
    let written = child.stdin.take().unwrap().write_all(input.as_bytes());
    if let Err(e) = written {
        assert_eq!(e.kind(), std::io::ErrorKind::BrokenPipe, "{e}");
    }
    child.wait_with_output().unwrap()
}

fn stdout_json(out: &Output) -> Value {
    assert!(
        out.status.success(),
        "stderr: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// Checks the JSON `triangles` form a valid triangulation of `points`.
fn check_triangulation(json: &Value, points: &[[f64; 2]]) -> Triangulation {
    let triangles: Vec<[u32; 3]> = serde_json::from_value(json["triangles"].clone()).unwrap();
    let ps = PointSet::new(points).unwrap();
    let t = Triangulation::from_triangles(&ps, triangles).unwrap();
    assert_eq!(json["points"], points.len());
    assert_eq!(json["stats"]["triangles"], t.triangles().len());
    assert_eq!(json["stats"]["edges"], t.edges().len());
    t
}

/// Asserts a clean failure whose stderr contains every one of `needles`.
fn assert_fails(out: &Output, needles: &[&str]) {
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "stderr: {err}");
    assert!(err.starts_with("optri: error: "), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    for n in needles {
        assert!(err.contains(n), "expected {n:?} in {err:?}");
    }
}

const SQUARE: &str = "x,y\n0,0\n4,0\n4,4\n0,4\n1,1\n3,2\n";
const SQUARE_POINTS: [[f64; 2]; 6] = [
    [0.0, 0.0],
    [4.0, 0.0],
    [4.0, 4.0],
    [0.0, 4.0],
    [1.0, 1.0],
    [3.0, 2.0],
];

#[test]
fn triangulate_json_from_a_file() {
    let dir = scratch("json");
    let input = write(&dir, "square.csv", SQUARE);
    let json = stdout_json(&run(&["triangulate", &input, "--json"]));
    let t = check_triangulation(&json, &SQUARE_POINTS);
    assert_eq!(json["criterion"], "delaunay");
    assert_eq!(json["exact"], true);
    assert!(json["algorithm"].is_string());
    assert_eq!(json["duplicates"], serde_json::json!([]));
    // Same triangles as the library's Delaunay triangulation.
    let lib = optri::delaunay(&PointSet::new(&SQUARE_POINTS).unwrap()).unwrap();
    assert_eq!(t.triangles(), lib.triangles());
    let stats = &json["stats"];
    for key in [
        "max_edge_length",
        "total_edge_length",
        "min_area",
        "max_area",
        "min_angle_deg",
        "max_angle_deg",
        "hull_points",
    ] {
        assert!(stats[key].is_number(), "{key}");
    }
    assert_eq!(stats["hull_points"], 4);
    for key in ["read", "total", "delaunay"] {
        assert!(json["timing_ms"][key].as_f64().unwrap() >= 0.0, "{key}");
    }
}

#[test]
fn triangulate_from_stdin_and_human_summary() {
    let json = stdout_json(&run_stdin(&["triangulate", "-", "--json"], SQUARE));
    check_triangulation(&json, &SQUARE_POINTS);
    let out = run_stdin(&["triangulate", "-"], "0 0\n1 0\n0 1\n0 0\n1 1\n0 1\n");
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("merged 2 duplicate points"), "{text}");
    assert!(text.contains("criterion: delaunay"), "{text}");
    assert!(text.contains("triangles: 2"), "{text}");
    // Parse errors on stdin are named too.
    assert_fails(
        &run_stdin(&["triangulate", "-"], "0 0\n1 x\n"),
        &["<stdin>:2:", "'x'"],
    );
}

#[test]
fn duplicates_are_reported_with_input_indices() {
    let dir = scratch("dups");
    let input = write(&dir, "d.txt", "0 0\n2 0\n0 2\n2 0\n2 2\n0 0\n");
    let json = stdout_json(&run(&["triangulate", &input, "--json"]));
    assert_eq!(json["duplicates"], serde_json::json!([[3, 1], [5, 0]]));
    let points = [
        [0.0, 0.0],
        [2.0, 0.0],
        [0.0, 2.0],
        [2.0, 0.0],
        [2.0, 2.0],
        [0.0, 0.0],
    ];
    let t = check_triangulation(&json, &points);
    assert!(t.triangles().iter().flatten().all(|&i| i != 3 && i != 5));
}

#[test]
fn tsplib_file_with_a_duplicate_and_outputs() {
    let dir = scratch("tsplib");
    let input = tsplib("a280");
    let svg = dir.join("a280.svg");
    let ele = dir.join("a280.ele");
    let geojson = dir.join("a280.geojson");
    let out_json = dir.join("a280.json");
    let out = run(&[
        "triangulate",
        &input,
        "--json",
        "--output",
        svg.to_str().unwrap(),
        "-o",
        ele.to_str().unwrap(),
        "-o",
        geojson.to_str().unwrap(),
        "-o",
        out_json.to_str().unwrap(),
    ]);
    let json = stdout_json(&out);
    let points = file_points(&input);
    assert_eq!(points.len(), 280);
    let t = check_triangulation(&json, &points);
    // Nodes 171 and 172 (input indices 170, 171) coincide.
    assert_eq!(json["duplicates"], serde_json::json!([[171, 170]]));
    assert_eq!(json["stats"]["hull_points"], 44);
    let svg = std::fs::read_to_string(svg).unwrap();
    assert!(svg.starts_with("<svg"));
    assert_eq!(svg.matches("<line class=\"edge\"").count(), t.edges().len());
    let node = std::fs::read_to_string(dir.join("a280.node")).unwrap();
    assert_eq!(text_points(&node, optri::io::InputFormat::Node), points);
    assert!(std::fs::read_to_string(ele)
        .unwrap()
        .contains(&format!("\n{} 3 0\n", t.triangles().len())));
    let written: Value = serde_json::from_str(&std::fs::read_to_string(out_json).unwrap()).unwrap();
    let back = optri::io::triangulation_from_json(&written).unwrap();
    assert_eq!(back.triangles(), t.triangles());
    let g: Value = serde_json::from_str(&std::fs::read_to_string(geojson).unwrap()).unwrap();
    assert_eq!(
        g["features"].as_array().unwrap().len(),
        t.triangles().len() + 280
    );
}

#[test]
fn bad_inputs_fail_cleanly_with_the_line() {
    let dir = scratch("bad");
    let cases: &[(&str, &str, &[&str])] = &[
        ("nan.txt", "0 0\n1 0\nNaN 1\n", &["nan.txt:3:", "finite"]),
        ("inf.txt", "0 0\n1 inf\n0 1\n", &["inf.txt:2:", "finite"]),
        (
            "garbage.txt",
            "0 0\n1 0\n0 1\nhello world\n",
            &["garbage.txt:4:", "'hello'"],
        ),
        ("empty.txt", "", &["empty.txt", "no points"]),
        (
            "comments.txt",
            "# nothing\n\n",
            &["comments.txt", "no points"],
        ),
        (
            "two.txt",
            "0 0\n1 1\n",
            &["two.txt", "at least 3 distinct", "has 2"],
        ),
        ("dup3.txt", "0 0\n1 1\n0 0\n", &["at least 3 distinct"]),
        (
            "collinear.txt",
            "0 0\n1 1\n2 2\n3 3\n",
            &["collinear.txt", "collinear"],
        ),
        (
            "ragged.txt",
            "0 0\n1 0\n0 1 5\n",
            &["ragged.txt:3:", "columns"],
        ),
        (
            "range.txt",
            "0 0\n1 0\n0 1e300\n",
            &["range.txt:3:", "range"],
        ),
        (
            "bad.tsp",
            "DIMENSION: 4\nNODE_COORD_SECTION\n1 0 0\n2 1 0\n3 0 1\nEOF\n",
            &["bad.tsp:1:", "DIMENSION is 4"],
        ),
        (
            "bad.geojson",
            "{\"type\":\"LineString\",\"coordinates\":[[0,0],[1,1]]}",
            &["bad.geojson", "LineString"],
        ),
    ];
    for (name, contents, needles) in cases {
        let path = write(&dir, name, contents);
        assert_fails(&run(&["triangulate", &path]), needles);
        assert_fails(&run(&["triangulate", &path, "--json"]), needles);
        // Graphs are defined on two points and on collinear points.
        if !["two.txt", "dup3.txt", "collinear.txt"].contains(name) {
            assert_fails(&run(&["graph", &path, "--kind", "rng"]), needles);
        }
    }
}

#[test]
fn bad_arguments_fail_cleanly() {
    let dir = scratch("args");
    let input = write(&dir, "ok.txt", SQUARE);
    assert_fails(
        &run(&["triangulate", &input, "--criterion", "prettiest"]),
        &["unknown criterion 'prettiest'", "delaunay"],
    );
    let png = dir.join("out.png");
    assert_fails(
        &run(&["triangulate", &input, "-o", png.to_str().unwrap()]),
        &["out.png", ".svg", ".json", ".ele", ".geojson"],
    );
    assert!(!png.exists());
    let missing = dir.join("missing.txt");
    assert_fails(
        &run(&["triangulate", missing.to_str().unwrap()]),
        &["missing.txt"],
    );
    assert_fails(
        &run(&["triangulate", &input, "--input-format", "xml"]),
        &["unknown input format 'xml'", "tsplib"],
    );
    let unwritable = dir.join("no/such/dir/out.svg");
    assert_fails(
        &run(&["triangulate", &input, "-o", unwritable.to_str().unwrap()]),
        &["no/such/dir/out.svg"],
    );
    let ele = dir.join("g.ele");
    assert_fails(
        &run(&[
            "graph",
            &input,
            "--kind",
            "mst",
            "-o",
            ele.to_str().unwrap(),
        ]),
        &["g.ele", "not a triangulation"],
    );
    // Usage errors are clap's (exit 2), still without a panic.
    let out = run(&["graph", &input, "--kind", "voronoi"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("gabriel") && !err.contains("panicked"),
        "{err}"
    );
}

#[test]
fn explicit_input_format_overrides_the_extension() {
    let dir = scratch("format");
    let input = write(&dir, "points.dat", "3 2 0 0\n1 0 0\n2 5 0\n3 0 5\n");
    let json = stdout_json(&run(&[
        "triangulate",
        &input,
        "--input-format",
        "node",
        "--json",
    ]));
    check_triangulation(&json, &[[0.0, 0.0], [5.0, 0.0], [0.0, 5.0]]);
    // Unknown extension, no flag: recognised by content as a .node file.
    let json = stdout_json(&run(&["triangulate", &input, "--json"]));
    check_triangulation(&json, &[[0.0, 0.0], [5.0, 0.0], [0.0, 5.0]]);
    // Forced to text, the header row of a .node file is a ragged row.
    assert_fails(
        &run(&["triangulate", &input, "--input-format", "text"]),
        &["points.dat:2:", "columns"],
    );
}

#[test]
fn graph_kinds_match_the_library() {
    let dir = scratch("graph");
    let text = "0 0\n4 0\n4 4\n0 4\n1 1\n3 2\n2 0\n1 1\n2 3.5\n";
    let input = write(&dir, "g.txt", text);
    let points = text_points(text, optri::io::InputFormat::Text);
    let ps = PointSet::new(&points).unwrap();
    let sorted = |mut e: Vec<[u32; 2]>| {
        for x in &mut e {
            x.sort_unstable();
        }
        e.sort_unstable();
        e
    };
    let expected = [
        (
            "hull",
            sorted({
                let h = optri::convex_hull(&ps);
                (0..h.len()).map(|i| [h[i], h[(i + 1) % h.len()]]).collect()
            }),
        ),
        (
            "rng",
            sorted(optri::relative_neighborhood_graph(&ps).unwrap()),
        ),
        ("gabriel", sorted(optri::gabriel_graph(&ps).unwrap())),
        ("mst", sorted(optri::minimum_spanning_tree(&ps).unwrap())),
        ("delaunay", sorted(optri::delaunay(&ps).unwrap().edges())),
    ];
    for (kind, edges) in &expected {
        let json = stdout_json(&run(&["graph", &input, "--kind", kind, "--json"]));
        assert_eq!(json["kind"], *kind);
        assert_eq!(json["points"], 9);
        assert_eq!(json["duplicates"], serde_json::json!([[7, 4]]));
        let got: Vec<[u32; 2]> = serde_json::from_value(json["edges"].clone()).unwrap();
        assert_eq!(&sorted(got), edges, "{kind}");
        assert!(json["timing_ms"]["total"].is_number());
    }
    // The hull includes the collinear point (2, 0); the MST is a tree.
    let hull = &expected[0].1;
    assert_eq!(hull.len(), 5);
    assert_eq!(expected[3].1.len(), 7);
    let svg = dir.join("mst.svg");
    let out = run(&[
        "graph",
        &input,
        "--kind",
        "mst",
        "-o",
        svg.to_str().unwrap(),
    ]);
    assert!(out.status.success());
    let svg = std::fs::read_to_string(svg).unwrap();
    assert_eq!(svg.matches("<line class=\"edge\"").count(), 7);
}

/// The panel titles of an SVG written by optri.
fn svg_titles(svg: &str) -> Vec<String> {
    svg.split("<text class=\"title\"")
        .skip(1)
        .map(|rest| {
            let text = &rest[rest.find('>').unwrap() + 1..];
            text[..text.find("</text>").unwrap()].to_string()
        })
        .collect()
}

#[test]
fn demo_draws_every_criterion() {
    let dir = scratch("demo");
    let out = Command::new(BIN)
        .arg("demo")
        .current_dir(&dir)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let svg = std::fs::read_to_string(dir.join("demo.svg")).unwrap();
    assert!(svg.starts_with("<svg"));
    let text = String::from_utf8_lossy(&out.stdout);
    let titles = svg_titles(&svg);
    assert_eq!(svg.matches("<g class=\"panel\"").count(), titles.len());
    // Every registered criterion has a panel (none is skipped), and every
    // panel says which point set it shows.
    for c in optri::Criterion::ALL {
        let prefix = format!("{} (", c.name());
        assert!(
            titles.iter().any(|t| t.starts_with(&prefix)),
            "{} has no panel: {titles:?}",
            c.name()
        );
        assert!(
            text.lines().any(|l| l.starts_with(&prefix)),
            "{} has no table row: {text}",
            c.name()
        );
    }
    assert!(
        titles.iter().all(|t| t.ends_with("— demo set")
            || t.ends_with("— convex set")
            || t.ends_with("— polygon set")),
        "{titles:?}"
    );
    // Min-weight takes any point set now: drawn on the demo set, exact.
    assert!(
        titles.contains(&"min-weight (exact) — demo set".to_string()),
        "{titles:?}"
    );
    let row = |label: &str, set: &str| {
        text.lines()
            .any(|l| l.starts_with(label) && l.split_whitespace().nth(2) == Some(set))
    };
    assert!(row("min-weight (exact)", "demo"), "{text}");
    assert!(row("greedy (exact)", "demo"), "{text}");
    assert!(row("delaunay (exact)", "demo"), "{text}");
    // The area criteria take any point set (exact in convex position, a
    // certified approximation otherwise): drawn on the demo set, labelled by
    // what was proven.
    for name in ["maxmin-area", "minmax-area"] {
        let drawn = ["exact", "uncertified"]
            .iter()
            .any(|how| row(&format!("{name} ({how})"), "demo"));
        assert!(drawn, "{name}: {text}");
    }
    // The polygon set: min-weight and minmax-area inside a simple polygon,
    // with its boundary drawn.
    for title in [
        "min-weight (exact) — polygon set",
        "minmax-area (exact) — polygon set",
    ] {
        assert!(titles.contains(&title.to_string()), "{titles:?}");
    }
    assert_eq!(svg.matches("<polygon class=\"boundary\"").count(), 2);
    assert!(
        text.contains("polygon set: a simple polygon of 12 vertices"),
        "{text}"
    );
    assert!(!text.contains("skipped"), "{text}");
    assert!(text.contains("merged 1 duplicate point"), "{text}");
    // Every criterion takes the demo set now: no convex set is needed.
    assert!(!text.contains("convex set:"), "{text}");
    let custom = dir.join("d2.svg");
    assert!(run(&["demo", "-o", custom.to_str().unwrap()])
        .status
        .success());
    assert!(custom.exists());
    assert_fails(
        &run(&["demo", "-o", dir.join("d.json").to_str().unwrap()]),
        &["d.json", ".svg"],
    );
}

/// Runs `args` with stdout (or stderr) on `/dev/full`, where every write fails.
#[cfg(target_os = "linux")]
fn run_into_dev_full(args: &[&str], stderr_too: bool) -> Output {
    let full = || {
        std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .unwrap()
    };
    let mut command = Command::new(BIN);
    command.args(args).stdout(full());
    if stderr_too {
        command.stderr(full());
    }
    command.output().unwrap()
}

#[cfg(target_os = "linux")]
#[test]
fn a_full_disk_on_stdout_or_stderr_is_a_clean_failure() {
    let dir = scratch("full");
    let input = write(&dir, "ok.txt", SQUARE);
    let svg = dir.join("d.svg");
    let svg = svg.to_str().unwrap();
    for args in [
        &["demo", "-o", svg][..],
        &["triangulate", &input, "--json"],
        &["triangulate", &input],
        &["graph", &input, "--kind", "mst"],
    ] {
        assert_fails(
            &run_into_dev_full(args, false),
            &["cannot write to stdout", "No space left"],
        );
    }
    // --help is printed by clap, which would otherwise exit 0 regardless.
    assert_fails(
        &run_into_dev_full(&["--help"], false),
        &["cannot write to stdout"],
    );
    // With stderr full too there is no message, but still exit code 1, not
    // a panic's 101.
    let missing = dir.join("missing.txt");
    let out = run_into_dev_full(&["triangulate", missing.to_str().unwrap()], true);
    assert_eq!(out.status.code(), Some(1));
    let out = run_into_dev_full(&["triangulate", &input, "--json"], true);
    assert_eq!(out.status.code(), Some(1));
}

#[test]
fn a_closed_stdout_pipe_is_a_clean_failure() {
    // The child blocks on stdin until the reading end of its stdout is
    // closed, so its write always meets a closed pipe (like `| true`).
    for args in [&["triangulate", "-", "--json"][..], &["triangulate", "-"]] {
        let mut child = Command::new(BIN)
            .args(args)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        drop(child.stdout.take());
        child
            .stdin
            .take()
            .unwrap()
            .write_all(SQUARE.as_bytes())
            .unwrap();
        let out = child.wait_with_output().unwrap();
        assert_fails(&out, &["cannot write to stdout", "pipe was closed"]);
    }
}

#[test]
fn every_tsplib_file_matches_its_readme_counts() {
    // (file, DIMENSION, duplicate coords, hull points incl. collinear) from
    // the TSPLIB README (crates/optri-oracle/data/tsplib/README.md),
    // computed there independently.
    let expected = [
        ("berlin52", 52, 0, 8),
        ("kroA100", 100, 0, 12),
        ("ch150", 150, 0, 15),
        ("a280", 280, 1, 44),
        ("lin318", 318, 0, 11),
        ("pr1002", 1002, 0, 31),
        ("u1060", 1060, 0, 24),
        ("vm1084", 1084, 0, 380),
        ("pcb3038", 3038, 0, 10),
        ("fl1577", 1577, 0, 85),
        ("fnl4461", 4461, 0, 21),
        ("att532", 532, 0, 12),
        ("ali535", 535, 29, 10),
        ("ts225", 225, 0, 96),
    ];
    for (name, n, duplicates, hull) in expected {
        let input = tsplib(name);
        let json = stdout_json(&run(&["triangulate", &input, "--json"]));
        assert_eq!(json["points"], n, "{name}");
        assert_eq!(
            json["duplicates"].as_array().unwrap().len(),
            duplicates,
            "{name}"
        );
        assert_eq!(json["stats"]["hull_points"], hull, "{name}");
        // 2n - h - 2 triangles over the distinct points.
        assert_eq!(
            json["stats"]["triangles"],
            2 * (n - duplicates) - hull - 2,
            "{name}"
        );
    }
}

#[test]
fn an_ele_output_never_overwrites_the_input_node_file() {
    let dir = scratch("ele-input");
    let node_text = "4 2 0 0\n0 0 0\n1 4 0\n2 4 4\n3 1 3\n";
    let input = write(&dir, "pts.node", node_text);
    // The same file however it is spelled: canonical paths are compared.
    let spellings = [
        dir.join("pts.ele"),
        dir.join(".").join("pts.ele"),
        dir.join("sub/../pts.ELE"),
    ];
    std::fs::create_dir_all(dir.join("sub")).unwrap();
    for ele in &spellings {
        assert_fails(
            &run(&["triangulate", &input, "-o", ele.to_str().unwrap()]),
            &[
                "refusing to overwrite the input file",
                "pts.node",
                ".node beside it",
            ],
        );
    }
    // Relative paths from another working directory, with a harmless output
    // first: nothing at all is written.
    let svg = dir.join("first.svg");
    let out = Command::new(BIN)
        .args([
            "triangulate",
            "pts.node",
            "-o",
            svg.to_str().unwrap(),
            "-o",
            "pts.ele",
        ])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert_fails(&out, &["pts.node"]);
    assert!(!svg.exists() && !dir.join("pts.ele").exists());
    assert_eq!(
        std::fs::read_to_string(dir.join("pts.node")).unwrap(),
        node_text
    );
    // An output that is the input itself is refused as well.
    let json_input = write(&dir, "t.json", r#"{"points":[[0,0],[1,0],[0,1]]}"#);
    assert_fails(
        &run(&["triangulate", &json_input, "-o", &json_input]),
        &["refusing to overwrite the input file", "t.json"],
    );
    assert_fails(
        &run(&["graph", &json_input, "--kind", "mst", "-o", &json_input]),
        &["refusing to overwrite the input file"],
    );
    // Another name is fine and writes its own .node.
    let other = dir.join("tri.ele");
    let out = run(&["triangulate", &input, "-o", other.to_str().unwrap()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(file_points(dir.join("tri.node")), file_points(&input));
    // --help says that .ele writes the .node too.
    let help = String::from_utf8_lossy(&run(&["triangulate", "--help"]).stdout).into_owned();
    assert!(
        help.contains(".ele") && help.contains("X.ele writes X.node"),
        "{help}"
    );
}

#[test]
fn geojson_output_reads_back_as_the_same_points() {
    let dir = scratch("geojson-round-trip");
    let input = write(&dir, "d.txt", "0 0\n4 0\n4 4\n0 4\n1 1\n3 2\n4 0\n");
    let geojson = dir.join("t.geojson");
    let first = stdout_json(&run(&[
        "triangulate",
        &input,
        "--json",
        "-o",
        geojson.to_str().unwrap(),
    ]));
    let points = file_points(&input);
    // The triangles (Polygons) are skipped; the Point features give every
    // input point, duplicate included, in input order.
    assert_eq!(file_points(&geojson), points);
    let again = stdout_json(&run(&["triangulate", geojson.to_str().unwrap(), "--json"]));
    assert_eq!(again["points"], 7);
    assert_eq!(again["duplicates"], first["duplicates"]);
    assert_eq!(again["triangles"], first["triangles"]);
    // A graph's GeoJSON (LineStrings and Points) reads back too.
    let graph = dir.join("g.geojson");
    let out = run(&[
        "graph",
        &input,
        "--kind",
        "rng",
        "-o",
        graph.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(file_points(&graph), points);
}

/// Points strictly in convex position, not semicircular: a hexagon.
const HEXAGON: &str = "2 0\n1 1.75\n-1 1.75\n-2 0\n-1 -1.75\n1 -1.75\n";
/// A semicircular convex polygon: every vertex strictly inside the circle on
/// the longest edge (points on the parabola y = (16 - x^2) / 8).
const SEMICIRCULAR: &str = "-4 0\n4 0\n-3 0.875\n-2 1.5\n-1 1.875\n0 2\n1 1.875\n2 1.5\n3 0.875\n";

/// A fan: five points on a line and an apex (its only triangulation).
const FAN: &str = "0 0\n1 0\n2 0\n3 0\n4 0\n1.5 2\n";

/// Sum of the edge lengths of the JSON `triangles`, each edge once.
fn total_length(json: &Value, points: &[[f64; 2]]) -> f64 {
    let t = check_triangulation(json, points);
    t.edges()
        .iter()
        .map(|&[a, b]| {
            let (p, q) = (points[a as usize], points[b as usize]);
            (p[0] - q[0]).hypot(p[1] - q[1])
        })
        .sum()
}

#[test]
fn greedy_names_its_algorithm_and_matches_the_library() {
    let cases = [
        (SQUARE, "general"),
        (HEXAGON, "convex"),
        (SEMICIRCULAR, "semicircular"),
        (FAN, "fan"),
    ];
    for (text, algorithm) in cases {
        let json = stdout_json(&run_stdin(
            &["triangulate", "-", "--criterion", "greedy", "--json"],
            text,
        ));
        assert_eq!(json["criterion"], "greedy");
        assert_eq!(json["exact"], true);
        assert_eq!(json["algorithm"], *algorithm);
        let detail = json["algorithm_detail"].as_str().unwrap();
        assert!(detail.starts_with(&format!("{algorithm} (")), "{detail}");
        let points = text_points(text, optri::io::InputFormat::Text);
        let lib =
            optri::triangulate(&PointSet::new(&points).unwrap(), optri::Criterion::Greedy).unwrap();
        let triangles: Vec<[u32; 3]> = serde_json::from_value(json["triangles"].clone()).unwrap();
        assert_eq!(triangles, lib.triangulation.triangles(), "{algorithm}");
        let reported = json["stats"]["total_edge_length"].as_f64().unwrap();
        let summed = total_length(&json, &points);
        assert!(
            (reported - summed).abs() <= 1e-12 * summed,
            "{reported} {summed}"
        );
    }
}

#[test]
fn min_weight_takes_any_point_set_and_is_certified_exact() {
    for input in [SQUARE, HEXAGON] {
        let points = text_points(input, optri::io::InputFormat::Text);
        let json = stdout_json(&run_stdin(
            &["triangulate", "-", "--criterion", "min-weight", "--json"],
            input,
        ));
        assert_eq!(json["criterion"], "min-weight");
        // Sums of square roots are compared exactly.
        assert_eq!(json["exact"], true);
        let weight = json["stats"]["total_edge_length"].as_f64().unwrap();
        assert!((weight - total_length(&json, &points)).abs() <= 1e-12 * weight);
        // No triangulation is lighter, the greedy one included.
        let greedy = stdout_json(&run_stdin(
            &["triangulate", "-", "--criterion", "greedy", "--json"],
            input,
        ));
        assert!(weight <= greedy["stats"]["total_edge_length"].as_f64().unwrap() * (1.0 + 1e-12));
    }
}

#[test]
fn criterion_names_are_case_insensitive() {
    let json = stdout_json(&run_stdin(
        &["triangulate", "-", "--criterion", "DELAUNAY", "--json"],
        SQUARE,
    ));
    assert_eq!(json["criterion"], "delaunay");
    let json = stdout_json(&run_stdin(
        &["triangulate", "-", "--criterion", "MinMax-Length", "--json"],
        SQUARE,
    ));
    assert_eq!(json["criterion"], "minmax-length");
    let json = stdout_json(&run_stdin(
        &["triangulate", "-", "--criterion", "Min-Weight", "--json"],
        HEXAGON,
    ));
    assert_eq!(json["criterion"], "min-weight");
    let available: Vec<&str> = optri::Criterion::ALL.iter().map(|c| c.name()).collect();
    assert_fails(
        &run_stdin(&["triangulate", "-", "--criterion", "Prettiest"], SQUARE),
        &["unknown criterion 'Prettiest'", &available.join(", ")],
    );
}

/// `doc` without its `timing_ms`, which differs from run to run (and a file
/// written before the run ends has no `write` or `total` phase).
fn untimed(doc: &Value) -> Value {
    let mut doc = doc.clone();
    doc.as_object_mut().unwrap().remove("timing_ms");
    doc
}

#[test]
fn json_on_stdout_and_a_json_file_are_one_document_that_reads_back() {
    let dir = scratch("one-schema");
    let input = tsplib("berlin52");
    let file = dir.join("b.json");
    let out = run(&[
        "triangulate",
        &input,
        "--criterion",
        "greedy",
        "--json",
        "-o",
        file.to_str().unwrap(),
    ]);
    let stdout = stdout_json(&out);
    let written: Value = serde_json::from_str(&std::fs::read_to_string(&file).unwrap()).unwrap();
    let keys = |v: &Value| v.as_object().unwrap().keys().cloned().collect::<Vec<_>>();
    assert_eq!(keys(&stdout), keys(&written));
    assert_eq!(untimed(&stdout), untimed(&written));
    assert_eq!(stdout["schema_version"], optri::io::SCHEMA_VERSION);
    assert_eq!(stdout["document"], "triangulation");
    assert_eq!(stdout["optimality"], "exact");
    assert_eq!(stdout["points"], 52);
    assert_eq!(stdout["coordinates"].as_array().unwrap().len(), 52);
    assert!(stdout["diagnostics"].is_object());
    assert!(stdout["timing_ms"]["write"].is_number() && written["timing_ms"]["write"].is_null());
    // The file reads back as the same triangulation, and as a point file.
    let back = optri::io::triangulation_from_json(&written).unwrap();
    let triangles: Vec<[u32; 3]> = serde_json::from_value(stdout["triangles"].clone()).unwrap();
    assert_eq!(back.triangles(), triangles);
    let again = stdout_json(&run(&[
        "triangulate",
        file.to_str().unwrap(),
        "--criterion",
        "greedy",
        "--json",
    ]));
    assert_eq!(again["triangles"], stdout["triangles"]);
    // The same for a graph.
    let file = dir.join("g.json");
    let out = run(&[
        "graph",
        &input,
        "--kind",
        "gabriel",
        "--json",
        "-o",
        file.to_str().unwrap(),
    ]);
    let stdout = stdout_json(&out);
    let written: Value = serde_json::from_str(&std::fs::read_to_string(&file).unwrap()).unwrap();
    assert_eq!(keys(&stdout), keys(&written));
    assert_eq!(untimed(&stdout), untimed(&written));
    assert_eq!(stdout["document"], "graph");
    assert_eq!(file_points(&file), file_points(&input));
}

#[test]
fn help_and_names_come_from_the_library_registry() {
    let help = String::from_utf8_lossy(&run(&["triangulate", "--help"]).stdout).into_owned();
    for c in optri::Criterion::ALL {
        assert!(
            help.contains(c.name()) && help.contains(c.description()),
            "{} missing from {help}",
            c.name()
        );
    }
    let help = String::from_utf8_lossy(&run(&["graph", "--help"]).stdout).into_owned();
    for k in optri::GraphKind::ALL {
        assert!(
            help.contains(k.name()) && help.contains(k.description()),
            "{} missing from {help}",
            k.name()
        );
    }
    // Graph kinds are case-insensitive; an unknown one gets the library's
    // message as a usage error.
    let json = stdout_json(&run_stdin(
        &["graph", "-", "--kind", "MsT", "--json"],
        SQUARE,
    ));
    assert_eq!(json["kind"], "mst");
    let out = run_stdin(&["graph", "-", "--kind", "voronoi"], SQUARE);
    assert_eq!(out.status.code(), Some(2));
    let expected = optri::GraphKind::from_name("voronoi")
        .unwrap_err()
        .to_string();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains(&expected), "{err}");
}

/// An L-shaped hexagon as a GeoJSON Feature (closed ring, clockwise) and the
/// same ring as a Triangle `.poly` (1-based, segments in order).
const L_RING: [[f64; 2]; 6] = [
    [0.0, 0.0],
    [0.0, 2.0],
    [1.0, 2.0],
    [1.0, 1.0],
    [2.0, 1.0],
    [2.0, 0.0],
];
const L_GEOJSON: &str = r#"{"type":"Feature","properties":{"name":"L"},"geometry":{"type":"Polygon",
    "coordinates":[[[0,0],[0,2],[1,2],[1,1],[2,1],[2,0],[0,0]]]}}"#;
const L_POLY: &str = "# an L\n6 2 0 1\n1 0 0 1\n2 0 2 1\n3 1 2 1\n4 1 1 1\n5 2 1 1\n6 2 0 1\n\
                      6 1\n1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 5 1\n5 5 6 1\n6 6 1 1\n0\n";

#[test]
fn polygon_inputs_are_triangulated_inside_by_every_polygon_criterion() {
    let dir = scratch("polygons");
    let geojson = write(&dir, "l.geojson", L_GEOJSON);
    let poly = write(&dir, "l.poly", L_POLY);
    let polygon = optri::SimplePolygon::new(&L_RING).unwrap();
    let n = L_RING.len();
    let mut tested = 0;
    for input in [&geojson, &poly] {
        for c in optri::Criterion::ALL
            .iter()
            .filter(|c| c.accepts(optri::InputKind::SimplePolygon))
        {
            if c.info().needs_elevations {
                // The ring has no z: refused, naming what is missing.
                let out = run(&["triangulate", input, "--criterion", c.name()]);
                assert!(!out.status.success(), "{input} {}", c.name());
                let stderr = String::from_utf8_lossy(&out.stderr);
                assert!(stderr.contains("needs an elevation"), "{stderr}");
                continue;
            }
            let json = stdout_json(&run(&[
                "triangulate",
                input,
                "--criterion",
                c.name(),
                "--json",
            ]));
            assert_eq!(json["domain"], "polygon", "{input} {}", c.name());
            assert_eq!(json["criterion"], c.name());
            assert_eq!(json["coordinates"], serde_json::json!(L_RING));
            let triangles: Vec<[u32; 3]> =
                serde_json::from_value(json["triangles"].clone()).unwrap();
            assert_eq!(triangles.len(), n - 2, "{input} {}", c.name());
            assert!(triangles.iter().flatten().all(|&i| (i as usize) < n));
            // The triangles cover the polygon exactly, and match the library.
            optri::Triangulation::from_polygon_triangles(&polygon, triangles.clone()).unwrap();
            let lib = optri::triangulate(&polygon, *c).unwrap();
            assert_eq!(triangles, lib.triangulation.triangles(), "{}", c.name());
            let back = optri::io::triangulation_from_json(&json).unwrap();
            assert_eq!(back.triangles(), &triangles[..]);
            tested += 1;
        }
    }
    assert!(tested >= 2 * 6, "{tested}");
    // The summary names the domain; the outputs are written, the SVG with
    // the boundary.
    let svg = dir.join("l.svg");
    let ele = dir.join("l.ele");
    let out = run(&[
        "triangulate",
        &poly,
        "--criterion",
        "minmax-area",
        "-o",
        svg.to_str().unwrap(),
        "-o",
        ele.to_str().unwrap(),
        "-o",
        dir.join("l-out.geojson").to_str().unwrap(),
        "-o",
        dir.join("l.json").to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("domain: polygon interior (6 vertices, given clockwise)"),
        "{text}"
    );
    let svg = std::fs::read_to_string(svg).unwrap();
    assert_eq!(svg.matches("<polygon class=\"boundary\"").count(), 1);
    let ele = std::fs::read_to_string(ele).unwrap();
    assert!(ele.lines().any(|l| l == "4 3 0"), "{ele}");
    let file: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("l.json")).unwrap()).unwrap();
    assert_eq!(file["domain"], "polygon");
    // Stdin with an explicit format.
    let json = stdout_json(&run_stdin(
        &["triangulate", "-", "--input-format", "poly", "--json"],
        L_POLY,
    ));
    assert_eq!(json["domain"], "polygon");
    // A point file's document says its domain too.
    let points = write(&dir, "square.csv", SQUARE);
    let json = stdout_json(&run(&["triangulate", &points, "--json"]));
    assert_eq!(json["domain"], "convex-hull");
    // `graph` reads a .poly's vertices as points.
    let json = stdout_json(&run(&["graph", &poly, "--kind", "hull", "--json"]));
    assert_eq!(json["points"], n);
}

#[test]
fn bad_polygons_fail_cleanly_naming_what_is_wrong() {
    let dir = scratch("bad-polygons");
    let bow = write(
        &dir,
        "bow.geojson",
        r#"{"type":"Polygon","coordinates":[[[0,0],[2,2],[2,0],[0,2],[0,0]]]}"#,
    );
    assert_fails(
        &run(&["triangulate", &bow, "--criterion", "minmax-area"]),
        &["bow.geojson", "edge 0-1 meets edge 2-3"],
    );
    let holes = write(
        &dir,
        "holes.geojson",
        r#"{"type":"FeatureCollection","features":[{"type":"Feature","geometry":{"type":"Polygon",
        "coordinates":[[[0,0],[4,0],[4,4],[0,4],[0,0]],[[1,1],[1,2],[2,2],[1,1]]]}}]}"#,
    );
    assert_fails(
        &run(&["triangulate", &holes]),
        &[
            "holes.geojson",
            "features[0].geometry",
            "holes are not supported yet",
        ],
    );
    let poly_holes = write(&dir, "h.poly", &L_POLY.replace("\n0\n", "\n1\n1 0.5 0.5\n"));
    assert_fails(
        &run(&["triangulate", &poly_holes]),
        &["h.poly:16:", "holes are not supported yet"],
    );
    // Two cycles in a .poly name the line of the second.
    let two = write(
        &dir,
        "two.poly",
        "6 2\n0 0 0\n1 1 0\n2 0 1\n3 5 5\n4 6 5\n5 5 6\n6 0\n\
         0 0 1\n1 1 2\n2 2 0\n3 3 4\n4 4 5\n5 5 3\n",
    );
    assert_fails(
        &run(&["triangulate", &two]),
        &["two.poly:12:", "more than one cycle"],
    );
    // A self-intersecting .poly ring is caught by the polygon check.
    let crossing = write(
        &dir,
        "x.poly",
        "4 2\n0 0 0\n1 2 2\n2 2 0\n3 0 2\n4 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n",
    );
    assert_fails(
        &run(&["triangulate", &crossing]),
        &["x.poly", "edge 0-1 meets edge 2-3"],
    );
}

/// `x y z` points with a duplicate (index 6 of index 1).
const TERRAIN: &str = "0 0 1\n4 0 2\n4 4 3.5\n0 4 -1\n1 1 0.25\n3 2 7\n4 0 2\n";

#[test]
fn triangulate_writes_obj_ply_and_off_meshes() {
    let dir = scratch("meshes");
    let input = write(&dir, "terrain.txt", TERRAIN);
    let path = |name: &str| dir.join(name).to_str().unwrap().to_string();
    let (obj, ply, off, ascii) = (path("t.obj"), path("t.ply"), path("t.off"), path("a.ply"));
    let args = [
        "triangulate",
        &input,
        "--json",
        "-o",
        &obj,
        "-o",
        &ply,
        "-o",
        &off,
    ];
    let json = stdout_json(&run(&args));
    let triangles: Vec<[u32; 3]> = serde_json::from_value(json["triangles"].clone()).unwrap();
    let points = file_points(&input);
    let z = [1.0, 2.0, 3.5, -1.0, 0.25, 7.0, 2.0];
    // OBJ and PLY read back as the input points with their elevations.
    for file in [&obj, &ply] {
        let source = optri::io::Source::Path(std::path::Path::new(file));
        let read = optri::io::read(source, &optri::io::ReadOptions::default()).unwrap();
        assert_eq!(read.input.points(), points, "{file}");
        assert_eq!(read.elevations.as_deref(), Some(&z[..]), "{file}");
    }
    // Binary by default, ASCII on request.
    let head = |file: &str| std::fs::read(file).unwrap()[..40].to_vec();
    assert!(String::from_utf8_lossy(&head(&ply)).contains("format binary_little_endian 1.0"));
    let out = run(&["triangulate", &input, "--ply-ascii", "-o", &ascii]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&head(&ascii)).contains("format ascii 1.0"));
    // The faces are the document's triangles, in every format.
    let off_text = std::fs::read_to_string(&off).unwrap();
    let off_faces: Vec<[u32; 3]> = off_text
        .lines()
        .skip(2 + points.len())
        .map(|l| {
            let f: Vec<u32> = l.split(' ').map(|t| t.parse().unwrap()).collect();
            assert_eq!(f[0], 3);
            [f[1], f[2], f[3]]
        })
        .collect();
    assert_eq!(off_faces, triangles);
    assert!(off_text.starts_with(&format!("OFF\n7 {} 0\n0 0 1\n4 0 2\n", triangles.len())));
    let obj_faces: Vec<[u32; 3]> = std::fs::read_to_string(&obj)
        .unwrap()
        .lines()
        .filter_map(|l| l.strip_prefix("f "))
        .map(|l| {
            let f: Vec<u32> = l
                .split(' ')
                .map(|t| t.parse::<u32>().unwrap() - 1)
                .collect();
            [f[0], f[1], f[2]]
        })
        .collect();
    assert_eq!(obj_faces, triangles);
    // A graph goes to OBJ, not to OFF, which is refused naming the format.
    let g_obj = path("g.obj");
    let out = run(&["graph", &input, "--kind", "mst", "-o", &g_obj]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let lines = std::fs::read_to_string(&g_obj).unwrap();
    assert_eq!(lines.lines().filter(|l| l.starts_with("l ")).count(), 5);
    let g_off = path("g.off");
    assert_fails(
        &run(&["graph", &input, "--kind", "mst", "-o", &g_off]),
        &["g.off", "OFF holds faces"],
    );
}

#[test]
fn triangulate_reads_ply_and_obj_meshes() {
    let dir = scratch("mesh-inputs");
    let input = write(&dir, "terrain.txt", TERRAIN);
    let ply = dir.join("t.ply").to_str().unwrap().to_string();
    let first = stdout_json(&run(&["triangulate", &input, "--json", "-o", &ply]));
    // The binary PLY, by its extension, and as content on stdin in ASCII.
    let again = stdout_json(&run(&["triangulate", &ply, "--json", "-q"]));
    for key in ["coordinates", "elevations", "triangles", "duplicates"] {
        assert_eq!(again[key], first[key], "{key}");
    }
    let ascii = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n\
                 property uchar red\nelement face 1\nproperty list uchar int vertex_index\n\
                 end_header\n0 0 9\n4 0 9\n4 4 9\n0 4 9\n4 0 1 2 3\n";
    let out = run_stdin(&["triangulate", "-", "--json"], ascii);
    let json = stdout_json(&out);
    assert_eq!(json["points"], 4);
    assert!(json["elevations"].is_null());
    let warnings = String::from_utf8_lossy(&out.stderr);
    assert!(
        warnings.contains("<stdin>: vertex properties ignored: 'red'")
            && warnings.contains("'face' (1 items) ignored"),
        "{warnings}"
    );
    // OBJ by its extension; a bad vertex names its line.
    let obj = write(
        &dir,
        "m.obj",
        "o m\nv 0 0 1\nv 4 0 2\nvn 0 0 1\nv 0 4 3\nf 1 2 3\n",
    );
    let json = stdout_json(&run(&["triangulate", &obj, "--json", "-q"]));
    assert_eq!(json["elevations"], serde_json::json!([1.0, 2.0, 3.0]));
    let bad = write(&dir, "bad.obj", "v 0 0\nv 1 x\n");
    assert_fails(
        &run(&["triangulate", &bad]),
        &["bad.obj:2: 'x' is not a number"],
    );
}
