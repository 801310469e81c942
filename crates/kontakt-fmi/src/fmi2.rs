//! The FMI 2.0 C API (the `fmi2*` functions of the standard's `fmi2Functions.h`), exported
//! unmangled by the cdylib: model exchange and co-simulation from one binary. Each
//! function is a thin layer over [`crate::instance::Core`]: it checks its pointers, runs
//! the call under `catch_unwind` (no panic crosses the boundary; a panic becomes
//! `fmi2Error` with a logged message) and logs every status other than `fmi2OK` through the
//! host's logger, naming the variable.
//!
//! Types: `fmi2Component` and `fmi2FMUstate` are `void*`, `fmi2Status`, `fmi2Type`,
//! `fmi2StatusKind`, `fmi2Boolean` and `fmi2Integer` are C `int`, `fmi2ValueReference` is
//! `unsigned int`, `fmi2Real` is `double`.

#![allow(non_snake_case)] // the standard's names

use crate::instance::{Core, Failure, FmuType, Mode, Status};
use crate::model::Model;
use std::ffi::{CStr, CString, c_char, c_int, c_uint, c_void};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::PathBuf;

/// The case file inside the FMU's `resources/` folder.
pub const CASE_FILE: &str = "case.toml";

/// `fmi2CallbackLogger`: `(componentEnvironment, instanceName, status, category,
/// message, ...)`, message a printf format.
pub type Logger =
    unsafe extern "C" fn(*mut c_void, *const c_char, c_int, *const c_char, *const c_char, ...);

/// `fmi2CallbackFunctions`.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct CallbackFunctions {
    /// `logger`.
    pub logger: Option<Logger>,
    /// `allocateMemory` (not used: canNotUseMemoryManagementFunctions).
    pub allocate_memory: Option<unsafe extern "C" fn(usize, usize) -> *mut c_void>,
    /// `freeMemory` (not used).
    pub free_memory: Option<unsafe extern "C" fn(*mut c_void)>,
    /// `stepFinished` (not used: no asynchronous steps).
    pub step_finished: Option<unsafe extern "C" fn(*mut c_void, c_int)>,
    /// `componentEnvironment`, passed back to the logger.
    pub component_environment: *mut c_void,
}

/// `fmi2EventInfo`.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct EventInfo {
    /// `newDiscreteStatesNeeded`.
    pub new_discrete_states_needed: c_int,
    /// `terminateSimulation`.
    pub terminate_simulation: c_int,
    /// `nominalsOfContinuousStatesChanged`.
    pub nominals_of_continuous_states_changed: c_int,
    /// `valuesOfContinuousStatesChanged`.
    pub values_of_continuous_states_changed: c_int,
    /// `nextEventTimeDefined`.
    pub next_event_time_defined: c_int,
    /// `nextEventTime`.
    pub next_event_time: f64,
}

/// An instance behind an `fmi2Component`.
pub struct Instance {
    name: CString,
    environment: *mut c_void,
    logger: Option<Logger>,
    logging: bool,
    /// The message of the last call that did not return `fmi2OK` (what the logger got).
    last_message: String,
    /// The state an FMU state saves.
    pub core: Core,
    /// The state after instantiation, for `fmi2Reset`.
    initial: Core,
}

impl Instance {
    /// Send `message` to the host's logger.
    fn log(&self, status: Status, message: &str) {
        emit(self.logger, self.environment, &self.name, status, message);
    }

    /// The message of the last call that did not return `fmi2OK`, as logged (empty if
    /// none).
    pub fn last_message(&self) -> &str {
        &self.last_message
    }
}

/// Send `message` to `logger` (if the host gave one), as `"%s"` with one argument.
fn emit(
    logger: Option<Logger>,
    environment: *mut c_void,
    name: &CStr,
    status: Status,
    message: &str,
) {
    let Some(logger) = logger else { return };
    let category: &CStr = match status {
        Status::Ok => c"logAll",
        Status::Warning => c"logStatusWarning",
        Status::Discard => c"logStatusDiscard",
        Status::Error => c"logStatusError",
        Status::Fatal => c"logStatusFatal",
    };
    let text = CString::new(message.replace('\0', "\\0")).unwrap_or_default();
    // SAFETY: the host's logger, called with its environment, NUL-terminated strings and
    // the format "%s" with one string argument.
    unsafe {
        logger(
            environment,
            name.as_ptr(),
            status as c_int,
            category.as_ptr(),
            c"%s".as_ptr(),
            text.as_ptr(),
        )
    };
}

