//! The spatial vehicle as an FMU's model: both tracks and the hull in
//! 3-D ([`SpatialVehicleSystem`]), a speed drive on each sprocket and a
//! driver holding a heading by skid steering, as the applications' 3-D
//! main job (`spatial`) drives it. With every parameter at its start
//! value the run is that main job's: the bump across both tracks, to
//! 3 m/s, a 90° turn to the left from 8 to 12 s, Bogacki-Shampine at its
//! default tolerance.

use std::marker::PhantomData;

use std::sync::Arc;

use trackgen::integrate::{Integrator, SimulationError};
use trackgen::nalgebra::DVector;
use trackgen::scenario::{Range, Scenario};
use trackgen::simulate::March;
use trackgen::spatial_vehicle::{
    DrivelineAsked, DrivelineKind, HeadingHold, SPATIAL_COLUMNS, SpatialGround, SpatialLaws,
    SpatialSimulated, SpatialVehicleSystem, drive_as_asked, on_ground, spatial_row,
};
use trackgen::terrain::course::CourseSpec;
use trackgen::vehicle::{Powertrain, speed_ramp};

use crate::error::FmuError;
use crate::instance::Instance;
use crate::plant::{Cells, Plant};
use crate::variables::{
    Causality, Input, Kind, Role, Setting, SettingRow, Start, Table, Variable, scenario_settings,
};

/// The spatial model of the vehicle `V` (declared with a `tracks`
/// block), as an FMU's [`Plant`]:
/// [`export_spatial_fmu!`](crate::export_spatial_fmu) exports it.
pub struct Spatial<V>(PhantomData<V>);

/// The 3-D main job's turn: degrees, its start and its duration, s.
const TURN: (f64, f64, f64) = (90.0, 8.0, 4.0);
/// The 3-D main job's duration, s.
const DURATION: f64 = 14.0;
/// A turn's range, degrees (the main job's `--turn`).
const TURN_RANGE: Range = Range::closed(-360.0, 360.0, "from -360 to 360 degrees");
/// A side slope's range, rise over run (the main job's `--side-slope`).
const SLOPE_RANGE: Range = Range::closed(-1.0, 1.0, "from -1 to 1");
/// A minimum steer ratio's range (the main job's `--steer-ratio`); 0
/// besides, for none.
const STEER_RATIO_RANGE: Range = Range::closed(1.01, 100.0, "0 (none) or from 1.01 to 100");
/// A yaw rate's range, rad/s: at most the driver's largest
/// ([`HeadingHold::DRIVER_MAX_YAW_RATE`]).
const YAW_RATE_RANGE: Range = Range::closed(
    -HeadingHold::DRIVER_MAX_YAW_RATE,
    HeadingHold::DRIVER_MAX_YAW_RATE,
    "from -1 to 1 rad/s",
);

