//! The web playground's JSON API: routes, limits and where computations
//! run. The HTTP loop in `commands::serve` reads requests and writes
//! [`Reply`]s; everything an answer says is built by the library: the
//! registry listing ([`io::registry_listing`]), the readers
//! ([`io::read`]) and the result documents of [`Request::run`], so a
//! criterion that lands later appears in the page without changes here.
//!
//! | request | answer |
//! |---|---|
//! | `GET /` | the page ([`INDEX_HTML`] with [`PLAYGROUND_JS`] and [`PLAYGROUND_CSS`], embedded; nothing is loaded from elsewhere) |
//! | `GET /api/criteria` | the registry listing document of `optri criteria --json` |
//! | `GET /api/limits` | `{"max_body_bytes", "max_points", "time_limit_s", "max_running", "small_points", "read_timeout_s"}` |
//! | `POST /api/triangulate` `{"points": [[x, y], …], "criterion"?, "polygon"?, "options"?}` | the triangulation document of `optri triangulate --json` (points may be `[x, y, z]`, all of them: `z` is the elevation) |
//! | `POST /api/compare` `{"points", "criteria"?: [names], "polygon"?, "options"?}` | the comparison document of `optri compare --json` |
//! | `POST /api/graph` `{"points", "kind", "options"?}` | the graph document of `optri graph --json` |
//! | `POST /api/decide` `{"points", "criterion", "at_least"? \| "at_most"?, "polygon"?, "options"?}` | the decision document of `optri decide --json` (a threshold is a number or a decimal string, taken at its decimal value) |
//! | `POST /api/read` `{"text", "filename"?, "format"?}` | `{"points": [[x, y], …], "polygon": bool, "format"}`: a file parsed by the library's readers (`[x, y, z]` when it has elevations) |
//!
//! Every `GET` route answers `HEAD` (the same headers, no body). `options`
//! maps option names of the listing to values (strings or numbers), checked
//! against what the criterion or graph reads; `metric` is also accepted as a
//! field of its own. Every request runs through the library's [`Request`],
//! as the CLI's and Python's do.
//!
//! The numbers of `points` are taken at their decimal values when the body
//! writes none with more than 15 significant digits
//! ([`ReadInput::from_json_numbers`]; the page's `JSON.stringify` writes
//! shortest decimals), and the documents say `coordinate_arithmetic`.
//!
//! # Status codes
//! Errors are `{"error": message}` with the library's message; a
//! criterion's refusal of the input (e.g. a convex-only criterion on a set
//! that is not in convex position) also names it: `{"error", "criterion"}`,
//! as in a comparison's results.
//! - 400: the request is not the documented JSON (syntax, types, unknown
//!   fields, unknown criterion, format or option, an option value the
//!   library refuses), or an HTTP/1.1 request without `Host`;
//! - 403: a server bound to a loopback address refuses a `Host` other than
//!   a loopback address or `localhost` with its port, and a POST whose
//!   `Origin` is another site (DNS rebinding; see `origin`);
//! - 404 and 405 (with `Allow`) for other paths and methods;
//! - 408: the request body stalled for [`Limits::read_timeout`];
//! - 413: a body over [`Limits::max_body_bytes`];
//! - 422: input the library refuses (too few points, collinear,
//!   out-of-range coordinates, a criterion that does not support the input,
//!   more than [`Limits::max_points`] points);
//! - 503: the request's time limit passed ([`Limits::time_limit`], see
//!   below), or [`Limits::max_running`] large computations are running
//!   already (then with `Retry-After: 1`).
//!
//! Every answer carries `X-Content-Type-Options: nosniff`, and the page a
//! `Content-Security-Policy` that lets it load its own script and style and
//! talk to this server only ([`PAGE_POLICY`]).
//!
//! # Limits
//! - **Reading.** Request headers must arrive within
//!   [`Limits::read_timeout`] of the connection's start or of the previous
//!   answer (so an idle keep-alive connection is closed after it too), and a
//!   body may stall for at most as long: a client that stops sending is
//!   dropped and holds nothing.
//! - **Time.** [`Limits::time_limit`] covers a POST from the arrival of its
//!   headers to its answer: reading the body, waiting for a slot, computing
//!   and writing the document. When it passes, the computation's
//!   [`Cancel`] is raised (the library stops at its next check) and the
//!   answer is 503 naming the limit. A comparison answers with what it has
//!   instead: it gets up to [`PARTIAL_GRACE`] more to return, its finished
//!   criteria are kept and each one the limit stopped reports "stopped: the
//!   time limit of … s passed"; the `time_limit` option (at most the
//!   server's) limits each criterion of a comparison separately.
//! - **Small and large.** A request with at most [`SMALL_POINTS`] points,
//!   and every `/api/read`, is small: it runs on one of [`SMALL_SLOTS`]
//!   one-thread pools and waits (within its time limit) when all are busy.
//!   A larger one takes one of [`Limits::max_running`] slots, each a pool
//!   with a thread per core, or gets 503 at once when none is free. So
//!   large computations never delay small ones, and a slot is freed when
//!   its computation actually stops (see `slots`). A large request's body is
//!   parsed in a small slot (linear work, bounded by the body limit).

