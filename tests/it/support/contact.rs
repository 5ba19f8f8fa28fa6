//! The contact pairs as a whole, composed from the runtime's stages as the
//! vehicle composes them (`trackgen::contact`: detection, then each
//! contact's response applied to both bodies): what the contact tests
//! check by hand.

use trackgen::contact::{
    BodyState, Contact, ContactForce, ContactLaws, ShoeGeometry, ground, soft_ground::SoftGround,
    sprocket, sprocket::ToothProfile, wheel,
};
use trackgen::multibody::BodyLoad;
use trackgen::terrain::Terrain;

/// The ground's forces on `links` under `laws`, added to `loads`; every
/// contact passed to `each` with its link.
pub fn ground_forces(
    (laws, terrain): (&ContactLaws, &Terrain),
    links: &[BodyState],
    shoe: &ShoeGeometry,
    loads: &mut [BodyLoad],
    mut each: impl FnMut(usize, &ContactForce),
) {
    let mut contacts: Vec<Contact> = Vec::new();
    ground::detect(terrain, links, shoe, &mut contacts);
    for contact in &contacts {
        let force = laws.respond(contact);
        force.apply(contact, &mut loads[contact.link], None);
        each(contact.link, &force);
    }
}

/// A wheel's (its state, rim radius) forces on `links` into `loads` and
/// the reactions into `wheel_load`.
pub fn rim_forces(
    laws: &ContactLaws,
    (wheel, radius): (&BodyState, f64),
    links: &[BodyState],
    shoe: &ShoeGeometry,
    (loads, wheel_load): (&mut [BodyLoad], &mut BodyLoad),
    mut each: impl FnMut(usize, &ContactForce),
) {
    let mut contacts: Vec<Contact> = Vec::new();
    wheel::detect((wheel, 1, radius), links, shoe, &mut contacts);
    for contact in &contacts {
        let force = laws.respond(contact);
        let other = (&mut *wheel_load, wheel.position);
        force.apply(contact, &mut loads[contact.link], Some(other));
        each(contact.link, &force);
    }
}

/// The sprocket's (its state, tooth profile) forces on `links` into
/// `loads` and the reactions into `sprocket_load`.
pub fn tooth_forces(
    (laws, profile): (&ContactLaws, &ToothProfile),
    sprocket_state: &BodyState,
    links: &[BodyState],
    shoe: &ShoeGeometry,
    (loads, sprocket_load): (&mut [BodyLoad], &mut BodyLoad),
    mut each: impl FnMut(usize, &ContactForce),
) {
    let mut contacts: Vec<Contact> = Vec::new();
    sprocket::detect((sprocket_state, 1), profile, links, shoe, &mut contacts);
    for contact in &contacts {
        let force = laws.respond(contact);
        let other = (&mut *sprocket_load, sprocket_state.position);
        force.apply(contact, &mut loads[contact.link], Some(other));
        each(contact.link, &force);
    }
}

/// The soil's forces on `links` (its undisturbed surface `terrain`), at
/// the ground points' shear displacements `shear`, into `loads`; every
/// point's `j̇` into `rate` (zero off the soil).
pub fn soil_forces(
    (soil, terrain): (&SoftGround, &Terrain),
    links: &[BodyState],
    shoe: &ShoeGeometry,
    loads: &mut [BodyLoad],
    (shear, rate): (&[f64], &mut [f64]),
    mut each: impl FnMut(usize, &ContactForce),
) {
    let points = shoe.ground_points.len();
    let mut contacts: Vec<Contact> = Vec::new();
    ground::detect(terrain, links, shoe, &mut contacts);
    rate.fill(0.0);
    for contact in &contacts {
        let slot = contact.link * points + contact.feature;
        let (force, slip) = soil.respond(contact, points, shear[slot]);
        rate[slot] = slip;
        if let Some(force) = force {
            force.apply(contact, &mut loads[contact.link], None);
            each(contact.link, &force);
        }
    }
}

/// A terrain with its laws, as the contact tests build it.
#[derive(Debug, Clone, PartialEq)]
pub struct GroundContact {
    /// The profile.
    pub terrain: Terrain,
    /// Normal law per contact point.
    pub normal: trackgen::laws::NormalLaw,
    /// Friction per contact point.
    pub friction: trackgen::laws::Friction,
}

impl GroundContact {
    /// [`ground_forces`] under these laws.
    pub fn apply(
        &self,
        links: &[BodyState],
        shoe: &ShoeGeometry,
        loads: &mut [BodyLoad],
        each: impl FnMut(usize, &ContactForce),
    ) {
        let laws = ContactLaws {
            normal: self.normal,
            friction: self.friction,
        };
        ground_forces((&laws, &self.terrain), links, shoe, loads, each);
    }
}

/// Rim laws, as the contact tests build them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelContact {
    /// Normal law.
    pub normal: trackgen::laws::NormalLaw,
    /// Friction.
    pub friction: trackgen::laws::Friction,
}

impl WheelContact {
    /// [`rim_forces`] under these laws.
    pub fn apply(
        &self,
        wheel: (&BodyState, f64),
        links: &[BodyState],
        shoe: &ShoeGeometry,
        loads: &mut [BodyLoad],
        wheel_load: &mut BodyLoad,
        each: impl FnMut(usize, &ContactForce),
    ) {
        let laws = ContactLaws {
            normal: self.normal,
            friction: self.friction,
        };
        rim_forces(&laws, wheel, links, shoe, (loads, wheel_load), each);
    }
}

/// Teeth with their laws, as the contact tests build them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SprocketContact {
    /// The teeth.
    pub profile: ToothProfile,
    /// Normal law.
    pub normal: trackgen::laws::NormalLaw,
    /// Friction.
    pub friction: trackgen::laws::Friction,
}

impl SprocketContact {
    /// [`tooth_forces`] under these laws.
    pub fn apply(
        &self,
        sprocket_state: &BodyState,
        links: &[BodyState],
        shoe: &ShoeGeometry,
        loads: &mut [BodyLoad],
        sprocket_load: &mut BodyLoad,
        each: impl FnMut(usize, &ContactForce),
    ) {
        let laws = ContactLaws {
            normal: self.normal,
            friction: self.friction,
        };
        let pair = (&laws, &self.profile);
        tooth_forces(
            pair,
            sprocket_state,
            links,
            shoe,
            (loads, sprocket_load),
            each,
        );
    }
}
