//! The figures printed after a run, from running summaries: no row is
//! kept for them.

use std::error::Error;
use std::path::Path;

use trackgen::ride::Line;
use trackgen::simulate::{EnergyBalance, RideSink, RunReport, Summary};

use crate::console::say;

/// Says a drawbar load of `pull` N (`along`: which way, in words), if
/// there is one: "a drawbar load of 20.0 kN pulling the hull back …".
pub fn say_drawbar(pull: f64, along: &str) {
    if pull != 0.0 {
        let way = if pull > 0.0 {
            "pulling the hull back"
        } else {
            "pushing the hull on"
        };
        say!(
            "a drawbar load of {:.1} kN {way}{along} from the start",
            pull.abs() / 1e3
        );
    }
}

/// Prints the run's figures; a warning line if the energy books are off by
/// more than [`EnergyBalance::bound_for_tolerance`] at `tolerance`.
pub fn print(summary: &Summary, report: &RunReport, wall: f64, tolerance: f64) {
    let get = |name: &str| summary.get(name);
    let max = |name: &str| get(name).map_or(f64::NAN, |s| s.max);
    let simulated = summary.time().map_or(0.0, |t| t.last - t.first);
    let books = summary.energy_balance();
    let (work, change, dissipated) = books.map_or((f64::NAN, f64::NAN, f64::NAN), |b| {
        (b.motor_work, b.energy_change, b.dissipated)
    });
    say!(
        "simulated {simulated:.2} s in {wall:.2} s of wall time: real-time factor {:.2}",
        simulated / wall
    );
    say!(
        "steps {} accepted, {} rejected; {} coordinate switches; max closure error {:.1e} m",
        report.stats.accepted,
        report.stats.rejected,
        report.switches,
        max("track.closure_error")
    );
    if let Some(line) = methods(report) {
        say!("{line}");
    }
    let residual = books.map_or(f64::NAN, |b| b.residual());
    // Books whose every term is under the joule they are printed to (a
    // short run from rest) have nothing to balance: their residual is
    // the integration's noise over the largest of three near-zeros.
    let largest = work.abs().max(change.abs()).max(dissipated.abs());
    if largest < NOTHING_MOVED {
        say!(
            "energy balance: motor work {work:.3} J, ΔE {change:.3} J, dissipated {dissipated:.3} J: \
             every term under {NOTHING_MOVED} J, nothing to check"
        );
    } else {
        say!(
            "energy balance: motor work {work:.0} J = ΔE {change:.0} J + dissipated {dissipated:.0} J  (residual {residual:.2e} of the largest term)"
        );
        if let Some(warning) = books.and_then(|b| books_warning(&b, tolerance)) {
            say!("{warning}");
        }
    }
    finish(summary);
}

/// Below this, J, no term of the energy books is checked.
const NOTHING_MOVED: f64 = 1.0;

/// The warning line for `books` off by more than
/// [`EnergyBalance::bound_for_tolerance`] at `tolerance` (a run's answers
/// are then no better than its books), naming a tolerance ten times
/// tighter to try; `None` where they close. Every run that prints its
/// books prints this after them, planar or in space.
pub fn books_warning(books: &EnergyBalance, tolerance: f64) -> Option<String> {
    books
        .check(EnergyBalance::bound_for_tolerance(tolerance))
        .err()
        .map(|off| format!("warning: {off}; try --tolerance {:.0e}", tolerance / 10.0))
}

/// The final speed and penetrations.
fn finish(summary: &Summary) {
    let get = |name: &str| summary.get(name);
    let last = |name: &str| get(name).map_or(f64::NAN, |s| s.last);
    let max = |name: &str| get(name).map_or(f64::NAN, |s| s.max);
    say!(
        "final speed {:.2} m/s; max penetration: ground {:.1} mm, wheels {:.1} mm, sprocket {:.1} mm",
        last("speed"),
        1e3 * max("ground_penetration"),
        1e3 * max("wheel_penetration"),
        1e3 * max("sprocket_penetration")
    );
}

