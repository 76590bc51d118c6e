//! The web playground's API end to end: `optri serve --port 0` in a child
//! process, plain HTTP/1.1 requests over a TCP socket, and the answers
//! checked against the library (the same documents as `triangulate --json`
//! and `compare --json`) and for their 4xx/503 refusals; then the server
//! under load on the loopback interface: stalled clients, small requests
//! beside large ones, cancellation at the time limit, keep-alive, `HEAD`,
//! Host/Origin refusals and the security headers. Every wait is bounded;
//! the only times asserted are generous bounds that catch a hang.

use optri::io::triangulation_from_json;
use optri_oracle::inputs;
use rand::rngs::StdRng;
use rand::SeedableRng;
use serde_json::{json, Value};
use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::process::{Child, Command, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

const BIN: &str = env!("CARGO_BIN_EXE_optri");

/// Longer than any answer or drop may take on a loaded machine: only a hang
/// gets there.
const HANG: Duration = Duration::from_secs(120);

/// A running `optri serve`, killed when dropped.
struct Server {
    child: Child,
    address: String,
}

/// One HTTP answer.
struct Answer {
    status: u16,
    /// Header names in lower case, in the order received.
    headers: Vec<(String, String)>,
    body: String,
}

impl Answer {
    fn header(&self, name: &str) -> Option<&str> {
        self.headers
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.as_str())
    }

    fn json(&self) -> Value {
        serde_json::from_str(&self.body)
            .unwrap_or_else(|e| panic!("{e}: not JSON: {:?}", self.body))
    }
}

