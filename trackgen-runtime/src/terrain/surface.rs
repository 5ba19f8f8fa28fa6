//! The ground under the vehicle: a height profile `y = h(x)`, or a
//! polyline whose vertical faces no height function can give (a step, a
//! trench wall).

use std::sync::Arc;

use thiserror::Error;

use super::profile::Profile;

/// A terrain profile. Heights in m, positions along x in m.
#[derive(Debug, Clone, PartialEq)]
pub enum Terrain {
    /// `h = height`.
    Flat {
        /// m.
        height: f64,
    },
    /// Flat at `height` up to `start`, then rising with `slope` (rise over
    /// run; negative for a descent).
    Ramp {
        /// m.
        height: f64,
        /// m.
        start: f64,
        /// Rise over run.
        slope: f64,
    },
    /// A cosine bump `h = height/2 (1 + cos(2π (x − centre)/width))` for
    /// `|x − centre| < width/2`, flat (0) elsewhere.
    Bump {
        /// m.
        centre: f64,
        /// Base width, m.
        width: f64,
        /// Peak height, m.
        height: f64,
    },
    /// `h = amplitude sin(2π x / wavelength)`.
    Sine {
        /// m.
        amplitude: f64,
        /// m.
        wavelength: f64,
    },
    /// Piecewise linear through points of strictly increasing x, flat
    /// beyond the ends. Build it with [`Terrain::table`].
    Table(Vec<(f64, f64)>),
    /// A polyline whose x never decreases, vertical faces allowed: a
    /// surveyed profile ([`Profile::read_csv`]), an obstacle course
    /// ([`Course`](super::profile::Course)) or a random one
    /// ([`RoughCourse`](super::roughness::RoughCourse)). Its height is the
    /// surface's from the right at a face; the ground meets a shoe's
    /// points by their distance to its nearest edge, so a face pushes a
    /// point sideways ([`ground::detect`](crate::contact::ground::detect)). Shared:
    /// cloning a configuration does not copy a long course.
    Profile(Arc<Profile>),
}

/// A terrain that cannot be built.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TerrainError {
    /// A table needs two points at least.
    #[error("a terrain table needs at least 2 points, got {0}")]
    TooFewPoints(usize),
    /// Table x values must increase strictly.
    #[error(
        "terrain table out of order: point {index} has x = {x} m, not after the previous x = {previous} m"
    )]
    OutOfOrder {
        /// Index of the offending point.
        index: usize,
        /// Its x, m.
        x: f64,
        /// The previous point's x, m.
        previous: f64,
    },
    /// A value is NaN or infinite.
    #[error("terrain: non-finite value at point {0}")]
    NonFinite(usize),
    /// A parameter of a flat, ramp, bump or sine terrain is NaN or
    /// infinite.
    #[error("terrain: the {terrain}'s {parameter} is {value}, not a finite number")]
    NonFiniteParameter {
        /// Which kind of terrain (`"ramp"`, …).
        terrain: &'static str,
        /// Which parameter (`"slope"`, …).
        parameter: &'static str,
        /// Its value.
        value: f64,
    },
}

impl Terrain {
    /// A polyline terrain ([`Terrain::Profile`]).
    pub fn profile(profile: Profile) -> Terrain {
        Terrain::Profile(Arc::new(profile))
    }

    /// A table terrain, checked: finite points in strictly increasing x.
    pub fn table(points: Vec<(f64, f64)>) -> Result<Terrain, TerrainError> {
        if points.len() < 2 {
            return Err(TerrainError::TooFewPoints(points.len()));
        }
        for (i, &(x, y)) in points.iter().enumerate() {
            if !(x.is_finite() && y.is_finite()) {
                return Err(TerrainError::NonFinite(i));
            }
            if i > 0 && x <= points[i - 1].0 {
                return Err(TerrainError::OutOfOrder {
                    index: i,
                    x,
                    previous: points[i - 1].0,
                });
            }
        }
        Ok(Terrain::Table(points))
    }

