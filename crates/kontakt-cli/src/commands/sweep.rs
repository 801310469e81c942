//! `kontakt sweep SWEEP.toml`: a parameter sweep run on the local cores with a progress
//! bar, resumable, combined into one table. A thin shell over `kontakt_case::Sweep`.

use crate::cli::{SweepArgs, SweepFields, SweepFormat};
use crate::commands::{InputError, progress};
use anyhow::Result;
use kontakt_case::sweep::{
    FIELDS_DIR, Fields, LocalOptions, MAX_THREADS, OutputFormat, Progress, Sweep,
};
use std::io::Write;

/// Run the subcommand.
pub fn run(args: &SweepArgs, out: &mut impl Write) -> Result<()> {
    if let Some(t) = args.threads.filter(|&t| t == 0 || t > MAX_THREADS) {
        return Err(InputError(format!(
            "invalid --threads = {t}: expected 1..={MAX_THREADS}"
        ))
        .into());
    }
    let mut sweep = Sweep::from_path_with_limit(&args.sweep, args.max_cases)?;
    if let Some(f) = args.fields {
        sweep = sweep.with_fields(match f {
            SweepFields::None => Fields::None,
            SweepFields::Npy => Fields::Npy,
        })?;
    }
    let format = match args.format {
        SweepFormat::Parquet => OutputFormat::Parquet,
        SweepFormat::Csv => OutputFormat::Csv,
    };
    let bar = progress(
        Some(sweep.len()),
        "{spinner} [{elapsed_precise}] {wide_bar} {pos}/{len} cases ({per_sec}, {eta} left)",
        args.quiet || args.json,
    );
    let on_progress = |p: Progress| {
        if let Some(b) = &bar {
            b.set_position(p.cases_done);
        }
    };
    let summary = sweep.run_local(
        &args.out,
        LocalOptions {
            threads: args.threads.unwrap_or(0),
            format,
            progress: Some(&on_progress),
        },
    );
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    let s = summary?;
    if args.json {
        let v = serde_json::json!({
            "out": args.out,
            "hash": sweep.hash(),
            "cases": sweep.len(),
            "chunks": s.chunks,
            "chunks_computed": s.chunks_computed,
            "chunks_reused": s.chunks_reused,
            "cases_computed": s.cases_computed,
            "cases_not_ok": s.combined.not_ok,
            "threads": s.threads,
            "seconds_computing": s.seconds_computing,
            "seconds_combining": s.seconds_combining,
            "results": s.combined.path,
            "columns": s.combined.columns,
            "fields": (sweep.fields() != Fields::None).then(|| args.out.join(FIELDS_DIR)),
        });
        serde_json::to_writer_pretty(&mut *out, &v)?;
        writeln!(out)?;
        return every_case_failed(&s.combined);
    }
    let per_case = if s.cases_computed > 0 {
        format!(
            ", {:.2} us per case and thread",
            1e6 * s.seconds_computing * s.threads as f64 / s.cases_computed as f64
        )
    } else {
        String::new()
    };
    writeln!(
        out,
        "Sweep{}: {} cases in {} chunks of {} ({} computed, {} found complete), {} threads, {:.2} s{per_case}",
        sweep
            .name()
            .map(|n| format!(" \"{n}\""))
            .unwrap_or_default(),
        sweep.len(),
        s.chunks,
        sweep.chunk_size(),
        s.chunks_computed,
        s.chunks_reused,
        s.threads,
        s.seconds_computing,
    )?;
    if s.combined.not_ok > 0 {
        writeln!(
            out,
            "{} cases not ok: see the status and error columns",
            s.combined.not_ok
        )?;
    }
    writeln!(
        out,
        "Results: {} ({} rows, {} columns)",
        s.combined.path.display(),
        s.combined.rows,
        s.combined.columns.len()
    )?;
    if sweep.fields() != Fields::None {
        writeln!(
            out,
            "Fields: {}/chunk-*/case-*-<field>.npy (float64, [ny, nx])",
            args.out.join(FIELDS_DIR).display()
        )?;
    }
    every_case_failed(&s.combined)
}

/// A sweep whose every case failed (invalid, failed or panic) is a failed run: exit
/// status 1 after the summary and the table are written (docs/sweep.md), so that a
/// script notices; a sweep with some solved cases succeeds and counts the others.
fn every_case_failed(c: &kontakt_case::sweep::CombineSummary) -> Result<()> {
    if c.rows > 0 && c.not_ok == c.rows {
        anyhow::bail!(
            "every case of the sweep failed ({} of {}): see the status and error columns of {}",
            c.not_ok,
            c.rows,
            c.path.display()
        );
    }
    Ok(())
}
