//! `optri serve`: the web playground. This is the HTTP loop only: hyper's
//! HTTP/1.1 (keep-alive, a time limit on request headers) on a one-thread
//! tokio runtime that only moves bytes, reading bodies within their own
//! time limits; the routes, the limits and the computations, which run on
//! pools of their own, are in `crate::web`.

use crate::args::ServeArgs;
use crate::web::{Api, Limits, Origins, Reply, Route};
use crate::CliResult;
use http_body_util::{BodyExt, Full};
use hyper::body::{Bytes, Incoming};
use hyper::header::{HeaderValue, CONTENT_LENGTH, CONTENT_TYPE, HOST, ORIGIN};
use hyper::{Method, Request, Response, Version};
use hyper_util::rt::{TokioIo, TokioTimer};
use std::convert::Infallible;
use std::io::Write;
use std::sync::Arc;
use std::time::Duration;
use tokio::sync::Semaphore;
use tokio::time::{timeout_at, Instant};

/// Connections served at once; more wait in the listen queue. Each costs a
/// few kilobytes, and a stalled one is dropped after the read timeout.
const MAX_CONNECTIONS: usize = 512;

/// The longest time limit and read timeout accepted: a year, in seconds.
pub(crate) const MAX_SECONDS: f64 = 365.0 * 24.0 * 3600.0;

pub(crate) fn run(args: ServeArgs) -> CliResult<()> {
    let limits = limits(&args)?;
    let listener = std::net::TcpListener::bind((args.host.as_str(), args.port))
        .map_err(|e| format!("cannot listen on {}:{}: {e}", args.host, args.port))?;
    let bound = listener
        .local_addr()
        .map_err(|e| format!("cannot read the listening address: {e}"))?;
    listener
        .set_nonblocking(true)
        .map_err(|e| format!("cannot listen on {bound}: {e}"))?;
    let runtime = tokio::runtime::Builder::new_current_thread()
        .enable_io()
        .enable_time()
        .build()
        .map_err(|e| format!("cannot start the server: {e}"))?;
    let server = Arc::new(Server {
        api: Api::new(limits),
        origins: Origins::new(bound),
    });
    runtime.block_on(async move {
        let listener = tokio::net::TcpListener::from_std(listener)
            .map_err(|e| format!("cannot listen on {bound}: {e}"))?;
        {
            // Scripts (and the tests) read the port from this line.
            let mut out = std::io::stdout().lock();
            writeln!(
                out,
                "optri serve: listening on http://{bound}/ (Ctrl-C stops)"
            )
            .and_then(|()| out.flush())
            .map_err(|e| crate::report::output_error("stdout", &e))?;
        }
        server.accept(listener).await;
        Ok(())
    })
}

/// The limits of `args`, refusing values that overflow or make no sense.
fn limits(args: &ServeArgs) -> CliResult<Limits> {
    let seconds = |option: &str, value: f64| {
        if !(0.0..=MAX_SECONDS).contains(&value) {
            return Err(format!(
                "invalid {option} {value:?}: give a number of seconds from 0 to {MAX_SECONDS} \
                 (a year)"
            ));
        }
        Ok(Duration::from_secs_f64(value))
    };
    let max_body_bytes = args.max_body_mib.checked_mul(1024 * 1024).ok_or_else(|| {
        format!(
            "invalid --max-body-mib {}: at most {} MiB fit in memory addresses",
            args.max_body_mib,
            usize::MAX / (1024 * 1024)
        )
    })?;
    if args.max_running == 0 {
        return Err("invalid --max-running 0: at least one computation must run".to_string());
    }
    let read_timeout = seconds("--read-timeout", args.read_timeout)?;
    if read_timeout.is_zero() {
        return Err("invalid --read-timeout 0: a client needs some time to send".to_string());
    }
    let time_limit = seconds("--time-limit", args.time_limit)?;
    if time_limit.is_zero() {
        return Err("invalid --time-limit 0: every request would be over it".to_string());
    }
    Ok(Limits {
        max_body_bytes,
        max_points: args.max_points,
        time_limit,
        max_running: args.max_running,
        read_timeout,
    })
}

/// What every connection shares.
struct Server {
    api: Api,
    origins: Origins,
}

