//! What every schema shares: TOML parsing with errors that name the line, the schema
//! version of the reports, and the `[body1]`/`[body2]` material tables.

use kontakt::material::ElasticMaterial;
use kontakt::{Error, Result};
use serde::{Deserialize, Serialize};

/// Version of the JSON result schema.
pub const SCHEMA_VERSION: u32 = 1;

/// Parse TOML into `T`, turning parser errors into [`Error::InvalidInput`] with field
/// `case`, the line number and the parser's message.
pub(crate) fn parse_toml<T: serde::de::DeserializeOwned>(text: &str) -> Result<T> {
    toml::from_str(text).map_err(|e| {
        let location = e
            .span()
            .map(|s| {
                let line = text[..s.start.min(text.len())].matches('\n').count() + 1;
                format!(" at line {line}")
            })
            .unwrap_or_default();
        Error::invalid(
            "case",
            format!("TOML{location}: {}", e.message().trim()),
            "a case file following docs/case-schema.md",
        )
    })
}

/// `[body1]` / `[body2]`: the elastic constants.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSpec {
    /// Young's modulus \[MPa\], > 0.
    pub e_mpa: f64,
    /// Poisson's ratio, -1 < nu <= 0.5.
    pub nu: f64,
}

/// An elastic material from case-file values, errors named by their keys
/// (`body1.e_mpa`, `body2.nu`); shared by the Hertz and PimP schemas.
pub(crate) fn material_keys(e_mpa: f64, nu: f64, prefix: &str) -> Result<ElasticMaterial> {
    ElasticMaterial::new(e_mpa, nu).map_err(|e| {
        e.map_field(|f| {
            let key = match f {
                "youngs_modulus" => "e_mpa",
                "poisson_ratio" => "nu",
                other => other,
            };
            format!("{prefix}.{key}")
        })
    })
}

/// The material of a `[body1]`/`[body2]` table, errors named `{prefix}.e_mpa`, `{prefix}.nu`.
pub(crate) fn material(m: &MaterialSpec, prefix: &str) -> Result<ElasticMaterial> {
    material_keys(m.e_mpa, m.nu, prefix)
}
