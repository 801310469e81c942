//! The roller end face against the ring rib of a tapered roller bearing (Wirsching et al. (2020)
//! §2.1, Figure 2b, Table 1).
//!
//! Everything is built in the axial section plane (world `X`–`Z`, ring axis `Z`, `X`
//! radial) and then revolved: the rib is a cone or torus around the ring axis, the roller
//! face a sphere or torus around the roller axis. Construction (docs/bearing.md):
//!
//! 1. The inner raceway is a cone of half-angle `alpha_i` around `Z` with its apex `P0`
//!    on the axis; the roller's apex coincides with it (true rolling), its axis `u` leaves
//!    the raceway generatrix at the roller half-angle `beta`.
//! 2. The roller face has radius `r_R` centred at distance `e` (eccentricity) from the
//!    roller axis, on the side of the contact. The contact point lies at the distance `h`
//!    from the roller axis, so the face normal there leans from the axis by
//!    `phi = asin((h - e) / r_R)` towards the raceway.
//! 3. The rib touches the face at that point: its generatrix is perpendicular to the face
//!    normal, which fixes the rib angle `alpha = 90° + phi - beta` between raceway and
//!    rib. The rib cone contains that generatrix; the rib torus has its meridian arc of
//!    radius `r_B` tangent to it, centred inside the ring.
//! 4. The face position along the axis follows from the roller's large-end radius: the
//!    face meets the roller's conical side at the large-end edge.

use crate::error::{Error, Result, positive_as};
use crate::gap::SurfacePairGap;
use crate::geometry::contact_point::ContactPoint;
use crate::geometry::surface::{Material, PlacedSurface, Surface};
use crate::units::Millimetre;
use nalgebra::{Isometry3, Point3, Translation3, Unit, UnitQuaternion, Vector3};

/// A tapered roller bearing's section data needed for the roller/rib contact.
///
/// The default is a representative bearing of 60 mm bore and 110 mm outside diameter;
/// its internal data are representative values derived in docs/bearing.md, not a
/// manufacturer's drawing. The raceway angle follows from the condition of true rolling:
/// the roller's apex lies on the ring axis, so `sin(alpha_i) = r_i tan(beta) / rho_L`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct TaperedRollerBearing {
    /// Bore diameter d \[mm\]. Bore and outside diameter only check that the roller fits
    /// the section (`d/2 <` inner raceway radius, the large end's cup-side edge `< D/2`);
    /// no result depends on them.
    #[cfg_attr(feature = "serde", serde(rename = "bore_mm"))]
    pub bore: Millimetre,
    /// Outside diameter D \[mm\] (a check only, see `bore`).
    #[cfg_attr(feature = "serde", serde(rename = "outside_diameter_mm"))]
    pub outside_diameter: Millimetre,
    /// Half-angle of the roller cone, beta \[deg\].
    pub roller_half_angle_deg: f64,
    /// Radius of the roller's large end (where face and conical side meet) \[mm\].
    #[cfg_attr(feature = "serde", serde(rename = "roller_large_end_radius_mm"))]
    pub roller_large_end_radius: Millimetre,
    /// Radius of the inner raceway at the roller's large end, measured from the ring axis
    /// \[mm\] (sets how far the roller sits from the axis).
    #[cfg_attr(feature = "serde", serde(rename = "inner_raceway_radius_mm"))]
    pub inner_raceway_radius: Millimetre,
}

impl Default for TaperedRollerBearing {
    fn default() -> Self {
        TaperedRollerBearing {
            bore: 60.0,
            outside_diameter: 110.0,
            roller_half_angle_deg: 3.0,
            roller_large_end_radius: 5.5,
            inner_raceway_radius: 35.0,
        }
    }
}

/// The roller's end face.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(
    feature = "serde",
    serde(tag = "shape", rename_all = "snake_case", deny_unknown_fields)
)]
pub enum FaceShape {
    /// Spherical face of radius `radius` centred on the roller axis (e = 0).
    Sphere {
        /// Face radius r_R \[mm\].
        #[cfg_attr(feature = "serde", serde(rename = "radius_mm"))]
        radius: Millimetre,
    },
    /// Toroidal face: an arc of radius `radius` centred `eccentricity` from the axis.
    Torus {
        /// Face radius r_R \[mm\].
        #[cfg_attr(feature = "serde", serde(rename = "radius_mm"))]
        radius: Millimetre,
        /// Eccentricity e \[mm\], distance of the arc centre from the roller axis.
        #[cfg_attr(feature = "serde", serde(rename = "eccentricity_mm"))]
        eccentricity: Millimetre,
    },
}