/// The message of a caught panic.
fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".into())
}

/// Run `f` on the instance `c` at the boundary: a failure is logged with the function's
/// name, a panic becomes `fmi2Error`.
///
/// # Safety
/// `c` is null or an instance from [`fmi2Instantiate`], not freed, not used by another
/// thread during the call.
unsafe fn call(
    c: *mut c_void,
    function: &str,
    f: impl FnOnce(&mut Instance) -> Result<Status, Failure>,
) -> c_int {
    if c.is_null() {
        return Status::Error as c_int;
    }
    // SAFETY: non-null and from fmi2Instantiate (the caller's contract).
    let instance = unsafe { &mut *c.cast::<Instance>() };
    let result = catch_unwind(AssertUnwindSafe(|| f(&mut *instance)));
    let status = match result {
        Ok(Ok(status)) => {
            if instance.logging {
                instance.log(Status::Ok, &format!("{function}: fmi2OK"));
            }
            status
        }
        Ok(Err((status, message))) => {
            instance.last_message = format!("{function}: {message}");
            instance.log(status, &instance.last_message);
            status
        }
        Err(payload) => {
            instance.core.dirty = true;
            instance.last_message = format!(
                "{function}: internal panic in kontakt (a bug, please report it): {}",
                panic_message(payload.as_ref())
            );
            instance.log(Status::Error, &instance.last_message);
            Status::Error
        }
    };
    status as c_int
}

/// `n` elements at `p` as a slice (an empty slice for `n = 0`, whatever `p`).
///
/// # Safety
/// `p` points to `n` readable elements when `n > 0`.
unsafe fn slice<'a, T>(p: *const T, n: usize, name: &str) -> Result<&'a [T], Failure> {
    if n == 0 {
        return Ok(&[]);
    }
    if p.is_null() {
        return Err((Status::Error, format!("{name} is a null pointer")));
    }
    // SAFETY: non-null, n readable elements by the caller's contract.
    Ok(unsafe { std::slice::from_raw_parts(p, n) })
}

/// `n` writable elements at `p`.
///
/// # Safety
/// `p` points to `n` writable elements when `n > 0`.
unsafe fn slice_mut<'a, T>(p: *mut T, n: usize, name: &str) -> Result<&'a mut [T], Failure> {
    if n == 0 {
        return Ok(&mut []);
    }
    if p.is_null() {
        return Err((Status::Error, format!("{name} is a null pointer")));
    }
    // SAFETY: non-null, n writable elements by the caller's contract.
    Ok(unsafe { std::slice::from_raw_parts_mut(p, n) })
}

/// The folder of a `file:` URI, percent-decoded: `file:` followed by `//` and an empty or
/// `localhost` authority and the absolute path (what FMPy and most hosts send), or by the
/// absolute path alone.
pub fn uri_to_path(uri: &str) -> Option<PathBuf> {
    let rest = uri.strip_prefix("file:")?;
    let rest = match rest.strip_prefix("//") {
        Some(r) => r.strip_prefix("localhost").unwrap_or(r),
        None => rest,
    };
    let mut bytes = Vec::with_capacity(rest.len());
    let mut raw = rest.bytes();
    while let Some(b) = raw.next() {
        if b == b'%' {
            let hex = [raw.next()?, raw.next()?];
            bytes.push(u8::from_str_radix(std::str::from_utf8(&hex).ok()?, 16).ok()?);
        } else {
            bytes.push(b);
        }
    }
    let mut path = String::from_utf8(bytes).ok()?;
    // a drive letter on Windows: `/C:/x` after the authority
    if cfg!(windows) && path.len() > 2 && path.as_bytes()[2] == b':' {
        path.remove(0);
    }
    Some(PathBuf::from(path))
}

