//! What a vehicle meets the world with, changeable at run time: terrain,
//! contact laws (rigid ground or soft soil), the arms' springs, the drive,
//! a drawbar load and how the track's loop is closed. The geometry (masses,
//! joints, wheels, shoes, teeth) is compiled in ([`Geometry`](super::Geometry)).

use super::fitted::ContactLawSet;
use super::powertrain::Cap;
use super::shift::Engaged;
use super::{Brake, ConfigError, DrawbarError, Drive, Powertrain, TorqueCap};
use crate::closure::ClosureMethod;
use crate::contact::soft_ground::Rut;
use crate::contact::{ContactLaws, GroundLaws};
use crate::multibody::ArmSpring;
use crate::terrain::Terrain;
use crate::terrain::soil::Soil;

/// How a vehicle meets the world. Nothing here enters the mass matrix:
/// every field can be changed between runs without recompiling (a vehicle
/// declared with `model!` gives its declared values from
/// [`Vehicle::declared_config`](super::Vehicle::declared_config)), and is checked when the
/// vehicle is built ([`build`](super::build)).
#[derive(Debug)]
pub struct VehicleConfig {
    /// The ground's profile (the undisturbed surface, on soft soil).
    pub terrain: Terrain,
    /// Shoes on rigid ground: the normal law, and friction with stiction
    /// (a tangential state per ground point) or regularised.
    pub ground: GroundLaws,
    /// Shoes' inner faces on road wheels, idler and rollers.
    pub wheels: ContactLaws,
    /// Shoes' pins on the sprocket's teeth.
    pub sprocket: ContactLaws,
    /// Soft soil under the track instead of rigid ground: its laws replace
    /// [`ground`](Self::ground)'s; the track's width comes from the
    /// declared shoe and each ground point's footprint is a pitch long
    /// ([`SoftGround`](crate::contact::soft_ground::SoftGround)). `None`
    /// drives on rigid ground.
    pub soil: Option<Soil>,
    /// What the soil remembers of earlier passes: the rut another run left
    /// ([`VehicleDynamics::rut`](super::VehicleDynamics::rut)), for a
    /// vehicle following in it. `None`: undisturbed soil.
    pub rut: Option<Rut>,
    /// The arms' torsion springs and dampers, one per arm of the chassis
    /// (any order): the declared ones from `Vehicle::config`.
    pub arms: Vec<ArmSpring>,
    /// The sprocket drive.
    pub drive: Drive,
    /// The engine and driveline behind the sprocket: the most torque the
    /// drive may give at each sprocket speed while it drives. `None`
    /// (default): the drive's own limit alone.
    pub powertrain: Option<Powertrain>,
    /// The brake on the sprocket, applied from its time on ([`Brake`]):
    /// `None` (default), no brake.
    pub brake: Option<Brake>,
    /// A drawbar load, N: a horizontal force pulling the chassis back at
    /// its centroid (negative pushes it forward). Default 0. The energy it
    /// takes out is booked with the dissipated work.
    pub drawbar_pull: f64,
    /// The link (numbered from 1) whose joint to the next is recorded as
    /// `tension`. Default 1.
    pub tension_link: usize,
    /// How the track's loop is closed: as declared (default), or by
    /// another method chosen at run time.
    pub closure: ClosureMethod,
}

impl VehicleConfig {
    /// A vehicle on `terrain`, driven by `drive`, with these arms and
    /// contact laws (a declared vehicle's: the declared, the rest fitted to
    /// it, [`ContactFit`](super::ContactFit)), on rigid ground, tension
    /// recorded at link 1, the loop closed as declared.
    pub fn new(
        terrain: Terrain,
        drive: Drive,
        arms: Vec<ArmSpring>,
        laws: ContactLawSet,
    ) -> VehicleConfig {
        VehicleConfig {
            terrain,
            ground: laws.ground,
            wheels: laws.wheels,
            sprocket: laws.sprocket,
            soil: None,
            rut: None,
            arms,
            drive,
            powertrain: None,
            brake: None,
            drawbar_pull: 0.0,
            tension_link: 1,
            closure: ClosureMethod::Declared,
        }
    }

    /// The law of a terrain corner against a shoe's or the hull's outline
    /// and of the hull's corners on the ground ([`outline`](crate::contact::outline)):
    /// the ground's normal law, and Coulomb friction of the ground's μ
    /// regularised at the rims' slip speed (the declared `wheels` law's):
    /// a corner has no stiction state.
    pub fn corner_laws(&self) -> ContactLaws {
        ContactLaws {
            normal: self.ground.normal,
            friction: crate::laws::Friction {
                mu: self.ground.friction.mu(),
                ..self.wheels.friction
            },
        }
    }

