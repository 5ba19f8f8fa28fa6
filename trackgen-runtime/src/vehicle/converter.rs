//! An engine driving the sprocket through a hydrodynamic torque converter,
//! a range gearbox and a final drive: what it gives at full load.
//!
//! The converter's two curves against the speed ratio `SR = ω_t / ω_p`
//! (turbine over pump) are the form of Wong, *Theory of Ground Vehicles*
//! (4th ed., 2008), §3.4, and of Project Chrono's
//! `ChAutomaticTransmissionShafts`:
//!
//! * the capacity factor `K(SR) = ω_p / √T_p` (rad/s per √(N m)): the pump
//!   absorbs `T_p = (ω_p / K)²`;
//! * the torque ratio `TR(SR) = T_t / T_p`: the turbine gives
//!   `T_t = TR · T_p`, and the converter's efficiency is `SR · TR`.
//!
//! At full load the engine runs where its full-load torque equals what the
//! pump absorbs at the turbine's speed, `T_e(ω_e) = (ω_e / K(ω_t / ω_e))²`
//! (the engine's and the pump's inertia play no part in the steady
//! match); at stall (`ω_t = 0`) that is `T_e(ω_e) = (ω_e / K(0))²` and the
//! turbine gives `TR(0)` times it. A range with a lock-up clutch locks
//! once the converter's speed ratio reaches the clutch's: the engine then
//! turns with the turbine and gives its full-load torque there.

use super::PowertrainError;
use super::engine::EngineDynamics;
use super::shift::{Engaged, Shift};
use super::tables::{engine_torque, lerp, solve_piece, table};

/// An engine, a torque converter with a lock-up clutch, a range gearbox and
/// a final drive, as one side's sprocket sees them at full load
/// ([`Powertrain::Converter`](super::Powertrain::Converter)).
///
/// Every speed is in rad/s and every torque in N m; ratios are reductions
/// (input speed over output speed, the way manuals state them: `4.16:1`).
#[derive(Debug, Clone, PartialEq)]
pub struct Driveline {
    /// Full-load (net, flywheel) engine torque, N m, against engine speed,
    /// rad/s: at least two points of increasing speed, linear between
    /// them; no torque beyond the last point (a negative value, a
    /// governor's cut-off, counts as none), and none below the first (the
    /// engine does not run below it).
    pub engine: Vec<(f64, f64)>,
    /// The converter's capacity factor `K`, rad/s per √(N m), against the
    /// speed ratio: from `SR = 0` (stall), increasing, each `K > 0`;
    /// linear between points, the last value held beyond the last.
    pub capacity: Vec<(f64, f64)>,
    /// The converter's torque ratio `TR` against the speed ratio: from
    /// `SR = 0`, increasing, each `TR ≥ 0`, and its efficiency `SR · TR`
    /// at most 1 at every point; linear between points, the last value
    /// held beyond the last.
    pub torque_ratio: Vec<(f64, f64)>,
    /// The gearbox's forward ranges, reductions (engine side over output
    /// side), each more than 0, lowest range first.
    pub ranges: Vec<f64>,
    /// The ranges (0-based, into [`ranges`](Self::ranges)) whose lock-up
    /// clutch engages.
    pub lockup_ranges: Vec<usize>,
    /// The converter's speed ratio at which the lock-up clutch engages, in
    /// (0, 1].
    pub lockup_speed_ratio: f64,
    /// The final drive's reduction, more than 0.
    pub final_drive: f64,
    /// The gearbox's efficiency (its gears, bearings and pumps), in (0, 1].
    pub gearbox_efficiency: f64,
    /// The final drive's efficiency, in (0, 1].
    pub final_drive_efficiency: f64,
    /// This sprocket's share of the driveline's output: 0.5 for a planar
    /// model of one side of a two-track vehicle; in (0, 1].
    pub share: f64,
    /// The reverse range's reduction (input over output speed, more than
    /// 0), if the gearbox has one: a driver asking the sprocket to turn
    /// backwards gets it, through the converter (it never locks up).
    /// `None`: reversing gets the forward ranges' envelope.
    pub reverse: Option<f64>,
    /// The gearbox's shift schedule; `None`: shifted ideally, each speed
    /// in the range that gives the most torque (the tractive-effort
    /// envelope a mobility model uses).
    pub shift: Option<Shift>,
    /// The engine's inertia, drag, governor and lock-up clutch, which make
    /// its speed a state of the run ([`EngineDynamics`]); `None`: the
    /// engine runs where the converter's steady match puts it
    /// ([`part_load`](Self::part_load)), with no inertia.
    pub dynamics: Option<EngineDynamics>,
    /// The steer unit's minimum steer ratios, one per forward range,
    /// range 1 first: the outer sprocket's speed over the inner's at full
    /// steer (a steer-ratio transmission's, as the M113A3's X200-4
    /// publishes them). Empty: the transmission has no steer unit, or its
    /// ratios are not known. Each more than 1.
    pub steer_ratios: Vec<f64>,
}

