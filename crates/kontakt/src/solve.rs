//! Why an iterative solver stopped: one termination status for every iterative solver
//! (PimP's force equilibrium, the half-space solver's conjugate gradients, and the ones
//! to come), after argmin's termination reasons.
//!
//! A solver that stops without converging is not an error at the solver level: its
//! result carries a [`SolveStatus`] and the caller decides, with
//! [`SolveStatus::require_converged`] or by inspecting [`Termination`].

use crate::error::{Error, Result};
use std::borrow::Cow;

/// The reason an iteration stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Termination {
    /// The residual reached the tolerance.
    Converged,
    /// The iteration limit was reached first.
    MaxIterations,
    /// The residual stopped decreasing (a round-off floor above the tolerance).
    Stagnated,
    /// The iteration left its valid region (a bracket could not be found, a residual
    /// became non-finite).
    Diverged,
}

impl Termination {
    /// The reason as a snake_case word, as in the JSON reports.
    pub fn as_str(self) -> &'static str {
        match self {
            Termination::Converged => "converged",
            Termination::MaxIterations => "max_iterations",
            Termination::Stagnated => "stagnated",
            Termination::Diverged => "diverged",
        }
    }
}

impl std::fmt::Display for Termination {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// How an iterative solve ended: the reason, the iterations it took and the final
/// residual in the solver's own documented measure (dimensionless).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
pub struct SolveStatus {
    /// Why the iteration stopped.
    pub termination: Termination,
    /// Iterations (or function evaluations, as the solver documents) performed.
    pub iterations: usize,
    /// Final residual, relative (see the solver's documentation).
    pub residual: f64,
}

impl SolveStatus {
    /// A status.
    pub fn new(termination: Termination, iterations: usize, residual: f64) -> Self {
        SolveStatus {
            termination,
            iterations,
            residual,
        }
    }

    /// Whether the iteration converged.
    pub fn converged(&self) -> bool {
        self.termination == Termination::Converged
    }

    /// The status itself when converged, else [`Error::NotConverged`] naming `what`
    /// and the reason.
    ///
    /// # Errors
    /// [`Error::NotConverged`] unless the termination is [`Termination::Converged`].
    pub fn require_converged(self, what: impl Into<Cow<'static, str>>) -> Result<Self> {
        if self.converged() {
            return Ok(self);
        }
        let what = what.into();
        Err(Error::NotConverged {
            what: match self.termination {
                Termination::Converged => what,
                t => format!("{what} ({})", t.as_str().replace('_', " ")).into(),
            },
            iterations: self.iterations,
            residual: self.residual,
        })
    }
}
