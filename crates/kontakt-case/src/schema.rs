//! The JSON Schema of the case files ([`case_schema`]), derived from the serde types that
//! read them: the keys each table takes (`additionalProperties: false` where the reader
//! refuses unknown keys), the required ones, the defaults, the enumerations and the doc
//! comments with their units as descriptions.
//!
//! The schema follows the parser, not the other way round:
//! - the `method` key picks the schema ([`crate::Case::from_toml_str`]): the case schema is
//!   a `oneOf` with one branch per entry of [`crate::Case::METHODS`], each fixing `method`
//!   to its name (required, except for `"hertz"`, the default when `method` is absent);
//! - a `[bearing] boundary` generates the internal keys that it makes optional
//!   ([`crate::bearing_design`]).
//!
//! Draft 7 (widely read by validators and editors), in draft-4 words where it costs nothing
//! (`enum: [x]` for `const: x`): Taplo, the TOML language server of most editors, documents
//! draft 4; it ignores the one draft-7 rule (`if`/`then`, a tapered bearing's `e`).
//! JSON has no infinity: where a case file writes `inf` (a flat body's radius), a validator
//! that converts TOML to JSON has to stand in the largest finite number.

use crate::bearing_case::BearingCase;
use crate::case::{Case, CaseFile};
use crate::friction_case::FrictionCase;
use crate::impact_case::ImpactCase;
use crate::mindlin_case::MindlinCase;
use crate::pimp_case::PimpCase;
use crate::rough_case::RoughCase;
use crate::traction_case::TractionCase;
use schemars::transform::RecursiveTransform;
use schemars::{SchemaGenerator, generate::SchemaSettings};
use serde_json::{Value, json};

/// The schema of one method's case table, as a reference into the definitions.
fn method_schema(method: &str, generator: &mut SchemaGenerator) -> Option<schemars::Schema> {
    Some(match method {
        "hertz" => generator.subschema_for::<CaseFile>(),
        "pimp" | "bem" => generator.subschema_for::<PimpCase>(),
        "traction" => generator.subschema_for::<TractionCase>(),
        "friction" => generator.subschema_for::<FrictionCase>(),
        "mindlin" => generator.subschema_for::<MindlinCase>(),
        "impact" => generator.subschema_for::<ImpactCase>(),
        "rough" => generator.subschema_for::<RoughCase>(),
        "bearing" => generator.subschema_for::<BearingCase>(),
        _ => return None,
    })
}

/// The JSON Schema (draft 7) of a kontakt case file, as a JSON value: one branch per
/// `method` (`oneOf`), the tables' keys with their units in the descriptions. A TOML case
/// file converted to JSON validates against it exactly when the case reader takes its keys
/// and types (the ranges of the values are checked when the case runs).
///
/// The same schema is checked in as `docs/kontakt-case.schema.json` and printed by
/// `kontakt schema`.
pub fn case_schema() -> Value {
    let mut generator = SchemaSettings::draft07()
        .for_deserialize()
        .with_transform(RecursiveTransform(unescape_brackets))
        .with_transform(RecursiveTransform(const_as_enum))
        .into_generator();
    let branches: Vec<Value> = Case::METHODS
        .iter()
        .filter_map(|&method| {
            let schema = method_schema(method, &mut generator)?;
            let mut branch = json!({
                "title": format!("method = \"{method}\""),
                "allOf": [schema.to_value()],
                "properties": { "method": { "enum": [method] } },
            });
            // `method` absent reads as a Hertz case; every other method names itself.
            if method != "hertz" {
                branch["required"] = json!(["method"]);
            }
            Some(branch)
        })
        .collect();
    let definitions = generator.take_definitions(true);
    json!({
        "$schema": "http://json-schema.org/draft-07/schema#",
        "title": "kontakt case file",
        "description": format!(
            "A kontakt case (TOML), kontakt {}: the `method` key (default \"hertz\") picks \
             the schema. Units: lengths mm, forces N, stresses and moduli MPa, speeds mm/s \
             or r/min, angles degrees, as each key's suffix says. docs/case-schema.md",
            env!("CARGO_PKG_VERSION")
        ),
        "type": "object",
        "properties": {
            "method": {
                "description": "The method, which picks the case's schema (default \"hertz\").",
                "enum": Case::METHODS,
                "default": "hertz",
            }
        },
        "oneOf": branches,
        "definitions": definitions,
    })
}

/// `const: x` as `enum: [x]`, the same constraint in a form that draft-4 readers (Taplo's
/// completion) understand too.
fn const_as_enum(schema: &mut schemars::Schema) {
    if let Some(value) = schema.remove("const") {
        schema.insert("enum".into(), Value::Array(vec![value]));
    }
}

/// Doc comments escape the brackets of units for rustdoc (`\[mm\]`) and link items
/// (``[`Name`]``); a description shows them plain (`[mm]`, `` `Name` ``).
fn unescape_brackets(schema: &mut schemars::Schema) {
    if let Some(Value::String(d)) = schema.get_mut("description") {
        *d = d
            .replace("\\[", "[")
            .replace("\\]", "]")
            .replace("[`", "`")
            .replace("`]", "`");
    }
}