/// Where the engine and converter run at full load for one range at one
/// turbine speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OperatingPoint {
    /// Engine (and pump) speed, rad/s.
    pub engine_speed: f64,
    /// Engine torque, N m.
    pub engine_torque: f64,
    /// The converter's speed ratio (1 when locked).
    pub speed_ratio: f64,
    /// The converter's torque ratio (1 when locked).
    pub torque_ratio: f64,
    /// Whether the lock-up clutch is engaged.
    pub locked: bool,
    /// The turbine's torque, N m.
    pub turbine_torque: f64,
    /// The turbine torque's slope with the turbine's speed, N m s/rad.
    pub turbine_slope: f64,
}

impl Driveline {
    /// Every figure in its range: the maps' axes increasing and finite, the
    /// converter's maps starting at `SR = 0`, no ratio or efficiency out of
    /// range, no converter efficiency over 1.
    pub fn check(&self) -> Result<(), PowertrainError> {
        table(&self.engine, "engine's full-load torque", |_| true)?;
        if self.engine[0].0 <= 0.0 {
            // The engine runs from its first speed up: at 0 the converter's
            // speed ratio has no meaning.
            return Err(PowertrainError::Table {
                what: "engine's full-load torque",
                point: 0,
            });
        }
        table(&self.capacity, "converter's capacity factor", |k| k > 0.0)?;
        table(&self.torque_ratio, "converter's torque ratio", |t| t >= 0.0)?;
        for (what, map) in [
            ("capacity factor", &self.capacity),
            ("torque ratio", &self.torque_ratio),
        ] {
            if map[0].0 != 0.0 {
                return Err(PowertrainError::ConverterStart {
                    what,
                    first: map[0].0,
                });
            }
        }
        for (point, &(sr, tr)) in self.torque_ratio.iter().enumerate() {
            if sr * tr > 1.0 {
                return Err(PowertrainError::ConverterEfficiency {
                    point,
                    efficiency: sr * tr,
                });
            }
        }
        if self.ranges.is_empty() {
            return Err(PowertrainError::Ratio {
                gear: 0,
                ratio: f64::NAN,
            });
        }
        for (gear, &ratio) in self.ranges.iter().enumerate() {
            if !(ratio.is_finite() && ratio > 0.0) {
                return Err(PowertrainError::Ratio { gear, ratio });
            }
        }
        if let Some(ratio) = self.reverse
            && !(ratio.is_finite() && ratio > 0.0)
        {
            return Err(PowertrainError::Ratio {
                gear: self.ranges.len(),
                ratio,
            });
        }
        if !(self.final_drive.is_finite() && self.final_drive > 0.0) {
            return Err(PowertrainError::FinalDrive(self.final_drive));
        }
        if let Some(&range) = self.lockup_ranges.iter().find(|&&r| r >= self.ranges.len()) {
            return Err(PowertrainError::LockupRange {
                range,
                ranges: self.ranges.len(),
            });
        }
        if !(self.lockup_speed_ratio > 0.0 && self.lockup_speed_ratio <= 1.0) {
            return Err(PowertrainError::LockupSpeedRatio(self.lockup_speed_ratio));
        }
        if let Some(shift) = &self.shift {
            shift.check(&self.ranges)?;
        }
        if !self.steer_ratios.is_empty() && self.steer_ratios.len() != self.ranges.len() {
            return Err(PowertrainError::SteerRatios {
                count: self.steer_ratios.len(),
                ranges: self.ranges.len(),
            });
        }
        if let Some((range, &ratio)) = self
            .steer_ratios
            .iter()
            .enumerate()
            .find(|(_, r)| !(r.is_finite() && **r > 1.0))
        {
            return Err(PowertrainError::SteerRatio { range, ratio });
        }
        if let Some(dynamics) = &self.dynamics {
            dynamics.check()?;
        }
        for (what, value) in [
            ("gearbox_efficiency", self.gearbox_efficiency),
            ("final_drive_efficiency", self.final_drive_efficiency),
            ("share", self.share),
        ] {
            if !(value > 0.0 && value <= 1.0) {
                return Err(PowertrainError::Stage { what, value });
            }
        }
        Ok(())
    }

