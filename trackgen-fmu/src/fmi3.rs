//! FMI 3.0 co-simulation: the functions [`export_fmu!`](crate::export_fmu)
//! exports, each a thin shim over these (generic over the vehicle). The
//! signatures are the standard's headers' (`fmi3FunctionTypes.h`,
//! FMI 3.0.1).

use std::ffi::{CString, c_char, c_void};

use trackgen::vehicle::Powertrain;

use crate::component::{self, Component, Fmi3Logger, Logger, Status};
use crate::error::FmuError;
use crate::instance::Instance;
use crate::plant::Plant;

/// `fmi3GetVersion`.
pub const VERSION: &std::ffi::CStr = c"3.0";

/// `fmi3InstantiateCoSimulation`: a new instance (with the engine
/// `engine` makes, if any), or null (logged) if the token is not this
/// FMU's or the vehicle cannot be built.
///
/// # Safety
/// The strings are null or NUL-terminated; the logger, if any, is callable
/// with `env` for the instance's lifetime.
pub unsafe fn instantiate<P: Plant>(
    name: *const c_char,
    token: *const c_char,
    env: *mut c_void,
    logger: Option<Fmi3Logger>,
    engine: Option<fn() -> Powertrain>,
) -> *mut c_void {
    let logger = logger.map_or(Logger::None, |f| Logger::Fmi3(f, env));
    // SAFETY: by the caller's contract.
    let name = unsafe { component::text(name) }.unwrap_or("trackgen");
    let Some(component) = Component::<P>::create(name, logger, engine) else {
        return std::ptr::null_mut();
    };
    // SAFETY: as above.
    let token = unsafe { component::text(token) }.unwrap_or("");
    let expected = crate::description::token::<P>(component.instance.variables());
    if !token.is_empty() && token != expected {
        component.log(
            Status::Error,
            &format!("instantiation token {token} is not this FMU's ({expected})"),
        );
        return std::ptr::null_mut();
    }
    Box::into_raw(component) as *mut c_void
}

/// `fmi3EnterInitializationMode`.
///
/// # Safety
/// `instance` is null or this library's and alive.
pub unsafe fn enter_initialization<P: Plant>(
    instance: *mut c_void,
    tolerance_defined: bool,
    tolerance: f64,
    start: f64,
    stop_defined: bool,
    stop: f64,
) -> Status {
    // SAFETY: by the caller's contract.
    unsafe {
        component::with::<P>(instance, |c| {
            c.instance.setup_experiment(
                tolerance_defined.then_some(tolerance),
                start,
                stop_defined.then_some(stop),
            )?;
            c.instance.enter_initialization()?;
            Ok(Status::Ok)
        })
    }
}

/// `fmi3DoStep`: never returns early, never needs event handling; a
/// failed run is an error, `lastSuccessfulTime` the point reached.
///
/// # Safety
/// As [`enter_initialization`]; the out-pointers are null or writable.
#[allow(clippy::too_many_arguments)]
pub unsafe fn do_step<P: Plant>(
    instance: *mut c_void,
    t: f64,
    h: f64,
    event_handling_needed: *mut bool,
    terminate: *mut bool,
    early_return: *mut bool,
    last_successful_time: *mut f64,
) -> Status {
    // SAFETY: by the caller's contract.
    unsafe {
        component::with::<P>(instance, |c| {
            let outcome = c.instance.do_step(t, h);
            let reached = c.instance.time();
            for (p, v) in [(event_handling_needed, false), (early_return, false)] {
                if !p.is_null() {
                    *p = v;
                }
            }
            if !terminate.is_null() {
                *terminate = outcome.is_err();
            }
            if !last_successful_time.is_null() {
                *last_successful_time = reached;
            }
            outcome.map(|()| Status::Ok)
        })
    }
}

