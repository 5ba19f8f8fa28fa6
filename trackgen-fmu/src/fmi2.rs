//! FMI 2.0 co-simulation, for the many tools that read only 2.0: the same
//! instance behind the 2.0 names and signatures (`fmi2FunctionTypes.h`,
//! FMI 2.0.4). Booleans are `int`, integers `int32`.

use std::ffi::{c_char, c_int, c_void};

use trackgen::vehicle::Powertrain;

use crate::component::{self, Component, Fmi2Logger, Logger, Status};
use crate::error::FmuError;
use crate::instance::Mode;
use crate::plant::Plant;

/// `fmi2GetVersion`.
pub const VERSION: &std::ffi::CStr = c"2.0";
/// `fmi2GetTypesPlatform`.
pub const TYPES_PLATFORM: &std::ffi::CStr = c"default";

/// `fmi2CallbackFunctions`.
#[repr(C)]
pub struct Callbacks {
    /// The logger.
    pub logger: Option<Fmi2Logger>,
    /// Unused: this FMU allocates with Rust's allocator.
    pub allocate: *mut c_void,
    /// Unused.
    pub free: *mut c_void,
    /// Unused: steps are synchronous.
    pub step_finished: *mut c_void,
    /// The environment the logger gets.
    pub environment: *mut c_void,
}

/// `fmi2Instantiate`: co-simulation only; the GUID must be this FMU's;
/// with the engine `engine` makes, if any.
///
/// # Safety
/// The strings are null or NUL-terminated; `callbacks` is null or valid
/// for the instance's lifetime.
pub unsafe fn instantiate<P: Plant>(
    name: *const c_char,
    kind: c_int,
    guid: *const c_char,
    callbacks: *const Callbacks,
    engine: Option<fn() -> Powertrain>,
) -> *mut c_void {
    // SAFETY: by the caller's contract.
    let logger = unsafe { callbacks.as_ref() }
        .and_then(|c| c.logger.map(|f| Logger::Fmi2(f, c.environment)))
        .unwrap_or(Logger::None);
    // SAFETY: as above.
    let name = unsafe { component::text(name) }.unwrap_or("trackgen");
    let Some(component) = Component::<P>::create(name, logger, engine) else {
        return std::ptr::null_mut();
    };
    if kind != 1 {
        component.log(
            Status::Error,
            "this FMU is for co-simulation only (fmi2CoSimulation)",
        );
        return std::ptr::null_mut();
    }
    // SAFETY: as above.
    let guid = unsafe { component::text(guid) }.unwrap_or("");
    let expected = crate::description::token::<P>(component.instance.variables());
    if guid != expected {
        component.log(
            Status::Error,
            &format!("GUID {guid} is not this FMU's ({expected})"),
        );
        return std::ptr::null_mut();
    }
    Box::into_raw(component) as *mut c_void
}

/// `fmi2GetString`.
///
/// # Safety
/// `instance` is null or this library's and alive; the arrays hold `n`
/// elements.
pub unsafe fn get_string<P: Plant>(
    instance: *mut c_void,
    refs: *const u32,
    n: usize,
    values: *mut *const c_char,
) -> Status {
    // SAFETY: by the caller's contract.
    unsafe { crate::fmi3::get_string::<P>(instance, refs, n, values, n) }
}

/// `fmi2SetString`.
///
/// # Safety
/// As [`get_string`].
pub unsafe fn set_string<P: Plant>(
    instance: *mut c_void,
    refs: *const u32,
    n: usize,
    values: *const *const c_char,
) -> Status {
    // SAFETY: by the caller's contract.
    unsafe { crate::fmi3::set_string::<P>(instance, refs, n, values, n) }
}

/// `fmi2GetRealStatus`: `fmi2LastSuccessfulTime` (2) is the point reached.
///
/// # Safety
/// As [`get_string`]; `value` is null or writable.
pub unsafe fn real_status<P: Plant>(instance: *mut c_void, kind: c_int, value: *mut f64) -> Status {
    // SAFETY: by the caller's contract.
    unsafe {
        component::with::<P>(instance, |c: &mut Component<P>| {
            if kind != 2 || value.is_null() {
                return Err(FmuError::State {
                    call: "fmi2GetRealStatus",
                    state: "but for fmi2LastSuccessfulTime",
                });
            }
            *value = c.instance.time();
            Ok(Status::Ok)
        })
    }
}