impl<V: SpatialVehicleSystem + 'static> Plant for Spatial<V> {
    type System = V::Spatial;

    fn name() -> String {
        format!("{}Spatial", V::NAME)
    }

    fn summary() -> &'static str {
        "both tracks and the hull, in 3-D"
    }

    fn default_experiment() -> (f64, f64) {
        (DURATION, Scenario::OUTPUT_EVERY)
    }

    fn declared_powertrain() -> Option<Powertrain> {
        V::powertrain()
    }

    fn table() -> Result<Vec<Variable>, FmuError> {
        Ok(table())
    }

    fn build(
        instance: &Instance<Self>,
    ) -> Result<(V::Spatial, DVector<f64>, Integrator), FmuError> {
        let built = |e: &dyn std::fmt::Display| FmuError::Build(e.to_string());
        let (mut system, mut y) = grounded::<V>(instance)?;
        let target = || -> Box<dyn Fn(f64) -> f64 + Send> {
            match instance.text(Setting::Drive) {
                "speed" => {
                    let cells = Arc::clone(&instance.cells);
                    Box::new(move |_| Cells::get(&cells.target_speed))
                }
                _ => Box::new(speed_ramp(
                    instance.number(Setting::Settle),
                    instance.number(Setting::Ramp),
                    instance.number(Setting::Speed),
                )),
            }
        };
        let asked = DrivelineAsked {
            driveline: DrivelineKind::named(instance.text(Setting::Driveline))
                .unwrap_or(DrivelineKind::Sides),
            steer_ratio: Some(instance.number(Setting::SteerRatio)).filter(|r| *r > 0.0),
            engine: instance.integer(Setting::Engine) == 1,
            speed: instance.number(Setting::Speed),
            powertrain: instance.engine.clone().ok_or_else(|| {
                "this FMU has no engine (engine = 1): its vehicle declares no powertrain and \
                 export_spatial_fmu! was given none"
                    .to_string()
            }),
        };
        drive_as_asked::<V>(&mut system, y.as_mut_slice(), &asked, target)
            .map_err(FmuError::Build)?;
        let gauge = V::layout().gauge;
        let hold = match instance.text(Setting::Steering) {
            "yaw_rate" => {
                let cells = Arc::clone(&instance.cells);
                HeadingHold {
                    heading: Box::new(move |t| cells.heading(t)),
                    gain: HeadingHold::DRIVER_GAIN,
                    max_difference: gauge * HeadingHold::DRIVER_MAX_YAW_RATE,
                }
            }
            _ => HeadingHold::driver(
                instance.number(Setting::Turn).to_radians(),
                (
                    instance.number(Setting::TurnAt),
                    instance.number(Setting::TurnTime),
                ),
                gauge,
            ),
        };
        system.set_steering(hold).map_err(|e| built(&e))?;
        system
            .set_drawbar_pull(instance.input(Input::DrawbarPull))
            .map_err(|e| built(&e))?;
        let tolerance = Some(instance.number(Setting::Tolerance))
            .filter(|t| *t > 0.0)
            .or(instance.master_tolerance())
            .unwrap_or(Integrator::DEFAULT_EXPLICIT_TOLERANCE);
        Ok((system, y, Integrator::bs23(tolerance)))
    }

    fn settle(system: &mut V::Spatial, march: &mut March) -> Result<(), SimulationError> {
        if system.after_step(march.time(), march.state().as_slice()) {
            march.restart();
        }
        Ok(())
    }

    type Reader = ();

    fn reader(_: &V::Spatial) {}

    fn observe(
        system: &mut V::Spatial,
        _: &(),
        (t, y): (f64, &[f64]),
        row: &mut Vec<f64>,
    ) -> Result<[f64; 3], FmuError> {
        let out = system
            .outputs(t, y)
            .map_err(|e| FmuError::Run(e.to_string()))?;
        row.clear();
        row.extend(spatial_row(&out));
        let energy = system.energy(y);
        Ok([energy.driven, energy.held(), energy.dissipated])
    }

    fn set_input(
        cells: &Cells,
        system: Option<&mut V::Spatial>,
        (input, t, value): (Input, f64, f64),
    ) -> Result<(), String> {
        match input {
            Input::TargetSpeed => Cells::set(&cells.target_speed, value),
            Input::TargetYawRate => cells.turn_at(t, value),
            Input::DrawbarPull => {
                if let Some(system) = system {
                    system.set_drawbar_pull(value).map_err(|e| e.to_string())?;
                }
            }
            Input::DriveTorque => return Err("not an input of the spatial vehicle".into()),
        }
        Ok(())
    }

    fn check_number(variable: &Variable, value: f64) -> Result<(), FmuError> {
        if variable.role == Role::Setting(Setting::SteerRatio) && value == 0.0 {
            return Ok(());
        }
        match range(variable.role) {
            Some(range) if !range.contains(value) => Err(FmuError::Parameter {
                name: variable.name.clone(),
                value: value.to_string(),
                why: range.what.to_string(),
            }),
            Some(_) => Ok(()),
            None => crate::instance::check_number(variable, value),
        }
    }

    fn check_string(setting: Setting, value: &str) -> Result<(), String> {
        match setting {
            Setting::Drive => ["profile", "speed"]
                .contains(&value)
                .then_some(())
                .ok_or_else(|| "one of profile, speed".into()),
            Setting::Driveline => DrivelineKind::named(value).map(|_| ()).ok_or_else(|| {
                let names: Vec<&str> = DrivelineKind::NAMES.iter().map(|(n, _)| *n).collect();
                format!("one of {}", names.join(", "))
            }),
            Setting::Steering => ["profile", "yaw_rate"]
                .contains(&value)
                .then_some(())
                .ok_or_else(|| "one of profile, yaw_rate".into()),
            _ => crate::instance::check_string(setting, value),
        }
    }
}

