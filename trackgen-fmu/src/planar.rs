//! The planar vehicle as an FMU's model: one side in the pitch plane,
//! the main job's run ([`Scenario`]) from the parameters.

use std::sync::Arc;

use trackgen::integrate::{Integrator, SimulationError};
use trackgen::nalgebra::DVector;
use trackgen::scenario::{Method, Scenario};
use trackgen::simulate::{DISSIPATED, ENERGY, MOTOR_WORK, March};
use trackgen::system::Simulated;
use trackgen::vehicle::{Drive, Vehicle, VehicleDynamics};

use crate::error::FmuError;
use crate::instance::Instance;
use crate::plant::{Cells, Plant};
use crate::variables::{self, Input, Role, Setting, Variable};

impl<V: Vehicle> Plant for V {
    type System = V::System;

    fn name() -> String {
        V::NAME.to_string()
    }

    fn summary() -> &'static str {
        "one side, pitch plane"
    }

    fn default_experiment() -> (f64, f64) {
        // The main job's: 8 s, rows every 10 ms.
        (8.0, 0.01)
    }

    fn declared_powertrain() -> Option<trackgen::vehicle::Powertrain> {
        V::powertrain()
    }

    fn table() -> Result<Vec<Variable>, FmuError> {
        variables::table::<V>()
    }

    fn build(instance: &Instance<V>) -> Result<(V::System, DVector<f64>, Integrator), FmuError> {
        let mut system =
            V::system_with(instance.config()?).map_err(|e| FmuError::Build(e.to_string()))?;
        variables::check_columns(instance.variables(), &system)?;
        system
            .set_drawbar_pull(instance.input(Input::DrawbarPull))
            .map_err(|e| FmuError::Build(e.to_string()))?;
        let y = system.initial_state();
        Ok((system, y, instance.integrator()))
    }

    fn settle(system: &mut V::System, march: &mut March) -> Result<(), SimulationError> {
        march.settle(system, &mut |_| {})
    }

    /// The books' columns (the motor's work, the energy, the dissipated
    /// work), `usize::MAX` where one is not recorded.
    type Reader = [usize; 3];

    fn reader(system: &V::System) -> [usize; 3] {
        let columns = system.columns();
        [MOTOR_WORK, ENERGY, DISSIPATED]
            .map(|name| columns.iter().position(|c| c == name).unwrap_or(usize::MAX))
    }

    fn observe(
        system: &mut V::System,
        books: &[usize; 3],
        (t, y): (f64, &[f64]),
        row: &mut Vec<f64>,
    ) -> Result<[f64; 3], FmuError> {
        row.clear();
        system
            .observe(t, y, row)
            .map_err(|e| FmuError::Run(e.to_string()))?;
        Ok(books.map(|i| row.get(i).copied().unwrap_or(f64::NAN)))
    }

    fn set_input(
        cells: &Cells,
        system: Option<&mut V::System>,
        (input, _, value): (Input, f64, f64),
    ) -> Result<(), String> {
        match input {
            Input::TargetSpeed => Cells::set(&cells.target_speed, value),
            Input::DriveTorque => Cells::set(&cells.torque, value),
            Input::DrawbarPull => {
                if let Some(system) = system {
                    system.set_drawbar_pull(value).map_err(|e| e.to_string())?;
                }
            }
            Input::TargetYawRate => return Err("not an input of the planar vehicle".into()),
        }
        Ok(())
    }
}

impl<V: Vehicle> Instance<V> {
    /// The integrator: the main job's (chosen by stiffness, steps of at
    /// most 10 ms) at the `tolerance` parameter, else the master's, else
    /// the main job's defaults.
    pub(crate) fn integrator(&self) -> Integrator {
        Scenario {
            method: Method::Auto,
            tolerance: self.tolerance(),
            ..Scenario::default()
        }
        .integrator()
    }

    /// The run the parameters name, as the main job's [`Scenario`]: the
    /// course, the soil, the speed profile, the engine and the integrator
    /// (`auto` at the `tolerance` parameter, else the master's, else the
    /// defaults). The master, not the scenario, sets the duration and the
    /// communication points. With every parameter at its start value,
    /// [`Scenario::default`] (a test holds them to it).
    pub fn scenario(&self) -> Result<Scenario, FmuError> {
        let scenario = Scenario {
            course: self.course()?,
            soil: self.soil()?,
            speed: self.number(Setting::Speed),
            settle: self.number(Setting::Settle),
            ramp: self.number(Setting::Ramp),
            engine: self.integer(Setting::Engine) == 1,
            method: Method::Auto,
            tolerance: self.tolerance(),
            ..Scenario::default()
        };
        // Each parameter was checked when set; the whole is held to the
        // scenario's own ranges as well.
        scenario.check().map_err(|e| FmuError::Parameter {
            name: e.setting.to_string(),
            value: e.value.to_string(),
            why: e.range.to_string(),
        })?;
        Ok(scenario)
    }

    /// The vehicle's configuration from the parameters.
    pub(crate) fn config(&self) -> Result<trackgen::vehicle::VehicleConfig, FmuError> {
        let scenario = self.scenario()?;
        let terrain = scenario
            .terrain()
            .map_err(|e| FmuError::Build(e.to_string()))?;
        let drive = match self.text(Setting::Drive) {
            "profile" => V::speed_drive(scenario.speed_profile()),
            "speed" => {
                let cells = Arc::clone(&self.cells);
                V::speed_drive(move |_| Cells::get(&cells.target_speed))
            }
            "torque" => {
                let cells = Arc::clone(&self.cells);
                Drive::Torque(Box::new(move |_| Cells::get(&cells.torque)))
            }
            other => {
                return Err(self.refuse_text("drive", &other, "one of profile, speed, torque"));
            }
        };
        let powertrain = if scenario.engine {
            Some(self.engine.clone().ok_or_else(|| {
                self.refuse_text(
                    "engine",
                    &1,
                    "this FMU has no engine: its vehicle declares no powertrain and export_fmu! \
                     was given none",
                )
            })?)
        } else {
            None
        };
        let mut config = scenario.config_with::<V>(terrain, drive, powertrain);
        for (i, (_, body)) in variables::arm_names::<V>().iter().enumerate() {
            let value = |role: Role| self.number_of(role);
            if let Some(arm) = config.arms.iter_mut().find(|a| a.body == *body) {
                arm.spring.stiffness = value(Role::ArmStiffness(i));
                arm.spring.damping = value(Role::ArmDamping(i));
            }
        }
        Ok(config)
    }
}
