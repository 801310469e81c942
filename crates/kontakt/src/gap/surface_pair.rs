//! The substitute geometry of two placed analytic surfaces, by ray casting (Wirsching et al. 2020,
//! Step 2, eq. 2).

use super::{BodyAtContact, FaceEdge, GapSource, check_len};
use crate::error::{Error, Result};
use crate::geometry::contact_point::{ContactPoint, find_contact};
use crate::geometry::surface::{Curvature, PlacedSurface, Profile, Ray, Surface};
use crate::geometry::{ContactFrame, Grid2, RelativeCurvature};
use crate::units::Millimetre;
use nalgebra::{Isometry3, Point3, Unit, Vector3};

/// The two bodies at the contact with their curvature tensors and no edges yet (the faces'
/// edges are marked after, `add_profile_ends`).
fn edgeless(tensors: [[f64; 3]; 2]) -> [BodyAtContact; 2] {
    tensors.map(|curvature| BodyAtContact {
        curvature,
        edges: [None, None],
    })
}

/// The gap between two placed surfaces, measured along the common normal from the
/// contact plane at their contact point.
///
/// Frame: origin at the contact point (the mid-point of the two surface points), `z`
/// along the common normal into body 1, `x` along body 1's first principal direction,
/// `y = z × x`. `g1` is cast from below (`+z`) onto body 1, `g2` from above (`−z`) onto
/// body 2; the sample is `g = g1 − g2` minus the pose's separation, so it is zero at the
/// contact point whether the pose leaves the bodies apart or interpenetrating.
#[derive(Debug, Clone, PartialEq)]
pub struct SurfacePairGap {
    body1: PlacedSurface,
    body2: PlacedSurface,
    contact: ContactPoint,
    ex: Unit<Vector3<f64>>,
    ey: Unit<Vector3<f64>>,
    curvature: RelativeCurvature,
    bodies: [BodyAtContact; 2],
}

impl SurfacePairGap {
    /// The gap of `body1` and `body2` at their contact point `contact` (from
    /// [`find_contact`] or an idealised construction such as the roller/rib pair).
    ///
    /// # Errors
    /// [`Error::Geometry`] when the relative curvature at the contact point is not
    /// positive in every direction (conformal surfaces or a line contact: PimP needs a
    /// point of first contact).
    pub fn new(body1: PlacedSurface, body2: PlacedSurface, contact: ContactPoint) -> Result<Self> {
        let (ex, ey, curvature, tensors) = Self::at_contact(&body1, &body2, &contact)?;
        let mut gap = SurfacePairGap {
            body1,
            body2,
            contact,
            ex,
            ey,
            curvature,
            bodies: edgeless(tensors),
        };
        gap.add_profile_ends();
        Ok(gap)
    }

    /// The same two surfaces at new poses (world, as [`PlacedSurface::pose`]) and their
    /// contact point there: equal to [`SurfacePairGap::new`] with the surfaces so placed,
    /// without copying the surfaces (a contact element moves its gap every call).
    ///
    /// # Errors
    /// As [`SurfacePairGap::new`]; the gap is then left unchanged.
    pub fn move_to(
        &mut self,
        pose1: &Isometry3<f64>,
        pose2: &Isometry3<f64>,
        contact: ContactPoint,
    ) -> Result<()> {
        let (old1, old2) = (self.body1.pose, self.body2.pose);
        self.body1.pose = *pose1;
        self.body2.pose = *pose2;
        match Self::at_contact(&self.body1, &self.body2, &contact) {
            Ok((ex, ey, curvature, tensors)) => {
                self.contact = contact;
                self.ex = ex;
                self.ey = ey;
                self.curvature = curvature;
                self.bodies = edgeless(tensors);
                self.add_profile_ends();
                Ok(())
            }
            Err(e) => {
                self.body1.pose = old1;
                self.body2.pose = old2;
                Err(e)
            }
        }
    }