mod origin;
mod slots;

pub(crate) use origin::Origins;

use hyper::body::Bytes;
use optri::io::{self, ComparisonReport, InputFormat, ReadInput, ReadOptions, Source, Threshold};
use optri::request::{Request, Results, Task};
use optri::{Cancel, Criterion, Error, Interruption, Options};
use serde::Deserialize;
use serde_json::{json, Value};
use slots::{Failure, Slots};
use std::borrow::Cow;
use std::collections::BTreeMap;
use std::path::Path;
use std::time::Duration;
use tokio::sync::oneshot;
use tokio::time::{timeout, timeout_at, Instant};

/// The page, embedded in the binary: plain HTML that loads
/// [`PLAYGROUND_CSS`] and [`PLAYGROUND_JS`] from this server.
pub(crate) const INDEX_HTML: &str = include_str!("index.html");
/// The page's script (`GET /playground.js`).
pub(crate) const PLAYGROUND_JS: &str = include_str!("playground.js");
/// The page's style sheet (`GET /playground.css`).
pub(crate) const PLAYGROUND_CSS: &str = include_str!("playground.css");

/// The page's `Content-Security-Policy`: its own script, style and API
/// only; `data:` for the empty icon, `blob:` for the downloads it builds.
pub(crate) const PAGE_POLICY: &str = "default-src 'none'; script-src 'self'; \
     style-src 'self'; img-src 'self' data: blob:; connect-src 'self'; base-uri 'none'; \
     form-action 'none'; frame-ancestors 'none'";

/// Requests with at most this many points are small (see the module docs):
/// every criterion answers them in well under a second except on
/// adversarial inputs, which the time limit stops.
pub(crate) const SMALL_POINTS: usize = 2_000;

/// Small computations running at once; more wait. The page sends one
/// request per criterion at once, and one slow criterion must not hold up
/// the others.
pub(crate) const SMALL_SLOTS: usize = 16;

/// How much longer than its time limit a comparison may take to return the
/// criteria it finished.
pub(crate) const PARTIAL_GRACE: Duration = Duration::from_secs(2);

/// What the server refuses, so one request cannot take the machine.
#[derive(Clone, Debug)]
pub(crate) struct Limits {
    /// Largest request body, bytes (larger: 413).
    pub max_body_bytes: usize,
    /// Most points one triangulate, compare or graph request may hold
    /// (more: 422).
    pub max_points: usize,
    /// Longest a POST may take, reading included (longer: 503).
    pub time_limit: Duration,
    /// Most large computations running at once (more: 503).
    pub max_running: usize,
    /// Longest a client may take to send request headers, or stall in a
    /// body (then it is dropped, or answered 408).
    pub read_timeout: Duration,
}

/// An HTTP answer: status, content type, body and any other headers.
#[derive(Debug)]
pub(crate) struct Reply {
    pub status: u16,
    pub content_type: &'static str,
    pub body: Cow<'static, str>,
    pub headers: Vec<(&'static str, &'static str)>,
}

const JSON: &str = "application/json";

