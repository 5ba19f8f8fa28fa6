//! The ground's shear on one stretch of a track's ground run sliding about
//! its instantaneous centre, in closed form.
//!
//! A stretch of the run carries the normal load `q` per unit length
//! (N/m), uniform over its length, and lies at lateral distance `d` from
//! the track's instantaneous centre; `ξ` is a point's longitudinal
//! distance from the centre. Sliding about the centre at yaw rate `ω`,
//! the point's velocity over the ground is `ω (−d, ξ)`, and the ground's
//! Coulomb friction on it is `−μ q sgn(ω) (−d, ξ)/ρ` per unit length, with
//! `ρ = √(ξ² + d²)` (isotropic: the force opposes the sliding, whatever
//! its direction). Its integrals over `ξ` from `a` to `b` are elementary
//! (`A(ξ) = asinh(ξ/|d|)`):
//!
//! - `∫ d/ρ dξ = d [A]`, `∫ ξ/ρ dξ = [ρ]`,
//! - `∫ ξ²/ρ dξ = ½ [ξρ − d² A]` (the moment of the force across),
//! - `∫ ρ dξ = ½ [ξρ + d² A]` (the power the friction dissipates),
//!
//! and so are their derivatives in `d` (`∫ ξ²/ρ³ dξ = [A − ξ/ρ]`,
//! `∫ ξd/ρ³ dξ = −[d/ρ]`), which give the steady turn's Newton method its
//! exact Jacobian. On the centre's own line (`d = 0`) the terms in `d`
//! vanish and `ρ = |ξ|`.

/// The ground's shear on a stretch of the run, per `μ q sgn(ω)` (so
/// multiply each term by it): the forces along the track and across it,
/// the moment of the force across about the centre's cross line, and the
/// dissipation (per `μ q |ω|`); and the derivatives of the first three in
/// the stretch's lateral distance from the centre, `d`. At `d = 0` the
/// derivative of `along` is infinite (`∫ dξ/|ξ|`) where the stretch
/// reaches `ξ = 0`: the solver never evaluates there.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(super) struct UnitShear {
    /// `∫ d/ρ dξ`: the force along the track, m.
    pub along: f64,
    /// `−∫ ξ/ρ dξ`: the force across the track, m.
    pub across: f64,
    /// `−∫ ξ²/ρ dξ`: the moment of the force across the track about the
    /// centre's cross line, m².
    pub moment: f64,
    /// `∫ ρ dξ`: the dissipation, m².
    pub dissipation: f64,
    /// `∂along/∂d`, dimensionless.
    pub along_d: f64,
    /// `∂across/∂d`, dimensionless.
    pub across_d: f64,
    /// `∂moment/∂d`, m.
    pub moment_d: f64,
}

/// [`UnitShear`] over `ξ ∈ [a, b]` at lateral distance `d` (all m).
pub(super) fn unit_shear(a: f64, b: f64, d: f64) -> UnitShear {
    let at = |xi: f64| {
        let rho = xi.hypot(d);
        // asinh(ξ/|d|), written so that d → 0 is finite where multiplied
        // by d (d·asinh(ξ/|d|) → 0 like d ln|d|).
        let area = if d == 0.0 {
            0.0
        } else {
            (xi / d.abs()).asinh()
        };
        let xi_over_rho = if rho == 0.0 { 0.0 } else { xi / rho };
        let d_over_rho = if rho == 0.0 { 0.0 } else { d / rho };
        UnitShear {
            along: d * area,
            across: -rho,
            moment: -0.5 * (xi * rho - d * d * area),
            dissipation: 0.5 * (xi * rho + d * d * area),
            along_d: area - xi_over_rho,
            across_d: -d_over_rho,
            moment_d: d * (area - xi_over_rho),
        }
    };
    let (lo, hi) = (at(a), at(b));
    UnitShear {
        along: hi.along - lo.along,
        across: hi.across - lo.across,
        moment: hi.moment - lo.moment,
        dissipation: hi.dissipation - lo.dissipation,
        along_d: hi.along_d - lo.along_d,
        across_d: hi.across_d - lo.across_d,
        moment_d: hi.moment_d - lo.moment_d,
    }
}

/// The integrands of [`UnitShear`]'s `along`, `across` and `moment` at
/// `ξ` (per unit length): what the stretch's ends contribute to their
/// derivatives in the centre's longitudinal position.
pub(super) fn unit_density(xi: f64, d: f64) -> [f64; 3] {
    let rho = xi.hypot(d);
    if rho == 0.0 {
        return [0.0; 3];
    }
    [d / rho, -xi / rho, -xi * xi / rho]
}