    /// The frame, relative curvature and bodies' curvature tensors `[k_xx, k_yy, k_xy]`
    /// \[1/mm\] of the two placed surfaces at their contact point.
    #[allow(clippy::type_complexity)]
    fn at_contact(
        body1: &PlacedSurface,
        body2: &PlacedSurface,
        contact: &ContactPoint,
    ) -> Result<(
        Unit<Vector3<f64>>,
        Unit<Vector3<f64>>,
        RelativeCurvature,
        [[f64; 3]; 2],
    )> {
        let n = contact.normal;
        // At the contact's feet, whose outward normals are -n (body 1) and n (body 2).
        let k1 = body1.curvature_on(&contact.point1, &-n);
        let k2 = body2.curvature_on(&contact.point2, &n);
        // x along body 1's first principal direction, projected into the plane.
        let ex = Unit::try_new(k1.d1.into_inner() - n.into_inner() * k1.d1.dot(&n), 1e-9)
            .or_else(|| any_perpendicular(&n))
            .ok_or_else(|| Error::Geometry {
                field: "normal".into(),
                reason: "the contact normal is not a unit vector".into(),
            })?;
        let ey = Unit::new_normalize(n.cross(&ex));
        let (mut kxx, mut kyy, mut kxy) = (0.0, 0.0, 0.0);
        let mut tensors = [[0.0; 3]; 2];
        for (t, k) in tensors.iter_mut().zip([&k1, &k2]) {
            let (xx, yy, xy) = tensor(k, &ex, &ey);
            kxx += xx;
            kyy += yy;
            kxy += xy;
            *t = [xx, yy, xy];
        }
        let curvature = RelativeCurvature::from_tensor(kxx, kyy, kxy).map_err(|e| match e {
            Error::Geometry { reason, .. } => Error::Geometry {
                field: "surfaces".into(),
                reason: format!("at the contact point: {reason}"),
            },
            other => other,
        })?;
        Ok((ex, ey, curvature, tensors))
    }

    /// A surface of revolution (a crowned roller) ends at its profile's `z` range: both
    /// ends become edges of its face.
    fn add_profile_ends(&mut self) {
        const QUANTITY: [[&str; 2]; 2] = [
            ["body1.half_length", "body1.profile"],
            ["body2.half_length", "body2.profile"],
        ];
        for (b, names) in QUANTITY.iter().enumerate() {
            let (surface, point) = if b == 0 {
                (&self.body1, self.contact.point1)
            } else {
                (&self.body2, self.contact.point2)
            };
            let Surface::Revolution(rev) = &surface.surface else {
                continue;
            };
            let quantity = match rev.profile() {
                Profile::Table { .. } => names[1],
                _ => names[0],
            };
            let z = surface.to_local(&point).z;
            let [z_min, z_max] = rev.z_range();
            let axis = surface.pose.rotation * Vector3::z();
            self.add_edge(b, axis, z_max - z, quantity, "the end of the profile");
            self.add_edge(b, -axis, z - z_min, quantity, "the end of the profile");
        }
    }

    /// Mark an edge of body `body` (0 or 1) where its face ends: the face ends where a
    /// coordinate whose world gradient is `gradient` (a unit vector, for example the
    /// radial direction from a roller's axis) has grown by `remaining` \[mm\] from the
    /// contact point. `quantity` names the input that sets the edge, `what` describes it.
    /// The edge lies along the gradient's projection into the contact plane; a gradient
    /// along the normal (the face ends nowhere near in the plane) adds no edge.
    pub fn add_edge(
        &mut self,
        body: usize,
        gradient: Vector3<f64>,
        remaining: Millimetre,
        quantity: &'static str,
        what: &'static str,
    ) {
        let n = self.contact.normal.into_inner();
        let g = gradient.try_normalize(0.0).unwrap_or_else(Vector3::zeros);
        let in_plane = g - n * g.dot(&n);
        let rate = in_plane.norm();
        if body > 1 || !(rate > 1e-9) || !remaining.is_finite() {
            return;
        }
        let u = in_plane / rate;
        self.bodies[body] = self.bodies[body].with_edge(FaceEdge {
            distance: remaining / rate,
            direction: [u.dot(&self.ex), u.dot(&self.ey)],
            quantity,
            what,
        });
    }

    /// Find the contact point of the two placed surfaces (Step 1) and build the gap.
    ///
    /// # Errors
    /// Those of [`find_contact`] and [`SurfacePairGap::new`].
    pub fn from_poses(
        body1: PlacedSurface,
        body2: PlacedSurface,
        guess: Option<Point3<f64>>,
    ) -> Result<Self> {
        let contact = find_contact(&body1, &body2, guess)?;
        Self::new(body1, body2, contact)
    }

    /// The contact point this gap is built on.
    pub fn contact(&self) -> &ContactPoint {
        &self.contact
    }