/// Reads one answer from `reader`: its head, then `Content-Length` bytes of
/// body (none for the answer to a `HEAD`).
fn read_answer(reader: &mut impl BufRead, head: bool) -> Answer {
    let mut status_line = String::new();
    reader.read_line(&mut status_line).unwrap();
    let status: u16 = status_line
        .split(' ')
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| panic!("no status in {status_line:?}"));
    let mut headers = Vec::new();
    loop {
        let mut line = String::new();
        reader.read_line(&mut line).unwrap();
        let line = line.trim_end();
        if line.is_empty() {
            break;
        }
        let (name, value) = line.split_once(':').unwrap();
        headers.push((name.to_ascii_lowercase(), value.trim().to_string()));
    }
    let mut answer = Answer {
        status,
        headers,
        body: String::new(),
    };
    if !head {
        let length: usize = answer
            .header("content-length")
            .expect("every answer has a length")
            .parse()
            .unwrap();
        let mut body = vec![0; length];
        reader.read_exact(&mut body).unwrap();
        answer.body = String::from_utf8(body).unwrap();
    }
    answer
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

    /// A connection that fails a read or write stalled longer than `HANG`.
    fn connect(&self) -> TcpStream {
        let stream = TcpStream::connect(&self.address).unwrap();
        stream.set_read_timeout(Some(HANG)).unwrap();
        stream.set_write_timeout(Some(HANG)).unwrap();
        stream
    }

    /// The head of a request with these `headers` (each ending in CRLF).
    fn head(&self, method: &str, path: &str, headers: &str, body: &[u8]) -> String {
        format!(
            "{method} {path} HTTP/1.1\r\nHost: {}\r\nContent-Type: application/json\r\n\
             Content-Length: {}\r\n{headers}\r\n",
            self.address,
            body.len()
        )
    }

    /// Sends one request with extra `headers` on a new connection; returns
    /// the answer.
    fn exchange(&self, method: &str, path: &str, headers: &str, body: &[u8]) -> Answer {
        let mut stream = self.connect();
        let head = self.head(
            method,
            path,
            &format!("Connection: close\r\n{headers}"),
            body,
        );
        stream.write_all(head.as_bytes()).unwrap();
        // The server may answer (413) before reading a large body.
        let _ = stream.write_all(body);
        read_answer(&mut BufReader::new(stream), method == "HEAD")
    }

    /// Sends one request; returns the status and the body.
    fn request(&self, method: &str, path: &str, body: &[u8]) -> (u16, String) {
        let answer = self.exchange(method, path, "", body);
        (answer.status, answer.body)
    }

    fn post(&self, path: &str, body: &Value) -> (u16, Value) {
        let (status, text) = self.request("POST", path, body.to_string().as_bytes());
        (status, serde_json::from_str(&text).unwrap())
    }

    /// The port, as a client writes it in `Host`.
    fn port(&self) -> &str {
        self.address.rsplit(':').next().unwrap()
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
    // Its script and style sheet come from the binary too.
    let mut texts = vec![page.clone()];
    for part in ["/playground.js", "/playground.css"] {
        assert!(
            page.contains(&format!("\"{part}\"")),
            "the page loads {part}"
        );
        let (status, text) = server.request("GET", part, b"");
        assert_eq!(status, 200, "{part}");
        texts.push(text);
    }
    // Offline: the page loads nothing from elsewhere (the only URL in it is
    // the SVG namespace).
    for text in &texts {
        for remote in [
            "src=\"http",
            "href=\"http",
            "https://",
            "url(http",
            "import ",
        ] {
            assert!(!text.contains(remote), "the page must not load {remote}…");
        }
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
fn decide_answers_the_decision_document_at_and_past_the_optimum() {
    let server = Server::start(&[]);
    // A convex pentagon in tenths: Algorithm 49 on decimal areas.
    let points = json!([[0.1, 0.1], [0.7, 0.1], [0.9, 0.4], [0.6, 0.9], [0.2, 0.7]]);
    let (status, optimum) = server.post(
        "/api/triangulate",
        &json!({"points": points, "criterion": "maxmin-area"}),
    );
    assert_eq!(status, 200, "{optimum}");
    let at = optimum["stats"]["min_area"].clone();
    let ask = |criterion: &str, bound: &str, threshold: Value| {
        server.post(
            "/api/decide",
            &json!({"points": points, "criterion": criterion, bound: threshold}),
        )
    };
    let (status, yes) = ask("maxmin-area", "at_least", at.clone());
    assert_eq!(status, 200, "{yes}");
    assert_eq!(yes["document"], "decision");
    assert_eq!(yes["answer"], true, "{yes}");
    assert_eq!(yes["witness"]["stats"]["min_area"], at);
    assert_eq!(yes["witness"]["coordinate_arithmetic"], "decimal-exact");
    let value = at.as_f64().unwrap();
    let next = f64::from_bits(value.to_bits() + 1);
    let (_, no) = ask("maxmin-area", "at_least", json!(next));
    assert_eq!(no["answer"], false, "{no}");
    assert!(no["witness"].is_null());
    // A decimal string just past the optimum.
    let (_, no) = ask(
        "maxmin-area",
        "at_least",
        json!(format!("{value}0000000000000000001")),
    );
    assert_eq!(no["answer"], false, "{no}");
    let (_, minmax) = ask("minmax-area", "at_most", json!(10));
    assert_eq!(minmax["answer"], true, "{minmax}");
    // Bad requests: 400 with the library's message.
    for (body, message) in [
        (
            json!({"points": points, "criterion": "maxmin-area", "at_least": -1}),
            "negative",
        ),
        (
            json!({"points": points, "criterion": "maxmin-area", "at_least": "nan"}),
            "at_least",
        ),
        (
            json!({"points": points, "criterion": "maxmin-area", "at_least": [1]}),
            "at_least",
        ),
        (
            json!({"points": points, "criterion": "maxmin-area", "at_most": 1}),
            "at_least",
        ),
        (
            json!({"points": points, "criterion": "delaunay", "at_least": 1}),
            "delaunay",
        ),
        (
            json!({"points": points, "criterion": "maxmin-area"}),
            "at_least",
        ),
        (json!({"points": points, "at_least": 1}), "criterion"),
    ] {
        let error = refused(server.post("/api/decide", &body), 400);
        assert!(error.contains(message), "{body}: {error}");
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
            // Three columns without a header: x y z.
            json!([
                [3.0, 2.0, 0.0],
                [1.0, 0.0, 0.0],
                [2.0, 1.0, 0.0],
                [3.0, 0.0, 1.0]
            ]),
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
        "invalid request: point 1 has 2 numbers, but point 0 has 3; every point is [x, y], or \
         every point [x, y, z]"
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
    let server = Server::start(&["--max-body-mib", "1", "--time-limit", "0.001"]);
    let big = vec![b' '; 1024 * 1024 + 1];
    let (status, text) = server.request("POST", "/api/compare", &big);
    assert_eq!(status, 413, "{text}");
    assert!(
        text.contains("larger than this server's limit of 1048576 bytes"),
        "{text}"
    );
    // A millisecond: reading 2000 points and greedy on them cannot answer
    // in time (a zero limit is refused at start).
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
    assert!(
        e.contains("longer than this server's limit of 0.001 s"),
        "{e}"
    );
}

// ---- the server under load, on the loopback interface ----

/// Seed of the large inputs.
const SEED_LARGE: u64 = 20_000;

/// A triangulate body of `n` uniform points (min-weight on 20 000 of them
/// takes seconds, Delaunay on 2 001 milliseconds).
fn large(criterion: &str, n: usize) -> Vec<u8> {
    let mut rng = StdRng::seed_from_u64(SEED_LARGE);
    let points = inputs::uniform_in_square(&mut rng, n, 1000.0);
    json!({"points": points, "criterion": criterion})
        .to_string()
        .into_bytes()
}

/// `body` posted to `/api/triangulate` from a thread of its own; the answer
/// arrives on the receiver.
fn post_in_background(server: &Server, body: Vec<u8>) -> mpsc::Receiver<Answer> {
    let mut stream = server.connect();
    let head = server.head("POST", "/api/triangulate", "Connection: close\r\n", &body);
    let (send, receive) = mpsc::channel();
    std::thread::spawn(move || {
        stream.write_all(head.as_bytes()).unwrap();
        stream.write_all(&body).unwrap();
        let _ = send.send(read_answer(&mut BufReader::new(stream), false));
    });
    receive
}

fn small_request(server: &Server) -> Answer {
    let body = json!({"points": square_and_centre(), "criterion": "minmax-length"}).to_string();
    server.exchange("POST", "/api/triangulate", "", body.as_bytes())
}

#[test]
fn stalled_clients_are_dropped_and_never_hold_up_others() {
    let server = Server::start(&["--read-timeout", "1"]);
    let start = Instant::now();
    // More stalled connections than there are small slots (16): idle ones,
    // ones stuck in their headers, and ones that announce a body and send
    // none or part of it.
    let stalls = [
        "",
        "POST /api/triangulate HTTP/1.1\r\nHost: ",
        "GET / HTTP/1.1\r\n",
        "POST /api/triangulate HTTP/1.1\r\nHost: H\r\nContent-Length: 1000\r\n\r\n",
        "POST /api/compare HTTP/1.1\r\nHost: H\r\nContent-Length: 1000\r\n\r\n{\"points\": [",
    ];
    let stalled: Vec<(usize, TcpStream)> = (0..25)
        .map(|i| {
            let mut stream = server.connect();
            let text =
                stalls[i % stalls.len()].replace("H\r\n", &format!("{}\r\n", server.address));
            stream.write_all(text.as_bytes()).unwrap();
            (i % stalls.len(), stream)
        })
        .collect();
    // Meanwhile a small request is answered at once.
    let answer = small_request(&server);
    assert_eq!(answer.status, 200, "{}", answer.body);
    // Each stalled client is dropped after the read timeout (1 s): those in
    // their headers without an answer, those in a body with 408.
    for (kind, stream) in stalled {
        let mut text = String::new();
        BufReader::new(stream)
            .read_to_string(&mut text)
            .unwrap_or_else(|e| panic!("stall {kind} was not dropped: {e}"));
        if kind >= 3 {
            assert!(text.starts_with("HTTP/1.1 408"), "stall {kind}: {text}");
            assert!(text.contains("stalled: nothing arrived for 1 s"), "{text}");
        } else {
            assert!(!text.contains(" 200 "), "stall {kind}: {text}");
        }
    }
    assert!(start.elapsed() < HANG);
    let answer = small_request(&server);
    assert_eq!(answer.status, 200, "{}", answer.body);
}

#[test]
fn small_requests_are_answered_beside_large_ones() {
    let server = Server::start(&["--max-running", "1", "--time-limit", "60"]);
    let start = Instant::now();
    // The one large slot is taken by a computation of a second or more; a
    // quick large one is accepted until it is, then refused as busy and
    // told to retry. (If a quick one held the slot when the long one asked,
    // the long one was refused: it is sent again.)
    let mut first = post_in_background(&server, large("min-weight", 20_000));
    let busy = loop {
        assert!(
            start.elapsed() < HANG,
            "the large computation never took its slot"
        );
        std::thread::sleep(Duration::from_millis(50));
        if first.try_recv().is_ok() {
            first = post_in_background(&server, large("min-weight", 20_000));
            continue;
        }
        let quick = server.exchange("POST", "/api/triangulate", "", &large("delaunay", 2_001));
        if quick.status != 200 {
            break quick;
        }
    };
    assert_eq!(busy.status, 503, "{}", busy.body);
    assert_eq!(busy.header("retry-after"), Some("1"));
    assert!(
        busy.json()["error"].as_str().unwrap().contains("busy"),
        "{}",
        busy.body
    );
    // A small request is answered while it runs, not queued behind it (the
    // large one takes a second or more, the small one milliseconds).
    let answer = small_request(&server);
    assert_eq!(answer.status, 200, "{}", answer.body);
    assert!(
        first.try_recv().is_err(),
        "the small request was answered after the large one"
    );
    let first = first
        .recv_timeout(HANG)
        .expect("the large computation answers");
    assert_eq!(first.status, 200, "{}", first.body);
    // Then a new large one is accepted.
    let again = server.exchange("POST", "/api/triangulate", "", &large("delaunay", 2_001));
    assert_eq!(again.status, 200, "{}", again.body);
}

#[test]
fn a_request_over_the_time_limit_is_cancelled_and_frees_its_slot() {
    let server = Server::start(&["--max-running", "1", "--time-limit", "0.5"]);
    let start = Instant::now();
    let over = server.exchange("POST", "/api/triangulate", "", &large("min-weight", 20_000));
    assert_eq!(over.status, 503, "{}", over.body);
    let e = over.json()["error"].as_str().unwrap().to_string();
    assert!(
        e.starts_with("stopped:") && e.contains("limit of 0.5 s"),
        "{e}"
    );
    // The answer came at the limit, not when the computation ended.
    assert!(start.elapsed() < HANG);
    // Its slot is freed when the computation stops: a new large computation
    // is refused as busy until then (or runs out of time itself, sharing the
    // cores with it), and accepted after.
    loop {
        let next = server.exchange("POST", "/api/triangulate", "", &large("delaunay", 2_001));
        if next.status == 200 {
            break;
        }
        assert_eq!(next.status, 503, "{}", next.body);
        let e = next.json()["error"].as_str().unwrap().to_string();
        let busy = next.header("retry-after") == Some("1") && e.contains("busy");
        assert!(busy || e.contains("limit of 0.5 s"), "{e}");
        assert!(start.elapsed() < HANG, "the slot was never freed");
        std::thread::sleep(Duration::from_millis(100));
    }
}

#[test]
fn keep_alive_and_head() {
    let server = Server::start(&[]);
    // Two requests on one connection, then HEAD, then a POST.
    let mut stream = server.connect();
    let mut reader = BufReader::new(stream.try_clone().unwrap());
    stream
        .write_all(server.head("GET", "/api/limits", "", b"").as_bytes())
        .unwrap();
    let limits = read_answer(&mut reader, false);
    assert_eq!(limits.status, 200);
    assert_eq!(limits.json()["small_points"], 2000);
    stream
        .write_all(server.head("GET", "/", "", b"").as_bytes())
        .unwrap();
    let page = read_answer(&mut reader, false);
    assert_eq!(page.status, 200);
    // HEAD: the same headers, no body (the next answer parses right after).
    for path in [
        "/",
        "/playground.js",
        "/playground.css",
        "/api/criteria",
        "/api/limits",
    ] {
        stream
            .write_all(server.head("HEAD", path, "", b"").as_bytes())
            .unwrap();
        let head = read_answer(&mut reader, true);
        assert_eq!(head.status, 200, "{path}");
        let (status, body) = server.request("GET", path, b"");
        assert_eq!(status, 200);
        assert_eq!(
            head.header("content-length"),
            Some(body.len().to_string().as_str()),
            "{path}"
        );
    }
    let body = json!({"points": square_and_centre()}).to_string();
    stream
        .write_all(
            server
                .head("POST", "/api/triangulate", "", body.as_bytes())
                .as_bytes(),
        )
        .unwrap();
    stream.write_all(body.as_bytes()).unwrap();
    let answer = read_answer(&mut reader, false);
    assert_eq!(answer.status, 200, "{}", answer.body);
    assert_eq!(answer.json()["criterion"], "delaunay");
    // HEAD of a POST route, and POST of a GET route: 405 with Allow.
    let (status, text) = server.request("HEAD", "/api/compare", b"");
    assert_eq!(status, 405, "{text}");
    let answer = server.exchange("POST", "/api/limits", "", b"{}");
    assert_eq!(answer.status, 405);
    assert_eq!(answer.header("allow"), Some("GET, HEAD"));
}

#[test]
fn host_and_origin_of_another_site_are_refused() {
    let server = Server::start(&[]);
    let port = server.port();
    let raw = |head: String, body: &str| {
        let mut stream = server.connect();
        stream.write_all(head.as_bytes()).unwrap();
        stream.write_all(body.as_bytes()).unwrap();
        read_answer(&mut BufReader::new(stream), false)
    };
    let get = |host: &str| {
        raw(
            format!("GET /api/limits HTTP/1.1\r\nHost: {host}\r\nConnection: close\r\n\r\n"),
            "",
        )
    };
    for host in [format!("localhost:{port}"), format!("127.0.0.1:{port}")] {
        assert_eq!(get(&host).status, 200, "{host}");
    }
    // DNS rebinding: a site whose name resolves to 127.0.0.1.
    for host in [
        format!("evil.example:{port}"),
        "localhost:1".to_string(),
        "localhost".to_string(),
    ] {
        let answer = get(&host);
        assert_eq!(answer.status, 403, "{host}");
        assert!(answer.json()["error"]
            .as_str()
            .unwrap()
            .contains("not this server"));
    }
    // HTTP/1.1 without Host is malformed.
    let answer = raw(
        "GET / HTTP/1.1\r\nConnection: close\r\n\r\n".to_string(),
        "",
    );
    assert_eq!(answer.status, 400, "{}", answer.body);
    let body = json!({"points": square_and_centre()}).to_string();
    let post = |origin: &str| {
        server.exchange(
            "POST",
            "/api/triangulate",
            &format!("Origin: {origin}\r\n"),
            body.as_bytes(),
        )
    };
    assert_eq!(post(&format!("http://localhost:{port}")).status, 200);
    assert_eq!(post(&format!("http://127.0.0.1:{port}")).status, 200);
    for origin in [
        format!("http://evil.example:{port}"),
        "null".to_string(),
        format!("https://localhost:{port}"),
    ] {
        let answer = post(&origin);
        assert_eq!(answer.status, 403, "{origin}");
        assert!(
            answer.json()["error"]
                .as_str()
                .unwrap()
                .contains("may not post"),
            "{}",
            answer.body
        );
    }
}

#[test]
fn every_answer_says_nosniff_and_the_page_has_a_policy() {
    let server = Server::start(&["--max-body-mib", "1"]);
    let answers = [
        server.exchange("GET", "/", "", b""),
        server.exchange("GET", "/api/criteria", "", b""),
        server.exchange("GET", "/nope", "", b""),
        server.exchange("POST", "/api/compare", "", b"{"),
        server.exchange("POST", "/api/compare", "", &vec![b' '; 1024 * 1024 + 1]),
        server.exchange("GET", "/", "Host: evil.example\r\n", b""),
    ];
    for answer in &answers {
        assert_eq!(
            answer.header("x-content-type-options"),
            Some("nosniff"),
            "{}",
            answer.status
        );
    }
    let policy = answers[0]
        .header("content-security-policy")
        .expect("the page has a policy");
    for rule in [
        "default-src 'none'",
        "script-src 'self'",
        "connect-src 'self'",
        "frame-ancestors 'none'",
    ] {
        assert!(policy.contains(rule), "{policy}");
    }
    assert!(!policy.contains("unsafe"), "{policy}");
    assert_eq!(answers[1].header("content-type"), Some("application/json"));
    assert_eq!(
        answers[2].header("content-type"),
        Some("application/json"),
        "errors are JSON too"
    );
}

#[test]
fn limits_that_overflow_or_make_no_sense_are_refused_at_start() {
    for (option, value, message) in [
        (
            "--max-body-mib",
            "17592186044416",
            "invalid --max-body-mib 17592186044416",
        ),
        (
            "--time-limit",
            "-1",
            "invalid --time-limit -1.0: give a number",
        ),
        ("--time-limit", "NaN", "invalid --time-limit NaN"),
        ("--time-limit", "1e300", "invalid --time-limit 1e300"),
        ("--read-timeout", "0", "invalid --read-timeout 0"),
        ("--max-running", "0", "invalid --max-running 0"),
        ("--time-limit", "0", "invalid --time-limit 0"),
    ] {
        let out = Command::new(BIN)
            .args(["serve", "--port", "0", &format!("{option}={value}")])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(1), "{option} {value}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains(message), "{stderr}");
        assert!(out.stdout.is_empty(), "it does not start listening");
    }
    // The help says what is small, as GET /api/limits does.
    let out = Command::new(BIN)
        .args(["serve", "--help"])
        .output()
        .unwrap();
    let help = String::from_utf8_lossy(&out.stdout);
    assert!(help.contains("at most 2000 points"), "{help}");
    assert!(help.contains("--read-timeout"), "{help}");
}

/// The area criteria's `alpha` and `approximation` options reach the run
/// and its report through the request layer.
#[test]
fn area_options_reach_the_report() {
    let server = Server::start(&[]);
    let points = json!([[0, 0], [9, 1], [17, 0], [20, 8], [16, 17], [8, 20], [7, 7]]);
    let (status, doc) = server.post(
        "/api/triangulate",
        &json!({"points": points, "criterion": "maxmin-area",
                "options": {"alpha": 5, "approximation": "rng-hull"}}),
    );
    assert_eq!(status, 200, "{doc}");
    assert_eq!(doc["approximation"]["choice"], "rng-hull");
    assert_eq!(doc["approximation"]["alpha"], json!(5.0));
    assert!(doc["stats"]["min_angle_deg"].as_f64().unwrap() >= 5.0);
    let message = refused(
        server.post(
            "/api/triangulate",
            &json!({"points": points, "criterion": "maxmin-area", "options": {"alpha": 70}}),
        ),
        422,
    );
    assert!(message.contains("α* = "), "{message}");
}