/// The rib face of the inner ring.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(
    feature = "serde",
    serde(tag = "shape", rename_all = "snake_case", deny_unknown_fields)
)]
pub enum RibShape {
    /// Conical rib (straight generatrix, r_B = 0 in Table 1).
    Cone,
    /// Toroidal rib: the generatrix is an arc of radius `radius`, convex towards the
    /// roller (its centre lies inside the ring, on the face normal through the contact).
    Torus {
        /// Rib radius r_B \[mm\], > 0 (convex; a concave rib is not modelled and a negative
        /// radius is refused).
        #[cfg_attr(feature = "serde", serde(rename = "radius_mm"))]
        radius: Millimetre,
    },
}

/// One roller-face / rib pairing.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct RollerRibSpec {
    /// The bearing.
    #[cfg_attr(feature = "serde", serde(default))]
    pub bearing: TaperedRollerBearing,
    /// Roller end face.
    pub face: FaceShape,
    /// Rib.
    pub rib: RibShape,
    /// Distance of the contact point from the roller axis, h \[mm\] (the same for every
    /// pairing, as in the paper).
    #[cfg_attr(
        feature = "serde",
        serde(default = "default_contact_height", rename = "contact_height_mm")
    )]
    pub contact_height: Millimetre,
}

#[cfg(feature = "serde")]
fn default_contact_height() -> Millimetre {
    CONTACT_HEIGHT
}

/// Contact height h \[mm\] that reproduces the rib angles of Wirsching et al. (2020) Table 1 with
/// the roller half-angle of 3° (docs/bearing.md §2).
pub const CONTACT_HEIGHT: Millimetre = 2.75;

/// Forces of the paper's study \[N\]: 100 to 400 in steps of 50.
pub const STUDY_FORCES: [f64; 7] = [100.0, 150.0, 200.0, 250.0, 300.0, 350.0, 400.0];

/// The eight built-in pairings of Wirsching et al. (2020) Table 1: (name, face, rib, rib angle
/// printed in the table \[deg\]).
pub const TABLE1: [(&str, FaceShape, RibShape, f64); 8] = [
    (
        "sphere-cone-29",
        FaceShape::Sphere { radius: 29.0 },
        RibShape::Cone,
        92.0,
    ),
    (
        "sphere-cone-57",
        FaceShape::Sphere { radius: 57.0 },
        RibShape::Cone,
        90.0,
    ),
    (
        "sphere-torus-29",
        FaceShape::Sphere { radius: 29.0 },
        RibShape::Torus { radius: 30.0 },
        92.0,
    ),
    (
        "sphere-torus-57",
        FaceShape::Sphere { radius: 57.0 },
        RibShape::Torus { radius: 30.0 },
        90.0,
    ),
    (
        "torus-cone-14",
        FaceShape::Torus {
            radius: 14.0,
            eccentricity: 2.0,
        },
        RibShape::Cone,
        90.0,
    ),
    (
        "torus-cone-28",
        FaceShape::Torus {
            radius: 28.0,
            eccentricity: 2.0,
        },
        RibShape::Cone,
        89.0,
    ),
    (
        "torus-torus-14",
        FaceShape::Torus {
            radius: 14.0,
            eccentricity: 2.0,
        },
        RibShape::Torus { radius: 30.0 },
        90.0,
    ),
    (
        "torus-torus-28",
        FaceShape::Torus {
            radius: 28.0,
            eccentricity: 2.0,
        },
        RibShape::Torus { radius: 30.0 },
        89.0,
    ),
];

impl RollerRibSpec {
    /// The built-in pairing `name` (see [`TABLE1`]) on the default bearing.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] (field `pairing`) for an unknown name, listing the valid ones.
    pub fn builtin(name: &str) -> Result<Self> {
        TABLE1
            .iter()
            .find(|(n, ..)| *n == name)
            .map(|&(_, face, rib, _)| RollerRibSpec {
                bearing: TaperedRollerBearing::default(),
                face,
                rib,
                contact_height: CONTACT_HEIGHT,
            })
            .ok_or_else(|| {
                let names: Vec<&str> = TABLE1.iter().map(|t| t.0).collect();
                Error::invalid("pairing", name, format!("one of {}", names.join(", ")))
            })
    }