impl Reply {
    fn json(status: u16, value: &impl serde::Serialize) -> Self {
        match serde_json::to_string(value) {
            Ok(body) => Self::text(status, JSON, body),
            Err(e) => Self::error(500, format!("cannot encode the answer: {e}")),
        }
    }

    fn text(status: u16, content_type: &'static str, body: impl Into<Cow<'static, str>>) -> Self {
        Reply {
            status,
            content_type,
            body: body.into(),
            headers: Vec::new(),
        }
    }

    /// `{"error": message}` with `status`.
    pub(crate) fn error(status: u16, message: impl Into<String>) -> Self {
        Self::json(status, &json!({ "error": message.into() }))
    }

    fn with_header(mut self, name: &'static str, value: &'static str) -> Self {
        self.headers.push((name, value));
        self
    }
}

/// What a request asks for, known from its method and path.
pub(crate) enum Route {
    /// Answered at once: a page, a listing, or a refusal.
    Ready(Reply),
    /// A POST whose body is read and then computed on.
    Compute(Endpoint),
}

/// The POST routes.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Endpoint {
    /// `/api/read`.
    Read,
    /// `/api/triangulate`, `/api/compare`, `/api/graph`, `/api/decide`.
    Run(Kind),
}

/// What a run computes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
    Triangulate,
    Compare,
    Graph,
    Decide,
}

