//! The web playground's JSON API, as a function from a request (method,
//! path, body) to a [`Reply`], so that the HTTP loop in `commands::serve`
//! only moves bytes. Every answer is built by the library: the registry
//! ([`Criterion::ALL`], [`optri::compare`]), the readers ([`io::read`])
//! and the result schema ([`TriangulationReport`], [`ComparisonReport`]), so
//! a criterion that lands later appears in the page without changes here.
//!
//! | request | answer |
//! |---|---|
//! | `GET /` | the page ([`INDEX_HTML`], embedded; no external resources) |
//! | `GET /api/criteria` | the registry listing document of `optri criteria --json` |
//! | `GET /api/limits` | `{"max_body_bytes", "max_points", "time_limit_s", "max_running"}` |
//! | `POST /api/triangulate` `{"points": [[x, y], …], "criterion"?, "polygon"?, "options"?}` | the triangulation document of `optri triangulate --json` |
//! | `POST /api/compare` `{"points", "criteria"?: [names], "polygon"?, "options"?}` | the comparison document of `optri compare --json` |
//! | `POST /api/graph` `{"points", "kind", "options"?}` | the graph document of `optri graph --json` |
//! | `POST /api/read` `{"text", "filename"?, "format"?}` | `{"points": [[x, y], …], "polygon": bool, "format"}`: a file parsed by the library's readers |
//!
//! `options` maps option names of the listing to values (strings or
//! numbers), checked against what the criterion or graph reads; `metric`
//! is also accepted as a field of its own. Every request runs through the
//! library's [`Request`], as the CLI's and Python's do.
//!
//! The numbers of `points` are taken at their decimal values when the body
//! writes none with more than 15 significant digits
//! ([`ReadInput::from_json_numbers`]; the page's `JSON.stringify` writes
//! shortest decimals), and the documents say `coordinate_arithmetic`.
//!
//! Errors are `{"error": message}` with the library's message: 400 for a
//! request that is not the documented JSON (syntax, types, unknown fields,
//! unknown criterion or format), 404/405 for other paths and methods, 413 for
//! a body over [`Limits::max_body_bytes`], 422 for input the library refuses
//! (too few points, collinear, out-of-range coordinates, a criterion that
//! does not support the input, more than [`Limits::max_points`] points) and
//! 503 when [`Limits::max_running`] computations are already running or one
//! exceeds [`Limits::time_limit`] (its thread then finishes in the background
//! and still counts as running, so a flood of slow requests cannot pile up).

use optri::io::{self, InputFormat, ReadInput, ReadOptions, Source};
use optri::request::{Request, Task};
use optri::{Criterion, Error};
use serde::Deserialize;
use serde_json::{json, Value};
use std::collections::BTreeMap;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{mpsc, Arc};
use std::time::Duration;

/// The page, embedded in the binary: plain HTML, CSS and JavaScript.
pub(crate) const INDEX_HTML: &str = include_str!("index.html");

/// What the server refuses, so one request cannot take the machine.
#[derive(Clone, Debug)]
pub(crate) struct Limits {
    /// Largest request body, bytes (larger: 413).
    pub max_body_bytes: usize,
    /// Most points one triangulate or compare request may hold (more: 422).
    pub max_points: usize,
    /// Longest a computation may take before the answer is 503.
    pub time_limit: Duration,
    /// Most computations running at once (more: 503).
    pub max_running: usize,
}

/// An HTTP answer: status, content type and body.
#[derive(Debug)]
pub(crate) struct Reply {
    pub status: u16,
    pub content_type: &'static str,
    pub body: String,
}

const JSON: &str = "application/json";

impl Reply {
    fn json(status: u16, value: &impl serde::Serialize) -> Self {
        match serde_json::to_string(value) {
            Ok(body) => Reply {
                status,
                content_type: JSON,
                body,
            },
            Err(e) => Reply::error(500, format!("cannot encode the answer: {e}")),
        }
    }

    pub(crate) fn error(status: u16, message: impl Into<String>) -> Self {
        Reply::json(status, &json!({ "error": message.into() }))
    }
}

/// The API's state shared by the worker threads.
pub(crate) struct Api {
    limits: Limits,
    running: Arc<AtomicUsize>,
}

/// One slot of [`Limits::max_running`], released when the computation (not
/// the request) ends.
struct Slot(Arc<AtomicUsize>);

