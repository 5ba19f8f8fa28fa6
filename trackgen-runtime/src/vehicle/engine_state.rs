//! The engine's speed as a state of the run ([`Driveline::engine_state`]):
//! the engine's and the converter pump's inertia, a governor that sets
//! the fuel, the engine's drag at no fuel, the converter's torques at any
//! speed ratio, and a lock-up clutch that slips up to its capacity.
//!
//! The engine's shaft (crankshaft, flywheel and the converter's pump, of
//! inertia `J`) turns at `ω_e` under
//!
//! ```text
//! J ω̇_e = T_e(ω_e, u) − T_p(ω_e, ω_t) − T_c(ω_e, ω_t)
//! T_e   = u T_full(ω_e) + (1 − u) T_drag(ω_e),   0 ≤ u ≤ 1
//! ```
//!
//! the form of Project Chrono's `ChEngineShafts` (the fuel scales the
//! full-load map; the engine's losses apart), here with the losses as
//! the engine's torque motoring at no fuel, `T_drag ≤ 0`, so that full
//! fuel gives the declared full-load (net) torque. The turbine turns at
//! `ω_t`, the gearbox's input. Unlocked, the converter's pump absorbs
//! `T_p = (ω_e / K(SR))²` and its turbine gives `T_t = TR(SR) T_p`
//! (`SR = ω_t / ω_e`; Wong, *Theory of Ground Vehicles*, 4th ed., §3.4);
//! locked, the clutch carries the engine's torque, `T_c`, and the
//! converter none.
//!
//! **The governor** sets the fuel. Through the converter it brings the
//! engine's speed, with time constant `τ_g`, to the speed `ω*` at which
//! the turbine gives the torque the driver asks (`T_t(ω*, ω_t) = T*`):
//! `J ω̇_e = J (ω* − ω_e) / τ_g` while the fuel it needs is between none
//! and full, the engine's own torque at the bound beyond. Locked, it fuels
//! for the torque asked and holds the engine to the turbine's speed,
//! `T_e = T* + J (ω_t − ω_e) / τ_g`, the driveline's twist carrying it.
//! So a light demand is met at once, a full one as fast as the engine's
//! torque over what the pump absorbs spins the engine and the pump up; in
//! the limit of no inertia and an instant governor the engine runs at
//! `ω*`, the quasi-static model of [`Driveline::part_load`]. The governor
//! never lets the engine below its idle speed, the map's first.
//!
//! **The converter at any speed ratio.** A hydrodynamic converter carries
//! no torque without slip: the declared maps are followed up to `SR = 1 −
//! δ` and the torque falls linearly to none at `SR = 1` (δ =
//! [`COUPLING_BAND`]); beyond, the turbine drives the pump (overrun: the
//! maps read at `2 − SR` with the torque's sign turned and `TR = 1`, as
//! Chrono's `ChShaftsTorqueConverter` reflects them), so the torques are
//! continuous through the coupling. A turbine forced backwards is the
//! converter at stall.
//!
//! The gearbox of such an engine shifts by its schedule ([`Driveline::shift`];
//! where none is declared, [`Driveline::ideal_schedule`] with
//! [`IDEAL_DOWNSHIFT`] and [`IDEAL_SHIFT_TIME`]): an ideal gearbox's
//! choice of range at every instant would switch the turbine's speed back
//! and forth with the sprocket's ripple, and the engine with it. A shift
//! engages its new range at once, the converter taking up the turbine's
//! change of speed, with the lock-up released until it is done.
//!
//! **The lock-up clutch** engages in a range that locks once the turbine
//! turns fast enough that the full-load match reaches the clutch's speed
//! ratio ([`Driveline::locks`]) and the converter's own speed ratio is at
//! least it, and releases with a hysteresis or to shift
//! ([`Driveline::lockup_next`], at the end of a step as the gearbox
//! shifts). Engaged, it and the driveline behind it are an elastic
//! element with a Coulomb limit ([`EngineDynamics::lockup`](super::EngineDynamics::lockup)): the twist
//! `z` (rad at the turbine, a state) carries `T_c = k z + c ż` while that
//! is under the clutch's capacity, the capacity (slipping) beyond; released,
//! the twist relaxes through its damper and carries nothing. A rigid lock
//! would put the engine's inertia on the sprocket (some 128 kg m² through
//! the M113A3's second range, a third of what the half hull and track
//! weigh there), and the shoes' passage shakes the sprocket at 30–60 Hz:
//! the compliance is what lets the engine ride through it, as the
//! driveline's shafts do.