/// A spatial parameter's or input's range, if it has its own.
fn range(role: Role) -> Option<Range> {
    match role {
        Role::Setting(Setting::SideSlope) => Some(SLOPE_RANGE),
        Role::Setting(Setting::Turn) => Some(TURN_RANGE),
        Role::Setting(Setting::TurnAt | Setting::TurnTime) => Some(Scenario::TIME_RANGE),
        Role::Setting(Setting::SteerRatio) => Some(STEER_RATIO_RANGE),
        Role::Input(Input::TargetSpeed) => Some(Scenario::SPEED_RANGE),
        Role::Input(Input::TargetYawRate) => Some(YAW_RATE_RANGE),
        _ => None,
    }
}

/// The vehicle set on the ground the parameters name (the grid of
/// `field_file`, else the course with each track's own file where
/// given) under its declared laws on the `soil`, as the 3-D main job
/// sets it: the system and its state.
fn grounded<V: SpatialVehicleSystem>(
    instance: &Instance<Spatial<V>>,
) -> Result<(V::Spatial, DVector<f64>), FmuError> {
    let built = |e: &dyn std::fmt::Display| FmuError::Build(e.to_string());
    let slope = instance.number(Setting::SideSlope);
    let laws = SpatialLaws {
        soil: instance.soil()?.soil(),
        ..V::declared_laws()
    };
    let sides = [Setting::RightCourseFile, Setting::LeftCourseFile]
        .map(|s| Some(instance.text(s)).filter(|file| !file.is_empty()));
    let field_file = instance.text(Setting::FieldFile);
    let ground = if field_file.is_empty() {
        SpatialGround::Course {
            course: instance.course()?,
            sides: sides.map(|file| file.map(|file| CourseSpec::File(file.into()))),
        }
    } else if sides.iter().any(Option::is_some) {
        return Err(built(
            &"field_file is the whole ground: left_course_file and right_course_file \
              cannot be given with it",
        ));
    } else {
        SpatialGround::GridFile(field_file.into())
    };
    let (system, y, _) = on_ground::<V>(laws, &ground, slope).map_err(|e| built(&e))?;
    Ok((system, y))
}