/// The instance `fmi2Instantiate` makes, or the message why not.
fn instantiate(
    fmu_type: c_int,
    guid: &str,
    resources: &str,
    name: CString,
    functions: &CallbackFunctions,
    logging: bool,
) -> Result<Instance, String> {
    let fmu_type = match fmu_type {
        0 => FmuType::ModelExchange,
        1 => FmuType::CoSimulation,
        other => return Err(format!("fmuType = {other}: expected 0 (ME) or 1 (CS)")),
    };
    let dir = uri_to_path(resources).ok_or_else(|| {
        format!("fmuResourceLocation = {resources:?}: expected a file: URI of the FMU's resources folder")
    })?;
    // some hosts pass the FMU's folder instead of its resources/ folder
    let path = [dir.join(CASE_FILE), dir.join("resources").join(CASE_FILE)]
        .into_iter()
        .find(|p| p.is_file())
        .unwrap_or_else(|| dir.join(CASE_FILE));
    let text = std::fs::read_to_string(&path)
        .map_err(|e| format!("cannot read the FMU's case {}: {e}", path.display()))?;
    let expected = crate::description::guid(&text);
    if guid != expected {
        return Err(format!(
            "fmuGUID = {guid}: this binary and resources/{CASE_FILE} belong to the FMU {expected} (the model description and the case do not match)"
        ));
    }
    let model = Model::from_case(&text).map_err(|e| format!("resources/{CASE_FILE}: {e}"))?;
    let core = Core::new(model, fmu_type);
    Ok(Instance {
        name,
        environment: functions.component_environment,
        logger: functions.logger,
        logging,
        last_message: String::new(),
        initial: core.clone(),
        core,
    })
}

/// `fmi2GetTypesPlatform`: `"default"`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetTypesPlatform() -> *const c_char {
    c"default".as_ptr()
}

/// `fmi2GetVersion`: `"2.0"`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetVersion() -> *const c_char {
    c"2.0".as_ptr()
}

/// `fmi2Instantiate`: plan the element from `resources/case.toml` at
/// `fmuResourceLocation` (a `file:` URI). Null on failure (the reason logged).
///
/// # Safety
/// The strings are null or NUL-terminated; `functions` is null or a valid
/// `fmi2CallbackFunctions` that outlives the instance.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2Instantiate(
    instance_name: *const c_char,
    fmu_type: c_int,
    fmu_guid: *const c_char,
    fmu_resource_location: *const c_char,
    functions: *const CallbackFunctions,
    _visible: c_int,
    logging_on: c_int,
) -> *mut c_void {
    if functions.is_null() || instance_name.is_null() {
        return std::ptr::null_mut();
    }
    // SAFETY: non-null and valid by contract.
    let functions = unsafe { *functions };
    // SAFETY: non-null, NUL-terminated by contract.
    let name = unsafe { CStr::from_ptr(instance_name) }.to_owned();
    let string = |p: *const c_char| -> String {
        if p.is_null() {
            String::new()
        } else {
            // SAFETY: non-null, NUL-terminated by contract.
            unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned()
        }
    };
    let (guid, resources) = (string(fmu_guid), string(fmu_resource_location));
    let made = catch_unwind(AssertUnwindSafe(|| {
        instantiate(
            fmu_type,
            &guid,
            &resources,
            name.clone(),
            &functions,
            logging_on != 0,
        )
    }))
    .unwrap_or_else(|p| {
        Err(format!(
            "internal panic in kontakt: {}",
            panic_message(p.as_ref())
        ))
    });
    match made {
        Ok(instance) => {
            if instance.logging {
                instance.log(
                    Status::Ok,
                    &format!("fmi2Instantiate: {}", instance.core.summary()),
                );
            }
            Box::into_raw(Box::new(instance)).cast()
        }
        Err(message) => {
            emit(
                functions.logger,
                functions.component_environment,
                &name,
                Status::Error,
                &format!("fmi2Instantiate: {message}"),
            );
            std::ptr::null_mut()
        }
    }
}