    /// An engine map's full-load torque at `speed` (rad/s), N m: linear
    /// between its points, none below its first speed or beyond its last,
    /// none where it falls below 0 (as [`engine`](Self::engine) is read).
    pub fn full_load(engine: &[(f64, f64)], speed: f64) -> f64 {
        engine_torque(engine, speed).0
    }

    /// The engine's rated speed, rad/s: where its full-load map's power
    /// `T ω` is largest (the map is linear between its points, so the
    /// largest is at a point or where a falling segment's `T ω` turns
    /// over, `ω = −a / 2b` for `T = a + b ω`).
    pub fn rated_speed(&self) -> f64 {
        let power = |w: f64| Self::full_load(&self.engine, w) * w;
        let mut best = (0.0, f64::NEG_INFINITY);
        let mut consider = |w: f64| {
            let p = power(w);
            if p > best.1 {
                best = (w, p);
            }
        };
        for pair in self.engine.windows(2) {
            let [(w0, t0), (w1, t1)] = [pair[0], pair[1]];
            consider(w0);
            consider(w1);
            let b = (t1 - t0) / (w1 - w0);
            let a = t0 - b * w0;
            if b < 0.0 {
                let w = -a / (2.0 * b);
                if w0 < w && w < w1 {
                    consider(w);
                }
            }
        }
        best.0
    }

    /// The part of the turbine's torque that reaches this sprocket: the
    /// stages' efficiencies times the side's share.
    pub fn fraction(&self) -> f64 {
        self.gearbox_efficiency * self.final_drive_efficiency * self.share
    }

    /// The overall reduction in range `range` (0-based; the
    /// [`reverse_range`](Self::reverse_range)'s index for reverse), engine
    /// side over sprocket: the range's times the final drive's.
    pub fn reduction(&self, range: usize) -> f64 {
        let ratio = match self.ranges.get(range) {
            Some(&ratio) => ratio,
            None => self.reverse.unwrap_or(f64::NAN),
        };
        ratio * self.final_drive
    }

    /// The reverse range's index, one past the forward ranges', if the
    /// gearbox has one ([`reverse`](Self::reverse)).
    pub fn reverse_range(&self) -> Option<usize> {
        self.reverse.map(|_| self.ranges.len())
    }

    /// The range `gear` (0-based, the reverse range last) as a run
    /// records it: numbered from 1, −1 in reverse, 0 for none.
    pub fn gear_number(&self, gear: Option<usize>) -> f64 {
        match gear {
            None => 0.0,
            Some(g) if Some(g) == self.reverse_range() => -1.0,
            Some(g) => (g + 1) as f64,
        }
    }

