//! The powertrain's tables and the one way each is read: linear between
//! points, held beyond the ends (an engine map: none beyond its last
//! speed), checked by one rule; and the bracketed root finder the
//! converter's matches are solved by.

use super::PowertrainError;

/// The root of `g` in `[a, b]` where `g(a) > 0 ≥ g(b)` (given with their
/// values), `g` piecewise smooth in between: from the secant's crossing,
/// Newton's steps kept inside the shrinking bracket, bisection where a
/// step would leave it. It stops after a Newton step shorter than 1e-10
/// of `ω_e`: quadratic convergence leaves an error of the order of that
/// step squared, at the last bits.
pub(super) fn solve_piece(
    g: &impl Fn(f64) -> (f64, f64),
    (mut a, ga): (f64, f64),
    (mut b, gb): (f64, f64),
) -> f64 {
    let mut x = a + (b - a) * ga / (ga - gb);
    if !(x > a && x < b) {
        x = 0.5 * (a + b);
    }
    for _ in 0..100 {
        let (value, slope) = g(x);
        if value > 0.0 {
            a = x;
        } else {
            b = x;
        }
        let newton = x - value / slope;
        if newton > a && newton < b {
            if (newton - x).abs() <= 1e-10 * x.abs() {
                return newton;
            }
            x = newton;
        } else {
            x = 0.5 * (a + b);
        }
        if b - a <= f64::EPSILON * b {
            return x;
        }
    }
    x
}

/// A table's value at `x`, linear between points and held beyond the ends,
/// and its slope (0 where held).
pub(super) fn lerp(points: &[(f64, f64)], x: f64) -> (f64, f64) {
    let (first, last) = (points[0], points[points.len() - 1]);
    if x <= first.0 {
        return (first.1, 0.0);
    }
    if x >= last.0 {
        return (last.1, 0.0);
    }
    let i = points
        .partition_point(|p| p.0 <= x)
        .clamp(1, points.len() - 1);
    let ((x0, y0), (x1, y1)) = (points[i - 1], points[i]);
    let slope = (y1 - y0) / (x1 - x0);
    (y0 + slope * (x - x0), slope)
}

/// The engine's full-load torque at `w` and its slope: the map, linear
/// between its points, none below its first speed or beyond its last, and
/// none where the map falls below 0 (a governor's cut-off). The one
/// reading of an engine map, [`Powertrain::Engine`](super::Powertrain::Engine)'s
/// too.
pub(super) fn engine_torque(map: &[(f64, f64)], w: f64) -> (f64, f64) {
    if w < map[0].0 || w > map[map.len() - 1].0 {
        return (0.0, 0.0);
    }
    let (torque, slope) = lerp(map, w);
    if torque > 0.0 {
        (torque, slope)
    } else {
        (0.0, 0.0)
    }
}

/// A table of two or more finite points of increasing abscissa from one
/// ≥ 0, each value accepted by `valid`: the one rule of every powertrain
/// table (an engine map, a converter's curves).
pub(super) fn table(
    points: &[(f64, f64)],
    what: &'static str,
    valid: impl Fn(f64) -> bool,
) -> Result<(), PowertrainError> {
    if points.len() < 2 {
        return Err(PowertrainError::Table {
            what,
            point: points.len(),
        });
    }
    for (i, &(x, y)) in points.iter().enumerate() {
        let increasing = i == 0 || x > points[i - 1].0;
        if !(x.is_finite() && y.is_finite() && x >= 0.0 && increasing && valid(y)) {
            return Err(PowertrainError::Table { what, point: i });
        }
    }
    Ok(())
}
