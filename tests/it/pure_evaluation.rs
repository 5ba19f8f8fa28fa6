//! A vehicle's right-hand side is a function of the state alone: the same
//! state gives the same bits whatever was evaluated before it. Regression:
//! the closure's recovery took the loop's rate over every link and then
//! the dependent pair's share out with the pair's rates left from the
//! previous recovery, so an evaluation at a state after one at another
//! (the stiffness probes of `--integrator auto`, a Jacobian's columns)
//! differed in the last bits from one before it, and a run with the probes
//! took 11 029 steps where the same run without them took 11 134.

use crate::support;
use support::vehicle::driven;

use trackgen::integrate::OdeSystem;
use trackgen::terrain::Terrain;
use trackgen::vehicle::{Vehicle, VehicleDynamics};
use trackgen::vehicles::{m113::M113, marder::Marder};

/// Drives `V` from rest for 0.6 s, then evaluates at the state, at the
/// state with every coordinate moved, and at the state again: the first
/// and last agree bit for bit.
fn pure<V: Vehicle>() {
    let (mut system, t, y) = driven::<V>(Terrain::Flat { height: 0.0 }, 0.6, 1e-3);
    let layout = system.layout();
    let n = y.len();
    let (mut first, mut between, mut again) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    system
        .derivative(t, y.as_slice(), &mut first)
        .expect("evaluates");
    let mut moved = y.clone();
    for i in layout.positions() {
        moved[i] += 1e-6;
    }
    system
        .derivative(t, moved.as_slice(), &mut between)
        .expect("evaluates");
    system
        .derivative(t, y.as_slice(), &mut again)
        .expect("evaluates");
    let differing: Vec<usize> = (0..n)
        .filter(|&i| first[i].to_bits() != again[i].to_bits())
        .collect();
    assert!(
        differing.is_empty(),
        "{}: {} components of f differ after an evaluation elsewhere: {:?}",
        V::NAME,
        differing.len(),
        &differing[..differing.len().min(8)]
    );
}

#[test]
fn an_evaluation_depends_on_its_state_alone() {
    pure::<M113>();
    pure::<Marder>();
}
