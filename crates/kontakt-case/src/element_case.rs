//! Contact-element cases (`method = "element"`): the two surfaces of a
//! [`kontakt::element::ContactElement`], their materials, the normal-contact back-end,
//! the friction law, the film, damping and the validity limit, read from TOML.
//!
//! An element case is not a [`crate::Case`]: it describes an element that a multi-body code
//! evaluates at its own poses (the C API of `kontakt-capi`, docs/mbs.md), not a problem
//! with one answer. [`ElementCase::from_toml_str`] parses it, [`element_from_case`] plans
//! the element; errors name the case-file key (`element.cells`, `damping.ramp_mm`,
//! `friction.mu`, `geometry.body1.radius_mm`).
//!
//! ```toml
//! name = "roller end face on the rib"
//! method = "element"
//!
//! [geometry]                 # kind = "roller_rib": the face on body 1, the rib on body 2,
//! kind = "roller_rib"        # both bodies' frames = the bearing frame (the world at the
//! pairing = "torus-torus-14" # reference placement), as for method = "pimp"
//! # kind = "surfaces": [geometry.body1] / [geometry.body2] placed surfaces (shape,
//! # radius_mm, ..., origin_mm, axis), each in its own body's frame
//!
//! [body1]                    # optional, default steel (210 000 MPa, 0.3)
//! e_mpa = 210000.0
//! nu = 0.3
//!
//! [element]
//! backend = "pimp"           # "hertz" | "pimp" | "halfspace"
//! cells = [64, 64]           # optional, pimp and halfspace only
//! mode = "corrected"         # optional, pimp only: "corrected" or "published"
//! max_approach_ratio = 0.01  # optional: validity limit, fraction of the smallest radius
//!
//! [friction]                 # optional: the keys of the friction cases (default Coulomb 0.1)
//! mu = 0.1
//!
//! [film]                     # optional: the film the friction law sees (absent: dry)
//! thickness_mm = 0.0002
//! lambda = 1.0
//! viscosity_mpa_s = 2e-8
//! alpha_per_mpa = 0.02
//!
//! [damping]                  # optional
//! coefficient_n_s_per_mm = 2.0
//! ramp_mm = 0.001
//! ```

use crate::common::{MaterialSpec, material, parse_toml};
use crate::friction_case::FrictionSpec;
use crate::pimp_case::{GeometrySpec, roller_rib_from_spec};
use kontakt::element::{Backend, ContactElement, Damping, ElementSpec};
use kontakt::friction::FilmState;
use kontakt::geometry::PlacedSurface;
use kontakt::halfspace::BemOptions;
use kontakt::material::ElasticMaterial;
use kontakt::pimp::{Mode, PimpOptions};
use kontakt::{Error, Result};
use serde::{Deserialize, Serialize};

/// An element case, as read from TOML.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ElementCase {
    /// Optional label.
    #[serde(default)]
    pub name: Option<String>,
    /// Must be `"element"`.
    pub method: String,
    /// The two surfaces: kind `roller_rib` or `surfaces`.
    pub geometry: GeometrySpec,
    /// Body 1 material (default steel).
    #[serde(default)]
    pub body1: Option<MaterialSpec>,
    /// Body 2 material (default steel).
    #[serde(default)]
    pub body2: Option<MaterialSpec>,
    /// The back-end and the validity limit.
    pub element: ElementOptionsSpec,
    /// The friction law (the keys of the friction cases).
    #[serde(default)]
    pub friction: FrictionSpec,
    /// The film the friction law sees; absent: dry.
    #[serde(default)]
    pub film: Option<FilmSpec>,
    /// Optional normal damping.
    #[serde(default)]
    pub damping: Option<DampingSpec>,
}

/// Names of the back-ends.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum BackendName {
    /// Hertz at the contact point's relative curvature.
    Hertz,
    /// PimP.
    Pimp,
    /// The coupled elastic half-space solver.
    Halfspace,
}

/// `[element]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ElementOptionsSpec {
    /// The normal-contact back-end.
    pub backend: BackendName,
    /// Grid cells `[nx, ny]` of PimP or the half-space solver (default 64 × 64).
    #[serde(default)]
    pub cells: Option<[usize; 2]>,
    /// PimP's bedding law (default corrected).
    #[serde(default)]
    pub mode: Option<Mode>,
    /// Validity limit of the approach, a fraction of the smallest relative radius of
    /// curvature (default 0.01).
    #[serde(default)]
    pub max_approach_ratio: Option<f64>,
}

/// `[film]`: the lubricant film of the friction law.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct FilmSpec {
    /// Film thickness \[mm\], ≥ 0.
    pub thickness_mm: f64,
    /// Film parameter Λ, ≥ 0.
    pub lambda: f64,
    /// Viscosity at zero pressure \[MPa·s\], > 0.
    pub viscosity_mpa_s: f64,
    /// Pressure-viscosity coefficient \[1/MPa\], ≥ 0.
    pub alpha_per_mpa: f64,
}

/// `[damping]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct DampingSpec {
    /// Full damping coefficient \[N·s/mm\], ≥ 0.
    pub coefficient_n_s_per_mm: f64,
    /// Approach over which the damping switches on \[mm\], > 0.
    pub ramp_mm: f64,
}

impl ElementCase {
    /// Parse an element case from TOML text (unknown keys refused).
    ///
    /// # Errors
    /// [`Error::CaseFile`] (line, key path, what the schema takes) for malformed TOML,
    /// unknown keys or wrong types;
    /// [`Error::InvalidInput`] with field `method` when it is not `"element"`.
    pub fn from_toml_str(text: &str) -> Result<Self> {
        let case: ElementCase = parse_toml(text)?;
        if case.method != "element" {
            return Err(Error::invalid(
                "method",
                &case.method,
                "\"element\" for this schema",
            ));
        }
        Ok(case)
    }

