//! `arch-enum serve`, driven over loopback HTTP: the API's bodies are the CLI's `--json`
//! documents byte for byte, the page is served, malformed requests get a 400 JSON error
//! naming the argument, and a seeded fuzz loop of malformed queries gets no 500 and leaves
//! the server answering.

use assert_cmd::cargo::cargo_bin;
use serde_json::Value;
use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// A running `arch-enum serve --port 0`, killed on drop.
struct Server {
    child: Child,
    addr: String,
}

impl Server {
    fn start() -> Server {
        Server::start_with(&[])
    }

    fn start_with(extra: &[&str]) -> Server {
        let mut child = Command::new(cargo_bin("arch-enum"))
            .args(["serve", "--port", "0"])
            .args(extra)
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let mut line = String::new();
        BufReader::new(child.stdout.take().unwrap())
            .read_line(&mut line)
            .unwrap();
        let addr = line
            .trim()
            .strip_prefix("http://")
            .and_then(|s| s.strip_suffix('/'))
            .unwrap_or_else(|| panic!("first line is the URL, got {line:?}"))
            .to_string();
        assert!(addr.starts_with("127.0.0.1:"), "loopback only: {addr}");
        Server { child, addr }
    }

    /// Sends `method target` (raw bytes: the target may be anything) and reads the reply.
    fn raw(&self, method: &[u8], target: &[u8]) -> std::io::Result<Reply> {
        let mut s = TcpStream::connect(&self.addr)?;
        s.set_read_timeout(Some(Duration::from_secs(30)))?;
        let mut req = Vec::new();
        req.extend_from_slice(method);
        req.push(b' ');
        req.extend_from_slice(target);
        req.extend_from_slice(b" HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n");
        s.write_all(&req)?;
        let mut buf = Vec::new();
        s.read_to_end(&mut buf)?;
        Reply::parse(&buf)
    }

    /// Sends `request` (a whole head, and a body if any) as it is and reads the reply.
    fn send(&self, request: &[u8]) -> std::io::Result<Reply> {
        let mut s = TcpStream::connect(&self.addr)?;
        s.set_read_timeout(Some(Duration::from_secs(30)))?;
        s.write_all(request)?;
        let mut buf = Vec::new();
        s.read_to_end(&mut buf)?;
        Reply::parse(&buf)
    }

