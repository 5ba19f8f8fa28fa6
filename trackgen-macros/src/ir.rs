//! The validated model: what [`crate::lower`] produces and
//! [`crate::codegen`] consumes. Numbers are [`Num`]s, already checked where
//! the macro can evaluate them; checks it cannot do are [`ConstCheck`]s that
//! rustc performs at compile time.

use std::rc::Rc;

use proc_macro2::{Span, TokenStream};
use syn::{Attribute, Ident, Visibility};

use crate::num::{ConstPool, Num, Vec2};

/// Everything one invocation declares.
pub struct Model {
    pub items: Vec<Item>,
}

/// A declared type.
pub struct Item {
    pub attrs: Vec<Attribute>,
    pub vis: Visibility,
    pub name: Ident,
    pub kind: ItemKind,
    /// Checks of constant expressions, for rustc.
    pub checks: Vec<ConstCheck>,
    /// The item's named constants: its constant expressions, each once.
    pub consts: Rc<ConstPool>,
}

pub enum ItemKind {
    Track(Track),
    Vehicle(Box<Vehicle>),
}

/// A chain of links, possibly closed (formulation §1, §2).
pub struct Track {
    pub links: Vec<Link>,
    pub closure: Closure,
    pub gravity: Vec2,
    /// The chain as a tree (link `i` hangs from link `i − 1`), lowered from
    /// `links` ([`crate::lower`]).
    pub bodies: Vec<TreeBody>,
}

/// A body of a tree in recursive coordinates: the track's chain and the
/// chassis are both lowered to these (formulation §1, §3). Body `b` hangs from its
/// parent by a revolute joint: `Rᵇ = Rᵖ + Aᵖ at_parent − Aᵇ at_self`.
#[derive(Clone)]
pub struct TreeBody {
    /// Names the body's locals in generated code: `s_{tag}`, `rx_{tag}`, …
    pub tag: String,
    pub mass: Num,
    pub inertia: Num,
    pub parent: Option<usize>,
    /// Joint point on the parent, parent frame, m.
    pub at_parent: Vec2,
    /// Joint point on this body, own frame, m (zero for the root).
    pub at_self: Vec2,
}

/// One track link (formulation §1).
#[derive(Clone)]
pub struct Link {
    pub mass: Num,
    pub inertia: Num,
    /// `ū1`: the joint to the previous link, link frame, m.
    pub u1: Vec2,
    /// `ū2`: the joint to the next link, link frame, m.
    pub u2: Vec2,
}

#[derive(Clone)]
pub enum Closure {
    Open,
    Partitioned,
    Penalty { stiffness: Num, damping: Num },
}

/// A chassis with its parts, and its track.
pub struct Vehicle {
    pub gravity: Vec2,
    /// The driver's seat on the frame, m, from the chassis centroid in the
    /// frame's axes (the centroid when not declared).
    pub seat: Vec2,
    /// The hull's outline on the frame, m, from the chassis centroid, as
    /// declared (empty: no hull).
    pub hull: Vec<Vec2>,
    pub parts: Vec<Part>,
    pub track: Track,
    /// The chassis as a tree: the frame (body 0), then each part preceded
    /// by its arm if it has one.
    pub chassis: Vec<TreeBody>,
    /// The body index of each part and of its arm, in `chassis`.
    pub part_bodies: Vec<(usize, Option<usize>)>,
    /// What makes the vehicle run; `None` without a `shoe` section (the
    /// dynamics only).
    pub running: Option<Running>,
    /// The spatial vehicle's two sides, if a `tracks` block is declared.
    pub tracks: Option<Tracks>,
}

/// A `tracks` block: the two sides of a spatial vehicle. One side is the
/// planar declaration (the right unless `side: left`); the other its
/// mirror, with the block's overrides (its link count, its parts'
/// places).
pub struct Tracks {
    /// Centre plane to centre plane, m.
    pub gauge: Num,
    /// The shoe's width, m (the `shoe` section's).
    pub shoe_width: Num,
    /// The centre guide's lateral play each way, m.
    pub guide_play: Num,
    /// The hull's tree: the frame (the whole hull), then the right side's
    /// parts and arms, then the left's, as [`Vehicle::chassis`] is built.
    pub hull: Vec<TreeBody>,
    /// The hull's parts, named `right_…` and `left_…`.
    pub parts: Vec<Part>,
    /// The body index of each of `parts` and of its arm, in `hull`.
    pub part_bodies: Vec<(usize, Option<usize>)>,
    /// Whether each of `parts` is on the left.
    pub left: Vec<bool>,
    /// Each hull body's offset along the lateral axis (left positive), m.
    pub offsets: Vec<Num>,
    /// Each hull body's inertia across the plane.
    pub hull_across: Vec<Across>,
    /// Each right-track link's.
    pub right_links: Vec<Across>,
    /// Each left-track link's.
    pub left_links: Vec<Across>,
    /// Whether the declaration describes the left side.
    pub declared_left: bool,
    /// The mirrored side's track, when its link count differs from the
    /// declared one's.
    pub mirror_track: Option<Track>,
}

/// A body's inertia about the plane's in-plane axes, kg m²: along `x`,
/// along the plane's normal-in-plane `z`, and the product.
#[derive(Clone)]
pub struct Across {
    pub xx: Num,
    pub zz: Num,
    pub xz: Num,
}

/// The declared contact and drive of a vehicle: what `Name::config`
/// returns. Nothing here enters the mass matrix.
pub struct Running {
    pub shoe: Shoe,
    /// The sprocket's declared profile; `None` fields take the scaled
    /// default (`ToothProfile::scaled`).
    pub tip_radius: Option<Num>,
    pub gap_radius: Option<Num>,
    pub gap_centre: Option<Num>,
    /// `ground`, `wheels`, `sprocket`.
    pub contact: [ContactPair; 3],
    /// Speed drive gains, N m s/rad and N m/rad, and torque limit, N m.
    pub proportional: Num,
    pub integral: Num,
    pub max_torque: Num,
    /// The declared `powertrain`, if any.
    pub powertrain: Option<Powertrain>,
}

