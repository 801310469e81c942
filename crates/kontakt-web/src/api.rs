//! The routes: the JSON API under `/api/` (docs/serve.md) and the embedded pages.

use crate::assets;
use crate::case_io;
use crate::error::{ApiError, json_response};
use crate::jobs::Jobs;
use crate::worker::Pool;
use axum::Router;
use axum::body::Bytes;
use axum::extract::rejection::BytesRejection;
use axum::extract::{DefaultBodyLimit, Path, Request, State};
use axum::http::{HeaderMap, HeaderValue, StatusCode, Uri, header};
use axum::middleware::{self, Next};
use axum::response::{IntoResponse, Response};
use axum::routing::{any, get, post};
use std::net::IpAddr;
use std::sync::Arc;
use std::time::Duration;

/// The server's limits (docs/serve.md, "Limits").
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// Longest solve of `POST /api/run`.
    pub run_time: Duration,
    /// Longest solve of a job.
    pub job_time: Duration,
    /// Largest request body, bytes.
    pub max_body: usize,
}

/// What every handler shares.
#[derive(Clone)]
pub struct AppState {
    /// The worker processes.
    pub pool: Arc<Pool>,
    /// The jobs.
    pub jobs: Arc<Jobs>,
    /// The limits.
    pub limits: Limits,
    /// The address the server listens on (decides which `Host` headers are accepted).
    pub address: IpAddr,
}

/// The whole application.
pub fn router(state: AppState) -> Router {
    Router::new()
        .route("/api/health", get(health))
        .route("/api/schema", get(schema))
        .route("/api/examples", get(list_examples))
        .route("/api/examples/{name}", get(get_example))
        .route("/api/case/parse", post(case_parse))
        .route("/api/case/toml", post(case_toml))
        .route("/api/run", post(run))
        .route("/api/jobs", post(job_start))
        .route("/api/jobs/{id}", get(job_status).delete(job_cancel))
        .route("/api/{*rest}", any(api_not_found))
        .fallback(static_asset)
        .method_not_allowed_fallback(method_not_allowed)
        .layer(DefaultBodyLimit::max(state.limits.max_body))
        .layer(middleware::from_fn_with_state(state.clone(), guard))
        .with_state(state)
}

fn json(value: &impl serde::Serialize) -> Response {
    match serde_json::to_string(value) {
        Ok(body) => json_response(StatusCode::OK, body),
        Err(e) => ApiError::new(StatusCode::INTERNAL_SERVER_ERROR, "internal", e.to_string())
            .into_response(),
    }
}

/// Refuse requests whose `Host` is not this machine when listening on loopback (a web page
/// elsewhere cannot reach the API through DNS rebinding), and set the headers that keep
/// the pages from being framed or sniffed.
async fn guard(State(state): State<AppState>, request: Request, next: Next) -> Response {
    if state.address.is_loopback() {
        let host = request
            .headers()
            .get(header::HOST)
            .and_then(|h| h.to_str().ok())
            .unwrap_or("");
        if !local_host(host) {
            return ApiError::new(
                StatusCode::MISDIRECTED_REQUEST,
                "request",
                format!("Host {host:?} is not this machine: the server answers 127.0.0.1 and localhost only"),
            )
            .into_response();
        }
    }
    let mut response = next.run(request).await;
    let h = response.headers_mut();
    h.insert(
        "x-content-type-options",
        HeaderValue::from_static("nosniff"),
    );
    h.insert("x-frame-options", HeaderValue::from_static("DENY"));
    h.insert("referrer-policy", HeaderValue::from_static("no-referrer"));
    h.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store"));
    response
}

/// `localhost`, `127.0.0.1`, `[::1]`, with or without a port.
fn local_host(host: &str) -> bool {
    let name = if let Some(rest) = host.strip_prefix('[') {
        rest.split(']').next().unwrap_or("")
    } else {
        host.split(':').next().unwrap_or("")
    };
    name.eq_ignore_ascii_case("localhost")
        || name.parse::<IpAddr>().is_ok_and(|ip| ip.is_loopback())
}

