//! The driveline a 3-D run asks for (the applications' `spatial
//! --driveline`, the spatial FMU's `driveline`): a speed drive on each
//! side, or one on a differential steered by its brakes, by a steer unit
//! in a range or in neutral, with or without the engine on its box (an
//! engine whose speed is a state where its inertia is declared, else its
//! envelope).

use super::{
    Differential, DifferentialSteer, Driveline, EngineEnvelope, FullSteer, HeadingHold, SideDrives,
    SpatialEngine, SpatialEngineError, SpatialSimulated, SpatialVehicleSystem, SteerDrive,
    SteeringBrakes,
};
use crate::vehicle::{Drive, Powertrain};

/// How the drive reaches the sprockets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DrivelineKind {
    /// A speed controller on each sprocket (the vehicle's declared
    /// gains), the driver moving their targets apart.
    Sides,
    /// One speed controller on a differential (twice a side's gains and
    /// limit), the driver braking the inner sprocket.
    Brakes,
    /// One speed controller on a differential with a steer unit holding
    /// the sprockets' speed ratio, at most the steer ratio asked for.
    SteerRatio,
    /// The differential in neutral (a target speed of 0: its box held at rest),
    /// its steer unit turning the sprockets apart at the steer drive's
    /// speed with the engine at its rated speed: a pivot about the
    /// vehicle's centre (the X200-4's; its converter powertrain's steer
    /// ratios and ranges give the steer drive's ratio).
    NeutralPivot,
}

impl DrivelineKind {
    /// Each kind by its name (`sides`, `brakes`, `steer-ratio`,
    /// `neutral-pivot`).
    pub const NAMES: [(&'static str, DrivelineKind); 4] = [
        ("sides", DrivelineKind::Sides),
        ("brakes", DrivelineKind::Brakes),
        ("steer-ratio", DrivelineKind::SteerRatio),
        ("neutral-pivot", DrivelineKind::NeutralPivot),
    ];

    /// The kind named `name`, if one is.
    pub fn named(name: &str) -> Option<DrivelineKind> {
        Self::NAMES
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, kind)| *kind)
    }
}

/// What a run asks of the driveline, and the powertrain it has (whose
/// transmission's minimum steer ratios, [`Powertrain::steer_ratios`],
/// are the steer unit's where none is asked).
pub struct DrivelineAsked {
    /// How the drive reaches the sprockets.
    pub driveline: DrivelineKind,
    /// The steer unit's minimum steer ratio, if given.
    pub steer_ratio: Option<f64>,
    /// Whether to drive through the engine.
    pub engine: bool,
    /// The target speed, m/s.
    pub speed: f64,
    /// The vehicle's powertrain, or why it has none (said where one is
    /// needed).
    pub powertrain: Result<Powertrain, String>,
}

impl DrivelineAsked {
    /// The powertrain, or why there is none.
    fn engine(&self) -> Result<Powertrain, String> {
        self.powertrain.clone()
    }

    /// Its transmission's minimum steer ratios, one per range: none where
    /// it has no powertrain or declares none.
    fn steer_ratios(&self) -> &[f64] {
        self.powertrain
            .as_ref()
            .map_or(&[], |powertrain| powertrain.steer_ratios())
    }
}

/// The steering brakes' largest torque over a side drive's limit:
/// holding the inner sprocket in a clutch-brake turn takes the
/// differential's half of the drive's torque and the ground's pull on
/// the inner track, about twice a side's turning torque (an assumption:
/// no brake figure of either vehicle was found).
const BRAKE_OVER_DRIVE: f64 = 2.0;
/// The driver's dead band on the steering brakes, m/s of the error of the
/// belts' difference ([`SteeringBrakes::dead_band`]).
const BRAKE_DEAD_BAND: f64 = 0.05;