use super::converter::Driveline;
use super::shift::Engaged;
use super::tables::{engine_torque, lerp, solve_piece};

/// The converter's coupling band, δ: the speed ratios below 1 over which
/// its torque falls to none at `SR = 1` (no slip, no torque).
pub const COUPLING_BAND: f64 = 0.02;

/// The downshift fraction of the schedule an engine with its speed a
/// state shifts by where none is declared ([`Driveline::ideal_schedule`]'s
/// `down`): 0.8 (assumed: an automatic gearbox's usual hysteresis).
pub const IDEAL_DOWNSHIFT: f64 = 0.8;

/// That schedule's shift time, s: 0.5 (assumed: a clutch-to-clutch power
/// shift of a planetary range box hands over in some 0.3–0.8 s).
pub const IDEAL_SHIFT_TIME: f64 = 0.5;

/// How far below its engaging speed the turbine slows before a lock-up
/// clutch releases, as a fraction of that speed: 0.05 (assumed: a lock-up
/// schedule's hysteresis).
pub const LOCKUP_RELEASE: f64 = 0.2;

/// The engine's state law at one instant ([`Driveline::engine_state`]):
/// its fuel and torques, what the turbine gives, and the engine's
/// acceleration, with their first derivatives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EngineState {
    /// The fuel, 0 (none) to 1 (full load).
    pub fuel: f64,
    /// The engine's torque, N m.
    pub engine_torque: f64,
    /// What the engine's shaft gives the converter's pump, the lock-up
    /// clutch and an accessory, N m.
    pub load: f64,
    /// What the turbine (with the clutch) gives the gearbox, N m.
    pub turbine_torque: f64,
    /// `∂T_t/∂ω_e`, `∂T_t/∂ω_t` (N m s/rad), `∂T_t/∂z` (N m/rad).
    pub turbine_slopes: [f64; 3],
    /// The engine's acceleration, rad/s².
    pub rate: f64,
    /// `∂ω̇_e/∂ω_e`, `∂ω̇_e/∂ω_t` (1/s), `∂ω̇_e/∂z` (1/s²), `∂ω̇_e/∂T*`
    /// (1/(kg m²)).
    pub rate_slopes: [f64; 4],
    /// The locked driveline's twist rate, rad/s.
    pub twist_rate: f64,
    /// `∂ż/∂ω_e`, `∂ż/∂ω_t` (1), `∂ż/∂z` (1/s).
    pub twist_slopes: [f64; 3],
    /// The elastic energy in the twisted driveline, J (the whole
    /// engine's).
    pub twist_energy: f64,
    /// The power the clutch and the driveline's damper dissipate, W (the
    /// whole engine's).
    pub clutch_dissipation: f64,
    /// The converter's speed ratio (1 locked).
    pub speed_ratio: f64,
    /// The converter's torque ratio, turbine over pump (1 locked, or with
    /// no torque through it).
    pub torque_ratio: f64,
    /// Whether the lock-up clutch is engaged.
    pub locked: bool,
}

/// The converter's torques at `(ω_e, ω_t)` and their slopes: pump and
/// turbine, each `(value, ∂/∂ω_e, ∂/∂ω_t)`, and the torque ratio.
#[derive(Debug, Clone, Copy)]
struct Fluid {
    pump: [f64; 3],
    turbine: [f64; 3],
    torque_ratio: f64,
}

impl Fluid {
    /// No torque through the converter (locked up).
    const NONE: Fluid = Fluid {
        pump: [0.0; 3],
        turbine: [0.0; 3],
        torque_ratio: 1.0,
    };
}