    /// The contact height h \[mm\] at which this spec's face meets a rib of angle
    /// `rib_angle_deg` \[deg\] between raceway and rib, as a drawing gives it (the contact
    /// height is then a result). The construction's step 3, `alpha = 90° + phi - beta` with
    /// the face normal's lean `phi = asin((h - e) / r_R)`, inverted:
    /// `h = e + r_R sin(alpha + beta - 90°) = e - r_R cos(alpha + beta)` (docs/bearing.md §3).
    /// Set it as `contact_height` to build the pair the drawing describes;
    /// [`RollerRib::rib_angle_deg`] of that pair is `rib_angle_deg` again.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `rib_angle_deg` unless the face normal's lean
    /// `alpha + beta - 90°` lies strictly between −90° and 90° and gives `h > 0`, or naming
    /// the face's radius or eccentricity or the roller half-angle when they are invalid.
    /// Whether the face reaches that height is checked by [`RollerRib::new`].
    pub fn contact_height_for_rib_angle(&self, rib_angle_deg: f64) -> Result<Millimetre> {
        let beta = angle(
            "bearing.roller_half_angle_deg",
            self.bearing.roller_half_angle_deg,
            0.0,
            20.0,
        )?;
        let (r_face, e) = match self.face {
            FaceShape::Sphere { radius } => (radius, 0.0),
            FaceShape::Torus {
                radius,
                eccentricity,
            } => (radius, eccentricity),
        };
        positive_as("face.radius", r_face, "a finite radius > 0 mm")?;
        if !(e.is_finite() && e >= 0.0) {
            return Err(Error::invalid(
                "face.eccentricity",
                e,
                "a finite eccentricity >= 0 mm",
            ));
        }
        let lo = 90.0 - beta.to_degrees() - 90.0;
        let hi = 90.0 - beta.to_degrees() + 90.0;
        let alpha = angle("rib_angle_deg", rib_angle_deg, lo, hi)?;
        let phi = alpha + beta - std::f64::consts::FRAC_PI_2;
        let h = e + r_face * phi.sin();
        if !(h > 0.0) {
            return Err(Error::invalid(
                "rib_angle_deg",
                rib_angle_deg,
                format!(
                    "a rib angle that puts the contact above the roller axis (it gives a contact \
                     height of {h:.4} mm; the angle must exceed {:.3} degrees for this face)",
                    (90.0f64.to_radians() - beta - (e / r_face).min(1.0).asin()).to_degrees()
                ),
            ));
        }
        Ok(h)
    }
}

/// A built roller/rib pair: the two placed surfaces and the idealised contact point.
#[derive(Debug, Clone, PartialEq)]
pub struct RollerRib {
    /// The specification it was built from.
    pub spec: RollerRibSpec,
    /// Roller end face (body 1), placed in the bearing frame.
    pub face: PlacedSurface,
    /// Rib (body 2), placed in the bearing frame.
    pub rib: PlacedSurface,
    /// Idealised contact point in the axial section plane; normal from rib into roller.
    pub contact: ContactPoint,
    /// Rib angle alpha between raceway and rib \[deg\] that puts the contact at `h`.
    pub rib_angle_deg: f64,
    /// Inclination phi of the face normal at the contact to the roller axis \[deg\].
    pub face_normal_angle_deg: f64,
    /// Unit vector of the roller axis (towards the large end).
    pub roller_axis: Unit<Vector3<f64>>,
    /// Point where the roller axis crosses the ring axis (the common apex) \[mm\].
    pub apex: Point3<f64>,
    /// Half-angle of the inner raceway cone alpha_i \[deg\]; the cup angle is
    /// `alpha_i + 2 beta`.
    pub raceway_angle_deg: f64,
}

