//! The ground a vehicle drives on, apart from how the vehicle meets it
//! (`contact`): its shape — a closed form, a table or a polyline with
//! vertical faces ([`Terrain`], [`profile`]), read from and written to
//! files, laid out as obstacle courses ([`profile::Course`]) or generated
//! as random roughness ([`roughness`]), and named as a user names it
//! ([`course`]) — and its strength: the soils of soft ground ([`soil`]).
//! In space, the ground is a height field ([`field`]): a profile per
//! side, a plane at any heading, a grid, a tilt added to any.

pub mod course;
pub mod field;
pub mod grid_file;
pub mod profile;
pub mod roughness;
pub mod soil;
mod surface;

pub use surface::{Terrain, TerrainError};
