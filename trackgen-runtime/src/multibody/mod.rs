//! What a compiled model is: the traits generated code implements, the
//! run-time description of the same body tree, the loads on its bodies,
//! the closing joint, a track's tensions from its joint forces, and why
//! its dynamics could not be evaluated.

mod closing;
mod description;
mod error;
mod load;
mod tension;
mod traits;

pub use closing::ClosingJoint;
pub use description::{
    ArmSpring, BodyDescription, ChassisPart, Closure, LoopJoint, PartKind, PitchError,
    TreeDescription,
};
pub use error::DynamicsError;
pub use load::BodyLoad;
pub use tension::joint_tensions;
pub use traits::{ChassisModel, RecursiveModel, TrackModel};
