//! What a vehicle's evaluation works in, allocated once when the vehicle is
//! built and reused by every evaluation (no allocation in the right-hand
//! side), and its first stage: the bodies' kinematics.

use nalgebra::{SVector, Vector2};

use super::books::EnergyBooks;
use crate::contact::{BodyState, Contact, ContactJacobian};
use crate::multibody::{BodyLoad, RecursiveModel};

/// The buffers of an evaluation, filled stage by stage.
pub(super) struct Workspace {
    /// Every link's state (kinematics).
    pub links: Vec<BodyState>,
    /// Every chassis body's state.
    pub parts: Vec<BodyState>,
    /// `(sin θ, cos θ)` of every chassis body.
    pub part_trig: Vec<(f64, f64)>,
    /// The same as rotations, for a linearisation.
    pub part_rotations: Vec<crate::planar::Rotation>,
    /// Scratch for the generated body states.
    pub positions: Vec<Vector2<f64>>,
    /// Scratch for the generated body velocities.
    pub velocities: Vec<Vector2<f64>>,
    /// Every contact found (detection), in order: the ground's, then each
    /// part's in the order of the chassis' parts.
    pub contacts: Vec<Contact>,
    /// Every contact's Jacobian, in the order of `contacts`, when the
    /// evaluation was linearised ([`forces::linearise`](super::forces::linearise)).
    pub jacobians: Vec<ContactJacobian>,
    /// The chassis' contacts with the ground at the last evaluation: the
    /// hull's and the rims' on sharp corners; `link` is the chassis body
    /// (0: the frame, whose outline is the hull).
    pub chassis_contacts: Vec<Contact>,
    /// Their Jacobians, in their order, when linearised: the `link` rows
    /// and columns are the chassis body's.
    pub chassis_jacobians: Vec<ContactJacobian>,
    /// The loads on the links (force elements).
    pub track_loads: Vec<BodyLoad>,
    /// The loads on the chassis bodies.
    pub chassis_loads: Vec<BodyLoad>,
    /// The rate of every shoe ground point's tangential state: its
    /// stiction deflection on rigid ground, its shear displacement on soft
    /// soil.
    pub tangential_rate: Vec<f64>,
    /// Each ground point's normal force at this evaluation, N: `None` for
    /// a point off the ground (on soil: above the undisturbed surface; a
    /// point below it bearing nothing is `Some(0.0)`, as its shear state
    /// still moves with its link). The Jacobian and the own `W` couple a
    /// point's tangential state to its link where this is `Some`.
    pub ground_normal: Vec<Option<f64>>,
    /// What the force elements stored, dissipated and did, at the last
    /// evaluation.
    pub books: EnergyBooks,
    /// The time and state of the evaluation the workspace holds (`None`
    /// while one is under way, or after one failed).
    pub at: Option<f64>,
    /// The state of that evaluation.
    pub state: Vec<f64>,
    /// Whether the track's accelerations (and joint forces) were solved
    /// at that state.
    pub accelerated: bool,
    /// Every joint's tension (recording).
    pub tensions: Vec<f64>,
    /// Every joint's distance from the sprocket's pitch circle (recording).
    pub offsets: Vec<f64>,
    /// The chassis' `[q̇_i, q̈_i]` (recording: the seat's acceleration).
    pub chassis_rates: Vec<f64>,
}

impl Workspace {
    /// Buffers for `links` links, `bodies` chassis bodies and
    /// `tangential` tangential states.
    pub fn new(links: usize, bodies: usize, tangential: usize) -> Workspace {
        let resting = BodyState::at_rest(Vector2::zeros(), 0.0);
        let largest = links.max(bodies);
        Workspace {
            links: vec![resting; links],
            parts: vec![resting; bodies],
            part_trig: vec![(0.0, 1.0); bodies],
            part_rotations: Vec::with_capacity(bodies),
            positions: vec![Vector2::zeros(); largest],
            velocities: vec![Vector2::zeros(); largest],
            contacts: Vec::with_capacity(8 * links),
            jacobians: Vec::new(),
            chassis_contacts: Vec::new(),
            chassis_jacobians: Vec::new(),
            track_loads: vec![BodyLoad::ZERO; links],
            chassis_loads: vec![BodyLoad::ZERO; bodies],
            tangential_rate: vec![0.0; tangential],
            ground_normal: vec![None; tangential],
            books: EnergyBooks::default(),
            at: None,
            state: Vec::new(),
            accelerated: false,
            tensions: Vec::with_capacity(links),
            offsets: Vec::with_capacity(links),
            chassis_rates: vec![0.0; 2 * (bodies + 2)],
        }
    }

    /// Stage 1, kinematics: every link's state from the track's recovered
    /// `(q_i, q̇_i)` and trigonometry `link_trig`, and every chassis body's
    /// from `(q_i, q̇_i)` (its trigonometry computed here, once, and kept
    /// for the chassis' dynamics).
    pub fn kinematics<T, const DT: usize, C, const DC: usize>(
        &mut self,
        (track, link_trig): (&T, &[(f64, f64)]),
        (qt, qdt): (&SVector<f64, DT>, &SVector<f64, DT>),
        chassis: &C,
        (qc, qdc): (&SVector<f64, DC>, &SVector<f64, DC>),
    ) where
        T: RecursiveModel<DT>,
        C: RecursiveModel<DC>,
    {
        let n = T::BODIES;
        let (r, v) = (&mut self.positions[..n], &mut self.velocities[..n]);
        track.body_states_with_trig(link_trig, qt, qdt, r, v);
        for (b, link) in self.links.iter_mut().enumerate() {
            *link = BodyState::with_sin_cos(r[b], qt[2 + b], link_trig[b], v[b], qdt[2 + b]);
        }
        let m = C::BODIES;
        let (r, v) = (&mut self.positions[..m], &mut self.velocities[..m]);
        crate::trig::sin_cos_each(&qc.as_slice()[2..], &mut self.part_trig);
        chassis.body_states_with_trig(&self.part_trig, qc, qdc, r, v);
        for (b, part) in self.parts.iter_mut().enumerate() {
            *part = BodyState::with_sin_cos(r[b], qc[2 + b], self.part_trig[b], v[b], qdc[2 + b]);
        }
    }
}
