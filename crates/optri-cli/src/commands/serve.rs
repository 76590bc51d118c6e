//! `optri serve`: the web playground. This is the HTTP loop only (tiny_http,
//! a few worker threads): the page and the API are in `crate::web`, which
//! answers from the library.

use crate::args::ServeArgs;
use crate::web::{Api, Limits, Reply};
use crate::CliResult;
use std::io::{Read, Write};
use std::sync::Arc;
use std::time::Duration;

/// Threads answering requests (computations run on threads of their own,
/// at most `Limits::max_running` at once).
const WORKERS: usize = 4;

pub(crate) fn run(args: ServeArgs) -> CliResult<()> {
    let limits = Limits {
        max_body_bytes: args.max_body_mib * 1024 * 1024,
        max_points: args.max_points,
        time_limit: Duration::try_from_secs_f64(args.time_limit)
            .map_err(|e| format!("invalid --time-limit {}: {e}", args.time_limit))?,
        max_running: args.max_running.max(1),
    };
    let address = format!("{}:{}", args.host, args.port);
    let server = tiny_http::Server::http(&address)
        .map_err(|e| format!("cannot listen on {address}: {e}"))?;
    let bound = server
        .server_addr()
        .to_ip()
        .map_or_else(|| address.clone(), |a| a.to_string());
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
    let server = Arc::new(server);
    let api = Arc::new(Api::new(limits.clone()));
    let workers: Vec<_> = (0..WORKERS)
        .map(|_| {
            let (server, api, limits) = (Arc::clone(&server), Arc::clone(&api), limits.clone());
            std::thread::spawn(move || {
                while let Ok(request) = server.recv() {
                    answer(&api, &limits, request);
                }
            })
        })
        .collect();
    for worker in workers {
        let _ = worker.join();
    }
    Ok(())
}

/// Reads the body within the size limit, answers, and sends the reply. A
/// client that hangs up is not an error of the server.
fn answer(api: &Api, limits: &Limits, mut request: tiny_http::Request) {
    let too_large = || {
        Reply::error(
            413,
            format!(
                "the request body is larger than this server's limit of {} bytes",
                limits.max_body_bytes
            ),
        )
    };
    let reply = if request
        .body_length()
        .is_some_and(|n| n > limits.max_body_bytes)
    {
        too_large()
    } else {
        let mut body = Vec::new();
        let limit = limits.max_body_bytes as u64 + 1;
        match request.as_reader().take(limit).read_to_end(&mut body) {
            Err(e) => Reply::error(400, format!("cannot read the request body: {e}")),
            Ok(_) if body.len() > limits.max_body_bytes => too_large(),
            Ok(_) => {
                let method = request.method().as_str().to_ascii_uppercase();
                api.respond(&method, request.url(), &body)
            }
        }
    };
    let content_type = tiny_http::Header::from_bytes("Content-Type", reply.content_type)
        .expect("a constant header is valid");
    let response = tiny_http::Response::from_string(reply.body)
        .with_status_code(reply.status)
        .with_header(content_type);
    let _ = request.respond(response);
}
