//! Planar rotation helpers (spec §0).

use nalgebra::Vector2;

/// `A(θ) v`, the rotation of a body-fixed vector into the global frame.
#[inline]
pub fn rotate(theta: f64, v: Vector2<f64>) -> Vector2<f64> {
    rotate_by(theta.sin_cos(), v)
}

/// `A(θ) v` given `(sin θ, cos θ)`, worked out already.
#[inline]
pub(crate) fn rotate_by((s, c): (f64, f64), v: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

/// `A_θ(θ) v = dA/dθ v`.
#[inline]
pub fn rotate_derivative(theta: f64, v: Vector2<f64>) -> Vector2<f64> {
    let (s, c) = theta.sin_cos();
    Vector2::new(-s * v.x - c * v.y, c * v.x - s * v.y)
}

/// The planar cross product `a × b = a.x b.y − a.y b.x` (spec §0).
#[inline]
pub(crate) fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}
