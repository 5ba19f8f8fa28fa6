//! The bounds a profile and its course pieces are held to.

/// The most points a profile holds: its bucket index counts them in `u32`.
pub const MAX_POINTS: usize = u32::MAX as usize;

/// The largest length of a course piece or width of an obstacle, m
/// (100 km): a bound that catches a unit mistake, not a physical limit.
pub const MAX_LENGTH: f64 = 1e5;

/// The largest height or depth of an obstacle, m.
pub const MAX_HEIGHT: f64 = 100.0;

/// The largest |x| or |z| a course starts at, m.
pub const MAX_COORDINATE: f64 = 1e6;

/// The largest |slope| (rise over run) of a grade: 10, a 1000 % grade
/// (84°).
pub const MAX_SLOPE: f64 = 10.0;