/// The request body as JSON: 415 unless it says it is JSON (a form on another web site
/// cannot send that without the browser asking first), 413 above the cap, 400 with the
/// parser's message when it does not parse.
fn json_body(
    headers: &HeaderMap,
    body: Result<Bytes, BytesRejection>,
) -> Result<serde_json::Value, ApiError> {
    let is_json = headers
        .get(header::CONTENT_TYPE)
        .and_then(|v| v.to_str().ok())
        .is_some_and(|v| {
            v.trim_start()
                .to_ascii_lowercase()
                .starts_with("application/json")
        });
    if !is_json {
        return Err(ApiError::new(
            StatusCode::UNSUPPORTED_MEDIA_TYPE,
            "request",
            "the body must be JSON (Content-Type: application/json)",
        ));
    }
    let bytes = body.map_err(|e| {
        let status = e.status();
        let message = if status == StatusCode::PAYLOAD_TOO_LARGE {
            "the request body is larger than the server's limit".to_string()
        } else {
            e.body_text()
        };
        ApiError::new(status, "request", message)
    })?;
    let value: serde_json::Value = serde_json::from_slice(&bytes)
        .map_err(|e| ApiError::bad_request(format!("the body is not valid JSON: {e}")))?;
    if !value.is_object() {
        return Err(ApiError::bad_request("the body must be a JSON object"));
    }
    Ok(value)
}

/// The member `key` of the body.
fn member<'a>(body: &'a serde_json::Value, key: &str) -> Result<&'a serde_json::Value, ApiError> {
    body.get(key)
        .ok_or_else(|| ApiError::bad_request(format!("the body has no \"{key}\" member")))
}

/// The case of a `{"case": ...}` body, checked by the case parser: its TOML text.
fn checked_case(
    headers: &HeaderMap,
    body: Result<Bytes, BytesRejection>,
) -> Result<String, ApiError> {
    let body = json_body(headers, body)?;
    let (text, source) = case_io::case_text(member(&body, "case")?)?;
    case_io::parse_case(&text, source)?;
    Ok(text)
}

async fn health() -> Response {
    json(&serde_json::json!({ "kontakt_version": kontakt::VERSION }))
}

/// The JSON Schema of the case files (`kontakt schema`, docs/kontakt-case.schema.json):
/// the forms' and editors' description of every key.
async fn schema() -> Response {
    json(&kontakt_case::case_schema())
}

async fn list_examples() -> Response {
    json(&assets::examples())
}

async fn get_example(Path(name): Path<String>) -> Response {
    match assets::example(&name) {
        Some(text) => ([(header::CONTENT_TYPE, "text/plain; charset=utf-8")], text).into_response(),
        None => ApiError::not_found(format!("no example case named {name:?}")).into_response(),
    }
}

async fn case_parse(headers: HeaderMap, body: Result<Bytes, BytesRejection>) -> Response {
    let result = (|| {
        let body = json_body(&headers, body)?;
        let text = member(&body, "toml")?.as_str().ok_or_else(|| {
            ApiError::bad_request("toml: expected the case file's text (a string)")
        })?;
        let (case, table) = case_io::parse_case(text, case_io::Source::Toml)?;
        Ok::<_, ApiError>(serde_json::json!({
            "case": case_io::json_of_table(&table),
            "method": case.method(),
        }))
    })();
    result.map_or_else(IntoResponse::into_response, |v| json(&v))
}

