//! Vehicles shipped with trackgen, declared with [`model!`](macro@crate::model)
//! like any user's: start from one.

pub mod m113;
pub mod marder;
