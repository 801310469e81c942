//! Solves in worker processes: the hard time limit and the cancellation of `kontakt serve`.
//!
//! Every solve runs in a child process, the server's own executable started in worker mode
//! (`kontakt serve --worker`), which reads one case per line on its standard input and
//! answers one line on its standard output ([`worker_main`]). The server keeps up to
//! `workers` of them alive and reuses them; a solve that passes its time limit, or whose
//! job is cancelled, or whose HTTP client went away, has its process killed, and a new one
//! is started for the next solve. The solvers have no cancellation hook, and a thread
//! cannot be stopped from outside: a process can, so a runaway solve never keeps a core
//! busy after its answer (408) has gone out.
//!
//! Protocol (private to this crate): the request is the case's TOML text as one JSON
//! string and a newline; the answer is `kontakt-worker: STATUS BODY` and a newline (other
//! lines on the worker's standard output are skipped), where BODY is the API's
//! JSON answer for that status (`{"report", "warnings"}` for 200, `{"error"}` otherwise).

use crate::error::ApiError;
use axum::http::StatusCode;
use std::io::{BufRead, Write};
use std::path::PathBuf;
#[cfg(all(test, unix))]
use std::sync::Arc;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Duration;
use tokio::io::{AsyncBufReadExt, AsyncWriteExt, BufReader};
use tokio::process::{Child, ChildStdin, ChildStdout};
use tokio::sync::Semaphore;

/// How to start a worker: the program (the `kontakt` executable) and its arguments.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct WorkerCommand {
    /// The executable.
    pub program: PathBuf,
    /// Its arguments, e.g. `["serve", "--worker"]`.
    pub args: Vec<String>,
}

/// One live worker process.
struct Worker {
    // Killed when dropped (kill_on_drop): a solve abandoned half-way takes its process along.
    _child: Child,
    stdin: ChildStdin,
    stdout: BufReader<ChildStdout>,
}

/// The answer of a solve: HTTP status and JSON body.
pub type Answer = (StatusCode, String);

/// The bounded pool of worker processes.
pub struct Pool {
    command: WorkerCommand,
    idle: Mutex<Vec<Worker>>,
    permits: Semaphore,
    waiting: AtomicUsize,
    max_waiting: usize,
}

impl Pool {
    /// A pool of at most `workers` concurrent solves and `max_waiting` solves waiting for
    /// one; no process is started before the first solve.
    pub fn new(command: WorkerCommand, workers: usize, max_waiting: usize) -> Self {
        Pool {
            command,
            idle: Mutex::new(Vec::new()),
            permits: Semaphore::new(workers.max(1)),
            waiting: AtomicUsize::new(0),
            max_waiting,
        }
    }

    /// Solve the case `text` (TOML, already checked by the case parser) in a worker, at most
    /// `limit` long; `cancel` resolving stops it (its process is killed).
    ///
    /// # Errors
    /// 503 when too many solves wait, 408 past the time limit, 499-like `cancelled` (409)
    /// when cancelled, 500 when the worker cannot be started or dies.
    pub async fn solve(
        &self,
        text: &str,
        limit: Duration,
        cancel: impl std::future::Future<Output = ()>,
    ) -> Result<Answer, ApiError> {
        tokio::pin!(cancel);
        let _permit = match self.permits.try_acquire() {
            Ok(permit) => permit,
            Err(_) => {
                // Every worker is busy: wait, unless `max_waiting` solves already do.
                let waiting = Waiting::enter(&self.waiting);
                if waiting.ahead >= self.max_waiting {
                    return Err(ApiError::new(
                        StatusCode::SERVICE_UNAVAILABLE,
                        "overloaded",
                        format!(
                            "the server is busy (every worker solving, {} solves waiting); \
                             try again shortly",
                            self.max_waiting
                        ),
                    ));
                }
                // The count is left when `waiting` drops: also when the client goes
                // away while waiting (this future dropped).
                let permit = tokio::select! {
                    p = self.permits.acquire() => p,
                    () = &mut cancel => return Err(cancelled()),
                };
                drop(waiting);
                permit.map_err(|_| internal("the worker pool is closed"))?
            }
        };
        let idle = self.idle.lock().ok().and_then(|mut v| v.pop());
        let mut worker = match idle {
            Some(w) => w,
            None => self.start()?,
        };
        let exchange = exchange(&mut worker, text);
        tokio::select! {
            answer = tokio::time::timeout(limit, exchange) => match answer {
                Ok(Ok(answer)) => {
                    if let Ok(mut v) = self.idle.lock() {
                        v.push(worker);
                    }
                    Ok(answer)
                }
                // The worker died or its pipe broke: drop (kill) it.
                Ok(Err(e)) => Err(internal(&format!("the worker process failed: {e}"))),
                Err(_) => Err(ApiError::new(
                    StatusCode::REQUEST_TIMEOUT,
                    "time_limit",
                    format!(
                        "the solve passed the server's time limit of {} s and was stopped; \
                         run it with `kontakt solve` or start the server with a larger \
                         --time-limit",
                        limit.as_secs_f64()
                    ),
                )),
            },
            () = &mut cancel => Err(cancelled()),
        }
    }

