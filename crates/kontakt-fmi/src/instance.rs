//! An FMU instance: the model, the values of its variables, the FMI state machine and the
//! lazy evaluation (the outputs are computed when asked for after an input changed).
//! Nothing here touches a raw pointer: fmi2.rs is the C boundary.

use crate::model::{Model, Outcome};
use std::fmt::Write as _;

/// `fmi2Status`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
#[repr(i32)]
pub enum Status {
    /// `fmi2OK`.
    Ok = 0,
    /// `fmi2Warning`.
    Warning = 1,
    /// `fmi2Discard`: the state is beyond the model's validity, or the solver did not
    /// converge; a smaller step may help.
    Discard = 2,
    /// `fmi2Error`: bad input (not finite, an unknown value reference) or an illegal call.
    Error = 3,
    /// `fmi2Fatal`.
    Fatal = 4,
}

/// A failed call: its status and the message for the logger.
pub type Failure = (Status, String);

/// `fmi2Type`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FmuType {
    /// `fmi2ModelExchange`.
    ModelExchange,
    /// `fmi2CoSimulation`.
    CoSimulation,
}

/// The FMI 2.0 states of an instance (the standard's state machines, merged).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// After `fmi2Instantiate` (or `fmi2Reset`).
    Instantiated,
    /// Between `fmi2EnterInitializationMode` and `fmi2ExitInitializationMode`.
    Initialization,
    /// Model exchange: event mode.
    Event,
    /// Model exchange: continuous-time mode.
    ContinuousTime,
    /// Co-simulation: between steps.
    StepComplete,
    /// After `fmi2Terminate`.
    Terminated,
}

/// The part of an instance an FMU state saves: the model (with its warm start), the
/// variables' values and the mode.
#[derive(Debug, Clone)]
pub struct Core {
    /// The element.
    pub model: Model,
    /// Every variable's value by value reference: parameters, inputs, outputs.
    pub values: Vec<f64>,
    /// Number of parameters.
    pub parameters: usize,
    /// Number of inputs.
    pub inputs: usize,
    /// The outputs are stale (an input or parameter changed since the last evaluation).
    pub dirty: bool,
    /// The last evaluation's failure or `Beyond` message, returned again until an input
    /// changes.
    pub last: Option<Failure>,
    /// The outputs hold the last evaluation (it succeeded, or went beyond the model's
    /// validity with the outputs computed).
    pub computed: bool,
    /// The FMI state.
    pub mode: Mode,
    /// ME or CS.
    pub fmu_type: FmuType,
    /// Current time, s.
    pub time: f64,
    /// The evaluations made (for tests and the log).
    pub evaluations: u64,
    /// The variables' names, for messages.
    pub names: Vec<&'static str>,
}

impl Core {
    /// A new instance's state from a planned model.
    pub fn new(model: Model, fmu_type: FmuType) -> Self {
        let variables = model.variables();
        let parameters = model.parameter_rows().len();
        let inputs = model.input_rows().len();
        let values = variables.iter().map(|v| v.start.unwrap_or(0.0)).collect();
        Core {
            model,
            values,
            parameters,
            inputs,
            dirty: true,
            last: None,
            computed: false,
            mode: Mode::Instantiated,
            fmu_type,
            time: 0.0,
            evaluations: 0,
            names: variables.iter().map(|v| v.name).collect(),
        }
    }

    fn first_output(&self) -> usize {
        self.parameters + self.inputs
    }

    /// The variable of a value reference, or an error naming it.
    fn index(&self, vr: u32) -> Result<usize, Failure> {
        let i = vr as usize;
        if i < self.values.len() {
            Ok(i)
        } else {
            Err((
                Status::Error,
                format!(
                    "value reference {vr} is not a Real variable of this FMU (0 to {})",
                    self.values.len() - 1
                ),
            ))
        }
    }

    /// Refuse a call in a mode that does not allow it.
    pub fn require(&self, function: &str, allowed: &[Mode]) -> Result<(), Failure> {
        if allowed.contains(&self.mode) {
            Ok(())
        } else {
            Err((
                Status::Error,
                format!("{function} is not allowed in the {:?} state", self.mode),
            ))
        }
    }

