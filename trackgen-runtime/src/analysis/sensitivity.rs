//! How a vehicle's rest changes with a spring rate: the equilibrium's
//! derivative by the implicit function theorem.

use nalgebra::DVector;

use super::statics::Statics;
use super::{AnalysisError, Equilibrium};
use crate::vehicle::VehicleDynamics;

/// The derivative of an equilibrium with respect to one arm's torsion
/// rate `k` (N m/rad), the spring's preload held.
#[derive(Debug, Clone, PartialEq)]
pub struct ArmSensitivity {
    /// The arm: its index in [`VehicleConfig::arms`](crate::vehicle::VehicleConfig::arms).
    pub arm: usize,
    /// `∂(hull height)/∂k`, m per N m/rad.
    pub height: f64,
    /// `∂(hull pitch)/∂k`, rad per N m/rad.
    pub pitch: f64,
    /// `∂y/∂k` of the whole state (zero for the coordinates an equilibrium
    /// holds fixed: the chassis' x, the sprocket's angle, the wheels'
    /// spins), per N m/rad.
    pub state: DVector<f64>,
}

/// The sensitivity of `equilibrium` (of `system`) to arm `arm`'s torsion
/// rate (the ground points in contact and the free coordinates as at the
/// equilibrium): with `r(u, k) = 0` the equilibrium's equations
/// ([`equilibrium`](super::equilibrium)), `∂u/∂k = −(∂r/∂u)⁻¹ ∂r/∂k`, both
/// Jacobians by central differences (`∂r/∂k` with a step of 10⁻⁶ of the
/// rate). One linear solve, against a Newton iteration per perturbed rate
/// for finite differences of equilibria.
pub fn equilibrium_sensitivity<S: VehicleDynamics>(
    system: &mut S,
    equilibrium: &Equilibrium,
    arm: usize,
) -> Result<ArmSensitivity, AnalysisError> {
    let arms = system.arms_mut().len();
    if arm >= arms {
        return Err(AnalysisError::NoArm { arm, arms });
    }
    let (t, y) = (equilibrium.t, &equilibrium.state);
    // The statics the equilibrium was found with: the shared deflection
    // an unknown only where the ground holds a load along it.
    let statics = Statics::at(system, t, y, equilibrium.friction_held)?;
    let jacobian = statics.jacobian(system, t, y)?;
    let k = system.arms_mut()[arm].spring.stiffness;
    let h = 1e-6 * k.abs().max(1.0);
    let rates = |system: &mut S, stiffness: f64| -> Result<DVector<f64>, AnalysisError> {
        system.arms_mut()[arm].spring.stiffness = stiffness;
        let done = statics.residual(system, t, y);
        system.arms_mut()[arm].spring.stiffness = k;
        done
    };
    let dr_dk = (rates(system, k + h)? - rates(system, k - h)?) / (2.0 * h);
    let du = jacobian
        .lu()
        .solve(&(-dr_dk))
        .ok_or(AnalysisError::Singular)?;
    // The state's change: the unknowns' through `write`, linear in them.
    let base = statics.read(y);
    let mut moved = y.clone();
    statics.write(&(&base + &du), &mut moved);
    let state = moved - y;
    let layout = &statics.layout;
    Ok(ArmSensitivity {
        arm,
        height: state[layout.chassis.start + 1],
        pitch: state[layout.chassis.start + 2],
        state,
    })
}
