//! Obstacle courses: run-in, obstacles and run-out laid end to end as a
//! profile.

use super::error::ProfileError;
use super::limits::{MAX_COORDINATE, MAX_HEIGHT, MAX_LENGTH, MAX_SLOPE};
use super::polyline::Profile;
use crate::trig::sin_cos;

/// How far a half-round's polygon may lie inside its circle, m: 0.1 mm.
/// Its facet count is chosen from the radius so that every facet's
/// sagitta is at most this (see [`Course::half_round`]).
pub const HALF_ROUND_TOLERANCE: f64 = 1e-4;

/// An obstacle of the mobility events (NRMM and NG-NRMM, NATO ET-148,
/// 2016; the guide's "Obstacle courses"), for
/// [`Course::then`] and [`Obstacle::course`]. Lengths in m; each is
/// range-checked when it is laid (the ranges are in [`Course`]'s methods).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Obstacle {
    /// [`Course::half_round`].
    HalfRound {
        /// Radius = height, m.
        radius: f64,
    },
    /// [`Course::step`].
    Step {
        /// m; up if positive, down if negative.
        height: f64,
    },
    /// [`Course::gap`].
    Gap {
        /// m.
        width: f64,
        /// m.
        depth: f64,
    },
    /// [`Course::ditch`].
    Ditch {
        /// m.
        depth: f64,
        /// m.
        bottom_width: f64,
        /// From the horizontal, degrees, in (0, 90].
        wall_angle: f64,
    },
    /// [`Course::barrier`].
    Barrier {
        /// m.
        height: f64,
        /// m.
        top_width: f64,
        /// From the horizontal, degrees, in (0, 90].
        wall_angle: f64,
    },
    /// [`Course::grade`].
    Grade {
        /// Rise over run.
        slope: f64,
        /// Horizontal run, m.
        length: f64,
    },
}

impl Obstacle {
    /// The course of a mobility event: from `(0, 0)` a flat run-in of
    /// `run_in` m, the obstacle, a flat run-out of `run_out` m.
    pub fn course(&self, run_in: f64, run_out: f64) -> Result<Profile, ProfileError> {
        Course::new()
            .flat(run_in)?
            .then(self)?
            .flat(run_out)?
            .profile()
    }
}

/// A course laid left to right, each piece starting where the last ended
/// (its x and height): `Course::new().flat(20.0)?.step(0.3)?.flat(20.0)?
/// .profile()?`.
///
/// Every argument is range-checked; an error names the piece, the
/// parameter and its allowed range ([`ProfileError::Parameter`]). The
/// bounds beyond the physical ones (positive widths, angles up to 90°) are
/// sanity bounds that catch a unit mistake: lengths and widths up to
/// [`MAX_LENGTH`], heights and depths up to [`MAX_HEIGHT`].
///
/// Vertical pieces laid one after another at one x (a step, then a gap's
/// first wall) merge into one face, as the ground they describe has one
/// (a wall of zero thickness holds no material); a face that merges to
/// zero height disappears.
#[derive(Debug, Clone, PartialEq)]
pub struct Course {
    points: Vec<(f64, f64)>,
}

impl Default for Course {
    fn default() -> Self {
        Course::new()
    }
}

/// `Ok` if `ok`, else the parameter's error.
fn check(
    ok: bool,
    shape: &'static str,
    parameter: &'static str,
    value: f64,
    allowed: &'static str,
) -> Result<(), ProfileError> {
    if ok {
        Ok(())
    } else {
        Err(ProfileError::Parameter {
            shape,
            parameter,
            value,
            allowed,
        })
    }
}

/// `0 < v ≤ hi` (false for NaN).
fn positive_up_to(v: f64, hi: f64) -> bool {
    v > 0.0 && v <= hi
}

impl Course {
    /// A course starting at `(0, 0)`.
    pub fn new() -> Course {
        Course {
            points: vec![(0.0, 0.0)],
        }
    }

    /// A course starting at `(x, z)`, m; `|x|, |z| ≤ 1e6` m
    /// ([`MAX_COORDINATE`]).
    pub fn starting_at(x: f64, z: f64) -> Result<Course, ProfileError> {
        let ok = |v: f64| v.abs() <= MAX_COORDINATE;
        check(ok(x), "course", "start x", x, "|x| ≤ 1e6 m")?;
        check(ok(z), "course", "start z", z, "|z| ≤ 1e6 m")?;
        Ok(Course {
            points: vec![(x, z)],
        })
    }

    /// Where the course ends so far, `(x, z)` in m.
    pub fn end(&self) -> (f64, f64) {
        self.points[self.points.len() - 1]
    }

