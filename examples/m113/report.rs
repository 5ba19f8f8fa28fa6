//! The figures printed after a run, from running summaries: no row is
//! kept for them.

use trackgen::simulate::{EnergyBalance, RunReport, Summary};

/// Prints the run's figures; a warning line if the energy books are off by
/// more than [`EnergyBalance::bound_for_tolerance`] at `tolerance`.
pub fn print(summary: &Summary, report: &RunReport, wall: f64, tolerance: f64) {
    let get = |name: &str| summary.get(name);
    let last = |name: &str| get(name).map_or(f64::NAN, |s| s.last);
    let max = |name: &str| get(name).map_or(f64::NAN, |s| s.max);
    let simulated = summary.time().map_or(0.0, |t| t.last - t.first);
    let books = summary.energy_balance();
    let (work, change, dissipated) = books.map_or((f64::NAN, f64::NAN, f64::NAN), |b| {
        (b.motor_work, b.energy_change, b.dissipated)
    });
    super::say!(
        "simulated {simulated:.2} s in {wall:.2} s of wall time: real-time factor {:.2}",
        simulated / wall
    );
    super::say!(
        "steps {} accepted, {} rejected; {} coordinate switches; max closure error {:.1e} m",
        report.stats.accepted,
        report.stats.rejected,
        report.switches,
        max("track.closure_error")
    );
    let residual = books.map_or(f64::NAN, |b| b.residual());
    super::say!(
        "energy balance: motor work {work:.0} J = ΔE {change:.0} J + dissipated {dissipated:.0} J  (residual {residual:.2e} of the largest term)"
    );
    if let Some(Err(off)) = books.map(|b| b.check(EnergyBalance::bound_for_tolerance(tolerance))) {
        super::say!("warning: {off}; try --tolerance {:.0e}", tolerance / 10.0);
    }
    super::say!(
        "final speed {:.2} m/s; max penetration: ground {:.1} mm, wheels {:.1} mm, sprocket {:.1} mm",
        last("speed"),
        1e3 * max("ground_penetration"),
        1e3 * max("wheel_penetration"),
        1e3 * max("sprocket_penetration")
    );
}