impl Driveline {
    /// The full-load torque the running engine gives at `we` (rad/s) and
    /// its slope: the map's, with the first point's torque held below it
    /// (the idle governor keeps the engine running there).
    fn running_full_load(&self, we: f64) -> (f64, f64) {
        let first = self.engine[0];
        if we < first.0 {
            (first.1.max(0.0), 0.0)
        } else {
            engine_torque(&self.engine, we)
        }
    }

    /// The converter's torques at engine speed `we` and turbine speed `wt`
    /// (rad/s) at any speed ratio (the module docs).
    fn fluid(&self, we: f64, wt: f64) -> Fluid {
        if we <= 0.0 {
            let tr = lerp(&self.torque_ratio, 0.0).0;
            return Fluid {
                pump: [0.0; 3],
                turbine: [0.0; 3],
                torque_ratio: tr,
            };
        }
        let sr = wt / we;
        // σ: where the maps are read; its slopes with ω_e and ω_t.
        let (sigma, dsigma, sign) = if sr <= 0.0 {
            (0.0, [0.0, 0.0], 1.0)
        } else if sr <= 1.0 {
            (sr, [-sr / we, 1.0 / we], 1.0)
        } else if sr < 2.0 {
            (2.0 - sr, [sr / we, -1.0 / we], -1.0)
        } else {
            (0.0, [0.0, 0.0], -1.0)
        };
        let (k, dk) = lerp(&self.capacity, sigma);
        let q = (we / k) * (we / k);
        let dq_dsigma = -2.0 * q * dk / k;
        // The coupling band: no slip, no torque.
        let gap = 1.0 - sigma;
        let (phi, dphi) = if gap < COUPLING_BAND {
            (gap / COUPLING_BAND, -1.0 / COUPLING_BAND)
        } else {
            (1.0, 0.0)
        };
        let tp = sign * q * phi;
        let dtp_dsigma = sign * (dq_dsigma * phi + q * dphi);
        let dtp_dwe_at_sigma = 2.0 * tp / we;
        let pump = [
            tp,
            dtp_dwe_at_sigma + dtp_dsigma * dsigma[0],
            dtp_dsigma * dsigma[1],
        ];
        let (tr, dtr) = if sign > 0.0 {
            lerp(&self.torque_ratio, sigma)
        } else {
            // Overrun: a converter gives no torque ratio (TR = 1).
            (1.0, 0.0)
        };
        let turbine = [
            tr * pump[0],
            tr * pump[1] + dtr * dsigma[0] * pump[0],
            tr * pump[2] + dtr * dsigma[1] * pump[0],
        ];
        Fluid {
            pump,
            turbine,
            torque_ratio: tr,
        }
    }

    /// Whether the lock-up clutch of range `range` (0-based) is engaged
    /// after a step that ended with it `locked`, the engine at `we` and the
    /// turbine at `wt` (rad/s), the gearbox `shifting` or not: a clutch
    /// engages in a range that locks, not while shifting, once the turbine
    /// turns fast enough that the full-load match reaches the clutch's
    /// speed ratio ([`locks`](Self::locks)) and the converter's own speed
    /// ratio is at least it; it releases while shifting, in a range that
    /// does not lock, or once the turbine has slowed [`LOCKUP_RELEASE`]
    /// below where it would engage (the hysteresis: a clutch held at its
    /// threshold would chatter with the sprocket's ripple).
    pub fn lockup_next(
        &self,
        range: usize,
        locked: bool,
        we: f64,
        wt: f64,
        shifting: bool,
    ) -> bool {
        if shifting || !self.lockup_ranges.contains(&range) || wt <= 0.0 {
            return false;
        }
        if locked {
            self.locks(wt / (1.0 - LOCKUP_RELEASE))
        } else {
            we > 0.0 && wt >= self.lockup_speed_ratio * we && self.locks(wt)
        }
    }