/// The API's state, shared by the connections.
pub(crate) struct Api {
    limits: Limits,
    /// `GET /api/criteria`, written once.
    listing: String,
    small: Slots,
    large: Slots,
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
struct DecideRequest {
    points: Vec<Vec<f64>>,
    criterion: String,
    #[serde(default)]
    at_least: Option<Value>,
    #[serde(default)]
    at_most: Option<Value>,
    #[serde(default)]
    polygon: bool,
    #[serde(default)]
    options: BTreeMap<String, Value>,
}

/// A threshold field: a decimal string, or a number as the decimal the body
/// wrote (serde_json prints a double as its shortest decimal).
fn threshold_field(
    option: &'static str,
    value: Option<Value>,
) -> Result<Option<Threshold>, Refusal> {
    let text = match value {
        None | Some(Value::Null) => return Ok(None),
        Some(Value::String(s)) => s,
        Some(Value::Number(n)) => n.to_string(),
        Some(other) => {
            return Err(bad_request(format!(
                "{option}: {other} is not a number or a decimal string"
            )))
        }
    };
    Threshold::parse(option, &text)
        .map(Some)
        .map_err(bad_request)
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

fn refused((status, message): Refusal) -> Reply {
    Reply::error(status, message)
}

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

/// A computation's request, checked and ready to run.
struct Prepared {
    request: Request,
    points: usize,
    /// Raised when the request's time limit passes.
    cancel: Cancel,
    time_limit: Duration,
}

/// What the small slot did with a POST: answered it, or prepared a large
/// computation.
enum Step {
    Done(Reply),
    Large(Box<Prepared>),
}

/// Raises the flag when dropped: a request whose client went away, or that
/// was answered, leaves no computation running for it.
struct CancelOnDrop(Cancel);

impl Drop for CancelOnDrop {
    fn drop(&mut self) {
        self.0.cancel();
    }
}

impl Api {
    pub(crate) fn new(limits: Limits) -> Self {
        let cores = std::thread::available_parallelism().map_or(1, usize::from);
        Api {
            listing: io::registry_listing().to_string(),
            small: Slots::new(SMALL_SLOTS, 1, "small"),
            large: Slots::new(limits.max_running, cores, "large"),
            limits,
        }
    }

    pub(crate) fn limits(&self) -> &Limits {
        &self.limits
    }

    /// Where a request goes, from its method and path (the query string
    /// plays no part). `HEAD` is routed as `GET`; the HTTP loop drops the
    /// body.
    pub(crate) fn route(&self, method: &str, path: &str) -> Route {
        let path = path.split('?').next().unwrap_or(path);
        let endpoint = match path {
            "/api/triangulate" => Some(Endpoint::Run(Kind::Triangulate)),
            "/api/compare" => Some(Endpoint::Run(Kind::Compare)),
            "/api/graph" => Some(Endpoint::Run(Kind::Graph)),
            "/api/decide" => Some(Endpoint::Run(Kind::Decide)),
            "/api/read" => Some(Endpoint::Read),
            _ => None,
        };
        if let Some(endpoint) = endpoint {
            return if method == "POST" {
                Route::Compute(endpoint)
            } else {
                Route::Ready(
                    Reply::error(405, format!("{path} answers POST only"))
                        .with_header("Allow", "POST"),
                )
            };
        }
        let page = match path {
            "/" | "/index.html" => Reply::text(200, "text/html; charset=utf-8", INDEX_HTML)
                .with_header("Content-Security-Policy", PAGE_POLICY),
            "/playground.js" => Reply::text(200, "text/javascript; charset=utf-8", PLAYGROUND_JS),
            "/playground.css" => Reply::text(200, "text/css; charset=utf-8", PLAYGROUND_CSS),
            "/api/criteria" => Reply::text(200, JSON, self.listing.clone()),
            "/api/limits" => Reply::json(200, &self.limits_document()),
            _ => {
                return Route::Ready(Reply::error(
                    404,
                    format!(
                        "no such page: {path} (the API is GET /api/criteria, GET /api/limits, \
                         POST /api/triangulate, POST /api/compare, POST /api/graph, POST /api/decide, \
                         POST /api/read)"
                    ),
                ))
            }
        };
        Route::Ready(if matches!(method, "GET" | "HEAD") {
            page
        } else {
            Reply::error(405, format!("{path} answers GET and HEAD only"))
                .with_header("Allow", "GET, HEAD")
        })
    }

    fn limits_document(&self) -> Value {
        json!({
            "max_body_bytes": self.limits.max_body_bytes,
            "max_points": self.limits.max_points,
            "time_limit_s": self.limits.time_limit.as_secs_f64(),
            "max_running": self.limits.max_running,
            "small_points": SMALL_POINTS,
            "read_timeout_s": self.limits.read_timeout.as_secs_f64(),
        })
    }

    /// 503 for a request whose time limit passed.
    pub(crate) fn out_of_time(&self) -> Reply {
        Reply::error(
            503,
            format!(
                "stopped: the request took longer than this server's limit of {} s; use the \
                 command line (optri triangulate, optri compare) for this input",
                self.limits.time_limit.as_secs_f64()
            ),
        )
    }

    /// 503 when every large slot is taken.
    fn busy(&self) -> Reply {
        Reply::error(
            503,
            format!(
                "the server is busy: {} computations of more than {SMALL_POINTS} points are \
                 running, its limit; try again shortly",
                self.large.count()
            ),
        )
        .with_header("Retry-After", "1")
    }

    /// Answers a POST whose `body` (at most `max_body_bytes` long) was read
    /// before `deadline`, computing on the slots of the module docs.
    pub(crate) async fn answer(&self, endpoint: Endpoint, body: Bytes, deadline: Instant) -> Reply {
        let cancel = Cancel::new();
        let _stop = CancelOnDrop(cancel.clone());
        self.compute(endpoint, body, deadline, &cancel)
            .await
            .unwrap_or_else(|reply| reply)
    }

    async fn compute(
        &self,
        endpoint: Endpoint,
        body: Bytes,
        deadline: Instant,
        cancel: &Cancel,
    ) -> Result<Reply, Reply> {
        let partial = matches!(endpoint, Endpoint::Run(Kind::Compare));
        let slot = timeout_at(deadline, self.small.wait())
            .await
            .map_err(|_| self.out_of_time())?;
        // A request whose deadline passed while it queued starts stopped:
        // every criterion stops at its first check instead of racing the
        // watcher below.
        if Instant::now() >= deadline {
            cancel.cancel();
        }
        let limits = self.limits.clone();
        let flag = cancel.clone();
        let first = slot.run(move || -> Result<Step, Refusal> {
            let kind = match endpoint {
                Endpoint::Read => return read(&body).map(Step::Done),
                Endpoint::Run(kind) => kind,
            };
            let prepared = prepare(kind, &body, &limits, flag)?;
            Ok(if prepared.points <= SMALL_POINTS {
                Step::Done(run(prepared))
            } else {
                Step::Large(Box::new(prepared))
            })
        });
        match self.wait(first, deadline, cancel, partial).await? {
            Err(refusal) => Err(refused(refusal)),
            Ok(Step::Done(reply)) => Ok(reply),
            Ok(Step::Large(_)) if Instant::now() >= deadline => Err(self.out_of_time()),
            Ok(Step::Large(prepared)) => {
                let slot = self.large.try_take().ok_or_else(|| self.busy())?;
                self.wait(slot.run(move || run(*prepared)), deadline, cancel, partial)
                    .await
            }
        }
    }

    /// The value of a computation, or 503 when `deadline` passes first
    /// (then `cancel` is raised; with `partial`, the computation has
    /// [`PARTIAL_GRACE`] more to return what it has), or 500 if it failed.
    async fn wait<T>(
        &self,
        mut job: oneshot::Receiver<Result<T, Failure>>,
        deadline: Instant,
        cancel: &Cancel,
        partial: bool,
    ) -> Result<T, Reply> {
        let done = match timeout_at(deadline, &mut job).await {
            Ok(done) => done,
            Err(_) => {
                cancel.cancel();
                if !partial {
                    return Err(self.out_of_time());
                }
                timeout(PARTIAL_GRACE, job)
                    .await
                    .map_err(|_| self.out_of_time())?
            }
        };
        match done {
            Ok(Ok(value)) => Ok(value),
            Ok(Err(failure)) => Err(Reply::error(
                500,
                format!(
                    "internal error (a bug in optri; please report it with the input): {failure}"
                ),
            )),
            Err(_) => Err(Reply::error(
                500,
                "internal error: the computation ended without an answer",
            )),
        }
    }
}

/// The library's request for a triangulate, compare or graph `body`: each
/// point an `[x, y]` pair or each an `[x, y, z]` triple (400 otherwise;
/// see [`points_and_elevations`]), at most [`Limits::max_points`]
/// (422), taken at their decimal values when the `body` writes none with
/// more than 15 significant digits ([`ReadInput::from_json_numbers`], as the
/// GeoJSON reader does), with the options named in the body (400 for one the
/// task does not read), this server's time limit (per criterion in a
/// comparison) and `cancel`.
fn prepare(kind: Kind, body: &[u8], limits: &Limits, cancel: Cancel) -> Result<Prepared, Refusal> {
    let (task, points, polygon, metric, options) = match kind {
        Kind::Triangulate => {
            let r: TriangulateRequest = parse(body)?;
            let task = Task::triangulate(&r.criterion).map_err(bad_request)?;
            (task, r.points, r.polygon, r.metric, r.options)
        }
        Kind::Compare => {
            let r: CompareRequest = parse(body)?;
            let task = Task::compare(&r.criteria).map_err(bad_request)?;
            (task, r.points, r.polygon, r.metric, r.options)
        }
        Kind::Graph => {
            let r: GraphRequest = parse(body)?;
            let task = Task::graph(&r.kind).map_err(bad_request)?;
            (task, r.points, false, r.metric, r.options)
        }
        Kind::Decide => {
            let r: DecideRequest = parse(body)?;
            let at_least = threshold_field("at_least", r.at_least)?;
            let at_most = threshold_field("at_most", r.at_most)?;
            let task = Task::decide(&r.criterion, at_least, at_most).map_err(bad_request)?;
            (task, r.points, r.polygon, None, r.options)
        }
    };
    if points.len() > limits.max_points {
        return Err((
            422,
            format!(
                "{} points is more than this server's limit of {} per request; use the \
                 command line (optri triangulate / optri compare) for large inputs",
                points.len(),
                limits.max_points
            ),
        ));
    }
    let count = points.len();
    let (points, elevations) = points_and_elevations(&points)?;
    let input = if polygon {
        io::Input::Polygon(points)
    } else {
        io::Input::Points(points)
    };
    // `parse` accepted the body, so it is UTF-8 and the lossy view is
    // the text itself.
    let mut read = ReadInput::from_json_numbers(input, &String::from_utf8_lossy(body));
    if let Some(z) = elevations {
        read = read.with_elevations(z);
    }
    let mut request =
        Request::new(read, task).with_options(Options::default().with_cancel(cancel.clone()));
    if !limits.time_limit.is_zero() {
        request
            .set_option("time_limit", &limits.time_limit.as_secs_f64().to_string())
            .map_err(|e| library_error(&e))?;
    }
    let named = metric.map(|m| ("metric".to_string(), Value::from(m)));
    for (name, value) in named.into_iter().chain(options) {
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
            let mut check = Options::default();
            check.set(&name, &text).map_err(bad_request)?;
            if check.time_limit > Some(limits.time_limit) {
                return Err(bad_request(format!(
                    "option time_limit: {text} s is more than this server's limit of {} s",
                    limits.time_limit.as_secs_f64()
                )));
            }
        }
        request.set_option(&name, &text).map_err(bad_request)?;
    }
    Ok(Prepared {
        request,
        points: count,
        cancel,
        time_limit: limits.time_limit,
    })
}

/// A request's points, and their elevations when every point has one.
type PointsWithElevations = (Vec<[f64; 2]>, Option<Vec<f64>>);

/// A request's `points`: every one `[x, y]`, or every one `[x, y, z]` (then
/// `z` is its elevation); 400 naming the first point that is neither or
/// differs from point 0.
fn points_and_elevations(points: &[Vec<f64>]) -> Result<PointsWithElevations, Refusal> {
    let width = points.first().map_or(2, Vec::len);
    let bad = points
        .iter()
        .position(|p| !matches!(p.len(), 2 | 3) || p.len() != width);
    if let Some(i) = bad {
        let n = points[i].len();
        return Err(bad_request(if matches!(n, 2 | 3) {
            format!(
                "point {i} has {n} numbers, but point 0 has {width}; every point is [x, y], or \
                 every point [x, y, z]"
            )
        } else {
            format!("point {i} has {n} numbers; each point is [x, y] or [x, y, z]")
        }));
    }
    let xy = points.iter().map(|p| [p[0], p[1]]).collect();
    let z = (width == 3).then(|| points.iter().map(|p| p[2]).collect());
    Ok((xy, z))
}

/// Runs a prepared request and answers with its document. A comparison
/// that the time limit cut short (its flag is raised only then) reports
/// each criterion it stopped as stopped by that limit, and keeps the rest.
fn run(prepared: Prepared) -> Reply {
    let Prepared {
        request,
        cancel,
        time_limit,
        ..
    } = prepared;
    let mut outcome = match request.run() {
        Ok(outcome) => outcome,
        Err(e) => {
            let (status, message) = library_error(&e);
            return match e {
                Error::Unsupported { criterion, .. } => {
                    Reply::json(status, &json!({ "error": message, "criterion": criterion }))
                }
                _ => Reply::error(status, message),
            };
        }
    };
    outcome.finish();
    if !cancel.is_cancelled() || outcome.comparison().is_none() {
        // Serialised directly, so the fields keep the documented order.
        return Reply::json(200, &outcome.document());
    }
    let (read, phases, results) = outcome.into_parts();
    let Results::Comparison(mut results) = results else {
        unreachable!("a comparison's results are a comparison")
    };
    for (_, result) in &mut results {
        if matches!(result, Err(Error::Interrupted(Interruption::Cancelled))) {
            *result = Err(Error::Interrupted(Interruption::TimeLimit {
                seconds: time_limit.as_secs_f64(),
            }));
        }
    }
    Reply::json(
        200,
        &ComparisonReport::new(&results)
            .with_input(&read)
            .with_timing(&phases),
    )
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
    // With elevations, every point is `[x, y, z]`, as the page sends it back.
    let points: Vec<Value> = match &read.elevations {
        Some(z) => read
            .input
            .points()
            .iter()
            .zip(z)
            .map(|(p, z)| json!([p[0], p[1], z]))
            .collect(),
        None => read.input.points().iter().map(|p| json!(p)).collect(),
    };
    Ok(Reply::json(
        200,
        &json!({
            "points": points,
            "polygon": matches!(read.input, io::Input::Polygon(_)),
            "format": read.format.map(InputFormat::name),
        }),
    ))
}

/// Runs `future` to its end on a runtime like the server's.
#[cfg(test)]
fn block_on<T>(future: impl std::future::Future<Output = T>) -> T {
    tokio::runtime::Builder::new_current_thread()
        .enable_time()
        .build()
        .unwrap()
        .block_on(future)
}

#[cfg(test)]
mod tests {
    use super::*;
    use optri_oracle::inputs;
    use rand::{rngs::StdRng, SeedableRng};
    use std::f64::consts::TAU;

