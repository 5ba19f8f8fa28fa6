//! The sprung arms of a chassis as one force element: road wheels on
//! trailing arms with torsion springs and dampers, an idler on a
//! tensioner arm ([`ArmSpring`], its law [`TorsionSpring`](crate::laws::TorsionSpring)).

use nalgebra::SVector;

use crate::multibody::{ArmSpring, BodyLoad, ChassisModel};

/// The springs compiled into the chassis `M`, in the order of its parts.
pub fn declared<M: ChassisModel<D>, const D: usize>() -> Vec<ArmSpring> {
    M::PARTS.iter().filter_map(|p| p.arm).collect()
}

/// The arm's angle `φ` from its design position relative to the chassis,
/// rad, and its rate, rad/s.
#[inline]
fn deflection<const D: usize>(
    arm: &ArmSpring,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
) -> (f64, f64) {
    (q[2 + arm.body] - q[2], qd[2 + arm.body] - qd[2])
}

/// What the arms store and dissipate at a state: `Σ ½ k φ² − preload φ`
/// (J, zero at the design positions, so that the spring torques are its
/// negative gradient) and `Σ c φ̇²` (W).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ArmBooks {
    /// J.
    pub potential: f64,
    /// W.
    pub dissipation: f64,
}

/// Adds every arm's torque `τ = preload − k φ − c φ̇` to its body's load
/// and `−τ` to the chassis frame's, and returns what the arms store and
/// dissipate.
///
/// # Panics
/// If an arm's body has no load (a programming error).
pub fn apply<const D: usize>(
    arms: &[ArmSpring],
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &mut [BodyLoad],
) -> ArmBooks {
    // From −0.0, as `Iterator::sum` of floats starts.
    let (mut energy, mut dissipation) = (-0.0, -0.0);
    for arm in arms {
        let (phi, rate) = deflection(arm, q, qd);
        let response = arm.spring.respond(phi, rate);
        loads[arm.body].moment += response.force;
        loads[0].moment -= response.force;
        energy += response.potential;
        dissipation += response.dissipation;
    }
    ArmBooks {
        potential: energy,
        dissipation,
    }
}