/// The spatial FMU's variables: the time; the course's, the speed
/// profile's, the engine's and the integrator's parameters as the planar
/// FMU's, the side slope and the steering; the inputs
/// `target_speed` and `target_yaw_rate`; one output per recorded column
/// ([`SPATIAL_COLUMNS`]) and the books' residual.
fn table() -> Vec<Variable> {
    let mut table = Table::new();
    let mut push = |name: &str, kind, causality, unit, description: String, start, role| {
        table.push(
            name.into(),
            (kind, causality, unit),
            description,
            start,
            role,
        );
    };
    use Causality::{Input as In, Output as Out, Parameter as P};
    for (name, kind, unit, description, start, setting) in scenario_settings() {
        let description = match setting {
            Setting::Soil => "rigid, or a soil of Wong's table (dry-sand, sandy-loam, clay, \
                 heavy-clay, lete-sand, snow): soft soil under both tracks, each leaving its rut \
                 (the 3-D main job's --soil)"
                .to_string(),
            Setting::Engine => "1: through the engine (the powertrain export_spatial_fmu!(V, \
                 powertrain = f) was given, else the vehicle's declared one; refused where there \
                 is neither): on a differential with the engine's inertia declared, its speed a \
                 state (governor, converter, ranges, lock-up); else its full-load envelope caps \
                 each side's drive or the box's, as the 3-D main job's --engine; 0: the \
                 controllers alone"
                .to_string(),
            Setting::Course => "the course, laid across the vehicle's whole width: flat, bump \
                 (a cosine bump 1 m wide), file (course_file), random (roughness, seed, \
                 course_length) or obstacle (obstacle, obstacle_at)"
                .to_string(),
            Setting::Tolerance => "Bogacki-Shampine's relative and absolute tolerance, 1e-12 to \
                 0.1 (0: the master's, else 1e-3, as the 3-D main job)"
                .to_string(),
            Setting::Drive => "what the speed controller on each sprocket holds: profile \
                 (profile_speed, profile_settle, profile_ramp) or speed (the input target_speed)"
                .to_string(),
            _ => description.to_string(),
        };
        push(
            name,
            kind,
            P,
            unit,
            description,
            start,
            Role::Setting(setting),
        );
    }
    for (name, kind, unit, description, start, setting) in spatial_settings() {
        push(
            name,
            kind,
            P,
            unit,
            description.into(),
            start,
            Role::Setting(setting),
        );
    }
    let inputs = [
        (
            "target_speed",
            "m/s",
            "drive = speed: the belts' speed each sprocket's controller holds, -20 to 20 (the driver moves the two apart to steer)",
            Input::TargetSpeed,
        ),
        (
            "target_yaw_rate",
            "rad/s",
            "steering = yaw_rate: the rate the heading wanted turns at, to the left positive, -1 to 1; the driver holds the hull to that heading",
            Input::TargetYawRate,
        ),
        (
            "drawbar_pull",
            "N",
            "a force pulling the hull back along its heading, level, at its centroid (negative pushes); its work is booked as dissipated",
            Input::DrawbarPull,
        ),
    ];
    for (name, unit, description, input) in inputs {
        push(
            name,
            Kind::Float64,
            In,
            unit,
            description.into(),
            Start::Float64(0.0),
            Role::Input(input),
        );
    }
    for (i, column) in SPATIAL_COLUMNS.iter().enumerate() {
        let (unit, description) = describe(column);
        push(
            column,
            Kind::Float64,
            Out,
            unit,
            description,
            Start::Computed,
            Role::Column(i),
        );
    }
    table.books_residual("the drives' work");
    table.0
}

/// The spatial model's own parameters: the side slope, the driveline and
/// the steering.
fn spatial_settings() -> [SettingRow; 10] {
    let (turn, turn_at, turn_time) = TURN;
    [
        (
            "side_slope",
            Kind::Float64,
            "1",
            "the ground's side slope, rise over run to the left, -1 to 1 (the vehicle set on it at rest)",
            Start::Float64(0.0),
            Setting::SideSlope,
        ),
        (
            "driveline",
            Kind::String,
            "",
            "how the drive reaches the sprockets: sides (a speed controller on each), brakes (one on a differential, the driver braking the inner sprocket), steer-ratio (one on a differential with a steer unit holding the sprockets' speed ratio at most steer_ratio) or neutral-pivot (the differential's box held still, speed 0, the steer unit pivoting the vehicle at the steer drive's speed that the powertrain's declared steer ratios give); with engine = 1 on a differential, an engine whose inertia is declared has its speed as a state, and a steer unit whose powertrain declares steer ratios is geared to it unless steer_ratio is set (the 3-D main job's --driveline, --steer-ratio and --engine)",
            Start::String("sides".into()),
            Setting::Driveline,
        ),
        (
            "steer_ratio",
            Kind::Float64,
            "1",
            "driveline = steer-ratio: the steer unit's minimum steer ratio, 1.01 to 100 (0: the powertrain's first declared steer ratio, refused where it declares none)",
            Start::Float64(0.0),
            Setting::SteerRatio,
        ),
        (
            "left_course_file",
            Kind::String,
            "",
            "a profile CSV (as course_file) under the left track alone, the course staying under the right, the two blended across the ground between the tracks; empty: the course (the 3-D main job's --left-course-file)",
            Start::String(String::new()),
            Setting::LeftCourseFile,
        ),
        (
            "right_course_file",
            Kind::String,
            "",
            "a profile CSV under the right track alone, as left_course_file",
            Start::String(String::new()),
            Setting::RightCourseFile,
        ),
        (
            "field_file",
            Kind::String,
            "",
            "an ESRI ASCII grid (.asc): the ground as heights on a grid instead of the course (whose parameters are then not read) and the side files (refused with it); empty: the course (the 3-D main job's --field-file)",
            Start::String(String::new()),
            Setting::FieldFile,
        ),
        (
            "steering",
            Kind::String,
            "",
            "how the driver steers: profile (turn, turn_at, turn_time) or yaw_rate (the heading wanted turns at the input target_yaw_rate)",
            Start::String("profile".into()),
            Setting::Steering,
        ),
        (
            "turn",
            Kind::Float64,
            "deg",
            "steering = profile: the turn, degrees to the left, -360 to 360 (0 drives straight)",
            Start::Float64(turn),
            Setting::Turn,
        ),
        (
            "turn_at",
            Kind::Float64,
            "s",
            "steering = profile: when the turn starts, 0 to 1e6",
            Start::Float64(turn_at),
            Setting::TurnAt,
        ),
        (
            "turn_time",
            Kind::Float64,
            "s",
            "steering = profile: how long the heading wanted takes to turn, 0 to 1e6 (0: a step)",
            Start::Float64(turn_time),
            Setting::TurnTime,
        ),
    ]
}