    /// Separation of the pose \[mm\]: > 0 the bodies are apart by this distance, < 0 they
    /// interpenetrate by its magnitude (the approach of the multi-body path).
    pub fn separation(&self) -> Millimetre {
        self.contact.separation
    }

    /// The frame axes `[x, y, z]` of the contact plane in world coordinates.
    pub fn axes(&self) -> [Unit<Vector3<f64>>; 3] {
        [self.ex, self.ey, self.contact.normal]
    }

    /// The axes `[x, y]` of the gap's principal frame (the frame of PimP's and the half-space
    /// solver's grids: `x` along the direction of the smaller relative curvature A, i.e. the
    /// Hertz ellipse's major axis) as unit vectors in world coordinates.
    pub fn principal_axes(&self) -> [[f64; 3]; 2] {
        let (s, c) = self.curvature.orientation.sin_cos();
        let (ex, ey) = (self.ex.into_inner(), self.ey.into_inner());
        let gx = ex * c + ey * s;
        let gy = ey * c - ex * s;
        [[gx.x, gx.y, gx.z], [gy.x, gy.y, gy.z]]
    }

    /// World point of the contact-plane point `(x, y)` \[mm\].
    pub fn world_point(&self, x: Millimetre, y: Millimetre) -> Point3<f64> {
        self.contact.point + self.ex.into_inner() * x + self.ey.into_inner() * y
    }
}

/// The normal-curvature tensor of one body in the plane frame (ex, ey).
fn tensor(k: &Curvature, ex: &Unit<Vector3<f64>>, ey: &Unit<Vector3<f64>>) -> (f64, f64, f64) {
    let (x1, y1) = (k.d1.dot(ex), k.d1.dot(ey));
    let (x2, y2) = (k.d2.dot(ex), k.d2.dot(ey));
    (
        k.k1 * x1 * x1 + k.k2 * x2 * x2,
        k.k1 * y1 * y1 + k.k2 * y2 * y2,
        k.k1 * x1 * y1 + k.k2 * x2 * y2,
    )
}

fn any_perpendicular(n: &Unit<Vector3<f64>>) -> Option<Unit<Vector3<f64>>> {
    let trial = if n.x.abs() < 0.9 {
        Vector3::x()
    } else {
        Vector3::y()
    };
    Unit::try_new(trial - n.into_inner() * trial.dot(n), 1e-9)
}

impl GapSource for SurfacePairGap {
    fn curvature(&self) -> RelativeCurvature {
        self.curvature
    }

    fn bodies(&self) -> Option<[BodyAtContact; 2]> {
        Some(self.bodies)
    }

    fn sample(&self, grid: &Grid2, rotation: f64, out: &mut [f64]) -> Result<()> {
        check_len(grid, out)?;
        let (s, c) = rotation.sin_cos();
        let n = self.contact.normal;
        let (ex, ey) = (self.ex.into_inner(), self.ey.into_inner());
        let half = [
            0.5 * grid.nx() as f64 * grid.dx(),
            0.5 * grid.ny() as f64 * grid.dy(),
        ];
        // Rays start this far on either side of the plane: beyond the sag of any surface
        // over the grid (the sag of a convex arc never exceeds its chord).
        let reach = 2.0 * (half[0].hypot(half[1]) + grid.x(0).abs().max(grid.y(0).abs()))
            + self.contact.separation.abs()
            + 1e-3;
        let up = Unit::new_unchecked(n.into_inner());
        let down = Unit::new_unchecked(-n.into_inner());
        let (mut t1_row, mut t2_row) = (reach, reach);
        for j in 0..grid.ny() {
            let yp = grid.y(j);
            let (mut t1, mut t2) = (t1_row, t2_row);
            for i in 0..grid.nx() {
                let xp = grid.x(i);
                let (x, y) = (c * xp - s * yp, s * xp + c * yp);
                let q = self.contact.point + ex * x + ey * y;
                let r1 = Ray {
                    origin: q - up.into_inner() * reach,
                    dir: up,
                };
                let r2 = Ray {
                    origin: q + up.into_inner() * reach,
                    dir: down,
                };
                let h1 = self.body1.intersect_near(&r1, t1, 0.0, 2.0 * reach);
                let h2 = self.body2.intersect_near(&r2, t2, 0.0, 2.0 * reach);
                let g = match (h1, h2) {
                    (Some(a), Some(b)) => {
                        t1 = a;
                        t2 = b;
                        // g1 = a - reach, g2 = reach - b.
                        (a - reach) - (reach - b) - self.contact.separation
                    }
                    _ => f64::INFINITY,
                };
                if g.is_nan() {
                    return Err(Error::Geometry {
                        field: "surfaces".into(),
                        reason: format!("ray casting gave NaN at ({x}, {y}) mm"),
                    });
                }
                out[j * grid.nx() + i] = g;
                if i == 0 {
                    (t1_row, t2_row) = (t1, t2);
                }
            }
        }
        Ok(())
    }