    /// Adds a point, merging consecutive vertical pieces at one x.
    fn push(&mut self, x: f64, z: f64) {
        let n = self.points.len();
        let (lx, lz) = self.points[n - 1];
        if x == lx {
            if n >= 2 && self.points[n - 2].0 == x {
                self.points[n - 1].1 = z;
                if self.points[n - 2].1 == z {
                    self.points.pop();
                }
                return;
            }
            if z == lz {
                return;
            }
        }
        self.points.push((x, z));
    }

    /// Flat ground, `0 < length ≤ 1e5` m: a run-in or run-out.
    pub fn flat(mut self, length: f64) -> Result<Course, ProfileError> {
        let ok = positive_up_to(length, MAX_LENGTH);
        check(ok, "flat", "length", length, "0 < length ≤ 1e5 m")?;
        let (x, z) = self.end();
        self.push(x + length, z);
        Ok(self)
    }

    /// A half-round obstacle: a half cylinder of radius = height,
    /// `0 < radius ≤ 100` m, `2 radius` long, as a polygon inscribed in
    /// the circle, its vertices on it.
    ///
    /// `n` facets (even, so that the crest `(x + r, z + r)` is a vertex)
    /// each span π/n of the circle; a facet's sagitta
    /// `r (1 − cos(π / 2n)) ≤ r (π / 2n)² / 2` is at most
    /// [`HALF_ROUND_TOLERANCE`] (0.1 mm) when
    /// `n ≥ π / (2 √(2 · 0.1 mm / r))`, the count used: 26 facets for a
    /// 2 in (0.0508 m) radius, 98 for 30 in (0.762 m). The vertices are
    /// mirrored about the crest; the crest and both feet are exact.
    pub fn half_round(mut self, radius: f64) -> Result<Course, ProfileError> {
        let ok = positive_up_to(radius, MAX_HEIGHT);
        check(ok, "half-round", "radius", radius, "0 < radius ≤ 100 m")?;
        let r = radius;
        let n = half_round_facets(r);
        let (x, z) = self.end();
        let centre = x + r;
        // Vertex k at angle π − kπ/n: (centre − r cos(kπ/n), z + r sin(kπ/n)).
        let offsets: Vec<(f64, f64)> = (1..n / 2)
            .map(|k| {
                let (s, c) = sin_cos(k as f64 * std::f64::consts::PI / n as f64);
                (r * c, r * s)
            })
            .collect();
        for &(dx, dz) in &offsets {
            self.push(centre - dx, z + dz);
        }
        self.push(centre, z + r);
        for &(dx, dz) in offsets.iter().rev() {
            self.push(centre + dx, z + dz);
        }
        self.push(centre + r, z);
        Ok(self)
    }

    /// A step: a vertical face of `height` m, up if positive, down if
    /// negative; `0 < |height| ≤ 100` m.
    pub fn step(mut self, height: f64) -> Result<Course, ProfileError> {
        let ok = positive_up_to(height.abs(), MAX_HEIGHT);
        check(ok, "step", "height", height, "0 < |height| ≤ 100 m")?;
        let (x, z) = self.end();
        self.push(x, z + height);
        Ok(self)
    }

    /// A gap (trench) with vertical walls, `width` (`0 < width ≤ 1e5` m)
    /// and `depth` (`0 < depth ≤ 100` m); the ground continues at the
    /// starting height.
    pub fn gap(mut self, width: f64, depth: f64) -> Result<Course, ProfileError> {
        let ok = positive_up_to(width, MAX_LENGTH);
        check(ok, "gap", "width", width, "0 < width ≤ 1e5 m")?;
        let ok = positive_up_to(depth, MAX_HEIGHT);
        check(ok, "gap", "depth", depth, "0 < depth ≤ 100 m")?;
        let (x, z) = self.end();
        self.push(x, z - depth);
        self.push(x + width, z - depth);
        self.push(x + width, z);
        Ok(self)
    }