    /// The element's specification, errors named by their case-file keys.
    ///
    /// # Errors
    /// As [`element_from_case`], except the back-end's and the film's checks, which the
    /// element makes when it is planned.
    pub fn spec(&self) -> Result<ElementSpec> {
        if self.method != "element" {
            return Err(Error::invalid(
                "method",
                &self.method,
                "\"element\" for this schema",
            ));
        }
        let (surface1, surface2) = surfaces(&self.geometry)?;
        let material_of = |m: &Option<MaterialSpec>, prefix: &str| match m {
            Some(m) => material(m, prefix),
            None => Ok(ElasticMaterial::STEEL),
        };
        let material1 = material_of(&self.body1, "body1")?;
        let material2 = material_of(&self.body2, "body2")?;
        let e = &self.element;
        if e.mode.is_some() && e.backend != BackendName::Pimp {
            return Err(Error::invalid(
                "element.mode",
                "given",
                "mode only with backend = \"pimp\"",
            ));
        }
        if e.cells.is_some() && e.backend == BackendName::Hertz {
            return Err(Error::invalid(
                "element.cells",
                "given",
                "cells only with backend = \"pimp\" or \"halfspace\"",
            ));
        }
        let backend = match e.backend {
            BackendName::Hertz => Backend::Hertz,
            BackendName::Pimp => {
                let d = PimpOptions::default();
                Backend::Pimp(PimpOptions {
                    mode: e.mode.unwrap_or(d.mode),
                    cells: e.cells.unwrap_or(d.cells),
                    ..d
                })
            }
            BackendName::Halfspace => {
                let d = BemOptions::default();
                Backend::HalfSpace(BemOptions {
                    cells: e.cells.unwrap_or(d.cells),
                    ..d
                })
            }
        };
        let film = match self.film {
            Some(f) => FilmState::new(f.thickness_mm, f.lambda, f.viscosity_mpa_s, f.alpha_per_mpa)
                .map_err(map_film)?,
            None => FilmState::dry(),
        };
        let friction = self.friction.law(self.film.is_some())?;
        let mut spec = ElementSpec::new(surface1, surface2)?;
        spec.material1 = material1;
        spec.material2 = material2;
        spec.backend = backend;
        spec.friction = friction;
        spec.film = film;
        spec.damping = self.damping.map(|d| Damping {
            coefficient: d.coefficient_n_s_per_mm,
            ramp: d.ramp_mm,
        });
        if let Some(r) = e.max_approach_ratio {
            spec.max_approach_ratio = r;
        }
        Ok(spec)
    }
}

fn map_film(e: Error) -> Error {
    e.map_field(|f| {
        let key = match f {
            "thickness" => "thickness_mm",
            "viscosity" => "viscosity_mpa_s",
            "alpha" => "alpha_per_mpa",
            other => other,
        };
        format!("film.{key}")
    })
}

/// The surfaces of body 1 and body 2, each in its body's frame.
fn surfaces(geometry: &GeometrySpec) -> Result<(PlacedSurface, PlacedSurface)> {
    match geometry {
        g @ GeometrySpec::RollerRib { .. } => {
            let (_, pair) = roller_rib_from_spec(g)?.ok_or_else(|| {
                Error::invalid("geometry.kind", "roller_rib", "a roller/rib geometry")
            })?;
            Ok((pair.face, pair.rib))
        }
        GeometrySpec::Surfaces {
            body1,
            body2,
            guess_mm,
        } => {
            if guess_mm.is_some() {
                return Err(Error::invalid(
                    "geometry.guess_mm",
                    "given",
                    "no guess for an element (each evaluation starts from the last contact point)",
                ));
            }
            Ok((
                body1.build("geometry.body1")?,
                body2.build("geometry.body2")?,
            ))
        }
        GeometrySpec::Hertz { .. } => Err(Error::invalid(
            "geometry.kind",
            "hertz",
            "roller_rib or surfaces (an element needs placed surfaces)",
        )),
        GeometrySpec::Map { .. } => Err(Error::invalid(
            "geometry.kind",
            "map",
            "roller_rib or surfaces (an element needs placed surfaces)",
        )),
    }
}

/// Plan the element of a case.
///
/// # Errors
/// [`Error::InvalidInput`] named by its case-file key: `method`, `geometry.*` (an unknown
/// pairing, a bad surface, kind `hertz` or `map`), `body1.*`/`body2.*`, `element.cells`,
/// `element.mode`, `element.max_approach_ratio`, `friction.*`, `film.*`,
/// `damping.coefficient_n_s_per_mm`, `damping.ramp_mm`.
pub fn element_from_case(case: &ElementCase) -> Result<ContactElement> {
    let spec = case.spec()?;
    ContactElement::new(spec).map_err(|e| {
        e.map_field(|f| match f {
            "damping.coefficient" => "damping.coefficient_n_s_per_mm".into(),
            "damping.ramp" => "damping.ramp_mm".into(),
            "max_approach_ratio" => "element.max_approach_ratio".into(),
            "cells[0]" => "element.cells[0]".into(),
            "cells[1]" => "element.cells[1]".into(),
            "thickness" => "film.thickness_mm".into(),
            "lambda" => "film.lambda".into(),
            "viscosity" => "film.viscosity_mpa_s".into(),
            "alpha" => "film.alpha_per_mpa".into(),
            other => other.into(),
        })
    })
}

/// Parse an element case from TOML text and plan its element.
///
/// # Errors
/// Those of [`ElementCase::from_toml_str`] and [`element_from_case`].
pub fn element_from_toml(text: &str) -> Result<ContactElement> {
    element_from_case(&ElementCase::from_toml_str(text)?)
}
