//! One FMU instance: its variables, FMI's state machine, and the run it
//! advances communication step by communication step.
//!
//! The run is a [`March`]: the integrator steps to the stop time as a
//! native run does, never clipped at a communication point; the outputs
//! at a communication point come from the step that covers it by dense
//! output, and that step's [`settle`](March::settle) waits for the next
//! `doStep`. So with inputs that do not change, the outputs equal the
//! native run's bit for bit. When the master changes an input or the
//! drawbar, the rest of the step past the communication point (taken with
//! the old values) is dropped and the run goes on from the communication
//! point's state.

use std::sync::Arc;

use trackgen::nalgebra::DVector;
use trackgen::scenario::{Range, Scenario, Soil};
use trackgen::simulate::{EnergyBalance, March};
use trackgen::terrain::course::{self, CourseSpec};
use trackgen::terrain::soil::SoilPreset;
use trackgen::vehicle::Powertrain;

use crate::error::FmuError;
use crate::plant::{Cells, Plant};
use crate::variables::{Causality, Input, Kind, Role, Setting, Start, Variable};

/// Where the instance is in FMI's state machine.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// Instantiated: parameters may be set.
    Instantiated,
    /// In initialisation mode: parameters and inputs may be set.
    Initialization,
    /// Stepping.
    Step,
    /// Terminated: outputs may be read.
    Terminated,
    /// A step failed: outputs may be read (the last communication point's);
    /// reset or free.
    Failed,
}

impl Mode {
    fn words(self) -> &'static str {
        match self {
            Mode::Instantiated => "before initialisation",
            Mode::Initialization => "in initialisation mode",
            Mode::Step => "in step mode",
            Mode::Terminated => "after terminate",
            Mode::Failed => "after a failed step (reset or free the instance)",
        }
    }
}

/// The run under way.
struct Running<P: Plant> {
    system: P::System,
    march: March,
    /// The last step covers the communication point reached and has not
    /// been settled ([`March::settle`]) yet.
    pending: bool,
    /// The communication point reached, s, and the state there.
    t: f64,
    y: DVector<f64>,
    /// The drive's work, the energy and the dissipated work at the start,
    /// J.
    books: [f64; 3],
    /// What reading a row finds once.
    reader: P::Reader,
    /// The last row read (its storage kept).
    row: Vec<f64>,
}

/// An FMU instance of the model `P`: a vehicle `V` (one side in the
/// pitch plane), or [`Spatial<V>`](crate::Spatial) (both tracks and the
/// hull in 3-D).
pub struct Instance<P: Plant> {
    table: Vec<Variable>,
    /// Every variable's value by value reference (a number in `numbers`,
    /// an integer in `integers`, a string in `strings`).
    numbers: Vec<f64>,
    integers: Vec<i32>,
    strings: Vec<String>,
    mode: Mode,
    start_time: f64,
    stop_time: Option<f64>,
    master_tolerance: Option<f64>,
    pub(crate) cells: Arc<Cells>,
    /// An input was changed since the last communication point.
    inputs_changed: bool,
    run: Option<Running<P>>,
    /// The engine `engine = 1` drives through.
    pub(crate) engine: Option<Powertrain>,
}

/// Without a stop time the run ends this long after its start, s.
const OPEN_END: f64 = 1e6;

impl<P: Plant> Instance<P> {
    /// A new instance with every variable at its start value, without an
    /// engine (the parameter `engine` must stay 0).
    pub fn new() -> Result<Self, FmuError> {
        Self::with_engine(None)
    }

    /// A new instance whose parameter `engine = 1` drives through
    /// `engine`.
    pub fn with_engine(engine: Option<Powertrain>) -> Result<Self, FmuError> {
        let table = P::table()?;
        let n = table.len();
        let mut instance = Instance {
            numbers: vec![f64::NAN; n],
            integers: vec![0; n],
            strings: vec![String::new(); n],
            table,
            mode: Mode::Instantiated,
            start_time: 0.0,
            stop_time: None,
            master_tolerance: None,
            cells: Arc::default(),
            inputs_changed: false,
            run: None,
            engine,
        };
        instance.set_start_values();
        Ok(instance)
    }

    fn set_start_values(&mut self) {
        for (i, v) in self.table.iter().enumerate() {
            match &v.start {
                Start::Float64(x) => self.numbers[i] = *x,
                Start::Int32(k) => self.integers[i] = *k,
                Start::String(s) => self.strings[i] = s.clone(),
                Start::Computed => self.numbers[i] = f64::NAN,
            }
        }
        self.cells.clear();
    }

    /// The variables (the model description's).
    pub fn variables(&self) -> &[Variable] {
        &self.table
    }

