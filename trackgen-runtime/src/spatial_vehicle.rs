//! The spatial vehicle's force elements and forward dynamics: the hull
//! (its frame with both sides' running gear, one planar tree floating in
//! space) and each side's track (a closed chain floating in its own
//! plane), three kinematically decoupled subsystems coupled by contact
//! alone, after Choi, Lee & Shabana, "Spatial dynamics of multibody
//! tracked vehicles" (*Vehicle System Dynamics* 29, 1998).
//!
//! The force elements, each from the bodies' world poses and motion:
//! - **the ground** (`contact::space`): every planar ground point of
//!   every shoe becomes two points across the shoe's width, at
//!   `±w/(2√3)` from its middle (two-point Gauss–Legendre across a
//!   uniform strip: the pair carries the strip's force and its moment of
//!   area, `w²/12` of the force's stiffness), each with half the normal
//!   law's stiffness (and a Kelvin–Voigt law's damping): on level ground
//!   with the track upright, the planar contact;
//! - **the rims and the guides** (`contact::axial`): each road wheel,
//!   idler and roller on its own side's track, the shoe's guide at the
//!   middle of its running face;
//! - **the teeth** (`contact::axial`): each sprocket on its own side's
//!   pins;
//! - **the arms' torsion springs**, as in the plane (`φ` the arm's angle
//!   from its design position relative to the frame; the planar torque
//!   `τ` is a moment `−τ η` in space, the plane's counter-clockwise being
//!   about its normal's reverse).
//!
//! Friction on the ground is regularised, or stiction with a deflection
//! per ground point in the ground's plane (two components, in the
//! surface's forward and left tangents: friction is isotropic there, and
//! a shoe sliding sideways in a turn is what resists the turn); a point
//! off the ground lets its deflection relax. On soft soil
//! ([`SpatialLaws::soil`]) the soil's laws replace the ground's, each
//! point's state its shear displacement in the ground's plane
//! (`contact::soft_space`), the rut pressed after each accepted step
//! ([`SpatialSystem::after_step`]). Each side's sprocket
//! has its own drive ([`SideDrives`]), or one drive reaches both through
//! a differential steered by brakes or a steer unit ([`Driveline`]).
//! [`SpatialSystem`] integrates the vehicle in time.

mod asked;
mod bodies;
mod declared;
mod drawbar;
mod drive;
mod driveline;
mod engine;
mod envelope;
mod ground;
mod on_course;
mod on_soil;
mod outputs;
mod rows;
mod scene;
mod steering;
mod system;
mod tensions;

pub use asked::{DrivelineAsked, DrivelineKind, asked_driveline, drive_as_asked};
use bodies::Bodies;
pub use declared::{HULL_MOTIONS, SpatialSimulated, SpatialVehicleSystem};
pub use drive::{DriveState, Driver};
pub use driveline::{
    Differential, DifferentialSteer, Driveline, DrivelineError, FullSteer, SideDrives, SteerDrive,
    SteerInput, SteerRatiosError, SteerUnit, SteeringBrakes, span, steer_drive_ratio,
};
pub use engine::{SpatialEngine, SpatialEngineError};
pub use envelope::EngineEnvelope;
pub use on_course::{OnCourseError, SpatialGround, on_course, on_grid, on_ground, on_grounds};
pub use outputs::{SideOutputs, SpatialOutputs};
pub use rows::{SPATIAL_COLUMNS, spatial_row};
pub use scene::{FLOOR_REACH, FLOOR_STEP, SpatialScene};
pub use steering::{HeadingHold, HeadingSchedule, SteeringError};
pub use system::{SideBooks, SpatialEnergy, SpatialSystem};
pub use tensions::TrackTensions;

use nalgebra::{Matrix3, SVector, Vector2, Vector3};

use crate::contact::axial::{GuideLaw, RimContact, SpaceFace, SpaceSprocket, SpaceWheel};
use crate::contact::soft_space::SoftSpace;
use crate::contact::sprocket::{Gaps, ToothProfile, pitch_radius, rolling_radius};
use crate::contact::{ContactLaws, GroundLaws, ShoeGeometry};
use crate::multibody::{
    ArmSpring, ChassisModel, ChassisPart, ClosingJoint, DynamicsError, PartKind, TrackModel,
};
use crate::spatial::{
    FloatingTree, PlaneMotion, PlanePose, PlaneRates, Side, SpatialError, SpatialLayout,
    SpatialLoad, plane_rotation,
};
use crate::terrain::field::HeightField;
use crate::terrain::soil::Soil;

