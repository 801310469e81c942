//! `[bearing] roller_model = "rib_contact"`: a tapered roller bearing whose rollers are each
//! in their own force and moment balance, with the roller end/rib contact as a Hertz point
//! contact (`kontakt_bearing::roller_equilibrium`, `docs/bearing-model.md` §15). The pair is
//! given in the vocabulary of the rib study (`examples/rib_friction.toml`,
//! `examples/roller_rib_custom_bearing.toml`):
//!
//! ```toml
//! [bearing]
//! type = "tapered"
//! roller_model = "rib_contact"     # default "iso"
//! # ...
//! [bearing.rib_contact]
//! pairing = "sphere-torus-57"      # a pairing of Wirsching et al. (2020) Table 1, or:
//! # face = { shape = "sphere", radius_mm = 57.0 }
//! # rib = { shape = "torus", radius_mm = 30.0 }
//! contact_height_mm = 2.75         # above the roller axis; default 2.75 with a pairing
//! model = "pimp"                   # the rib's force law: "hertz" (default) or "pimp"
//! ```
//!
//! The rib normal then follows from the face and the contact height; a `rib_angle_deg`
//! given as well must agree with it (1e-8 rad). Units: mm, N, MPa, rad.

use kontakt::bearing::{CONTACT_HEIGHT, FaceShape, RibShape, RollerRibSpec};
use kontakt::{Error, Result};
use kontakt_bearing::geometry::RollerBearing;
use kontakt_bearing::roller_equilibrium::{
    CylindricalRibs, RibArrangement, RibContact, RibContactSolver, RibModel, RibTableRange,
};
use serde::{Deserialize, Serialize};

/// `bearing.roller_model`: how a tapered roller is held.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize, schemars::JsonSchema,
)]
#[serde(rename_all = "snake_case")]
pub enum RollerModel {
    /// The ISO/TS 16281 slice law of both raceway contacts in series (the default).
    #[default]
    Iso,
    /// Every roller in its own force and moment balance with a Hertz rib contact.
    RibContact,
}

impl RollerModel {
    pub(crate) fn is_iso(&self) -> bool {
        *self == RollerModel::Iso
    }
}

/// `[bearing.rib_contact]`: the roller's large-end face and the cone's rib, by a built-in
/// pairing or by `face` and `rib`, and the contact height (mm).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RibContactSpec {
    /// A built-in pairing of Wirsching et al. (2020) Table 1 (`"sphere-torus-57"`, ...), or
    /// none with `face` and `rib`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pairing: Option<String>,
    /// The roller's end face: `{ shape = "sphere", radius_mm }` or
    /// `{ shape = "torus", radius_mm, eccentricity_mm }`, mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub face: Option<FaceShape>,
    /// The rib: `{ shape = "cone" }` or `{ shape = "torus", radius_mm }`, mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rib: Option<RibShape>,
    /// Distance of the contact point from the roller axis, mm; tapered: default 2.75 (the
    /// rib study's) with a pairing, required with `face` and `rib`; cylindrical: required.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact_height_mm: Option<f64>,
    /// Cylindrical only (required there): which rings have ribs, `"nu"`, `"nj"`, `"nup"`
    /// or `"n"`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub arrangement: Option<ArrangementSpec>,
    /// Cylindrical only (required there): the roller end face's sphere radius r_R, mm
    /// (>= L_we/2).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub face_radius_mm: Option<f64>,
    /// Cylindrical only (required there): the roller's axial end play between the ribs of
    /// one ring, mm (>= 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub end_play_mm: Option<f64>,
    /// The rib contact's force law in the roller balance: `"hertz"` (default, closed form)
    /// or `"pimp"` (Wirsching et al. 2020, a load-approach curve tabulated once at plan
    /// time; tapered only). The rib pressure reported is the model's, MPa.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub model: Option<RibModelSpec>,
}

/// `bearing.rib_contact.model`: the rib contact's force law in the roller balance.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize, schemars::JsonSchema,
)]
#[serde(rename_all = "lowercase")]
pub enum RibModelSpec {
    /// Hertz's point contact at the contact point.
    #[default]
    Hertz,
    /// PimP, tabulated at plan time (docs/bearing-model.md §15.8).
    Pimp,
}