    /// Checks a terrain however it was built: every parameter finite, and
    /// a table as [`table`](Self::table) requires. A bump of zero or
    /// negative width is no bump and a sine of zero wavelength is flat
    /// (see [`height_and_slope`](Self::height_and_slope)): both are valid.
    /// Vehicles check their terrain when they are assembled and built.
    pub fn check(&self) -> Result<(), TerrainError> {
        let finite = |terrain, parameters: &[(&'static str, f64)]| match parameters
            .iter()
            .find(|(_, v)| !v.is_finite())
        {
            Some(&(parameter, value)) => Err(TerrainError::NonFiniteParameter {
                terrain,
                parameter,
                value,
            }),
            None => Ok(()),
        };
        match self {
            Terrain::Flat { height } => finite("flat", &[("height", *height)]),
            Terrain::Ramp {
                height,
                start,
                slope,
            } => finite(
                "ramp",
                &[("height", *height), ("start", *start), ("slope", *slope)],
            ),
            Terrain::Bump {
                centre,
                width,
                height,
            } => finite(
                "bump",
                &[("centre", *centre), ("width", *width), ("height", *height)],
            ),
            Terrain::Sine {
                amplitude,
                wavelength,
            } => finite(
                "sine",
                &[("amplitude", *amplitude), ("wavelength", *wavelength)],
            ),
            Terrain::Table(points) => Terrain::table(points.clone()).map(drop),
            // A profile is checked when it is made.
            Terrain::Profile(_) => Ok(()),
        }
    }

    /// `h(x)`, m.
    pub fn height(&self, x: f64) -> f64 {
        self.height_and_slope(x).0
    }

    /// `(h(x), h'(x))`.
    #[inline]
    pub fn height_and_slope(&self, x: f64) -> (f64, f64) {
        match self {
            Terrain::Flat { height } => (*height, 0.0),
            Terrain::Ramp {
                height,
                start,
                slope,
            } => {
                if x <= *start {
                    (*height, 0.0)
                } else {
                    (height + slope * (x - start), *slope)
                }
            }
            Terrain::Bump {
                centre,
                width,
                height,
            } => {
                let u = x - centre;
                if u.abs() >= width / 2.0 {
                    (0.0, 0.0)
                } else {
                    let k = 2.0 * std::f64::consts::PI / width;
                    (
                        height / 2.0 * (1.0 + (k * u).cos()),
                        -height / 2.0 * k * (k * u).sin(),
                    )
                }
            }
            Terrain::Sine { wavelength, .. } if *wavelength == 0.0 => (0.0, 0.0),
            Terrain::Sine {
                amplitude,
                wavelength,
            } => {
                let k = 2.0 * std::f64::consts::PI / wavelength;
                (amplitude * (k * x).sin(), amplitude * k * (k * x).cos())
            }
            // Out of line: the closed forms above stay small enough to
            // inline into the contact passes, which call this per point.
            Terrain::Profile(profile) => profile_height_and_slope(profile, x),
            Terrain::Table(points) => table_height_and_slope(points, x),
        }
    }

    /// `h''(x)`, 1/m: the profile's curvature term, which turns a ground
    /// contact's normal as its point moves (zero on the straight pieces of
    /// ramps and tables, whose kinks have none).
    #[inline]
    pub fn curvature(&self, x: f64) -> f64 {
        match self {
            Terrain::Flat { .. }
            | Terrain::Ramp { .. }
            | Terrain::Table(_)
            | Terrain::Profile(_) => 0.0,
            Terrain::Bump {
                centre,
                width,
                height,
            } => {
                let u = x - centre;
                if u.abs() >= width / 2.0 {
                    0.0
                } else {
                    let k = 2.0 * std::f64::consts::PI / width;
                    -height / 2.0 * k * k * (k * u).cos()
                }
            }
            Terrain::Sine { wavelength, .. } if *wavelength == 0.0 => 0.0,
            Terrain::Sine {
                amplitude,
                wavelength,
            } => {
                let k = 2.0 * std::f64::consts::PI / wavelength;
                -amplitude * k * k * (k * x).sin()
            }
        }
    }

    /// The highest point of the terrain over `[x0, x1]`, m: for culling.
    pub fn max_height(&self, x0: f64, x1: f64) -> f64 {
        match self {
            Terrain::Flat { height } => *height,
            Terrain::Ramp { .. } => self.height(x0).max(self.height(x1)),
            Terrain::Bump { centre, height, .. } => {
                let ends = self.height(x0).max(self.height(x1));
                // A bump's crest inside the interval; a dip's highest points
                // are at the ends (or the flat around it).
                if (x0..=x1).contains(centre) {
                    ends.max(*height)
                } else {
                    ends
                }
            }
            Terrain::Sine { amplitude, .. } => amplitude.abs(),
            Terrain::Table(points) => {
                let inside = points.iter().filter(|p| p.0 > x0 && p.0 < x1).map(|p| p.1);
                inside.fold(self.height(x0).max(self.height(x1)), f64::max)
            }
            Terrain::Profile(profile) => profile.max_height(x0, x1),
        }
    }
}

/// [`Profile::height_and_slope`], called out of line.
#[inline(never)]
fn profile_height_and_slope(profile: &Profile, x: f64) -> (f64, f64) {
    profile.height_and_slope(x)
}

/// A table's `(h(x), h'(x))`: linear between its points, level beyond.
#[inline(never)]
fn table_height_and_slope(points: &[(f64, f64)], x: f64) -> (f64, f64) {
    // Built directly (not by `table`), a table may be empty.
    let (Some(&first), Some(&last)) = (points.first(), points.last()) else {
        return (0.0, 0.0);
    };
    // NaN is neither left of, right of nor between the points:
    // it has no segment (the search below would find none).
    if x.is_nan() {
        return (f64::NAN, f64::NAN);
    }
    if x <= first.0 {
        return (first.1, 0.0);
    }
    if x >= last.0 {
        return (last.1, 0.0);
    }
    let i = points.partition_point(|p| p.0 <= x);
    let (a, b) = (points[i - 1], points[i]);
    let slope = (b.1 - a.1) / (b.0 - a.0);
    (a.1 + slope * (x - a.0), slope)
}