/// `fmi2FreeInstance`. Null is ignored.
///
/// # Safety
/// `c` is null or from [`fmi2Instantiate`], not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeInstance(c: *mut c_void) {
    if c.is_null() {
        return;
    }
    let _ = catch_unwind(AssertUnwindSafe(|| {
        // SAFETY: from Box::into_raw in fmi2Instantiate, freed once (the contract).
        drop(unsafe { Box::from_raw(c.cast::<Instance>()) });
    }));
}

/// `fmi2SetDebugLogging`: switch the per-call log (`logAll`) on or off; the categories
/// `logStatusWarning`, `logStatusDiscard`, `logStatusError`, `logStatusFatal` are always
/// logged.
///
/// # Safety
/// `c` as for every function; `categories` points to `n` strings.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetDebugLogging(
    c: *mut c_void,
    logging_on: c_int,
    n: usize,
    categories: *const *const c_char,
) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2SetDebugLogging", |i| {
            let list = slice(categories, n, "categories")?;
            for &p in list {
                if p.is_null() {
                    return Err((Status::Error, "a category is a null pointer".into()));
                }
                let name = CStr::from_ptr(p).to_string_lossy();
                if !crate::description::LOG_CATEGORIES
                    .iter()
                    .any(|(c, _)| *c == name)
                {
                    return Err((Status::Error, format!("unknown log category {name:?}")));
                }
            }
            i.logging = logging_on != 0;
            Ok(Status::Ok)
        })
    }
}

/// `fmi2SetupExperiment`: sets the start time.
///
/// # Safety
/// `c` as for every function.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetupExperiment(
    c: *mut c_void,
    _tolerance_defined: c_int,
    _tolerance: f64,
    start_time: f64,
    _stop_time_defined: c_int,
    _stop_time: f64,
) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2SetupExperiment", |i| {
            i.core
                .require("fmi2SetupExperiment", &[Mode::Instantiated])?;
            i.core.time = start_time;
            Ok(Status::Ok)
        })
    }
}

/// `fmi2EnterInitializationMode`.
///
/// # Safety
/// `c` as for every function.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2EnterInitializationMode(c: *mut c_void) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2EnterInitializationMode", |i| {
            i.core
                .require("fmi2EnterInitializationMode", &[Mode::Instantiated])?;
            i.core.mode = Mode::Initialization;
            Ok(Status::Ok)
        })
    }
}

/// `fmi2ExitInitializationMode`: to event mode (ME) or step complete (CS).
///
/// # Safety
/// `c` as for every function.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2ExitInitializationMode(c: *mut c_void) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2ExitInitializationMode", |i| {
            i.core
                .require("fmi2ExitInitializationMode", &[Mode::Initialization])?;
            i.core.mode = match i.core.fmu_type {
                FmuType::ModelExchange => Mode::Event,
                FmuType::CoSimulation => Mode::StepComplete,
            };
            Ok(Status::Ok)
        })
    }
}

/// `fmi2Terminate`.
///
/// # Safety
/// `c` as for every function.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2Terminate(c: *mut c_void) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2Terminate", |i| {
            i.core.require(
                "fmi2Terminate",
                &[Mode::Event, Mode::ContinuousTime, Mode::StepComplete],
            )?;
            i.core.mode = Mode::Terminated;
            Ok(Status::Ok)
        })
    }
}

/// `fmi2Reset`: back to the state after instantiation (start values, no warm start).
///
/// # Safety
/// `c` as for every function.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2Reset(c: *mut c_void) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2Reset", |i| {
            i.core = i.initial.clone();
            Ok(Status::Ok)
        })
    }
}

/// `fmi2GetReal`: evaluates the element when an output is asked for after an input
/// changed. `fmi2Discard` beyond the model's validity (the contact element's outputs are
/// written; the bearing's are not: it refuses the displacement), `fmi2Error` for bad
/// input; the message names the variable.
///
/// # Safety
/// `c` as for every function; `vr` and `value` point to `nvr` elements.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetReal(
    c: *mut c_void,
    vr: *const c_uint,
    nvr: usize,
    value: *mut f64,
) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2GetReal", |i| {
            let vr = slice(vr, nvr, "vr")?;
            let value = slice_mut(value, nvr, "value")?;
            i.core.get_real(vr, value)
        })
    }
}

