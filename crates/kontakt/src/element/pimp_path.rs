//! The PimP back-end's options on a planned element: how the gap is sampled.

use super::ContactElement;
use crate::pimp::{GapSampling, PimpTracker};

impl ContactElement {
    /// Choose how the PimP back-end samples the gap: [`GapSampling::Interpolated`] (the
    /// default: exact rays on a stencil, a polynomial on the cells) or
    /// [`GapSampling::Exact`] (exact rays on every cell, for comparison). Forgets the
    /// tracked grid. No effect on the other back-ends.
    pub fn set_pimp_sampling(&mut self, sampling: GapSampling) {
        if let (Some(t), Some(p)) = (&mut self.tracker, self.pimp) {
            // A tracker of a validated solver cannot fail to plan.
            if let Ok(new) = PimpTracker::new(p, sampling) {
                *t = new;
            }
        }
    }

    /// The PimP back-end's tracker (grid, gap and resize count of the last evaluation);
    /// `None` for the other back-ends.
    pub fn pimp_tracker(&self) -> Option<&PimpTracker> {
        self.tracker.as_ref()
    }
}