/// A recorded column's unit and description, from its name.
fn describe(column: &str) -> (&'static str, String) {
    let (side, leaf) = match column.split_once('_') {
        Some(("r", leaf)) => ("the right track's ", leaf),
        Some(("l", leaf)) => ("the left track's ", leaf),
        _ => ("", column),
    };
    let (unit, what) = match leaf {
        "x" | "y" | "z" => ("m", "the centre of mass's position (world axes)"),
        "heading" => ("rad", "the hull's heading, to the left positive"),
        "pitch" => ("rad", "the frame's pitch, nose up positive"),
        "roll" => ("rad", "the hull's roll, the left side up positive"),
        "yaw_rate" => ("rad/s", "the hull's yaw rate, to the left positive"),
        "vx" | "vy" | "vz" => ("m/s", "the centre of mass's velocity (world axes)"),
        "ax" | "ay" | "az" => ("m/s2", "the centre of mass's acceleration (world axes)"),
        "lateral_acceleration" => (
            "m/s2",
            "the centre of mass's acceleration across the heading",
        ),
        "turn_radius" => ("m", "the radius of the centre of mass's path"),
        "sprocket_speed" => ("rad/s", "sprocket's speed relative to the frame"),
        "sprocket_torque" => ("N.m", "sprocket's torque from the driveline"),
        "sprocket_power" | "brake_power" => ("W", "power into its sprocket (or its brake's)"),
        "brake_torque" => ("N.m", "steering brake's torque"),
        "belt_speed" => (
            "m/s",
            "belt speed: the sprocket's speed times its rolling radius",
        ),
        "ground_speed" => ("m/s", "speed over the ground along the heading"),
        "slip" => ("1", "slip, 1 - ground speed / belt speed"),
        "track_speed" => ("m/s", "speed round the hull at its ground patch"),
        "ground_fx" | "ground_fy" | "ground_fz" => ("N", "ground force (world axes)"),
        "ground_yaw_moment" => ("N.m", "ground's yaw moment about the centre of mass"),
        "tension_tight" | "tension_slack" | "tension_largest" => ("N", "track tension"),
        "engine_speed" => ("rad/s", "the engine's speed (NaN without an engine)"),
        "engine_torque" => ("N.m", "the engine's torque (NaN without an engine)"),
        "engine_power" | "turbine_power" => (
            "W",
            "the engine's or the turbine's power (NaN without an engine)",
        ),
        "gear" => ("1", "the range engaged (NaN without an engine)"),
        "speed_ratio" | "torque_ratio" => ("1", "the converter's ratio (NaN without an engine)"),
        "locked" => (
            "1",
            "1 with the lock-up clutch engaged (NaN without an engine)",
        ),
        _ => ("1", ""),
    };
    (unit, format!("{side}{what} ({column})"))
}