/// `fmi2SetReal`: inputs and tunable parameters; a non-finite value is `fmi2Error`
/// naming the variable (and not taken).
///
/// # Safety
/// `c` as for every function; `vr` and `value` point to `nvr` elements.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetReal(
    c: *mut c_void,
    vr: *const c_uint,
    nvr: usize,
    value: *const f64,
) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2SetReal", |i| {
            let vr = slice(vr, nvr, "vr")?;
            let value = slice(value, nvr, "value")?;
            i.core.set_real(vr, value)
        })
    }
}

/// No variable of the type: `fmi2OK` for none, `fmi2Error` naming the first reference.
fn none_of(kind: &str, vr: &[c_uint]) -> Result<Status, Failure> {
    match vr.first() {
        None => Ok(Status::Ok),
        Some(r) => Err((
            Status::Error,
            format!(
                "value reference {r}: this FMU has no {kind} variables (every variable is a Real)"
            ),
        )),
    }
}

macro_rules! no_variables {
    ($get:ident, $set:ident, $t:ty, $kind:literal) => {
        /// No variables of this type: `fmi2OK` for `nvr = 0`, else `fmi2Error`.
        ///
        /// # Safety
        /// `c` as for every function; `vr` points to `nvr` elements.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $get(
            c: *mut c_void,
            vr: *const c_uint,
            nvr: usize,
            _value: *mut $t,
        ) -> c_int {
            // SAFETY: by contract.
            unsafe {
                call(c, stringify!($get), |_| {
                    none_of($kind, slice(vr, nvr, "vr")?)
                })
            }
        }

        /// No variables of this type: `fmi2OK` for `nvr = 0`, else `fmi2Error`.
        ///
        /// # Safety
        /// `c` as for every function; `vr` points to `nvr` elements.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $set(
            c: *mut c_void,
            vr: *const c_uint,
            nvr: usize,
            _value: *const $t,
        ) -> c_int {
            // SAFETY: by contract.
            unsafe {
                call(c, stringify!($set), |_| {
                    none_of($kind, slice(vr, nvr, "vr")?)
                })
            }
        }
    };
}

no_variables!(fmi2GetInteger, fmi2SetInteger, c_int, "Integer");
no_variables!(fmi2GetBoolean, fmi2SetBoolean, c_int, "Boolean");
no_variables!(fmi2GetString, fmi2SetString, *const c_char, "String");

/// `fmi2GetFMUstate`: a copy of the instance's state (the element with its warm start,
/// the variables, the mode); reuses `*state` if it is one already.
///
/// # Safety
/// `c` as for every function; `state` writable, `*state` null or from this function.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetFMUstate(c: *mut c_void, state: *mut *mut c_void) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2GetFMUstate", |i| {
            if state.is_null() {
                return Err((Status::Error, "FMUstate is a null pointer".into()));
            }
            let old = *state;
            if old.is_null() {
                *state = Box::into_raw(Box::new(i.core.clone())).cast();
            } else {
                *old.cast::<Core>() = i.core.clone();
            }
            Ok(Status::Ok)
        })
    }
}

/// `fmi2SetFMUstate`: restore a state of [`fmi2GetFMUstate`].
///
/// # Safety
/// `c` as for every function; `state` null or from [`fmi2GetFMUstate`] of an instance
/// of the same FMU.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetFMUstate(c: *mut c_void, state: *mut c_void) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2SetFMUstate", |i| {
            if state.is_null() {
                return Err((Status::Error, "FMUstate is a null pointer".into()));
            }
            let saved = &*state.cast::<Core>();
            if saved.names != i.core.names {
                return Err((Status::Error, "the FMUstate belongs to another FMU".into()));
            }
            i.core = saved.clone();
            Ok(Status::Ok)
        })
    }
}

/// `fmi2FreeFMUstate`: release a state and set `*state` to null.
///
/// # Safety
/// `c` as for every function; `state` null or writable, `*state` null or from
/// [`fmi2GetFMUstate`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeFMUstate(c: *mut c_void, state: *mut *mut c_void) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2FreeFMUstate", |_| {
            if !state.is_null() && !(*state).is_null() {
                drop(Box::from_raw((*state).cast::<Core>()));
                *state = std::ptr::null_mut();
            }
            Ok(Status::Ok)
        })
    }
}