/// `fmi3GetString`: the strings stay valid until the next call that
/// reads strings.
///
/// # Safety
/// As [`enter_initialization`]; the arrays hold `n` elements.
pub unsafe fn get_string<P: Plant>(
    instance: *mut c_void,
    refs: *const u32,
    n_refs: usize,
    values: *mut *const c_char,
    n_values: usize,
) -> Status {
    // SAFETY: by the caller's contract.
    unsafe {
        component::with::<P>(instance, |c| {
            same_length(n_refs, n_values)?;
            let refs = component::slice(refs, n_refs)?;
            let values = component::slice_mut(values, n_values)?;
            c.strings.clear();
            for r in refs {
                let s = c.instance.get_string(*r)?;
                c.strings.push(CString::new(s).unwrap_or_default());
            }
            for (v, s) in values.iter_mut().zip(&c.strings) {
                *v = s.as_ptr();
            }
            Ok(Status::Ok)
        })
    }
}

/// `fmi3SetString`.
///
/// # Safety
/// As [`get_string`]; each string is null or NUL-terminated.
pub unsafe fn set_string<P: Plant>(
    instance: *mut c_void,
    refs: *const u32,
    n_refs: usize,
    values: *const *const c_char,
    n_values: usize,
) -> Status {
    // SAFETY: by the caller's contract.
    unsafe {
        component::with::<P>(instance, |c| {
            same_length(n_refs, n_values)?;
            let refs = component::slice(refs, n_refs)?;
            let values = component::slice(values, n_values)?;
            for (r, v) in refs.iter().zip(values) {
                c.instance.set_string(*r, component::text(*v)?)?;
            }
            Ok(Status::Ok)
        })
    }
}

/// A value type the FMI getters and setters move: `fmi3Float64` (`f64`,
/// FMI 2.0's `fmi2Real`) or `fmi3Int32` (`i32`, `fmi2Integer`), each
/// read and written by the instance's own method.
pub trait Value: Copy {
    /// The instance's values of `refs` into `out`.
    fn get<P: Plant>(
        instance: &Instance<P>,
        refs: &[u32],
        out: &mut [Self],
    ) -> Result<(), FmuError>;
    /// Sets the instance's `refs` to `values`.
    fn set<P: Plant>(
        instance: &mut Instance<P>,
        refs: &[u32],
        values: &[Self],
    ) -> Result<(), FmuError>;
}

impl Value for f64 {
    fn get<P: Plant>(
        instance: &Instance<P>,
        refs: &[u32],
        out: &mut [f64],
    ) -> Result<(), FmuError> {
        instance.get_f64(refs, out)
    }
    fn set<P: Plant>(
        instance: &mut Instance<P>,
        refs: &[u32],
        values: &[f64],
    ) -> Result<(), FmuError> {
        instance.set_f64(refs, values)
    }
}

impl Value for i32 {
    fn get<P: Plant>(
        instance: &Instance<P>,
        refs: &[u32],
        out: &mut [i32],
    ) -> Result<(), FmuError> {
        instance.get_i32(refs, out)
    }
    fn set<P: Plant>(
        instance: &mut Instance<P>,
        refs: &[u32],
        values: &[i32],
    ) -> Result<(), FmuError> {
        instance.set_i32(refs, values)
    }
}

/// `fmi3GetFloat64` and `fmi3GetInt32` (and FMI 2.0's `fmi2GetReal` and
/// `fmi2GetInteger`, with `n_values = n_refs`).
///
/// # Safety
/// As [`get_string`].
pub unsafe fn get<P: Plant, T: Value>(
    instance: *mut c_void,
    (refs, n_refs): (*const u32, usize),
    (values, n_values): (*mut T, usize),
) -> Status {
    // SAFETY: by the caller's contract.
    unsafe {
        component::with::<P>(instance, |c| {
            same_length(n_refs, n_values)?;
            let (refs, values) = (
                component::slice(refs, n_refs)?,
                component::slice_mut(values, n_values)?,
            );
            T::get(&c.instance, refs, values).map(|()| Status::Ok)
        })
    }
}

/// `fmi3SetFloat64` and `fmi3SetInt32` (and `fmi2SetReal`,
/// `fmi2SetInteger`).
///
/// # Safety
/// As [`get_string`].
pub unsafe fn set<P: Plant, T: Value>(
    instance: *mut c_void,
    (refs, n_refs): (*const u32, usize),
    (values, n_values): (*const T, usize),
) -> Status {
    // SAFETY: by the caller's contract.
    unsafe {
        component::with::<P>(instance, |c| {
            same_length(n_refs, n_values)?;
            let (refs, values) = (
                component::slice(refs, n_refs)?,
                component::slice(values, n_values)?,
            );
            T::set(&mut c.instance, refs, values).map(|()| Status::Ok)
        })
    }
}

