//! Planar geometry (formulation §0): the rotation `A(θ)`, kept as its
//! `(sin θ, cos θ)` so that every body's trigonometry is computed once per
//! evaluation (as nalgebra's `UnitComplex` keeps `(cos, sin)`), and the
//! planar cross product and quarter turn. The one owner of them: every
//! rotation of a body-fixed vector and every moment arm in the runtime
//! goes through here.

use nalgebra::Vector2;

/// A planar rotation `A(θ)` by its `(sin θ, cos θ)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rotation {
    sin: f64,
    cos: f64,
}

impl Rotation {
    /// No rotation.
    pub const IDENTITY: Rotation = Rotation { sin: 0.0, cos: 1.0 };

    /// `A(θ)`, its trigonometry by the library's `sin_cos`.
    #[inline]
    pub fn new(theta: f64) -> Rotation {
        Rotation::from_sin_cos(theta.sin_cos())
    }

    /// `A(θ)` from `(sin θ, cos θ)` worked out already (the generated code's
    /// vectorised [`sin_cos_each`](crate::trig::sin_cos_each), say).
    #[inline]
    pub const fn from_sin_cos((sin, cos): (f64, f64)) -> Rotation {
        Rotation { sin, cos }
    }

    /// `(sin θ, cos θ)`.
    #[inline]
    pub const fn sin_cos(self) -> (f64, f64) {
        (self.sin, self.cos)
    }

    /// `A(θ) v`: a body-fixed vector in the global frame.
    #[inline]
    pub fn apply(self, v: Vector2<f64>) -> Vector2<f64> {
        let (s, c) = (self.sin, self.cos);
        Vector2::new(c * v.x - s * v.y, s * v.x + c * v.y)
    }

    /// `A(θ)ᵀ v`: a global vector in the body's frame.
    #[inline]
    pub fn apply_inverse(self, v: Vector2<f64>) -> Vector2<f64> {
        let (s, c) = (self.sin, self.cos);
        Vector2::new(c * v.x + s * v.y, c * v.y - s * v.x)
    }

    /// `A_θ(θ) v = dA/dθ v`.
    #[inline]
    pub fn derivative(self, v: Vector2<f64>) -> Vector2<f64> {
        let (s, c) = (self.sin, self.cos);
        Vector2::new(-s * v.x - c * v.y, c * v.x - s * v.y)
    }
}

/// `A(θ) v`, the rotation of a body-fixed vector into the global frame.
#[inline]
pub fn rotate(theta: f64, v: Vector2<f64>) -> Vector2<f64> {
    Rotation::new(theta).apply(v)
}

/// `A_θ(θ) v = dA/dθ v`.
#[inline]
pub fn rotate_derivative(theta: f64, v: Vector2<f64>) -> Vector2<f64> {
    Rotation::new(theta).derivative(v)
}

/// The planar cross product `a × b = a.x b.y − a.y b.x` (formulation §0): the
/// moment of force `b` at arm `a`, the sine of the angle between unit
/// vectors.
#[inline]
pub fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

/// `⟂v = (−v_y, v_x)`: `v` turned a quarter turn counter-clockwise, so
/// that `A_θ(θ) v = ⟂(A(θ) v)` and `cross(a, b) = ⟂a · b`.
#[inline]
pub fn perp(v: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(-v.y, v.x)
}

/// `ω × r` for an angular velocity `ω` about the plane's normal: the
/// velocity of a point at offset `r` from the axis, `ω (−r_y, r_x)`.
#[inline]
pub fn spin(omega: f64, r: Vector2<f64>) -> Vector2<f64> {
    perp(r) * omega
}