fn not_serializable() -> Result<Status, Failure> {
    Err((
        Status::Error,
        "FMU states cannot be serialized (canSerializeFMUstate = false)".into(),
    ))
}

/// Not supported (`canSerializeFMUstate = false`): `fmi2Error`.
///
/// # Safety
/// `c` as for every function.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SerializedFMUstateSize(
    c: *mut c_void,
    _state: *mut c_void,
    _size: *mut usize,
) -> c_int {
    // SAFETY: by contract.
    unsafe { call(c, "fmi2SerializedFMUstateSize", |_| not_serializable()) }
}

/// Not supported (`canSerializeFMUstate = false`): `fmi2Error`.
///
/// # Safety
/// `c` as for every function.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SerializeFMUstate(
    c: *mut c_void,
    _state: *mut c_void,
    _bytes: *mut c_char,
    _size: usize,
) -> c_int {
    // SAFETY: by contract.
    unsafe { call(c, "fmi2SerializeFMUstate", |_| not_serializable()) }
}

/// Not supported (`canSerializeFMUstate = false`): `fmi2Error`.
///
/// # Safety
/// `c` as for every function.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
    c: *mut c_void,
    _bytes: *const c_char,
    _size: usize,
    _state: *mut *mut c_void,
) -> c_int {
    // SAFETY: by contract.
    unsafe { call(c, "fmi2DeSerializeFMUstate", |_| not_serializable()) }
}

/// `fmi2GetDirectionalDerivative`: `dvUnknown = (∂outputs/∂inputs) dvKnown` for outputs
/// (unknowns) and inputs (knowns): the bearing's forces and moments from its stiffness,
/// everything else by central differences along the seed (docs/fmi.md).
///
/// # Safety
/// `c` as for every function; the arrays hold `n_unknown` / `n_known` elements.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetDirectionalDerivative(
    c: *mut c_void,
    unknown: *const c_uint,
    n_unknown: usize,
    known: *const c_uint,
    n_known: usize,
    dv_known: *const f64,
    dv_unknown: *mut f64,
) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2GetDirectionalDerivative", |i| {
            let unknown = slice(unknown, n_unknown, "vUnknown_ref")?;
            let known = slice(known, n_known, "vKnown_ref")?;
            let seed = slice(dv_known, n_known, "dvKnown")?;
            let out = slice_mut(dv_unknown, n_unknown, "dvUnknown")?;
            i.core.directional_derivative(unknown, known, seed, out)
        })
    }
}

// ------------------------------------------------------------------ model exchange

fn model_exchange(i: &Instance, function: &str) -> Result<(), Failure> {
    if i.core.fmu_type == FmuType::ModelExchange {
        Ok(())
    } else {
        Err((
            Status::Error,
            format!("{function} is a model-exchange function; this instance is co-simulation"),
        ))
    }
}

/// `fmi2EnterEventMode`.
///
/// # Safety
/// `c` as for every function.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2EnterEventMode(c: *mut c_void) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2EnterEventMode", |i| {
            model_exchange(i, "fmi2EnterEventMode")?;
            i.core
                .require("fmi2EnterEventMode", &[Mode::Event, Mode::ContinuousTime])?;
            i.core.mode = Mode::Event;
            Ok(Status::Ok)
        })
    }
}

/// `fmi2NewDiscreteStates`: no discrete states, no time events.
///
/// # Safety
/// `c` as for every function; `info` writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2NewDiscreteStates(c: *mut c_void, info: *mut EventInfo) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2NewDiscreteStates", |i| {
            model_exchange(i, "fmi2NewDiscreteStates")?;
            i.core.require("fmi2NewDiscreteStates", &[Mode::Event])?;
            if info.is_null() {
                return Err((Status::Error, "fmi2eventInfo is a null pointer".into()));
            }
            info.write(EventInfo {
                new_discrete_states_needed: 0,
                terminate_simulation: 0,
                nominals_of_continuous_states_changed: 0,
                values_of_continuous_states_changed: 0,
                next_event_time_defined: 0,
                next_event_time: 0.0,
            });
            Ok(Status::Ok)
        })
    }
}