/// Give `solver` the rib law of `model` (Hertz: nothing to do); errors named
/// `bearing.rib_contact.model` (a cylindrical bearing; a pair PimP cannot solve).
fn set_model(solver: &mut RibContactSolver, model: Option<RibModelSpec>) -> Result<()> {
    if let Some(RibModelSpec::Pimp) = model {
        solver
            .set_rib_model(RibModel::Pimp, &RibTableRange::default())
            .map_err(|e| e.map_field(|f| format!("bearing.{f}")))?;
    }
    Ok(())
}

/// `bearing.rib_contact.arrangement` of a cylindrical roller bearing.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum ArrangementSpec {
    /// Ribs on the outer ring only: no axial load.
    Nu,
    /// Outer ring ribs at both ends, an inner ring rib at the −z end: axial load in +z.
    Nj,
    /// Ribs at both ends of both rings: axial load both ways.
    Nup,
    /// Ribs on the inner ring only: no axial load.
    N,
}

impl ArrangementSpec {
    fn library(self) -> RibArrangement {
        match self {
            ArrangementSpec::Nu => RibArrangement::Nu,
            ArrangementSpec::Nj => RibArrangement::Nj,
            ArrangementSpec::Nup => RibArrangement::Nup,
            ArrangementSpec::N => RibArrangement::N,
        }
    }
}

const KEY: &str = "bearing.rib_contact";

impl RibContactSpec {
    /// The library's pair: errors named by the case key.
    fn pair(&self) -> Result<RibContact> {
        let (face, rib, height) = match (&self.pairing, self.face, self.rib) {
            (Some(p), None, None) => {
                let spec = RollerRibSpec::builtin(p)
                    .map_err(|e| e.map_field(|_| format!("{KEY}.pairing")))?;
                (
                    spec.face,
                    spec.rib,
                    self.contact_height_mm.unwrap_or(CONTACT_HEIGHT),
                )
            }
            (None, Some(face), Some(rib)) => {
                let h = self.contact_height_mm.ok_or_else(|| Error::CaseFile {
                    line: None,
                    key: format!("{KEY}.contact_height_mm").into(),
                    message: format!(
                        "missing key `{KEY}.contact_height_mm`: with face and rib the contact height above the roller axis [mm] is required"
                    ),
                })?;
                (face, rib, h)
            }
            _ => {
                return Err(Error::invalid(
                    format!("{KEY}.pairing"),
                    self.pairing.as_deref().unwrap_or("none"),
                    "either `pairing` or both `face` and `rib`",
                ));
            }
        };
        Ok(RibContact {
            face,
            rib,
            contact_height_mm: height,
        })
    }
}

