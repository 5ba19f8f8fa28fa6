//! A declared spatial vehicle set on its course: the profile laid across
//! the vehicle's whole width (or each track on its own), tilted by a side
//! slope, the vehicle
//! assembled on it at rest heading along the course. The one start of
//! every 3-D run: the applications' main job and modes, the spatial FMU
//! and the mobility events. What a user names (a course, each track's
//! own, or a grid file) is one [`SpatialGround`], set on by [`on_ground`].

use std::path::PathBuf;

use nalgebra::{DVector, Vector2};
use thiserror::Error;

use super::{SpatialLaws, SpatialSimulated, SpatialVehicleSystem};
use crate::assembly::SideError;
use crate::spatial::SpatialError;
use crate::terrain::Terrain;
use crate::terrain::course::{CourseError, CourseSpec};
use crate::terrain::field::{FieldError, FieldShape, Grid, HeightField};
use crate::terrain::grid_file::{GridFileError, read_grid};
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
    /// A course (the whole ground's, or a track's own) cannot be laid.
    #[error(transparent)]
    Course(#[from] CourseError),
    /// The grid file cannot be read.
    #[error(transparent)]
    GridFile(#[from] GridFileError),
}

/// The ground of a 3-D run as its user names it: the main job's
/// `--course`, `--right-course-file`, `--left-course-file` and
/// `--field-file`, the spatial FMU's settings of those names.
#[derive(Clone, Debug, PartialEq)]
pub enum SpatialGround {
    /// `course` across the vehicle's whole width, or under a track its
    /// own profile where `sides` (right, left) gives one.
    Course {
        /// The course under both tracks.
        course: CourseSpec,
        /// A track's own course (right, left), where given.
        sides: [Option<CourseSpec>; 2],
    },
    /// The heights of an ESRI ASCII grid file: the whole ground.
    GridFile(PathBuf),
}

impl SpatialGround {
    /// What the ground is, for the run's heading: `a bump 0.10 m high at
    /// x = 12.0 m, under the left track flat ground`.
    pub fn describe(&self) -> String {
        match self {
            SpatialGround::Course { course, sides } => {
                let mut said = course.describe();
                for (spec, track) in sides.iter().zip(["right", "left"]) {
                    if let Some(spec) = spec {
                        said.push_str(&format!(", under the {track} track {}", spec.describe()));
                    }
                }
                said
            }
            SpatialGround::GridFile(path) => format!("the height field of {}", path.display()),
        }
    }
}

/// The vehicle `V` under `laws` on `ground` with a side slope
/// `side_slope`: [`on_grid`] on a grid file's heights, else
/// [`on_grounds`] with each track on its own course where given (the
/// whole course where not). A file that cannot be read or a course that
/// cannot be laid is refused here, before anything runs.
pub fn on_ground<V: SpatialVehicleSystem>(
    laws: SpatialLaws,
    ground: &SpatialGround,
    side_slope: f64,
) -> Result<(V::Spatial, DVector<f64>, HeightField), OnCourseError> {
    match ground {
        SpatialGround::GridFile(path) => on_grid::<V>(laws, read_grid(path)?, side_slope),
        SpatialGround::Course { course, sides } => {
            let whole = course.terrain()?;
            let [right, left] = sides
                .clone()
                .map(|side| side.map_or_else(|| Ok(whole.clone()), |spec| spec.terrain()));
            on_grounds::<V>(laws, (&right?, &left?), side_slope)
        }
    }
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
