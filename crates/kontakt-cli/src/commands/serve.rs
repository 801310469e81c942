//! `kontakt serve`: the local web calculator (crates/kontakt-web; docs/serve.md). This
//! file only turns the flags into [`kontakt_web::ServeOptions`].

use crate::cli::ServeArgs;
use crate::error::InputError;
use anyhow::{Context, Result};
use std::io::Write;
use std::time::Duration;

pub fn run(args: &ServeArgs, out: &mut impl Write) -> Result<()> {
    if args.worker {
        let stdin = std::io::stdin().lock();
        let stdout = std::io::stdout().lock();
        return kontakt_web::worker_main(stdin, stdout).context("worker process");
    }
    if !(0.1..=86_400.0).contains(&args.time_limit) {
        return Err(InputError(format!(
            "invalid --time-limit = {}: expected 0.1 <= S <= 86400 (seconds)",
            args.time_limit
        ))
        .into());
    }
    if let Some(n) = args.workers
        && !(1..=256).contains(&n)
    {
        return Err(InputError(format!("invalid --workers = {n}: expected 1 <= N <= 256")).into());
    }
    let program = std::env::current_exe()
        .context("cannot find the kontakt executable for the worker processes")?;
    let worker = kontakt_web::WorkerCommand {
        program,
        args: vec!["serve".into(), "--worker".into()],
    };
    let mut options = kontakt_web::ServeOptions::new(args.address, args.port, worker);
    options.limits.run_time = Duration::from_secs_f64(args.time_limit);
    options.limits.job_time = Duration::from_secs_f64(args.time_limit * 10.0);
    if let Some(n) = args.workers {
        options.workers = n;
    }
    if !args.address.is_loopback() {
        eprintln!(
            "warning: listening on {}, not on 127.0.0.1: every machine that reaches this \
             address can run solves here (the API has no authentication)",
            args.address
        );
    }
    let mut printed = Ok(());
    kontakt_web::serve(&options, |bound| {
        let url = kontakt_web::url(bound);
        // The URL alone on the first line: scripts and tests read it (with --port 0).
        printed = writeln!(out, "{url}").and_then(|()| out.flush());
        eprintln!("kontakt serve: the calculator is at {url} (Ctrl-C stops the server)");
        if args.open
            && let Err(e) = kontakt_web::open_browser(&url)
        {
            eprintln!("warning: cannot open a browser ({e}); open {url} yourself");
        }
    })
    .with_context(|| format!("cannot serve on {}:{}", args.address, args.port))?;
    printed.map_err(Into::into)
}