/// The solver of a `roller_model = "rib_contact"` bearing of type `label` (with the
/// `[bearing]` keys `roller_model`, `rib_contact`, `rib_angle_deg`), `None` for the ISO
/// model.
///
/// # Errors
/// `bearing.rib_contact` given with the ISO model; `bearing.roller_model` on a bearing that
/// is not tapered; `bearing.rib_contact` missing; the pair's and the solver's errors named
/// by their case keys (`bearing.rib_contact.contact_height_mm`, `bearing.rib_angle_deg`,
/// `bearing.slices`).
pub(crate) fn plan_rib(
    model: RollerModel,
    rib_contact: Option<&RibContactSpec>,
    rib_angle_deg: Option<f64>,
    label: &str,
    bearing: &RollerBearing,
) -> Result<Option<RibContactSolver>> {
    if model == RollerModel::Iso {
        if rib_contact.is_some() {
            return Err(Error::invalid(
                KEY,
                "given",
                "no [bearing.rib_contact] with roller_model = \"iso\" (the pair is used by roller_model = \"rib_contact\")",
            ));
        }
        return Ok(None);
    }
    if label != "tapered" && label != "cylindrical" {
        return Err(Error::invalid(
            "bearing.roller_model",
            "rib_contact",
            format!(
                "\"iso\" for type = \"{label}\": the rib-contact roller model is for tapered and cylindrical roller bearings"
            ),
        ));
    }
    let spec = rib_contact.ok_or_else(|| Error::CaseFile {
        line: None,
        key: KEY.into(),
        message: format!(
            "missing table `[{KEY}]`: roller_model = \"rib_contact\" needs the roller end/rib pair (pairing or face and rib)"
        ),
    })?;
    if label == "cylindrical" {
        let mut solver = cylindrical(spec, bearing)?;
        set_model(&mut solver, spec.model)?;
        return Ok(Some(solver));
    }
    for (key, given) in [
        ("arrangement", spec.arrangement.is_some()),
        ("face_radius_mm", spec.face_radius_mm.is_some()),
        ("end_play_mm", spec.end_play_mm.is_some()),
    ] {
        if given {
            return Err(Error::invalid(
                format!("{KEY}.{key}"),
                "given",
                "none for type = \"tapered\" (the key is for cylindrical roller bearings; a tapered roller's pair is `pairing` or `face` and `rib`)",
            ));
        }
    }
    let pair = spec.pair()?;
    // the rib normal comes from the pair; a rib_angle_deg given as well must agree
    let mut free = bearing.clone();
    free.rib_angle_rad = None;
    let mut solver = RibContactSolver::new(free, pair).map_err(|e| {
        e.map_field(|f| match f.strip_prefix("rib_contact.") {
            Some(k) => format!("{KEY}.{k}"),
            None => format!("bearing.{f}"),
        })
    })?;
    let built = solver.rib_normal_angle();
    if let Some(given) = rib_angle_deg
        && !((given.to_radians() - built).abs() <= 1e-8)
    {
        return Err(Error::invalid(
            "bearing.rib_angle_deg",
            given,
            format!(
                "{:.9} deg (the rib normal of the roller end/rib pair, to 1e-8 rad) or no rib_angle_deg: with roller_model = \"rib_contact\" the face and the contact height set it",
                built.to_degrees()
            ),
        ));
    }
    set_model(&mut solver, spec.model)?;
    Ok(Some(solver))
}

/// The solver of a cylindrical roller bearing with ribs: errors named by the case key.
fn cylindrical(spec: &RibContactSpec, bearing: &RollerBearing) -> Result<RibContactSolver> {
    let missing = |key: &str, what: &str| Error::CaseFile {
        line: None,
        key: format!("{KEY}.{key}").into(),
        message: format!(
            "missing key `{KEY}.{key}`: a cylindrical roller bearing's rib contacts need {what}"
        ),
    };
    for (key, given) in [
        ("pairing", spec.pairing.is_some()),
        ("face", spec.face.is_some()),
        ("rib", spec.rib.is_some()),
    ] {
        if given {
            return Err(Error::invalid(
                format!("{KEY}.{key}"),
                "given",
                "none for type = \"cylindrical\" (its ribs are `arrangement`, `face_radius_mm`, `contact_height_mm`, `end_play_mm`)",
            ));
        }
    }
    let arrangement = spec.arrangement.ok_or_else(|| {
        missing(
            "arrangement",
            "the rib arrangement, \"nu\", \"nj\", \"nup\" or \"n\"",
        )
    })?;
    let ribs = CylindricalRibs {
        face_radius_mm: spec
            .face_radius_mm
            .ok_or_else(|| missing("face_radius_mm", "the roller end face's sphere radius [mm]"))?,
        contact_height_mm: spec.contact_height_mm.ok_or_else(|| {
            missing(
                "contact_height_mm",
                "the height of the contact above the roller axis [mm]",
            )
        })?,
        end_play_mm: spec
            .end_play_mm
            .ok_or_else(|| missing("end_play_mm", "the roller's axial end play [mm]"))?,
    };
    RibContactSolver::cylindrical(bearing.clone(), arrangement.library(), ribs).map_err(|e| {
        e.map_field(|f| match f.strip_prefix("ribs.") {
            Some(k) => format!("{KEY}.{k}"),
            None => format!("bearing.{f}"),
        })
    })
}