    /// The full-load operating point in range `range` (0-based) with the
    /// turbine at `turbine_speed` (rad/s, ≥ 0): the converter's match, or
    /// the lock-up's where the range locks and the match's speed ratio
    /// reaches the clutch's ([`locks`](Self::locks)). `None` where the
    /// engine cannot drive the turbine that fast.
    pub fn operating_point(&self, range: usize, turbine_speed: f64) -> Option<OperatingPoint> {
        if self.lockup_ranges.contains(&range) && self.locks(turbine_speed) {
            let (torque, slope) = engine_torque(&self.engine, turbine_speed);
            if torque > 0.0 {
                return Some(OperatingPoint {
                    engine_speed: turbine_speed,
                    engine_torque: torque,
                    speed_ratio: 1.0,
                    torque_ratio: 1.0,
                    locked: true,
                    turbine_torque: torque,
                    turbine_slope: slope,
                });
            }
        }
        self.converter_match(turbine_speed)
    }

    /// Whether a lock-up clutch engages with the turbine at `wt` (rad/s):
    /// where the converter has no match, or its match's speed ratio is at
    /// least [`lockup_speed_ratio`](Self::lockup_speed_ratio) — the match
    /// lies at or below `ω_x = wt / SR_lock`, so `g(ω_x) ≤ 0` (the pump
    /// there absorbs at least what the engine gives), without solving the
    /// match.
    pub fn locks(&self, wt: f64) -> bool {
        let low = wt.max(self.engine[0].0);
        if low >= self.engine[self.engine.len() - 1].0 || self.imbalance(low, wt).0 <= 0.0 {
            return true;
        }
        let at = wt / self.lockup_speed_ratio;
        at >= low && self.imbalance(at, wt).0 <= 0.0
    }

    /// The converter's full-load match at turbine speed `wt` (rad/s, ≥ 0):
    /// an engine speed at or above both `wt` and the map's first speed
    /// where the engine's full-load torque equals what the pump absorbs,
    /// `g(ω_e) = T_e(ω_e) − (ω_e / K(wt / ω_e))² = 0`, in the first piece
    /// of the engine map at whose end `g ≤ 0` (so `g` crosses from
    /// positive: the speed the engine, opened from idle, accelerates to).
    /// The root is the only one where the full-load torque does not rise
    /// faster with speed than the pump's absorption, the condition for the
    /// match to be stable. `None` where no such speed exists (the pump,
    /// even at `SR = 1`, absorbs more than the engine gives).
    pub fn converter_match(&self, wt: f64) -> Option<OperatingPoint> {
        let low = wt.max(self.engine[0].0);
        if low >= self.engine[self.engine.len() - 1].0 {
            return None;
        }
        let g = |we: f64| self.imbalance(we, wt);
        let mut ga = g(low).0;
        if ga <= 0.0 {
            return None;
        }
        let mut a = low;
        for &(b, _) in &self.engine {
            if b <= low {
                continue;
            }
            let gb = g(b).0;
            if gb <= 0.0 {
                return Some(self.matched(solve_piece(&g, (a, ga), (b, gb)), wt));
            }
            (a, ga) = (b, gb);
        }
        None
    }

    /// `g(ω_e) = T_e(ω_e) − (ω_e / K(ω_t / ω_e))²` and `∂g/∂ω_e`.
    fn imbalance(&self, we: f64, wt: f64) -> (f64, f64) {
        let (te, dte) = engine_torque(&self.engine, we);
        let (tp, dtp_dwe, _) = self.pump_torque(we, wt);
        (te - tp, dte - dtp_dwe)
    }

    /// What the pump absorbs at engine speed `we` and turbine speed `wt`,
    /// `T_p = (ω_e / K(SR))²`, and its partial slopes with `ω_e` and `ω_t`.
    fn pump_torque(&self, we: f64, wt: f64) -> (f64, f64, f64) {
        let sr = wt / we;
        let (k, dk) = lerp(&self.capacity, sr);
        let tp = (we / k) * (we / k);
        // ∂T_p/∂K = −2 T_p / K; ∂SR/∂ω_e = −SR/ω_e, ∂SR/∂ω_t = 1/ω_e.
        let dtp_dk = -2.0 * tp / k;
        (
            tp,
            2.0 * tp / we + dtp_dk * dk * (-sr / we),
            dtp_dk * dk / we,
        )
    }

