//! Long solves as jobs: `POST /api/jobs` starts one and answers its id at once, `GET`
//! polls it, `DELETE` cancels it (its worker process is killed).

use crate::error::ApiError;
use crate::worker::{Answer, Pool};
use axum::http::StatusCode;
use std::collections::HashMap;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};
use tokio::sync::oneshot;

/// Where a job is.
#[derive(Debug)]
enum State {
    Running(Option<oneshot::Sender<()>>),
    Done(serde_json::Value),
    Failed(serde_json::Value),
    Cancelled,
}

#[derive(Debug)]
struct Job {
    started: Instant,
    finished: Option<Duration>,
    state: State,
}

/// The server's jobs: at most `max_jobs` kept (the oldest finished ones are forgotten
/// first; when all are running, a new one is refused with 503).
pub struct Jobs {
    table: Mutex<(u64, HashMap<String, Job>)>,
    max_jobs: usize,
}

impl Jobs {
    /// An empty table keeping at most `max_jobs` jobs.
    pub fn new(max_jobs: usize) -> Self {
        Jobs {
            table: Mutex::new((0, HashMap::new())),
            max_jobs: max_jobs.max(1),
        }
    }

    /// Start solving `text` (checked TOML) in `pool`; the job's id.
    ///
    /// # Errors
    /// 503 when `max_jobs` jobs are running.
    pub fn start(
        self: &Arc<Self>,
        pool: Arc<Pool>,
        text: String,
        limit: Duration,
    ) -> Result<String, ApiError> {
        let (tx, rx) = oneshot::channel::<()>();
        let id = {
            let mut guard = lock(&self.table);
            let (counter, table) = &mut *guard;
            if table.len() >= self.max_jobs {
                let oldest = table
                    .iter()
                    .filter(|(_, j)| !matches!(j.state, State::Running(_)))
                    .min_by_key(|(_, j)| j.started)
                    .map(|(id, _)| id.clone());
                match oldest {
                    Some(id) => {
                        table.remove(&id);
                    }
                    None => {
                        return Err(ApiError::new(
                            StatusCode::SERVICE_UNAVAILABLE,
                            "overloaded",
                            format!("{} jobs are running; wait for one to end", self.max_jobs),
                        ));
                    }
                }
            }
            *counter += 1;
            let id = format!("{:x}{:08x}", *counter, std::process::id());
            table.insert(
                id.clone(),
                Job {
                    started: Instant::now(),
                    finished: None,
                    state: State::Running(Some(tx)),
                },
            );
            id
        };
        let jobs = Arc::clone(self);
        let job_id = id.clone();
        tokio::spawn(async move {
            let cancel = async {
                // A dropped sender (the job forgotten) also ends the solve.
                let _ = rx.await;
            };
            let result = pool.solve(&text, limit, cancel).await;
            jobs.finish(&job_id, result);
        });
        Ok(id)
    }

    fn finish(&self, id: &str, result: Result<Answer, ApiError>) {
        let mut guard = lock(&self.table);
        let Some(job) = guard.1.get_mut(id) else {
            return;
        };
        if !matches!(job.state, State::Running(_)) {
            return;
        }
        job.finished = Some(job.started.elapsed());
        job.state = match result {
            Ok((status, body)) => {
                let value = serde_json::from_str(&body).unwrap_or(serde_json::Value::Null);
                if status == StatusCode::OK {
                    State::Done(value)
                } else {
                    State::Failed(value["error"].clone())
                }
            }
            Err(e) if e.kind == "cancelled" => State::Cancelled,
            Err(e) => State::Failed(serde_json::to_value(&e).unwrap_or_default()),
        };
    }