    /// Seed of the comparison's points.
    const SEED_POINTS: u64 = 2_000;

    fn limits(time_limit: Duration) -> Limits {
        Limits {
            max_body_bytes: 1 << 20,
            max_points: 10_000,
            time_limit,
            max_running: 1,
            read_timeout: Duration::from_secs(5),
        }
    }

    #[test]
    fn past_the_deadline_the_flag_is_raised_and_the_slot_freed_when_the_work_stops() {
        let api = Api::new(limits(Duration::from_millis(50)));
        let cancel = Cancel::new();
        let flag = cancel.clone();
        let reply = block_on(async {
            let job = api.large.try_take().unwrap().run(move || {
                // A computation that checks its flag, as the library does.
                while !flag.is_cancelled() {
                    std::thread::sleep(Duration::from_millis(1));
                }
            });
            let deadline = Instant::now() + Duration::from_millis(50);
            api.wait(job, deadline, &cancel, false).await
        })
        .unwrap_err();
        assert_eq!(reply.status, 503);
        assert!(reply.body.contains("limit of 0.05 s"), "{}", reply.body);
        assert!(cancel.is_cancelled());
        block_on(async {
            timeout(Duration::from_secs(60), api.large.wait())
                .await
                .expect("the slot is freed once the work has stopped")
        });
    }

