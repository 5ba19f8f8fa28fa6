//! Sprung arms of a chassis: road wheels on trailing arms with torsion
//! springs and dampers, an idler on a tensioner arm (see [`ArmSpring`]).
//!
//! The generic functions use the springs compiled into the chassis model
//! ([`ChassisModel::PARTS`]); the `*_of` functions take any list of
//! springs, so that a vehicle can run with rates set at run time
//! ([`VehicleConfig::arms`](crate::vehicle::VehicleConfig::arms)).

use nalgebra::SVector;

use crate::model::{ArmSpring, BodyLoad, ChassisModel};

/// The arm's angle `φ` from its design position relative to the chassis,
/// rad, and its rate, rad/s.
fn deflection<const D: usize>(
    arm: &ArmSpring,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
) -> (f64, f64) {
    (q[2 + arm.body] - q[2], qd[2 + arm.body] - qd[2])
}

/// The springs compiled into `M`.
pub fn declared_arms<M: ChassisModel<D>, const D: usize>()
-> impl Iterator<Item = &'static ArmSpring> {
    M::PARTS.iter().filter_map(|p| p.arm.as_ref())
}

/// Adds every arm's torque `τ = preload − k φ − c φ̇` to its load, and `−τ`
/// to the chassis frame's.
///
/// # Panics
/// If `loads` does not have one entry per body (a programming error).
pub fn add_arm_torques<M: ChassisModel<D>, const D: usize>(
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &mut [BodyLoad],
) {
    assert_eq!(loads.len(), M::BODIES, "one load per body");
    add_arm_torques_of(declared_arms::<M, D>(), q, qd, loads);
}

/// [`add_arm_torques`] for the springs `arms`.
///
/// # Panics
/// If an arm's body has no load (a programming error).
pub fn add_arm_torques_of<'a, const D: usize>(
    arms: impl IntoIterator<Item = &'a ArmSpring>,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &mut [BodyLoad],
) {
    for arm in arms {
        let (phi, rate) = deflection(arm, q, qd);
        let torque = arm.preload - arm.stiffness * phi - arm.damping * rate;
        loads[arm.body].moment += torque;
        loads[0].moment -= torque;
    }
}

/// The springs' potential energy `Σ ½ k φ² − preload φ`, J (zero at the
/// design position), so that the spring torques are its negative gradient.
pub fn arm_energy<M: ChassisModel<D>, const D: usize>(q: &SVector<f64, D>) -> f64 {
    arm_energy_of(declared_arms::<M, D>(), q)
}

/// [`arm_energy`] for the springs `arms`.
pub fn arm_energy_of<'a, const D: usize>(
    arms: impl IntoIterator<Item = &'a ArmSpring>,
    q: &SVector<f64, D>,
) -> f64 {
    let zero = SVector::<f64, D>::zeros();
    arms.into_iter()
        .map(|arm| {
            let (phi, _) = deflection(arm, q, &zero);
            0.5 * arm.stiffness * phi * phi - arm.preload * phi
        })
        .sum()
}

/// The power the arm dampers dissipate, `Σ c φ̇²`, W.
pub fn arm_dissipation<M: ChassisModel<D>, const D: usize>(qd: &SVector<f64, D>) -> f64 {
    arm_dissipation_of(declared_arms::<M, D>(), qd)
}

/// [`arm_dissipation`] for the springs `arms`.
pub fn arm_dissipation_of<'a, const D: usize>(
    arms: impl IntoIterator<Item = &'a ArmSpring>,
    qd: &SVector<f64, D>,
) -> f64 {
    arms.into_iter()
        .map(|arm| {
            let rate = qd[2 + arm.body] - qd[2];
            arm.damping * rate * rate
        })
        .sum()
}
