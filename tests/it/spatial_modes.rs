//! The spatial vehicle's modes at rest (`analysis::spatial_modes`)
//! against the planar model's: the `Twin`, its left side its right's
//! mirror and its hull twice a side's chassis (2400 kg against 1200, a
//! pitch inertia of 3800 kg m² against 1900), bounces and pitches as one
//! of its sides does. Its planar side's modes are found at the
//! equilibrium Newton's method finds (`analysis::equilibrium`) with the
//! exact Jacobian where the vehicle gives one; the spatial vehicle's at
//! the rest it settles to, by central differences over every state:
//! two routes to the same two frequencies. By symmetry the in-plane
//! modes do not couple to the out-of-plane ones (roll, sway, yaw), so
//! each hull motion's mode is the planar one's.

use trackgen::analysis::{
    EquilibriumOptions, equilibrium, mode_of, modes, settle, spatial_mode_of, spatial_modes,
};
use trackgen::spatial_vehicle::{SideDrives, SpatialSimulated, SpatialVehicleSystem};
use trackgen::terrain::Terrain;
use trackgen::terrain::field::HeightField;
use trackgen::vehicle::Vehicle;

use crate::support::twin::Twin;

/// How far the spatial frequencies may stand from the planar ones,
/// relative: 0.5 %. The settled state is not the planar equilibrium
/// (what is left of the settling, the largest acceleration of any tree
/// coordinate once the rates are zeroed, is printed), and the central
/// differences give six digits; the planar route's rest is Newton's, to
/// 1e-8 m/s². Measured: 0.02 % (bounce) and 0.05 % (pitch), and the
/// damping ratios within 0.003. Under the declared ground, whose
/// friction is regularised: stiction's rest depends on how the vehicle
/// got there, and its springs' stretch at the settled rest is not the
/// planar equilibrium's.
const AGREE: f64 = 0.005;

#[test]
fn the_mirrored_vehicles_bounce_and_pitch_are_its_planar_sides() {
    let flat = Terrain::Flat { height: 0.0 };
    let mut planar = Twin::system(flat.clone(), Twin::speed_drive(|_| 0.0)).expect("builds");
    let rest = equilibrium(&mut planar, &EquilibriumOptions::default()).expect("rests");
    let planar_modes = modes(&mut planar, rest.t, &rest.state).expect("planar modes");

    let mut spatial =
        Twin::spatial(Twin::declared_laws(), HeightField::level()).expect("the spatial vehicle");
    let start = spatial.assembled(&flat).expect("assembled");
    spatial
        .set_drives(SideDrives {
            right: Twin::speed_drive(|_| 0.0),
            left: Twin::speed_drive(|_| 0.0),
        })
        .expect("speed drives");
    let still = settle(&mut spatial, &start, 4.0, 1e-6).expect("settles");
    println!("settled: residual acceleration {:.2e}", still.residual);
    let found = spatial_modes(&mut spatial, still.t, &still.y, 30.0).expect("spatial modes");
    for m in found.iter().filter(|m| m.oscillates()).take(12) {
        let (what, share) = m.hull_motion();
        println!(
            "{:7.3} Hz  ζ {:.3}  {what} {:.2}",
            m.frequency, m.damping_ratio, share
        );
    }
    for (planar_name, spatial_name) in
        [("hull bounce", "hull bounce"), ("hull pitch", "hull pitch")]
    {
        let plane = mode_of(&planar_modes, planar_name).expect("a planar mode");
        let space = spatial_mode_of(&found, spatial_name).expect("a spatial mode");
        println!(
            "{spatial_name}: spatial {:.4} Hz (ζ {:.3}, share {:.2}), planar {:.4} Hz (ζ {:.3})",
            space.frequency,
            space.damping_ratio,
            space.share_of(spatial_name),
            plane.frequency,
            plane.damping_ratio
        );
        assert!(
            (space.frequency / plane.frequency - 1.0).abs() <= AGREE,
            "{spatial_name}: {} Hz against {} Hz",
            space.frequency,
            plane.frequency
        );
    }
    // The roll is the hull's own: no planar mode to compare, but one
    // oscillating mode holds it.
    assert!(spatial_mode_of(&found, "hull roll").is_some());
}