    #[test]
    fn a_comparison_past_its_deadline_reports_the_criteria_the_limit_stopped() {
        let api = Api::new(limits(Duration::from_secs(7)));
        let mut rng = StdRng::seed_from_u64(SEED_POINTS);
        let points = inputs::uniform_in_square(&mut rng, SMALL_POINTS, 1000.0);
        let criteria = ["delaunay", "greedy", "minmax-length"];
        let body = json!({ "points": points, "criteria": criteria }).to_string();
        // The deadline has passed when the computation starts: every
        // criterion is stopped at its first check, and the answer says so.
        let reply = block_on(api.answer(
            Endpoint::Run(Kind::Compare),
            Bytes::from(body),
            Instant::now(),
        ));
        assert_eq!(reply.status, 200, "{}", reply.body);
        let doc: Value = serde_json::from_str(&reply.body).unwrap();
        assert_eq!(doc["document"], "comparison");
        let results = doc["results"].as_array().unwrap();
        assert_eq!(results.len(), criteria.len());
        for (r, name) in results.iter().zip(criteria) {
            assert_eq!(r["criterion"], name);
            assert_eq!(
                r["error"],
                "stopped: the time limit of 7 s passed before the run finished"
            );
        }
        // One criterion: 503 naming the limit.
        let body = json!({ "points": points, "criterion": "greedy" }).to_string();
        let reply = block_on(api.answer(
            Endpoint::Run(Kind::Triangulate),
            Bytes::from(body),
            Instant::now(),
        ));
        assert_eq!(reply.status, 503, "{}", reply.body);
        assert!(reply.body.contains("limit of 7 s"), "{}", reply.body);
        // Within the limit, the same comparison is whole.
        let body = json!({ "points": points, "criteria": criteria }).to_string();
        let reply = block_on(api.answer(
            Endpoint::Run(Kind::Compare),
            Bytes::from(body),
            Instant::now() + Duration::from_secs(600),
        ));
        let doc: Value = serde_json::from_str(&reply.body).unwrap();
        assert!(doc["results"]
            .as_array()
            .unwrap()
            .iter()
            .all(|r| r["triangles"].is_array()));
    }