    /// `fmi2SetReal`: inputs any time before termination, parameters (tunable) outside
    /// continuous-time mode. A non-finite value is refused naming the variable, and kept
    /// out.
    pub fn set_real(&mut self, vr: &[u32], value: &[f64]) -> Result<Status, Failure> {
        if self.mode == Mode::Terminated {
            return Err((
                Status::Error,
                "fmi2SetReal is not allowed after fmi2Terminate".into(),
            ));
        }
        for (&r, &x) in vr.iter().zip(value) {
            let i = self.index(r)?;
            let name = self.names[i];
            if i >= self.first_output() {
                return Err((
                    Status::Error,
                    format!("{name} (value reference {r}) is an output: it cannot be set"),
                ));
            }
            if !x.is_finite() {
                return Err((
                    Status::Error,
                    format!("invalid {name} = {x}: expected a finite number"),
                ));
            }
            if i < self.parameters {
                if self.mode == Mode::ContinuousTime {
                    return Err((
                        Status::Error,
                        format!(
                            "parameter {name} can be changed in event mode, not in continuous-time mode"
                        ),
                    ));
                }
                if self.values[i] != x {
                    self.model
                        .set_parameter(i, x)
                        .map_err(|e| (Status::Error, e.to_string()))?;
                }
            }
            self.values[i] = x;
            self.dirty = true;
        }
        Ok(Status::Ok)
    }

    /// Evaluate the element if an input changed: the status of the evaluation (also
    /// for a repeated call on unchanged inputs).
    pub fn update(&mut self) -> Result<Status, Failure> {
        if self.dirty {
            self.dirty = false;
            let first = self.first_output();
            let (head, outputs) = self.values.split_at_mut(first);
            let inputs = &head[self.parameters..];
            self.evaluations += 1;
            let result = self.model.evaluate(inputs, outputs);
            self.computed = result.is_ok();
            self.last = match result {
                Ok(Outcome::Valid) => None,
                Ok(Outcome::Beyond(message)) => Some((Status::Discard, message)),
                Err(e) => {
                    let bad = inputs.iter().any(|x| !x.is_finite());
                    let status = match e {
                        kontakt::Error::InvalidInput { .. } if !bad => Status::Discard,
                        kontakt::Error::NotConverged { .. } => Status::Discard,
                        _ => Status::Error,
                    };
                    Some((status, e.to_string()))
                }
            };
        }
        match &self.last {
            None => Ok(Status::Ok),
            Some(f) => Err(f.clone()),
        }
    }

    /// `fmi2GetReal`: evaluates first when an output is asked for and an input changed.
    /// On `Discard` beyond the contact's validity the outputs are written as well; on any
    /// other failure nothing is written.
    pub fn get_real(&mut self, vr: &[u32], value: &mut [f64]) -> Result<Status, Failure> {
        if self.mode == Mode::Instantiated {
            return Err((
                Status::Error,
                "fmi2GetReal is not allowed before fmi2EnterInitializationMode".into(),
            ));
        }
        let mut output = false;
        for &r in vr {
            output |= self.index(r)? >= self.first_output();
        }
        let status = if output {
            self.update()
        } else {
            Ok(Status::Ok)
        };
        // on failure nothing is written, except beyond the contact's validity where the
        // outputs are computed (and the status says Discard)
        if status.is_ok() || (output && self.computed) {
            for (v, &r) in value.iter_mut().zip(vr) {
                *v = self.values[r as usize];
            }
        }
        status
    }

    /// `fmi2GetDirectionalDerivative`: outputs with respect to inputs only.
    pub fn directional_derivative(
        &mut self,
        unknown: &[u32],
        known: &[u32],
        seed: &[f64],
        out: &mut [f64],
    ) -> Result<Status, Failure> {
        let first = self.first_output();
        let mut u = Vec::with_capacity(unknown.len());
        for &r in unknown {
            let i = self.index(r)?;
            if i < first {
                return Err((
                    Status::Error,
                    format!(
                        "fmi2GetDirectionalDerivative: unknown {} is not an output",
                        self.names[i]
                    ),
                ));
            }
            u.push(i - first);
        }
        let mut k = Vec::with_capacity(known.len());
        for &r in known {
            let i = self.index(r)?;
            if !(self.parameters..first).contains(&i) {
                return Err((
                    Status::Error,
                    format!(
                        "fmi2GetDirectionalDerivative: known {} is not an input",
                        self.names[i]
                    ),
                ));
            }
            k.push(i - self.parameters);
        }
        if let Some(s) = seed.iter().position(|s| !s.is_finite()) {
            return Err((
                Status::Error,
                format!(
                    "fmi2GetDirectionalDerivative: dvKnown[{s}] = {} is not finite",
                    seed[s]
                ),
            ));
        }
        let status = self.update();
        if let Err((Status::Error, _)) = &status {
            return status;
        }
        let inputs = &self.values[self.parameters..first];
        self.model
            .directional_derivative(inputs, &k, seed, &u, out)
            .map_err(|e| (Status::Discard, e.to_string()))?;
        status
    }

    /// A one-line summary of the instance for the debug log.
    pub fn summary(&self) -> String {
        let mut s = String::new();
        let _ = write!(
            s,
            "{:?} {:?} element, {} parameters, {} inputs, {} outputs",
            self.fmu_type,
            self.model.kind(),
            self.parameters,
            self.inputs,
            self.values.len() - self.first_output()
        );
        s
    }
}