impl RollerRib {
    /// Build the pair.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a non-positive or non-finite dimension, an angle out
    /// of range, a contact height the face cannot reach (`|h - e| >= r_R`, or `h` beyond
    /// the roller's large-end radius), or a roller that does not fit between the bore and
    /// the outside diameter.
    pub fn new(spec: RollerRibSpec) -> Result<Self> {
        let b = spec.bearing;
        positive_as("bearing.bore", b.bore, "a finite diameter > 0 mm")?;
        if !(b.outside_diameter > b.bore && b.outside_diameter.is_finite()) {
            return Err(Error::invalid(
                "bearing.outside_diameter",
                b.outside_diameter,
                "a finite diameter > bore in mm",
            ));
        }
        let beta = angle(
            "bearing.roller_half_angle_deg",
            b.roller_half_angle_deg,
            0.0,
            20.0,
        )?;
        let rho_l = positive_as(
            "bearing.roller_large_end_radius",
            b.roller_large_end_radius,
            "a finite radius > 0 mm",
        )?;
        let r_race = b.inner_raceway_radius;
        if !(r_race > 0.5 * b.bore && r_race < 0.5 * b.outside_diameter) {
            return Err(Error::invalid(
                "bearing.inner_raceway_radius",
                r_race,
                "between bore/2 and outside_diameter/2 in mm",
            ));
        }
        // True rolling: the roller apex on the ring axis.
        let sin_alpha_i = r_race * beta.tan() / rho_l;
        if !(sin_alpha_i < 0.9) {
            return Err(Error::invalid(
                "bearing.roller_large_end_radius",
                rho_l,
                format!(
                    "more than {:.3} mm: with the roller apex on the ring axis the raceway \
                     angle asin(r_i tan(beta) / rho_L) must stay below 64 degrees",
                    r_race * beta.tan() / 0.9
                ),
            ));
        }
        let alpha_i = sin_alpha_i.asin();
        let h = positive_as(
            "contact_height",
            spec.contact_height,
            "a finite height > 0 mm",
        )?;
        if h >= rho_l {
            return Err(Error::invalid(
                "contact_height",
                h,
                format!("less than the roller's large-end radius {rho_l} mm"),
            ));
        }
        let (r_face, e) = match spec.face {
            FaceShape::Sphere { radius } => (
                positive_as("face.radius", radius, "a finite radius > 0 mm")?,
                0.0,
            ),
            FaceShape::Torus {
                radius,
                eccentricity,
            } => {
                let r = positive_as("face.radius", radius, "a finite radius > 0 mm")?;
                if !(eccentricity.is_finite() && eccentricity >= 0.0 && eccentricity < h) {
                    return Err(Error::invalid(
                        "face.eccentricity",
                        eccentricity,
                        format!("0 <= e < contact_height = {h} mm"),
                    ));
                }
                (r, eccentricity)
            }
        };
        if !((h - e) < r_face) {
            return Err(Error::invalid(
                "face.radius",
                r_face,
                format!("larger than contact_height - eccentricity = {} mm", h - e),
            ));
        }
        let phi = ((h - e) / r_face).asin();
        if !(rho_l - e < r_face) {
            return Err(Error::invalid(
                "face.radius",
                r_face,
                format!(
                    "larger than the large-end radius - eccentricity = {} mm (the face must reach \
                     the roller's edge)",
                    rho_l - e
                ),
            ));
        }

        // Section plane X-Z (Y = 0); t: raceway generatrix towards the large end,
        // n: raceway normal into the roller; u: roller axis; v: perpendicular to u away
        // from the raceway.
        let t = Vector3::new(alpha_i.sin(), 0.0, alpha_i.cos());
        let n = Vector3::new(alpha_i.cos(), 0.0, -alpha_i.sin());
        let u = t * beta.cos() + n * beta.sin();
        let v = -t * beta.sin() + n * beta.cos();
        // Raceway apex on the ring axis: the raceway point at radius r_race is at axial
        // distance r_race / sin(alpha_i) from it along t.
        let large_end = Point3::new(r_race, 0.0, 0.0);
        let apex = large_end - t * (r_race / alpha_i.sin());
        // Roller frame: axial coordinate lambda from the apex along u.
        let lambda_edge = rho_l / beta.tan();
        // The roller must fit the section: its large end's outer edge (on the cup side)
        // inside the outside diameter. Bore and outside diameter enter nothing else.
        let outer_edge = apex + u * lambda_edge + v * rho_l;
        let outer_radius = outer_edge.x.hypot(outer_edge.y);
        if !(outer_radius < 0.5 * b.outside_diameter) {
            return Err(Error::invalid(
                "bearing.outside_diameter",
                b.outside_diameter,
                format!(
                    "more than twice the radius of the roller's large end at the cup \
                     ({outer_radius:.3} mm): the roller must fit inside the outside diameter"
                ),
            ));
        }
        let lambda_face = lambda_edge - (r_face * r_face - (rho_l - e).powi(2)).sqrt();
        let lambda_c = lambda_face + r_face * phi.cos();
        let contact = apex + u * lambda_c - v * h;
        // Face normal at the contact (outward from the roller, into the rib).
        let m = u * phi.cos() - v * phi.sin();
        let rib_angle = std::f64::consts::FRAC_PI_2 + phi - beta;

        let face_centre_on_axis = apex + u * lambda_face;
        let face = match spec.face {
            FaceShape::Sphere { .. } => PlacedSurface::new(
                Surface::sphere(r_face, Material::Inside).map_err(prefix("face"))?,
                Isometry3::from_parts(
                    Translation3::from(face_centre_on_axis.coords),
                    UnitQuaternion::identity(),
                ),
            )?,
            FaceShape::Torus { .. } => PlacedSurface::new(
                Surface::torus(e, r_face, Material::Inside).map_err(prefix("face"))?,
                frame_along(face_centre_on_axis, &Unit::new_normalize(u)),
            )?,
        };

        // Rib generatrix direction (perpendicular to m in the section plane).
        let w = Vector3::new(-m.z, 0.0, m.x);
        let rib = match spec.rib {
            RibShape::Cone => {
                // Apex of the rib cone: where the generatrix through the contact meets Z.
                if w.x.abs() < 1e-12 {
                    return Err(Error::Geometry {
                        field: "rib".into(),
                        reason: "the rib generatrix is parallel to the ring axis: a cylinder, not a cone"
                            .into(),
                    });
                }
                let s = -contact.x / w.x;
                let cone_apex = contact + w * s;
                // The nappe opens from the apex towards the contact.
                let axis = Vector3::new(0.0, 0.0, (contact.z - cone_apex.z).signum());
                let generatrix = (contact - cone_apex).normalize();
                let half_angle = generatrix.dot(&axis).clamp(-1.0, 1.0).acos();
                // Ring material lies along +m from the contact: inside the nappe when that
                // point is closer to the cone axis (smaller angle).
                let probe = contact + m * 1e-3 - cone_apex;
                let inside = probe.normalize().dot(&axis).acos() < half_angle;
                let material = if inside {
                    Material::Inside
                } else {
                    Material::Outside
                };
                PlacedSurface::new(
                    Surface::cone(half_angle, material).map_err(prefix("rib"))?,
                    frame_along(cone_apex, &Unit::new_normalize(axis)),
                )?
            }
            RibShape::Torus { radius } => {
                let r_b = positive_as("rib.radius", radius, "a finite radius > 0 mm")?;
                let centre = contact + m * r_b;
                let major = centre.x.hypot(centre.y);
                if !(major > r_b) {
                    return Err(Error::invalid(
                        "rib.radius",
                        r_b,
                        format!(
                            "smaller than the distance of its centre from the ring axis ({major:.3} mm)"
                        ),
                    ));
                }
                PlacedSurface::new(
                    Surface::torus(major, r_b, Material::Inside).map_err(prefix("rib"))?,
                    Isometry3::translation(0.0, 0.0, centre.z),
                )?
            }
        };
        let normal = Unit::new_normalize(-m);
        Ok(RollerRib {
            spec,
            face,
            rib,
            contact: ContactPoint {
                point1: contact,
                point2: contact,
                point: contact,
                normal,
                separation: 0.0,
            },
            rib_angle_deg: rib_angle.to_degrees(),
            face_normal_angle_deg: phi.to_degrees(),
            roller_axis: Unit::new_normalize(u),
            apex,
            raceway_angle_deg: alpha_i.to_degrees(),
        })
    }
}

