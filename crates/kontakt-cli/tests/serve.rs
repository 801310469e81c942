//! `kontakt serve` over HTTP (issue 32): the real binary on 127.0.0.1 with `--port 0`, each
//! endpoint, the error answers, the time limit and the cancellation (the worker process is
//! killed: no CPU keeps burning), and a bounded load test on loopback.

#![allow(clippy::unwrap_used)] // tests: a panic is a failure with its message

mod support;

use serde_json::{Value, json};
use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// A `kontakt serve --port 0` process, killed when dropped.
struct Server {
    child: Child,
    /// `127.0.0.1:PORT`
    addr: String,
}

impl Server {
    fn start(extra: &[&str]) -> Server {
        Self::start_in(extra, &mut Command::new(env!("CARGO_BIN_EXE_kontakt")))
    }

    /// Start `command` (the binary, with its environment) as `serve --port 0 EXTRA`.
    fn start_in(extra: &[&str], command: &mut Command) -> Server {
        let mut child = command
            .args(["serve", "--port", "0"])
            .args(extra)
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let mut line = String::new();
        BufReader::new(child.stdout.take().unwrap())
            .read_line(&mut line)
            .unwrap();
        let addr = line
            .trim()
            .strip_prefix("http://")
            .and_then(|r| r.strip_suffix('/'))
            .unwrap_or_else(|| panic!("first line is not the URL: {line:?}"))
            .to_string();
        assert!(addr.starts_with("127.0.0.1:"), "{addr}");
        Server { child, addr }
    }

    fn get(&self, path: &str) -> (u16, String) {
        self.request("GET", path, &[], b"")
    }

    /// POST a JSON value.
    fn post(&self, path: &str, body: &Value) -> (u16, Value) {
        self.post_raw(path, "application/json", body.to_string().as_bytes())
    }

    fn post_raw(&self, path: &str, content_type: &str, body: &[u8]) -> (u16, Value) {
        let (status, text) = self.request("POST", path, &[("Content-Type", content_type)], body);
        (status, serde_json::from_str(&text).unwrap_or(Value::Null))
    }

    /// One HTTP/1.1 request on its own connection: the status and the body. The `Host`
    /// header is the server's address unless `headers` name one.
    fn request(
        &self,
        method: &str,
        path: &str,
        headers: &[(&str, &str)],
        body: &[u8],
    ) -> (u16, String) {
        let mut s = TcpStream::connect(&self.addr).unwrap();
        s.set_read_timeout(Some(Duration::from_secs(120))).unwrap();
        let mut head = format!("{method} {path} HTTP/1.1\r\nConnection: close\r\n");
        if !headers.iter().any(|(k, _)| k.eq_ignore_ascii_case("host")) {
            head.push_str(&format!("Host: {}\r\n", self.addr));
        }
        for (k, v) in headers {
            head.push_str(&format!("{k}: {v}\r\n"));
        }
        head.push_str(&format!("Content-Length: {}\r\n\r\n", body.len()));
        s.write_all(head.as_bytes()).unwrap();
        // A server that refuses a large body may answer before reading it all.
        let _ = s.write_all(body);
        let mut raw = Vec::new();
        let _ = s.read_to_end(&mut raw);
        let text = String::from_utf8_lossy(&raw).to_string();
        let (head, body) = text
            .split_once("\r\n\r\n")
            .unwrap_or_else(|| panic!("no HTTP answer to {method} {path}: {text:?}"));
        let status = head.split(' ').nth(1).unwrap().parse().unwrap();
        let body = if head
            .to_ascii_lowercase()
            .contains("transfer-encoding: chunked")
        {
            dechunk(body)
        } else {
            body.to_string()
        };
        (status, body)
    }