    /// The job's state as the API answers it.
    ///
    /// # Errors
    /// 404 for an unknown id.
    pub fn status(&self, id: &str) -> Result<serde_json::Value, ApiError> {
        let guard = lock(&self.table);
        let job = guard.1.get(id).ok_or_else(|| unknown(id))?;
        let elapsed = job.finished.unwrap_or_else(|| job.started.elapsed());
        let mut v = serde_json::json!({
            "id": id,
            "elapsed_s": elapsed.as_secs_f64(),
            "progress": serde_json::Value::Null,
        });
        match &job.state {
            State::Running(_) => v["state"] = "running".into(),
            State::Done(answer) => {
                v["state"] = "done".into();
                v["progress"] = 1.0.into();
                v["report"] = answer["report"].clone();
                v["warnings"] = answer["warnings"].clone();
                for key in ["axis_stress", "fields"] {
                    if let Some(x) = answer.get(key) {
                        v[key] = x.clone();
                    }
                }
            }
            State::Failed(error) => {
                v["state"] = "failed".into();
                v["error"] = error.clone();
            }
            State::Cancelled => v["state"] = "cancelled".into(),
        }
        Ok(v)
    }

    /// Cancel a running job (its worker is killed); a finished job is left as it is.
    ///
    /// # Errors
    /// 404 for an unknown id.
    pub fn cancel(&self, id: &str) -> Result<serde_json::Value, ApiError> {
        {
            let mut guard = lock(&self.table);
            let job = guard.1.get_mut(id).ok_or_else(|| unknown(id))?;
            if let State::Running(tx) = &mut job.state {
                if let Some(tx) = tx.take() {
                    let _ = tx.send(());
                }
                job.finished = Some(job.started.elapsed());
                job.state = State::Cancelled;
            }
        }
        self.status(id)
    }
}

fn unknown(id: &str) -> ApiError {
    ApiError::not_found(format!(
        "no job with id {id:?} (finished jobs are kept for a while only)"
    ))
}

/// The lock, also after a panic elsewhere (the table stays consistent: every change is one
/// assignment).
fn lock<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    m.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;
    use crate::worker::WorkerCommand;

    /// A worker that never answers (`sleep`): jobs stay running until cancelled.
    fn sleeping_pool() -> Arc<Pool> {
        let command = WorkerCommand {
            program: "sleep".into(),
            args: vec!["30".into()],
        };
        Arc::new(Pool::new(command, 2, 4))
    }

    #[tokio::test]
    async fn the_table_is_bounded_and_cancel_frees_a_place() {
        let jobs = Arc::new(Jobs::new(1));
        let pool = sleeping_pool();
        let limit = Duration::from_secs(30);
        let first = jobs.start(Arc::clone(&pool), "x".into(), limit).unwrap();
        assert_eq!(jobs.status(&first).unwrap()["state"], "running");
        // The one place is taken by a running job: refused.
        let e = jobs
            .start(Arc::clone(&pool), "x".into(), limit)
            .unwrap_err();
        assert_eq!(e.status, StatusCode::SERVICE_UNAVAILABLE, "{e:?}");
        // Cancelled, the first is forgotten to make room for the next.
        assert_eq!(jobs.cancel(&first).unwrap()["state"], "cancelled");
        let second = jobs.start(Arc::clone(&pool), "x".into(), limit).unwrap();
        assert_ne!(first, second);
        assert_eq!(
            jobs.status(&first).unwrap_err().status,
            StatusCode::NOT_FOUND
        );
        assert_eq!(jobs.cancel(&second).unwrap()["state"], "cancelled");
        // Cancelling twice leaves it cancelled.
        assert_eq!(jobs.cancel(&second).unwrap()["state"], "cancelled");
    }

    #[tokio::test]
    async fn a_job_past_its_limit_fails_with_the_time_limit_error() {
        let jobs = Arc::new(Jobs::new(4));
        let id = jobs
            .start(sleeping_pool(), "x".into(), Duration::from_millis(200))
            .unwrap();
        tokio::time::sleep(Duration::from_millis(1500)).await;
        let v = jobs.status(&id).unwrap();
        assert_eq!(v["state"], "failed", "{v}");
        assert_eq!(v["error"]["kind"], "time_limit", "{v}");
        assert!(v["elapsed_s"].as_f64().unwrap() < 1.4, "{v}");
    }
}