/// The laws of the spatial vehicle's contacts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpatialLaws {
    /// Each planar ground point's law (its friction regularised), as the
    /// planar vehicle's: split across the width here.
    pub ground: GroundLaws,
    /// The rims on the shoes.
    pub wheels: ContactLaws,
    /// The teeth on the pins.
    pub sprocket: ContactLaws,
    /// The centre guides against the wheels.
    pub guide: GuideLaw,
    /// Soft soil under the tracks instead of rigid ground: its laws
    /// replace [`ground`](Self::ground)'s (`contact::soft_space`: the
    /// planar soft ground's at each point across the width). `None`:
    /// rigid ground.
    pub soil: Option<Soil>,
}

impl SpatialLaws {
    /// Every law's parameters in their ranges; the first out of range as
    /// an error naming its contacts.
    pub fn check(&self) -> Result<(), SpatialError> {
        let law = |pair, checked: Result<(), crate::laws::ParameterError>| {
            checked.map_err(|source| SpatialError::Law { pair, source })
        };
        law("ground", self.ground.check())?;
        law("rims", self.wheels.check())?;
        law("teeth", self.sprocket.check())?;
        law("guides", self.guide.check())?;
        if let Some(soil) = &self.soil {
            soil.check().map_err(SpatialError::Soil)?;
        }
        Ok(())
    }
}

/// One tree's pose and motion.
#[derive(Debug, Clone, PartialEq)]
pub struct TreeState<const D: usize> {
    /// Where it is.
    pub pose: PlanePose<D>,
    /// How it moves.
    pub rates: PlaneRates<D>,
}

impl<const D: usize> TreeState<D> {
    /// The pose and the rates together, as the bodies' routes take them
    /// (`Bodies` does not see this type).
    fn parts(&self) -> (&PlanePose<D>, &PlaneRates<D>) {
        (&self.pose, &self.rates)
    }
}

/// What the force elements give at a state: every body's load and the
/// books.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SpatialLoads {
    /// Each hull body's load.
    pub hull: Vec<SpatialLoad>,
    /// Each right-track link's.
    pub right: Vec<SpatialLoad>,
    /// Each left-track link's.
    pub left: Vec<SpatialLoad>,
    /// Elastic energy stored in the contacts and springs, J.
    pub potential: f64,
    /// Power they dissipate, W.
    pub dissipation: f64,
    /// Where that power is lost on each side (right, left): `dissipation`
    /// is their sum, the same terms added in another order.
    pub losses: [SideLosses; 2],
}

/// The power a side's force elements dissipate, W.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SideLosses {
    /// The ground under the track (its normal law's damping, the
    /// shoes' slip and their stiction's damper and relaxing).
    pub ground: f64,
    /// The running gear on the track: the rims, the guides and the
    /// sprocket's teeth.
    pub running_gear: f64,
    /// The side's suspension: its arms' dampers.
    pub suspension: f64,
}

/// What a right-hand side's loads reuse from one evaluation to the next:
/// the trees' bodies in the world (the hull's, the right track's, the
/// left's) and the loads.
#[derive(Default)]
pub(crate) struct LoadScratch {
    bodies: [Bodies; 3],
    loads: SpatialLoads,
    /// Each track's joint forces (right, left; one per link).
    joint_forces: [Vec<Vector2<f64>>; 2],
}

/// What the ground gives one of a track's ground points at a state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GroundForce {
    /// The track's side.
    pub side: Side,
    /// The link the point belongs to (0 the chain's root).
    pub link: usize,
    /// The point in the world, m.
    pub at: Vector3<f64>,
    /// The ground's force on the link there, N (world axes).
    pub force: Vector3<f64>,
}

/// The whole vehicle's mass and the motion of its centre of mass.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MassCentre {
    /// The mass of the hull and both tracks, kg.
    pub mass: f64,
    /// Where the centre of mass is, m.
    pub position: Vector3<f64>,
    /// How fast it moves, m/s.
    pub velocity: Vector3<f64>,
}

/// A side's driven sprocket: its body in the hull and its rolling radius,
/// m (the track's mean speed per unit of its speed,
/// [`rolling_radius`]).
#[derive(Debug, Clone, Copy, PartialEq)]
struct DrivenSprocket {
    body: usize,
    rolling_radius: f64,
    /// The pitch circle's radius, m (the pins' seat).
    pitch_radius: f64,
}

