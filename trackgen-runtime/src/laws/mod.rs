//! The force laws of the model, each the one owner of its formula: what
//! force it gives, the elastic energy it stores and the power it
//! dissipates, from one call, so that a vehicle's energy books balance by
//! construction (`motor work = ΔE + dissipated`).
//!
//! * [`penalty`]: the cut closing joint's spring-damper (paper Fig. 5).
//! * [`contact`]: normal laws (Hunt-Crossley, Kelvin-Voigt) and
//!   regularised Coulomb friction;
//! * [`stiction`]: friction with stiction, an elastic tangential contact
//!   with a Coulomb limit, its deflection a state; [`stiction_plane`] the
//!   same law in the ground's plane (two components, isotropic).
//! * [`torsion`]: the torsion spring-damper of a sprung arm.
//!
//! The laws know nothing of bodies or geometry: they take a deflection
//! and its rate and give a [`Response`]. The soil's laws
//! ([`crate::terrain::soil`]) are kept with the soil they describe.

pub mod contact;
pub mod penalty;
pub mod stiction;
pub mod stiction_plane;
pub mod torsion;

pub use contact::{Friction, NormalLaw};
pub use penalty::PenaltyJoint;
pub use stiction::{Stiction, TangentialResponse, TangentialSlopes};
pub use stiction_plane::{PlaneTangentialResponse, PlaneTangentialSlopes};
pub use torsion::TorsionSpring;

/// What a law gives at a state: its force (a scalar along the law's own
/// direction, or a vector), the elastic energy it stores (J) and the
/// power it dissipates (W, never negative for a passive law).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Response<F> {
    /// The force, N (or moment, N m).
    pub force: F,
    /// Elastic energy stored, J.
    pub potential: f64,
    /// Power dissipated, W.
    pub dissipation: f64,
}

/// A law's parameter out of its range: `name` is the field, `value` what
/// it held, `allowed` the range in words.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("`{name}` = {value} is out of range: it must be {allowed}")]
pub struct ParameterError {
    /// The parameter's field name.
    pub name: &'static str,
    /// Its value.
    pub value: f64,
    /// The allowed range, in words.
    pub allowed: &'static str,
}

impl ParameterError {
    /// `Ok` if `value` is finite and at least `low` (strictly above it if
    /// `strict`), else the error naming the parameter.
    pub(crate) fn check(
        name: &'static str,
        value: f64,
        low: f64,
        strict: bool,
    ) -> Result<(), ParameterError> {
        let ok = value.is_finite() && if strict { value > low } else { value >= low };
        if ok {
            return Ok(());
        }
        let allowed = match (low == 0.0, strict) {
            (true, true) => "positive and finite",
            (true, false) => "zero or more, and finite",
            _ => "finite",
        };
        Err(ParameterError {
            name,
            value,
            allowed,
        })
    }
}
