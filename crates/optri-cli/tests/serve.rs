//! The web playground's API end to end: `optri serve --port 0` in a child
//! process, plain HTTP/1.1 requests over a TCP socket, and the answers
//! checked against the library (the same documents as `triangulate --json`
//! and `compare --json`) and for their 4xx/503 refusals.

use optri::io::triangulation_from_json;
use serde_json::{json, Value};
use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::process::{Child, Command, Stdio};

const BIN: &str = env!("CARGO_BIN_EXE_optri");

/// A running `optri serve`, killed when dropped.
struct Server {
    child: Child,
    address: String,
}

impl Server {
    fn start(extra: &[&str]) -> Server {
        let mut child = Command::new(BIN)
            .args(["serve", "--port", "0"])
            .args(extra)
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .unwrap();
        let mut line = String::new();
        BufReader::new(child.stdout.take().unwrap())
            .read_line(&mut line)
            .unwrap();
        // "optri serve: listening on http://127.0.0.1:PORT/ (Ctrl-C stops)"
        let address = line
            .split("http://")
            .nth(1)
            .and_then(|rest| rest.split('/').next())
            .unwrap_or_else(|| panic!("no address in {line:?}"))
            .to_string();
        Server { child, address }
    }

    /// Sends one request; returns the status and the body.
    fn request(&self, method: &str, path: &str, body: &[u8]) -> (u16, String) {
        let mut stream = TcpStream::connect(&self.address).unwrap();
        let head = format!(
            "{method} {path} HTTP/1.1\r\nHost: {}\r\nContent-Type: application/json\r\n\
             Content-Length: {}\r\nConnection: close\r\n\r\n",
            self.address,
            body.len()
        );
        stream.write_all(head.as_bytes()).unwrap();
        // The server may answer (413) before reading a large body.
        let _ = stream.write_all(body);
        let mut answer = Vec::new();
        stream.read_to_end(&mut answer).unwrap();
        let answer = String::from_utf8(answer).unwrap();
        let status: u16 = answer
            .split(' ')
            .nth(1)
            .and_then(|s| s.parse().ok())
            .unwrap_or_else(|| panic!("no status in {answer:?}"));
        let body = answer
            .split_once("\r\n\r\n")
            .map_or("", |(_, b)| b)
            .to_string();
        (status, body)
    }