/// Sets the driveline `args` ask for on `system` at its state `y`
/// ([`asked_driveline`], the vehicle's mass read at `y`), the engine whose
/// speed is a state started at its idle, and, where `args` drive through
/// an engine that is no state, its full-load envelope capping the drive:
/// what to say of it, or why it cannot be. The one set-up of the 3-D
/// main job's and the spatial FMU's drive.
pub fn drive_as_asked<V: SpatialVehicleSystem>(
    system: &mut V::Spatial,
    y: &mut [f64],
    args: &DrivelineAsked,
    target: impl Fn() -> Box<dyn Fn(f64) -> f64 + Send>,
) -> Result<String, String> {
    let mass = system
        .outputs(0.0, y)
        .map_err(|e| e.to_string())?
        .centre
        .mass;
    let (driveline, mut said) = asked_driveline::<V>(args, (system, mass), target)?;
    system.set_driveline(driveline).map_err(|e| e.to_string())?;
    system.start_engine(y);
    if args.engine && system.engine().is_none() {
        let envelope = EngineEnvelope::new(args.engine()?)
            .map_err(|e| format!("{}'s powertrain: {e}", V::NAME))?;
        said.push_str(&format!(
            ", capped by the engine's full-load envelope (at most {:.1} kW a side)",
            envelope.powertrain().max_power() / 1e3
        ));
        system.set_envelope(Some(envelope));
    }
    Ok(said)
}

/// The driveline `args` ask for of the vehicle `V` (its `system` and its
/// `mass`, kg), with its speed drive toward `target` (m/s against time),
/// and what to say of it; refused, saying why, where the vehicle cannot
/// give it: a differential's controller takes twice
/// a side's gains and limit, a steer unit half a side's gains and a
/// side's limit ([`Differential::with_steer_unit`]), steering brakes twice a
/// side's limit with the parking brake's elastic stage on half the
/// vehicle's mass reflected to a sprocket, fully on when the driver's
/// error (the gauge times the yaw rate against the difference asked) is
/// a third of the largest difference beyond a dead band of 0.05 m/s (a brake
/// turns the vehicle only past the ground's turning resistance, so the
/// driver must brake hard on a small error).
pub fn asked_driveline<V: SpatialVehicleSystem>(
    args: &DrivelineAsked,
    (system, mass): (&V::Spatial, f64),
    target: impl Fn() -> Box<dyn Fn(f64) -> f64 + Send>,
) -> Result<(Driveline, String), String> {
    if args.driveline == DrivelineKind::Sides {
        let drives = SideDrives {
            right: V::speed_drive(target()),
            left: V::speed_drive(target()),
        };
        return Ok((
            Driveline::Sides(drives),
            "a speed drive on each sprocket".into(),
        ));
    }
    let side = V::speed_drive(|_| 0.0);
    let not_speed = || format!("{}'s drive is not a speed controller", V::NAME);
    if args.driveline == DrivelineKind::NeutralPivot {
        // The box held at rest by a differential's speed drive toward the
        // target, 0.
        let (full, said) = neutral_pivot::<V>(args)?;
        let differential = Differential::with_steer_unit(&side, target(), FullSteer::Neutral(full))
            .ok_or_else(not_speed)?;
        return Ok((Driveline::Differential(differential), said));
    }
    if args.driveline == DrivelineKind::SteerRatio {
        let ratio = args
            .steer_ratio
            .or(args.steer_ratios().first().copied())
            .ok_or_else(|| {
                format!(
                    "{}'s powertrain declares no steer ratios: give --steer-ratio",
                    V::NAME
                )
            })?;
        let mut differential =
            Differential::with_steer_unit(&side, target(), FullSteer::Ratio(ratio))
                .ok_or_else(not_speed)?;
        let mut said = format!("a differential with a steer unit (minimum steer ratio {ratio})");
        if let Some(engine) = engine_on_box::<V>(args)? {
            if let (None, Some(drive), DifferentialSteer::Unit(unit)) = (
                args.steer_ratio,
                SteerDrive::of(&args.engine()?)
                    .map_err(|e| format!("{}'s steer ratios: {e}", V::NAME))?,
                &mut differential.steer,
            ) {
                unit.full_steer = FullSteer::Engine(drive.ratio);
                said = format!(
                    "a differential with the steer drive geared to the engine (full steer {:.5} \
                     of the engine's speed apart: the published minimum steer ratios in every \
                     range, locked up)",
                    drive.ratio
                );
            }
            said.push_str(&engine_said(&engine));
            differential.engine = Some(engine);
        }
        return Ok((Driveline::Differential(differential), said));
    }
    let Drive::Speed {
        proportional,
        integral,
        max_torque,
        ..
    } = side
    else {
        return Err(not_speed());
    };
    let drive = Drive::Speed {
        target: target(),
        proportional: 2.0 * proportional,
        integral: 2.0 * integral,
        max_torque: 2.0 * max_torque,
    };
    let largest = V::layout().gauge * HeadingHold::DRIVER_MAX_YAW_RATE / 3.0;
    let radius = system.rolling_radius();
    let inertia = 0.5 * mass * radius * radius;
    let brakes = SteeringBrakes::by_parking_rule(
        BRAKE_OVER_DRIVE * max_torque,
        inertia,
        (largest, BRAKE_DEAD_BAND),
    );
    let mut said = format!(
        "a differential steered by its brakes ({:.1} kN m each)",
        brakes.max_torque / 1e3
    );
    let engine = engine_on_box::<V>(args)?;
    if let Some(engine) = &engine {
        said.push_str(&engine_said(engine));
    }
    let differential = Differential {
        drive,
        steer: DifferentialSteer::Brakes(brakes),
        input: Box::new(|_| 0.0),
        engine,
    };
    Ok((Driveline::Differential(differential), said))
}

