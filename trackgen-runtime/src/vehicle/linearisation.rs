//! A vehicle linearised at a state: what its exact Jacobian
//! (`jacobian.rs`) and ROS34PW2's own `W` (`implicit.rs`) both start
//! from, gathered once from the evaluation there (`VehicleSystem`'s
//! `linearised`): the bodies' states, every contact with its Jacobian
//! beside its load (`forces::linearise`), the arms' and the drive's
//! slopes, and the ground points' tangential states.

use super::drive::DriveSlopes;
use crate::contact::{Contact, ContactJacobian};
use crate::multibody::ArmSpring;
use crate::planar::Rotation;

/// The ground points' tangential states at a linearisation.
#[derive(Debug, Clone, Copy)]
pub(super) struct GroundPoints<'a> {
    /// Ground points per link.
    pub per_link: usize,
    /// The unit of the stiction deflections, m (1 on soil).
    pub unit: f64,
    /// Each point's normal force, `None` off the ground (empty without
    /// tangential states).
    pub touching: &'a [Option<f64>],
    /// `∂ż/∂z` of a lifted point's relaxing deflection, with stiction.
    pub relaxation: Option<f64>,
}

/// A vehicle linearised at a state.
pub(super) struct Linearisation<'a> {
    /// The track's recovered `q_i`, `q̇_i` and every link's `(sin θ, cos θ)`.
    pub track: (&'a [f64], &'a [f64], &'a [(f64, f64)]),
    /// The dependent pair (0-based links).
    pub pair: [usize; 2],
    /// The chassis' `q_i`, `q̇_i` and every body's rotation.
    pub chassis: (&'a [f64], &'a [f64], &'a [Rotation]),
    /// Every contact at the state, and each one's Jacobian in the same
    /// order.
    pub contacts: &'a [Contact],
    /// The contacts' Jacobians.
    pub jacobians: &'a [ContactJacobian],
    /// The chassis bodies' contacts with the ground (the hull's, the
    /// rims'), `link` the body, and their Jacobians in the same order.
    pub chassis_contacts: (&'a [Contact], &'a [ContactJacobian]),
    /// The arms' springs.
    pub arms: &'a [ArmSpring],
    /// The sprocket's body and the drive's slopes.
    pub drive: Option<(usize, DriveSlopes)>,
    /// The ground points' tangential states.
    pub points: GroundPoints<'a>,
}