    /// Where the instance is in FMI's state machine.
    pub fn mode(&self) -> Mode {
        self.mode
    }

    /// The communication point reached, s (the start time before the run).
    pub fn time(&self) -> f64 {
        self.run.as_ref().map_or(self.start_time, |r| r.t)
    }

    /// The experiment: the master's tolerance (if it gives one), the start
    /// and the stop time, s (FMI 2.0's `fmi2SetupExperiment`; FMI 3.0
    /// gives them on entering initialisation).
    pub fn setup_experiment(
        &mut self,
        tolerance: Option<f64>,
        start: f64,
        stop: Option<f64>,
    ) -> Result<(), FmuError> {
        self.expect(&[Mode::Instantiated], "setting up the experiment")?;
        if !start.is_finite() {
            return Err(self.refuse("startTime", start, "a finite time"));
        }
        if let Some(stop) = stop
            && !(stop.is_finite() && stop > start)
        {
            return Err(self.refuse("stopTime", stop, "a finite time after the start"));
        }
        if let Some(tol) = tolerance
            && !Scenario::TOLERANCE_RANGE.contains(tol)
        {
            return Err(self.refuse("tolerance", tol, Scenario::TOLERANCE_RANGE.what));
        }
        self.start_time = start;
        self.stop_time = stop;
        self.master_tolerance = tolerance;
        Ok(())
    }

    /// Enters initialisation mode.
    pub fn enter_initialization(&mut self) -> Result<(), FmuError> {
        self.expect(&[Mode::Instantiated], "entering initialisation mode")?;
        self.mode = Mode::Initialization;
        Ok(())
    }

    /// Leaves initialisation mode: builds the vehicle from the parameters
    /// and starts the run; the outputs are the start's.
    pub fn exit_initialization(&mut self) -> Result<(), FmuError> {
        self.expect(&[Mode::Initialization], "leaving initialisation mode")?;
        let (system, y, integrator) = P::build(self)?;
        let t0 = self.start_time;
        let t_end = self.stop_time.unwrap_or(t0 + OPEN_END);
        let march = March::from_state(integrator, y.clone(), t0, t_end)
            .map_err(|e| FmuError::Build(e.to_string()))?;
        let mut run = Running {
            reader: P::reader(&system),
            system,
            march,
            pending: false,
            t: t0,
            y,
            books: [0.0; 3],
            row: Vec::new(),
        };
        let (row, books) = observe::<P>(&mut run, t0)?;
        run.books = books;
        self.store_outputs(&row, books, books);
        run.row = row;
        self.run = Some(run);
        self.inputs_changed = false;
        self.mode = Mode::Step;
        Ok(())
    }

    /// Advances from the communication point `t` (the one reached) by `h`
    /// (s). On failure the instance keeps the last point's outputs and
    /// takes no more steps.
    pub fn do_step(&mut self, t: f64, h: f64) -> Result<(), FmuError> {
        self.expect(&[Mode::Step], "doStep")?;
        let now = self.time();
        let run = self.run.as_mut().expect("a run in step mode");
        let eps = run.march.eps();
        if !(h.is_finite() && h > 0.0) {
            return Err(FmuError::Step(format!(
                "a communication step is more than 0 s, got {h}"
            )));
        }
        if (t - now).abs() > eps.max(1e-9 * h) {
            return Err(FmuError::Step(format!(
                "the current communication point is t = {now} s, the master gave {t} s"
            )));
        }
        let target = t + h;
        if target > run.march.end() + eps {
            return Err(FmuError::Step(format!(
                "t = {target} s is past the stop time {} s",
                run.march.end()
            )));
        }
        let changed = std::mem::take(&mut self.inputs_changed);
        let result = advance::<P>(run, target, changed);
        match result {
            Ok((row, books)) => {
                let start = self.run.as_ref().expect("a run").books;
                self.store_outputs(&row, start, books);
                self.run.as_mut().expect("a run").row = row;
                Ok(())
            }
            Err(e) => {
                self.mode = Mode::Failed;
                Err(e)
            }
        }
    }

    /// Terminates: outputs stay readable.
    pub fn terminate(&mut self) -> Result<(), FmuError> {
        self.expect(
            &[Mode::Step, Mode::Failed, Mode::Initialization],
            "terminate",
        )?;
        self.mode = Mode::Terminated;
        Ok(())
    }

    /// Back to the state after instantiation: every variable at its start
    /// value, no run.
    pub fn reset(&mut self) {
        self.run = None;
        self.mode = Mode::Instantiated;
        self.start_time = 0.0;
        self.stop_time = None;
        self.master_tolerance = None;
        self.inputs_changed = false;
        self.set_start_values();
    }

