//! The Jacobian by forward differences, for the linearly implicit methods
//! when the system gives none.

use nalgebra::DVector;

use super::{OdeSystem, Stats};
use crate::integrate::SimulationError;

/// `∂f/∂y` at `(t, y)`, whose slope is `f0`, by forward differences with
/// the step `√ε · max(|yⱼ|, 1)` (half the digits of `f`: the truncation and
/// the rounding errors balance), into `jacobian` (column-major, `n × n`).
/// Columns `j` with `skip(j)` are left as they are (components nothing
/// reads). `argument` and `slope` are scratch vectors of length `n`.
#[allow(clippy::too_many_arguments)]
pub(crate) fn forward_jacobian(
    system: &mut dyn OdeSystem,
    stats: &mut Stats,
    (t, y, f0): (f64, &DVector<f64>, &DVector<f64>),
    skip: impl Fn(usize) -> bool,
    argument: &mut DVector<f64>,
    slope: &mut DVector<f64>,
    jacobian: &mut [f64],
) -> Result<(), SimulationError> {
    let n = y.len();
    argument.copy_from(y);
    for (j, column) in jacobian.chunks_exact_mut(n).enumerate() {
        if skip(j) {
            continue;
        }
        let d = f64::EPSILON.sqrt() * y[j].abs().max(1.0);
        argument[j] = y[j] + d;
        super::evaluate(system, stats, t, argument, slope)?;
        argument[j] = y[j];
        for ((c, &fp), &f) in column.iter_mut().zip(slope.as_slice()).zip(f0.as_slice()) {
            *c = (fp - f) / d;
        }
    }
    Ok(())
}