    /// The gearbox and the lock-up clutch after an accepted step at time
    /// `t` (s), from `(engaged, locked)`, the gearbox's output (the
    /// sprocket, or a differential's box) turning at `omega` (rad/s), the
    /// engine at `engine_speed` (rad/s; `None` where its speed is no
    /// state: no lock-up is decided), the driver asking `reverse`: a
    /// scheduled gearbox shifted where its schedule says
    /// ([`Shift::next`](super::Shift::next), its input at the engaged
    /// range's reduction times `|ω|`; in reverse the forward ranges wait
    /// where they are), then the clutch engaged or released in the range
    /// now in use ([`lockup_next`](Self::lockup_next)). The one rule the
    /// planar sprocket's and the spatial box's runs follow.
    pub fn gearbox_next(
        &self,
        t: f64,
        (engaged, locked): (Option<Engaged>, bool),
        (omega, engine_speed): (f64, Option<f64>),
        reverse: bool,
    ) -> (Option<Engaged>, bool) {
        let mut engaged = engaged;
        if let (Some(now), Some(shift), false) = (engaged, self.shift.as_ref(), reverse)
            && let Some(next) = shift.next(now, self.reduction(now.range) * omega.abs(), t)
        {
            engaged = Some(next);
        }
        let Some(we) = engine_speed else {
            return (engaged, locked);
        };
        let range = match (reverse, self.reverse_range(), engaged) {
            (true, Some(r), _) => r,
            (_, _, Some(now)) => now.range,
            _ => return (engaged, locked),
        };
        let shifting = engaged.is_some_and(|e| e.from.is_some());
        let wt = self.reduction(range) * omega.abs();
        (engaged, self.lockup_next(range, locked, we, wt, shifting))
    }

    /// The speed the governor brings the engine to for a turbine at `wt`
    /// (rad/s) asked for `asked` (N m, the whole turbine's, ≥ 0), and its
    /// slopes with `wt` and `asked`: through the converter the speed at
    /// which the turbine gives it, `T_t(ω*, ω_t) = T*`; locked, the
    /// turbine's; never below idle.
    fn governed_speed(&self, locked: bool, wt: f64, asked: f64) -> (f64, [f64; 2]) {
        let idle = self.engine[0].0;
        if locked {
            return if wt > idle {
                (wt, [1.0, 0.0])
            } else {
                (idle, [0.0, 0.0])
            };
        }
        let low = wt.max(0.0);
        if asked <= 0.0 {
            return if low > idle {
                (low, [if wt > 0.0 { 1.0 } else { 0.0 }, 0.0])
            } else {
                (idle, [0.0, 0.0])
            };
        }
        // g(ω) = T* − T_t(ω, ω_t): T* at the low end (no slip, or no
        // engine speed), ≤ 0 where the engine reaches.
        let g = |we: f64| {
            let f = self.fluid(we, wt);
            (asked - f.turbine[0], -f.turbine[1])
        };
        let high = self.engine[self.engine.len() - 1].0;
        let (gb, _) = g(high);
        let speed = if low >= high || gb > 0.0 {
            high.max(low)
        } else {
            solve_piece(&g, (low, asked), (high, gb))
        };
        if speed <= idle {
            return (idle, [0.0, 0.0]);
        }
        let f = self.fluid(speed, wt);
        if speed >= high || f.turbine[1] <= 0.0 {
            return (speed, [0.0, 0.0]);
        }
        // The implicit function theorem on T_t(ω*, ω_t) = T*.
        (speed, [-f.turbine[2] / f.turbine[1], 1.0 / f.turbine[1]])
    }

    /// The engine's state law with the engine at `we` and the turbine at
    /// `wt` (rad/s), the lock-up clutch `locked` or not
    /// ([`lockup_next`](Self::lockup_next) decides it at a step's end), the
    /// locked driveline twisted by `twist` (rad at the turbine), the driver
    /// asking the turbine for `asked` (N m, the whole turbine's, ≥ 0): the
    /// fuel the governor sets, what the turbine gives, the engine's
    /// acceleration and the twist's rate, and their slopes. Needs this
    /// driveline's [`dynamics`](Driveline::dynamics) (`None` without).
    pub fn engine_state(
        &self,
        locked: bool,
        we: f64,
        wt: f64,
        twist: f64,
        asked: f64,
    ) -> Option<EngineState> {
        self.loaded_engine_state(locked, we, wt, twist, asked, 0.0)
    }

