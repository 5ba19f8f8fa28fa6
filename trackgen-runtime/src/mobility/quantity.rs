//! The names of the quantities the events answer: one owner for each, so
//! that a report, a published figure ([`Published`](super::Published))
//! and a test find the same answer by the same name.

/// The top speed on level ground at full throttle, m/s
/// ([`grade::top_speed`](super::grade::top_speed)).
pub const TOP_SPEED: &str = "top speed on the flat";
/// The steepest grade climbed from a crawl, rise over run
/// ([`grade::steepest`](super::grade::steepest)).
pub const STEEPEST_GRADE: &str = "steepest grade";
/// The highest vertical step climbed, m ([`obstacle::step`](super::obstacle::step)).
pub const HIGHEST_STEP: &str = "highest step";
/// The widest trench crossed, m ([`obstacle::gap`](super::obstacle::gap)).
pub const WIDEST_GAP: &str = "widest gap";
/// The deepest trapezoidal ditch crossed, m
/// ([`obstacle::ditch`](super::obstacle::ditch)).
pub const DEEPEST_DITCH: &str = "deepest ditch";
/// The highest trapezoidal barrier crossed, m
/// ([`obstacle::barrier`](super::obstacle::barrier)).
pub const HIGHEST_BARRIER: &str = "highest barrier";
/// The steepest side slope held driving along it, rise over run
/// ([`side_slope::steepest`](super::side_slope::steepest)).
pub const STEEPEST_SIDE_SLOPE: &str = "steepest side slope";
