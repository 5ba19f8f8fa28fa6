//! A declared spatial vehicle set on its course: the profile laid across
//! the vehicle's whole width (or each track on its own), tilted by a side
//! slope, the vehicle
//! assembled on it at rest heading along the course. The one start of
//! every 3-D run: the applications' main job and modes, the spatial FMU
//! and the mobility events.

use nalgebra::{DVector, Vector2};
use thiserror::Error;

use super::{SpatialLaws, SpatialSimulated, SpatialVehicleSystem};
use crate::assembly::SideError;
use crate::spatial::SpatialError;
use crate::terrain::Terrain;
use crate::terrain::field::{FieldError, FieldShape, Grid, HeightField};
use crate::terrain::profile::ProfileError;

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
    /// A grid's section under a track is no profile.
    #[error("the ground under a track: {0}")]
    Section(#[from] ProfileError),
}

/// The vehicle `V` under `laws` (its declared ones:
/// [`SpatialVehicleSystem::declared_laws`]) on `terrain` laid across its
/// width ([`HeightField::profile`]), with a side slope `side_slope` (rise over
/// run to the left: the ground `z = s y` added), assembled at rest heading
/// along `x` ([`SpatialSimulated::assembled`]) and, on a slope, turned
/// onto it ([`SpatialSimulated::rolled`]): the system, its sprockets
/// free, and its state; and the ground.
pub fn on_course<V: SpatialVehicleSystem>(
    laws: SpatialLaws,
    terrain: &Terrain,
    side_slope: f64,
) -> Result<(V::Spatial, DVector<f64>, HeightField), OnCourseError> {
    on_grounds::<V>(laws, (terrain, terrain), side_slope)
}

/// [`on_course`] with each track on its own profile (`grounds`: under
/// the right track, under the left; [`HeightField::sides`], blended
/// across the ground between the tracks, the gauge less the track's
/// width), each track assembled on its own
/// ([`SpatialSimulated::assembled_on`]). The same as [`on_course`] where
/// the two are the same.
pub fn on_grounds<V: SpatialVehicleSystem>(
    laws: SpatialLaws,
    (right, left): (&Terrain, &Terrain),
    side_slope: f64,
) -> Result<(V::Spatial, DVector<f64>, HeightField), OnCourseError> {
    let layout = V::layout();
    let between = layout.gauge - layout.shoe_width;
    let field = HeightField::sides(right, left, between);
    set_on::<V>(laws, field, (right, left), side_slope)
}

/// [`on_course`] on heights on a grid (a [`Grid`] read from a file:
/// [`read_grid`](crate::terrain::grid_file::read_grid)), each track
/// assembled on the grid's section under its centre plane
/// ([`Grid::section`], the field's own heights there).
pub fn on_grid<V: SpatialVehicleSystem>(
    laws: SpatialLaws,
    grid: Grid,
    side_slope: f64,
) -> Result<(V::Spatial, DVector<f64>, HeightField), OnCourseError> {
    let half = 0.5 * V::layout().gauge;
    let [right, left] = [-half, half].map(|y| grid.section(y).map(Terrain::profile));
    let (right, left) = (right?, left?);
    let field = HeightField {
        base: FieldShape::Grid(grid),
        ..HeightField::level()
    };
    set_on::<V>(laws, field, (&right, &left), side_slope)
}

/// `V` on `field` with `side_slope` added, each track assembled on its
/// ground of `grounds` (right, left) and the whole rolled onto the slope.
fn set_on<V: SpatialVehicleSystem>(
    laws: SpatialLaws,
    field: HeightField,
    grounds: (&Terrain, &Terrain),
    side_slope: f64,
) -> Result<(V::Spatial, DVector<f64>, HeightField), OnCourseError> {
    let field = field.tilted(Vector2::new(0.0, side_slope));
    field.check()?;
    let mut system = V::spatial(laws, field.clone())?;
    let mut y = system.assembled_on(grounds)?;
    if side_slope != 0.0 {
        y = system.rolled(y.as_slice(), side_slope.atan());
    }
    Ok((system, y, field))
}
