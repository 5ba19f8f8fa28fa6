//! One recipe builds every vehicle: the tests' helper, `M113::system` and
//! `trackgen::vehicle::build` give the same vehicle, bit for bit, and code
//! written once for any `V: Vehicle` builds and runs both declared
//! vehicles.
//!
//! Tolerances: none. The same configuration through the same recipe must
//! give the same numbers exactly (a second recipe that, say, skipped the
//! tensioner's adjustment would differ in the derivative at the first
//! bit: the tensioner's preload is in the idler arm's torque).

use crate::support;

use trackgen::closure::ClosureMethod;
use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::simulate::{Output, simulate};
use trackgen::system::Simulated;
use trackgen::terrain::Terrain;
use trackgen::vehicle::{Vehicle, VehicleDynamics, build};
use trackgen::vehicles::{m113::M113, m113::M113Chassis, marder::Marder};

use support::vehicle::m113_with;

const FLAT: Terrain = Terrain::Flat { height: 0.0 };

fn bits(values: &[f64]) -> Vec<u64> {
    values.iter().map(|v| v.to_bits()).collect()
}

/// The state and its derivative at the start.
fn start<S: Simulated>(system: &mut S) -> (Vec<f64>, Vec<f64>) {
    let y = system.initial_state();
    let mut dy = vec![0.0; y.len()];
    system
        .derivative(0.0, y.as_slice(), &mut dy)
        .expect("an evaluation");
    (y.as_slice().to_vec(), dy)
}

#[test]
fn the_test_helper_builds_the_m113_that_ships() {
    let drive = || M113::speed_drive(|t| 2.0 * t.min(1.0));
    let mut shipped = M113::system(FLAT, drive()).expect("the M113 builds");
    let mut helper = m113_with(FLAT, drive(), ClosureMethod::Declared);
    let mut built = build::<M113>(M113::declared_config(FLAT, drive())).expect("the M113 builds");
    let (y, dy) = start(&mut shipped);
    for (name, other) in [("helper", start(&mut helper)), ("build", start(&mut built))] {
        assert_eq!(bits(&y), bits(&other.0), "{name}: start state");
        assert_eq!(bits(&dy), bits(&other.1), "{name}: its derivative");
    }
    // The tensioner is set: its spring's preload is the declared one plus
    // k φ₀ for the angle the assembly set the arm to (not zero for the
    // M113's track), and the other arms are as declared.
    let declared = M113::declared_config(FLAT, drive()).arms;
    let running = &shipped.config().arms;
    for (d, r) in declared.iter().zip(running) {
        assert_eq!(d.body, r.body);
        assert_eq!(d.spring.stiffness, r.spring.stiffness);
        if r.body == M113Chassis::IDLER_ARM {
            assert_ne!(
                d.spring.preload, r.spring.preload,
                "the tensioner is adjusted"
            );
        } else {
            assert_eq!(d.spring.preload, r.spring.preload);
        }
    }
}

/// What generic code over `V: Vehicle` can do with any declared vehicle:
/// build it, read its coordinate counts and parts, run it.
fn runs<V: Vehicle>() -> f64 {
    let mut system = V::system(FLAT, V::speed_drive(|t| t.min(1.0))).expect("it builds");
    let n = system.dimension();
    // Partitioned track: n independent coordinates and rates; chassis
    // coordinates and rates; the drive's integral, the motor's work, the
    // dissipation and the engine's work; the ground's stiction deflection
    // at every ground point.
    let points = V::geometry().shoe.ground_points.len();
    assert_eq!(
        n,
        2 * (V::TRACK_DOF - 2) + 2 * V::CHASSIS_DOF + 4 + points * (V::TRACK_DOF - 2),
        "{}",
        V::NAME
    );
    assert_eq!(V::System::track_dof(), V::TRACK_DOF);
    assert!(V::System::parts().len() >= 3, "{}: parts", V::NAME);
    let r = system.sprocket_pitch_radius();
    let geometry = V::geometry();
    let pitch = V::System::track_description().pitch().expect("one pitch");
    let want = pitch / (2.0 * (std::f64::consts::PI / geometry.sprocket.teeth as f64).sin());
    assert_eq!(r, want, "{}: pitch radius", V::NAME);
    let results = simulate(
        &mut system,
        Integrator::Bs23 {
            rtol: 1e-3,
            atol: 1e-3,
            max_step: 0.01,
        },
        0.0,
        0.2,
        Output::Every(0.05),
    )
    .expect("it runs");
    *results.column("x").expect("x").last().expect("rows")
}

#[test]
fn generic_code_builds_and_runs_every_declared_vehicle() {
    for (name, x) in [("M113", runs::<M113>()), ("Marder", runs::<Marder>())] {
        assert!(x.is_finite(), "{name}: x = {x}");
    }
}
