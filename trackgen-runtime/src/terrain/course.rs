//! The courses a run drives, as a user names them: a cosine bump (or
//! dip), a surveyed profile from a file, a random course of a given
//! roughness, or an obstacle between flat run-in and run-out; with the
//! syntax the main job's options and an FMU's parameters share
//! ([`roughness`], [`obstacle`]).

use std::path::PathBuf;
use thiserror::Error;

use super::Terrain;
use super::profile::{Course as Polyline, Obstacle, Profile, ProfileError};
use super::roughness::{
    DETRENDING_BASE_LENGTH, Iso8608Class, RoughCourse, RoughnessError, SPACING, Spectrum,
};

/// Where a random course starts, m: behind the vehicle (whose centroid
/// starts at 0 and whose track spans about ±2.4 m).
pub const ROUGH_START: f64 = -10.0;
/// Its flat run-in from there, m, and the length over which the roughness
/// fades in after it, m: the vehicle starts on the flat.
pub const ROUGH_RUN_IN: (f64, f64) = (15.0, 5.0);

/// Flat ground before an obstacle starts from here, m.
pub const OBSTACLE_RUN_IN_FROM: f64 = -100.0;
/// Flat ground after an obstacle, m.
pub const OBSTACLE_RUN_OUT: f64 = 200.0;

/// A course that cannot be laid: a file that cannot be read, a
/// roughness or an obstacle out of its range.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum CourseError {
    /// The profile (a file's, or the obstacle's) was refused.
    #[error(transparent)]
    Profile(#[from] ProfileError),
    /// The random course was refused.
    #[error(transparent)]
    Roughness(#[from] RoughnessError),
}

/// A random course's length when none is given, m: what a run at `speed`
/// (m/s) for `duration` (s) covers, a fifth more, and 20 m.
pub fn rough_length(speed: f64, duration: f64) -> f64 {
    1.2 * speed.abs() * duration + 20.0
}

/// How rough a random course is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Roughness {
    /// An ISO 8608 class, A to H.
    Class(Iso8608Class),
    /// A detrended RMS elevation, m.
    Rms(f64),
}

/// The ground's profile.
#[derive(Debug, Clone, PartialEq)]
pub enum CourseSpec {
    /// Flat ground at height 0.
    Flat,
    /// A cosine bump (a dip if the height is negative) 1 m wide.
    Bump {
        /// Its centre, m.
        at: f64,
        /// Its height, m.
        height: f64,
    },
    /// A profile read from a CSV file (`x,z`, m).
    File(PathBuf),
    /// A random course.
    Rough {
        /// How rough.
        roughness: Roughness,
        /// The generator's seed.
        seed: u64,
        /// Its rough length, m.
        length: f64,
    },
    /// An obstacle on flat ground.
    Obstacle {
        /// Which.
        obstacle: Obstacle,
        /// Where it starts, m.
        at: f64,
    },
    /// A ground laid out in code (a profile of obstacles and grades, say,
    /// as the mobility events lay theirs): taken as it is.
    Laid(Terrain),
}

impl CourseSpec {
    /// The terrain: the file read, the course generated or laid out.
    /// Errors name the file and line, or the parameter and its range.
    pub fn terrain(&self) -> Result<Terrain, CourseError> {
        Ok(match self {
            CourseSpec::Flat => Terrain::Flat { height: 0.0 },
            CourseSpec::Bump { at, height } => Terrain::Bump {
                centre: *at,
                width: 1.0,
                height: *height,
            },
            CourseSpec::File(path) => Terrain::profile(Profile::read_csv(path)?),
            CourseSpec::Rough {
                roughness,
                seed,
                length,
            } => {
                let spectrum = match *roughness {
                    Roughness::Class(class) => Spectrum::Iso8608(class),
                    Roughness::Rms(rms) => Spectrum::DetrendedRms {
                        rms,
                        base_length: DETRENDING_BASE_LENGTH,
                    },
                };
                let course = RoughCourse::new(spectrum, *length, SPACING, *seed)
                    .starting_at(ROUGH_START)
                    .with_run_in(ROUGH_RUN_IN.0, ROUGH_RUN_IN.1);
                Terrain::profile(course.profile()?)
            }
            CourseSpec::Obstacle { obstacle, at } => {
                let course = Polyline::starting_at(OBSTACLE_RUN_IN_FROM, 0.0)?
                    .flat(at - OBSTACLE_RUN_IN_FROM)?
                    .then(obstacle)?
                    .flat(OBSTACLE_RUN_OUT)?;
                Terrain::profile(course.profile()?)
            }
            CourseSpec::Laid(terrain) => terrain.clone(),
        })
    }

