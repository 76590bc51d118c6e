//! Which requests a server bound to a loopback address accepts: those whose
//! `Host` names a loopback address or `localhost` with the server's port,
//! and POSTs whose `Origin`, if they carry one, is such an address too.
//!
//! This defeats DNS rebinding: a page from another site that has its
//! domain name resolve to 127.0.0.1 reaches the port, but its requests say
//! `Host: its-domain` (and its POSTs `Origin: http://its-domain`), so it can
//! neither read the playground nor start computations. A server bound to
//! another address serves whoever reaches it (the `--host` help says so)
//! and checks neither.

use std::net::{IpAddr, SocketAddr};

/// The server's own address, as the check needs it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Origins {
    /// Bound to a loopback address: the checks apply.
    loopback: bool,
    port: u16,
}

/// A refused request: its status and message.
pub(crate) type Refusal = (u16, String);

impl Origins {
    /// The checks for a server listening on `bound`.
    pub(crate) fn new(bound: SocketAddr) -> Self {
        Self {
            loopback: bound.ip().is_loopback(),
            port: bound.port(),
        }
    }

    /// Accepts or refuses a request from its method and its `Host` and
    /// `Origin` headers (`None`: absent; a header that is not text is
    /// passed as `Some("")`). An HTTP/1.1 request without `Host` is malformed
    /// (400, RFC 9112 §3.2); an HTTP/1.0 one has no `Host` to check.
    pub(crate) fn check(
        &self,
        post: bool,
        http_1_1: bool,
        host: Option<&str>,
        origin: Option<&str>,
    ) -> Result<(), Refusal> {
        if host.is_none() && http_1_1 {
            return Err((400, "an HTTP/1.1 request needs a Host header".to_string()));
        }
        if !self.loopback {
            return Ok(());
        }
        if let Some(host) = host {
            if !self.is_own(host) {
                return Err((
                    403,
                    format!(
                        "Host {host:?} is not this server: a server on a loopback address \
                         answers requests for localhost:{port} or 127.0.0.1:{port} only",
                        port = self.port
                    ),
                ));
            }
        }
        if let Some(origin) = origin.filter(|_| post) {
            let own = origin
                .strip_prefix("http://")
                .is_some_and(|authority| self.is_own(authority));
            if !own {
                return Err((
                    403,
                    format!(
                        "a page from {origin:?} may not post to this server: it accepts \
                         requests from its own page (http://localhost:{}/) only",
                        self.port
                    ),
                ));
            }
        }
        Ok(())
    }

    /// Is `authority` (`name[:port]`, `[v6][:port]`) a loopback name or
    /// address with this server's port (80 when none is written)?
    fn is_own(&self, authority: &str) -> bool {
        let (name, port) = match authority.rsplit_once(':') {
            // An IPv6 address without a port has colons but ends with `]`.
            Some((name, port)) if !port.ends_with(']') => (name, port.parse::<u16>().ok()),
            _ => (authority, Some(80)),
        };
        let loopback_name = name.eq_ignore_ascii_case("localhost")
            || name
                .strip_prefix('[')
                .and_then(|n| n.strip_suffix(']'))
                .unwrap_or(name)
                .parse::<IpAddr>()
                .is_ok_and(|ip| ip.is_loopback());
        loopback_name && port == Some(self.port)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn loopback(port: u16) -> Origins {
        Origins::new(SocketAddr::from(([127, 0, 0, 1], port)))
    }

    fn status(result: Result<(), Refusal>) -> u16 {
        result.map_or_else(|(status, _)| status, |()| 200)
    }

    #[test]
    fn host_must_be_a_loopback_name_with_the_port() {
        let o = loopback(8000);
        for host in [
            "localhost:8000",
            "LocalHost:8000",
            "127.0.0.1:8000",
            "127.1.2.3:8000",
            "[::1]:8000",
        ] {
            assert_eq!(
                status(o.check(false, true, Some(host), None)),
                200,
                "{host}"
            );
        }
        for host in [
            "evil.example:8000",
            "localhost:8001",
            "localhost",
            "localhost.:8000",
            "127.0.0.1:80000",
            "10.0.0.1:8000",
            "[::2]:8000",
            "localhost:8000:8000",
            "",
        ] {
            assert_eq!(
                status(o.check(false, true, Some(host), None)),
                403,
                "{host}"
            );
        }
        // Without a port, a Host means port 80.
        assert_eq!(
            status(loopback(80).check(false, true, Some("localhost"), None)),
            200
        );
        assert_eq!(
            status(loopback(80).check(false, true, Some("[::1]"), None)),
            200
        );
        assert_eq!(status(o.check(false, true, None, None)), 400);
        assert_eq!(status(o.check(false, false, None, None)), 200);
    }

    #[test]
    fn a_post_from_another_origin_is_refused() {
        let o = loopback(8000);
        let host = Some("127.0.0.1:8000");
        for origin in ["http://127.0.0.1:8000", "http://localhost:8000"] {
            assert_eq!(
                status(o.check(true, true, host, Some(origin))),
                200,
                "{origin}"
            );
        }
        for origin in [
            "http://evil.example:8000",
            "https://localhost:8000",
            "http://localhost:9000",
            "null",
            "http://localhost:8000/path",
        ] {
            assert_eq!(
                status(o.check(true, true, host, Some(origin))),
                403,
                "{origin}"
            );
        }
        // GETs are not checked for Origin; no Origin is a script, not a page.
        assert_eq!(status(o.check(false, true, host, Some("null"))), 200);
        assert_eq!(status(o.check(true, true, host, None)), 200);
    }

    #[test]
    fn a_server_on_another_address_checks_neither() {
        let o = Origins::new(SocketAddr::from(([0, 0, 0, 0], 8000)));
        assert_eq!(
            status(o.check(
                true,
                true,
                Some("evil.example"),
                Some("http://evil.example")
            )),
            200
        );
        assert_eq!(status(o.check(true, true, None, None)), 400);
    }
}
