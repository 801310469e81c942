//! The element behind an FMU instance: planned from the case in the FMU's `resources/`,
//! evaluated at the inputs, its parameters tuned, its outputs' directional derivatives.
//! A thin layer over [`BearingElement`] and [`ContactElement`]; the variables are the
//! tables of [`crate::variables`].

use crate::variables::{
    BEARING_ARGUMENTS, BEARING_INPUTS, BEARING_OUTPUTS, BEARING_PARAMETERS, CONTACT_ARGUMENTS,
    CONTACT_INPUTS, CONTACT_OUTPUTS, CONTACT_PARAMETERS, Derivative, Input, Parameter,
};
use kontakt::element::{ContactElement, ContactStatus};
use kontakt::geometry::Twist;
use kontakt::{Error, Result};
use kontakt_case::bearing_model::{BearingElement, BearingElementOutput};
use kontakt_case::element_case::{DampingSpec, ElementCase, element_from_case};
use nalgebra::{Isometry3, Quaternion, Translation3, UnitQuaternion, Vector3};

/// The damping ramp a contact case without `[damping]` starts with, mm.
pub const DEFAULT_RAMP_MM: f64 = 1e-3;

/// How far a quaternion input's norm may be from 1 before the FMU refuses it (a host's
/// linear interpolation of a quaternion shortens it by up to `1 − cos(Δφ/2)` between
/// samples; within this tolerance the FMU normalises it).
pub const QUATERNION_NORM_TOLERANCE: f64 = 1e-2;

/// Which element the case describes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A bearing case (`method = "bearing"`): [`BearingElement`].
    Bearing,
    /// An element case (`method = "element"`): [`ContactElement`].
    Contact,
}

/// One variable of an FMU, as the model description lists it.
#[derive(Debug, Clone, Copy)]
pub struct Variable {
    /// FMI name.
    pub name: &'static str,
    /// `parameter`, `input` or `output`.
    pub causality: &'static str,
    /// Unit, `None` for a number.
    pub unit: Option<&'static str>,
    /// Description.
    pub description: &'static str,
    /// Start value (parameters and inputs).
    pub start: Option<f64>,
}

/// A planned element with its parameters.
// One per instance: the bearing's last output (336 bytes) stays inline so that an
// evaluation allocates nothing.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone)]
pub enum Model {
    /// The bearing element.
    Bearing {
        /// The element.
        element: Box<BearingElement>,
        /// The last successful evaluation (its stiffness gives the derivatives).
        last: Option<BearingElementOutput>,
    },
    /// The contact element.
    Contact {
        /// The element.
        element: Box<ContactElement>,
        /// The case it was planned from (re-planned when a parameter changes).
        case: Box<ElementCase>,
        /// `damping_coefficient`, `damping_ramp`, `mu`.
        parameters: [f64; 3],
    },
}

/// What an evaluation says besides its outputs.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// Within the model's validity.
    Valid,
    /// The outputs are computed but the state is beyond the model's validity (the
    /// message says why): `fmi2Discard`.
    Beyond(String),
}

/// The method of a case text (`"bearing"`, `"element"`), if it names one.
fn method(text: &str) -> Option<String> {
    let table = text.parse::<toml::Table>().ok()?;
    table.get("method")?.as_str().map(str::to_string)
}

impl Model {
    /// Plan the element of a case text: a bearing case (`method = "bearing"`) or an
    /// element case (`method = "element"`).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `method` for any other method; the case's errors,
    /// named by their keys.
    pub fn from_case(text: &str) -> Result<Self> {
        match method(text).as_deref() {
            Some("bearing") => Ok(Model::Bearing {
                element: Box::new(BearingElement::from_toml(text)?),
                last: None,
            }),
            Some("element") => {
                let case = ElementCase::from_toml_str(text)?;
                let element = element_from_case(&case)?;
                let damping = case.damping.map_or([0.0, DEFAULT_RAMP_MM], |d| {
                    [d.coefficient_n_s_per_mm, d.ramp_mm]
                });
                let mu = element.spec().friction.boundary_coefficient;
                Ok(Model::Contact {
                    element: Box::new(element),
                    case: Box::new(case),
                    parameters: [damping[0], damping[1], mu],
                })
            }
            other => Err(Error::invalid(
                "method",
                other.unwrap_or("(missing)"),
                "\"bearing\" (a bearing element FMU) or \"element\" (a contact element FMU)",
            )),
        }
    }

    /// Which element this is.
    pub fn kind(&self) -> Kind {
        match self {
            Model::Bearing { .. } => Kind::Bearing,
            Model::Contact { .. } => Kind::Contact,
        }
    }

