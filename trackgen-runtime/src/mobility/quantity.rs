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
/// The smallest radius turned at a crawl at full steer, m
/// ([`turning::smallest_radius`](super::turning::smallest_radius)).
pub const SMALLEST_TURNING_RADIUS: &str = "smallest turning radius";
/// That turn's radius without slip, m
/// ([`SmallestTurn::kinematic`](super::turning::SmallestTurn::kinematic)).
pub const RADIUS_WITHOUT_SLIP: &str = "radius without slip";
/// The pivot turn's yaw rate at the crawl's belt speeds, rad/s
/// ([`turning::pivot`](super::turning::pivot)).
pub const PIVOT_YAW_RATE: &str = "pivot turn's yaw rate";
/// The pivot turn's power at both sprockets, kW
/// ([`turning::pivot`](super::turning::pivot)).
pub const PIVOT_POWER: &str = "pivot turn's power";
/// The fastest steady turn held on a circle, m/s
/// ([`cornering::fastest`](super::cornering::fastest)).
pub const CORNERING_SPEED: &str = "cornering speed";