    /// The operating point at the converter's match `we` for turbine speed
    /// `wt`, with the turbine torque's total slope with `wt` by the
    /// implicit function theorem on `g(ω_e, ω_t) = 0`.
    fn matched(&self, we: f64, wt: f64) -> OperatingPoint {
        let sr = wt / we;
        let (te, dte) = engine_torque(&self.engine, we);
        let (tr, dtr) = lerp(&self.torque_ratio, sr);
        let (_, dtp_dwe, dtp_dwt) = self.pump_torque(we, wt);
        // g = T_e − T_p: dω_e/dω_t = −g_t / g_e = −T_p,t / (T_p,e − T_e').
        let dwe = dtp_dwt / (dte - dtp_dwe);
        let dsr = 1.0 / we - sr / we * dwe;
        // T_t = TR(SR) T_p with T_p = T_e(ω_e) on the match.
        OperatingPoint {
            engine_speed: we,
            engine_torque: te,
            speed_ratio: sr,
            torque_ratio: tr,
            locked: false,
            turbine_torque: tr * te,
            turbine_slope: dtr * dsr * te + tr * dte * dwe,
        }
    }

    /// Where the engine and converter run in range `range` (0-based) when
    /// the turbine turns at `wt` (rad/s) and gives `tt` (N m, the whole
    /// turbine's, ≥ 0) — at part load as at full: the converter's own
    /// characteristic sets the engine's speed, `TR(SR) (ω_e / K(SR))² = T_t`
    /// with `SR = ω_t / ω_e`, and the engine gives what the pump absorbs,
    /// `T_e = T_t / TR` (the throttle is whatever gives it). The root is
    /// found between `ω_t` (the coupling) and the full-load match's speed,
    /// where the turbine gives at least `tt`; a range that locks is locked
    /// where the root's speed ratio reaches the clutch's, or where the
    /// full-load point is locked, and then `ω_e = ω_t`, `T_e = T_t`.
    /// A turbine turned backwards (`wt < 0`, the vehicle forcing the
    /// sprocket back) is the converter at stall. Where even the coupling
    /// gives more than `tt` (a light load near `SR = 1`) the converter is
    /// at the coupling, `ω_e = ω_t`. `turbine_slope` is not computed (0).
    pub fn part_load(&self, range: usize, wt: f64, tt: f64) -> OperatingPoint {
        self.part_load_near(range, wt, tt, self.operating_point(range, wt.max(0.0)))
    }

    /// [`part_load`](Self::part_load) given the range's full-load point at
    /// the turbine's speed (`max(wt, 0)`): the envelope's, found with the
    /// cap, solved once.
    pub(super) fn part_load_near(
        &self,
        range: usize,
        wt: f64,
        tt: f64,
        full: Option<OperatingPoint>,
    ) -> OperatingPoint {
        let locking = self.lockup_ranges.contains(&range);
        let locked = |we: f64, te: f64| OperatingPoint {
            engine_speed: we,
            engine_torque: te,
            speed_ratio: 1.0,
            torque_ratio: 1.0,
            locked: true,
            turbine_torque: te,
            turbine_slope: 0.0,
        };
        let w = wt.max(0.0);
        if let Some(point) = full
            && point.locked
        {
            return locked(w, tt);
        }
        // h(ω_e) = T_t − TR(SR) (ω_e / K(SR))²: positive at the coupling
        // (the converter gives less than asked), ≤ 0 at the full-load match.
        let turbine = |we: f64| -> (f64, f64) {
            let sr = w / we;
            let (k, dk) = lerp(&self.capacity, sr);
            let (tr, dtr) = lerp(&self.torque_ratio, sr);
            let tp = (we / k) * (we / k);
            let dsr = -sr / we;
            let dtp = 2.0 * tp / we - 2.0 * tp / k * dk * dsr;
            (tr * tp, dtr * dsr * tp + tr * dtp)
        };
        let h = |we: f64| {
            let (t, dt) = turbine(we);
            (tt - t, -dt)
        };
        let coupling = || {
            let tr = lerp(&self.torque_ratio, 1.0).0;
            OperatingPoint {
                engine_speed: w,
                engine_torque: tt / tr,
                speed_ratio: 1.0,
                torque_ratio: tr,
                locked: false,
                turbine_torque: tt,
                turbine_slope: 0.0,
            }
        };
        // At stall `SR = 0` at every engine speed but 0, where it has no
        // meaning: there `h` is `T_t`, its limit.
        let ga = if w > 0.0 { h(w).0 } else { tt };
        if ga <= 0.0 && w > 0.0 {
            return if locking { locked(w, tt) } else { coupling() };
        }
        if tt <= 0.0 {
            // At rest with nothing asked: the engine gives nothing.
            return coupling();
        }
        // The full-load match gives at least `tt` (the drive is capped
        // there): the upper end of the bracket, where the turbine gives
        // the match's torque. A torque past it (by the cap's rounding)
        // runs at it; with no match (the cap is 0 there, so nothing is
        // asked) the converter is at the coupling.
        let Some(full) = full else {
            return coupling();
        };
        let (b, gb) = (full.engine_speed, tt - full.turbine_torque);
        if gb > 0.0 || b <= w {
            return full;
        }
        let we = solve_piece(&h, (w, ga), (b, gb));
        let sr = w / we;
        if locking && sr >= self.lockup_speed_ratio {
            return locked(w, tt);
        }
        let tr = lerp(&self.torque_ratio, sr).0;
        OperatingPoint {
            engine_speed: we,
            engine_torque: tt / tr,
            speed_ratio: sr,
            torque_ratio: tr,
            locked: false,
            turbine_torque: tt,
            turbine_slope: 0.0,
        }
    }