    /// [`engine_state`](Self::engine_state) with the engine's shaft also
    /// loaded by `accessory` N m besides the converter's pump and the
    /// clutch (a hydrostatic steer unit's pump, driven by the engine): the
    /// governor fuels for it, and it slows the engine as the pump does;
    /// its slopes are not in the state's (it is taken as given).
    pub fn loaded_engine_state(
        &self,
        locked: bool,
        we: f64,
        wt: f64,
        twist: f64,
        asked: f64,
        accessory: f64,
    ) -> Option<EngineState> {
        let dynamics = self.dynamics.as_ref()?;
        let clutch = dynamics.lockup();
        let cap = dynamics.lockup_capacity;
        // Each as (value, ∂/∂ω_e, ∂/∂ω_t, ∂/∂z).
        let (clutch_torque, twist_rate, clutch_books) = if locked {
            let slip = we - wt;
            let r = clutch.respond(twist, slip, cap);
            let d = clutch.slopes(twist, slip, cap);
            (
                [-r.force, -d.force[1], d.force[1], -d.force[0]],
                [r.rate, d.rate[1], -d.rate[1], d.rate[0]],
                (r.potential, r.dissipation),
            )
        } else {
            let r = clutch.relax(twist);
            let d = clutch.relax_slopes();
            (
                [0.0; 4],
                [r.rate, 0.0, 0.0, d.rate[0]],
                (r.potential, r.dissipation),
            )
        };
        let (fluid, speed_ratio, torque_ratio) = if locked {
            (Fluid::NONE, 1.0, 1.0)
        } else {
            let f = self.fluid(we, wt);
            let sr = if we > 0.0 { wt / we } else { 0.0 };
            (f, sr, f.torque_ratio)
        };
        let load = [
            fluid.pump[0] + clutch_torque[0] + accessory,
            fluid.pump[1] + clutch_torque[1],
            fluid.pump[2] + clutch_torque[2],
            clutch_torque[3],
        ];
        let turbine = [
            fluid.turbine[0] + clutch_torque[0],
            fluid.turbine[1] + clutch_torque[1],
            fluid.turbine[2] + clutch_torque[2],
            clutch_torque[3],
        ];
        // What the governor fuels for beyond the speed it steers by: the
        // load at this state through the converter; locked, the torque
        // asked (∂/∂T* last).
        let feed = if locked {
            [asked + accessory, 0.0, 0.0, 0.0, 1.0]
        } else {
            [load[0], load[1], load[2], load[3], 0.0]
        };
        let (full, dfull) = self.running_full_load(we);
        let (drag, ddrag) = lerp(&dynamics.drag, we.max(0.0));
        let (target, dtarget) = self.governed_speed(locked, wt, asked);
        let j = dynamics.inertia;
        let tau = dynamics.governor_time;
        let span = full - drag;
        let need = feed[0] - drag + j * (target - we) / tau;
        let fuel = if span > 0.0 {
            (need / span).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let engine_torque = fuel * full + (1.0 - fuel) * drag;
        let rate = (engine_torque - load[0]) / j;
        let rate_slopes = if span > 0.0 && fuel > 0.0 && fuel < 1.0 {
            // J ω̇_e = feed − load + J (ω* − ω_e) / τ_g.
            [
                (feed[1] - load[1]) / j - 1.0 / tau,
                (feed[2] - load[2]) / j + dtarget[0] / tau,
                (feed[3] - load[3]) / j,
                feed[4] / j + dtarget[1] / tau,
            ]
        } else {
            let own = if fuel >= 1.0 { dfull } else { ddrag };
            [(own - load[1]) / j, -load[2] / j, -load[3] / j, 0.0]
        };
        Some(EngineState {
            fuel,
            engine_torque,
            load: load[0],
            turbine_torque: turbine[0],
            turbine_slopes: [turbine[1], turbine[2], turbine[3]],
            rate,
            rate_slopes,
            twist_rate: twist_rate[0],
            twist_slopes: [twist_rate[1], twist_rate[2], twist_rate[3]],
            twist_energy: clutch_books.0,
            clutch_dissipation: clutch_books.1,
            speed_ratio,
            torque_ratio,
            locked,
        })
    }
}