/// The engine, its speed a state, that `--engine` puts on a
/// differential's box: `None` without `--engine`, or for a vehicle whose
/// powertrain declares no engine inertia (its envelope caps the drive
/// then).
fn engine_on_box<V: SpatialVehicleSystem>(
    args: &DrivelineAsked,
) -> Result<Option<SpatialEngine>, String> {
    if !args.engine {
        return Ok(None);
    }
    match SpatialEngine::new(args.engine()?) {
        Ok(engine) => Ok(Some(engine)),
        Err(SpatialEngineError::NoDynamics) => Ok(None),
        Err(e) => Err(format!("{}'s powertrain: {e}", V::NAME)),
    }
}

/// What to say of an engine on the box.
fn engine_said(engine: &SpatialEngine) -> String {
    let d = engine.driveline();
    format!(
        ", through the engine (its speed a state from {:.0} rpm idle, rated {:.1} kW), the \
         torque converter (stall torque ratio {:.2}) and {} ranges with lock-up",
        engine.idle() * 30.0 / std::f64::consts::PI,
        engine.rated_power() / 1e3,
        d.torque_ratio[0].1,
        d.ranges.len()
    )
}

/// The sprockets' speed difference at full steer in neutral that `args`
/// ask for, rad/s, and what to say of it: `k ω_e`, `k` the steer drive's
/// ratio that its converter powertrain's steer ratios and ranges imply
/// ([`SteerDrive`]) and `ω_e` the
/// engine's rated speed (the governor at full throttle). Refused, saying
/// why: a speed asked (a pivot stands), `--engine` (it caps the box's
/// drive, and no range drives the box in neutral), no steer ratios
/// declared or no converter powertrain.
fn neutral_pivot<V: SpatialVehicleSystem>(args: &DrivelineAsked) -> Result<(f64, String), String> {
    if args.speed != 0.0 {
        return Err(format!(
            "a pivot in neutral stands: give --speed 0 (not {})",
            args.speed
        ));
    }
    if args.engine {
        return Err(
            "--engine caps the drive on the differential's box, and in neutral no range drives it"
                .into(),
        );
    }
    if args.steer_ratios().is_empty() {
        return Err(format!(
            "{}'s powertrain declares no steer ratios: a neutral pivot's steer drive is found \
             from them",
            V::NAME
        ));
    }
    let drive = SteerDrive::of(&args.engine()?)
        .map_err(|e| format!("{}'s steer ratios: {e}", V::NAME))?
        .ok_or_else(|| {
            format!(
                "{}'s powertrain has no ranges: a neutral pivot's steer drive is found from its \
                 ranges' reductions and its steer ratios",
                V::NAME
            )
        })?;
    let (full, ratio, engine, departure) = (
        drive.full_difference(),
        drive.ratio,
        drive.engine_speed,
        drive.departure,
    );
    let said = format!(
        "a differential in neutral, its box held still and its steer unit pivoting it: the \
         sprockets {full:.2} rad/s apart at full steer, the steer drive's {ratio:.5} of the \
         engine's rated {:.0} rpm (the steer ratios' ranges within {:.1} % of it)",
        engine * 30.0 / std::f64::consts::PI,
        departure * 100.0
    );
    Ok((full, said))
}