    /// What the course is, for the run's heading: `a bump 0.10 m high at
    /// x = 12.0 m`.
    pub fn describe(&self) -> String {
        match self {
            CourseSpec::Flat => "flat ground".to_string(),
            CourseSpec::Bump { at, height } => format!(
                "{} {:.2} m {} at x = {at:.1} m",
                if *height < 0.0 { "dip" } else { "bump" },
                height.abs(),
                if *height < 0.0 { "deep" } else { "high" },
            ),
            CourseSpec::File(path) => format!("the profile of {}", path.display()),
            CourseSpec::Rough {
                roughness,
                seed,
                length,
            } => {
                let how = match roughness {
                    Roughness::Class(class) => format!("ISO 8608 class {}", class.letter()),
                    Roughness::Rms(rms) => {
                        format!("{:.1} mm ({:.2} in) detrended RMS", rms * 1e3, rms / 0.0254)
                    }
                };
                format!(
                    "a random course, {how}, {length:.0} m from x = {} m (seed {seed})",
                    ROUGH_START + ROUGH_RUN_IN.0
                )
            }
            CourseSpec::Obstacle { obstacle, at } => {
                format!("{} at x = {at:.1} m", describe_obstacle(obstacle))
            }
            CourseSpec::Laid(_) => "a ground laid out in code".to_string(),
        }
    }

    /// The title's last words: `over a bump`, `through a dip`.
    pub fn title(&self) -> String {
        match self {
            CourseSpec::Bump { height, .. } if *height < 0.0 => "through a dip".to_string(),
            CourseSpec::Bump { .. } => "over a bump".to_string(),
            CourseSpec::Flat => "on flat ground".to_string(),
            CourseSpec::File(_) => "over a surveyed profile".to_string(),
            CourseSpec::Rough { .. } => "over rough ground".to_string(),
            CourseSpec::Obstacle { obstacle, .. } => format!("at {}", describe_obstacle(obstacle)),
            CourseSpec::Laid(_) => "over its own ground".to_string(),
        }
    }

    /// Where the picture of the vehicle is taken, m (the chassis
    /// centroid's x): a metre short of the bump or the obstacle, the front
    /// wheels on it; the start elsewhere.
    pub fn focus(&self) -> f64 {
        match self {
            CourseSpec::Bump { at, .. } | CourseSpec::Obstacle { at, .. } => at - 1.0,
            CourseSpec::Flat
            | CourseSpec::File(_)
            | CourseSpec::Rough { .. }
            | CourseSpec::Laid(_) => 0.0,
        }
    }
}

/// `a half-round 0.20 m high`.
fn describe_obstacle(obstacle: &Obstacle) -> String {
    match *obstacle {
        Obstacle::HalfRound { radius } => format!("a half-round {radius:.2} m high"),
        Obstacle::Step { height } if height < 0.0 => {
            format!("a step down of {:.2} m", -height)
        }
        Obstacle::Step { height } => format!("a step {height:.2} m high"),
        Obstacle::Gap { width, depth } => format!("a trench {width:.2} m wide, {depth:.2} m deep"),
        Obstacle::Ditch {
            depth,
            bottom_width,
            wall_angle,
        } => format!(
            "a ditch {depth:.2} m deep, {bottom_width:.2} m wide at the bottom, walls at {wall_angle:.0}°"
        ),
        Obstacle::Barrier {
            height,
            top_width,
            wall_angle,
        } => format!(
            "a barrier {height:.2} m high, {top_width:.2} m wide on top, walls at {wall_angle:.0}°"
        ),
        Obstacle::Grade { slope, length } => {
            format!("a {:.0} % grade {length:.1} m long", slope * 100.0)
        }
    }
}

