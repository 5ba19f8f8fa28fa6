//! What both C APIs share: the instance behind the opaque pointer, its
//! logger, and the boundary every call crosses (null pointers refused,
//! panics caught, errors logged and turned into a status).

use std::ffi::{CStr, CString, c_char, c_int, c_void};
use std::panic::{AssertUnwindSafe, catch_unwind};

use trackgen::vehicle::Powertrain;

use crate::error::FmuError;
use crate::instance::Instance;
use crate::plant::Plant;

/// A status, as both versions number them: OK 0, warning 1, discard 2,
/// error 3, fatal 4.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(C)]
pub enum Status {
    /// The call did what was asked.
    Ok = 0,
    /// Done, with something to say.
    Warning = 1,
    /// Not done, the instance can go on.
    Discard = 2,
    /// Not done; this instance needs a reset or free.
    Error = 3,
    /// Not done; no instance can go on.
    Fatal = 4,
}

/// FMI 3.0's logger: `(instanceEnvironment, status, category, message)`.
pub type Fmi3Logger = unsafe extern "C" fn(
    env: *mut c_void,
    status: c_int,
    category: *const c_char,
    message: *const c_char,
);

/// FMI 2.0's logger: `(componentEnvironment, instanceName, status,
/// category, message, ...)`, printf-style.
pub type Fmi2Logger = unsafe extern "C" fn(
    env: *mut c_void,
    instance_name: *const c_char,
    status: c_int,
    category: *const c_char,
    message: *const c_char,
    ...
);

/// Where messages go.
#[derive(Clone, Copy)]
pub enum Logger {
    /// Nowhere (the master gave none).
    None,
    /// An FMI 3.0 master's.
    Fmi3(Fmi3Logger, *mut c_void),
    /// An FMI 2.0 master's.
    Fmi2(Fmi2Logger, *mut c_void),
}

/// An instance behind the C API's opaque pointer.
pub struct Component<P: Plant> {
    /// The instance.
    pub instance: Instance<P>,
    name: CString,
    logger: Logger,
    /// Strings handed to the master, alive until the next call that reads
    /// strings (as the standard allows).
    pub strings: Vec<CString>,
}

impl<P: Plant> Component<P> {
    /// A new instance named `name` logging to `logger`, with the engine
    /// the library was exported with, else the vehicle's declared one
    /// ([`Plant::declared_powertrain`]), if any; `None` (after logging why) if
    /// the vehicle cannot be built.
    pub fn create(
        name: &str,
        logger: Logger,
        engine: Option<fn() -> Powertrain>,
    ) -> Option<Box<Component<P>>> {
        let name = CString::new(name.replace('\0', " ")).unwrap_or_default();
        let created = catch_unwind(|| {
            Instance::<P>::with_engine(engine.map(|f| f()).or_else(P::declared_powertrain))
        });
        match created {
            Ok(Ok(instance)) => Some(Box::new(Component {
                instance,
                name,
                logger,
                strings: Vec::new(),
            })),
            Ok(Err(e)) => {
                log(logger, &name, Status::Error, &e.to_string());
                None
            }
            Err(panic) => {
                log(
                    logger,
                    &name,
                    Status::Error,
                    &FmuError::Panic(panic_text(&*panic)).to_string(),
                );
                None
            }
        }
    }

    /// Logs a message at `status`.
    pub fn log(&self, status: Status, message: &str) {
        log(self.logger, &self.name, status, message);
    }
}

