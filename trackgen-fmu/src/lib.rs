//! # trackgen-fmu
//!
//! A declared vehicle as a Functional Mock-up Unit: FMI 3.0 and FMI 2.0
//! co-simulation, for fmpy, Simulink, Modelica tools and any other
//! importer; in the pitch plane ([`export_fmu!`]), or in 3-D with both
//! tracks, the hull and steering for a vehicle declared with a `tracks`
//! block ([`export_spatial_fmu!`], the model [`Spatial`]).
//!
//! A `cdylib` crate exports the C API for one vehicle with
//! [`export_fmu!`]; [`write_fmu`] packs the library with its model
//! description into `<Name>.fmu` (3.0) and `<Name>-fmi2.fmu` (2.0).
//! `tools/build-fmu.sh m113 OUTDIR` does both for the M113 (and `marder`
//! for the Marder); for a user's own vehicle, the `fmu` subcommand of
//! its application (`trackgen_app`) packs the library its crate built.
//!
//! ```ignore
//! // src/lib.rs of a crate with `crate-type = ["cdylib", "rlib"]`:
//! trackgen_fmu::export_fmu!(MyVehicle);
//! // then, from its binary (`trackgen_app::main::<MyVehicle>()`):
//! //   my-vehicle fmu --library target/release/libmy_vehicle.so --out fmu
//! // or from any code that links `MyVehicle`:
//! trackgen_fmu::write_fmu::<MyVehicle>(library, out_dir, trackgen_fmu::Version::Fmi3)?;
//! ```
//!
//! The variables ([`variables::table`]): parameters (the course, the soil,
//! the tolerance, the drive and its speed profile, each arm's spring and
//! damper rates), inputs (`target_speed`, `drive_torque`,
//! `drawbar_pull`), and every recorded column as an output with the
//! energy books' residual. The defaults are the main job's, so a default
//! run is the main job's run: the integrator steps to the stop time as a
//! native run does and each communication point is read from the step
//! that covers it ([`Instance`]), so the outputs equal the native run's
//! bit for bit while the inputs are unchanged.
//!
//! No panic crosses the C boundary: every call runs under
//! `catch_unwind`; a refused value, a failed step or a caught panic is an
//! error status with a message through the master's logger.

#![warn(missing_docs)]

pub mod component;
pub mod description;
mod error;
pub mod fmi2;
pub mod fmi3;
mod instance;
mod package;
mod planar;
mod plant;
mod spatial;
pub mod variables;

pub use error::FmuError;
pub use instance::{Instance, Mode};
pub use package::{PackageError, Version, write_fmu};
pub use plant::{Cells, Plant};
pub use spatial::Spatial;

/// Exports the FMI 3.0 and FMI 2.0 co-simulation functions for the
/// vehicle `$vehicle` (a type implementing `trackgen::vehicle::Vehicle`)
/// from the `cdylib` this is written in. One vehicle per library: the
/// functions have the standard's fixed names.
///
/// With `powertrain = f` (a `fn() -> trackgen::vehicle::Powertrain`), the
/// parameter `engine = 1` drives through that engine; without, through the
/// vehicle's declared powertrain (`powertrain { … }` in its declaration),
/// and where it declares none `engine = 1` is refused.
///
/// ```ignore
/// trackgen_fmu::export_fmu!(trackgen::vehicles::m113::M113,
///                           powertrain = trackgen::vehicles::m113::powertrain);
/// ```
#[macro_export]
macro_rules! export_fmu {
    ($vehicle:ty) => {
        $crate::__export_fmi3!($vehicle, None);
        $crate::__export_fmi2!($vehicle, None);
    };
    ($vehicle:ty, powertrain = $powertrain:path $(,)?) => {
        $crate::__export_fmi3!(
            $vehicle,
            Some($powertrain as fn() -> ::trackgen::vehicle::Powertrain)
        );
        $crate::__export_fmi2!(
            $vehicle,
            Some($powertrain as fn() -> ::trackgen::vehicle::Powertrain)
        );
    };
}

/// Exports the FMI 3.0 and FMI 2.0 co-simulation functions for the
/// spatial model of `$vehicle` (a vehicle declared with a `tracks` block:
/// both tracks and the hull in 3-D, [`Spatial`]) from the `cdylib` this
/// is written in; [`write_fmu`]`::<Spatial<V>>` packs it as
/// `<Name>Spatial.fmu`. One model per library, as [`export_fmu!`]; with
/// `powertrain = f`, the parameter `engine = 1` caps each sprocket's
/// drive by that engine's envelope, else by the vehicle's declared one.
///
/// ```ignore
/// trackgen_fmu::export_spatial_fmu!(trackgen::vehicles::m113::M113);
/// ```
#[macro_export]
macro_rules! export_spatial_fmu {
    ($vehicle:ty $(,)?) => {
        $crate::__export_fmi3!($crate::Spatial<$vehicle>, None);
        $crate::__export_fmi2!($crate::Spatial<$vehicle>, None);
    };
    ($vehicle:ty, powertrain = $powertrain:path $(,)?) => {
        $crate::__export_fmi3!(
            $crate::Spatial<$vehicle>,
            Some($powertrain as fn() -> ::trackgen::vehicle::Powertrain)
        );
        $crate::__export_fmi2!(
            $crate::Spatial<$vehicle>,
            Some($powertrain as fn() -> ::trackgen::vehicle::Powertrain)
        );
    };
}