    fn get(&self, target: &str) -> Reply {
        self.raw(b"GET", target.as_bytes())
            .unwrap_or_else(|e| panic!("GET {target}: {e}"))
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

#[derive(Debug)]
struct Reply {
    status: u16,
    headers: Vec<(String, String)>,
    body: Vec<u8>,
}

impl Reply {
    fn parse(buf: &[u8]) -> std::io::Result<Reply> {
        let bad =
            |what: &str| std::io::Error::new(std::io::ErrorKind::InvalidData, what.to_string());
        let end = buf
            .windows(4)
            .position(|w| w == b"\r\n\r\n")
            .ok_or_else(|| bad("no end of headers"))?;
        let head = std::str::from_utf8(&buf[..end]).map_err(|_| bad("head not UTF-8"))?;
        let mut lines = head.split("\r\n");
        let status = lines
            .next()
            .and_then(|l| l.split(' ').nth(1))
            .and_then(|c| c.parse().ok())
            .ok_or_else(|| bad("no status"))?;
        let headers = lines
            .filter_map(|l| l.split_once(':'))
            .map(|(k, v)| (k.trim().to_ascii_lowercase(), v.trim().to_string()))
            .collect();
        let mut reply = Reply {
            status,
            headers,
            body: buf[end + 4..].to_vec(),
        };
        if reply.header("transfer-encoding") == Some("chunked") {
            reply.body = dechunk(&reply.body).ok_or_else(|| bad("bad chunked body"))?;
        }
        Ok(reply)
    }
    fn header(&self, name: &str) -> Option<&str> {
        self.headers
            .iter()
            .find(|(k, _)| k == name)
            .map(|(_, v)| v.as_str())
    }
    fn json(&self) -> Value {
        serde_json::from_slice(&self.body).unwrap_or_else(|e| {
            panic!(
                "body is not JSON ({e}): {}",
                String::from_utf8_lossy(&self.body)
            )
        })
    }
}

/// The body of a `Transfer-Encoding: chunked` reply.
fn dechunk(mut raw: &[u8]) -> Option<Vec<u8>> {
    let mut body = Vec::new();
    loop {
        let eol = raw.windows(2).position(|w| w == b"\r\n")?;
        let size = std::str::from_utf8(&raw[..eol]).ok()?;
        let size = usize::from_str_radix(size.split(';').next()?.trim(), 16).ok()?;
        raw = &raw[eol + 2..];
        if size == 0 {
            return Some(body);
        }
        body.extend_from_slice(raw.get(..size)?);
        raw = raw.get(size + 2..)?;
    }
}

/// The CLI's standard output and exit status for `args`.
fn cli(args: &[&str]) -> (Vec<u8>, i32) {
    let out = Command::new(cargo_bin("arch-enum"))
        .args(args)
        .stderr(Stdio::null())
        .output()
        .unwrap();
    (out.stdout, out.status.code().unwrap())
}

/// Each endpoint's body is byte for byte the CLI's `--json` output; exit 0 and exit 1
/// (an answer: no equilibrium, ...) are 200, exit 2 (bad input) is 400.
#[test]
fn api_bodies_are_the_cli_json() {
    let server = Server::start();
    let cases: &[(&str, &[&str])] = &[
        (
            "/api/solve?alpha=0&mu=0.35",
            &["solve", "--alpha", "0", "--mu", "0.35"],
        ),
        (
            "/api/solve?alpha=0&blocks=6&mu=ms",
            &["solve", "--alpha", "0", "--blocks", "6", "--mu", "ms"],
        ),
        (
            "/api/solve?alpha-deg=30&blocks=12&mu=inf&weight=centroid",
            &[
                "solve",
                "--alpha-deg",
                "30",
                "--blocks",
                "12",
                "--mu",
                "inf",
                "--weight",
                "centroid",
            ],
        ),
        (
            "/api/solve?beta_right=-0.2&beta_left=3.0&mu=0.5&explain",
            &[
                "solve",
                "--beta-right",
                "-0.2",
                "--beta-left",
                "3.0",
                "--mu",
                "0.5",
                "--explain",
            ],
        ),
        (
            "/api/solve?alpha=0&mu=0.2",
            &["solve", "--alpha", "0", "--mu", "0.2"],
        ),
        ("/api/modes?alpha=0", &["modes", "--alpha", "0"]),
        (
            "/api/modes?alpha=1.0&blocks=12",
            &["modes", "--alpha", "1.0", "--blocks", "12"],
        ),
        (
            "/api/assess?alpha=0&eta=0.2&mu=0.35",
            &["assess", "--alpha", "0", "--eta", "0.2", "--mu", "0.35"],
        ),
        (
            "/api/assess?span=10&rise=5&ring=0.6&mu=0.6&width=1&unit_weight=20",
            &[
                "assess",
                "--span",
                "10",
                "--rise",
                "5",
                "--ring",
                "0.6",
                "--mu",
                "0.6",
                "--width",
                "1",
                "--unit-weight",
                "20",
            ],
        ),
        (
            "/api/load?alpha=0&eta=0.3&mu=0.8&horizontal",
            &[
                "load",
                "--alpha",
                "0",
                "--eta",
                "0.3",
                "--mu",
                "0.8",
                "--horizontal",
            ],
        ),
        (
            "/api/load?alpha=0&blocks=20&eta=0.3&mu=0.8&point-load-deg=60",
            &[
                "load",
                "--alpha",
                "0",
                "--blocks",
                "20",
                "--eta",
                "0.3",
                "--mu",
                "0.8",
                "--point-load-deg",
                "60",
            ],
        ),
        (
            "/api/certify?alpha=0&mu=0.35",
            &["certify", "--alpha", "0", "--mu", "0.35"],
        ),
        (
            "/api/curve?alpha=0&points=5",
            &["curve", "--alpha", "0", "--points", "5"],
        ),
        // bad input: the CLI's own error document
        (
            "/api/solve?alpha=0&mu=-1",
            &["solve", "--alpha", "0", "--mu", "-1"],
        ),
        (
            "/api/solve?alpha=0&mu=abc",
            &["solve", "--alpha", "0", "--mu", "abc"],
        ),
        (
            "/api/solve?alpha=2&mu=1",
            &["solve", "--alpha", "2", "--mu", "1"],
        ),
        (
            "/api/assess?alpha=0&eta=3&mu=1",
            &["assess", "--alpha", "0", "--eta", "3", "--mu", "1"],
        ),
    ];
    let mut exits = [0; 3];
    for (target, args) in cases {
        let reply = server.get(target);
        let mut args = args.to_vec();
        args.push("--json");
        let (stdout, code) = cli(&args);
        exits[code as usize] += 1;
        let status = if code == 2 { 400 } else { 200 };
        assert_eq!(reply.status, status, "{target} (CLI exit {code})");
        assert_eq!(
            reply.header("content-type"),
            Some("application/json"),
            "{target}"
        );
        assert!(
            reply.body == stdout,
            "{target}: the body differs from `arch-enum {}`:\n{}\n---\n{}",
            args.join(" "),
            String::from_utf8_lossy(&reply.body),
            String::from_utf8_lossy(&stdout)
        );
    }
    // the cases cover every kind of exit
    assert!(exits.iter().all(|&n| n > 0), "exits 0/1/2: {exits:?}");
}

#[test]
fn page_and_figures_are_served() {
    let server = Server::start();
    for (target, kind, needle) in [
        ("/", "text/html", "<title>arch-enum explorer</title>"),
        ("/index.html", "text/html", "/explorer.js"),
        ("/explorer.js", "text/javascript", "drawDiagram"),
        ("/explorer.css", "text/css", "svg.diagram"),
    ] {
        let r = server.get(target);
        assert_eq!(r.status, 200, "{target}");
        assert!(
            r.header("content-type").unwrap().starts_with(kind),
            "{target}"
        );
        assert!(
            String::from_utf8_lossy(&r.body).contains(needle),
            "{target}"
        );
    }
    // the figure is the `plot arch` SVG, byte for byte
    let dir = std::env::temp_dir().join(format!("arch-enum-serve-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("arch.svg");
    let (_, code) = cli(&[
        "plot",
        "arch",
        "--alpha",
        "0",
        "--mu",
        "0.35",
        "--out",
        file.to_str().unwrap(),
    ]);
    assert_eq!(code, 0);
    let r = server.get("/api/plot/arch?alpha=0&mu=0.35");
    assert_eq!(r.status, 200);
    assert_eq!(r.header("content-type"), Some("image/svg+xml"));
    assert!(
        r.body == std::fs::read(&file).unwrap(),
        "the SVG differs from `plot arch --out`"
    );
    std::fs::remove_dir_all(&dir).unwrap();
    for target in [
        "/api/plot/load?alpha=0&eta=0.3&mu=0.8&horizontal",
        "/api/plot/eccentricity?alpha=0&mu=0.35",
    ] {
        let r = server.get(target);
        assert_eq!(r.status, 200, "{target}");
        assert!(r.body.starts_with(b"<svg"), "{target}");
    }
    // no figure (mu below mu_ms): 422 with the plot command's reason
    let r = server.get("/api/plot/arch?alpha=0&mu=0.2");
    assert_eq!(r.status, 422);
    assert!(r.json()["message"].as_str().unwrap().contains("mu_ms"));
}

/// A 400 with the error document, whose message contains `needle`.
fn refused(server: &Server, target: &str, needle: &str) {
    refused_with(400, server, target, needle)
}

/// A `status` with the error document, whose message contains `needle`.
fn refused_with(status: u16, server: &Server, target: &str, needle: &str) {
    let r = server.get(target);
    let shown: String = target.chars().take(120).collect();
    assert_eq!(
        r.status,
        status,
        "{shown}: {}",
        String::from_utf8_lossy(&r.body)
    );
    assert_eq!(
        r.header("content-type"),
        Some("application/json"),
        "{shown}"
    );
    let v = r.json();
    assert_eq!(v["status"], "error", "{shown}");
    let message = v["message"].as_str().unwrap();
    assert!(
        message.contains(needle),
        "{shown}: {message:?} lacks {needle:?}"
    );
}

#[test]
fn malformed_requests_are_refused_with_the_argument_named() {
    let server = Server::start();
    // bad numbers, unknown keys, missing values, refused keys
    refused(&server, "/api/solve?alpha=0&mu=abc", "--mu");
    refused(&server, "/api/solve?alpha=0&mu=", "--mu");
    refused(&server, "/api/solve?alpha=0&mu", "'mu' needs a value");
    refused(&server, "/api/solve?alpha=0", "--mu");
    refused(
        &server,
        "/api/solve?alpha=0&mu=1&bogus=2",
        "unknown parameter 'bogus'",
    );
    refused(
        &server,
        "/api/solve?alpha=0&mu=1&json",
        "unknown parameter 'json'",
    );
    // a figure's width is its PNG's: the API draws SVG
    refused(
        &server,
        "/api/plot/arch?alpha=0&mu=1&width=500",
        "unknown parameter 'width'",
    );
    refused(
        &server,
        "/api/solve?alpha=0&mu=1&compas=x.json",
        "unknown parameter 'compas'",
    );
    refused(
        &server,
        "/api/certify?alpha=0&mu=1&out=c.json",
        "unknown parameter 'out'",
    );
    refused(
        &server,
        "/api/plot/arch?alpha=0&mu=1&out=a.svg",
        "unknown parameter 'out'",
    );
    refused(&server, "/api/solve?alpha=0&mu=1&mu=2", "--mu");
    refused(
        &server,
        "/api/load?alpha=0&eta=0.3&mu=1&horizontal=maybe",
        "'horizontal' is a flag",
    );
    refused(&server, "/api/load?alpha=0&eta=0.3&mu=1", "--horizontal");
    refused(&server, "/api/plot/arch?alpha=0&mu=-2", "--mu");
    // counts beyond the served limits
    refused(&server, "/api/solve?alpha=0&mu=1&blocks=100001", "--blocks");
    refused(
        &server,
        "/api/solve?alpha=0&mu=1&blocks=99999999999999999999",
        "--blocks",
    );
    refused(
        &server,
        "/api/load?alpha=0&eta=0.3&mu=1&horizontal&blocks=1001",
        "--blocks",
    );
    refused(&server, "/api/modes?alpha=0&blocks=201", "--blocks");
    refused(
        &server,
        "/api/modes?alpha=0&blocks=71&weight=centroid",
        "/api/modes with --weight centroid: 1 to 70",
    );
    refused(
        &server,
        "/api/certify?alpha=0&blocks=1001&eta=0.3&mu=0.8&horizontal",
        "/api/certify with a live load: 1 to 1000",
    );
    refused(&server, "/api/curve?alpha=0&points=101", "--points");
    let joints: Vec<String> = (1..=250)
        .map(|k| format!("{:.4}", k as f64 * 0.012))
        .collect();
    refused(
        &server,
        &format!("/api/modes?alpha=0&joints={}", joints.join(",")),
        "--joints",
    );
    // percent-encoding garbage and non-UTF-8
    refused(&server, "/api/solve?alpha=0&mu=%G1", "'mu'");
    refused(&server, "/api/solve?alpha=0&mu=%", "'mu'");
    refused(&server, "/api/solve?alpha=0&mu=%4", "'mu'");
    refused(&server, "/api/solve?alpha=0&mu=%+1", "'mu'");
    refused(
        &server,
        "/api/solve?alpha=0&mu=%FF%FE",
        "'mu' is not valid UTF-8",
    );
    refused(
        &server,
        "/api/solve?alpha=0&%C3%28=1",
        "parameter name is not valid UTF-8",
    );
    refused(&server, "/api/solve?alpha=0&mu=%00", "--mu");
    // a very long URL: 414
    refused_with(
        414,
        &server,
        &format!("/api/solve?alpha=0&mu={}", "1".repeat(9000)),
        "at most 8192",
    );
    // unknown paths and methods: 404 and 405, JSON
    for target in [
        "/nope",
        "/api/verify?file=/etc/passwd",
        "/api/plot/map?alpha=0",
        "/api/",
        "/api/solve/x",
    ] {
        let r = server.get(target);
        assert_eq!(r.status, 404, "{target}");
        assert_eq!(r.json()["status"], "error");
    }
    let r = server.raw(b"POST", b"/api/solve?alpha=0&mu=1").unwrap();
    assert_eq!(r.status, 405);
    assert_eq!(r.header("allow"), Some("GET"));
    assert_eq!(r.json()["status"], "error");
    // raw non-ASCII bytes in the request line, and a request line that is not HTTP (a
    // space in the target): 400 with the error document
    for target in [
        &b"/api/solve?alpha=0&mu=\xff\xfe"[..],
        b"/api/solve?alpha=0 &mu=1",
    ] {
        let r = server.raw(b"GET", target).unwrap();
        assert_eq!(r.status, 400);
        assert!(r.json()["message"]
            .as_str()
            .unwrap()
            .contains("malformed request"));
    }
    assert_eq!(server.get("/api/solve?alpha=0&mu=1").status, 200);
}

/// xorshift64*: a seeded generator, so a failure replays.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    fn pick<'a>(&mut self, xs: &[&'a str]) -> &'a str {
        xs[(self.next() % xs.len() as u64) as usize]
    }
}

/// Random and malformed query strings (seeded; at most 3000 requests and 90 s): no 500,
/// every reply a known status with a JSON error document, the server answering after.
#[test]
fn fuzzed_queries_never_crash_the_server() {
    let server = Server::start();
    let endpoints = [
        "/api/solve",
        "/api/modes",
        "/api/assess",
        "/api/load",
        "/api/certify",
        "/api/curve",
        "/api/plot/arch",
        "/api/plot/load",
        "/api/plot/eccentricity",
        "/api/nope",
        "/",
        "/api/plot/",
    ];
    let keys = [
        "alpha",
        "alpha-deg",
        "alpha_deg",
        "beta-right",
        "beta-left",
        "blocks",
        "joints",
        "weight",
        "mu",
        "eta",
        "explain",
        "horizontal",
        "horizontal-left",
        "point-load",
        "point-load-deg",
        "point-load-joint",
        "gap",
        "points",
        "mu-min",
        "mu-max",
        "radius",
        "depth",
        "density",
        "g",
        "limit-states",
        "out",
        "json",
        "help",
        "",
        "%",
        "%zz",
        "%FF",
        "a%00b",
        "--mu",
        "-",
        "=",
    ];
    let values = [
        "0",
        "1",
        "0.35",
        "-0.5",
        "1.2",
        "3.2",
        "inf",
        "-inf",
        "nan",
        "NaN",
        "1e308",
        "1e-320",
        "-0",
        "",
        "%",
        "%4",
        "%zz",
        "%FF%FE",
        "%C3%A9",
        "abc",
        "0x10",
        "1,2,3",
        "0,0.5,1",
        "0.5,0.2",
        "centreline",
        "centroid",
        "true",
        "false",
        "12",
        "2",
        "100001",
        "5001",
        "18446744073709551616",
        "+3",
        "1e3",
        "%2B1",
        "%20",
        "a+b",
        "30",
        "60",
        "1e-15",
        "-%31",
    ];
    let (count, budget) = (3000, Duration::from_secs(90));
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let start = Instant::now();
    let mut statuses = std::collections::BTreeMap::new();
    let mut sent = 0;
    while sent < count && start.elapsed() < budget {
        let mut target = rng.pick(&endpoints).to_string();
        target.push('?');
        for i in 0..rng.next() % 7 {
            if i > 0 {
                target.push(if rng.next().is_multiple_of(20) {
                    ';'
                } else {
                    '&'
                });
            }
            target.push_str(rng.pick(&keys));
            if !rng.next().is_multiple_of(8) {
                target.push('=');
                target.push_str(rng.pick(&values));
            }
        }
        // mostly arches that are fast to answer: a shape and a small N with a valid mu
        if rng.next().is_multiple_of(3) {
            target.push_str("&alpha=0.3&blocks=6&mu=0.8");
        }
        let r = server
            .raw(b"GET", target.as_bytes())
            .unwrap_or_else(|e| panic!("{target}: {e}"));
        assert!(
            [200, 400, 404, 422].contains(&r.status),
            "{target}: status {} {}",
            r.status,
            String::from_utf8_lossy(&r.body)
        );
        if r.status != 200 {
            assert_eq!(r.json()["status"], "error", "{target}");
        }
        *statuses.entry(r.status).or_insert(0) += 1;
        sent += 1;
    }
    assert!(sent >= 500, "only {sent} requests in {budget:?}");
    eprintln!(
        "fuzz: {sent} requests in {:.1} s: {statuses:?}",
        start.elapsed().as_secs_f64()
    );
    // every status seen is a known one, and both answers and refusals occurred
    assert!(statuses.contains_key(&200) && statuses.contains_key(&400));
    let r = server.get("/api/solve?alpha=0&mu=0.35");
    assert_eq!(r.status, 200);
    assert_eq!(
        r.body,
        cli(&["solve", "--alpha", "0", "--mu", "0.35", "--json"]).0
    );
}

/// The error document with `status`, whose message contains `needle`.
fn error_reply(r: &Reply, status: u16, needle: &str) {
    assert_eq!(r.status, status, "{}", String::from_utf8_lossy(&r.body));
    assert_eq!(r.header("content-type"), Some("application/json"));
    let v = r.json();
    assert_eq!(v["status"], "error");
    let message = v["message"].as_str().unwrap();
    assert!(message.contains(needle), "{message:?} lacks {needle:?}");
}

#[test]
fn heads_and_bodies_are_bounded_and_the_host_checked() {
    let server = Server::start();
    let port = server.addr.rsplit_once(':').unwrap().1.to_string();
    let get = |headers: &str| {
        let head = format!("GET /api/solve?alpha=0&mu=0.35 HTTP/1.1\r\n{headers}\r\n");
        server.send(head.as_bytes()).unwrap()
    };
    // a body declared far beyond what is accepted: refused without reading or allocating it
    let r = get("Host: localhost\r\nContent-Length: 100000000000\r\n");
    error_reply(&r, 413, "100000000000 bytes");
    error_reply(
        &get("Host: localhost\r\nTransfer-Encoding: chunked\r\n"),
        411,
        "Content-Length",
    );
    error_reply(
        &get("Host: localhost\r\nContent-Length: 1\r\nContent-Length: 2\r\n"),
        400,
        "Content-Length",
    );
    // a small body is read and dropped; the answer is the command's
    let head = "GET /api/solve?alpha=0&mu=0.35 HTTP/1.1\r\nHost: localhost\r\nContent-Length: 5\r\n\r\nhello";
    assert_eq!(server.send(head.as_bytes()).unwrap().status, 200);
    // a head over 16 KiB
    let long = format!("Host: localhost\r\nX-Pad: {}\r\n", "a".repeat(20_000));
    error_reply(&get(&long), 431, "16384 bytes");
    // DNS rebinding: a Host other than this server's
    for host in [
        "evil.example.com",
        "evil.example.com:80",
        "127.0.0.1:1",
        "localhost.evil.com",
    ] {
        error_reply(&get(&format!("Host: {host}\r\n")), 421, host);
    }
    for host in [
        "localhost",
        "127.0.0.1",
        &format!("127.0.0.1:{port}"),
        &format!("LocalHost:{port}"),
    ] {
        assert_eq!(get(&format!("Host: {host}\r\n")).status, 200, "{host}");
    }
    error_reply(&get(""), 400, "no Host header");
    // a head that never ends: 408 after the head deadline (5 s)
    let mut s = TcpStream::connect(&server.addr).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
    s.write_all(b"GET / HTTP/1.1\r\nHost: localhost\r\n")
        .unwrap();
    let t = Instant::now();
    let mut buf = Vec::new();
    s.read_to_end(&mut buf).unwrap();
    error_reply(
        &Reply::parse(&buf).unwrap(),
        408,
        "did not arrive within 5 s",
    );
    assert!(t.elapsed() < Duration::from_secs(20));
    assert_eq!(server.get("/").status, 200);
}

#[test]
fn long_work_is_stopped_at_the_budget() {
    let server = Server::start_with(&["--budget", "0.5"]);
    // `modes` of an arch within a degree of vertical takes seconds on the command line
    let r = server.get("/api/modes?alpha_deg=-89");
    error_reply(&r, 503, "time budget of 0.5 s");
    assert_eq!(server.get("/api/solve?alpha=0&mu=0.35").status, 200);
    let (code, err) = {
        let o = Command::new(cargo_bin("arch-enum"))
            .args(["serve", "--budget", "0"])
            .output()
            .unwrap();
        (
            o.status.code(),
            String::from_utf8_lossy(&o.stderr).to_string(),
        )
    };
    assert_eq!(code, Some(2));
    assert!(
        err.contains("--budget") && err.contains("0.1 to 3600"),
        "{err}"
    );
    let o = Command::new(cargo_bin("arch-enum"))
        .args(["serve", "--port", "-1"])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("'-1'") && err.contains("--port"), "{err}");
}

/// Every attack of the issue at once, on loopback, each bounded: slow heads, idle
/// connections that declared a body, long computations; a probe of the page and one of a
/// command are answered within 2 s while they run (the command's possibly with 503 when
/// every computation is taken), and the server answers after.
#[test]
fn attacks_leave_the_server_answering() {
    let server = Server::start_with(&["--budget", "4"]);
    let addr = server.addr.clone();
    // 300 slow heads: a byte now and then, never finished
    let slow: Vec<TcpStream> = (0..300)
        .filter_map(|_| {
            let mut s = TcpStream::connect(&addr).ok()?;
            s.write_all(b"GET / HTTP/1.1\r\nHost: localhost\r\nX-a: ")
                .ok()?;
            Some(s)
        })
        .collect();
    assert!(slow.len() >= 250, "{} slow connections opened", slow.len());
    // idle connections that declared a body and never send it
    let idle: Vec<TcpStream> = (0..4)
        .map(|_| {
            let mut s = TcpStream::connect(&addr).unwrap();
            s.write_all(
                b"GET /api/solve?alpha=0&mu=0.35 HTTP/1.1\r\nHost: localhost\r\nContent-Length: 60000\r\n\r\n",
            )
            .unwrap();
            s
        })
        .collect();
    // long computations, more than run at once
    let long: Vec<_> = (0..6)
        .map(|_| {
            let addr = addr.clone();
            std::thread::spawn(move || {
                let mut s = TcpStream::connect(&addr).unwrap();
                s.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
                s.write_all(b"GET /api/modes?alpha_deg=-89 HTTP/1.1\r\nHost: localhost\r\n\r\n")
                    .unwrap();
                let mut buf = Vec::new();
                let _ = s.read_to_end(&mut buf);
                Reply::parse(&buf).map(|r| r.status).ok()
            })
        })
        .collect();
    std::thread::sleep(Duration::from_millis(300));
    for target in ["/", "/api/solve?alpha=0&mu=0.35"] {
        let t = Instant::now();
        let r = server.get(target);
        let took = t.elapsed();
        assert!(took < Duration::from_secs(2), "{target} took {took:?}");
        match r.status {
            200 => {}
            503 => assert_ne!(target, "/", "the page needs no computation"),
            s => panic!("{target}: {s}"),
        }
        if target != "/" {
            assert!(r.json().is_object());
        }
    }
    for h in long {
        let status = h.join().unwrap();
        assert!(matches!(status, Some(503) | Some(200)), "{status:?}");
    }
    drop((slow, idle));
    assert_eq!(server.get("/api/solve?alpha=0&mu=0.35").status, 200);
}