    /// A trapezoidal ditch: `depth` (`0 < depth ≤ 100` m), `bottom_width`
    /// (`0 < bottom_width ≤ 1e5` m) and `wall_angle` from the horizontal
    /// in degrees, `0 < wall_angle ≤ 90` (90: vertical walls, a gap). Each
    /// wall runs `depth / tan(wall_angle)`; the top width is
    /// `bottom_width + 2 depth / tan(wall_angle)`, the cross-section
    /// `depth (bottom_width + depth / tan(wall_angle))`.
    pub fn ditch(
        self,
        depth: f64,
        bottom_width: f64,
        wall_angle: f64,
    ) -> Result<Course, ProfileError> {
        let ok = positive_up_to(depth, MAX_HEIGHT);
        check(ok, "ditch", "depth", depth, "0 < depth ≤ 100 m")?;
        let ok = positive_up_to(bottom_width, MAX_LENGTH);
        let allowed = "0 < bottom_width ≤ 1e5 m";
        check(ok, "ditch", "bottom_width", bottom_width, allowed)?;
        let ok = positive_up_to(wall_angle, 90.0);
        let allowed = "0 < wall_angle ≤ 90 degrees";
        check(ok, "ditch", "wall_angle", wall_angle, allowed)?;
        Ok(self.trapezoid(-depth, bottom_width, wall_angle))
    }

    /// A trapezoidal barrier: `height` (`0 < height ≤ 100` m),
    /// `top_width` (`0 < top_width ≤ 1e5` m) and `wall_angle` from the
    /// horizontal in degrees, `0 < wall_angle ≤ 90` (90: vertical walls).
    /// Each wall runs `height / tan(wall_angle)`; the cross-section is
    /// `height (top_width + height / tan(wall_angle))`.
    pub fn barrier(
        self,
        height: f64,
        top_width: f64,
        wall_angle: f64,
    ) -> Result<Course, ProfileError> {
        let ok = positive_up_to(height, MAX_HEIGHT);
        check(ok, "barrier", "height", height, "0 < height ≤ 100 m")?;
        let ok = positive_up_to(top_width, MAX_LENGTH);
        let allowed = "0 < top_width ≤ 1e5 m";
        check(ok, "barrier", "top_width", top_width, allowed)?;
        let ok = positive_up_to(wall_angle, 90.0);
        let allowed = "0 < wall_angle ≤ 90 degrees";
        check(ok, "barrier", "wall_angle", wall_angle, allowed)?;
        Ok(self.trapezoid(height, top_width, wall_angle))
    }

    /// A wall up (`rise > 0`) or down, a flat of `width`, a wall back.
    fn trapezoid(mut self, rise: f64, width: f64, wall_angle: f64) -> Course {
        let run = if wall_angle == 90.0 {
            0.0
        } else {
            let (s, c) = sin_cos(wall_angle * (std::f64::consts::PI / 180.0));
            rise.abs() * c / s
        };
        let (x, z) = self.end();
        let (x1, x2) = (x + run, x + run + width);
        self.push(x1, z + rise);
        self.push(x2, z + rise);
        self.push(x2 + run, z);
        self
    }

    /// A grade: `slope` rise over run (`|slope| ≤ 10`, negative for a
    /// descent) over a horizontal run of `length` m (`0 < length ≤ 1e5`);
    /// it ends `slope · length` higher.
    pub fn grade(mut self, slope: f64, length: f64) -> Result<Course, ProfileError> {
        let ok = slope.abs() <= MAX_SLOPE;
        check(ok, "grade", "slope", slope, "|slope| ≤ 10 (rise over run)")?;
        let ok = positive_up_to(length, MAX_LENGTH);
        check(ok, "grade", "length", length, "0 < length ≤ 1e5 m")?;
        let (x, z) = self.end();
        self.push(x + length, z + slope * length);
        Ok(self)
    }

    /// Lays `obstacle` (by its method above).
    pub fn then(self, obstacle: &Obstacle) -> Result<Course, ProfileError> {
        match *obstacle {
            Obstacle::HalfRound { radius } => self.half_round(radius),
            Obstacle::Step { height } => self.step(height),
            Obstacle::Gap { width, depth } => self.gap(width, depth),
            Obstacle::Ditch {
                depth,
                bottom_width,
                wall_angle,
            } => self.ditch(depth, bottom_width, wall_angle),
            Obstacle::Barrier {
                height,
                top_width,
                wall_angle,
            } => self.barrier(height, top_width, wall_angle),
            Obstacle::Grade { slope, length } => self.grade(slope, length),
        }
    }

    /// The course as a profile, checked like any other (a course of one
    /// step and nothing else, for one, spans no length).
    pub fn profile(self) -> Result<Profile, ProfileError> {
        Profile::new(self.points)
    }
}

/// The facet count of a half-round of radius `r` (see
/// [`Course::half_round`]): even, at least 2.
pub(super) fn half_round_facets(r: f64) -> usize {
    let n = (std::f64::consts::PI / (2.0 * (2.0 * HALF_ROUND_TOLERANCE / r).sqrt())).ceil();
    let n = (n as usize).max(2);
    n + n % 2
}
