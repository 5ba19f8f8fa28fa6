//! A declared spatial vehicle set on its course: the profile laid across
//! the vehicle's whole width, tilted by a side slope, the vehicle
//! assembled on it at rest heading along the course. The one start of the
//! applications' 3-D main job and of the spatial FMU.

use nalgebra::{DVector, Vector2};
use thiserror::Error;

use super::{SpatialSimulated, SpatialVehicleSystem};
use crate::assembly::SideError;
use crate::spatial::SpatialError;
use crate::terrain::Terrain;
use crate::terrain::field::{FieldError, FieldShape, HeightField};

/// Why a spatial vehicle cannot be set on its course.
#[derive(Debug, Error)]
pub enum OnCourseError {
    /// The ground is no height field (a side slope that is not finite).
    #[error(transparent)]
    Ground(#[from] FieldError),
    /// The vehicle cannot be built on it.
    #[error(transparent)]
    Vehicle(#[from] SpatialError),
    /// Its tracks cannot be assembled on it.
    #[error(transparent)]
    Assembly(#[from] SideError),
}

/// The vehicle `V` under its declared laws on `terrain` laid across its
/// width, with a side slope `side_slope` (rise over run to the left: the
/// ground `z = s y` added), assembled at rest heading along `x`
/// ([`SpatialSimulated::assembled`]) and, on a slope, turned onto it
/// ([`SpatialSimulated::rolled`]): the system, its sprockets free, and
/// its state; and the ground.
pub fn on_course<V: SpatialVehicleSystem>(
    terrain: &Terrain,
    side_slope: f64,
) -> Result<(V::Spatial, DVector<f64>, HeightField), OnCourseError> {
    let field = HeightField {
        base: FieldShape::Profile(terrain.clone()),
        ..HeightField::level()
    }
    .tilted(Vector2::new(0.0, side_slope));
    field.check()?;
    let mut system = V::spatial(V::declared_laws(), field.clone())?;
    let mut y = system.assembled(terrain)?;
    if side_slope != 0.0 {
        y = system.rolled(y.as_slice(), side_slope.atan());
    }
    Ok((system, y, field))
}
