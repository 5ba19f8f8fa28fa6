//! A planar tree floating in space: a track of a spatial vehicle, or its
//! hull with the running gear of both sides (the guide's "The
//! formulation", §6), after Choi, Lee & Shabana, "Spatial dynamics of
//! multibody tracked vehicles" (*Vehicle System Dynamics* 29, 1998), who
//! keep each track a closed chain of pinned links whose pins are
//! parallel, so that the chain stays in one plane while that plane moves
//! in space. The hull's running gear turns about axes parallel too (the
//! arms' pivots, the wheels' axles), each side in its own plane half a
//! gauge from the hull's: a body may sit at a constant offset along the
//! plane's normal.
//!
//! **Coordinates** (written for a chain; a tree's root plays link 1's
//! part). The chain's plane is a frame `P` whose axes are `ξ`
//! (forward, kept horizontal), `η` (the pins' axis, normal to the plane)
//! and `ζ`; its orientation is `A = R_z(ψ) R_x(φ)`, a yaw `ψ` and a roll
//! `φ` (a pitch of the plane is a rotation in it, which the links' angles
//! already carry). The coordinates are link 1's centroid in the world
//! (`r¹`, 3), the yaw and roll (2) and the links' absolute angles in the
//! plane (`θ¹ … θⁿ`): the planar chain's `q_i` with its in-plane place
//! moved into `r¹`, three coordinates more than in the plane. The
//! parameterisation is singular where the plane lies flat (`φ = ±90°`).
//!
//! **Velocities** are quasi-velocities chosen so that the mass matrix is
//! block diagonal: in the plane, link 1's velocity in `P`'s components
//! `(v_ξ, v_ζ)` and the links' angular rates relative to the plane's own
//! turning about `η`, `θ̇ᵏ − ω_η` — the planar chain's `q̇_i`, whose mass
//! matrix is the planar `M_i` unchanged (the generated code); out of the
//! plane, `w = (v_η, ω_ξ, ω_ζ)`, link 1's velocity across the plane and
//! the plane's angular velocity about `ξ` and `ζ` (`ω = (φ̇, ψ̇ sin φ,
//! ψ̇ cos φ)` in `P`), with a 3 × 3 mass matrix summed in O(n). A link's
//! velocity in the plane depends only on the first set, its velocity
//! across the plane and its angular velocity about `ξ` and `ζ` only on
//! the second, and its spin about `η` only on the first: the kinetic
//! energy is the planar chain's plus `½ Σ mᵏ (v_η + ω_ζ ξᵏ − ω_ξ ζᵏ)²`
//! plus the links' rotation about the plane's axes. A body offset by `e`
//! along `η` moves in the plane at `e (−ω_ζ, ω_ξ)` more, which couples
//! the two sets: the out-of-plane equations then take the Schur
//! complement `M_w − Cᵀ M_i⁻¹ C`, `M_i⁻¹ C` by the planar route under
//! two more sets of loads (still O(n)).
//!
//! **Equations of motion** (Newton–Euler per link in `P`'s components,
//! `a = V̇ + ω × V`, `τ = Ḣ + ω × H`, projected on the quasi-velocities):
//! the planar chain's equations, solved by its own generated O(n) route,
//! under each link's loads in the plane plus the inertial terms the
//! plane's motion adds; and the 3 × 3 out-of-plane equations. Gravity
//! (the declared planar gravity's size, pointing down the world's `z`)
//! has components `(0, −g sin φ, −g cos φ)` in `P`. The links' inertia
//! across the plane is declared per link ([`OutOfPlaneInertia`]); each
//! link is symmetric about the chain's plane (no products of inertia with
//! `η`).
//!
//! `tests/it/spatial_tree.rs` holds the accelerations to a dense route
//! written independently: each link's pose from the coordinates with
//! plain rotation matrices, its Jacobians and bias accelerations by
//! Taylor arithmetic, `Jᵀ M J` and Newton–Euler's right-hand side summed
//! and solved in the coordinates' own rates.

mod layout;
mod tree;

pub use layout::{Side, SpatialLayout, SpatialVehicle};
pub use tree::{FloatingTree, PlaneMotion, PlanePose, PlaneRates, SpatialLoad, WorldMotion};

use nalgebra::Matrix3;

/// A link's inertia about its own axes in the chain's plane, kg m²: along
/// the link (`x`), normal to it in the plane (`z`), and their product;
/// its inertia about the pin axis is the planar model's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OutOfPlaneInertia {
    /// About the link's `x` axis (along it), kg m².
    pub xx: f64,
    /// About the link's `z` axis (in the plane, across it), kg m².
    pub zz: f64,
    /// The product `I_xz`, kg m².
    pub xz: f64,
}

