//! The FMU's `modelDescription.xml` (FMI 2.0), written from the case and the variable
//! tables, and the GUID that ties the description, the case in `resources/` and the
//! binary together.

use crate::model::{Kind, Model};
use crate::variables::UNITS;
use kontakt::Result;
use std::fmt::Write as _;

/// The model identifier: the binary is `binaries/<platform>/kontakt_fmi.<so|dylib|dll>`.
pub const MODEL_IDENTIFIER: &str = "kontakt_fmi";

/// The log categories (`fmi2SetDebugLogging`) and what they carry.
pub const LOG_CATEGORIES: &[(&str, &str)] = &[
    (
        "logStatusWarning",
        "calls that return fmi2Warning (always logged)",
    ),
    (
        "logStatusDiscard",
        "calls that return fmi2Discard: a state beyond the model's validity (always logged)",
    ),
    (
        "logStatusError",
        "calls that return fmi2Error: bad input, an illegal call (always logged)",
    ),
    (
        "logStatusFatal",
        "calls that return fmi2Fatal (always logged)",
    ),
    ("logAll", "every call (with loggingOn)"),
];

/// The GUID of the FMU of a case: FNV-1a (128 bits) of the kontakt version and the case
/// text. `fmi2Instantiate` recomputes it from `resources/case.toml` and refuses a
/// model description that does not match.
pub fn guid(case: &str) -> String {
    let mut h: u128 = 0x6c62272e07bb014262b821756295c58d;
    let prime: u128 = 0x0000000001000000000000000000013B;
    for b in concat!("kontakt-fmi ", env!("CARGO_PKG_VERSION"), "\n")
        .bytes()
        .chain(case.bytes())
    {
        h ^= u128::from(b);
        h = h.wrapping_mul(prime);
    }
    let x = format!("{h:032x}");
    format!(
        "{{{}-{}-{}-{}-{}}}",
        &x[0..8],
        &x[8..12],
        &x[12..16],
        &x[16..20],
        &x[20..32]
    )
}

/// `text` with the XML special characters escaped, for an attribute value.
fn escape(text: &str) -> String {
    let mut s = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => s.push_str("&amp;"),
            '<' => s.push_str("&lt;"),
            '>' => s.push_str("&gt;"),
            '"' => s.push_str("&quot;"),
            '\'' => s.push_str("&apos;"),
            c if c.is_control() => s.push(' '),
            c => s.push(c),
        }
    }
    s
}

/// A real as the XML takes it (shortest round-trip form).
fn real(x: f64) -> String {
    format!("{x:?}")
}