    /// Reads numbers.
    pub fn get_f64(&self, refs: &[u32], out: &mut [f64]) -> Result<(), FmuError> {
        for (r, o) in refs.iter().zip(out.iter_mut()) {
            let v = self.variable(*r, Kind::Float64)?;
            if v.causality == Causality::Output && self.run.is_none() {
                return Err(FmuError::State {
                    call: "reading an output",
                    state: "before the end of initialisation (outputs are computed when it ends)",
                });
            }
            *o = self.numbers[*r as usize];
        }
        Ok(())
    }

    /// Reads integers.
    pub fn get_i32(&self, refs: &[u32], out: &mut [i32]) -> Result<(), FmuError> {
        for (r, o) in refs.iter().zip(out.iter_mut()) {
            self.variable(*r, Kind::Int32)?;
            *o = self.integers[*r as usize];
        }
        Ok(())
    }

    /// Reads a string.
    pub fn get_string(&self, r: u32) -> Result<&str, FmuError> {
        self.variable(r, Kind::String)?;
        Ok(&self.strings[r as usize])
    }

    /// Sets numbers: parameters before the run, inputs at any time; each
    /// checked against its range (a refused value leaves the variable as
    /// it was).
    pub fn set_f64(&mut self, refs: &[u32], values: &[f64]) -> Result<(), FmuError> {
        for (r, value) in refs.iter().zip(values) {
            let v = self.variable(*r, Kind::Float64)?.clone();
            self.settable(&v)?;
            P::check_number(&v, *value)?;
            let i = *r as usize;
            if let Role::Input(input) = v.role {
                let t = self.time();
                let system = self.run.as_mut().map(|r| &mut r.system);
                P::set_input(&self.cells, system, (input, t, *value))
                    .map_err(|why| self.refuse_text(&v.name, value, &why))?;
                if self.numbers[i].to_bits() != value.to_bits() {
                    self.inputs_changed = true;
                }
            }
            self.numbers[i] = *value;
        }
        Ok(())
    }

    /// Sets integers (parameters, before the run).
    pub fn set_i32(&mut self, refs: &[u32], values: &[i32]) -> Result<(), FmuError> {
        for (r, value) in refs.iter().zip(values) {
            let v = self.variable(*r, Kind::Int32)?.clone();
            self.settable(&v)?;
            if v.role == Role::Setting(Setting::Engine) && !(0..=1).contains(value) {
                return Err(self.refuse_text(
                    &v.name,
                    value,
                    "0 (the controller alone) or 1 (through the engine)",
                ));
            }
            self.integers[*r as usize] = *value;
        }
        Ok(())
    }

    /// Sets a string (a parameter, before the run), checked at once.
    pub fn set_string(&mut self, r: u32, value: &str) -> Result<(), FmuError> {
        let v = self.variable(r, Kind::String)?.clone();
        self.settable(&v)?;
        if let Role::Setting(setting) = v.role {
            P::check_string(setting, value).map_err(|why| FmuError::Parameter {
                name: v.name.clone(),
                value: format!("\"{value}\""),
                why,
            })?;
        }
        self.strings[r as usize] = value.to_string();
        Ok(())
    }

    fn variable(&self, r: u32, kind: Kind) -> Result<&Variable, FmuError> {
        self.table
            .get(r as usize)
            .filter(|v| v.kind == kind)
            .ok_or(FmuError::ValueReference {
                value_reference: r,
                kind: match kind {
                    Kind::Float64 => "Float64",
                    Kind::Int32 => "Int32",
                    Kind::String => "String",
                },
            })
    }

    fn settable(&self, v: &Variable) -> Result<(), FmuError> {
        let allowed: &[Mode] = match v.causality {
            Causality::Parameter => &[Mode::Instantiated, Mode::Initialization],
            Causality::Input => &[Mode::Instantiated, Mode::Initialization, Mode::Step],
            Causality::Output | Causality::Independent => {
                return Err(FmuError::Parameter {
                    name: v.name.clone(),
                    value: "(any)".into(),
                    why: "computed by the FMU, not set".into(),
                });
            }
        };
        self.expect(allowed, "setting a variable")
    }

    fn expect(&self, allowed: &[Mode], call: &'static str) -> Result<(), FmuError> {
        if allowed.contains(&self.mode) {
            Ok(())
        } else {
            Err(FmuError::State {
                call,
                state: self.mode.words(),
            })
        }
    }

    pub(crate) fn refuse(&self, name: &str, value: f64, why: &str) -> FmuError {
        self.refuse_text(name, &value, why)
    }