    /// The CPU time (user + system, clock ticks) of the server's child processes: the
    /// workers.
    #[cfg(target_os = "linux")]
    fn workers_cpu(&self) -> u64 {
        let me = self.child.id().to_string();
        let mut total = 0;
        for entry in std::fs::read_dir("/proc").unwrap().flatten() {
            let Ok(stat) = std::fs::read_to_string(entry.path().join("stat")) else {
                continue;
            };
            // pid (comm) state ppid ... utime(14) stime(15)
            let Some((_, rest)) = stat.rsplit_once(") ") else {
                continue;
            };
            let f: Vec<&str> = rest.split(' ').collect();
            if f.len() > 12 && f[1] == me {
                total += f[11].parse::<u64>().unwrap_or(0) + f[12].parse::<u64>().unwrap_or(0);
            }
        }
        total
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn dechunk(mut body: &str) -> String {
    let mut out = String::new();
    while let Some((size, rest)) = body.split_once("\r\n") {
        let n = usize::from_str_radix(size.trim(), 16).unwrap_or(0);
        if n == 0 {
            break;
        }
        out.push_str(&rest[..n]);
        body = &rest[n + 2..];
    }
    out
}

fn example_text(name: &str) -> String {
    std::fs::read_to_string(support::example(name)).unwrap()
}

/// What `kontakt solve --json` prints for the example.
fn cli_json(name: &str) -> Value {
    let out = support::kontakt()
        .args(["solve", "--json"])
        .arg(support::example(name))
        .output()
        .unwrap();
    assert!(out.status.success(), "{name}");
    serde_json::from_slice(&out.stdout).unwrap()
}

/// A case that runs for tens of seconds: a rough surface of 1024 × 1024 cells at six
/// loads (the time-limit and cancellation tests stop it long before).
fn slow_case() -> String {
    example_text("rough_self_affine.toml")
        .replace("points = [256, 256]", "points = [1024, 1024]")
        .replace("short_cutoff_mm = 0.015625", "short_cutoff_mm = 0.004")
        .replace(
            "mean_pressure_mpa = [100.0, 200.0, 400.0, 800.0]",
            "mean_pressure_mpa = [50.0, 100.0, 200.0, 400.0, 800.0, 1600.0]",
        )
}

/// `/api/case/parse` of a case text that parses: `{"case", "method"}`.
fn parsed(s: &Server, text: &str) -> Value {
    let (status, parsed) = s.post("/api/case/parse", &json!({ "toml": text }));
    assert_eq!(status, 200, "{parsed}");
    assert!(parsed["case"].is_object(), "{parsed}");
    parsed
}

fn error_of(v: &Value) -> &Value {
    assert!(
        v["error"]["message"].is_string(),
        "not an error answer: {v}"
    );
    &v["error"]
}

#[test]
fn health_examples_and_pages() {
    let s = Server::start(&[]);
    let (status, body) = s.get("/api/health");
    assert_eq!(status, 200);
    let v: Value = serde_json::from_str(&body).unwrap();
    assert_eq!(v["kontakt_version"], env!("CARGO_PKG_VERSION"));

    // the case files' JSON Schema, the one `kontakt schema` prints
    let (status, body) = s.get("/api/schema");
    assert_eq!(status, 200);
    let schema: Value = serde_json::from_str(&body).unwrap();
    assert_eq!(schema, kontakt_case::case_schema());

    let (status, body) = s.get("/api/examples");
    assert_eq!(status, 200);
    let list: Vec<Value> = serde_json::from_str(&body).unwrap();
    let on_disk = std::fs::read_dir(support::example(""))
        .unwrap()
        .flatten()
        .filter(|e| e.path().extension().is_some_and(|x| x == "toml"))
        .count();
    assert_eq!(list.len(), on_disk, "every examples/*.toml is listed");
    let ball = list.iter().find(|e| e["name"] == "ball_on_flat").unwrap();
    assert_eq!(ball["method"], "hertz");
    assert_eq!(ball["title"], "ball on flat");
    assert!(list.iter().any(|e| e["method"] == "bearing"));

    let (status, text) = s.get("/api/examples/ball_on_flat");
    assert_eq!(status, 200);
    assert_eq!(text, example_text("ball_on_flat.toml"));
    let (status, body) = s.get("/api/examples/nope");
    assert_eq!(status, 404);
    error_of(&serde_json::from_str(&body).unwrap());
    // No way out of the examples folder.
    assert_eq!(s.get("/api/examples/..%2FCargo").0, 404);

    let (status, page) = s.get("/");
    assert_eq!(status, 200);
    assert!(page.contains("<html"), "{page}");
    assert_eq!(s.get("/no-such-page.html").0, 404);
    let (status, body) = s.get("/api/nope");
    assert_eq!(status, 404);
    error_of(&serde_json::from_str(&body).unwrap());
}

/// The API's report is exactly what `kontakt solve --json` prints, for a Hertz, a PimP
/// roller-end/rib, a friction, two bearing and a traction case; the case as a JSON object
/// (from /api/case/parse) gives the same report as its TOML text, and /api/case/toml writes
/// it back as the same tables.
#[test]
fn run_equals_solve_json() {
    let s = Server::start(&[]);
    for name in [
        "ball_on_flat.toml",
        "roller_rib_torus_torus.toml",
        "rib_friction.toml",
        "bearing_6205.toml",
        "bearing_32008x_friction.toml",
        "traction_twin_disc.toml",
    ] {
        let text = example_text(name);
        let (status, answer) = s.post("/api/run", &json!({ "case": text }));
        assert_eq!(status, 200, "{name}: {answer}");
        let expected = cli_json(name);
        assert_eq!(answer["report"], expected, "{name}");
        // A report without warnings may leave its `warnings` key out; the API's list is there.
        let warnings = expected.get("warnings").cloned().unwrap_or(json!([]));
        assert_eq!(answer["warnings"], warnings, "{name}");

        let parsed = parsed(&s, &text);
        let (status, from_json) = s.post("/api/run", &json!({ "case": parsed["case"] }));
        assert_eq!(status, 200, "{name}: {from_json}");
        assert_eq!(from_json["report"], expected, "{name} as a JSON object");

        // Saved again as TOML (a form's "save"): the same tables.
        let (status, saved) = s.post("/api/case/toml", &json!({ "case": parsed["case"] }));
        assert_eq!(status, 200, "{saved}");
        let again: toml::Table = saved["toml"].as_str().unwrap().parse().unwrap();
        let original: toml::Table = text.parse().unwrap();
        assert_eq!(again, original, "{name}");
        assert_eq!(saved["method"], parsed["method"]);
    }
}

/// Loading into a form and saving refuse what the case parser refuses (the round trip of
/// good cases is in `run_equals_solve_json`).
#[test]
fn case_parse_and_toml_round_trip() {
    let s = Server::start(&[]);
    let (status, v) = s.post(
        "/api/case/parse",
        &json!({ "toml": "method = \"hertz\"\nload = 3\nbogus = 1\n" }),
    );
    assert_eq!(status, 422, "{v}");
    assert_eq!(error_of(&v)["field"], "bogus");
    let (status, v) = s.post(
        "/api/case/toml",
        &json!({ "case": { "method": "hertz", "bogus": 1 } }),
    );
    assert_eq!(status, 422, "{v}");
    let e = error_of(&v);
    assert_eq!(e["field"], "bogus");
    assert!(
        e["message"]
            .as_str()
            .unwrap()
            .starts_with("unknown key `bogus`"),
        "{e}"
    );
    let (status, v) = s.post("/api/case/parse", &json!({ "toml": "a = [" }));
    assert_eq!(status, 400, "{v}");
    assert!(
        error_of(&v)["message"].as_str().unwrap().contains("line 1"),
        "{v}"
    );
}

/// Input errors: 422 with the command line's message and the field; malformed bodies 400
/// with the parser's message; oversize 413; wrong method 405; not JSON 415; a foreign
/// Host 421.
#[test]
fn error_answers() {
    let s = Server::start(&[]);
    let hertz = example_text("ball_on_flat.toml");

    // The same message as `kontakt solve` prints, after its file-name prefix.
    let bad = hertz.replace("force_n = 100.0", "force_n = -5.0");
    assert_ne!(bad, hertz, "the example's load line changed");
    let path = std::env::temp_dir().join(format!("kontakt-serve-test-{}.toml", std::process::id()));
    std::fs::write(&path, &bad).unwrap();
    let cli = support::kontakt().arg("solve").arg(&path).output().unwrap();
    std::fs::remove_file(&path).unwrap();
    assert_eq!(cli.status.code(), Some(2));
    let cli_line = String::from_utf8(cli.stderr).unwrap();
    let (status, v) = s.post("/api/run", &json!({ "case": bad }));
    assert_eq!(status, 422, "{v}");
    let e = error_of(&v);
    assert_eq!(e["field"], "load.force_n", "{e}");
    assert_eq!(e["value"], "-5", "{e}");
    assert!(e["expected"].is_string(), "{e}");
    let message = e["message"].as_str().unwrap();
    assert!(
        cli_line.trim_end().ends_with(message),
        "CLI: {cli_line} API: {message}"
    );

    // A number too large for f64 in TOML: the TOML reader refuses it (400, its message).
    let case = hertz.replace("force_n = 100.0", "force_n = 1e400");
    let (status, v) = s.post("/api/run", &json!({ "case": case }));
    assert_eq!(status, 400, "{v}");
    assert!(
        error_of(&v)["message"]
            .as_str()
            .unwrap()
            .contains("overflow"),
        "{v}"
    );
    // NaN and infinity in TOML: the case runner's range check.
    for value in ["nan", "inf", "-inf"] {
        let case = hertz.replace("force_n = 100.0", &format!("force_n = {value}"));
        let (status, v) = s.post("/api/run", &json!({ "case": case }));
        assert_eq!(status, 422, "{value}: {v}");
        assert_eq!(error_of(&v)["field"], "load.force_n", "{value}: {v}");
    }
    // ... and in JSON, where the JSON parser refuses them.
    for body in [
        r#"{"case": {"load": {"force_n": NaN}}}"#,
        r#"{"case": {"load": {"force_n": 1e400}}}"#,
        r#"{"case": "#,
        "[1, 2]",
        r#"{"toml": "x"}"#,
        r#"{"case": 3}"#,
        r#"{"case": {"load": null}}"#,
        r#"{"case": {"load": {"force_n": 1e999}}}"#,
    ] {
        let (status, v) = s.post_raw("/api/run", "application/json", body.as_bytes());
        assert_eq!(status, 400, "{body}: {v}");
        error_of(&v);
    }
    // Unknown keys, by the case parser, with the key's full path.
    let case = hertz.replace("[load]", "[load]\nforce_kn = 1.0");
    let (status, v) = s.post("/api/run", &json!({ "case": case }));
    assert_eq!(status, 422, "{v}");
    assert_eq!(error_of(&v)["field"], "load.force_kn");
    // Files are not read.
    let (status, v) = s.post(
        "/api/run",
        &json!({ "case": example_text("bem_wavy_map.toml") }),
    );
    if example_text("bem_wavy_map.toml").contains("file") {
        assert_eq!(status, 422, "{v}");
        assert!(
            error_of(&v)["field"].as_str().unwrap().ends_with("file"),
            "{v}"
        );
    }
    // The body cap (1 MiB).
    let big = json!({ "case": format!("{hertz}\n#{}", "x".repeat(2 << 20)) }).to_string();
    let (status, v) = s.post_raw("/api/run", "application/json", big.as_bytes());
    assert_eq!(status, 413, "{v}");
    error_of(&v);
    // Method, media type, host.
    let (status, body) = s.get("/api/run");
    assert_eq!(status, 405);
    error_of(&serde_json::from_str(&body).unwrap());
    let (status, v) = s.post_raw("/api/run", "text/plain", b"{\"case\": \"\"}");
    assert_eq!(status, 415, "{v}");
    let (status, _) = s.request("GET", "/api/health", &[("Host", "evil.example")], b"");
    assert_eq!(status, 421);
    let (status, _) = s.request("GET", "/api/health", &[("Host", "localhost:1")], b"");
    assert_eq!(status, 200);
}

/// A solve past the time limit is answered 408 and its worker process killed (the
/// workers' CPU time stops growing); a job can be cancelled (killed the same way), a job
/// past its own limit fails with 408's error, and a quick job ends with the report of
/// /api/run.
#[test]
fn time_limit_and_cancellation() {
    let s = Server::start(&["--time-limit", "0.5", "--workers", "2"]);
    let slow = slow_case();

    let t = Instant::now();
    let (status, v) = s.post("/api/run", &json!({ "case": slow }));
    assert_eq!(status, 408, "{v}");
    assert_eq!(error_of(&v)["kind"], "time_limit");
    assert!(t.elapsed() < Duration::from_secs(10), "{:?}", t.elapsed());
    #[cfg(target_os = "linux")]
    assert_no_cpu_burning(&s);

    // The server is still there, with a fresh worker.
    let (status, v) = s.post(
        "/api/run",
        &json!({ "case": example_text("ball_on_flat.toml") }),
    );
    assert_eq!(status, 200, "{v}");
    let quick_report = v["report"].clone();

    // Cancel a running job.
    let (status, v) = s.post("/api/jobs", &json!({ "case": slow }));
    assert_eq!(status, 202, "{v}");
    let id = v["id"].as_str().unwrap().to_string();
    let (status, body) = s.get(&format!("/api/jobs/{id}"));
    assert_eq!(status, 200);
    let state: Value = serde_json::from_str(&body).unwrap();
    assert_eq!(state["state"], "running", "{state}");
    assert!(state["progress"].is_null());
    std::thread::sleep(Duration::from_millis(300));
    let (status, body) = s.request("DELETE", &format!("/api/jobs/{id}"), &[], b"");
    assert_eq!(status, 200, "{body}");
    let (_, body) = s.get(&format!("/api/jobs/{id}"));
    let state: Value = serde_json::from_str(&body).unwrap();
    assert_eq!(state["state"], "cancelled", "{state}");
    #[cfg(target_os = "linux")]
    assert_no_cpu_burning(&s);

    // A quick job: done, with the report of /api/run.
    let (_, v) = s.post(
        "/api/jobs",
        &json!({ "case": example_text("ball_on_flat.toml") }),
    );
    let state = poll(&s, v["id"].as_str().unwrap());
    assert_eq!(state["state"], "done", "{state}");
    assert_eq!(state["report"], quick_report);
    assert_eq!(state["progress"], 1.0);

    // A job of a bad case is refused at once, as /api/run refuses it.
    let (status, v) = s.post("/api/jobs", &json!({ "case": "bogus = 1" }));
    assert_eq!(status, 422, "{v}");

    // A job past its limit (ten times --time-limit: 5 s) fails.
    let (_, v) = s.post("/api/jobs", &json!({ "case": slow }));
    let state = poll(&s, v["id"].as_str().unwrap());
    assert_eq!(state["state"], "failed", "{state}");
    assert_eq!(state["error"]["kind"], "time_limit", "{state}");

    let (status, _) = s.get("/api/jobs/nope");
    assert_eq!(status, 404);
    let (status, _) = s.request("DELETE", "/api/jobs/nope", &[], b"");
    assert_eq!(status, 404);
}

/// A client that gives up mid-solve: its worker is killed, long before the time limit
/// (60 s). While the client waits the worker computes (its CPU time grows), after it left
/// the CPU time stands still.
#[cfg(target_os = "linux")]
#[test]
fn a_client_that_leaves_stops_its_solve() {
    let s = Server::start(&["--time-limit", "60"]);
    let body = json!({ "case": slow_case() }).to_string();
    let mut c = TcpStream::connect(&s.addr).unwrap();
    write!(
        c,
        "POST /api/run HTTP/1.1\r\nHost: {}\r\nContent-Type: application/json\r\n\
         Content-Length: {}\r\n\r\n{body}",
        s.addr,
        body.len()
    )
    .unwrap();
    std::thread::sleep(Duration::from_millis(500));
    let before = s.workers_cpu();
    std::thread::sleep(Duration::from_millis(500));
    assert!(
        s.workers_cpu() > before + 10,
        "the solve runs while the client waits"
    );
    drop(c);
    assert_no_cpu_burning(&s);
    assert_eq!(s.get("/api/health").0, 200);
}

fn poll(s: &Server, id: &str) -> Value {
    let t = Instant::now();
    loop {
        let (status, body) = s.get(&format!("/api/jobs/{id}"));
        assert_eq!(status, 200, "{body}");
        let v: Value = serde_json::from_str(&body).unwrap();
        if v["state"] != "running" {
            return v;
        }
        assert!(
            t.elapsed() < Duration::from_secs(60),
            "job {id} still running"
        );
        std::thread::sleep(Duration::from_millis(50));
    }
}

/// The workers' CPU time does not grow over half a second: nothing was left running.
#[cfg(target_os = "linux")]
fn assert_no_cpu_burning(s: &Server) {
    std::thread::sleep(Duration::from_millis(300));
    let before = s.workers_cpu();
    std::thread::sleep(Duration::from_millis(500));
    let after = s.workers_cpu();
    assert!(
        after <= before + 2,
        "workers still busy: {before} -> {after} ticks"
    );
}

/// 8 clients × 200 requests of mixed cases (five methods, and two bad cases) on loopback:
/// every answer arrives and equals the answer to the same request made alone (whose
/// reports equal `kontakt solve --json`, `run_equals_solve_json`), and the server answers
/// at once afterwards.
#[test]
fn load_test_loses_nothing() {
    let s = Server::start(&[]);
    let hertz = example_text("ball_on_flat.toml");
    let cases: Vec<Value> = vec![
        json!({ "case": hertz }),
        json!({ "case": example_text("crossed_cylinders.toml") }),
        json!({ "case": example_text("roller_rib_torus_torus.toml") }),
        json!({ "case": example_text("traction_twin_disc.toml") }),
        json!({ "case": example_text("bearing_6205.toml") }),
        json!({ "case": example_text("mindlin_fretting.toml") }),
        json!({ "case": hertz.replace("force_n = 100.0", "force_n = nan") }),
        json!({ "case": hertz.replace("[load]", "[load]\nbogus = 1") }),
    ];
    let expected: Vec<(u16, Value)> = cases.iter().map(|c| s.post("/api/run", c)).collect();
    assert_eq!(
        expected.iter().map(|e| e.0).collect::<Vec<_>>(),
        [200, 200, 200, 200, 200, 200, 422, 422]
    );
    let t = Instant::now();
    let (clients, requests) = (8, 200);
    let answered: usize = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..clients)
            .map(|c| {
                let (s, cases, expected) = (&s, &cases, &expected);
                scope.spawn(move || {
                    for r in 0..requests {
                        let k = (c * 7 + r * 3) % cases.len();
                        let answer = s.post("/api/run", &cases[k]);
                        assert_eq!(answer, expected[k], "client {c}, request {r}, case {k}");
                    }
                    requests
                })
            })
            .collect();
        handles.into_iter().map(|h| h.join().unwrap()).sum()
    });
    let elapsed = t.elapsed();
    assert_eq!(answered, clients * requests);
    let t = Instant::now();
    assert_eq!(s.get("/api/health").0, 200);
    assert!(t.elapsed() < Duration::from_secs(1), "{:?}", t.elapsed());
    eprintln!(
        "load test: {answered} requests in {elapsed:.2?} ({:.0} requests/s)",
        answered as f64 / elapsed.as_secs_f64()
    );
}

