//! What a compiled model is: the traits generated code implements, and the
//! run-time description of the same body tree.

mod closing;
mod description;
mod load;
mod traits;

pub use closing::ClosingJoint;
pub use description::{
    ArmSpring, BodyDescription, ChassisPart, Closure, LoopJoint, PartKind, PitchError,
    TreeDescription,
};
pub use load::BodyLoad;
pub use traits::{ChassisModel, RecursiveModel, TrackModel};
