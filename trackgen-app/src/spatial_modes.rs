//! The spatial vehicle's modes at rest (`modes --spatial`): settled on
//! level ground with both sprockets held by their speed drives, then
//! linearised (`trackgen::analysis::spatial_modes`), each mode named by
//! the hull's motion holding most of its kinetic energy.

use std::path::Path;

use trackgen::analysis::{settle, spatial_mode_of, spatial_modes};
use trackgen::spatial_vehicle::{
    HULL_MOTIONS, SideDrives, SpatialSimulated, SpatialVehicleSystem, on_course,
};
use trackgen::terrain::Terrain;

use crate::console::say;
use crate::offered::SpatialModes;

/// How long the vehicle settles before it is linearised, s: its hull's
/// bounce and pitch (above 1 Hz, at damping ratios of 0.15 or more) have
/// decayed fifty-fold by then. A slower mode (the Marder's sway, 0.2 Hz)
/// has not; setting the rates to zero takes its motion out, not its
/// displacement.
pub(crate) const SETTLE: f64 = 4.0;
/// The settling run's tolerance: tight, so that the rest is one.
const TOLERANCE: f64 = 1e-6;
/// The highest natural frequency kept, Hz: the hull's and the running
/// gear's modes, not the contacts' and the links'.
pub(crate) const UP_TO: f64 = 30.0;
/// The least share of a mode's kinetic energy that makes it the hull's
/// mode of a motion in the summary.
const SHARE: f64 = 0.1;

/// `V`'s spatial modes at rest up to [`UP_TO`] Hz, and the residual
/// acceleration of its rest; an error in words.
pub(crate) fn modes_at_rest<V: SpatialVehicleSystem>() -> Result<SpatialModes, String> {
    let flat = Terrain::Flat { height: 0.0 };
    let (mut system, start, _) = on_course::<V>(V::declared_laws(), &flat, 0.0)
        .map_err(|e| format!("the spatial vehicle on level ground: {e}"))?;
    system
        .set_drives(SideDrives {
            right: V::speed_drive(|_| 0.0),
            left: V::speed_drive(|_| 0.0),
        })
        .map_err(|e| format!("holding its sprockets: {e}"))?;
    let rest =
        settle(&mut system, &start, SETTLE, TOLERANCE).map_err(|e| format!("settling it: {e}"))?;
    let modes = spatial_modes(&mut system, rest.t, &rest.y, UP_TO)
        .map_err(|e| format!("its modes: {e}"))?;
    Ok((rest.residual, modes))
}

/// Prints the hull's mode of each motion and writes every mode to
/// `dir/modes-spatial.csv`; the file's name.
pub(crate) fn report(
    (residual, modes): &SpatialModes,
    dir: &Path,
) -> Result<String, Box<dyn std::error::Error>> {
    say!(
        "in 3-D, settled {SETTLE:.0} s (accelerations left {residual:.1e}), {} modes up to {UP_TO:.0} Hz; the hull's:",
        modes.len()
    );
    for motion in HULL_MOTIONS {
        // A motion no oscillating mode gives a tenth of its energy has
        // no mode of its own here (sway, held by the shoes' stiction).
        match spatial_mode_of(modes, motion).filter(|m| m.share_of(motion) >= SHARE) {
            Some(m) => say!(
                "  {motion:<12} {:7.3} Hz  damping {:.3}  ({:.0} % of the mode's kinetic energy)",
                m.frequency,
                m.damping_ratio,
                100.0 * m.share_of(motion)
            ),
            None => say!(
                "  {motion:<12} no oscillating mode up to {UP_TO:.0} Hz holds a tenth of its energy"
            ),
        }
    }
    let name = "modes-spatial.csv";
    let mut csv = csv::Writer::from_path(dir.join(name))?;
    let mut header = vec!["frequency_hz", "damped_hz", "damping_ratio"];
    header.extend(HULL_MOTIONS);
    csv.write_record(&header)?;
    for m in modes {
        let mut row = vec![
            m.frequency.to_string(),
            m.damped_frequency.to_string(),
            m.damping_ratio.to_string(),
        ];
        row.extend(m.hull.iter().map(f64::to_string));
        csv.write_record(&row)?;
    }
    csv.flush()?;
    Ok(name.to_string())
}