/// The flags: a bad time limit or worker count is an input error (status 2); another
/// address than loopback is warned about (here one not on this machine, so the bind fails
/// after the warning, status 1); `--open` without an opener is a warning and the server
/// runs on.
#[test]
fn flags_and_warnings() {
    for (flag, value) in [
        ("--time-limit", "0"),
        ("--time-limit", "nan"),
        ("--workers", "0"),
    ] {
        let out = support::kontakt()
            .args(["serve", "--port", "0", flag, value])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{flag} {value}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert!(
            err.starts_with(&format!("error: invalid {flag} = ")),
            "{err}"
        );
        assert_eq!(err.lines().count(), 1, "{err}");
    }

    // 192.0.2.1 (TEST-NET-1, RFC 5737) is never an address of this machine.
    let out = support::kontakt()
        .args(["serve", "--port", "0", "--address", "192.0.2.1"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.starts_with("warning: listening on 192.0.2.1, not on 127.0.0.1"),
        "{err}"
    );
    assert!(err.contains("error: cannot serve on 192.0.2.1:0"), "{err}");

    // --open with no opener on the PATH.
    let empty =
        std::env::temp_dir().join(format!("kontakt-serve-test-path-{}", std::process::id()));
    std::fs::create_dir_all(&empty).unwrap();
    let mut server = Server::start_in(
        &["--open"],
        Command::new(env!("CARGO_BIN_EXE_kontakt")).env("PATH", &empty),
    );
    let mut stderr = BufReader::new(server.child.stderr.take().unwrap());
    let mut warning = String::new();
    while !warning.starts_with("warning:") {
        warning.clear();
        if stderr.read_line(&mut warning).unwrap() == 0 {
            break;
        }
    }
    assert!(
        warning.starts_with("warning: cannot open a browser"),
        "{warning}"
    );
    assert_eq!(server.get("/api/health").0, 200, "the server runs on");
    drop(server);
    std::fs::remove_dir_all(&empty).unwrap();
}