impl Server {
    /// Accepts connections forever, each served by a task of its own.
    async fn accept(self: Arc<Self>, listener: tokio::net::TcpListener) {
        let connections = Arc::new(Semaphore::new(MAX_CONNECTIONS));
        loop {
            let permit = Arc::clone(&connections)
                .acquire_owned()
                .await
                .expect("the semaphore is never closed");
            let stream = match listener.accept().await {
                Ok((stream, _)) => stream,
                Err(_) => {
                    // Out of file descriptors, or a connection reset before
                    // it was accepted: try again shortly.
                    tokio::time::sleep(Duration::from_millis(50)).await;
                    continue;
                }
            };
            let _ = stream.set_nodelay(true);
            let server = Arc::clone(&self);
            tokio::spawn(async move {
                let _permit = permit;
                let read_timeout = server.api.limits().read_timeout;
                let service = hyper::service::service_fn(move |request| {
                    let server = Arc::clone(&server);
                    async move { Ok::<_, Infallible>(server.answer(request).await) }
                });
                // A client that hangs up or times out is not an error of the
                // server.
                let _ = hyper::server::conn::http1::Builder::new()
                    .timer(TokioTimer::new())
                    .header_read_timeout(read_timeout)
                    .keep_alive(true)
                    .serve_connection(TokioIo::new(stream), service)
                    .await;
            });
        }
    }

    /// Checks where a request comes from, routes it, reads its body if it
    /// has one to compute on, and answers.
    async fn answer(&self, request: Request<Incoming>) -> Response<Full<Bytes>> {
        let start = Instant::now();
        let head = request.method() == Method::HEAD;
        let checked = self.origins.check(
            request.method() == Method::POST,
            request.version() == Version::HTTP_11,
            header_text(request.headers().get(HOST)),
            header_text(request.headers().get(ORIGIN)),
        );
        let route = match checked {
            Err((status, message)) => Route::Ready(Reply::error(status, message)),
            Ok(()) => {
                let method = if head {
                    "GET"
                } else {
                    request.method().as_str()
                };
                self.api.route(method, request.uri().path())
            }
        };
        let reply = match route {
            Route::Ready(reply) => reply,
            Route::Compute(endpoint) => {
                let deadline = start + self.api.limits().time_limit;
                match self.read_body(request, deadline).await {
                    Ok(body) => self.api.answer(endpoint, body, deadline).await,
                    Err(reply) => reply,
                }
            }
        };
        respond(reply, head)
    }

    /// The body, read before `deadline` (503) with no stall longer than the
    /// read timeout (408), and no longer than the limit (413).
    async fn read_body(
        &self,
        request: Request<Incoming>,
        deadline: Instant,
    ) -> Result<Bytes, Reply> {
        let limits = self.api.limits();
        let too_large = || {
            Reply::error(
                413,
                format!(
                    "the request body is larger than this server's limit of {} bytes",
                    limits.max_body_bytes
                ),
            )
        };
        let announced = request
            .headers()
            .get(CONTENT_LENGTH)
            .and_then(|v| v.to_str().ok()?.parse::<u64>().ok());
        if announced.is_some_and(|n| n > limits.max_body_bytes as u64) {
            return Err(too_large());
        }
        let mut body = request.into_body();
        let mut read = Vec::new();
        loop {
            let stall = Instant::now() + limits.read_timeout;
            let frame = match timeout_at(stall.min(deadline), body.frame()).await {
                Ok(Some(frame)) => frame,
                Ok(None) => return Ok(Bytes::from(read)),
                Err(_) if Instant::now() >= deadline => return Err(self.api.out_of_time()),
                Err(_) => {
                    return Err(Reply::error(
                        408,
                        format!(
                            "the request body stalled: nothing arrived for {} s",
                            limits.read_timeout.as_secs_f64()
                        ),
                    ))
                }
            };
            let frame = frame
                .map_err(|e| Reply::error(400, format!("cannot read the request body: {e}")))?;
            if let Ok(data) = frame.into_data() {
                if read.len() + data.len() > limits.max_body_bytes {
                    return Err(too_large());
                }
                read.extend_from_slice(&data);
            }
        }
    }
}

/// A header's text; one that is not text is passed as empty (and refused
/// where it is checked).
fn header_text(value: Option<&HeaderValue>) -> Option<&str> {
    value.map(|v| v.to_str().unwrap_or(""))
}

/// The HTTP response of `reply`: its headers and `nosniff`, and its body
/// unless the request was `HEAD` (hyper then writes the length and no body).
fn respond(reply: Reply, head: bool) -> Response<Full<Bytes>> {
    let body = match reply.body {
        std::borrow::Cow::Borrowed(text) => Bytes::from_static(text.as_bytes()),
        std::borrow::Cow::Owned(text) => Bytes::from(text),
    };
    let mut response = Response::builder()
        .status(reply.status)
        .header(CONTENT_TYPE, reply.content_type)
        .header("X-Content-Type-Options", "nosniff");
    if head {
        response = response.header(CONTENT_LENGTH, body.len());
    }
    for (name, value) in reply.headers {
        response = response.header(name, value);
    }
    let body = if head { Bytes::new() } else { body };
    response.body(Full::new(body)).unwrap_or_else(|_| {
        let mut failed = Response::new(Full::new(Bytes::from_static(
            b"{\"error\": \"cannot encode the answer\"}",
        )));
        *failed.status_mut() = hyper::StatusCode::INTERNAL_SERVER_ERROR;
        failed
    })
}