/// The spatial vehicle: its three trees, its layout, the shoe and the
/// sprocket's profile, the contacts' laws and the ground.
pub struct SpatialDynamics<'m, H, const DH: usize, R, const DR: usize, L, const DL: usize> {
    /// The hull with both sides' running gear.
    pub hull: FloatingTree<'m, H, DH>,
    /// The right track.
    pub right: FloatingTree<'m, R, DR>,
    /// The left track.
    pub left: FloatingTree<'m, L, DL>,
    parts: &'static [ChassisPart],
    sides: Vec<Side>,
    /// Each side's sprocket (right, left), where it has one.
    sprockets: [Option<DrivenSprocket>; 2],
    shoe: ShoeGeometry,
    profile: ToothProfile,
    /// The profile's gaps, found once.
    gaps: Gaps,
    laws: SpatialLaws,
    field: HeightField,
    /// The soft soil and what it remembers, on soil ([`SpatialLaws::soil`]).
    soil: Option<SoftSpace>,
    /// The tracks' centre planes apart, m.
    gauge: f64,
    /// Every arm's spring, the declared one but for each tensioner's rest
    /// angle moved to where the assembly set it
    /// ([`set_tensioners`](Self::set_tensioners)).
    arms: Vec<ArmSpring>,
}

impl<'m, H, const DH: usize, R, const DR: usize, L, const DL: usize>
    SpatialDynamics<'m, H, DH, R, DR, L, DL>
