//! The Jacobian `∂f/∂y` of a right-hand side by central differences.

use nalgebra::{DMatrix, DVector};

use crate::integrate::OdeSystem;
use crate::integrate::SimulationError;

/// The central-difference step for a state component of value `value`:
/// `10⁻⁶ · max(|value|, 1)`. The truncation error of a central difference
/// is `h² f‴ / 6` and its rounding error `ε |f| / h`; with contact
/// stiffnesses of order 10⁷ N/m over lengths of order 1 mm, `f‴ / f'` is
/// of order 10⁶ m⁻², so `h = 10⁻⁶` (m, rad, m/s …) keeps the truncation
/// near 10⁻⁷ relative and the rounding (f of order 10³, ε 2·10⁻¹⁶)
/// below 10⁻⁷ relative: the derivatives are good to about six digits,
/// which is what an equilibrium's Newton iteration and the modes'
/// frequencies need.
pub fn step_for(value: f64) -> f64 {
    1e-6 * value.abs().max(1.0)
}

/// The columns `columns` of the Jacobian `∂f/∂y` of `system` at `(t, y)`,
/// by central differences ([`step_for`]), all rows: `2 · columns.len()`
/// evaluations.
pub fn state_jacobian<S: OdeSystem + ?Sized>(
    system: &mut S,
    t: f64,
    y: &[f64],
    columns: &[usize],
) -> Result<DMatrix<f64>, SimulationError> {
    let n = y.len();
    let mut jacobian = DMatrix::zeros(n, columns.len());
    let (mut plus, mut minus) = (DVector::zeros(n), DVector::zeros(n));
    let mut shifted = y.to_vec();
    for (c, &j) in columns.iter().enumerate() {
        let h = step_for(y[j]);
        shifted[j] = y[j] + h;
        system.derivative(t, &shifted, plus.as_mut_slice())?;
        shifted[j] = y[j] - h;
        system.derivative(t, &shifted, minus.as_mut_slice())?;
        shifted[j] = y[j];
        jacobian.set_column(c, &((&plus - &minus) / (2.0 * h)));
    }
    Ok(jacobian)
}
