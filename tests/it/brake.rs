//! The brake on the sprocket: parked on it, the M113 stays put on 10, 30
//! and 60 % grades; a brake too weak for the grade slips.
//!
//! The M113 is driven at 1 m/s up a ramp until its rearmost wheel is a
//! metre up it (as `grade_hold.rs` does), its speed controller brought to
//! 0 over 1 s, and its parking brake applied then (15 kN m, twice what the
//! 60 % grade asks of one sprocket: `m g sin α r` = 7.6 kN m at the
//! M113A3's weight; stiffness and damping from `Brake::parking`). From
//! the moment it stops (the first sample after the brake from which the
//! hull stays slower than 1 mm/s for a second) it is watched 10 s
//! (Bogacki-Shampine 1e-4); the run lasts 40 s after the brake, so that
//! the watch fits after the slowest stop. The stop itself rings: the hull surges on the shoes'
//! stiction at about 0.9 Hz, lightly damped (±10 mm at first on 10 %; at
//! the M113A3's combat weight its speed stays under 1 mm/s from 17.7,
//! 15.9 and 22.1 s after the brake on 10, 30 and 60 %), as it does when
//! the controller holds the sprocket; that is the stopping, not the brake.
//!
//! - **Holds**: the hull moves less than 1 mm along the slope in those
//!   10 s (the bound). The brake's elastic stage turns under the
//!   held torque by `τ / k` (at most 10 mrad, 2.5 mm of track) while the
//!   vehicle stops, before the watch starts; once stopped, the stage's
//!   deflection is a rotation and cannot creep. Measured: 0.049, 0.165
//!   and 0.070 mm on 10, 30 and 60 % (the ringing's tail).
//! - **Slips**: with the brake at a tenth of what the 60 % grade asks, the
//!   vehicle rolls back more than 1 m in the same 10 s (a brake that did
//!   not slip at its limit would hold).

use crate::support;

use support::vehicle::{along_slope, m113_weight};
use trackgen::contact::sprocket::track_speed;
use trackgen::integrate::Integrator;
use trackgen::simulate::{Output, simulate};
use trackgen::terrain::Terrain;
use trackgen::vehicle::{Brake, Vehicle};
use trackgen::vehicles::m113::{self, M113};

const RAMP_START: f64 = 3.0;
/// The stop: the rearmost wheel (2.2 m behind the centroid) a metre up
/// the ramp at 1 m/s; the controller at 0 a second later.
const STOP: f64 = 1.5 + RAMP_START + 2.2 + 1.0;

/// The M113's sprocket's rolling radius, m: `N p / (2π)`.
fn rolling_radius() -> f64 {
    track_speed(10, m113::SHOE_PITCH, 1.0)
}

/// Parked on `grade` with a brake of `torque` N m applied at STOP + 1 s:
/// how far the hull moved along the slope in the 10 s after it stopped
/// (`from_stop`) or after the brake, m, and whether it stopped.
fn parked(grade: f64, torque: f64, from_stop: bool) -> (f64, bool) {
    let target = |t: f64| {
        let up = ((t - 0.5) / 1.0).clamp(0.0, 1.0);
        let down = ((STOP + 1.0 - t) / 1.0).clamp(0.0, 1.0);
        up.min(down)
    };
    let terrain = Terrain::Ramp {
        height: 0.0,
        start: RAMP_START,
        slope: grade,
    };
    let mut config = M113::declared_config(terrain, M113::speed_drive(target));
    let radius = rolling_radius();
    let inertia = m113_weight() / 9.81 * radius * radius;
    config.brake = Some(Brake::parking(torque, inertia, STOP + 1.0));
    let mut system = M113::system_with(config).expect("it builds");
    let end = STOP + 1.0 + 40.0;
    let results = simulate(
        &mut system,
        Integrator::Bs23 {
            rtol: 1e-4,
            atol: 1e-4,
            max_step: 0.01,
        },
        0.0,
        end,
        Output::Every(0.01),
    )
    .expect("the run completes");
    let along = along_slope(&results, grade);
    let times = results.times();
    let speed = results.column("speed").unwrap();
    let braked = times.partition_point(|&t| t <= STOP + 1.0);
    // Stopped: slower than 1 mm/s for a whole second (100 samples).
    let stopped = (braked..times.len().saturating_sub(100))
        .find(|&k| speed[k..k + 100].iter().all(|v| v.abs() < 1e-3));
    let from = if from_stop {
        stopped.expect("it stops")
    } else {
        braked
    };
    if let Some(k) = stopped {
        eprintln!(
            "{:.0} % grade: stopped {:.2} s after the brake",
            grade * 100.0,
            times[k] - (STOP + 1.0)
        );
    }
    let watch = times.partition_point(|&t| t < times[from] + 10.0);
    assert!(watch < times.len(), "the run covers the 10 s watch");
    let moved = along[from..=watch]
        .iter()
        .map(|a| (a - along[from]).abs())
        .fold(0.0, f64::max);
    (moved, stopped.is_some())
}

#[test]
fn parked_on_its_brake_it_stays_put() {
    for grade in [0.1, 0.3, 0.6] {
        let (moved, stopped) = parked(grade, 15e3, true);
        assert!(stopped, "{grade}: it stops");
        eprintln!(
            "{:.0} % grade: the hull moved {:.4} mm in 10 s",
            grade * 100.0,
            moved * 1e3
        );
        assert!(
            moved < 1e-3,
            "{:.0} % grade: the parked hull moved {:.3} mm",
            grade * 100.0,
            moved * 1e3
        );
    }
}

#[test]
fn a_brake_too_weak_for_the_grade_slips() {
    let grade: f64 = 0.6;
    let asked = m113_weight() * grade.atan().sin() * rolling_radius();
    let (moved, _) = parked(grade, 0.1 * asked, false);
    assert!(
        moved > 1.0,
        "a brake of a tenth of {asked} N m: moved {moved} m"
    );
}