/// The model description of the FMU of a case text (a bearing case or an element case)
/// and which element it is: the element is planned, so a bad case fails here with its
/// key named.
///
/// # Errors
/// Those of [`Model::from_case`].
pub fn model_description(case: &str) -> Result<(String, Kind)> {
    let model = Model::from_case(case)?;
    let name = case
        .parse::<toml::Table>()
        .ok()
        .and_then(|t| t.get("name").and_then(|n| n.as_str().map(str::to_string)));
    let (kind, what) = match model.kind() {
        Kind::Bearing => (
            "bearing",
            "kontakt bearing element: the inner ring's displacement and velocity relative to the outer ring in, the bearing's reaction on the inner ring out",
        ),
        Kind::Contact => (
            "contact",
            "kontakt contact element: the two bodies' poses and twists in, force, moments, friction and the contact point out",
        ),
    };
    let model_name = match &name {
        Some(n) => format!("kontakt {kind}: {n}"),
        None => format!("kontakt {kind}"),
    };
    let mut x = String::new();
    let w = &mut x;
    // writing to a String cannot fail
    let _ = writeln!(w, r#"<?xml version="1.0" encoding="UTF-8"?>"#);
    let _ = writeln!(
        w,
        r#"<fmiModelDescription fmiVersion="2.0" modelName="{}" guid="{}" description="{}" author="kontakt developers" version="{}" license="MIT OR Apache-2.0" generationTool="kontakt {}" variableNamingConvention="structured" numberOfEventIndicators="0">"#,
        escape(&model_name),
        guid(case),
        escape(what),
        env!("CARGO_PKG_VERSION"),
        env!("CARGO_PKG_VERSION"),
    );
    let common = r#"canGetAndSetFMUstate="true" canSerializeFMUstate="false" providesDirectionalDerivative="true" canNotUseMemoryManagementFunctions="true""#;
    let _ = writeln!(
        w,
        r#"  <ModelExchange modelIdentifier="{MODEL_IDENTIFIER}" completedIntegratorStepNotNeeded="true" {common}/>"#
    );
    let _ = writeln!(
        w,
        r#"  <CoSimulation modelIdentifier="{MODEL_IDENTIFIER}" canHandleVariableCommunicationStepSize="true" canInterpolateInputs="false" maxOutputDerivativeOrder="0" {common}/>"#
    );
    let variables = model.variables();
    let _ = writeln!(w, "  <UnitDefinitions>");
    for (unit, [kg, m, s, rad], factor) in UNITS {
        if !variables.iter().any(|v| v.unit == Some(unit)) {
            continue;
        }
        let mut base = String::new();
        for (name, e) in [("kg", kg), ("m", m), ("s", s), ("rad", rad)] {
            if *e != 0 {
                let _ = write!(base, r#" {name}="{e}""#);
            }
        }
        if *factor != 1.0 {
            let _ = write!(base, r#" factor="{}""#, real(*factor));
        }
        let _ = writeln!(
            w,
            r#"    <Unit name="{}"><BaseUnit{base}/></Unit>"#,
            escape(unit)
        );
    }
    let _ = writeln!(w, "  </UnitDefinitions>");
    let _ = writeln!(w, "  <LogCategories>");
    for (name, description) in LOG_CATEGORIES {
        let _ = writeln!(
            w,
            r#"    <Category name="{name}" description="{}"/>"#,
            escape(description)
        );
    }
    let _ = writeln!(w, "  </LogCategories>");
    let _ = writeln!(
        w,
        r#"  <DefaultExperiment startTime="0.0" stopTime="1.0"/>"#
    );
    let _ = writeln!(w, "  <ModelVariables>");
    for (vr, v) in variables.iter().enumerate() {
        let attributes = match v.causality {
            "parameter" => r#"causality="parameter" variability="tunable" initial="exact""#,
            "input" => r#"causality="input" variability="continuous""#,
            _ => r#"causality="output" variability="continuous" initial="calculated""#,
        };
        let mut real_attributes = String::new();
        if let Some(unit) = v.unit {
            let _ = write!(real_attributes, r#" unit="{}""#, escape(unit));
        }
        if let Some(start) = v.start {
            let _ = write!(real_attributes, r#" start="{}""#, real(start));
        }
        let _ = writeln!(
            w,
            r#"    <ScalarVariable name="{}" valueReference="{vr}" description="{}" {attributes}><Real{real_attributes}/></ScalarVariable>"#,
            escape(v.name),
            escape(v.description),
        );
    }
    let _ = writeln!(w, "  </ModelVariables>");
    // Outputs depend on every input and parameter (direct feedthrough): no
    // `dependencies` attribute, which FMI 2.0 reads as "depends on all knowns".
    let outputs: Vec<usize> = variables
        .iter()
        .enumerate()
        .filter(|(_, v)| v.causality == "output")
        .map(|(i, _)| i + 1)
        .collect();
    let _ = writeln!(w, "  <ModelStructure>");
    for section in ["Outputs", "InitialUnknowns"] {
        let _ = writeln!(w, "    <{section}>");
        for index in &outputs {
            let _ = writeln!(w, r#"      <Unknown index="{index}"/>"#);
        }
        let _ = writeln!(w, "    </{section}>");
    }
    let _ = writeln!(w, "  </ModelStructure>");
    let _ = writeln!(w, "</fmiModelDescription>");
    Ok((x, model.kind()))
}
