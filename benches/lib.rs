//! What the benches share: the tracks and the state they are timed at, a
//! vehicle driven to a moving state.

use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::nalgebra::{DVector, SVector};
use trackgen::system::Simulated;
use trackgen::vehicle::{Vehicle, VehicleConfig, build};

trackgen::model! {
    /// An M113-like closed track of 8 shoes.
    pub track Track8 { links: 8, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } }
    /// 16 shoes.
    pub track Track16 { links: 16, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } }
    /// 32 shoes.
    pub track Track32 { links: 32, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } }
    /// 64 shoes.
    pub track Track64 { links: 64, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } }
    /// 128 shoes.
    pub track Track128 { links: 128, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } }
}

/// A ring (the loop closes) with every angle distinct, turning and moving.
pub fn state<const D: usize>() -> (SVector<f64, D>, SVector<f64, D>) {
    let n = (D - 2) as f64;
    let q = SVector::from_fn(|i, _| {
        if i < 2 {
            0.3
        } else {
            2.0 * std::f64::consts::PI * (i - 2) as f64 / n
        }
    });
    let qd = SVector::from_fn(|i, _| if i < 2 { 1.0 } else { 0.5 });
    (q, qd)
}

/// `V` with `config` run for `duration` s by Bogacki-Shampine at 1e-4
/// (the ground pressed and switches restarting it after every step, as
/// in a run): its system, the time and the state reached.
pub fn driven<V: Vehicle>(config: VehicleConfig, duration: f64) -> (V::System, f64, DVector<f64>) {
    let mut system = build::<V>(config).unwrap();
    let mut y = system.initial_state();
    let mut stepper = Integrator::Bs23 {
        rtol: 1e-4,
        atol: 1e-4,
        max_step: 0.01,
    }
    .stepper(system.dimension());
    let mut t = 0.0;
    while t < duration {
        stepper.step(&mut system, &mut t, &mut y, duration).unwrap();
        if system.after_step(t, y.as_mut_slice(), &mut |_| {}).unwrap() {
            stepper.restart();
        }
    }
    (system, t, y)
}