where
    H: ChassisModel<DH>,
    R: TrackModel<DR>,
    L: TrackModel<DL>,
{
    /// The vehicle of these compiled trees laid out as `layout` says,
    /// with the shoe, the profile, the laws and the ground. A layout that
    /// does not fit the trees (an inertia or offset per body, a side per
    /// part) is an error, and so is a track whose links differ in length
    /// (a sprocket's rolling radius needs one pitch), and so is a law
    /// out of its range ([`SpatialLaws::check`]), and on soft soil a shoe
    /// with no width.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        hull: &'m H,
        (right, left): (&'m R, &'m L),
        layout: &SpatialLayout,
        shoe: ShoeGeometry,
        profile: ToothProfile,
        laws: SpatialLaws,
        field: HeightField,
    ) -> Result<Self, SpatialError> {
        laws.check()?;
        if layout.part_sides.len() != H::PARTS.len() {
            return Err(SpatialError::Sides {
                parts: H::PARTS.len(),
                given: layout.part_sides.len(),
            });
        }
        let pitches = [
            (Side::Right, right.description().pitch()),
            (Side::Left, left.description().pitch()),
        ];
        let soil = match laws.soil {
            None => None,
            Some(soil) => {
                let [right_pitch, left_pitch] = pitches.map(|(side, pitch)| {
                    pitch.map_err(|source| SpatialError::Pitch { side, source })
                });
                let pitches = [right_pitch?, left_pitch?];
                let links = [R::BODIES, L::BODIES];
                Some(SoftSpace::new(soil, &shoe, pitches, links).map_err(SpatialError::Soil)?)
            }
        };
        let mut sprockets = [None; 2];
        for (s, (side, pitch)) in pitches.into_iter().enumerate() {
            let Some((part, _)) = H::PARTS
                .iter()
                .zip(&layout.part_sides)
                .find(|(p, at)| p.kind == PartKind::Sprocket && **at == side)
            else {
                continue;
            };
            let pitch = pitch.map_err(|source| SpatialError::Pitch { side, source })?;
            sprockets[s] = Some(DrivenSprocket {
                body: part.body,
                rolling_radius: rolling_radius(profile.teeth, pitch),
                pitch_radius: pitch_radius(profile.teeth, pitch),
            });
        }
        Ok(SpatialDynamics {
            hull: FloatingTree::new(hull, layout.hull_across.clone())?
                .with_offsets(layout.hull_offsets.clone())?,
            right: FloatingTree::new(right, layout.right_links.clone())?,
            left: FloatingTree::new(left, layout.left_links.clone())?,
            parts: H::PARTS,
            sides: layout.part_sides.clone(),
            sprockets,
            shoe,
            gaps: Gaps::of(&profile),
            profile,
            laws,
            field,
            soil,
            gauge: layout.gauge,
            arms: H::PARTS.iter().filter_map(|p| p.arm).collect(),
        })
    }

    /// Each side's tensioner as the assembly set it on its track (right,
    /// left: the arm's body in the hull and its angle from the declared
    /// position, rad; [`AssembledSides::tensioners`](crate::assembly::AssembledSides)):
    /// its spring's rest angle is moved there, as the planar vehicle's (a
    /// track adjuster's job: the tensioner then pushes with its declared
    /// preload, `τ = preload − k φ` becoming `preload + k φ₀ − k φ`).
    pub fn set_tensioners(&mut self, tensioners: [Option<(usize, f64)>; 2]) {
        self.arms = self.parts.iter().filter_map(|p| p.arm).collect();
        for (body, set) in tensioners.iter().flatten() {
            for arm in self.arms.iter_mut().filter(|a| a.body == *body) {
                arm.spring.preload += arm.spring.stiffness * set;
            }
        }
    }

    /// How many values each track's ground points' stiction deflections
    /// (on soil, shear displacements) take (right, left): two per point
    /// (each planar ground point of each link as two across the width),
    /// none under regularised friction on rigid ground.
    pub fn ground_states(&self) -> [usize; 2] {
        if self.soil.is_none() && !self.laws.ground.friction.has_state() {
            return [0; 2];
        }
        let per_link = 2 * 2 * self.shoe.ground_points.len();
        [
            per_link * self.right.masses().len(),
            per_link * self.left.masses().len(),
        ]
    }

    /// Every force element's loads at a state, the ground's stiction
    /// deflections (if any) relaxed.
    pub fn loads(
        &self,
        hull: &TreeState<DH>,
        right: &TreeState<DR>,
        left: &TreeState<DL>,
    ) -> SpatialLoads {
        let [r, l] = self.ground_states();
        let (mut right_rates, mut left_rates) = (vec![0.0; r], vec![0.0; l]);
        self.loads_with(
            (hull, right, left),
            [&vec![0.0; r], &vec![0.0; l]],
            [&mut right_rates, &mut left_rates],
        )
    }

    /// Every force element's loads at a state with each track's ground
    /// points' stiction `deflections` (m, [`ground_states`](Self::ground_states)
    /// values each: point by point, link by link, forward then left),
    /// their rates into `rates`.
    pub fn loads_with(
        &self,
        states: (&TreeState<DH>, &TreeState<DR>, &TreeState<DL>),
        deflections: [&[f64]; 2],
        rates: [&mut [f64]; 2],
    ) -> SpatialLoads {
        self.loads_in(&self.plane_motions(states), states, deflections, rates)
    }

    /// Each tree's bodies in its plane at a state
    /// ([`FloatingTree::plane_motion`]): found once per evaluation, read
    /// by [`loads_in`](Self::loads_in) and
    /// [`accelerations_in`](Self::accelerations_in).
    pub fn plane_motions(
        &self,
        (hull, right, left): (&TreeState<DH>, &TreeState<DR>, &TreeState<DL>),
    ) -> [PlaneMotion; 3] {
        [
            self.hull.plane_motion(&hull.pose, &hull.rates),
            self.right.plane_motion(&right.pose, &right.rates),
            self.left.plane_motion(&left.pose, &left.rates),
        ]
    }

    /// [`loads_with`](Self::loads_with) with the trees' `motions` in
    /// their planes found already ([`plane_motions`](Self::plane_motions)).
    pub fn loads_in(
        &self,
        motions: &[PlaneMotion; 3],
        states: (&TreeState<DH>, &TreeState<DR>, &TreeState<DL>),
        deflections: [&[f64]; 2],
        rates: [&mut [f64]; 2],
    ) -> SpatialLoads {
        let mut scratch = LoadScratch::default();
        self.loads_into(motions, states, deflections, rates, &mut scratch);
        scratch.loads
    }

    /// [`loads_in`](Self::loads_in) into `scratch.loads`, the bodies'
    /// world motion in `scratch.bodies`: a right-hand side's loads found
    /// without allocating.
    pub(crate) fn loads_into(
        &self,
        motions: &[PlaneMotion; 3],
        (hull, right, left): (&TreeState<DH>, &TreeState<DR>, &TreeState<DL>),
        deflections: [&[f64]; 2],
        rates: [&mut [f64]; 2],
        scratch: &mut LoadScratch,
    ) {
        let [frame, right_links, left_links] = &mut scratch.bodies;
        frame.fill(&self.hull, &motions[0], hull.parts());
        right_links.fill(&self.right, &motions[1], right.parts());
        left_links.fill(&self.left, &motions[2], left.parts());
        let [frame, tracks @ ..] = &scratch.bodies;
        let out = &mut scratch.loads;
        for (loads, bodies) in [
            (&mut out.hull, frame),
            (&mut out.right, &tracks[0]),
            (&mut out.left, &tracks[1]),
        ] {
            loads.clear();
            loads.resize(bodies.len(), SpatialLoad::default());
        }
        (out.potential, out.dissipation) = (0.0, 0.0);
        out.losses = [SideLosses::default(); 2];
        let plane = plane_rotation(hull.pose.yaw, hull.pose.roll);
        let mut rates = rates.into_iter();
        for (s, side) in [Side::Right, Side::Left].into_iter().enumerate() {
            let links = &tracks[s];
            let mut link_loads = std::mem::take(match side {
                Side::Right => &mut out.right,
                Side::Left => &mut out.left,
            });
            let books = self.ground(
                side,
                links,
                &mut link_loads,
                (deflections[s], rates.next().unwrap_or_default()),
                None,
            );
            out.potential += books.0;
            out.dissipation += books.1;
            out.losses[s].ground = books.1;
            for (part, _) in self
                .parts
                .iter()
                .zip(&self.sides)
                .filter(|(_, p)| **p == side)
            {
                let books = self.running_gear(
                    part,
                    (frame, hull, &plane),
                    links,
                    (&mut out.hull, &mut link_loads),
                );
                out.potential += books.0;
                out.dissipation += books.1;
                out.losses[s].running_gear += books.1;
            }
            match side {
                Side::Right => out.right = link_loads,
                Side::Left => out.left = link_loads,
            }
        }
        let books = self.arms(hull, &plane, &mut out.hull, &mut out.losses);
        out.potential += books.0;
        out.dissipation += books.1;
    }

    /// What the ground gives each ground point on it at a state, the
    /// tracks' ground deflections `deflections` (m, right then left, as
    /// [`loads_with`](Self::loads_with) takes them): the right track's
    /// points, then the left's, link by link.
    pub fn ground_forces(
        &self,
        (right, left): (&TreeState<DR>, &TreeState<DL>),
        deflections: [&[f64]; 2],
    ) -> Vec<GroundForce> {
        let tracks = [
            Bodies::at(&self.right, right.parts()),
            Bodies::at(&self.left, left.parts()),
        ];
        self.ground_forces_of([&tracks[0], &tracks[1]], deflections)
    }

    /// [`ground_forces`](Self::ground_forces) on the tracks' links in the
    /// world found already (right, left).
    fn ground_forces_of(&self, tracks: [&Bodies; 2], deflections: [&[f64]; 2]) -> Vec<GroundForce> {
        let mut out = Vec::new();
        for (s, side) in [Side::Right, Side::Left].into_iter().enumerate() {
            let links = tracks[s];
            let mut loads = vec![SpatialLoad::default(); links.len()];
            let mut rates = vec![0.0; deflections[s].len()];
            self.ground(
                side,
                links,
                &mut loads,
                (deflections[s], &mut rates),
                Some(&mut out),
            );
        }
        out
    }

    /// The centre of mass of the hull and both tracks, and its velocity,
    /// at a state: the mass-weighted mean of every body's centroid.
    pub fn mass_centre(
        &self,
        (hull, right, left): (&TreeState<DH>, &TreeState<DR>, &TreeState<DL>),
    ) -> MassCentre {
        self.mass_centre_of(&self.bodies_at((hull, right, left)))
    }

    /// Every body of the hull, the right track and the left in the world
    /// at a state.
    fn bodies_at(
        &self,
        (hull, right, left): (&TreeState<DH>, &TreeState<DR>, &TreeState<DL>),
    ) -> [Bodies; 3] {
        [
            Bodies::at(&self.hull, hull.parts()),
            Bodies::at(&self.right, right.parts()),
            Bodies::at(&self.left, left.parts()),
        ]
    }

    /// [`mass_centre`](Self::mass_centre) of the bodies in the world found
    /// already ([`bodies_at`](Self::bodies_at)).
    fn mass_centre_of(&self, [hull, right, left]: &[Bodies; 3]) -> MassCentre {
        let mut total = MassCentre {
            mass: 0.0,
            position: Vector3::zeros(),
            velocity: Vector3::zeros(),
        };
        let mut add = |bodies: &Bodies, masses: &[f64]| {
            for ((at, velocity), &m) in bodies
                .centroids()
                .iter()
                .zip(bodies.velocities())
                .zip(masses)
            {
                total.mass += m;
                total.position += m * at;
                total.velocity += m * velocity;
            }
        };
        add(hull, self.hull.masses());
        add(right, self.right.masses());
        add(left, self.left.masses());
        total.position /= total.mass;
        total.velocity /= total.mass;
        total
    }

    /// One part of the hull on its side's track: a rim with the guide, or
    /// the teeth; the loads on both; what they store and dissipate.
    fn running_gear(
        &self,
        part: &ChassisPart,
        (frame, hull, plane): (&Bodies, &TreeState<DH>, &Matrix3<f64>),
        links: &Bodies,
        (hull_loads, link_loads): (&mut [SpatialLoad], &mut [SpatialLoad]),
    ) -> (f64, f64) {
        let b = part.body;
        let (centre, velocity, spin) = (frame.centroid(b), frame.velocity(b), frame.spin(b));
        let reach = match part.kind {
            PartKind::Sprocket => self.profile.addendum,
            _ => part.radius + self.laws.guide.height,
        } + self.shoe.extent();
        let (mut potential, mut dissipation) = (0.0, 0.0);
        let sprocket = (part.kind == PartKind::Sprocket).then(|| {
            let sprocket = SpaceSprocket {
                centre,
                axes: [plane.column(0).into(), plane.column(2).into()],
                angle: hull.pose.planar[2 + b],
                velocity,
                angular_velocity: spin,
            };
            (sprocket, sprocket.in_plane())
        });
        for k in links.near(centre, reach * reach) {
            let [rear, front] = self.shoe.inner_face;
            // Written out, not `inner_face.map(…)`: the array's map left
            // its closure out of line in this loop (1.7 million calls in
            // 2 s of the M113, 2 % of the evaluation).
            let face = SpaceFace {
                ends: [links.point(k, rear), links.point(k, front)],
                inward: links.axis(k, 2),
                guide: links.point(k, (self.shoe.inner_face[0] + self.shoe.inner_face[1]) / 2.0),
                centroid: links.centroid(k),
                velocity: links.velocity(k),
                angular_velocity: links.spin(k),
            };
            if let Some((sprocket, turned)) = &sprocket {
                for pin in &self.shoe.pins {
                    let x = links.point(k, *pin);
                    let Some(contact) = sprocket.pin_contact_among(
                        (&self.profile, &self.gaps, turned),
                        &face,
                        x,
                        self.shoe.pin_radius,
                    ) else {
                        continue;
                    };
                    let force = self.laws.sprocket.respond_axial(&contact);
                    links.push(link_loads, k, force.force, contact.point);
                    frame.push(hull_loads, b, -force.force, contact.point);
                    potential += force.potential;
                    dissipation += force.dissipation;
                }
            } else {
                let wheel = SpaceWheel {
                    centre,
                    axle: frame.axis(b, 1),
                    radius: part.radius,
                    velocity,
                    angular_velocity: spin,
                };
                let Some(rim) = RimContact::near(&wheel, &face, self.laws.guide.height) else {
                    continue;
                };
                // A force that is exactly zero (the guide inside its
                // play, the rim short of the face) is not added: adding
                // a zero leaves every load's bits as they were (a load
                // starts at +0, and +0 + −0 is +0).
                let guide = self.laws.guide.respond(&rim);
                if guide.force != 0.0 {
                    let along = rim.contact.axle * guide.force;
                    links.push(link_loads, k, along, rim.guide);
                    frame.push(hull_loads, b, -along, rim.guide);
                }
                let mut radial = rim.contact.normal * guide.radial;
                potential += guide.potential;
                dissipation += guide.dissipation;
                let touching = rim.contact.depth > 0.0;
                if touching {
                    let force = self.laws.wheels.respond_axial(&rim.contact);
                    radial += force.force;
                    potential += force.potential;
                    dissipation += force.dissipation;
                }
                if touching || guide.radial != 0.0 {
                    links.push(link_loads, k, radial, rim.contact.point);
                    frame.push(hull_loads, b, -radial, rim.contact.point);
                }
            }
        }
        (potential, dissipation)
    }

    /// The arms' torsion springs: the planar torque `τ` on the arm as the
    /// moment `−τ η`, its reverse on the frame; what each dissipates
    /// added to its side's `losses` too.
    fn arms(
        &self,
        hull: &TreeState<DH>,
        plane: &Matrix3<f64>,
        loads: &mut [SpatialLoad],
        losses: &mut [SideLosses; 2],
    ) -> (f64, f64) {
        let eta: Vector3<f64> = plane.column(1).into();
        let (q, qd) = (&hull.pose.planar, &hull.rates.planar);
        let (mut potential, mut dissipation) = (0.0, 0.0);
        // The arms are the parts' that have one, in the parts' order.
        let sides = (self.parts.iter().zip(&self.sides))
            .filter(|(part, _)| part.arm.is_some())
            .map(|(_, side)| *side);
        for (arm, side) in self.arms.iter().zip(sides) {
            let (phi, rate) = (q[2 + arm.body] - q[2], qd[2 + arm.body] - qd[2]);
            let response = arm.spring.respond(phi, rate);
            loads[arm.body].moment -= eta * response.force;
            loads[0].moment += eta * response.force;
            potential += response.potential;
            dissipation += response.dissipation;
            losses[side.index()].suspension += response.dissipation;
        }
        (potential, dissipation)
    }

    /// The three trees' accelerations under the force elements and
    /// gravity, the tracks' loops closed by the plain constraint: for
    /// each, the rates of its quasi-velocities in its plane (the planar
    /// `q̈_i`) and across it.
    pub fn accelerations(
        &self,
        hull: &TreeState<DH>,
        right: &TreeState<DR>,
        left: &TreeState<DL>,
    ) -> Result<Accelerations<DH, DR, DL>, DynamicsError> {
        let closed = ClosingJoint::Constrained {
            stabilisation: Vector2::zeros(),
        };
        let loads = self.loads(hull, right, left);
        self.accelerations_under(hull, right, left, &loads, [closed; 2])
    }

    /// [`accelerations`](Self::accelerations) under `loads`, each track's
    /// loop as `closing` says (right, left).
    pub fn accelerations_under(
        &self,
        hull: &TreeState<DH>,
        right: &TreeState<DR>,
        left: &TreeState<DL>,
        loads: &SpatialLoads,
        closing: [ClosingJoint; 2],
    ) -> Result<Accelerations<DH, DR, DL>, DynamicsError> {
        let states = (hull, right, left);
        let mut forces = [
            vec![Vector2::zeros(); self.right.masses().len()],
            vec![Vector2::zeros(); self.left.masses().len()],
        ];
        let [r, l] = &mut forces;
        self.accelerations_in(
            &self.plane_motions(states),
            states,
            (loads, closing),
            [r, l],
        )
    }

    /// [`accelerations_under`](Self::accelerations_under) with the trees'
    /// `motions` in their planes found already
    /// ([`plane_motions`](Self::plane_motions)), each track's joint forces
    /// written to `joint_forces` (right, left; one per link, as
    /// [`FloatingTree::closed_accelerations_in`] writes them).
    ///
    /// # Panics
    /// If `joint_forces` are not one per link (a programming error).
    pub fn accelerations_in(
        &self,
        motions: &[PlaneMotion; 3],
        (hull, right, left): (&TreeState<DH>, &TreeState<DR>, &TreeState<DL>),
        (loads, closing): (&SpatialLoads, [ClosingJoint; 2]),
        joint_forces: [&mut [Vector2<f64>]; 2],
    ) -> Result<Accelerations<DH, DR, DL>, DynamicsError> {
        let [m_hull, m_right, m_left] = motions;
        let [f_right, f_left] = joint_forces;
        Ok((
            self.hull
                .accelerations_in(m_hull, &hull.pose, &hull.rates, &loads.hull)?,
            self.right.closed_accelerations_in(
                m_right,
                (&right.pose, &right.rates),
                &loads.right,
                closing[0],
                f_right,
            )?,
            self.left.closed_accelerations_in(
                m_left,
                (&left.pose, &left.rates),
                &loads.left,
                closing[1],
                f_left,
            )?,
        ))
    }
}

/// The hull's, the right track's and the left track's accelerations, each
/// in its plane (the planar `q̈_i`) and across it.
pub type Accelerations<const DH: usize, const DR: usize, const DL: usize> = (
    (SVector<f64, DH>, Vector3<f64>),
    (SVector<f64, DR>, Vector3<f64>),
    (SVector<f64, DL>, Vector3<f64>),
);