/// With `--engine`: whether the engine, not the controller, set the speed
/// (its load reached 1 at some time) and its load at the end.
pub fn engine(summary: &Summary) {
    let Some(load) = summary.get("engine_load") else {
        return;
    };
    let set_by = if load.max >= 1.0 - 1e-9 {
        "the engine at full load set the speed for part of the run"
    } else {
        "the controller set the speed throughout"
    };
    say!(
        "engine: {set_by}; load at the end {:.2}, largest {:.2}",
        load.last,
        load.max
    );
}

/// What `--integrator auto` ran, from its stiffness checks: `integrator:
/// Bogacki-Shampine from 0.0 s, ROS34PW2 from 2.0 s (stiffest rate
/// 9.1e3 /s, 3.4 × what Bogacki-Shampine's accuracy step allows); 6500 of
/// 7400 steps implicit`. `None` for a fixed method.
fn methods(report: &RunReport) -> Option<String> {
    let checks = &report.checks;
    let first = checks.first()?;
    let name = |implicit: bool| {
        if implicit {
            "ROS34PW2"
        } else {
            "Bogacki-Shampine"
        }
    };
    let mut spans = vec![format!("{} from {:.1} s", name(first.implicit), first.t)];
    for pair in checks.windows(2) {
        if pair[1].implicit != pair[0].implicit {
            spans.push(format!(
                "{} from {:.1} s",
                name(pair[1].implicit),
                pair[1].t
            ));
        }
    }
    let stiffest = checks
        .iter()
        .max_by(|a, b| a.ratio.total_cmp(&b.ratio))
        .unwrap_or(first);
    Some(format!(
        "integrator (auto): {} (stiffest rate up to {:.1e} /s, {:.1} × what Bogacki-Shampine's accuracy step allows; switch above {:.1}); {} of {} steps implicit",
        spans.join(", "),
        stiffest.stiffest,
        stiffest.ratio,
        trackgen::integrate::auto::IMPLICIT_ABOVE,
        report.stats.implicit,
        report.stats.accepted
    ))
}

/// The ride at the seat: the figures the ride and half-round limits are
/// set on (6 W absorbed, 2.5 g), measured from the end of the speed ramp;
/// or why there are none.
pub fn ride(ride: Option<&RideSink>, output_every: f64) {
    let Some(ride) = ride else {
        say!(
            "ride at the seat: rows every {output_every} s are too far apart; \
             --output-every {} or less gives the ride figures",
            RideSink::MAX_INTERVAL
        );
        return;
    };
    let figures = ride.figures();
    if figures.samples == 0 {
        say!(
            "ride at the seat: the run ended before t = {:.1} s, where the measurement starts",
            ride.from()
        );
        return;
    }
    say!(
        "ride at the seat from t = {:.1} s: absorbed power {:.2} W (vertical), W_k RMS {:.3} m/s², \
         W_d RMS {:.3} m/s², peak {:.2} g (30 Hz low-pass)",
        ride.from(),
        figures.absorbed_power,
        figures.wk_rms,
        figures.wd_rms,
        figures.peak_g
    );
}

/// How many of the seat's lines are printed.
const LINES: usize = 5;
/// How far a line may be from a harmonic of the shoe passage, as a share
/// of its frequency, beyond a bin and a half: the speed's spread over the
/// measurement.
const SPEED_SPREAD: f64 = 0.005;
/// How far from a hull mode at rest, as a share of its frequency beyond
/// a bin and a half: a mode moves at speed.
const MODE_SPREAD: f64 = 0.05;