/// `fmi2EnterContinuousTimeMode`.
///
/// # Safety
/// `c` as for every function.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2EnterContinuousTimeMode(c: *mut c_void) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2EnterContinuousTimeMode", |i| {
            model_exchange(i, "fmi2EnterContinuousTimeMode")?;
            i.core
                .require("fmi2EnterContinuousTimeMode", &[Mode::Event])?;
            i.core.mode = Mode::ContinuousTime;
            Ok(Status::Ok)
        })
    }
}

/// `fmi2CompletedIntegratorStep`: never asks for an event or termination.
///
/// # Safety
/// `c` as for every function; the two flags writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2CompletedIntegratorStep(
    c: *mut c_void,
    _no_set_state_prior: c_int,
    enter_event_mode: *mut c_int,
    terminate_simulation: *mut c_int,
) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2CompletedIntegratorStep", |i| {
            model_exchange(i, "fmi2CompletedIntegratorStep")?;
            i.core
                .require("fmi2CompletedIntegratorStep", &[Mode::ContinuousTime])?;
            if enter_event_mode.is_null() || terminate_simulation.is_null() {
                return Err((Status::Error, "a flag is a null pointer".into()));
            }
            enter_event_mode.write(0);
            terminate_simulation.write(0);
            Ok(Status::Ok)
        })
    }
}

/// `fmi2SetTime`.
///
/// # Safety
/// `c` as for every function.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetTime(c: *mut c_void, time: f64) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2SetTime", |i| {
            model_exchange(i, "fmi2SetTime")?;
            if !time.is_finite() {
                return Err((Status::Error, format!("invalid time = {time}")));
            }
            i.core.time = time;
            Ok(Status::Ok)
        })
    }
}

/// The FMU has no continuous states: `nx` must be 0.
fn no_states(i: &Instance, function: &str, nx: usize) -> Result<Status, Failure> {
    model_exchange(i, function)?;
    if nx == 0 {
        Ok(Status::Ok)
    } else {
        Err((
            Status::Error,
            format!("nx = {nx}: this FMU has no continuous states (numberOfContinuousStates = 0)"),
        ))
    }
}

macro_rules! state_vector {
    ($name:ident, $t:ty) => {
        /// No continuous states (nor event indicators): `fmi2OK` for a length of 0.
        ///
        /// # Safety
        /// `c` as for every function.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(c: *mut c_void, _x: $t, nx: usize) -> c_int {
            // SAFETY: by contract.
            unsafe {
                call(c, stringify!($name), |i| {
                    no_states(i, stringify!($name), nx)
                })
            }
        }
    };
}

state_vector!(fmi2SetContinuousStates, *const f64);
state_vector!(fmi2GetDerivatives, *mut f64);
state_vector!(fmi2GetEventIndicators, *mut f64);
state_vector!(fmi2GetContinuousStates, *mut f64);
state_vector!(fmi2GetNominalsOfContinuousStates, *mut f64);

// ------------------------------------------------------------------ co-simulation

fn co_simulation(i: &Instance, function: &str) -> Result<(), Failure> {
    if i.core.fmu_type == FmuType::CoSimulation {
        Ok(())
    } else {
        Err((
            Status::Error,
            format!("{function} is a co-simulation function; this instance is model exchange"),
        ))
    }
}

/// Not supported (`canInterpolateInputs = false`): `fmi2Error`.
///
/// # Safety
/// `c` as for every function.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetRealInputDerivatives(
    c: *mut c_void,
    _vr: *const c_uint,
    _nvr: usize,
    _order: *const c_int,
    _value: *const f64,
) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2SetRealInputDerivatives", |_| {
            Err((
                Status::Error,
                "input derivatives are not used (canInterpolateInputs = false)".into(),
            ))
        })
    }
}