    #[test]
    fn a_criterion_that_refuses_the_input_is_named() {
        let api = Api::new(limits(Duration::from_secs(60)));
        // A star with 4001 vertices: more than the polygon program takes.
        let star: Vec<[f64; 2]> = (0..4001)
            .map(|i| {
                let (r, angle) = (1000.0 - 100.0 * (i % 2) as f64, i as f64 / 4001.0 * TAU);
                [r * angle.cos(), r * angle.sin()]
            })
            .collect();
        let body = json!({ "points": star, "criterion": "minmax-area", "polygon": true });
        let reply = block_on(api.answer(
            Endpoint::Run(Kind::Triangulate),
            Bytes::from(body.to_string()),
            Instant::now() + Duration::from_secs(600),
        ));
        let doc: Value = serde_json::from_str(&reply.body).unwrap();
        assert_eq!(reply.status, 422, "{doc}");
        assert_eq!(doc["criterion"], "minmax-area", "{doc}");
        // An input every criterion refuses names none.
        let body = json!({ "points": [[0, 0], [1, 1], [2, 2]], "criterion": "delaunay" });
        let reply = block_on(api.answer(
            Endpoint::Run(Kind::Triangulate),
            Bytes::from(body.to_string()),
            Instant::now() + Duration::from_secs(600),
        ));
        let doc: Value = serde_json::from_str(&reply.body).unwrap();
        assert_eq!(reply.status, 422);
        assert!(doc.get("criterion").is_none(), "{doc}");
    }

