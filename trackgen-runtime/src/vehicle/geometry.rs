//! What a vehicle touches the world with: its shoes' contact features and
//! its sprocket's teeth, compiled from the declaration.

use crate::contact::ShoeGeometry;
use crate::contact::sprocket::ToothProfile;

/// A vehicle's contact geometry, compiled with its masses from the
/// declaration's `shoe` and sprocket: what its shoes touch the world with
/// and what its sprocket's teeth are. Fixed for the vehicle (the laws that
/// act on it are in [`VehicleConfig`](super::VehicleConfig)).
#[derive(Debug, Clone, PartialEq)]
pub struct Geometry {
    /// The shoes' contact features.
    pub shoe: ShoeGeometry,
    /// The sprocket's teeth, from its declared `teeth` (the same number
    /// as its [`ChassisPart::teeth`](crate::multibody::ChassisPart::teeth)) and radii.
    pub sprocket: ToothProfile,
}