impl OutOfPlaneInertia {
    /// A body of `mass` (kg) whose planar section has `inertia` (kg m²)
    /// about the pin axis, spread evenly across `width` (m) of the plane's
    /// normal: `I/2 + m w²/12` about both in-plane axes, no product.
    /// Exact for any body of revolution about that axis (a solid or hollow
    /// wheel: `m r²/4 + m w²/12` for a solid one), a thin lamina's
    /// perpendicular-axis rule `I/2` at zero width, and the declaration's
    /// default for bodies whose figures are not declared (for a link or an
    /// arm, a stated approximation).
    pub fn extruded(mass: f64, inertia: f64, width: f64) -> OutOfPlaneInertia {
        let across = inertia / 2.0 + mass * width * width / 12.0;
        OutOfPlaneInertia {
            xx: across,
            zz: across,
            xz: 0.0,
        }
    }

    /// A uniform plate of `mass` (kg), `length` along the link, `width`
    /// across the plane and `thickness` in it (m): `m (w² + t²)/12` about
    /// `x`, `m (l² + w²)/12` about `z`, no product.
    pub fn plate(mass: f64, length: f64, width: f64, thickness: f64) -> OutOfPlaneInertia {
        OutOfPlaneInertia {
            xx: mass * (width * width + thickness * thickness) / 12.0,
            zz: mass * (length * length + width * width) / 12.0,
            xz: 0.0,
        }
    }
}

/// The plane's orientation `A = R_z(ψ) R_x(φ)`: its columns are the
/// plane's `ξ`, `η` and `ζ` axes in the world.
pub fn plane_rotation(yaw: f64, roll: f64) -> Matrix3<f64> {
    let (sy, cy) = yaw.sin_cos();
    let (sr, cr) = roll.sin_cos();
    Matrix3::new(cy, -sy * cr, sy * sr, sy, cy * cr, -cy * sr, 0.0, sr, cr)
}

/// Why a spatial chain cannot be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SpatialError {
    /// One out-of-plane inertia per body is needed.
    #[error("the tree has {bodies} bodies but {given} out-of-plane inertias were given")]
    Inertias {
        /// The tree's bodies.
        bodies: usize,
        /// The inertias given.
        given: usize,
    },
    /// An inertia is not positive definite (`xx > 0`, `zz > 0`,
    /// `xx zz > xz²`), or not finite.
    #[error("body {body}'s out-of-plane inertia is not positive definite: {inertia:?}")]
    Inertia {
        /// The body, 0-based.
        body: usize,
        /// What was given.
        inertia: OutOfPlaneInertia,
    },
    /// One offset per body is needed.
    #[error("the tree has {bodies} bodies but {given} offsets were given")]
    Offsets {
        /// The tree's bodies.
        bodies: usize,
        /// The offsets given.
        given: usize,
    },
    /// An offset is not finite.
    #[error("body {body}'s offset across the plane is not finite: {offset}")]
    Offset {
        /// The body, 0-based.
        body: usize,
        /// What was given, m.
        offset: f64,
    },
    /// One side per part of the hull is needed.
    #[error("the hull has {parts} parts but {given} sides were given")]
    Sides {
        /// The hull's parts.
        parts: usize,
        /// The sides given.
        given: usize,
    },
    /// A side's track has links of different lengths: its sprocket has no
    /// one rolling radius.
    #[error("the {side:?} track has no single pitch: {source}")]
    Pitch {
        /// The side.
        side: Side,
        /// Why.
        source: crate::multibody::PitchError,
    },
    /// A contact law's parameter is out of its range.
    #[error("the law of the {pair}: {source}")]
    Law {
        /// Which contacts: "ground", "rims", "teeth" or "guides".
        pair: &'static str,
        /// Why.
        source: crate::laws::ParameterError,
    },
    /// The soft soil's parameters make no soil, or the shoe has no width
    /// for it to bear.
    #[error("the soil: {0}")]
    Soil(crate::terrain::soil::SoilError),
    /// The planar model's gravity must point down its `y` axis, which
    /// becomes the world's vertical.
    #[error("the planar gravity must be (0, −g), got ({x}, {y}) m/s²")]
    Gravity {
        /// Its x component, m/s².
        x: f64,
        /// Its y component, m/s².
        y: f64,
    },
}