/// A declared powertrain: the runtime's `Driveline`, field for field
/// (tables as `(x, y)` pairs, lock-up ranges 0-based).
pub struct Powertrain {
    /// Full-load torque, N m, against engine speed, rad/s.
    pub engine: Vec<(Num, Num)>,
    /// The converter's capacity factor against its speed ratio.
    pub capacity: Vec<(Num, Num)>,
    /// The converter's torque ratio against its speed ratio.
    pub torque_ratio: Vec<(Num, Num)>,
    /// The ranges' reductions, lowest range first.
    pub ranges: Vec<Num>,
    /// The ranges that lock up, 0-based.
    pub lockup: Vec<usize>,
    pub lockup_speed_ratio: Num,
    pub final_drive: Num,
    pub gearbox_efficiency: Num,
    pub final_drive_efficiency: Num,
    pub share: Num,
    /// The shift schedule: upshift and downshift speeds per range (rad/s)
    /// and the shift time (s); `None`: shifted ideally.
    pub shift: Option<(Vec<Num>, Vec<Num>, Num)>,
    /// The reverse range's reduction, if declared.
    pub reverse: Option<Num>,
    /// The engine's inertia, drag, governor and lock-up clutch, if
    /// declared: its speed a state of the run.
    pub dynamics: Option<EngineDynamics>,
    /// The steer unit's minimum steer ratios, one per range; empty: none.
    pub steer_ratios: Vec<Num>,
}

/// A declared engine whose speed is a state: the runtime's
/// `EngineDynamics`, its optional figures `None` for the runtime's
/// defaults.
pub struct EngineDynamics {
    /// kg m².
    pub inertia: Num,
    /// The torque at no fuel, N m, against engine speed, rad/s.
    pub drag: Vec<(Num, Num)>,
    /// s.
    pub governor_time: Option<Num>,
    /// N m.
    pub lockup_capacity: Option<Num>,
    /// N m/rad.
    pub lockup_stiffness: Option<Num>,
    /// N m s/rad.
    pub lockup_damping: Option<Num>,
}

/// A shoe's contact features, link frame, m.
pub struct Shoe {
    pub ground_points: Vec<Vec2>,
    /// Distance from the pitch line to the inner running face.
    pub inner_offset: Num,
    pub pins: Vec<Vec2>,
    pub pin_radius: Num,
    /// The track's width, m, if declared (soft soil needs it).
    pub width: Option<Num>,
}

/// A declared contact pair: a normal law replacing the fitted one, and
/// friction fields replacing the fitted ones (on the ground, `slip` asks
/// for regularised friction, the tangential keys tune stiction).
#[derive(Default)]
pub struct ContactPair {
    pub normal: Option<NormalLaw>,
    pub mu: Option<Num>,
    pub slip: Option<Num>,
    /// N/m.
    pub tangential_stiffness: Option<Num>,
    /// N s/m.
    pub tangential_damping: Option<Num>,
}

pub enum NormalLaw {
    /// N/mⁿ, n, s/m.
    HuntCrossley {
        stiffness: Num,
        exponent: Num,
        chi: Num,
    },
    /// N/m, N s/m.
    KelvinVoigt { stiffness: Num, damping: Num },
}

#[derive(Clone, Copy, PartialEq, Eq)]
pub enum PartKind {
    Sprocket,
    Idler,
    RoadWheel,
    Roller,
}

impl PartKind {
    pub fn keyword(self) -> &'static str {
        match self {
            PartKind::Sprocket => "sprocket",
            PartKind::Idler => "idler",
            PartKind::RoadWheel => "road_wheel",
            PartKind::Roller => "roller",
        }
    }

    pub fn from_keyword(s: &str) -> Option<PartKind> {
        [
            PartKind::Sprocket,
            PartKind::Idler,
            PartKind::RoadWheel,
            PartKind::Roller,
        ]
        .into_iter()
        .find(|k| k.keyword() == s)
    }
}

/// A body pinned to the chassis at its own centre.
#[derive(Clone)]
pub struct Part {
    pub name: Ident,
    pub kind: PartKind,
    /// Pin position relative to the chassis centroid, chassis frame, m.
    pub at: Vec2,
    pub mass: Num,
    pub inertia: Num,
    pub radius: Num,
    pub teeth: u32,
    /// The trailing arm or swing arm carrying the part, if any.
    pub arm: Option<Arm>,
}

/// An arm pinned to the chassis at `pivot`, carrying a part at its other
/// end, sprung by a torsion spring-damper about the pivot. Its centroid is
/// taken midway between pivot and part.
#[derive(Clone)]
pub struct Arm {
    /// Pivot relative to the chassis centroid, chassis frame, m.
    pub pivot: Vec2,
    pub mass: Num,
    pub inertia: Num,
    /// N m/rad.
    pub stiffness: Num,
    /// N m s/rad.
    pub damping: Num,
    /// N m, counter-clockwise on the arm at its design angle.
    pub preload: Num,
    /// The angles (rad from the design position) the assembly may set the
    /// arm to, to take up a track's slack: (low, high), low ≤ 0 ≤ high.
    pub travel: Vec2,
}

/// A property of constant expressions that the macro cannot evaluate, for
/// rustc to assert at compile time; the error points at `span`.
pub struct ConstCheck {
    pub span: Span,
    pub condition: TokenStream,
    pub message: String,
}
