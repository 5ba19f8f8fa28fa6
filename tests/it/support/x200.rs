//! The M113A3's steer drive worked out by hand from the published
//! figures, apart from the runtime's route (`SteerDrive::of`): the tests
//! of the pivot in neutral and of the steer unit geared to the engine
//! hold the runtime to it.

use trackgen::vehicles::m113;

/// The steer drive's ratio `k` (the sprockets' speed difference at full
/// steer over the engine's speed): the mean over the X200-4's four ranges
/// of `q_r / (N_r N_f)`, `q_r = 2 (ρ_r − 1)/(ρ_r + 1)` from each range's
/// minimum steer ratio `ρ_r` (the outer sprocket's speed over the
/// inner's), `N_r` the range's reduction and `N_f` the final drive's.
pub fn steer_drive_ratio() -> f64 {
    m113::STEER_RATIOS
        .iter()
        .zip(m113::RANGES)
        .map(|(rho, n)| 2.0 * (rho - 1.0) / (rho + 1.0) / (n * m113::FINAL_DRIVE))
        .sum::<f64>()
        / m113::RANGES.len() as f64
}
