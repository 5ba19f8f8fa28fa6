//! A track that does not slip carries the hull at its own mean speed.
//!
//! With no slip a track advances one pitch per tooth, so on flat rigid
//! ground at a steady speed the hull's mean speed is the track's,
//! `N p ω / (2π)` (`trackgen::contact::sprocket::track_speed`, the
//! recorded `track_speed`): 1.6 % below `ω R` for 10 teeth, `R` the
//! pitch-circle radius. The shoes on the ground stick (friction with
//! stiction), so the true slip, `1 − v / v_t`, is small and not negative
//! while driving.
//!
//! Tolerances, and why: the mean over 20 s of steady driving (after 10 s
//! to reach the speed and settle) of the hull's speed over the track's
//! within `[0.995, 1.0]` (the bound: the sticking shoes creep by
//! their tangential springs' deflection only, and the traction on flat
//! ground, the rolling resistance of 2–5 % of the weight, asks for a slip
//! well under 0.5 %; a track that outran its shoes, as regularised
//! friction let it by 0.46 %, fails). Both vehicles, at 2 and 3 m/s,
//! Bogacki-Shampine 1e-4 (the mean speeds agree with Dormand-Prince 1e-6
//! to 1e-5). The speed drive aims for the track's mean speed too: the
//! mean track speed within 0.5 % of the command.

use trackgen::Vehicle;
use trackgen::contact::Terrain;
use trackgen::integrate::Integrator;
use trackgen::simulate::{Output, simulate};
use trackgen::vehicle::slip;
use trackgen::vehicles::m113::M113;
use trackgen::vehicles::marder::Marder;

/// The mean hull speed over the mean track speed over the last 20 s of a
/// 30 s run at `speed` (m/s) on flat ground, and the mean track speed.
fn ratio<V: Vehicle>(speed: f64) -> (f64, f64) {
    let drive = V::speed_drive(move |t| speed * ((t - 0.5) / 2.0).clamp(0.0, 1.0));
    let mut vehicle = V::system(Terrain::Flat { height: 0.0 }, drive).expect("it builds");
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
    for (name, speed, (r, track)) in [
        ("M113", 2.0, ratio::<M113>(2.0)),
        ("M113", 3.0, ratio::<M113>(3.0)),
        ("Marder", 2.0, ratio::<Marder>(2.0)),
        ("Marder", 3.0, ratio::<Marder>(3.0)),
    ] {
        eprintln!(
            "{name} at {speed} m/s: hull / track speed {r:.5} (slip {:.4}), track {track:.4} m/s",
            slip(r * track, track)
        );
        assert!(
            (0.995..=1.0).contains(&r),
            "{name} at {speed} m/s: the hull moves at {r:.5} of the track's mean speed"
        );
        assert!(
            (track / speed - 1.0).abs() < 5e-3,
            "{name} at {speed} m/s: the track's mean speed {track} m/s"
        );
    }
}
