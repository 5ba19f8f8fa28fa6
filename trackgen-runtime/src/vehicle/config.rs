//! What a vehicle meets the world with, changeable at run time: terrain,
//! contact laws (rigid ground or soft soil), the arms' springs, the drive,
//! a drawbar load and how the track's loop is closed. The geometry (masses,
//! joints, wheels, shoes, teeth) is compiled in ([`Geometry`](super::Geometry)).

use super::{ConfigError, Drive};
use crate::closure::ClosureMethod;
use crate::contact::soft_ground::Rut;
use crate::contact::soil::Soil;
use crate::contact::{ContactLaws, Friction, NormalLaw, Terrain};
use crate::model::ArmSpring;

/// How a vehicle meets the world. Nothing here enters the mass matrix:
/// every field can be changed between runs without recompiling (a vehicle
/// declared with `model!` gives its declared values from
/// [`Vehicle::config`](super::Vehicle::config)), and is checked when the
/// vehicle is built ([`build`](super::build)).
#[derive(Debug)]
pub struct VehicleConfig {
    /// The ground's profile (the undisturbed surface, on soft soil).
    pub terrain: Terrain,
    /// Shoes on rigid ground.
    pub ground: ContactLaws,
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
    /// The default normal law of shoes on the ground: Hunt-Crossley,
    /// `k` = 2e6 N/m per shoe point, exponent 1, `χ` = 2 s/m.
    ///
    /// Hunt-Crossley with exponent 1 (`F = k δ (1 + χ δ̇)`) has no force
    /// jump when a contact opens or closes, which would make an adaptive
    /// integrator stumble at each of the thousands of contact changes of a
    /// run. The stiffness keeps a 10-tonne vehicle's static penetrations
    /// within a few millimetres; `χ` damps the contacts without making the
    /// light shoes' rotation the stiffest mode of the model.
    pub const GROUND_LAW: NormalLaw = NormalLaw::HuntCrossley {
        stiffness: 2e6,
        exponent: 1.0,
        chi: 2.0,
    };
    /// The default friction of shoes on the ground: μ = 0.8 over 0.1 m/s
    /// of slip (regularised where it carries the traction).
    pub const GROUND_FRICTION: Friction = Friction { mu: 0.8, slip: 0.1 };
    /// The default normal law of the track on wheel rims and sprocket
    /// teeth: Hunt-Crossley, `k` = 1e7 N/m, exponent 1, `χ` = 0.5 s/m.
    pub const RIM_LAW: NormalLaw = NormalLaw::HuntCrossley {
        stiffness: 1e7,
        exponent: 1.0,
        chi: 0.5,
    };
    /// The default friction of the track on rims and teeth: μ = 0.4 over
    /// 0.5 m/s of slip. Regularised more widely than the ground's: there it
    /// only spins the wheels up and rubs the flanks, and the friction slope
    /// `μ F_n / v_s` on a light shoe under a loaded rim is the stiffest mode
    /// of a vehicle (measured on the M113: the explicit integrator's step
    /// grows 1.75× from 0.2 to 0.5 m/s).
    pub const RIM_FRICTION: Friction = Friction { mu: 0.4, slip: 0.5 };

    /// A vehicle on `terrain`, driven by `drive`, with these arms and the
    /// default contact laws ([`GROUND_LAW`](Self::GROUND_LAW),
    /// [`GROUND_FRICTION`](Self::GROUND_FRICTION), [`RIM_LAW`](Self::RIM_LAW)
    /// and [`RIM_FRICTION`](Self::RIM_FRICTION) on wheels and sprocket), on
    /// rigid ground, tension recorded at link 1, the loop closed as
    /// declared.
    pub fn new(terrain: Terrain, drive: Drive, arms: Vec<ArmSpring>) -> VehicleConfig {
        let rim = ContactLaws {
            normal: Self::RIM_LAW,
            friction: Self::RIM_FRICTION,
        };
        VehicleConfig {
            terrain,
            ground: ContactLaws {
                normal: Self::GROUND_LAW,
                friction: Self::GROUND_FRICTION,
            },
            wheels: rim,
            sprocket: rim,
            soil: None,
            rut: None,
            arms,
            drive,
            drawbar_pull: 0.0,
            tension_link: 1,
            closure: ClosureMethod::Declared,
        }
    }

    /// Checks what the configuration alone can tell (the terrain, the
    /// drive, every law's parameters, the soil, the drawbar), every value
    /// against its range; what needs the compiled model is checked when
    /// the vehicle is built.
    pub fn check(&self) -> Result<(), ConfigError> {
        self.terrain.check()?;
        self.drive.check()?;
        for (pair, laws) in [
            ("ground", &self.ground),
            ("wheels", &self.wheels),
            ("sprocket", &self.sprocket),
        ] {
            laws.check()
                .map_err(|source| ConfigError::Contact { pair, source })?;
        }
        for arm in &self.arms {
            arm.spring.check().map_err(|source| ConfigError::Arm {
                body: arm.body,
                source,
            })?;
        }
        if let Some(soil) = &self.soil {
            soil.check()?;
        }
        if !self.drawbar_pull.is_finite() {
            return Err(ConfigError::Drawbar {
                pull: self.drawbar_pull,
            });
        }
        Ok(())
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