    /// What range `range` gives the sprocket at full load at sprocket
    /// speed `speed` (rad/s, ≥ 0): N m, its slope with the speed, N m
    /// s/rad, and the range's full-load point (`None`: the engine cannot
    /// drive the turbine that fast, and the range gives nothing).
    pub fn in_range(&self, range: usize, speed: f64) -> (f64, f64, Option<OperatingPoint>) {
        let n = self.reduction(range);
        let fraction = self.fraction();
        match self.operating_point(range, n * speed) {
            Some(point) => (
                fraction * n * point.turbine_torque,
                fraction * n * n * point.turbine_slope,
                Some(point),
            ),
            None => (0.0, 0.0, None),
        }
    }

    /// A shift schedule at this gearbox's ideal shift points, for a
    /// vehicle whose own are not published: range `r` shifts up at the
    /// sprocket speed where range `r + 1`'s full-load torque overtakes it
    /// (found by a scan of 4000 speeds to the range's reach, then
    /// bisection to the last bits), and range `r + 1` down at `down` (in
    /// (0, 1)) of that speed; both as the gearbox's input speeds; a shift
    /// takes `time` s. Accelerating at full throttle it shifts where the
    /// envelope changes range; slowing, `1 − down` later. `None` where a
    /// range never overtakes the one below it.
    pub fn ideal_schedule(&self, down: f64, time: f64) -> Option<Shift> {
        let n = self.ranges.len();
        let (mut up, mut low) = (vec![0.0; n], vec![0.0; n]);
        for r in 0..n.saturating_sub(1) {
            let better = |w: f64| self.in_range(r + 1, w).0 > self.in_range(r, w).0;
            let reach = self.engine[self.engine.len() - 1].0 / self.reduction(r);
            let steps = 4000;
            let step = reach / steps as f64;
            let first = (1..=steps).map(|k| k as f64 * step).find(|&w| better(w))?;
            let (mut a, mut b) = (first - step, first);
            while b - a > f64::EPSILON * b {
                let mid = 0.5 * (a + b);
                if mid <= a || mid >= b {
                    break;
                }
                if better(mid) {
                    b = mid;
                } else {
                    a = mid;
                }
            }
            up[r] = self.reduction(r) * b;
            low[r + 1] = self.reduction(r + 1) * down * b;
        }
        Some(Shift {
            up,
            down: low,
            time,
        })
    }

