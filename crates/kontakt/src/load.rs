//! What a normal-contact solve holds fixed: one load-control type for every solver
//! (Hertz point and line contact, PimP, the half-space solver).
//!
//! Units: force \[N\], approach \[mm\], line load \[N/mm\].

use crate::error::{Error, Result, positive_as};
use crate::units::{Millimetre, Newton};

/// The load control of a normal-contact solve.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum LoadControl {
    /// The normal force \[N\], > 0 (load control).
    Force(Newton),
    /// The rigid approach \[mm\] of distant points, measured from first touch (or from
    /// a gap map's zero level), > 0 (displacement control).
    Approach(Millimetre),
    /// The load per unit length \[N/mm\], > 0: line contacts only.
    LineLoad(f64),
}

impl LoadControl {
    /// The control of a point-contact field solver (PimP, the half-space solver):
    /// a positive, finite force or approach.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a non-positive or non-finite value, or a line load
    /// (naming `line_load`: field solvers of point contacts take a force or an approach).
    pub fn point(self) -> Result<Self> {
        match self {
            LoadControl::Force(f) => positive_as("force", f, "a finite force > 0 N")?,
            LoadControl::Approach(d) => positive_as("approach", d, "a finite approach > 0 mm")?,
            LoadControl::LineLoad(q) => {
                return Err(Error::invalid(
                    "line_load",
                    q,
                    "a force (N) or an approach (mm): this solver treats point contacts",
                ));
            }
        };
        Ok(self)
    }
}