/// An array's length against its references'.
pub fn same_length(n_refs: usize, n_values: usize) -> Result<(), FmuError> {
    if n_refs == n_values {
        Ok(())
    } else {
        Err(FmuError::Step(format!(
            "{n_values} values for {n_refs} value references (every variable is a scalar)"
        )))
    }
}

/// A function this FMU does not provide (an error, logged).
///
/// # Safety
/// As [`enter_initialization`].
pub unsafe fn unsupported<P: Plant>(instance: *mut c_void, name: &'static str) -> Status {
    // SAFETY: by the caller's contract.
    unsafe {
        component::with::<P>(instance, |_| {
            Err(FmuError::State {
                call: name,
                state: "in this FMU (co-simulation only; no FMU state, no derivatives, no clocks)",
            })
        })
    }
}

/// Exports the FMI 3.0 functions for `$vehicle` (used by
/// [`export_fmu!`](crate::export_fmu)).
#[doc(hidden)]
#[macro_export]
macro_rules! __export_fmi3 {
    ($v:ty, $engine:expr) => {
        const _: () = {
            use ::std::ffi::{c_char, c_int, c_void};
            use $crate::component::{self as c, Status};
            use $crate::fmi3;

            #[unsafe(no_mangle)]
            pub extern "C" fn fmi3GetVersion() -> *const c_char {
                fmi3::VERSION.as_ptr()
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3SetDebugLogging(
                instance: *mut c_void,
                _on: bool,
                _n: usize,
                _categories: *const *const c_char,
            ) -> c_int {
                unsafe { c::with::<$v>(instance, |_| Ok(Status::Ok)) as c_int }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3InstantiateCoSimulation(
                name: *const c_char,
                token: *const c_char,
                _resources: *const c_char,
                _visible: bool,
                _logging_on: bool,
                _event_mode_used: bool,
                _early_return_allowed: bool,
                _required: *const u32,
                _n_required: usize,
                env: *mut c_void,
                logger: Option<c::Fmi3Logger>,
                _intermediate: *mut c_void,
            ) -> *mut c_void {
                unsafe { fmi3::instantiate::<$v>(name, token, env, logger, $engine) }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3InstantiateModelExchange(
                _name: *const c_char,
                _token: *const c_char,
                _resources: *const c_char,
                _visible: bool,
                _logging_on: bool,
                _env: *mut c_void,
                _logger: *mut c_void,
            ) -> *mut c_void {
                ::std::ptr::null_mut()
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3InstantiateScheduledExecution(
                _name: *const c_char,
                _token: *const c_char,
                _resources: *const c_char,
                _visible: bool,
                _logging_on: bool,
                _env: *mut c_void,
                _logger: *mut c_void,
                _clock: *mut c_void,
                _lock: *mut c_void,
                _unlock: *mut c_void,
            ) -> *mut c_void {
                ::std::ptr::null_mut()
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3FreeInstance(instance: *mut c_void) {
                unsafe { c::free::<$v>(instance) }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3EnterInitializationMode(
                instance: *mut c_void,
                tolerance_defined: bool,
                tolerance: f64,
                start: f64,
                stop_defined: bool,
                stop: f64,
            ) -> c_int {
                unsafe {
                    fmi3::enter_initialization::<$v>(
                        instance,
                        tolerance_defined,
                        tolerance,
                        start,
                        stop_defined,
                        stop,
                    ) as c_int
                }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3ExitInitializationMode(instance: *mut c_void) -> c_int {
                unsafe {
                    c::with::<$v>(instance, |c| {
                        c.instance.exit_initialization().map(|()| Status::Ok)
                    }) as c_int
                }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3EnterStepMode(instance: *mut c_void) -> c_int {
                unsafe { c::with::<$v>(instance, |_| Ok(Status::Ok)) as c_int }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3Terminate(instance: *mut c_void) -> c_int {
                unsafe { c::with::<$v>(instance, |c| c.instance.terminate().map(|()| Status::Ok)) as c_int }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3Reset(instance: *mut c_void) -> c_int {
                unsafe {
                    c::with::<$v>(instance, |c| {
                        c.instance.reset();
                        Ok(Status::Ok)
                    }) as c_int
                }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3GetFloat64(
                instance: *mut c_void,
                refs: *const u32,
                n_refs: usize,
                values: *mut f64,
                n_values: usize,
            ) -> c_int {
                unsafe { fmi3::get::<$v, f64>(instance, (refs, n_refs), (values, n_values)) as c_int }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3SetFloat64(
                instance: *mut c_void,
                refs: *const u32,
                n_refs: usize,
                values: *const f64,
                n_values: usize,
            ) -> c_int {
                unsafe { fmi3::set::<$v, f64>(instance, (refs, n_refs), (values, n_values)) as c_int }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3GetInt32(
                instance: *mut c_void,
                refs: *const u32,
                n_refs: usize,
                values: *mut i32,
                n_values: usize,
            ) -> c_int {
                unsafe { fmi3::get::<$v, i32>(instance, (refs, n_refs), (values, n_values)) as c_int }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3SetInt32(
                instance: *mut c_void,
                refs: *const u32,
                n_refs: usize,
                values: *const i32,
                n_values: usize,
            ) -> c_int {
                unsafe { fmi3::set::<$v, i32>(instance, (refs, n_refs), (values, n_values)) as c_int }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3GetString(
                instance: *mut c_void,
                refs: *const u32,
                n_refs: usize,
                values: *mut *const c_char,
                n_values: usize,
            ) -> c_int {
                unsafe { fmi3::get_string::<$v>(instance, refs, n_refs, values, n_values) as c_int }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3SetString(
                instance: *mut c_void,
                refs: *const u32,
                n_refs: usize,
                values: *const *const c_char,
                n_values: usize,
            ) -> c_int {
                unsafe { fmi3::set_string::<$v>(instance, refs, n_refs, values, n_values) as c_int }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3DoStep(
                instance: *mut c_void,
                t: f64,
                h: f64,
                _no_set_state_prior: bool,
                event_handling_needed: *mut bool,
                terminate: *mut bool,
                early_return: *mut bool,
                last_successful_time: *mut f64,
            ) -> c_int {
                unsafe {
                    fmi3::do_step::<$v>(
                        instance,
                        t,
                        h,
                        event_handling_needed,
                        terminate,
                        early_return,
                        last_successful_time,
                    ) as c_int
                }
            }

            $crate::__fmi3_unsupported!($v;
                fmi3EnterEventMode(),
                fmi3EnterConfigurationMode(),
                fmi3ExitConfigurationMode(),
                fmi3GetFloat32(r: *const u32, nr: usize, v: *mut f32, nv: usize),
                fmi3SetFloat32(r: *const u32, nr: usize, v: *const f32, nv: usize),
                fmi3GetInt8(r: *const u32, nr: usize, v: *mut i8, nv: usize),
                fmi3SetInt8(r: *const u32, nr: usize, v: *const i8, nv: usize),
                fmi3GetUInt8(r: *const u32, nr: usize, v: *mut u8, nv: usize),
                fmi3SetUInt8(r: *const u32, nr: usize, v: *const u8, nv: usize),
                fmi3GetInt16(r: *const u32, nr: usize, v: *mut i16, nv: usize),
                fmi3SetInt16(r: *const u32, nr: usize, v: *const i16, nv: usize),
                fmi3GetUInt16(r: *const u32, nr: usize, v: *mut u16, nv: usize),
                fmi3SetUInt16(r: *const u32, nr: usize, v: *const u16, nv: usize),
                fmi3GetUInt32(r: *const u32, nr: usize, v: *mut u32, nv: usize),
                fmi3SetUInt32(r: *const u32, nr: usize, v: *const u32, nv: usize),
                fmi3GetInt64(r: *const u32, nr: usize, v: *mut i64, nv: usize),
                fmi3SetInt64(r: *const u32, nr: usize, v: *const i64, nv: usize),
                fmi3GetUInt64(r: *const u32, nr: usize, v: *mut u64, nv: usize),
                fmi3SetUInt64(r: *const u32, nr: usize, v: *const u64, nv: usize),
                fmi3GetBoolean(r: *const u32, nr: usize, v: *mut bool, nv: usize),
                fmi3SetBoolean(r: *const u32, nr: usize, v: *const bool, nv: usize),
                fmi3GetBinary(r: *const u32, nr: usize, s: *mut usize, v: *mut *const u8, nv: usize),
                fmi3SetBinary(r: *const u32, nr: usize, s: *const usize, v: *const *const u8, nv: usize),
                fmi3GetClock(r: *const u32, nr: usize, v: *mut bool),
                fmi3SetClock(r: *const u32, nr: usize, v: *const bool),
                fmi3GetNumberOfVariableDependencies(r: u32, n: *mut usize),
                fmi3GetVariableDependencies(d: u32, e: *mut usize, i: *mut u32, ei: *mut usize, k: *mut c_int, n: usize),
                fmi3GetFMUState(s: *mut *mut c_void),
                fmi3SetFMUState(s: *mut c_void),
                fmi3FreeFMUState(s: *mut *mut c_void),
                fmi3SerializedFMUStateSize(s: *mut c_void, n: *mut usize),
                fmi3SerializeFMUState(s: *mut c_void, b: *mut u8, n: usize),
                fmi3DeserializeFMUState(b: *const u8, n: usize, s: *mut *mut c_void),
                fmi3GetDirectionalDerivative(u: *const u32, nu: usize, k: *const u32, nk: usize, s: *const f64, ns: usize, o: *mut f64, no: usize),
                fmi3GetAdjointDerivative(u: *const u32, nu: usize, k: *const u32, nk: usize, s: *const f64, ns: usize, o: *mut f64, no: usize),
                fmi3GetIntervalDecimal(r: *const u32, nr: usize, v: *mut f64, q: *mut c_int),
                fmi3GetIntervalFraction(r: *const u32, nr: usize, c: *mut u64, res: *mut u64, q: *mut c_int),
                fmi3GetShiftDecimal(r: *const u32, nr: usize, v: *mut f64),
                fmi3GetShiftFraction(r: *const u32, nr: usize, c: *mut u64, res: *mut u64),
                fmi3SetIntervalDecimal(r: *const u32, nr: usize, v: *const f64),
                fmi3SetIntervalFraction(r: *const u32, nr: usize, c: *const u64, res: *const u64),
                fmi3SetShiftDecimal(r: *const u32, nr: usize, v: *const f64),
                fmi3SetShiftFraction(r: *const u32, nr: usize, c: *const u64, res: *const u64),
                fmi3EvaluateDiscreteStates(),
                fmi3UpdateDiscreteStates(a: *mut bool, b: *mut bool, c: *mut bool, d: *mut bool, e: *mut bool, f: *mut f64),
                fmi3GetOutputDerivatives(r: *const u32, nr: usize, o: *const i32, v: *mut f64, nv: usize),
                fmi3ActivateModelPartition(clock: u32, at: f64),
                fmi3CompletedIntegratorStep(no_set: bool, event: *mut bool, terminate: *mut bool),
                fmi3EnterContinuousTimeMode(),
                fmi3GetContinuousStateDerivatives(v: *mut f64, n: usize),
                fmi3GetContinuousStates(v: *mut f64, n: usize),
                fmi3GetEventIndicators(v: *mut f64, n: usize),
                fmi3GetNominalsOfContinuousStates(v: *mut f64, n: usize),
                fmi3GetNumberOfContinuousStates(n: *mut usize),
                fmi3GetNumberOfEventIndicators(n: *mut usize),
                fmi3SetContinuousStates(v: *const f64, n: usize),
                fmi3SetTime(t: f64),
            );
        };
    };
}

/// Exports FMI 3.0 functions this FMU does not provide, with the
/// standard's signatures (used by [`export_fmu!`](crate::export_fmu)).
#[doc(hidden)]
#[macro_export]
macro_rules! __fmi3_unsupported {
    ($v:ty; $($name:ident ( $($arg:ident : $ty:ty),* )),* $(,)?) => {
        $(
            #[unsafe(no_mangle)]
            #[allow(unused_variables)]
            pub unsafe extern "C" fn $name(instance: *mut ::std::ffi::c_void, $($arg: $ty),*) -> ::std::ffi::c_int {
                unsafe { $crate::fmi3::unsupported::<$v>(instance, stringify!($name)) as ::std::ffi::c_int }
            }
        )*
    };
}