/// The seat's spectrum over the measured rows: the lines that carry the
/// most absorbed power, named when they are the shoe passage's harmonics
/// (`pitch`, m) or near one of `hull_modes` (Hz, name; from `--modes`),
/// printed; every bin written to `dir/seat_spectrum.csv`. Returns the
/// file written, if any.
pub fn seat_spectrum(
    ride: &RideSink,
    pitch: Option<f64>,
    hull_modes: &[(f64, String)],
    dir: &Path,
) -> Result<Option<String>, Box<dyn Error>> {
    let Some(spectrum) = ride.spectrum() else {
        if ride.figures().samples > 0 {
            say!(
                "seat spectrum: fewer than {} s measured, no spectrum",
                RideSink::SPECTRUM_SEGMENT
            );
        }
        return Ok(None);
    };
    let absorbed = spectrum.absorbed();
    let total: f64 = absorbed.iter().sum();
    let speed = ride.mean_speed().unwrap_or(f64::NAN);
    let pitch = pitch.unwrap_or(f64::NAN);
    let df = spectrum.df;
    // A line's bin and one each side hold a tone (the Hann window): a
    // line is matched within a bin and a half and its spread.
    let lines = spectrum.lines(&absorbed, LINES, 1);
    let near = |line: &Line, spread: f64| 1.5 * df + spread * line.frequency;
    say!(
        "seat spectrum ({} segments, bins {:.3} Hz apart) at {:.2} m/s, shoe passage v/p {:.2} Hz: \
         absorbed power {:.2} W; the lines that carry most:",
        spectrum.segments,
        df,
        speed,
        speed / pitch,
        total
    );
    for line in &lines {
        let name = line
            .name(
                speed,
                pitch,
                hull_modes,
                (near(line, SPEED_SPREAD), near(line, MODE_SPREAD)),
            )
            .unwrap_or_else(|| {
                // Where it stands against the passage tells a sub-harmonic
                // (a line at a third of it, say) from a resonance, over
                // runs at two speeds.
                let share = line.frequency * pitch / speed;
                if hull_modes.is_empty() {
                    format!("{share:.2} v/p: not a harmonic (--modes names the hull's modes)")
                } else {
                    format!("{share:.2} v/p: not a harmonic nor a hull mode at rest")
                }
            });
        say!(
            "  {:7.2} Hz  {:6.3} W ({:4.1} %)  {name}",
            line.frequency,
            line.carried,
            100.0 * line.carried / total
        );
    }
    let harmonics: f64 = absorbed
        .iter()
        .enumerate()
        .filter(|&(k, _)| {
            let line = Line {
                frequency: spectrum.frequency(k),
                carried: 0.0,
            };
            line.shoe_harmonic(speed, pitch, near(&line, SPEED_SPREAD))
                .is_some()
        })
        .map(|(_, w)| w)
        .sum();
    say!(
        "  the bins on the shoe passage's harmonics (v/2p, v/p to 12 v/p) carry {:.1} % of it",
        100.0 * harmonics / total
    );
    let mut csv = csv::Writer::from_path(dir.join("seat_spectrum.csv"))?;
    csv.write_record(["frequency_hz", "seat_az_psd", "absorbed_power_w"])?;
    for (k, (psd, w)) in spectrum.psd.iter().zip(&absorbed).enumerate() {
        csv.write_record([
            format!("{}", spectrum.frequency(k)),
            format!("{psd}"),
            format!("{w}"),
        ])?;
    }
    csv.flush()?;
    Ok(Some("seat_spectrum.csv".to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Books that close within their bound at a tolerance give no
    /// warning; books past it (and books that are NaN) give one naming a
    /// tenfold tighter tolerance. The bound is the runtime's own
    /// (`EnergyBalance::bound_for_tolerance`), 10 % either side of it.
    #[test]
    fn the_books_warn_past_their_bound_only() {
        let books = |residual: f64| EnergyBalance {
            motor_work: 1000.0,
            energy_change: 400.0,
            dissipated: 600.0 - 1000.0 * residual,
        };
        let bound = EnergyBalance::bound_for_tolerance(1e-3);
        assert_eq!(books_warning(&books(0.9 * bound), 1e-3), None);
        assert_eq!(books_warning(&books(-0.9 * bound), 1e-3), None);
        for residual in [1.1 * bound, -1.1 * bound] {
            let warning = books_warning(&books(residual), 1e-3).expect("a warning");
            assert!(warning.starts_with("warning: "), "{warning}");
            assert!(warning.ends_with("try --tolerance 1e-4"), "{warning}");
        }
        let nan = EnergyBalance {
            dissipated: f64::NAN,
            ..books(0.0)
        };
        assert!(books_warning(&nan, 1e-3).is_some());
    }
}