fn log(logger: Logger, name: &CStr, status: Status, message: &str) {
    let category: &CStr = match status {
        Status::Ok => c"logStatusOK",
        Status::Warning => c"logStatusWarning",
        Status::Discard => c"logStatusDiscard",
        Status::Error => c"logStatusError",
        Status::Fatal => c"logStatusFatal",
    };
    let message = CString::new(message.replace('\0', " ")).unwrap_or_default();
    match logger {
        Logger::None => {}
        // SAFETY: the master gave these callbacks for this instance's
        // lifetime; the strings outlive the calls.
        Logger::Fmi3(f, env) => unsafe {
            f(env, status as c_int, category.as_ptr(), message.as_ptr())
        },
        // The message goes as an argument of "%s", never as the format.
        Logger::Fmi2(f, env) => unsafe {
            f(
                env,
                name.as_ptr(),
                status as c_int,
                category.as_ptr(),
                c"%s".as_ptr(),
                message.as_ptr(),
            )
        },
    }
}

fn panic_text(panic: &(dyn std::any::Any + Send)) -> String {
    panic
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| panic.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "no message".into())
}

/// Runs `call` on the instance behind `pointer`: a null pointer is an
/// error (nothing to log to), a panic is caught and logged, an error is
/// logged; the status says which.
///
/// # Safety
/// `pointer` is null or a pointer this library returned from an
/// instantiate function and has not freed.
pub unsafe fn with<P: Plant>(
    pointer: *mut c_void,
    call: impl FnOnce(&mut Component<P>) -> Result<Status, FmuError>,
) -> Status {
    if pointer.is_null() {
        return Status::Error;
    }
    // SAFETY: by the caller's contract.
    let component = unsafe { &mut *(pointer as *mut Component<P>) };
    let logger = (component.logger, component.name.clone());
    match catch_unwind(AssertUnwindSafe(|| call(component))) {
        Ok(Ok(status)) => status,
        Ok(Err(e)) => {
            log(logger.0, &logger.1, Status::Error, &e.to_string());
            Status::Error
        }
        Err(panic) => {
            log(
                logger.0,
                &logger.1,
                Status::Error,
                &FmuError::Panic(panic_text(&*panic)).to_string(),
            );
            Status::Error
        }
    }
}

/// Frees an instance.
///
/// # Safety
/// As [`with`]; the pointer is not used again.
pub unsafe fn free<P: Plant>(pointer: *mut c_void) {
    if !pointer.is_null() {
        // SAFETY: by the caller's contract, a box this library leaked.
        let component = unsafe { Box::from_raw(pointer as *mut Component<P>) };
        let _ = catch_unwind(AssertUnwindSafe(move || drop(component)));
    }
}

/// The `n` elements at `pointer` (none for a null pointer with `n = 0`).
///
/// # Safety
/// `pointer` points to `n` valid elements, or `n` is 0.
pub unsafe fn slice<'a, T>(pointer: *const T, n: usize) -> Result<&'a [T], FmuError> {
    if n == 0 {
        Ok(&[])
    } else if pointer.is_null() {
        Err(FmuError::Step("a null array with a non-zero length".into()))
    } else {
        // SAFETY: by the caller's contract.
        Ok(unsafe { std::slice::from_raw_parts(pointer, n) })
    }
}

/// As [`slice()`], mutable.
///
/// # Safety
/// As [`slice()`].
pub unsafe fn slice_mut<'a, T>(pointer: *mut T, n: usize) -> Result<&'a mut [T], FmuError> {
    if n == 0 {
        Ok(&mut [])
    } else if pointer.is_null() {
        Err(FmuError::Step("a null array with a non-zero length".into()))
    } else {
        // SAFETY: by the caller's contract.
        Ok(unsafe { std::slice::from_raw_parts_mut(pointer, n) })
    }
}

/// A C string given by the master (`""` for a null pointer).
///
/// # Safety
/// `pointer` is null or a NUL-terminated string.
pub unsafe fn text<'a>(pointer: *const c_char) -> Result<&'a str, FmuError> {
    if pointer.is_null() {
        return Ok("");
    }
    // SAFETY: by the caller's contract.
    unsafe { CStr::from_ptr(pointer) }
        .to_str()
        .map_err(|_| FmuError::Step("a string that is not UTF-8".into()))
}