    fn post(&self, path: &str, body: &Value) -> (u16, Value) {
        let (status, text) = self.request("POST", path, body.to_string().as_bytes());
        (status, serde_json::from_str(&text).unwrap())
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// 5 points: a square and an interior point (not in convex position).
fn square_and_centre() -> Value {
    json!([[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0], [1.0, 1.0]])
}

/// The error message of a refusal, checked for its status.
fn refused(answer: (u16, Value), status: u16) -> String {
    assert_eq!(answer.0, status, "{}", answer.1);
    answer.1["error"]
        .as_str()
        .unwrap_or_else(|| panic!("no error message in {}", answer.1))
        .to_string()
}

#[test]
fn the_page_and_the_criteria_come_from_the_binary_and_the_registry() {
    let server = Server::start(&[]);
    let (status, page) = server.request("GET", "/", b"");
    assert_eq!(status, 200);
    assert!(page.contains("<title>optri playground</title>"), "{page}");
    // Offline: the page loads nothing from elsewhere (the only URL in it is
    // the SVG namespace).
    for remote in [
        "src=\"http",
        "href=\"http",
        "https://",
        "url(http",
        "import ",
    ] {
        assert!(!page.contains(remote), "the page must not load {remote}…");
    }
    let (status, text) = server.request("GET", "/api/criteria", b"");
    assert_eq!(status, 200);
    let v: Value = serde_json::from_str(&text).unwrap();
    let names: Vec<&str> = v["criteria"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["name"].as_str().unwrap())
        .collect();
    let registry: Vec<&str> = optri::Criterion::ALL.iter().map(|c| c.name()).collect();
    assert_eq!(names, registry);
    // The same document as `optri criteria --json` and Python's registry().
    assert_eq!(v, optri::io::registry_listing());
    let (status, text) = server.request("GET", "/api/limits", b"");
    assert_eq!(status, 200);
    let v: Value = serde_json::from_str(&text).unwrap();
    assert_eq!(v["max_body_bytes"], 8 * 1024 * 1024);
}

#[test]
fn triangulate_answers_the_document_of_triangulate_json() {
    let server = Server::start(&[]);
    for criterion in ["minmax-length", "GREEDY", "delaunay"] {
        let (status, doc) = server.post(
            "/api/triangulate",
            &json!({"points": square_and_centre(), "criterion": criterion}),
        );
        assert_eq!(status, 200, "{doc}");
        assert_eq!(doc["document"], "triangulation");
        assert_eq!(doc["criterion"], criterion.to_ascii_lowercase());
        // Re-validated exactly; 2n - h - 2 = 4 triangles.
        let t = triangulation_from_json(&doc).unwrap();
        assert_eq!(t.triangles().len(), 4);
        let stats = &doc["stats"];
        for key in ["longest_edge", "smallest_triangle", "largest_triangle"] {
            assert!(stats[key].is_array(), "{key}: {stats}");
        }
        assert!(doc["timing_ms"]["total"].is_number());
        // The document of `optri triangulate --json` on the same points:
        // every field equal but the timings, which the CLI takes around
        // reading a file.
        let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("serve-triangulate");
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("square.txt");
        std::fs::write(&file, "0 0\n4 0\n4 3\n0 3\n1 1\n").unwrap();
        let out = Command::new(BIN)
            .args([
                "triangulate",
                file.to_str().unwrap(),
                "--json",
                "--criterion",
                criterion,
            ])
            .output()
            .unwrap();
        assert!(out.status.success());
        let mut cli: Value = serde_json::from_slice(&out.stdout).unwrap();
        // The file's decimals and the request's short JSON numbers are both
        // taken at their decimal values.
        assert_eq!(cli["coordinate_arithmetic"], json!("decimal-exact"));
        let mut web = doc.clone();
        cli.as_object_mut().unwrap().remove("timing_ms");
        web.as_object_mut().unwrap().remove("timing_ms");
        assert_eq!(web, cli);
        let _ = std::fs::remove_dir_all(&dir);
    }
    // A polygon: the points are a ring (an L-shape, clockwise).
    let l = json!([[0, 0], [0, 2], [1, 2], [1, 1], [2, 1], [2, 0]]);
    let (status, doc) = server.post(
        "/api/triangulate",
        &json!({"points": l, "criterion": "minmax-area", "polygon": true}),
    );
    assert_eq!(status, 200, "{doc}");
    assert_eq!(doc["domain"], "polygon");
    assert_eq!(doc["triangles"].as_array().unwrap().len(), 4);
}

#[test]
fn compare_answers_every_result_or_its_refusal() {
    let server = Server::start(&[]);
    let (status, doc) = server.post("/api/compare", &json!({"points": square_and_centre()}));
    assert_eq!(status, 200, "{doc}");
    assert_eq!(doc["document"], "comparison");
    let results = doc["results"].as_array().unwrap();
    assert_eq!(results.len(), optri::Criterion::ALL.len());
    let points =
        optri::PointSet::new(&[[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0], [1.0, 1.0]])
            .unwrap();
    for (r, &c) in results.iter().zip(optri::Criterion::ALL) {
        assert_eq!(r["criterion"], c.name());
        match optri::triangulate(&points, c) {
            Ok(s) => {
                assert_eq!(r["triangles"], json!(s.triangulation.triangles()), "{c:?}");
                assert_eq!(r["exact"], s.exact);
            }
            Err(e) => assert_eq!(r["error"], e.to_string(), "{c:?}"),
        }
    }
    assert!(
        results
            .iter()
            .any(|r| r["criterion"] == "min-weight" && r["exact"] == true),
        "min-weight solves general point sets exactly"
    );
    let (status, doc) = server.post(
        "/api/compare",
        &json!({"points": square_and_centre(), "criteria": ["greedy", "delaunay"]}),
    );
    assert_eq!(status, 200);
    let names: Vec<&Value> = doc["results"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| &r["criterion"])
        .collect();
    assert_eq!(names, [&json!("greedy"), &json!("delaunay")]);
}

#[test]
fn request_numbers_are_taken_at_their_decimal_values() {
    let server = Server::start(&[]);
    // (0.1, 0.3), (0.2, 0.6), (0.3, 0.9) are collinear as written, not as
    // doubles: as decimals (0.2, 0.6) is a hull vertex and no triangle is flat.
    let tenths =
        r#"{"points": [[0.1, 0.3], [0.2, 0.6], [0.3, 0.9], [0.3, 0.1]], "criterion": "greedy"}"#;
    let (status, text) = server.request("POST", "/api/triangulate", tenths.as_bytes());
    assert_eq!(status, 200, "{text}");
    let doc: Value = serde_json::from_str(&text).unwrap();
    assert_eq!(doc["coordinate_arithmetic"], "decimal-exact");
    assert_eq!(doc["triangles"].as_array().unwrap().len(), 2, "{doc}");
    assert_eq!(doc["stats"]["hull_points"], 4);
    // The user's values and units, not the scaled integers.
    assert_eq!(doc["coordinates"][1], json!([0.2, 0.6]));
    let longest = doc["stats"]["max_edge_length"].as_f64().unwrap();
    assert!((longest - 0.8).abs() < 1e-12, "{longest}");
    // A literal with 17 significant digits is not its double's shortest
    // decimal: the request runs on the doubles.
    let long = tenths.replace("[0.1, 0.3]", "[0.10000000000000001, 0.3]");
    let (status, text) = server.request("POST", "/api/triangulate", long.as_bytes());
    assert_eq!(status, 200, "{text}");
    let doc: Value = serde_json::from_str(&text).unwrap();
    assert_eq!(doc["coordinate_arithmetic"], "binary64");
    // Compare reports it once for every result.
    let (status, doc) = server.post(
        "/api/compare",
        &json!({"points": [[0.1, 0.3], [0.2, 0.6], [0.3, 0.9], [0.3, 0.1]], "criteria": ["delaunay", "minmax-length"]}),
    );
    assert_eq!(status, 200, "{doc}");
    let results = doc["results"].as_array().unwrap();
    assert_eq!(results.len(), 2, "{doc}");
    for r in results {
        assert_eq!(r["coordinate_arithmetic"], "decimal-exact", "{r}");
        assert_eq!(r["triangles"].as_array().unwrap().len(), 2, "{r}");
    }
}

#[test]
fn read_parses_files_with_the_library_readers() {
    let server = Server::start(&[]);
    let (status, v) = server.post(
        "/api/read",
        &json!({"text": "x,y\n0,0\n1,0\n0,1\n", "filename": "p.csv"}),
    );
    assert_eq!(status, 200, "{v}");
    assert_eq!(v["points"], json!([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]));
    assert_eq!(v["polygon"], false);
    let tsp = "NAME: t\nTYPE: TSP\nDIMENSION: 3\nNODE_COORD_SECTION\n1 0 0\n2 5 0\n3 0 5\nEOF\n";
    let (status, v) = server.post("/api/read", &json!({ "text": tsp }));
    assert_eq!(status, 200, "{v}");
    assert_eq!(v["format"], "tsplib");
    // Pasted clouds whose first row reads as a Triangle header are text;
    // a whole `.node` is a `.node`.
    for (text, format, points) in [
        (
            "3 2 0\n1 0 0\n2 1 0\n3 0 1\n",
            "text",
            json!([[3.0, 2.0], [1.0, 0.0], [2.0, 1.0], [3.0, 0.0]]),
        ),
        (
            "0 2\n1 3\n5 6\n",
            "text",
            json!([[0.0, 2.0], [1.0, 3.0], [5.0, 6.0]]),
        ),
        (
            "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n",
            "node",
            json!([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]),
        ),
    ] {
        let (status, v) = server.post("/api/read", &json!({ "text": text }));
        assert_eq!(status, 200, "{v}");
        assert_eq!((&v["format"], &v["points"]), (&json!(format), &points));
    }
    let polygon = r#"{"type": "Polygon", "coordinates": [[[0,0],[2,0],[1,1],[0,0]]]}"#;
    let (_, v) = server.post("/api/read", &json!({ "text": polygon }));
    assert_eq!(v["polygon"], true);
    let e = refused(
        server.post(
            "/api/read",
            &json!({"text": "1 2\n3 4\nfoo 5\n", "filename": "a.txt"}),
        ),
        422,
    );
    assert_eq!(e, "a.txt: line 3: 'foo' is not a number");
    let e = refused(
        server.post("/api/read", &json!({"text": "1 2", "format": "png"})),
        400,
    );
    assert!(e.contains("unknown input format 'png'"), "{e}");
}

#[test]
fn bad_requests_get_a_4xx_with_the_message_and_the_server_survives() {
    let server = Server::start(&["--max-points", "50"]);
    let raw = |body: &str| {
        let (status, text) = server.request("POST", "/api/compare", body.as_bytes());
        let v: Value = serde_json::from_str(&text).unwrap();
        (status, v)
    };
    // Malformed JSON, wrong types, NaN (not JSON), unknown fields.
    let e = refused(raw(r#"{"points": [[0, 0], [1, 0]"#), 400);
    assert!(e.starts_with("invalid request: EOF"), "{e}");
    let e = refused(raw(r#"{"points": "x"}"#), 400);
    assert!(e.contains("invalid type: string"), "{e}");
    let e = refused(raw(r#"{"points": [[0, 0], [1, 0], [0, NaN]]}"#), 400);
    assert!(e.starts_with("invalid request"), "{e}");
    let e = refused(raw(r#"{"points": [[0, 0], [1, 0], [0, 1e999]]}"#), 400);
    assert!(e.contains("number out of range"), "{e}");
    let e = refused(raw(r#"{"points": [[0, 0, 1], [1, 0], [0, 1]]}"#), 400);
    assert_eq!(
        e,
        "invalid request: point 0 has 3 numbers; each point is [x, y]"
    );
    let e = refused(
        raw(r#"{"points": [[0, 0], [1, 0], [0, 1]], "colour": "red"}"#),
        400,
    );
    assert!(e.contains("unknown field `colour`"), "{e}");
    // Unknown criterion: the valid ones are listed.
    let e = refused(
        server.post(
            "/api/triangulate",
            &json!({"points": square_and_centre(), "criterion": "fastest"}),
        ),
        400,
    );
    assert!(
        e.contains("unknown criterion 'fastest'") && e.contains("minmax-length"),
        "{e}"
    );
    let e = refused(
        server.post(
            "/api/compare",
            &json!({"points": square_and_centre(), "criteria": ["delaunay", "nope"]}),
        ),
        400,
    );
    assert!(e.contains("unknown criterion 'nope'"), "{e}");
    // Input the library refuses: 422 with its message.
    let e = refused(raw(r#"{"points": [[0, 0], [1, 0]]}"#), 422);
    assert!(e.contains("at least 3 distinct points"), "{e}");
    let e = refused(raw(r#"{"points": [[0, 0], [1, 1], [2, 2], [1, 1]]}"#), 422);
    assert!(e.contains("collinear"), "{e}");
    let e = refused(raw(r#"{"points": [[0, 0], [1, 0], [0, 1e300]]}"#), 422);
    assert!(e.contains("point 2") && e.contains("exact range"), "{e}");
    let e = refused(
        server.post(
            "/api/triangulate",
            &json!({"points": square_and_centre(), "criterion": "delaunay", "metric": "l1"}),
        ),
        400,
    );
    assert!(
        e.contains("unknown option 'metric' for criterion delaunay"),
        "{e}"
    );
    let e = refused(
        server.post(
            "/api/triangulate",
            &json!({"points": square_and_centre(), "criterion": "minmax-length", "metric": "lp:0"}),
        ),
        400,
    );
    assert!(e.contains("invalid metric: lp:0"), "{e}");
    let e = refused(
        server.post(
            "/api/triangulate",
            &json!({"points": [[0, 0], [2, 0], [0, 2], [2, 2]], "polygon": true}),
        ),
        422,
    );
    assert!(e.contains("not a simple polygon"), "{e}");
    // Too many points for this server (--max-points 50).
    let many: Vec<[f64; 2]> = (0..51).map(|i| [i as f64, (i * i % 17) as f64]).collect();
    let e = refused(server.post("/api/compare", &json!({ "points": many })), 422);
    assert!(e.contains("51 points") && e.contains("limit of 50"), "{e}");
    // Paths and methods.
    let (status, text) = server.request("GET", "/api/nope", b"");
    assert_eq!(status, 404, "{text}");
    let (status, text) = server.request("GET", "/api/compare", b"");
    assert_eq!(status, 405, "{text}");
    assert!(text.contains("POST only"));
    let (status, _) = server.request("DELETE", "/", b"");
    assert_eq!(status, 405);
    // After all that, the server still answers.
    let (status, _) = server.post("/api/compare", &json!({"points": square_and_centre()}));
    assert_eq!(status, 200);
}

#[test]
fn size_and_time_limits_refuse_with_413_and_503() {
    let server = Server::start(&["--max-body-mib", "1", "--time-limit", "0"]);
    let big = vec![b' '; 1024 * 1024 + 1];
    let (status, text) = server.request("POST", "/api/compare", &big);
    assert_eq!(status, 413, "{text}");
    assert!(
        text.contains("larger than this server's limit of 1048576 bytes"),
        "{text}"
    );
    // A zero time limit: the computation cannot answer in time.
    let points: Vec<[f64; 2]> = (0..2000)
        .map(|i| {
            let t = i as f64;
            [
                (t * 0.618_034).fract() * 1000.0,
                (t * 0.414_214).fract() * 1000.0,
            ]
        })
        .collect();
    let e = refused(
        server.post(
            "/api/triangulate",
            &json!({"points": points, "criterion": "greedy"}),
        ),
        503,
    );
    assert!(e.contains("longer than this server's limit of 0 s"), "{e}");
}
