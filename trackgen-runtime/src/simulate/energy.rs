//! The energy books of a recorded run: `motor_work = ΔE + dissipated`.
//!
//! A vehicle integrates the motor's work and the dissipated work with its
//! state and records the mechanical energy including every elastic term
//! (springs, contacts, a penalty joint, soil), so the balance checks every
//! force of the model at once. What is left over is integration error
//! (and any force the books miss): [`EnergyBalance::residual`].

use super::{Results, Summary};

/// Column of the mechanical energy (kinetic + potential + elastic), J.
pub const ENERGY: &str = "energy";
/// Column of the work done by the motor since the start, J.
pub const MOTOR_WORK: &str = "motor_work";
/// Column of the work dissipated since the start (dampers, contact
/// damping, friction, soil), J.
pub const DISSIPATED: &str = "dissipated";

/// The three terms of the books between the first and the last row.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EnergyBalance {
    /// Work done by the motor, J.
    pub motor_work: f64,
    /// Change of the mechanical energy, J.
    pub energy_change: f64,
    /// Work dissipated, J.
    pub dissipated: f64,
}

/// Residual below which the books count as closed however tight the
/// tolerance: floating-point rounding over millions of steps of terms of
/// 1e4–1e5 J is around 1e-9 of the work; 1e-6 leaves room for the ~1e-7
/// the tests measure at Dormand-Prince 1e-6 to 1e-7.
pub const RESIDUAL_FLOOR: f64 = 1e-6;

/// How many times the integrator's relative tolerance the books may be off.
/// Measured on the M113 (`tests/it/vehicle_m113.rs`; docs/performance.md):
/// 2.7e-3 over the
/// 8 s bump course at Bogacki-Shampine 1e-3, 3e-4 at Dormand-Prince 1e-4,
/// 9e-7 at 1e-6; 1.1e-2 over a simulated hour at 1e-3 (the error
/// accumulates with the steps). Ten tolerances flags a run whose books are
/// several times worse than these, and the hour at 1e-3.
pub const RESIDUAL_PER_TOLERANCE: f64 = 10.0;

/// The books were off by more than the bound allowed.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error(
    "energy books off by {residual:.2e} of the largest term (motor work {:.0} J, ΔE {:.0} J, \
     dissipated {:.0} J), above the bound {bound:.1e}: a force the books miss, or too loose a \
     tolerance for this run's length",
    books.motor_work, books.energy_change, books.dissipated
)]
pub struct EnergyBalanceError {
    /// The books.
    pub books: EnergyBalance,
    /// Their residual, [`EnergyBalance::residual`].
    pub residual: f64,
    /// The bound it exceeded.
    pub bound: f64,
}

impl EnergyBalance {
    /// The books of an in-memory run, from its first and last rows; `None`
    /// if it has no rows or does not record the three columns (a track or
    /// chassis on its own).
    pub fn of_results(results: &Results) -> Option<EnergyBalance> {
        let (first, last) = (results.get(0)?, results.last()?);
        let change = |c: &str| Some(last.get(c)? - first.get(c)?);
        Some(EnergyBalance {
            motor_work: change(MOTOR_WORK)?,
            energy_change: change(ENERGY)?,
            dissipated: change(DISSIPATED)?,
        })
    }

    /// The books of a streamed run, from its running [`Summary`].
    pub fn of_summary(summary: &Summary) -> Option<EnergyBalance> {
        let change = |c: &str| summary.get(c).map(|s| s.change());
        Some(EnergyBalance {
            motor_work: change(MOTOR_WORK)?,
            energy_change: change(ENERGY)?,
            dissipated: change(DISSIPATED)?,
        })
    }

    /// `(W − ΔE − D) / max(|W|, |ΔE|, |D|)`: signed, relative to the
    /// largest term (the motor's work in a driven run; the energy lost in a
    /// vehicle settling without drive). Zero when nothing happened; NaN if
    /// any term is.
    pub fn residual(&self) -> f64 {
        let (w, e, d) = (self.motor_work, self.energy_change, self.dissipated);
        let scale = w.abs().max(e.abs()).max(d.abs());
        if scale == 0.0 {
            0.0
        } else if scale.is_nan() || w.is_nan() || e.is_nan() || d.is_nan() {
            f64::NAN
        } else {
            (w - e - d) / scale
        }
    }

    /// The bound for a run at relative tolerance `rtol`:
    /// [`RESIDUAL_PER_TOLERANCE`]` · rtol`, at least [`RESIDUAL_FLOOR`].
    /// For a fixed-step integrator pass the tolerance its step achieves, or
    /// use [`check`](Self::check) with a bound of your own.
    pub fn bound_for_tolerance(rtol: f64) -> f64 {
        (RESIDUAL_PER_TOLERANCE * rtol).max(RESIDUAL_FLOOR)
    }

    /// `Ok` if `|residual| ≤ bound`; otherwise (NaN included) the books and
    /// the bound as an error.
    pub fn check(&self, bound: f64) -> Result<(), EnergyBalanceError> {
        let residual = self.residual();
        if residual.abs() <= bound {
            Ok(())
        } else {
            Err(EnergyBalanceError {
                books: *self,
                residual,
                bound,
            })
        }
    }
}

impl Results {
    /// The energy books of this run (see [`EnergyBalance`]); `None` unless
    /// it records `energy`, `motor_work` and `dissipated` (a vehicle).
    pub fn energy_balance(&self) -> Option<EnergyBalance> {
        EnergyBalance::of_results(self)
    }
}

impl Summary {
    /// The energy books of a streamed run (see [`EnergyBalance`]).
    pub fn energy_balance(&self) -> Option<EnergyBalance> {
        EnergyBalance::of_summary(self)
    }
}