    /// Checks what the configuration alone can tell (the terrain, the
    /// drive, every law's parameters, the soil, the drawbar), every value
    /// against its range; what needs the compiled model is checked when
    /// the vehicle is built.
    pub fn check(&self) -> Result<(), ConfigError> {
        self.terrain.check()?;
        self.drive.check()?;
        if let Some(powertrain) = &self.powertrain {
            powertrain.check()?;
        }
        if let Some(brake) = &self.brake {
            brake.check()?;
        }
        let pair = |pair| move |source| ConfigError::Contact { pair, source };
        self.ground.check().map_err(pair("ground"))?;
        self.wheels.check().map_err(pair("wheels"))?;
        self.sprocket.check().map_err(pair("sprocket"))?;
        for arm in &self.arms {
            arm.spring.check().map_err(|source| ConfigError::Arm {
                body: arm.body,
                source,
            })?;
        }
        if let Some(soil) = &self.soil {
            soil.check()?;
        }
        DrawbarError::check(self.drawbar_pull)?;
        Ok(())
    }

    /// The powertrain's cap on the drive at sprocket speed `omega`
    /// (rad/s), its torque at rest being `stall` (N m,
    /// [`stall_torque`](Self::stall_torque), found once per build), a
    /// scheduled gearbox in the range `engaged`, in reverse where the
    /// driver asks (`reverse`, [`Drive::asks_reverse`]): none without a
    /// powertrain.
    pub(super) fn torque_cap(
        &self,
        omega: f64,
        stall: f64,
        (engaged, reverse): (Option<Engaged>, bool),
    ) -> TorqueCap {
        self.torque_cap_in_gear(omega, stall, (engaged, reverse)).0
    }

    /// [`torque_cap`](Self::torque_cap), and the powertrain's own cap
    /// (its gear and full-load point) for the engine's side.
    pub(super) fn torque_cap_in_gear(
        &self,
        omega: f64,
        stall: f64,
        (engaged, reverse): (Option<Engaged>, bool),
    ) -> (TorqueCap, Option<Cap>) {
        self.powertrain
            .as_ref()
            .map_or((TorqueCap::NONE, None), |p| {
                cap_in_gear(p, omega, stall, (engaged, reverse))
            })
    }

    /// Where a run through this configuration's powertrain starts its
    /// gearbox: a converter driveline with a shift schedule in its lowest
    /// range; `None` (shifted ideally, or no gears to schedule) else.
    pub(super) fn first_engaged(&self) -> Option<Engaged> {
        match &self.powertrain {
            Some(Powertrain::Converter(driveline)) if driveline.shift.is_some() => {
                Some(Engaged::LOWEST)
            }
            _ => None,
        }
    }

    /// The powertrain's torque at rest, N m, forward and in reverse (∞
    /// without a powertrain; reverse as forward without a reverse range).
    pub(super) fn stall_torque(&self) -> (f64, f64) {
        self.powertrain
            .as_ref()
            .map_or((f64::INFINITY, f64::INFINITY), Powertrain::stall_torques)
    }

    /// The arms, checked to be one per arm of a chassis whose arms are at
    /// `declared` (bodies, any order).
    pub(super) fn check_arms(&self, declared: &[ArmSpring]) -> Result<(), ConfigError> {
        let mut configured: Vec<usize> = self.arms.iter().map(|a| a.body).collect();
        let mut declared: Vec<usize> = declared.iter().map(|a| a.body).collect();
        configured.sort_unstable();
        declared.sort_unstable();
        if configured == declared {
            Ok(())
        } else {
            Err(ConfigError::Arms {
                configured,
                declared,
            })
        }
    }
}

/// `powertrain`'s cap on the drive at sprocket speed `omega` (rad/s), its
/// torque at rest being `stall` (N m), a scheduled gearbox in the range
/// `engaged`, in reverse where the driver asks (`reverse`), and its own
/// cap (its gear and full-load point): the one rule the planar sprocket's
/// drive ([`VehicleConfig::torque_cap_in_gear`]) and the spatial
/// differential's box through an engine read.
pub(super) fn cap_in_gear(
    powertrain: &Powertrain,
    omega: f64,
    stall: f64,
    (engaged, reverse): (Option<Engaged>, bool),
) -> (TorqueCap, Option<Cap>) {
    let cap = powertrain.cap(omega.abs(), engaged, reverse);
    (
        TorqueCap {
            value: cap.torque,
            slope: cap.slope,
            stall,
        },
        Some(cap),
    )
}
