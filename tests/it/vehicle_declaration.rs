//! The declaration is the whole vehicle: what `model!` generates from the
//! M113's running keys (shoe, profile, contact, drive), and the run-time
//! overrides of `VehicleConfig`, each a number that could fail.
//!
//! Tolerances, and why:
//! - **Declared = Chrono's M113 figures** (`M113_TrackShoeSinglePin`,
//!   `M113_SprocketSinglePin`; the shoe, sprocket and track width written
//!   out here again): exact; any
//!   difference is a transcription error.
//! - **Scaled profile** (`ToothProfile::scaled(10, 0.154)` against the
//!   M113's 0.2605, 0.3 and 0.089 m): 2e-4 m. Its proportions are rounded
//!   to two figures (0.073, 0.33 and 0.48), which at the M113's pitch
//!   moves each radius by at most 0.005 × 0.154 / 2 ≈ 4e-4 m; measured
//!   8e-5 m.
//! - **Arms overridden with the compiled rates**: bit-identical results
//!   (the same numbers through the same operations).
//! - **Arms overridden with other rates**: the energy books close to 1e-5
//!   of the motor's work at Dormand-Prince 1e-6 (the bound of
//!   `tests/vehicle_m113.rs`, same run length and integrator): a run whose
//!   springs act with one rate and are booked with another would leave a
//!   residual of the spring energy difference, ~`½ Δk φ²` per arm, hundreds
//!   of joules against a work of ~1e4 J; measured 3.1e-6. The override
//!   must also act: the stiffer road-wheel arms deflect less, by more than
//!   10 % at the end (measured 0.30 rad as declared, 0.146 rad at twice
//!   the rates: about half, as a linear spring under the same load).

use crate::support;

use trackgen::contact::{
    ContactLaws, GroundFriction, GroundLaws, ShoeGeometry, sprocket::ToothProfile,
};
use trackgen::integrate::Integrator;
use trackgen::laws::{Friction, NormalLaw, ParameterError, Stiction};
use trackgen::nalgebra::Vector2;
use trackgen::simulate::{Output, Results, simulate};
use trackgen::terrain::Terrain;
use trackgen::vehicle::{BuildError, ConfigError, Drive, Vehicle, VehicleConfig};
use trackgen::vehicles::{m113, m113::M113, m113::M113Chassis};

use support::vehicle::Books;

const FLAT: Terrain = Terrain::Flat { height: 0.0 };

#[test]
fn m113_declaration_carries_the_m113_figures() {
    let v = |x, y| Vector2::new(x, y);
    let geometry = M113::geometry();
    assert_eq!(
        geometry.shoe,
        ShoeGeometry {
            ground_points: vec![v(-0.06, -0.03), v(0.06, -0.03)],
            inner_face: [v(-0.077, 0.03), v(0.077, 0.03)],
            pins: vec![v(0.0535, 0.0), v(-0.061, 0.0)],
            pin_radius: 0.015,
            width: Some(0.381),
        }
    );
    assert_eq!(
        geometry.sprocket,
        ToothProfile {
            teeth: 10,
            addendum: 0.2605,
            arc_centre_radius: 0.3,
            arc_radius: 0.089,
        }
    );
    let declared = M113::declared_config(FLAT, Drive::Free);
    let hunt_crossley = |stiffness, chi| NormalLaw::HuntCrossley {
        stiffness,
        exponent: 1.0,
        chi,
    };
    // The ground's friction is stiction (no `slip` declared), its
    // tangential spring fitted: the normal law's stiffness at the static
    // depth, critically damped on an 18.02 kg shoe on its two points.
    // (The mean shoe mass is summed over the 64 links: rounding, 1e-12.)
    let GroundLaws {
        normal,
        friction:
            GroundFriction::Stiction(Stiction {
                mu,
                stiffness,
                damping,
            }),
    } = declared.ground
    else {
        panic!("stiction on the ground: {:?}", declared.ground)
    };
    assert_eq!((normal, mu, stiffness), (hunt_crossley(2e6, 2.0), 0.8, 2e6));
    let want = (2.0 * 2e6 * 18.02f64).sqrt();
    assert!((damping - want).abs() < 1e-12 * want, "{damping} vs {want}");
    let rim = ContactLaws {
        normal: hunt_crossley(1e7, 0.5),
        friction: Friction { mu: 0.4, slip: 0.5 },
    };
    assert_eq!((declared.wheels, declared.sprocket), (rim, rim));
    assert_eq!(declared.tension_link, 1);
    let arms = &declared.arms;
    assert_eq!(arms.len(), 6, "five road-wheel arms and the tensioner");
    assert_eq!(arms[0].body, M113Chassis::RW1_ARM);
    assert_eq!(arms[5].body, M113Chassis::IDLER_ARM);
    assert_eq!(arms[0].spring.stiffness, m113::TORSION_STIFFNESS);
    assert_eq!((M113::TRACK_DOF, M113::CHASSIS_DOF), (66, 16));
    match M113::speed_drive(|_| 1.0) {
        Drive::Speed {
            proportional,
            integral,
            max_torque,
            ..
        } => assert_eq!((proportional, integral, max_torque), (3000.0, 6000.0, 2e4)),
        _ => panic!("a speed drive"),
    }
}

