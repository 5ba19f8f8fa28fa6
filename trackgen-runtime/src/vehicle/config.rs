//! What a vehicle meets the world with, changeable at run time: shoe,
//! contact laws (rigid ground or soft soil), the arms' springs, the drive
//! and a drawbar load.

use super::Drive;
use crate::contact::ground::GroundContact;
use crate::contact::soft_ground::SoftGround;
use crate::contact::soil::{Soil, SoilError};
use crate::contact::sprocket::{SprocketContact, ToothProfile};
use crate::contact::wheel::WheelContact;
use crate::contact::{Friction, NormalLaw, ShoeGeometry, Terrain};
use crate::model::{ArmSpring, ChassisModel};
use crate::simulate::SimulationError;
use crate::suspension::declared_arms;

/// How a vehicle meets the world: shoe geometry, the three contact pairs,
/// the arms' springs and the drive. Nothing here enters the mass matrix:
/// every field can be changed at run time, between runs, without
/// recompiling (a vehicle declared with `model!` gives its declared values
/// from `Name::config`).
#[derive(Debug)]
pub struct VehicleConfig {
    /// The shoes' contact features.
    pub shoe: ShoeGeometry,
    /// Track on terrain.
    pub ground: GroundContact,
    /// Track on road wheels, idler and rollers.
    pub wheels: WheelContact,
    /// Track on sprocket teeth.
    pub sprocket: SprocketContact,
    /// The sprocket drive.
    pub drive: Drive,
    /// The link (numbered from 1) whose joint to the next is recorded as
    /// `tension`.
    pub tension_link: usize,
    /// The arms' torsion springs and dampers, one per arm of the chassis
    /// (any order), replacing the rates compiled into the chassis model;
    /// `None` runs with the compiled ones ([`ChassisModel::PARTS`]).
    pub arms: Option<Vec<ArmSpring>>,
    /// Soft soil under the track ([`on_soil`](Self::on_soil)): `None`
    /// drives on the rigid [`ground`](Self::ground). Its surface must be
    /// the ground's terrain; the ground's laws are then not used.
    pub soil: Option<SoftGround>,
    /// A drawbar load, N: a horizontal force pulling the chassis back at
    /// its centroid (negative pushes it forward). Default 0. The energy it
    /// takes out is booked with the dissipated work.
    pub drawbar_pull: f64,
}

impl VehicleConfig {
    /// The default normal law of shoes on the ground: Hunt-Crossley,
    /// `k` = 2e6 N/m per shoe point, exponent 1, `χ` = 2 s/m (see
    /// [`m113`](Self::m113) for why).
    pub const GROUND_LAW: NormalLaw = NormalLaw::HuntCrossley {
        stiffness: 2e6,
        exponent: 1.0,
        chi: 2.0,
    };
    /// The default friction of shoes on the ground: μ = 0.8 over 0.1 m/s
    /// of slip.
    pub const GROUND_FRICTION: Friction = Friction { mu: 0.8, slip: 0.1 };
    /// The default normal law of the track on wheel rims and sprocket
    /// teeth: Hunt-Crossley, `k` = 1e7 N/m, exponent 1, `χ` = 0.5 s/m.
    pub const RIM_LAW: NormalLaw = NormalLaw::HuntCrossley {
        stiffness: 1e7,
        exponent: 1.0,
        chi: 0.5,
    };
    /// The default friction of the track on rims and teeth: μ = 0.4 over
    /// 0.5 m/s of slip.
    pub const RIM_FRICTION: Friction = Friction { mu: 0.4, slip: 0.5 };

    /// A vehicle with these shoes and sprocket teeth on `terrain`, driven
    /// by `drive`, with the default contact laws ([`GROUND_LAW`](Self::GROUND_LAW),
    /// [`GROUND_FRICTION`](Self::GROUND_FRICTION), [`RIM_LAW`](Self::RIM_LAW)
    /// and [`RIM_FRICTION`](Self::RIM_FRICTION) on wheels and sprocket),
    /// tension recorded at link 1 and the arms' compiled springs.
    pub fn new(
        shoe: ShoeGeometry,
        profile: ToothProfile,
        terrain: Terrain,
        drive: Drive,
    ) -> VehicleConfig {
        VehicleConfig {
            shoe,
            ground: GroundContact {
                terrain,
                normal: Self::GROUND_LAW,
                friction: Self::GROUND_FRICTION,
            },
            wheels: WheelContact {
                normal: Self::RIM_LAW,
                friction: Self::RIM_FRICTION,
            },
            sprocket: SprocketContact {
                profile,
                normal: Self::RIM_LAW,
                friction: Self::RIM_FRICTION,
            },
            drive,
            tension_link: 1,
            arms: None,
            soil: None,
            drawbar_pull: 0.0,
        }
    }