    fn sample_points(
        &self,
        xs: &[f64],
        ys: &[f64],
        rotation: f64,
        out: &mut [f64],
        warm: &mut [[f64; 2]],
    ) -> Result<()> {
        if out.len() != xs.len() * ys.len() {
            return Err(Error::invalid(
                "out.len()",
                out.len(),
                "xs.len() * ys.len() points",
            ));
        }
        let warm_ok = warm.len() == out.len();
        let (s, c) = rotation.sin_cos();
        let far = |v: &[f64]| v.iter().fold(0.0f64, |m, a| m.max(a.abs()));
        let (fx, fy) = (far(xs), far(ys));
        // As in `sample`: beyond the sag of either surface over the points.
        let reach = 2.0 * (fx.hypot(fy) + fx.max(fy)) + self.contact.separation.abs() + 1e-3;
        let mut row_start = (reach, reach);
        // Every ray runs along ±n: its local directions once.
        let n = self.contact.normal.into_inner();
        let dirs = (
            self.body1.dir_to_local(&Unit::new_unchecked(n)),
            self.body2.dir_to_local(&Unit::new_unchecked(-n)),
        );
        for (l, &yp) in ys.iter().enumerate() {
            let mut t = row_start;
            for (k, &xp) in xs.iter().enumerate() {
                let idx = l * xs.len() + k;
                // The last call's hits, as heights over the plane, are the best guesses.
                if warm_ok && warm[idx][0].is_finite() && warm[idx][1].is_finite() {
                    t = (reach + warm[idx][0], reach - warm[idx][1]);
                }
                let g = self.cast(c * xp - s * yp, s * xp + c * yp, reach, &dirs, &mut t)?;
                out[idx] = g;
                if warm_ok {
                    warm[idx] = if g.is_finite() {
                        [t.0 - reach, reach - t.1]
                    } else {
                        [f64::INFINITY; 2]
                    };
                }
                if k == 0 {
                    row_start = t;
                }
            }
        }
        Ok(())
    }
}

impl SurfacePairGap {
    /// One gap value at the source-frame point `(x, y)` \[mm\], rays cast from `reach` on
    /// either side of the plane with the guesses `t` (updated to the hits); `dirs` the
    /// local images of `n` in body 1 and of `−n` in body 2.
    #[inline]
    fn cast(
        &self,
        x: f64,
        y: f64,
        reach: f64,
        dirs: &(Unit<Vector3<f64>>, Unit<Vector3<f64>>),
        t: &mut (f64, f64),
    ) -> Result<f64> {
        let n = self.contact.normal.into_inner();
        let q = self.contact.point + self.ex.into_inner() * x + self.ey.into_inner() * y;
        let h1 = self
            .body1
            .intersect_near_along(&(q - n * reach), &dirs.0, t.0, 0.0, 2.0 * reach);
        let h2 = self
            .body2
            .intersect_near_along(&(q + n * reach), &dirs.1, t.1, 0.0, 2.0 * reach);
        let g = match (h1, h2) {
            (Some(a), Some(b)) => {
                *t = (a, b);
                (a - reach) - (reach - b) - self.contact.separation
            }
            _ => f64::INFINITY,
        };
        if g.is_nan() {
            return Err(Error::Geometry {
                field: "surfaces".into(),
                reason: format!("ray casting gave NaN at ({x}, {y}) mm"),
            });
        }
        Ok(g)
    }
}

impl ContactFrame {
    /// The frame of a surface-pair gap: its contact point and axes `[x, y, z]`.
    pub fn of_gap(gap: &SurfacePairGap) -> Self {
        let [ex, ey, normal] = gap.axes();
        ContactFrame {
            origin: gap.contact().point,
            ex,
            ey,
            normal,
        }
    }
}