    /// The parameters' rows.
    pub fn parameter_rows(&self) -> &'static [Parameter] {
        match self {
            Model::Bearing { .. } => BEARING_PARAMETERS,
            Model::Contact { .. } => CONTACT_PARAMETERS,
        }
    }

    /// The inputs' rows.
    pub fn input_rows(&self) -> &'static [Input] {
        match self {
            Model::Bearing { .. } => BEARING_INPUTS,
            Model::Contact { .. } => CONTACT_INPUTS,
        }
    }

    /// The number of outputs.
    pub fn outputs(&self) -> usize {
        match self {
            Model::Bearing { .. } => BEARING_OUTPUTS.len(),
            Model::Contact { .. } => CONTACT_OUTPUTS.len(),
        }
    }

    /// How output `i`'s derivatives are computed.
    fn derivative(&self, i: usize) -> Derivative {
        match self {
            Model::Bearing { .. } => BEARING_OUTPUTS[i].derivative,
            Model::Contact { .. } => CONTACT_OUTPUTS[i].derivative,
        }
    }

    /// The parameters' current values.
    pub fn parameters(&self) -> Vec<f64> {
        match self {
            Model::Bearing { element, .. } => vec![element.damping_s()],
            Model::Contact { parameters, .. } => parameters.to_vec(),
        }
    }

    /// Every variable, in value-reference order: parameters, inputs, outputs.
    pub fn variables(&self) -> Vec<Variable> {
        let parameters = self.parameters();
        let mut v: Vec<Variable> = self
            .parameter_rows()
            .iter()
            .zip(parameters)
            .map(|(p, start)| Variable {
                name: p.name,
                causality: "parameter",
                unit: p.unit,
                description: p.description,
                start: Some(start),
            })
            .collect();
        // the bearing's ring speeds start at the case's [speed]
        let speeds = match self {
            Model::Bearing { element, .. } => element.speeds(),
            Model::Contact { .. } => [0.0; 2],
        };
        v.extend(self.input_rows().iter().map(|i| Variable {
            name: i.name,
            causality: "input",
            unit: i.unit,
            description: i.description,
            start: Some(match i.name {
                "omega_inner" => speeds[0],
                "omega_outer" => speeds[1],
                _ => i.start,
            }),
        }));
        let output = |name, unit, description| Variable {
            name,
            causality: "output",
            unit,
            description,
            start: None,
        };
        match self {
            Model::Bearing { .. } => v.extend(
                BEARING_OUTPUTS
                    .iter()
                    .map(|o| output(o.name, o.unit, o.description)),
            ),
            Model::Contact { .. } => v.extend(
                CONTACT_OUTPUTS
                    .iter()
                    .map(|o| output(o.name, o.unit, o.description)),
            ),
        }
        v
    }

    /// Set parameter `i` (in the order of [`Model::parameter_rows`]).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the FMI parameter for a value the element refuses;
    /// the element keeps its parameters then.
    pub fn set_parameter(&mut self, i: usize, value: f64) -> Result<()> {
        match self {
            Model::Bearing { element, .. } => element.set_damping(value),
            Model::Contact {
                element,
                case,
                parameters,
            } => {
                let mut p = *parameters;
                p[i] = value;
                let mut c = (**case).clone();
                c.damping = (p[0] != 0.0).then_some(DampingSpec {
                    coefficient_n_s_per_mm: p[0],
                    ramp_mm: p[1],
                });
                c.friction.mu = Some(p[2]);
                // the ramp is checked even while the damping is off
                if !(p[1].is_finite() && p[1] > 0.0) {
                    return Err(Error::invalid("damping_ramp", p[1], "a finite ramp > 0 mm"));
                }
                let planned = element_from_case(&c).map_err(|e| {
                    e.map_field(|f| match f {
                        "damping.coefficient_n_s_per_mm" => "damping_coefficient".into(),
                        "damping.ramp_mm" => "damping_ramp".into(),
                        "friction.mu" => "mu".into(),
                        other => other.into(),
                    })
                })?;
                **element = planned;
                **case = c;
                *parameters = p;
                Ok(())
            }
        }
    }

    /// Evaluate the element at the inputs `x` (in the order of [`Model::input_rows`]) and
    /// write the outputs to `out`. Allocates nothing for the bearing; the contact element
    /// allocates only a message beyond its validity.
    ///
    /// # Errors
    /// The element's, with the arguments renamed to the FMI inputs (`dz`,
    /// `pose1 (inputs pose1.x to pose1.qz)`); a quaternion input whose norm is off by more
    /// than [`QUATERNION_NORM_TOLERANCE`] (field `pose1.qw..qz`).
    pub fn evaluate(&mut self, x: &[f64], out: &mut [f64]) -> Result<Outcome> {
        match self {
            Model::Bearing { element, last } => {
                let u = std::array::from_fn(|i| x[i]);
                let v = std::array::from_fn(|i| x[5 + i]);
                let rename = |e: Error| {
                    e.map_field(|f| match BEARING_ARGUMENTS.iter().position(|a| *a == f) {
                        Some(i) => BEARING_INPUTS[i].name.into(),
                        None => f.into(),
                    })
                };
                if element.speeds() != [x[10], x[11]] {
                    element.set_speeds(x[10], x[11]).map_err(rename)?;
                }
                let r = element.evaluate(u, v).map_err(rename)?;
                for (o, row) in out.iter_mut().zip(BEARING_OUTPUTS) {
                    *o = (row.value)(&r);
                }
                *last = Some(r);
                Ok(Outcome::Valid)
            }
            Model::Contact { element, .. } => {
                let pose1 = pose(&x[0..7], "pose1")?;
                let pose2 = pose(&x[7..14], "pose2")?;
                let twist = |t: &[f64]| {
                    Twist::new(
                        Vector3::new(t[0], t[1], t[2]),
                        Vector3::new(t[3], t[4], t[5]),
                    )
                };
                let r = element
                    .evaluate(&pose1, &pose2, &twist(&x[14..20]), &twist(&x[20..26]))
                    .map_err(|e| {
                        e.map_field(|f| match CONTACT_ARGUMENTS.iter().find(|(a, _)| *a == f) {
                            Some((_, name)) => (*name).into(),
                            None => f.into(),
                        })
                    })?;
                for (o, row) in out.iter_mut().zip(CONTACT_OUTPUTS) {
                    *o = (row.value)(&r);
                }
                Ok(match r.status {
                    ContactStatus::OutOfValidity => Outcome::Beyond(r.message),
                    _ => Outcome::Valid,
                })
            }
        }
    }

    /// The directional derivative `dv_unknown = J dv_known` of the outputs `unknown`
    /// (output indices) with respect to the inputs `known` (input indices) at the inputs
    /// `x`, the element evaluated there last (its state is left unchanged). Analytic from
    /// the bearing's stiffness where [`Derivative::Reaction`] allows it, otherwise central
    /// differences along the seed.
    ///
    /// # Errors
    /// Those of [`Model::evaluate`] at the two shifted inputs.
    pub fn directional_derivative(
        &self,
        x: &[f64],
        known: &[usize],
        seed: &[f64],
        unknown: &[usize],
        out: &mut [f64],
    ) -> Result<()> {
        if let Model::Bearing {
            element,
            last: Some(r),
        } = self
        {
            let beta = element.damping_s();
            let exact = beta == 0.0 || x[5..10].iter().all(|v| *v == 0.0);
            let rows: Option<Vec<Option<usize>>> = unknown
                .iter()
                .map(|&i| match self.derivative(i) {
                    Derivative::Reaction(row) => Some(Some(row)),
                    Derivative::Zero => Some(None),
                    Derivative::Differences => None,
                })
                .collect();
            if let (true, Some(rows)) = (exact, rows) {
                for (o, row) in out.iter_mut().zip(rows) {
                    *o = match row {
                        None => 0.0,
                        Some(i) => known
                            .iter()
                            .zip(seed)
                            .map(|(&j, s)| {
                                // the ring speeds move the friction torque only
                                s * match j {
                                    0..5 => -r.stiffness[i][j],
                                    5..10 => -beta * r.stiffness[i][j - 5],
                                    _ => 0.0,
                                }
                            })
                            .sum(),
                    };
                }
                return Ok(());
            }
        }
        let scale = known.iter().map(|&j| x[j].abs()).fold(1.0, f64::max);
        let size = seed.iter().map(|s| s.abs()).fold(0.0, f64::max);
        if size == 0.0 {
            out.iter_mut().for_each(|o| *o = 0.0);
            return Ok(());
        }
        let h = 1e-7 * scale / size;
        let n = self.outputs();
        let shifted = |sign: f64| -> Result<Vec<f64>> {
            let mut xs = x.to_vec();
            for (&j, s) in known.iter().zip(seed) {
                xs[j] += sign * h * s;
            }
            let mut m = self.clone();
            let mut o = vec![0.0; n];
            m.evaluate(&xs, &mut o)?;
            Ok(o)
        };
        let plus = shifted(1.0)?;
        let minus = shifted(-1.0)?;
        for (o, &i) in out.iter_mut().zip(unknown) {
            *o = match self.derivative(i) {
                Derivative::Zero => 0.0,
                _ => (plus[i] - minus[i]) / (2.0 * h),
            };
        }
        Ok(())
    }
}

/// A pose from `x, y, z, qw, qx, qy, qz`, the quaternion normalised.
fn pose(p: &[f64], name: &'static str) -> Result<Isometry3<f64>> {
    let q = Quaternion::new(p[3], p[4], p[5], p[6]);
    let norm = q.norm();
    // non-finite values pass on to the element, which names them
    if norm.is_finite() && (norm - 1.0).abs() > QUATERNION_NORM_TOLERANCE {
        return Err(Error::invalid(
            format!("{name}.qw..qz"),
            format!("a quaternion of norm {norm}"),
            format!(
                "a unit quaternion (norm within {QUATERNION_NORM_TOLERANCE} of 1; the FMU normalises it)"
            ),
        ));
    }
    let q = if norm.is_finite() { q / norm } else { q };
    Ok(Isometry3::from_parts(
        Translation3::new(p[0], p[1], p[2]),
        UnitQuaternion::new_unchecked(q),
    ))
}