/// `fmi2GetBooleanStatus`: `fmi2Terminated` (3) after a failed step.
///
/// # Safety
/// As [`real_status`].
pub unsafe fn boolean_status<P: Plant>(
    instance: *mut c_void,
    kind: c_int,
    value: *mut c_int,
) -> Status {
    // SAFETY: by the caller's contract.
    unsafe {
        component::with::<P>(instance, |c: &mut Component<P>| {
            if kind != 3 || value.is_null() {
                return Err(FmuError::State {
                    call: "fmi2GetBooleanStatus",
                    state: "but for fmi2Terminated",
                });
            }
            *value = c_int::from(c.instance.mode() == Mode::Failed);
            Ok(Status::Ok)
        })
    }
}

/// Exports the FMI 2.0 functions for `$vehicle` (used by
/// [`export_fmu!`](crate::export_fmu)).
#[doc(hidden)]
#[macro_export]
macro_rules! __export_fmi2 {
    ($v:ty, $engine:expr) => {
        const _: () = {
            use ::std::ffi::{c_char, c_int, c_void};
            use $crate::component::{self as c, Status};
            use $crate::fmi2;

            #[unsafe(no_mangle)]
            pub extern "C" fn fmi2GetTypesPlatform() -> *const c_char {
                fmi2::TYPES_PLATFORM.as_ptr()
            }

            #[unsafe(no_mangle)]
            pub extern "C" fn fmi2GetVersion() -> *const c_char {
                fmi2::VERSION.as_ptr()
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2SetDebugLogging(
                instance: *mut c_void,
                _on: c_int,
                _n: usize,
                _categories: *const *const c_char,
            ) -> c_int {
                unsafe { c::with::<$v>(instance, |_| Ok(Status::Ok)) as c_int }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2Instantiate(
                name: *const c_char,
                kind: c_int,
                guid: *const c_char,
                _resources: *const c_char,
                callbacks: *const fmi2::Callbacks,
                _visible: c_int,
                _logging_on: c_int,
            ) -> *mut c_void {
                unsafe { fmi2::instantiate::<$v>(name, kind, guid, callbacks, $engine) }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2FreeInstance(instance: *mut c_void) {
                unsafe { c::free::<$v>(instance) }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2SetupExperiment(
                instance: *mut c_void,
                tolerance_defined: c_int,
                tolerance: f64,
                start: f64,
                stop_defined: c_int,
                stop: f64,
            ) -> c_int {
                unsafe {
                    c::with::<$v>(instance, |c| {
                        c.instance
                            .setup_experiment(
                                (tolerance_defined != 0).then_some(tolerance),
                                start,
                                (stop_defined != 0).then_some(stop),
                            )
                            .map(|()| Status::Ok)
                    }) as c_int
                }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2EnterInitializationMode(instance: *mut c_void) -> c_int {
                unsafe {
                    c::with::<$v>(instance, |c| {
                        c.instance.enter_initialization().map(|()| Status::Ok)
                    }) as c_int
                }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2ExitInitializationMode(instance: *mut c_void) -> c_int {
                unsafe {
                    c::with::<$v>(instance, |c| {
                        c.instance.exit_initialization().map(|()| Status::Ok)
                    }) as c_int
                }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2Terminate(instance: *mut c_void) -> c_int {
                unsafe { c::with::<$v>(instance, |c| c.instance.terminate().map(|()| Status::Ok)) as c_int }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2Reset(instance: *mut c_void) -> c_int {
                unsafe {
                    c::with::<$v>(instance, |c| {
                        c.instance.reset();
                        Ok(Status::Ok)
                    }) as c_int
                }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2GetReal(
                instance: *mut c_void,
                refs: *const u32,
                n: usize,
                values: *mut f64,
            ) -> c_int {
                unsafe { $crate::fmi3::get::<$v, f64>(instance, (refs, n), (values, n)) as c_int }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2SetReal(
                instance: *mut c_void,
                refs: *const u32,
                n: usize,
                values: *const f64,
            ) -> c_int {
                unsafe { $crate::fmi3::set::<$v, f64>(instance, (refs, n), (values, n)) as c_int }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2GetInteger(
                instance: *mut c_void,
                refs: *const u32,
                n: usize,
                values: *mut i32,
            ) -> c_int {
                unsafe { $crate::fmi3::get::<$v, i32>(instance, (refs, n), (values, n)) as c_int }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2SetInteger(
                instance: *mut c_void,
                refs: *const u32,
                n: usize,
                values: *const i32,
            ) -> c_int {
                unsafe { $crate::fmi3::set::<$v, i32>(instance, (refs, n), (values, n)) as c_int }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2GetString(
                instance: *mut c_void,
                refs: *const u32,
                n: usize,
                values: *mut *const c_char,
            ) -> c_int {
                unsafe { fmi2::get_string::<$v>(instance, refs, n, values) as c_int }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2SetString(
                instance: *mut c_void,
                refs: *const u32,
                n: usize,
                values: *const *const c_char,
            ) -> c_int {
                unsafe { fmi2::set_string::<$v>(instance, refs, n, values) as c_int }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2DoStep(
                instance: *mut c_void,
                t: f64,
                h: f64,
                _no_set_state_prior: c_int,
            ) -> c_int {
                unsafe {
                    c::with::<$v>(instance, |c| c.instance.do_step(t, h).map(|()| Status::Ok)) as c_int
                }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2GetRealStatus(
                instance: *mut c_void,
                kind: c_int,
                value: *mut f64,
            ) -> c_int {
                unsafe { fmi2::real_status::<$v>(instance, kind, value) as c_int }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2GetBooleanStatus(
                instance: *mut c_void,
                kind: c_int,
                value: *mut c_int,
            ) -> c_int {
                unsafe { fmi2::boolean_status::<$v>(instance, kind, value) as c_int }
            }

            $crate::__fmi2_unsupported!($v;
                fmi2GetBoolean(r: *const u32, n: usize, v: *mut c_int),
                fmi2SetBoolean(r: *const u32, n: usize, v: *const c_int),
                fmi2GetFMUstate(s: *mut *mut c_void),
                fmi2SetFMUstate(s: *mut c_void),
                fmi2FreeFMUstate(s: *mut *mut c_void),
                fmi2SerializedFMUstateSize(s: *mut c_void, n: *mut usize),
                fmi2SerializeFMUstate(s: *mut c_void, b: *mut c_char, n: usize),
                fmi2DeSerializeFMUstate(b: *const c_char, n: usize, s: *mut *mut c_void),
                fmi2GetDirectionalDerivative(u: *const u32, nu: usize, k: *const u32, nk: usize, dv: *const f64, o: *mut f64),
                fmi2SetRealInputDerivatives(r: *const u32, n: usize, o: *const c_int, v: *const f64),
                fmi2GetRealOutputDerivatives(r: *const u32, n: usize, o: *const c_int, v: *mut f64),
                fmi2CancelStep(),
                fmi2GetStatus(k: c_int, v: *mut c_int),
                fmi2GetIntegerStatus(k: c_int, v: *mut c_int),
                fmi2GetStringStatus(k: c_int, v: *mut *const c_char),
                fmi2CompletedIntegratorStep(no_set: c_int, event: *mut c_int, terminate: *mut c_int),
                fmi2EnterContinuousTimeMode(),
                fmi2EnterEventMode(),
                fmi2GetContinuousStates(v: *mut f64, n: usize),
                fmi2GetDerivatives(v: *mut f64, n: usize),
                fmi2GetEventIndicators(v: *mut f64, n: usize),
                fmi2GetNominalsOfContinuousStates(v: *mut f64, n: usize),
                fmi2NewDiscreteStates(info: *mut c_void),
                fmi2SetContinuousStates(v: *const f64, n: usize),
                fmi2SetTime(t: f64),
            );
        };
    };
}

/// Exports FMI 2.0 functions this FMU does not provide, with the
/// standard's signatures (used by [`export_fmu!`](crate::export_fmu)).
#[doc(hidden)]
#[macro_export]
macro_rules! __fmi2_unsupported {
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