    /// What the gearbox `engaged` gives the sprocket at full load at
    /// sprocket speed `speed` (rad/s, ≥ 0): the engaged range's
    /// [`in_range`](Self::in_range), or while a shift takes its time the
    /// lesser of the two ranges'; with the range that gives it.
    pub fn scheduled(
        &self,
        engaged: Engaged,
        speed: f64,
    ) -> (f64, f64, usize, Option<OperatingPoint>) {
        let (torque, slope, point) = self.in_range(engaged.range, speed);
        if let Some((from, _)) = engaged.from {
            let (before, before_slope, before_point) = self.in_range(from, speed);
            if before < torque {
                return (before, before_slope, from, before_point);
            }
        }
        (torque, slope, engaged.range, point)
    }

    /// The most torque any range gives the sprocket at sprocket speed
    /// `speed` (rad/s, ≥ 0), N m, its slope with the speed, N m s/rad, and
    /// the range (0-based) that gives it (`None` if none drives).
    pub fn envelope(&self, speed: f64) -> (f64, f64, Option<usize>) {
        let (torque, slope, best) = self.envelope_point(speed);
        (torque, slope, best.map(|(range, _)| range))
    }

    /// [`envelope`](Self::envelope), with the best range's full-load
    /// operating point.
    pub(super) fn envelope_point(&self, speed: f64) -> (f64, f64, Option<(usize, OperatingPoint)>) {
        let fraction = self.fraction();
        let mut best = (0.0, 0.0, None);
        for range in 0..self.ranges.len() {
            let n = self.reduction(range);
            // A range whose bound cannot beat the best so far is not solved.
            let locking = self.lockup_ranges.contains(&range);
            if fraction * n * self.turbine_bound(n * speed, locking) <= best.0 {
                continue;
            }
            if let Some(point) = self.operating_point(range, n * speed) {
                let torque = fraction * n * point.turbine_torque;
                if torque > best.0 {
                    let slope = fraction * n * n * point.turbine_slope;
                    best = (torque, slope, Some((range, point)));
                }
            }
        }
        best
    }

    /// At most what the turbine gives at turbine speed `wt` (rad/s), N m:
    /// the engine turns at least as fast as the turbine, so at most the
    /// map's largest torque from `wt` up, times the largest torque ratio
    /// at a speed ratio of at least `wt` over the map's last speed (or 1
    /// where the range may lock).
    fn turbine_bound(&self, wt: f64, locking: bool) -> f64 {
        let last = self.engine[self.engine.len() - 1].0;
        let torque = most_from(&self.engine, wt.max(self.engine[0].0));
        let ratio = most_from(&self.torque_ratio, wt / last);
        torque * if locking { ratio.max(1.0) } else { ratio }
    }

    /// The most power the sprocket gets at full load, W: the envelope's
    /// largest `τ ω`, by a scan of 4000 speeds up to the highest range's
    /// reach refined by golden sections about the best.
    pub fn max_power(&self) -> f64 {
        let lowest = (0..self.ranges.len())
            .map(|r| self.reduction(r))
            .fold(f64::INFINITY, f64::min);
        let top = self.engine[self.engine.len() - 1].0 / lowest;
        // The envelope is piecewise smooth: a fine scan of its power,
        // refined at its best sample by golden sections.
        let power = |w: f64| self.envelope(w).0 * w;
        let n = 4000;
        let (mut best_w, mut best) = (0.0, 0.0);
        for i in 0..=n {
            let w = top * i as f64 / n as f64;
            let p = power(w);
            if p > best {
                (best_w, best) = (w, p);
            }
        }
        let step = top / n as f64;
        let (mut a, mut b) = ((best_w - step).max(0.0), (best_w + step).min(top));
        let phi = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..80 {
            let c = b - phi * (b - a);
            let d = a + phi * (b - a);
            if power(c) >= power(d) {
                b = d;
            } else {
                a = c;
            }
        }
        best.max(power(0.5 * (a + b)))
    }
}

/// The largest value of a table (as [`lerp`](super::tables::lerp) reads it) at `x` or beyond.
fn most_from(points: &[(f64, f64)], x: f64) -> f64 {
    points
        .iter()
        .filter(|p| p.0 > x)
        .fold(lerp(points, x).0, |m, p| m.max(p.1))
}
