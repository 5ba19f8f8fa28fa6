//! The steering estimate's inputs from the planar M113 at rest
//! (`trackgen steer`): the ground's loads carry its weight, centred under
//! its centre of gravity as the bodies' masses and places put it, along a
//! run as long as the published ground contact length.

use trackgen::analysis::{EquilibriumOptions, equilibrium};
use trackgen::multibody::RecursiveModel;
use trackgen::nalgebra::Vector2;
use trackgen::steering::TrackLoad;
use trackgen::terrain::Terrain;
use trackgen::vehicle::{Vehicle, VehicleDynamics};
use trackgen::vehicles::m113::{self, M113, M113Chassis, M113Track};

type System = <M113 as Vehicle>::System;

use crate::support::vehicle::m113_weight;

/// The M113 at rest on flat ground and the ground's loads there.
fn loads_at_rest() -> (Vec<(Vector2<f64>, f64)>, f64) {
    let mut system =
        M113::system(Terrain::Flat { height: 0.0 }, M113::speed_drive(|_| 0.0)).unwrap();
    let rest = equilibrium(&mut system, &EquilibriumOptions::default()).unwrap();
    let loads = system.ground_loads(rest.t, rest.state.as_slice()).unwrap();
    // The centre of gravity from every body's mass and centroid.
    let (qt, qc) = system.coordinates(rest.t, rest.state.as_slice()).unwrap();
    let (track, chassis) = (M113Track.description(), M113Chassis.description());
    let mut links = vec![Vector2::zeros(); track.bodies.len()];
    let mut parts = vec![Vector2::zeros(); chassis.bodies.len()];
    System::track_positions(qt.as_slice(), &mut links);
    System::chassis_positions(qc.as_slice(), &mut parts);
    let bodies = track
        .bodies
        .iter()
        .zip(&links)
        .chain(chassis.bodies.iter().zip(&parts));
    let (mass, moment) = bodies.fold((0.0, 0.0), |(m, s), (b, p)| (m + b.mass, s + b.mass * p.x));
    (loads, moment / mass)
}

#[test]
fn the_loads_at_rest_carry_the_weight_under_the_centre_of_gravity() {
    // At rest on level ground only the weight and the ground's normal
    // loads act along the vertical and turn the vehicle: their sum is the
    // weight and their centre is under the centre of gravity, to the
    // equilibrium's accelerations left (1e-8 in their units: some 1e-4 N
    // and 1e-9 m here; bounds 1e-7 of the weight and 1 µm).
    let (loads, centre_of_gravity) = loads_at_rest();
    let total: f64 = loads.iter().map(|l| l.1).sum();
    let weight = m113_weight();
    assert!(
        (total - weight).abs() < 1e-7 * weight,
        "{total} N against {weight} N"
    );
    let centre = loads.iter().map(|l| l.0.x * l.1).sum::<f64>() / total;
    assert!(
        (centre - centre_of_gravity).abs() < 1e-6,
        "the loads' centre {centre} m, the centre of gravity {centre_of_gravity} m"
    );
}

#[test]
fn the_loaded_run_is_the_published_ground_contact_length() {
    // AFV Database, M113: ground contact length 105 in (2.667 m). The
    // loaded run reaches from the rearmost loaded ground point to the
    // foremost, each end half a cell further: resolved to about a shoe
    // pitch (0.154 m, whether the end shoe's point bears), the bound.
    let (loads, _) = loads_at_rest();
    let along: Vec<(f64, f64)> = loads.iter().map(|l| (l.0.x, l.1)).collect();
    let length = TrackLoad::from_points(0.5 * m113::GAUGE, &along).length();
    let published = 105.0 * 0.0254;
    assert!(
        (length - published).abs() < m113::SHOE_PITCH,
        "loaded {length} m against the published {published} m"
    );
}
