//! What a declaration's `tracks` block compiles to: the two sides of a
//! spatial vehicle, each a planar track in its own plane, and the hull
//! with the running gear of both, laid out across the vehicle.

use super::OutOfPlaneInertia;

/// A side of the vehicle, seen from the driver's seat facing forward.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Side {
    /// The left side: its track's plane at `+gauge/2` along the hull's
    /// lateral axis `η` (which points left).
    Left,
    /// The right side, the one the planar declaration describes: its
    /// plane at `−gauge/2`.
    Right,
}

impl Side {
    /// `+1` on the left, `−1` on the right: the sign of the side's offset
    /// along `η`.
    pub fn sign(self) -> f64 {
        match self {
            Side::Left => 1.0,
            Side::Right => -1.0,
        }
    }

    /// Its place in every per-side pair: right 0, left 1.
    pub fn index(self) -> usize {
        match self {
            Side::Right => 0,
            Side::Left => 1,
        }
    }
}

/// The spatial vehicle's layout across its width, as declared: what the
/// hull's and the tracks' [`FloatingTree`](super::FloatingTree)s need
/// beside their generated planar code.
///
/// The hull is the declaration's chassis with the running gear of both
/// sides: the frame (body 0, the whole hull: its declared 3-D mass and
/// inertia), the right side's parts and arms in the planar declaration's
/// order, then the left side's in the same order. Every body of a side
/// turns in that side's track plane.
#[derive(Debug, Clone, PartialEq)]
pub struct SpatialLayout {
    /// The side the planar declaration describes; the other is its
    /// mirror.
    pub declared: Side,
    /// The distance between the two tracks' centre planes, m.
    pub gauge: f64,
    /// The track's width across its plane, m (the shoe's).
    pub shoe_width: f64,
    /// How far a track may slide across the wheels and sprocket before
    /// its centre guides bear on them, m, each way.
    pub guide_play: f64,
    /// Each hull body's offset from the hull's plane along `η`, m: 0 for
    /// the frame, `∓gauge/2` for the right and left sides' bodies.
    pub hull_offsets: Vec<f64>,
    /// Each hull body's inertia about the plane's other two axes.
    pub hull_across: Vec<OutOfPlaneInertia>,
    /// The side of each of the hull's parts, in the order of its
    /// `ChassisModel::PARTS`.
    pub part_sides: Vec<Side>,
    /// Each right-track link's inertia about the plane's other two axes.
    pub right_links: Vec<OutOfPlaneInertia>,
    /// Each left-track link's.
    pub left_links: Vec<OutOfPlaneInertia>,
}

/// A vehicle declared with a `tracks` block: its two sides compiled. The
/// declared side's track is the planar declaration's (`NameTrack`); the
/// mirrored side's is the same type unless the block changes its link
/// count (`NameLeftTrack` or `NameRightTrack`); the hull is `NameHull`,
/// the chassis with both sides' running gear.
///
/// ```ignore
/// use trackgen::spatial::{FloatingTree, SpatialVehicle};
/// let layout = M113::layout();
/// let hull = FloatingTree::new(&M113Hull, layout.hull_across.clone())?
///     .with_offsets(layout.hull_offsets.clone())?;
/// ```
pub trait SpatialVehicle {
    /// Hull coordinates `q_i` (both sides' bodies and the frame, + 2).
    const HULL_DOF: usize;
    /// Right-track coordinates `q_i` (its links + 2).
    const RIGHT_TRACK_DOF: usize;
    /// Left-track coordinates `q_i` (its links + 2).
    const LEFT_TRACK_DOF: usize;
    /// The hull with both sides' running gear (`NameHull`, a
    /// [`ChassisModel<HULL_DOF>`](crate::multibody::ChassisModel)).
    type Hull: Copy + Default + Send + Sync + 'static;
    /// The right track (a
    /// [`TrackModel<RIGHT_TRACK_DOF>`](crate::multibody::TrackModel)).
    type RightTrack: Copy + Default + Send + Sync + 'static;
    /// The left track (a
    /// [`TrackModel<LEFT_TRACK_DOF>`](crate::multibody::TrackModel)).
    type LeftTrack: Copy + Default + Send + Sync + 'static;

    /// The layout across the vehicle, as declared.
    fn layout() -> SpatialLayout;
}
