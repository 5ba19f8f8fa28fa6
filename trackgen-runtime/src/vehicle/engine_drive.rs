//! The sprocket's drive through an engine whose speed is a state
//! ([`EngineDynamics`](super::EngineDynamics)): the driver's demand split
//! into what it asks of the engine and what it asks of the brakes, the
//! turbine turned by the sprocket through the range's reduction, and the
//! turbine's torque back at the sprocket.
//!
//! The driver (the speed controller, or a torque schedule) asks for a
//! torque at the sprocket (the controller's integral held where the
//! powertrain's full-load envelope caps it, as without the engine's
//! inertia). Pushing the way the driver asks, it is asked of the turbine,
//! `T* = |τ_d| / (f n)` (`n` the range's
//! reduction with the final drive's, `f` the stages' efficiencies times
//! the side's share); the governor brings the engine to the speed that
//! gives it ([`Driveline::engine_state`]), and the sprocket gets what the
//! turbine gives, `f n T_t` the way the range drives it. Against the way
//! the driver asks (or while the driver asks to stand) the demand is the
//! brakes', on the sprocket as it is, and nothing is asked of the engine.
//! The turbine turns at `ω_t = g n ω`, `ω` the sprocket's speed relative
//! to the chassis and `g` the way the range turns it (−1 forward: the
//! sprocket turns clockwise driving forward; +1 in reverse).

use super::config::cap_in_gear;
use super::{Drive, DriveSlopes, Engaged, EngineSide, Powertrain, TorqueCap};
use crate::integrate::SimulationError;

/// What the drive gives at one instant through an engine with its speed a
/// state: the sprocket's torque, the rates of the drive's own states, the
/// fuel and the engine's side, and their slopes over the drive's states
/// `(ω, s, ω_e)`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct EngineDrive {
    /// The torque on the sprocket, N m.
    pub torque: f64,
    /// The controller integral's rate, rad/s.
    pub integral_rate: f64,
    /// The engine's acceleration, rad/s².
    pub engine_rate: f64,
    /// The locked driveline's twist rate, rad/s.
    pub twist_rate: f64,
    /// The elastic energy of the twisted driveline, this side's share, J.
    pub twist_energy: f64,
    /// The governor's fuel, 0 to 1.
    pub fuel: f64,
    /// The engine's side, for the books and the record.
    pub side: EngineSide,
    /// First derivatives.
    pub slopes: DriveSlopes,
}

/// The sprocket's side of [`engine_drive`]: its speed relative to the
/// chassis (rad/s), its rolling radius (m), the powertrain's stall torque
/// (N m) and the gearbox's state (the engaged range of a scheduled
/// gearbox, and whether the driver asks reverse).
#[derive(Debug, Clone, Copy)]
pub(crate) struct AtSprocket {
    pub omega: f64,
    pub rolling_radius: f64,
    pub stall: f64,
    pub gearbox: (Option<Engaged>, bool),
    /// Whether the lock-up clutch is engaged (kept by the run).
    pub locked: bool,
}

/// The drive `drive` at time `t` with the sprocket `at` its state, the
/// controller's integral at `integral` (rad), the engine at
/// `engine_speed` (rad/s) and the locked driveline twisted by `twist` (rad
/// at the turbine), through `powertrain`, a converter driveline whose
/// [`dynamics`](super::Driveline::dynamics) are declared, its engine's
/// shaft also loaded by `accessory` N m (a steer unit's pump; its slopes
/// are not in the drive's).
#[inline]
pub(crate) fn engine_drive(
    powertrain: &Powertrain,
    drive: &Drive,
    t: f64,
    at: AtSprocket,
    integral: f64,
    (engine_speed, twist, accessory): (f64, f64, f64),
) -> Result<EngineDrive, SimulationError> {
    let Powertrain::Converter(driveline) = powertrain else {
        unreachable!("engine_drive is called for a converter driveline")
    };
    let AtSprocket {
        omega,
        rolling_radius,
        stall,
        gearbox,
        locked,
    } = at;
    let (cap, own) = cap_in_gear(powertrain, omega, stall, gearbox);
    // The controller's integral is held where the powertrain's envelope
    // caps its torque (no wind-up), as without the engine's inertia; what
    // it asks of the engine is its torque within its own limit alone: at
    // full throttle the governor opens the fuel fully, rather than
    // following the envelope's cap as the sprocket's speed ripples.
    let (_, integral_rate, capped_slopes, _) =
        drive.checked_law(t, omega, rolling_radius, integral, cap)?;
    let (demand, _, demand_slopes, direction) =
        drive.checked_law(t, omega, rolling_radius, integral, TorqueCap::NONE)?;
    // The range the gearbox is in: reverse where the driver asks it; the
    // scheduled one (a shift engages it at once); shifted ideally, the
    // cap's (the envelope's best; beyond every range's reach, the highest).
    let range = match (gearbox, driveline.reverse_range()) {
        ((_, true), Some(reverse)) => reverse,
        ((Some(engaged), _), _) => engaged.range,
        _ => own
            .and_then(|c| c.gear)
            .unwrap_or(driveline.ranges.len() - 1),
    };
    let way = if direction > 0.0 { 1.0 } else { -1.0 };
    let n = driveline.reduction(range);
    let f = driveline.fraction();
    let wt = way * n * omega;
    let driving = direction != 0.0 && demand * way > 0.0;
    let (asked, brake) = if driving {
        (demand.abs() / (f * n), 0.0)
    } else {
        (0.0, demand)
    };
    let state = driveline
        .loaded_engine_state(locked, engine_speed, wt, twist, asked, accessory)
        .unwrap_or_else(|| unreachable!("engine_drive is called for a driveline with dynamics"));
    let torque = way * f * n * state.turbine_torque + brake;
    // Slopes over (ω, s, ω_e, z): the demand's through what it asks of
    // the engine or the brakes, the turbine's through ω_t = g n ω.
    let [d_omega, d_integral, _, _] = demand_slopes.torque;
    let (asked_by, brake_by) = if driving {
        let k = way / (f * n);
        ([k * d_omega, k * d_integral], [0.0, 0.0])
    } else {
        ([0.0, 0.0], [d_omega, d_integral])
    };
    let [tt_we, tt_wt, tt_z] = state.turbine_slopes;
    let [e_we, e_wt, e_z, e_asked] = state.rate_slopes;
    let [z_we, z_wt, z_z] = state.twist_slopes;
    let to_turbine = way * n;
    let slopes = DriveSlopes {
        torque: [
            f * n * n * tt_wt + brake_by[0],
            brake_by[1],
            way * f * n * tt_we,
            way * f * n * tt_z,
        ],
        rate: capped_slopes.rate,
        engine: [
            e_wt * to_turbine + e_asked * asked_by[0],
            e_asked * asked_by[1],
            e_we,
            e_z,
        ],
        twist: [z_wt * to_turbine, 0.0, z_we, z_z],
    };
    let share = driveline.share;
    let side = EngineSide {
        gear: Some(range),
        engine_speed,
        engine_torque: state.engine_torque,
        speed_ratio: state.speed_ratio,
        torque_ratio: state.torque_ratio,
        locked: Some(state.locked),
        engine_power: share * state.engine_torque * engine_speed,
        turbine_power: share * state.turbine_torque * wt,
    };
    Ok(EngineDrive {
        torque,
        integral_rate,
        engine_rate: state.rate,
        twist_rate: state.twist_rate,
        twist_energy: share * state.twist_energy,
        fuel: state.fuel,
        side,
        slopes,
    })
}