    /// Puts the track on soft `soil` over the ground's terrain (its
    /// undisturbed surface), for a track `width` m wide whose shoes are
    /// `pitch` m long on the ground (each shoe's ground points share a
    /// footprint of `width × pitch`, so the track bears on its whole
    /// contact length): see [`SoftGround`]. A soil that fails
    /// [`Soil::check`], or a width or pitch that is not positive, is an
    /// error.
    pub fn on_soil(&mut self, soil: Soil, width: f64, pitch: f64) -> Result<(), SoilError> {
        self.soil = Some(SoftGround::new(
            soil,
            self.ground.terrain.clone(),
            width,
            pitch,
            &self.shoe,
        )?);
        Ok(())
    }

    /// The M113's contact (shoes and sprocket of `shared/spec/m113.md`,
    /// friction 0.8 on the ground and 0.4 on wheels and sprocket) on
    /// `terrain`, driven by `drive`: [`new`](Self::new) with
    /// [`ShoeGeometry::m113`] and [`ToothProfile::m113`]. The vehicle
    /// declared in `trackgen::vehicles::m113` gives the same from its
    /// declaration (`M113::config`).
    ///
    /// Normal laws are Hunt-Crossley with exponent 1 (`F = k δ (1 + χ δ̇)`:
    /// no force jump when a contact opens or closes, which would make an
    /// adaptive integrator stumble at each of the thousands of contact
    /// changes of a run). Stiffnesses: ground 2e6 N/m per shoe point, rims
    /// and teeth 1e7 N/m, so static penetrations stay within a few
    /// millimetres. The `χ` (2 and 0.5 s/m) damp the contacts without
    /// making the light shoes' rotation the stiffest mode of the model.
    /// Friction is regularised over 0.1 m/s of slip on the ground, where it
    /// carries the traction, and over 0.5 m/s on rims and teeth, where it
    /// only spins the wheels up and rubs the flanks: the friction slope
    /// `μ F_n / v_s` on an 18 kg shoe under a loaded rim is the stiffest mode
    /// of the model, and sets the explicit integrator's step (measured: the
    /// step grows 1.75× from 0.2 to 0.5 m/s; without rim friction at all,
    /// 2×).
    pub fn m113(terrain: Terrain, drive: Drive) -> VehicleConfig {
        Self::new(ShoeGeometry::m113(), ToothProfile::m113(), terrain, drive)
    }
}

impl VehicleConfig {
    /// Moves the rest angle of the tensioner's spring to where the
    /// assembly set the arm (`assembled.tensioner`), as a track adjuster
    /// does: the tensioner then pushes with its declared preload at the
    /// start, and the track's tension comes from that preload, not from a
    /// spring wound up by however far the assembly swung the arm. In
    /// `τ = preload − k φ`, the preload becomes `preload + k φ₀` (the
    /// arms' compiled rates are copied into [`arms`](Self::arms) first if
    /// it is `None`). Nothing changes without a tensioner.
    pub fn adjust_tensioner<C: ChassisModel<DC>, const DC: usize, const DT: usize>(
        &mut self,
        assembled: &super::Assembled<DT, DC>,
    ) {
        let Some((body, angle)) = assembled.tensioner else {
            return;
        };
        let arms = self
            .arms
            .get_or_insert_with(|| declared_arms::<C, DC>().copied().collect());
        for arm in arms.iter_mut().filter(|a| a.body == body) {
            arm.preload += arm.stiffness * angle;
        }
    }
}

/// The arms' springs a vehicle runs with: `arms` if given, checked to be
/// one per arm of `C` with finite rates, stiffness and damping zero or
/// more; otherwise the compiled ones.
pub(super) fn checked_arms<C: ChassisModel<DC>, const DC: usize>(
    arms: Option<&[ArmSpring]>,
) -> Result<Vec<ArmSpring>, SimulationError> {
    let declared: Vec<ArmSpring> = declared_arms::<C, DC>().copied().collect();
    let Some(arms) = arms else {
        return Ok(declared);
    };
    let mut bodies: Vec<usize> = arms.iter().map(|a| a.body).collect();
    let mut expected: Vec<usize> = declared.iter().map(|a| a.body).collect();
    bodies.sort_unstable();
    expected.sort_unstable();
    if bodies != expected {
        return Err(SimulationError::Setup(format!(
            "the configured arms act on bodies {bodies:?}; the chassis has arms at bodies {expected:?}"
        )));
    }
    for arm in arms {
        let rates_ok = arm.stiffness >= 0.0 && arm.damping >= 0.0;
        let finite = [arm.stiffness, arm.damping, arm.preload]
            .iter()
            .all(|v| v.is_finite());
        if !(rates_ok && finite) {
            return Err(SimulationError::Setup(format!(
                "the arm at body {} needs finite stiffness and damping of zero or more and a finite preload, \
                 got stiffness {}, damping {}, preload {}",
                arm.body, arm.stiffness, arm.damping, arm.preload
            )));
        }
    }
    Ok(arms.to_vec())
}