async fn case_toml(headers: HeaderMap, body: Result<Bytes, BytesRejection>) -> Response {
    let result = (|| {
        let body = json_body(&headers, body)?;
        let case = member(&body, "case")?;
        if !case.is_object() {
            return Err(ApiError::bad_request(
                "case: expected the case's tables (a JSON object)",
            ));
        }
        let text = case_io::toml_of_json(case)?;
        let (case, _) = case_io::parse_case(&text, case_io::Source::Json)?;
        Ok(serde_json::json!({ "toml": text, "method": case.method() }))
    })();
    result.map_or_else(IntoResponse::into_response, |v| json(&v))
}

async fn run(
    State(state): State<AppState>,
    headers: HeaderMap,
    body: Result<Bytes, BytesRejection>,
) -> Response {
    let text = match checked_case(&headers, body) {
        Ok(t) => t,
        Err(e) => return e.into_response(),
    };
    // A client that goes away drops this future, and with it the worker (killed).
    match state
        .pool
        .solve(&text, state.limits.run_time, std::future::pending())
        .await
    {
        Ok((status, body)) => json_response(status, body),
        Err(e) => e.into_response(),
    }
}

async fn job_start(
    State(state): State<AppState>,
    headers: HeaderMap,
    body: Result<Bytes, BytesRejection>,
) -> Response {
    let started = checked_case(&headers, body).and_then(|text| {
        state
            .jobs
            .start(Arc::clone(&state.pool), text, state.limits.job_time)
    });
    match started {
        Ok(id) => {
            let location = format!("/api/jobs/{id}");
            let mut r = json_response(
                StatusCode::ACCEPTED,
                serde_json::json!({ "id": id }).to_string(),
            );
            if let Ok(v) = HeaderValue::from_str(&location) {
                r.headers_mut().insert(header::LOCATION, v);
            }
            r
        }
        Err(e) => e.into_response(),
    }
}

async fn job_status(State(state): State<AppState>, Path(id): Path<String>) -> Response {
    state
        .jobs
        .status(&id)
        .map_or_else(IntoResponse::into_response, |v| json(&v))
}

async fn job_cancel(State(state): State<AppState>, Path(id): Path<String>) -> Response {
    state
        .jobs
        .cancel(&id)
        .map_or_else(IntoResponse::into_response, |v| json(&v))
}

async fn api_not_found(uri: Uri) -> Response {
    ApiError::not_found(format!(
        "no API endpoint {} (docs/serve.md lists them)",
        uri.path()
    ))
    .into_response()
}

async fn method_not_allowed(method: axum::http::Method, uri: Uri) -> Response {
    ApiError::new(
        StatusCode::METHOD_NOT_ALLOWED,
        "request",
        format!("{method} is not allowed on {}", uri.path()),
    )
    .into_response()
}

/// A page, script or style from the embedded assets; `/` is `index.html`.
async fn static_asset(method: axum::http::Method, uri: Uri) -> Response {
    if method != axum::http::Method::GET && method != axum::http::Method::HEAD {
        return method_not_allowed(method, uri).await;
    }
    let path = uri.path().trim_start_matches('/');
    let path = if path.is_empty() || path.ends_with('/') {
        format!("{path}index.html")
    } else {
        path.to_string()
    };
    match assets::Assets::get(&path) {
        Some(file) => (
            [(header::CONTENT_TYPE, assets::content_type(&path))],
            file.data.into_owned(),
        )
            .into_response(),
        None => (
            StatusCode::NOT_FOUND,
            [(header::CONTENT_TYPE, "text/plain; charset=utf-8")],
            format!("no page {}", uri.path()),
        )
            .into_response(),
    }
}

#[cfg(test)]
mod tests {
    use super::local_host;

    #[test]
    fn only_this_machine_is_a_local_host() {
        for h in [
            "localhost",
            "localhost:8080",
            "127.0.0.1:1",
            "[::1]:80",
            "LOCALHOST",
        ] {
            assert!(local_host(h), "{h}");
        }
        for h in [
            "",
            "evil.example",
            "evil.example:80",
            "10.0.0.1:80",
            "localhost.evil.example",
        ] {
            assert!(!local_host(h), "{h}");
        }
    }
}