    pub(crate) fn refuse_text(
        &self,
        name: &str,
        value: &dyn std::fmt::Display,
        why: &str,
    ) -> FmuError {
        FmuError::Parameter {
            name: name.to_string(),
            value: value.to_string(),
            why: why.to_string(),
        }
    }

    pub(crate) fn setting(&self, setting: Setting) -> usize {
        self.table
            .iter()
            .position(|v| v.role == Role::Setting(setting))
            .expect("every setting is in the table")
    }

    pub(crate) fn number(&self, setting: Setting) -> f64 {
        self.numbers[self.setting(setting)]
    }

    pub(crate) fn text(&self, setting: Setting) -> &str {
        &self.strings[self.setting(setting)]
    }

    pub(crate) fn input(&self, input: Input) -> f64 {
        let i = self
            .table
            .iter()
            .position(|v| v.role == Role::Input(input))
            .expect("every input is in the table");
        self.numbers[i]
    }

    /// The `tolerance` parameter where it is set (above 0), else the
    /// master's.
    pub(crate) fn tolerance(&self) -> Option<f64> {
        Some(self.number(Setting::Tolerance))
            .filter(|t| *t > 0.0)
            .or(self.master_tolerance)
    }

    /// The soil the `soil` parameter names.
    pub(crate) fn soil(&self) -> Result<Soil, FmuError> {
        let name = self.text(Setting::Soil);
        name.parse().map_err(|_| {
            self.refuse_text(
                "soil",
                &name,
                &format!("rigid or one of {}", SoilPreset::names()),
            )
        })
    }

    /// The course the parameters name.
    pub(crate) fn course(&self) -> Result<CourseSpec, FmuError> {
        let course = self.text(Setting::Course);
        Ok(match course {
            "flat" => CourseSpec::Flat,
            "bump" => CourseSpec::Bump {
                at: self.number(Setting::BumpAt),
                height: self.number(Setting::BumpHeight),
            },
            "file" => CourseSpec::File(self.text(Setting::CourseFile).into()),
            "random" => {
                let roughness =
                    course::roughness(self.text(Setting::Roughness)).map_err(|why| {
                        self.refuse_text("roughness", &self.text(Setting::Roughness), &why)
                    })?;
                let seed = self.integers[self.setting(Setting::Seed)];
                let seed = u64::try_from(seed)
                    .map_err(|_| self.refuse("seed", f64::from(seed), "0 or more"))?;
                let given = self.number(Setting::CourseLength);
                let length = if given > 0.0 {
                    given
                } else {
                    let duration = self.stop_time.map_or(60.0, |s| s - self.start_time);
                    course::rough_length(self.number(Setting::Speed), duration)
                        .min(Scenario::COURSE_LENGTH_RANGE.hi)
                };
                CourseSpec::Rough {
                    roughness,
                    seed,
                    length,
                }
            }
            "obstacle" => CourseSpec::Obstacle {
                obstacle: course::obstacle(self.text(Setting::Obstacle)).map_err(|why| {
                    self.refuse_text("obstacle", &self.text(Setting::Obstacle), &why)
                })?,
                at: self.number(Setting::ObstacleAt),
            },
            other => {
                return Err(self.refuse_text(
                    "course",
                    &other,
                    "one of flat, bump, file, random, obstacle",
                ));
            }
        })
    }

    /// The outputs from a recorded row; the books' residual from the
    /// books at the start and now (the drive's work, the energy held, the
    /// energy dissipated, J).
    fn store_outputs(&mut self, row: &[f64], start: [f64; 3], now: [f64; 3]) {
        let books = EnergyBalance {
            motor_work: now[0] - start[0],
            energy_change: now[1] - start[1],
            dissipated: now[2] - start[2],
        };
        for (i, v) in self.table.iter().enumerate() {
            match v.role {
                Role::Column(c) => self.numbers[i] = row[c],
                Role::BooksResidual => self.numbers[i] = books.residual(),
                Role::Time => self.numbers[i] = self.run.as_ref().map_or(self.start_time, |r| r.t),
                _ => {}
            }
        }
    }

    /// The master's tolerance, if it gave one.
    pub(crate) fn master_tolerance(&self) -> Option<f64> {
        self.master_tolerance
    }

    /// The integer parameter `setting`.
    pub(crate) fn integer(&self, setting: Setting) -> i32 {
        self.integers[self.setting(setting)]
    }

    /// The number of the variable whose role is `role`.
    pub(crate) fn number_of(&self, role: Role) -> f64 {
        let k = self
            .table
            .iter()
            .position(|v| v.role == role)
            .expect("a variable of this role");
        self.numbers[k]
    }
}