/// Not supported (`maxOutputDerivativeOrder = 0`): `fmi2Error`.
///
/// # Safety
/// `c` as for every function.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetRealOutputDerivatives(
    c: *mut c_void,
    _vr: *const c_uint,
    _nvr: usize,
    _order: *const c_int,
    _value: *mut f64,
) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2GetRealOutputDerivatives", |_| {
            Err((
                Status::Error,
                "output derivatives are not provided (maxOutputDerivativeOrder = 0)".into(),
            ))
        })
    }
}

/// `fmi2DoStep`: the element has no state of its own, so a step holds the inputs, moves
/// the time and evaluates the outputs at the step's end (its status is the step's:
/// `fmi2Discard` beyond the model's validity).
///
/// # Safety
/// `c` as for every function.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2DoStep(
    c: *mut c_void,
    current: f64,
    step: f64,
    _no_set_state_prior: c_int,
) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2DoStep", |i| {
            co_simulation(i, "fmi2DoStep")?;
            i.core.require("fmi2DoStep", &[Mode::StepComplete])?;
            if !(step.is_finite() && step >= 0.0 && current.is_finite()) {
                return Err((
                    Status::Error,
                    format!(
                        "invalid communicationStepSize = {step} at {current}: expected a finite step >= 0"
                    ),
                ));
            }
            let status = i.core.update();
            if !matches!(status, Err((Status::Error, _))) {
                i.core.time = current + step;
            }
            status
        })
    }
}

/// Not supported (no asynchronous steps): `fmi2Error`.
///
/// # Safety
/// `c` as for every function.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2CancelStep(c: *mut c_void) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2CancelStep", |_| {
            Err((
                Status::Error,
                "fmi2DoStep never returns fmi2Pending: nothing to cancel".into(),
            ))
        })
    }
}

/// `fmi2GetStatus` (`fmi2DoStepStatus`): `fmi2OK`; other kinds `fmi2Discard`.
///
/// # Safety
/// `c` as for every function; `value` writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetStatus(c: *mut c_void, kind: c_int, value: *mut c_int) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2GetStatus", |i| {
            co_simulation(i, "fmi2GetStatus")?;
            if kind != 0 || value.is_null() {
                return Err((Status::Discard, format!("status kind {kind} not provided")));
            }
            value.write(Status::Ok as c_int);
            Ok(Status::Ok)
        })
    }
}

/// `fmi2GetRealStatus` (`fmi2LastSuccessfulTime`): the time; other kinds `fmi2Discard`.
///
/// # Safety
/// `c` as for every function; `value` writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetRealStatus(c: *mut c_void, kind: c_int, value: *mut f64) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2GetRealStatus", |i| {
            co_simulation(i, "fmi2GetRealStatus")?;
            if kind != 2 || value.is_null() {
                return Err((Status::Discard, format!("status kind {kind} not provided")));
            }
            value.write(i.core.time);
            Ok(Status::Ok)
        })
    }
}

/// `fmi2GetIntegerStatus`: none provided (`fmi2Discard`).
///
/// # Safety
/// `c` as for every function.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetIntegerStatus(
    c: *mut c_void,
    kind: c_int,
    _value: *mut c_int,
) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2GetIntegerStatus", |_| {
            Err((Status::Discard, format!("status kind {kind} not provided")))
        })
    }
}

/// `fmi2GetBooleanStatus` (`fmi2Terminated`): false; other kinds `fmi2Discard`.
///
/// # Safety
/// `c` as for every function; `value` writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetBooleanStatus(
    c: *mut c_void,
    kind: c_int,
    value: *mut c_int,
) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2GetBooleanStatus", |_| {
            if kind != 3 || value.is_null() {
                return Err((Status::Discard, format!("status kind {kind} not provided")));
            }
            value.write(0);
            Ok(Status::Ok)
        })
    }
}

/// `fmi2GetStringStatus`: none provided (`fmi2Discard`).
///
/// # Safety
/// `c` as for every function.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetStringStatus(
    c: *mut c_void,
    kind: c_int,
    _value: *mut *const c_char,
) -> c_int {
    // SAFETY: by contract.
    unsafe {
        call(c, "fmi2GetStringStatus", |_| {
            Err((Status::Discard, format!("status kind {kind} not provided")))
        })
    }
}