    fn start(&self) -> Result<Worker, ApiError> {
        let mut child = tokio::process::Command::new(&self.command.program)
            .args(&self.command.args)
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::inherit())
            .kill_on_drop(true)
            .spawn()
            .map_err(|e| internal(&format!("cannot start a worker process: {e}")))?;
        let (Some(stdin), Some(stdout)) = (child.stdin.take(), child.stdout.take()) else {
            return Err(internal("the worker process has no pipes"));
        };
        Ok(Worker {
            _child: child,
            stdin,
            stdout: BufReader::new(stdout),
        })
    }
}

/// The start of an answer line of a worker.
const ANSWER: &str = "kontakt-worker: ";

/// Send one case, read one answer.
async fn exchange(worker: &mut Worker, text: &str) -> std::io::Result<Answer> {
    let mut line = serde_json::to_string(text)?;
    line.push('\n');
    worker.stdin.write_all(line.as_bytes()).await?;
    worker.stdin.flush().await?;
    // Lines without the marker are not answers (something in the solve printed to
    // standard output): skipped.
    let mut answer = String::new();
    let rest = loop {
        answer.clear();
        if worker.stdout.read_line(&mut answer).await? == 0 {
            return Err(std::io::Error::new(
                std::io::ErrorKind::UnexpectedEof,
                "it exited during the solve",
            ));
        }
        if let Some(rest) = answer.strip_prefix(ANSWER) {
            break rest;
        }
    };
    let (status, body) = rest
        .trim_end()
        .split_once(' ')
        .ok_or_else(|| std::io::Error::other("malformed answer"))?;
    let status = status
        .parse::<u16>()
        .ok()
        .and_then(|s| StatusCode::from_u16(s).ok())
        .ok_or_else(|| std::io::Error::other("malformed status"))?;
    Ok((status, body.to_string()))
}

/// One solve counted as waiting for a worker while this lives.
struct Waiting<'a> {
    count: &'a AtomicUsize,
    /// How many were waiting before this one.
    ahead: usize,
}

impl<'a> Waiting<'a> {
    fn enter(count: &'a AtomicUsize) -> Self {
        let ahead = count.fetch_add(1, Ordering::SeqCst);
        Waiting { count, ahead }
    }
}

impl Drop for Waiting<'_> {
    fn drop(&mut self) {
        self.count.fetch_sub(1, Ordering::SeqCst);
    }
}

fn internal(message: &str) -> ApiError {
    ApiError::new(StatusCode::INTERNAL_SERVER_ERROR, "internal", message)
}

fn cancelled() -> ApiError {
    ApiError::new(StatusCode::CONFLICT, "cancelled", "the solve was cancelled")
}

/// The worker's side: read cases (one JSON string of TOML text a line) from `input`, run
/// each through [`kontakt_case::Case::run`] and write `kontakt-worker: STATUS BODY` lines to `output`,
/// until `input` ends.
///
/// # Errors
/// Reading or writing the pipes.
pub fn worker_main(input: impl BufRead, mut output: impl Write) -> std::io::Result<()> {
    watch_parent();
    for line in input.lines() {
        let line = line?;
        let (status, body) = match serde_json::from_str::<String>(&line) {
            Ok(text) => solve_here(&text),
            Err(e) => {
                let e = ApiError::bad_request(format!("worker request: {e}"));
                (e.status, e.body())
            }
        };
        writeln!(output, "{ANSWER}{} {body}", status.as_u16())?;
        output.flush()?;
    }
    Ok(())
}

/// End this worker when its server is gone. An idle worker sees its input end; a busy
/// one would finish its solve first, so a thread checks every 200 ms whether the process
/// was handed to another parent (the server killed without a chance to kill its workers)
/// and exits if so.
fn watch_parent() {
    #[cfg(unix)]
    {
        let parent = std::os::unix::process::parent_id();
        std::thread::spawn(move || {
            loop {
                std::thread::sleep(Duration::from_millis(200));
                if std::os::unix::process::parent_id() != parent {
                    std::process::exit(3);
                }
            }
        });
    }
}

/// Parse and run one case in this process: the API's answer for it.
pub fn solve_here(text: &str) -> Answer {
    let run = || -> Result<String, ApiError> {
        let (case, _) = crate::case_io::parse_case(text, crate::case_io::Source::Toml)?;
        // No file is read (parse_case refuses the keys that name one); the base folder
        // is only where relative paths would be resolved.
        let outcome = case
            .run(std::path::Path::new("."))
            .map_err(|e| ApiError::from_case(&e))?;
        report_body(&outcome)
    };
    match std::panic::catch_unwind(run) {
        Ok(Ok(body)) => (StatusCode::OK, body),
        Ok(Err(e)) => (e.status, e.body()),
        Err(_) => {
            let e = internal("the solver panicked (a bug: please report the case)");
            (e.status, e.body())
        }
    }
}

