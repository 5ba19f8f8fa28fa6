use nalgebra::Vector2;

use crate::planar::cross;

/// An applied load on one body, reduced to its centroid: force `F` (N, global
/// frame) and moment `T` (N m, counter-clockwise positive). Gravity is not
/// part of it: the model adds gravity itself.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BodyLoad {
    /// Force at the centroid, global frame, N.
    pub force: Vector2<f64>,
    /// Moment about the centroid, N m.
    pub moment: f64,
}

impl BodyLoad {
    /// No load.
    pub const ZERO: BodyLoad = BodyLoad {
        force: Vector2::new(0.0, 0.0),
        moment: 0.0,
    };

    /// A force at the centroid.
    pub fn force(force: Vector2<f64>) -> Self {
        BodyLoad { force, moment: 0.0 }
    }

    /// A pure moment.
    pub fn moment(moment: f64) -> Self {
        BodyLoad {
            force: Vector2::zeros(),
            moment,
        }
    }

    /// A force applied at a point of the body whose offset from the centroid,
    /// in the global frame, is `arm` (`A ū` for a body point `ū`). Adds the
    /// moment `arm × F` (formulation §0).
    #[inline]
    pub fn force_at(force: Vector2<f64>, arm: Vector2<f64>) -> Self {
        BodyLoad {
            force,
            moment: cross(arm, force),
        }
    }

    /// The sum of two loads on the same body.
    #[inline]
    pub fn plus(self, other: BodyLoad) -> Self {
        BodyLoad {
            force: self.force + other.force,
            moment: self.moment + other.moment,
        }
    }
}