impl RollerRib {
    /// The substitute geometry of the pair: the face (body 1) and the rib (body 2) at the
    /// idealised contact point, with the face's edge at the roller's large end (radius
    /// `bearing.roller_large_end_radius` from the roller axis) known to the size check
    /// ([`crate::field::validity`]). The rib's height is not part of the bearing data and
    /// is not checked.
    ///
    /// # Errors
    /// Those of [`SurfacePairGap::new`].
    pub fn gap(&self) -> Result<SurfacePairGap> {
        let mut gap = SurfacePairGap::new(self.face.clone(), self.rib.clone(), self.contact)?;
        let u = self.roller_axis.into_inner();
        let from_axis = self.contact.point1 - self.apex;
        let radial = from_axis - u * from_axis.dot(&u);
        gap.add_edge(
            0,
            radial,
            self.spec.bearing.roller_large_end_radius - radial.norm(),
            "bearing.roller_large_end_radius",
            "the roller's large end (the edge of its end face)",
        );
        Ok(gap)
    }
}

/// An angle in degrees, validated to lie in (lo, hi), returned in radians.
fn angle(field: &'static str, deg: f64, lo: f64, hi: f64) -> Result<f64> {
    if deg.is_finite() && deg > lo && deg < hi {
        Ok(deg.to_radians())
    } else {
        Err(Error::invalid(
            field,
            deg,
            format!("{lo} < angle < {hi} degrees"),
        ))
    }
}

/// A rigid frame with origin `origin` whose local z axis is `axis` (the pose of a surface
/// of revolution; the turn about the axis is irrelevant).
pub fn frame_along(origin: Point3<f64>, axis: &Unit<Vector3<f64>>) -> Isometry3<f64> {
    let rotation = UnitQuaternion::rotation_between(&Vector3::z(), axis).unwrap_or_else(|| {
        UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI)
    });
    Isometry3::from_parts(Translation3::from(origin.coords), rotation)
}

fn prefix(body: &'static str) -> impl Fn(Error) -> Error {
    move |e| e.map_field(|f| format!("{body}.{f}"))
}