impl Drop for Slot {
    fn drop(&mut self) {
        self.0.fetch_sub(1, Ordering::SeqCst);
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct TriangulateRequest {
    points: Vec<Vec<f64>>,
    #[serde(default = "default_criterion")]
    criterion: String,
    #[serde(default)]
    polygon: bool,
    /// The registry's `metric` option (`Metric::parse` syntax).
    #[serde(default)]
    metric: Option<String>,
    #[serde(default)]
    options: BTreeMap<String, Value>,
}

fn default_criterion() -> String {
    Criterion::Delaunay.name().to_string()
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct CompareRequest {
    points: Vec<Vec<f64>>,
    #[serde(default)]
    criteria: Vec<String>,
    #[serde(default)]
    polygon: bool,
    #[serde(default)]
    metric: Option<String>,
    #[serde(default)]
    options: BTreeMap<String, Value>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct GraphRequest {
    points: Vec<Vec<f64>>,
    kind: String,
    #[serde(default)]
    metric: Option<String>,
    #[serde(default)]
    options: BTreeMap<String, Value>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ReadRequest {
    text: String,
    #[serde(default)]
    filename: Option<String>,
    #[serde(default)]
    format: Option<String>,
}

/// A failed request: its status and message.
type Refusal = (u16, String);

/// 400: the request is not the documented JSON.
fn bad_request(e: impl std::fmt::Display) -> Refusal {
    (400, format!("invalid request: {e}"))
}

/// The status of a library error: 422 (the input is refused), 503 (the run
/// was stopped by its time limit), 500 for a bug.
fn library_error(e: &Error) -> Refusal {
    let status = match e {
        Error::Internal(_) => 500,
        Error::Interrupted(_) => 503,
        _ => 422,
    };
    (status, e.to_string())
}

fn parse<T: serde::de::DeserializeOwned>(body: &[u8]) -> Result<T, Refusal> {
    serde_json::from_slice(body).map_err(bad_request)
}

impl Api {
    pub(crate) fn new(limits: Limits) -> Self {
        Api {
            limits,
            running: Arc::new(AtomicUsize::new(0)),
        }
    }

    /// Answers one request. `body` is at most `max_body_bytes` long (the
    /// HTTP loop answers 413 itself otherwise).
    pub(crate) fn respond(&self, method: &str, path: &str, body: &[u8]) -> Reply {
        // The query string plays no part in any answer.
        let path = path.split('?').next().unwrap_or(path);
        let result = match (method, path) {
            ("GET", "/" | "/index.html") => {
                return Reply {
                    status: 200,
                    content_type: "text/html; charset=utf-8",
                    body: INDEX_HTML.to_string(),
                }
            }
            ("GET", "/api/criteria") => Ok(Reply::json(200, &io::registry_listing())),
            ("GET", "/api/limits") => Ok(Reply::json(200, &self.limits())),
            ("POST", "/api/triangulate") => self.triangulate(body),
            ("POST", "/api/compare") => self.compare(body),
            ("POST", "/api/graph") => self.graph(body),
            ("POST", "/api/read") => read(body),
            (_, "/" | "/index.html" | "/api/criteria" | "/api/limits") => {
                Err((405, format!("{path} answers GET only")))
            }
            (_, "/api/triangulate" | "/api/compare" | "/api/graph" | "/api/read") => {
                Err((405, format!("{path} answers POST only")))
            }
            _ => Err((
                404,
                format!(
                    "no such page: {path} (the API is GET /api/criteria, GET /api/limits, \
                     POST /api/triangulate, POST /api/compare, POST /api/graph, POST /api/read)"
                ),
            )),
        };
        result.unwrap_or_else(|(status, message)| Reply::error(status, message))
    }

    fn limits(&self) -> Value {
        json!({
            "max_body_bytes": self.limits.max_body_bytes,
            "max_points": self.limits.max_points,
            "time_limit_s": self.limits.time_limit.as_secs_f64(),
            "max_running": self.limits.max_running,
        })
    }

    /// The library's request for `task` on the points of a request body:
    /// each an `[x, y]` pair (400 otherwise), at most
    /// [`Limits::max_points`] (422), taken at their decimal values when the
    /// `body` writes none with more than 15 significant digits
    /// ([`ReadInput::from_json_numbers`], as the GeoJSON reader does), with
    /// the options named in the body (400 for one the task does not read)
    /// and this server's time limit.
    fn request(
        &self,
        task: Task,
        points: &[Vec<f64>],
        polygon: bool,
        metric: Option<&str>,
        options: &BTreeMap<String, Value>,
        body: &[u8],
    ) -> Result<Request, Refusal> {
        if points.len() > self.limits.max_points {
            return Err((
                422,
                format!(
                    "{} points is more than this server's limit of {} per request; use the \
                     command line (optri triangulate / optri compare) for large inputs",
                    points.len(),
                    self.limits.max_points
                ),
            ));
        }
        let points = points
            .iter()
            .enumerate()
            .map(|(i, p)| match p[..] {
                [x, y] => Ok([x, y]),
                _ => Err(bad_request(format!(
                    "point {i} has {} numbers; each point is [x, y]",
                    p.len()
                ))),
            })
            .collect::<Result<Vec<[f64; 2]>, Refusal>>()?;
        let input = if polygon {
            io::Input::Polygon(points)
        } else {
            io::Input::Points(points)
        };
        // `parse` accepted the body, so it is UTF-8 and the lossy view is
        // the text itself.
        let read = ReadInput::from_json_numbers(input, &String::from_utf8_lossy(body));
        let mut request = Request::new(read, task);
        if !self.limits.time_limit.is_zero() {
            request
                .set_option(
                    "time_limit",
                    &self.limits.time_limit.as_secs_f64().to_string(),
                )
                .map_err(|e| library_error(&e))?;
        }
        let named = metric.map(|m| ("metric", Value::from(m)));
        for (name, value) in named
            .into_iter()
            .chain(options.iter().map(|(n, v)| (n.as_str(), v.clone())))
        {
            let text = match &value {
                Value::String(s) => s.clone(),
                Value::Number(n) => n.to_string(),
                other => {
                    return Err(bad_request(format!(
                        "option {name}: {other} is not a string or a number"
                    )))
                }
            };
            if name == "time_limit" {
                let mut check = optri::Options::default();
                check.set(name, &text).map_err(bad_request)?;
                if check.time_limit > Some(self.limits.time_limit) {
                    return Err(bad_request(format!(
                        "option time_limit: {text} s is more than this server's limit of {} s",
                        self.limits.time_limit.as_secs_f64()
                    )));
                }
            }
            request.set_option(name, &text).map_err(bad_request)?;
        }
        Ok(request)
    }

    /// Runs `request` within the limits and answers with its document.
    fn run(&self, request: Request) -> Result<Reply, Refusal> {
        let mut outcome = self
            .compute(move || request.run())?
            .map_err(|e| library_error(&e))?;
        outcome.finish();
        // Serialised directly, so the fields keep the documented order.
        Ok(Reply::json(200, &outcome.document()))
    }

    /// Runs `work` on its own thread within the limits.
    fn compute<T: Send + 'static>(
        &self,
        work: impl FnOnce() -> T + Send + 'static,
    ) -> Result<T, Refusal> {
        let busy = self
            .running
            .fetch_update(Ordering::SeqCst, Ordering::SeqCst, |n| {
                (n < self.limits.max_running).then_some(n + 1)
            })
            .is_err();
        if busy {
            return Err((
                503,
                format!(
                    "the server is busy ({} computations running); try again shortly",
                    self.limits.max_running
                ),
            ));
        }
        let slot = Slot(Arc::clone(&self.running));
        let (send, receive) = mpsc::channel();
        std::thread::spawn(move || {
            let _slot = slot;
            // The receiver may have given up (time limit): nothing to do then.
            let _ = send.send(work());
        });
        match receive.recv_timeout(self.limits.time_limit) {
            Ok(value) => Ok(value),
            Err(mpsc::RecvTimeoutError::Timeout) => Err((
                503,
                format!(
                    "the computation took longer than this server's limit of {} s; use the \
                     command line for this input",
                    self.limits.time_limit.as_secs_f64()
                ),
            )),
            Err(mpsc::RecvTimeoutError::Disconnected) => Err((
                500,
                "internal error: the computation failed (this is a bug, please report it)"
                    .to_string(),
            )),
        }
    }

    fn triangulate(&self, body: &[u8]) -> Result<Reply, Refusal> {
        let r: TriangulateRequest = parse(body)?;
        let task = Task::triangulate(&r.criterion).map_err(bad_request)?;
        let request = self.request(
            task,
            &r.points,
            r.polygon,
            r.metric.as_deref(),
            &r.options,
            body,
        )?;
        self.run(request)
    }

    fn compare(&self, body: &[u8]) -> Result<Reply, Refusal> {
        let r: CompareRequest = parse(body)?;
        let task = Task::compare(&r.criteria).map_err(bad_request)?;
        let request = self.request(
            task,
            &r.points,
            r.polygon,
            r.metric.as_deref(),
            &r.options,
            body,
        )?;
        self.run(request)
    }

    fn graph(&self, body: &[u8]) -> Result<Reply, Refusal> {
        let r: GraphRequest = parse(body)?;
        let task = Task::graph(&r.kind).map_err(bad_request)?;
        let request = self.request(
            task,
            &r.points,
            false,
            r.metric.as_deref(),
            &r.options,
            body,
        )?;
        self.run(request)
    }
}

/// `POST /api/read`: parses a file's text with the library's readers; the
/// format is `format` if given, else the `filename`'s extension, else
/// picked by content (as the CLI does for stdin).
fn read(body: &[u8]) -> Result<Reply, Refusal> {
    let request: ReadRequest = parse(body)?;
    let format = match (&request.format, &request.filename) {
        (Some(name), _) => Some(InputFormat::from_name(name).map_err(bad_request)?),
        (None, Some(name)) => InputFormat::from_path(Path::new(name)).ok(),
        (None, None) => None,
    };
    let options = ReadOptions::default()
        .with_format(format)
        .with_polygons(true);
    let read = io::read(Source::Text(&request.text), &options).map_err(|e| {
        let name = request.filename.as_deref().unwrap_or("the input");
        (422, format!("{name}: {e}"))
    })?;
    Ok(Reply::json(
        200,
        &json!({
            "points": read.input.points(),
            "polygon": matches!(read.input, io::Input::Polygon(_)),
            "format": read.format.map(InputFormat::name),
        }),
    ))
}