/// `--roughness`: an ISO 8608 class (A to H), or a detrended RMS elevation
/// with its unit (`1in`, `25mm`, `0.03m`), at most 0.5 m.
pub fn roughness(s: &str) -> Result<Roughness, String> {
    let what = "a roughness is an ISO 8608 class A to H, or a detrended RMS elevation \
                with its unit, more than 0 and at most 0.5 m: 1in, 25mm, 0.03m";
    let t = s.trim();
    let mut letters = t.chars();
    if let (Some(c), None) = (letters.next(), letters.next())
        && let Some(class) = Iso8608Class::from_letter(c)
    {
        return Ok(Roughness::Class(class));
    }
    let (number, scale) = if let Some(n) = t.strip_suffix("in") {
        (n, 0.0254)
    } else if let Some(n) = t.strip_suffix("mm") {
        (n, 1e-3)
    } else if let Some(n) = t.strip_suffix('m') {
        (n, 1.0)
    } else {
        return Err(format!("`{s}` is no roughness; {what}"));
    };
    let value: f64 = number
        .trim()
        .parse()
        .map_err(|_| format!("`{s}` is no roughness; {what}"))?;
    let rms = value * scale;
    if rms.is_finite() && rms > 0.0 && rms <= 0.5 {
        Ok(Roughness::Rms(rms))
    } else {
        Err(format!("`{s}` is out of range; {what}"))
    }
}

/// `--obstacle`: `half-round:R`, `step:H`, `gap:WIDTH:DEPTH`,
/// `ditch:DEPTH:BOTTOM:ANGLE`, `barrier:HEIGHT:TOP:ANGLE`,
/// `grade:SLOPE:LENGTH` (m; angles in degrees from the horizontal; a
/// slope as rise over run). Each value is range-checked when the course is
/// laid (the profile's builders say which and why).
pub fn obstacle(s: &str) -> Result<Obstacle, String> {
    let usage = "an obstacle is half-round:R, step:H, gap:WIDTH:DEPTH, \
                 ditch:DEPTH:BOTTOM:ANGLE, barrier:HEIGHT:TOP:ANGLE or grade:SLOPE:LENGTH \
                 (m, angles in degrees)";
    let mut fields = s.trim().split(':');
    let kind = fields.next().unwrap_or("");
    let values: Vec<f64> = fields
        .map(|f| {
            f.trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| format!("`{f}` in `{s}` is not a finite number; {usage}"))
        })
        .collect::<Result<_, _>>()?;
    let want = |n: usize| {
        if values.len() == n {
            Ok(())
        } else {
            Err(format!(
                "`{kind}` takes {n} value(s), `{s}` gives {}; {usage}",
                values.len()
            ))
        }
    };
    let obstacle = match kind {
        "half-round" => want(1).map(|()| Obstacle::HalfRound { radius: values[0] }),
        "step" => want(1).map(|()| Obstacle::Step { height: values[0] }),
        "gap" => want(2).map(|()| Obstacle::Gap {
            width: values[0],
            depth: values[1],
        }),
        "ditch" => want(3).map(|()| Obstacle::Ditch {
            depth: values[0],
            bottom_width: values[1],
            wall_angle: values[2],
        }),
        "barrier" => want(3).map(|()| Obstacle::Barrier {
            height: values[0],
            top_width: values[1],
            wall_angle: values[2],
        }),
        "grade" => want(2).map(|()| Obstacle::Grade {
            slope: values[0],
            length: values[1],
        }),
        _ => Err(format!("`{s}` is no obstacle; {usage}")),
    }?;
    // The builders' own checks, now, so a bad value is refused before the
    // run with the parameter and its range.
    obstacle
        .course(1.0, 1.0)
        .map_err(|e| format!("`{s}`: {e}"))?;
    Ok(obstacle)
}
