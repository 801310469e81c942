//! What a gap source knows of its two bodies at the contact point: each body's own
//! curvature and the edges of its face. The field solvers' size check
//! ([`crate::field::validity`]) compares the contact zone with them.

use crate::units::{Millimetre, Radian};

/// One body at the contact point, in the gap source's frame (`x`, `y` in the contact
/// plane, as in [`crate::gap::GapSource::sample`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyAtContact {
    /// The body's normal-curvature tensor `[k_xx, k_yy, k_xy]` \[1/mm\] in the source's
    /// frame: the normal curvature in the direction at angle `θ` from `x` is
    /// `k_xx cos²θ + 2 k_xy sinθ cosθ + k_yy sin²θ` (convex > 0, concave < 0, flat 0).
    pub curvature: [f64; 3],
    /// Where the body's face ends near the contact point (a roller end face at the roller's
    /// edge, a crowned roller at its ends); `None` for a face that does not end (a ball, a
    /// plane, a closed torus).
    pub edges: [Option<FaceEdge>; 2],
}

/// An edge of a body's face: the face ends `distance` from the contact point in the
/// direction `direction` of the contact plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FaceEdge {
    /// Distance \[mm\] from the contact point to the edge along `direction`, in the contact
    /// plane (≤ 0: the contact point is at or beyond the edge).
    pub distance: Millimetre,
    /// Unit direction `[x, y]` in the source's frame, from the contact point towards the
    /// edge.
    pub direction: [f64; 2],
    /// The input that sets the edge, as the library's errors name it (for example
    /// `bearing.roller_large_end_radius`, `body1.half_length`).
    pub quantity: &'static str,
    /// What the edge is, for messages (for example "the roller's large end").
    pub what: &'static str,
}

impl BodyAtContact {
    /// A body without edges whose principal radii are `radii` \[mm\] (convex > 0, concave
    /// < 0, `inf` flat), its first principal direction at `angle` \[rad\] from the source's
    /// `x` axis.
    pub fn from_radii(radii: [Millimetre; 2], angle: Radian) -> Self {
        let (k1, k2) = (1.0 / radii[0], 1.0 / radii[1]);
        let (s, c) = angle.sin_cos();
        BodyAtContact {
            curvature: [
                k1 * c * c + k2 * s * s,
                k1 * s * s + k2 * c * c,
                (k1 - k2) * s * c,
            ],
            edges: [None, None],
        }
    }

    /// The normal curvature \[1/mm\] in the direction at `theta` \[rad\] from the source's
    /// `x` axis.
    pub fn normal_curvature(&self, theta: Radian) -> f64 {
        let [kxx, kyy, kxy] = self.curvature;
        let (s, c) = theta.sin_cos();
        kxx * c * c + 2.0 * kxy * s * c + kyy * s * s
    }

    /// The angles \[rad\] of the tensor's two principal directions from the source's `x`
    /// axis.
    pub fn principal_directions(&self) -> [Radian; 2] {
        let [kxx, kyy, kxy] = self.curvature;
        let t = 0.5 * (2.0 * kxy).atan2(kxx - kyy);
        [t, t + std::f64::consts::FRAC_PI_2]
    }

    /// The same body with `edge` added in the first free slot (a third edge replaces the
    /// nearer-to-infinity one, so that the two nearest edges are kept).
    pub fn with_edge(mut self, edge: FaceEdge) -> Self {
        match self.edges {
            [None, _] => self.edges[0] = Some(edge),
            [Some(_), None] => self.edges[1] = Some(edge),
            [Some(a), Some(b)] => {
                let far = if a.distance >= b.distance { 0 } else { 1 };
                if edge.distance < self.edges[far].map_or(f64::INFINITY, |e| e.distance) {
                    self.edges[far] = Some(edge);
                }
            }
        }
        self
    }
}
