//! Pictures of trackgen runs, apart from the physics: the vehicle at one
//! moment on its ground as a still SVG picture ([`vehicle`]), the run's
//! time histories ([`plots`]) and a self-contained page that plays the
//! run ([`animation`]; in 3-D, [`spatial_animation`]). The geometry they draw is the runtime's
//! `trackgen::scene` (a [`Frame`](trackgen::scene::Frame) of the vehicle
//! from its recorded coordinates, the [`Ground`](trackgen::scene::Ground)
//! it drove on); the main job, the mobility report and a user's own code
//! draw through this crate alike.

#![warn(missing_docs)]

pub mod animation;
pub mod plots;
pub mod spatial_animation;
pub mod vehicle;
