//! `kontakt serve`: a local web calculator in the `kontakt` binary.
//!
//! An HTTP server (axum on tokio) that answers a JSON API over [`kontakt_case::Case::run`],
//! the dispatch of `kontakt solve` (same validation, same messages, the same JSON report),
//! and serves the calculator's pages embedded in the binary. Solves run in worker
//! processes (the same executable in worker mode, [`worker`]): bounded in number, limited
//! in time, killed on cancellation. docs/serve.md describes the API, the limits and the
//! security model.

pub mod api;
pub mod assets;
pub mod case_io;
pub mod error;
pub mod jobs;
pub mod page_data;
pub mod worker;

pub use api::Limits;
pub use error::ApiError;
pub use worker::{WorkerCommand, worker_main};

use std::net::{IpAddr, SocketAddr};
use std::sync::Arc;
use std::time::Duration;

/// How `kontakt serve` runs.
#[derive(Debug, Clone, PartialEq)]
pub struct ServeOptions {
    /// The address to listen on (127.0.0.1 unless the user names another).
    pub address: IpAddr,
    /// The port; 0 picks a free one.
    pub port: u16,
    /// Concurrent solves (worker processes).
    pub workers: usize,
    /// Solves that may wait for a worker before the server answers 503.
    pub max_waiting: usize,
    /// Jobs kept (running and finished).
    pub max_jobs: usize,
    /// The time and size limits.
    pub limits: Limits,
    /// How to start a worker process.
    pub worker: WorkerCommand,
}

impl ServeOptions {
    /// The defaults on `address:port` with workers started by `worker`: as many workers as
    /// the machine has cores (at least 2), 64 waiting solves, 64 jobs, 60 s a solve of
    /// `/api/run`, 10 min a job, 1 MiB a body.
    pub fn new(address: IpAddr, port: u16, worker: WorkerCommand) -> Self {
        let cores = std::thread::available_parallelism().map_or(2, usize::from);
        ServeOptions {
            address,
            port,
            workers: cores.max(2),
            max_waiting: 64,
            max_jobs: 64,
            limits: Limits {
                run_time: Duration::from_secs(60),
                job_time: Duration::from_secs(600),
                max_body: 1 << 20,
            },
            worker,
        }
    }
}

/// Listen, call `ready` with the bound address (the caller prints the URL, opens the
/// browser), and serve until the process ends.
///
/// # Errors
/// The address cannot be bound (in use, not an address of this machine), or the runtime
/// cannot start.
pub fn serve(options: &ServeOptions, ready: impl FnOnce(SocketAddr)) -> std::io::Result<()> {
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()?;
    runtime.block_on(async {
        let listener =
            tokio::net::TcpListener::bind(SocketAddr::new(options.address, options.port)).await?;
        let bound = listener.local_addr()?;
        let state = api::AppState {
            pool: Arc::new(worker::Pool::new(
                options.worker.clone(),
                options.workers,
                options.max_waiting,
            )),
            jobs: Arc::new(jobs::Jobs::new(options.max_jobs)),
            limits: options.limits,
            address: options.address,
        };
        ready(bound);
        axum::serve(listener, api::router(state)).await
    })
}

/// The URL of the server at `address` (`http://127.0.0.1:PORT/`; IPv6 in brackets).
pub fn url(address: SocketAddr) -> String {
    format!("http://{address}/")
}

/// Open `url` in the desktop's browser (`xdg-open`, `open` on macOS, `explorer` on
/// Windows), without a shell and without waiting for it.
///
/// # Errors
/// The opener cannot be started (the caller warns; the server runs on).
pub fn open_browser(url: &str) -> std::io::Result<()> {
    let opener = if cfg!(target_os = "macos") {
        "open"
    } else if cfg!(windows) {
        "explorer"
    } else {
        "xdg-open"
    };
    std::process::Command::new(opener)
        .arg(url)
        .stdin(std::process::Stdio::null())
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .map(drop)
}
