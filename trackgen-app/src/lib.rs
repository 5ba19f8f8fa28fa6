//! The trackgen application for any declared vehicle: the main job
//! (`run`), the mobility events (`mobility`), the modes at rest (`modes`),
//! the steady turns estimated from the loads at rest (`steer`) and the
//! FMU's packing (`fmu`), as one command line.
//!
//! A user's own binary gets every subcommand, option, output and report
//! the built-in vehicles have:
//!
//! ```no_run
//! # use trackgen::vehicles::m113::M113 as MyTank;
//! fn main() -> std::process::ExitCode {
//!     trackgen_app::main::<MyTank>()
//! }
//! ```
//!
//! and a binary offering several vehicles (chosen with `--vehicle`, the
//! first the default) lists them, each with what the vehicle's declaration
//! cannot say (a powertrain given as a function, its published figures):
//!
//! ```no_run
//! use trackgen::vehicles::{m113::{self, M113}, marder::{self, Marder}};
//! use trackgen_app::{App, Entry};
//!
//! fn main() -> std::process::ExitCode {
//!     App::new()
//!         .vehicle(Entry::of::<M113>().published(&m113::PUBLISHED))
//!         .vehicle(Entry::of::<Marder>().published(&marder::PUBLISHED))
//!         .main()
//! }
//! ```
//!
//! `run` is the default subcommand: `my-tank --speed 5` is
//! `my-tank run --speed 5`.

mod app;
mod cli;
mod console;
mod fmu;
mod mobility;
mod modes;
mod nearest;
mod offered;
mod outputs;
mod report;
mod run;
mod spatial;
mod spatial_driveline;
mod spatial_frames;
mod spatial_modes;
mod spatial_rows;
mod steer;
mod turn_runs;

pub use app::{App, Entry, main};
