//! The API's error answer: one shape for every failure, `{"error": {"message", "field",
//! "value", "expected", "kind"}}`, with the HTTP status that says whose fault it is.

use axum::http::StatusCode;
use axum::response::{IntoResponse, Response};
use serde::Serialize;

/// An error answer of the API. `message` is the one line the command line prints for the
/// same input (without the file name it prefixes); `field` is the case key as the file
/// spells it (`body1.e_mpa`), when the error names one.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ApiError {
    /// The HTTP status: 400 malformed body, 404 unknown id or name, 408 time limit, 413
    /// body too large, 415 not JSON, 422 input the case runner refuses, 500 the worker
    /// failed, 503 overloaded.
    #[serde(skip)]
    pub status: StatusCode,
    /// What went wrong, one line.
    pub message: String,
    /// The case key, e.g. `load.force_n`, or `None`.
    pub field: Option<String>,
    /// The value received, as the message quotes it.
    pub value: Option<String>,
    /// The valid range or form.
    pub expected: Option<String>,
    /// The class of error: `input`, `geometry`, `case_file`, `not_converged`, `request`,
    /// `time_limit`, `cancelled`, `overloaded`, `not_found`, `internal`.
    pub kind: &'static str,
}

impl ApiError {
    /// An error without a field.
    pub fn new(status: StatusCode, kind: &'static str, message: impl Into<String>) -> Self {
        ApiError {
            status,
            message: one_line(&message.into()),
            field: None,
            value: None,
            expected: None,
            kind,
        }
    }

    /// A malformed request body (400), with the parser's message.
    pub fn bad_request(message: impl Into<String>) -> Self {
        Self::new(StatusCode::BAD_REQUEST, "request", message)
    }

    /// Nothing under that name or id (404).
    pub fn not_found(message: impl Into<String>) -> Self {
        Self::new(StatusCode::NOT_FOUND, "not_found", message)
    }

    /// A case the runner refuses, from the library's error: 422 with the field, value and
    /// valid range the library names (the same text as the command line's message).
    pub fn from_case(err: &kontakt::Error) -> Self {
        let mut e = Self::new(StatusCode::UNPROCESSABLE_ENTITY, "input", err.to_string());
        match err {
            kontakt::Error::InvalidInput {
                field,
                value,
                expected,
            } => {
                e.field = Some(field.to_string());
                e.value = Some(value.clone());
                e.expected = Some(expected.to_string());
            }
            kontakt::Error::Geometry { field, .. } => {
                e.kind = "geometry";
                e.field = Some(field.to_string());
            }
            kontakt::Error::CaseFile { key, .. } => {
                e.kind = "case_file";
                e.field = (key != "case").then(|| key.to_string());
            }
            kontakt::Error::NotConverged { .. } => e.kind = "not_converged",
            // kontakt::Error is non-exhaustive: a new variant is an input error until
            // it is classified here.
            _ => {}
        }
        e
    }

    /// The JSON body, `{"error": {...}}`.
    pub fn body(&self) -> String {
        serde_json::json!({ "error": self }).to_string()
    }
}

impl IntoResponse for ApiError {
    fn into_response(self) -> Response {
        json_response(self.status, self.body())
    }
}

/// A JSON answer: the status and the body, `Content-Type: application/json`.
pub fn json_response(status: StatusCode, body: String) -> Response {
    (
        status,
        [(axum::http::header::CONTENT_TYPE, "application/json")],
        axum::body::Body::from(body),
    )
        .into_response()
}

/// Whitespace (newlines of multi-line messages included) collapsed to single spaces.
pub fn one_line(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}