#[test]
fn scaled_profile_has_the_m113_proportions() {
    let scaled = ToothProfile::scaled(10, m113::SHOE_PITCH);
    let m113 = M113::geometry().sprocket;
    assert_eq!(scaled.teeth, 10);
    for (what, got, want) in [
        ("tip", scaled.addendum, m113.addendum),
        (
            "gap centre",
            scaled.arc_centre_radius,
            m113.arc_centre_radius,
        ),
        ("gap radius", scaled.arc_radius, m113.arc_radius),
    ] {
        assert!((got - want).abs() < 2e-4, "{what}: {got} vs {want}");
    }
    // Neighbouring gaps never meet, for any tooth count.
    for teeth in 3..60 {
        let p = ToothProfile::scaled(teeth, 0.1);
        let chord = 2.0 * p.arc_centre_radius * (std::f64::consts::PI / teeth as f64).sin();
        assert!(2.0 * p.arc_radius < chord, "{teeth} teeth");
        assert!(
            p.arc_centre_radius - p.arc_radius < p.addendum,
            "{teeth} teeth"
        );
    }
}

fn driven(config: VehicleConfig) -> Results {
    let mut system = M113::system_with(config).expect("the M113 assembles");
    simulate(
        &mut system,
        Integrator::Dopri5 {
            rtol: 1e-6,
            atol: 1e-6,
            max_step: 0.01,
        },
        0.0,
        1.5,
        Output::Every(0.01),
    )
    .expect("the run completes")
}

fn drive() -> Drive {
    M113::speed_drive(|t| 1.5 * ((t - 0.5) / 1.0).clamp(0.0, 1.0))
}

/// Mean deflection of the road-wheel arms from the chassis at the end, rad.
fn arm_deflection(results: &Results) -> f64 {
    let last = |c: &str| *results.column(c).expect(c).last().expect("samples");
    let chassis = last("chassis.theta_chassis");
    (1..=5)
        .map(|i| (last(&format!("chassis.theta_rw{i}_arm")) - chassis).abs())
        .sum::<f64>()
        / 5.0
}

#[test]
fn arm_rates_are_overridden_at_run_time() {
    let base = driven(M113::declared_config(FLAT, drive()));
    let mut same = M113::declared_config(FLAT, drive());
    same.arms = std::mem::take(&mut same.arms);
    let same = driven(same);
    assert_eq!(base.times(), same.times());
    assert_eq!(
        base.column("energy").expect("energy"),
        same.column("energy").expect("energy")
    );

    let mut stiff = M113::declared_config(FLAT, drive());
    for arm in stiff.arms.iter_mut().take(5) {
        arm.spring.stiffness *= 2.0;
        arm.spring.damping *= 2.0;
    }
    let stiff = driven(stiff);
    let books = Books::of(&stiff);
    assert!(
        books.relative() < 1e-5,
        "residual {} J of {} J",
        books.residual,
        books.work
    );
    let (soft, hard) = (arm_deflection(&base), arm_deflection(&stiff));
    assert!(
        hard < 0.9 * soft,
        "arms deflect {hard} rad at twice the rate, {soft} rad as declared"
    );
}

#[test]
fn bad_arm_overrides_are_config_errors() {
    let mut missing = M113::declared_config(FLAT, Drive::Free);
    missing.arms.pop();
    let error = M113::system_with(missing).err().expect("refused");
    assert!(
        matches!(&error, BuildError::Config(ConfigError::Arms { configured, declared })
            if configured.len() == 5 && declared.len() == 6),
        "{error}"
    );
    let mut negative = M113::declared_config(FLAT, Drive::Free);
    negative.arms[2].spring.damping = -1.0;
    let error = M113::system_with(negative).err().expect("refused");
    assert!(
        matches!(
            &error,
            BuildError::Config(ConfigError::Arm {
                body,
                source: ParameterError { name: "damping", value, .. },
            }) if *body == negative_body() && *value == -1.0
        ),
        "{error}"
    );
    assert!(error.to_string().contains("damping"), "{error}");
}

/// The body of the third declared arm.
fn negative_body() -> usize {
    M113::declared_config(FLAT, Drive::Free).arms[2].body
}