    #[test]
    fn points_carry_elevations_all_or_none() {
        let api = Api::new(limits(Duration::from_secs(60)));
        let ask = |kind: Kind, body: Value| {
            let reply = block_on(api.answer(
                Endpoint::Run(kind),
                Bytes::from(body.to_string()),
                Instant::now() + Duration::from_secs(600),
            ));
            (
                reply.status,
                serde_json::from_str::<Value>(&reply.body).unwrap(),
            )
        };
        let terrain = json!([[0, 0, 1], [4, 0, 2.5], [0, 3, -1], [4, 3, 0]]);
        let (status, doc) = ask(Kind::Triangulate, json!({ "points": terrain }));
        assert_eq!(status, 200, "{doc}");
        assert_eq!(doc["elevations"], json!([1.0, 2.5, -1.0, 0.0]));
        assert_eq!(doc["coordinates"][1], json!([4.0, 0.0]));
        let (status, doc) = ask(
            Kind::Compare,
            json!({ "points": terrain, "criteria": ["greedy"] }),
        );
        assert_eq!(status, 200, "{doc}");
        assert_eq!(doc["results"][0]["elevations"][1], 2.5);
        // Mixed lengths are refused naming the point; so are bad elevations.
        for (points, status, needle) in [
            (
                json!([[0, 0, 1], [4, 0], [0, 3, 2]]),
                400,
                "point 1 has 2 numbers, but point 0 has 3",
            ),
            (
                json!([[0, 0], [4, 0], [0, 3, 2]]),
                400,
                "point 2 has 3 numbers, but point 0 has 2",
            ),
            (
                json!([[0, 0], [4, 0, 1, 2], [0, 3]]),
                400,
                "point 1 has 4 numbers; each point is",
            ),
            (
                json!([[0, 0, 1], [4, 0, 1e300], [0, 3, 2]]),
                422,
                "point 1 has elevation",
            ),
            (
                json!([[0, 0, 1], [4, 0, 2], [0, 3, 2], [4, 0, 3]]),
                422,
                "point 3 repeats point 1",
            ),
        ] {
            let (got, doc) = ask(Kind::Triangulate, json!({ "points": points }));
            assert_eq!(got, status, "{doc}");
            let message = doc["error"].as_str().unwrap();
            assert!(message.contains(needle), "{message}");
        }
        // A file with a z column reads back as triples.
        let reply = read(
            json!({ "text": "0 0 1\n4 0 2\n0 3 3\n" })
                .to_string()
                .as_bytes(),
        )
        .unwrap();
        let doc: Value = serde_json::from_str(&reply.body).unwrap();
        assert_eq!(
            doc["points"],
            json!([[0.0, 0.0, 1.0], [4.0, 0.0, 2.0], [0.0, 3.0, 3.0]])
        );
    }
}