/// `{"report": <what kontakt solve --json prints>, "warnings": [...]}`: the report is the
/// outcome's own serialization, the one `kontakt solve --json` prints.
pub fn report_body(outcome: &kontakt_case::Outcome) -> Result<String, ApiError> {
    let report = serde_json::to_string(outcome).map_err(|e| internal(&format!("report: {e}")))?;
    let warnings = serde_json::to_string(outcome.warnings())
        .map_err(|e| internal(&format!("warnings: {e}")))?;
    // What the pages draw beside the report (crate::page_data): stresses along the axis,
    // pressure fields.
    let mut extras = String::new();
    for (key, value) in crate::page_data::extras(outcome) {
        extras.push_str(&format!(",\"{key}\":{value}"));
    }
    Ok(format!(
        "{{\"report\":{report},\"warnings\":{warnings}{extras}}}"
    ))
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;

    /// A "worker" that never answers (`sleep`), or that exits at once (`true`).
    fn pool(program: &str, args: &[&str], workers: usize, max_waiting: usize) -> Pool {
        let command = WorkerCommand {
            program: program.into(),
            args: args.iter().map(|a| a.to_string()).collect(),
        };
        Pool::new(command, workers, max_waiting)
    }

    #[tokio::test]
    async fn time_limit_overload_cancel_and_a_dead_worker() {
        let p = Arc::new(pool("sleep", &["30"], 1, 0));
        let limit = Duration::from_millis(300);
        // The one worker is busy: with no waiting room the next solve is refused (503).
        let busy = {
            let p = Arc::clone(&p);
            tokio::spawn(async move { p.solve("x", limit, std::future::pending()).await })
        };
        tokio::time::sleep(Duration::from_millis(100)).await;
        let e = p
            .solve("x", limit, std::future::pending())
            .await
            .unwrap_err();
        assert_eq!(e.status, StatusCode::SERVICE_UNAVAILABLE, "{e:?}");
        // The busy one passes its limit: 408, well before `sleep 30` would end.
        let t = std::time::Instant::now();
        let e = busy.await.unwrap().unwrap_err();
        assert_eq!(e.status, StatusCode::REQUEST_TIMEOUT, "{e:?}");
        assert!(t.elapsed() < Duration::from_secs(5));
        // Cancelled while solving.
        let e = p
            .solve("x", Duration::from_secs(30), tokio::time::sleep(limit))
            .await
            .unwrap_err();
        assert_eq!(e.kind, "cancelled", "{e:?}");
        // A waiting solve whose client went away (its future dropped) frees its place.
        let p = Arc::new(pool("sleep", &["30"], 1, 1));
        let long = Duration::from_secs(30);
        let spawn = |p: &Arc<Pool>| {
            let p = Arc::clone(p);
            tokio::spawn(async move { p.solve("x", long, std::future::pending()).await })
        };
        let busy = spawn(&p);
        tokio::time::sleep(Duration::from_millis(100)).await;
        let waiter = spawn(&p);
        tokio::time::sleep(Duration::from_millis(100)).await;
        let e = p
            .solve("x", long, std::future::pending())
            .await
            .unwrap_err();
        assert_eq!(e.status, StatusCode::SERVICE_UNAVAILABLE, "{e:?}");
        waiter.abort();
        let _ = waiter.await;
        let again = spawn(&p);
        tokio::time::sleep(Duration::from_millis(100)).await;
        assert!(
            !again.is_finished(),
            "the freed place is taken again, not refused"
        );
        again.abort();
        busy.abort();
        // A worker that dies: 500, not a hang.
        let dead = pool("true", &[], 1, 4);
        let e = dead
            .solve("x", Duration::from_secs(30), std::future::pending())
            .await
            .unwrap_err();
        assert_eq!(e.status, StatusCode::INTERNAL_SERVER_ERROR, "{e:?}");
        // A worker that cannot be started: 500 naming it.
        let missing = pool("/nonexistent-kontakt-worker", &[], 1, 4);
        let e = missing
            .solve("x", Duration::from_secs(30), std::future::pending())
            .await
            .unwrap_err();
        assert!(e.message.contains("cannot start"), "{e:?}");
    }

    #[tokio::test]
    async fn stray_output_lines_are_skipped() {
        let script = "read x; echo stray; echo 'kontakt-worker: 200 {\"report\":1}'; read y";
        let p = pool("sh", &["-c", script], 1, 1);
        let (status, body) = p
            .solve("x", Duration::from_secs(10), std::future::pending())
            .await
            .unwrap();
        assert_eq!((status, body.as_str()), (StatusCode::OK, "{\"report\":1}"));
    }

    #[test]
    fn worker_main_answers_a_line_per_case() {
        let case = "method = \"hertz\"\nbogus = 1\n";
        let input = format!("{}\nnot json\n", serde_json::to_string(case).unwrap());
        let mut out = Vec::new();
        worker_main(input.as_bytes(), &mut out).unwrap();
        let out = String::from_utf8(out).unwrap();
        let lines: Vec<&str> = out.lines().collect();
        assert_eq!(lines.len(), 2, "{out}");
        assert!(
            lines[0].starts_with("kontakt-worker: 422 {\"error\""),
            "{}",
            lines[0]
        );
        assert!(
            lines[1].starts_with("kontakt-worker: 400 {\"error\""),
            "{}",
            lines[1]
        );
    }
}
