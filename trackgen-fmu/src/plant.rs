//! What an FMU's model is to its instance: the planar vehicle (one side
//! in the pitch plane, [`Vehicle`](trackgen::vehicle::Vehicle)) or the
//! spatial one (both tracks and the hull, [`Spatial`](crate::Spatial)).
//! The instance keeps FMI's state machine, the variables' values and the
//! run's order of steps; the plant builds the run from the parameters,
//! takes the inputs and reads the outputs.

use std::sync::atomic::{AtomicU64, Ordering};

use trackgen::integrate::{Integrator, OdeSystem, SimulationError};
use trackgen::nalgebra::DVector;
use trackgen::simulate::March;
use trackgen::vehicle::Powertrain;

use crate::error::FmuError;
use crate::instance::Instance;
use crate::variables::{Input, Setting, Variable};

/// A model an FMU exports: its variables, how its run is built from
/// them, and what it records.
pub trait Plant: Sized + 'static {
    /// The system the run integrates.
    type System: OdeSystem;

    /// The model's name (the model description's `modelName`; the
    /// identifier and the library's name are made from it).
    fn name() -> String;

    /// What the model is, after its name in the model description.
    fn summary() -> &'static str;

    /// The default experiment: its stop time and communication step, s
    /// (the main job's duration and rows).
    fn default_experiment() -> (f64, f64);

    /// The engine the parameter `engine = 1` drives through where the
    /// library was exported with none: the vehicle's declared one, if any.
    fn declared_powertrain() -> Option<Powertrain> {
        None
    }

    /// The variables: parameters, inputs, then the outputs.
    fn table() -> Result<Vec<Variable>, FmuError>;

    /// The run the instance's parameters and inputs name: the system, its
    /// state at the start and the integrator.
    fn build(
        instance: &Instance<Self>,
    ) -> Result<(Self::System, DVector<f64>, Integrator), FmuError>;

    /// After an accepted step, the system's own rule between steps (the
    /// planar closure's switching and projection, a spatial gearbox's
    /// shifts), the integrator restarted where it asks.
    fn settle(system: &mut Self::System, march: &mut March) -> Result<(), SimulationError>;

    /// What [`observe`](Self::observe) finds once per run (where the books
    /// sit among the recorded columns).
    type Reader;

    /// The run's [`Reader`](Self::Reader), from its system.
    fn reader(system: &Self::System) -> Self::Reader;

    /// The recorded row at `at`, `(t, y)`, into `row` (one value per output
    /// column), and the books: the drive's work, the energy held and the
    /// energy dissipated since the run's start, J.
    fn observe(
        system: &mut Self::System,
        reader: &Self::Reader,
        at: (f64, &[f64]),
        row: &mut Vec<f64>,
    ) -> Result<[f64; 3], FmuError>;

    /// The input `input` set to `value` at the communication point `t`
    /// (s): into `cells`, which the run's drives read, or the running
    /// `system` (where there is one). `Err` says why it is refused.
    fn set_input(
        cells: &Cells,
        system: Option<&mut Self::System>,
        input: (Input, f64, f64),
    ) -> Result<(), String>;

    /// Why a number's value is refused, if it is (checked when set).
    fn check_number(variable: &Variable, value: f64) -> Result<(), FmuError> {
        crate::instance::check_number(variable, value)
    }

    /// Why a string parameter's value is refused, if it is (checked when
    /// set).
    fn check_string(setting: Setting, value: &str) -> Result<(), String> {
        crate::instance::check_string(setting, value)
    }
}

/// The inputs the run's closures read while it runs (shared with them):
/// the speed wanted, the torque, and the heading wanted as a line in
/// time (`ψ_ref(t) = ψ₀ + r (t − t₀)`, `r` the yaw rate asked for).
#[derive(Debug, Default)]
pub struct Cells {
    /// The target speed, m/s.
    pub target_speed: AtomicU64,
    /// The drive's torque, N m.
    pub torque: AtomicU64,
    /// The yaw rate asked for, rad/s.
    pub yaw_rate: AtomicU64,
    /// When the yaw rate asked for last changed, s (`t₀`).
    pub heading_from: AtomicU64,
    /// The heading wanted then, rad (`ψ₀`).
    pub heading_then: AtomicU64,
}

impl Cells {
    /// A cell's value.
    pub fn get(cell: &AtomicU64) -> f64 {
        f64::from_bits(cell.load(Ordering::Relaxed))
    }

    /// Sets a cell.
    pub fn set(cell: &AtomicU64, value: f64) {
        cell.store(value.to_bits(), Ordering::Relaxed);
    }

    /// Every cell at 0.
    pub(crate) fn clear(&self) {
        for cell in [
            &self.target_speed,
            &self.torque,
            &self.yaw_rate,
            &self.heading_from,
            &self.heading_then,
        ] {
            Cells::set(cell, 0.0);
        }
    }

    /// The heading wanted at `t` (s) and its rate: rad, rad/s.
    pub fn heading(&self, t: f64) -> (f64, f64) {
        let rate = Cells::get(&self.yaw_rate);
        let from = Cells::get(&self.heading_from);
        (Cells::get(&self.heading_then) + rate * (t - from), rate)
    }

    /// The yaw rate asked for becomes `rate` (rad/s) at `t` (s): the
    /// heading wanted goes on from where it is then, without a jump.
    pub fn turn_at(&self, t: f64, rate: f64) {
        let (heading, _) = self.heading(t);
        Cells::set(&self.heading_then, heading);
        Cells::set(&self.heading_from, t);
        Cells::set(&self.yaw_rate, rate);
    }
}