/// The recorded row at the communication point reached, and the books.
fn observe<P: Plant>(run: &mut Running<P>, t: f64) -> Result<(Vec<f64>, [f64; 3]), FmuError> {
    let mut row = std::mem::take(&mut run.row);
    let books = P::observe(
        &mut run.system,
        &run.reader,
        (t, run.y.as_slice()),
        &mut row,
    )?;
    Ok((row, books))
}

/// The run from its communication point to `target` (s), in the native
/// run's order: the pending step settled (or, inputs `changed`, dropped),
/// steps until one covers `target`, the state there by dense output.
fn advance<P: Plant>(
    run: &mut Running<P>,
    target: f64,
    changed: bool,
) -> Result<(Vec<f64>, [f64; 3]), FmuError> {
    let failed = |e: trackgen::integrate::SimulationError| FmuError::Run(e.to_string());
    let eps = run.march.eps();
    if run.pending {
        if changed {
            run.march.restart_at(run.t, run.y.clone());
            P::settle(&mut run.system, &mut run.march).map_err(failed)?;
            run.pending = false;
        } else if run.march.time() >= target - eps {
            // The same step covers this point too.
            run.y = run.march.state_at(target);
            run.t = target;
            return observe::<P>(run, target);
        } else {
            P::settle(&mut run.system, &mut run.march).map_err(failed)?;
            run.pending = false;
        }
    }
    loop {
        run.march.step(&mut run.system).map_err(failed)?;
        if run.march.time() >= target - eps {
            run.y = run.march.state_at(target);
            run.t = target;
            run.pending = true;
            return observe::<P>(run, target);
        }
        P::settle(&mut run.system, &mut run.march).map_err(failed)?;
    }
}

/// A number's range, by its variable.
pub(crate) fn check_number(v: &Variable, value: f64) -> Result<(), FmuError> {
    // The scenario's figures by the scenario's own ranges
    // ([`Scenario::check`]), as the main job's options are held to them;
    // `zero` is what 0 means where it is allowed besides.
    let within = |range: Range, zero: Option<&str>| {
        if zero.is_some() && value == 0.0 || range.contains(value) {
            Ok(())
        } else {
            Err(FmuError::Parameter {
                name: v.name.clone(),
                value: value.to_string(),
                why: match zero {
                    Some(means) => format!("0 ({means}) or {}", range.what),
                    None => range.what.to_string(),
                },
            })
        }
    };
    let finite = Range::closed(f64::MIN, f64::MAX, "a finite number");
    match v.role {
        Role::Setting(Setting::BumpHeight) => within(Scenario::BUMP_HEIGHT_RANGE, None),
        Role::Setting(Setting::BumpAt | Setting::ObstacleAt) => {
            within(Scenario::POSITION_RANGE, None)
        }
        Role::Setting(Setting::CourseLength) => {
            within(Scenario::COURSE_LENGTH_RANGE, Some("what the run covers"))
        }
        Role::Setting(Setting::Tolerance) => {
            within(Scenario::TOLERANCE_RANGE, Some("the defaults"))
        }
        Role::Setting(Setting::Speed) => within(Scenario::SPEED_RANGE, None),
        Role::Setting(Setting::Settle | Setting::Ramp) => within(Scenario::TIME_RANGE, None),
        Role::ArmStiffness(_) => within(
            Range::open_below(0.0, f64::MAX, "more than 0 N m/rad, finite"),
            None,
        ),
        Role::ArmDamping(_) => within(
            Range::closed(0.0, f64::MAX, "0 or more N m s/rad, finite"),
            None,
        ),
        _ => within(finite, None),
    }
}

/// A string parameter's values, checked when set: why `value` is
/// refused, if it is.
pub(crate) fn check_string(setting: Setting, value: &str) -> Result<(), String> {
    match setting {
        Setting::Course => ["flat", "bump", "file", "random", "obstacle"]
            .contains(&value)
            .then_some(())
            .ok_or_else(|| "one of flat, bump, file, random, obstacle".into()),
        Setting::Drive => ["profile", "speed", "torque"]
            .contains(&value)
            .then_some(())
            .ok_or_else(|| "one of profile, speed, torque".into()),
        Setting::Soil => {
            if value == "rigid" || value.parse::<SoilPreset>().is_ok() {
                Ok(())
            } else {
                Err(format!("rigid or one of {}", SoilPreset::names()))
            }
        }
        Setting::Roughness => course::roughness(value).map(|_| ()),
        Setting::Obstacle => course::obstacle(value).map(|_| ()),
        _ => Ok(()),
    }
}
