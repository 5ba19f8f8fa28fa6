//! How the hull's bounce and pitch change with the torsion bars' rate:
//! each vehicle at rest (`trackgen::analysis::equilibrium`) with its road
//! wheels' torsion rate scaled from half to twice the declared, and its
//! modes there (`trackgen::analysis::modes`); then, at the declared rate,
//! how the hull's height and pitch at rest move with each arm's rate
//! (`equilibrium_sensitivity`).
//!
//! `cargo run --release --example torsion_modes`

use std::error::Error;

use trackgen::analysis::{
    EquilibriumOptions, equilibrium, equilibrium_sensitivity, mode_of, modes,
};
use trackgen::multibody::PartKind;
use trackgen::terrain::Terrain;
use trackgen::vehicle::{Vehicle, VehicleDynamics};
use trackgen::vehicles::{m113::M113, marder::Marder};

/// The road wheels' arm bodies of `V`.
fn road_wheel_arms<V: Vehicle>() -> Vec<usize> {
    <V::System as VehicleDynamics>::parts()
        .iter()
        .filter(|p| p.kind == PartKind::RoadWheel)
        .filter_map(|p| p.arm.as_ref().map(|a| a.body))
        .collect()
}

fn sweep<V: Vehicle>() -> Result<(), Box<dyn Error>> {
    let arms = road_wheel_arms::<V>();
    println!(
        "{}: road wheels' torsion rate against the hull's modes at rest",
        V::NAME
    );
    println!(
        "  rate ×   k (N m/rad)   height (m)   pitch (mrad)   bounce (Hz, ζ, share)  pitch (Hz, ζ, share)"
    );
    for factor in [0.5, 0.75, 1.0, 1.5, 2.0] {
        let mut config = V::declared_config(Terrain::Flat { height: 0.0 }, V::speed_drive(|_| 0.0));
        let mut rate = 0.0;
        for arm in config.arms.iter_mut().filter(|a| arms.contains(&a.body)) {
            arm.spring.stiffness *= factor;
            rate = arm.spring.stiffness;
        }
        let mut system = V::system_with(config)?;
        let rest = equilibrium(&mut system, &EquilibriumOptions::default())?;
        let modes = modes(&mut system, rest.t, &rest.state)?;
        let describe = |name| {
            mode_of(&modes, name).map_or("—".to_string(), |m| {
                let share = m.share_of(name);
                format!(
                    "{:6.3} {:5.2} ({:2.0} %)",
                    m.frequency,
                    m.damping_ratio,
                    100.0 * share
                )
            })
        };
        println!(
            "  {factor:6.2}   {rate:11.0}   {:10.4}   {:12.3}   {:>20}   {:>20}",
            rest.height,
            rest.pitch * 1e3,
            describe("hull bounce"),
            describe("hull pitch"),
        );
    }
    let mut system = V::system(Terrain::Flat { height: 0.0 }, V::speed_drive(|_| 0.0))?;
    let rest = equilibrium(&mut system, &EquilibriumOptions::default())?;
    println!("  at the declared rates, per 10 % more rate on one arm:");
    for (index, arm) in system.arms_mut().to_vec().iter().enumerate() {
        let name = <V::System as VehicleDynamics>::parts()
            .iter()
            .find(|p| p.arm.as_ref().is_some_and(|a| a.body == arm.body))
            .map_or("?", |p| p.name);
        let s = equilibrium_sensitivity(&mut system, &rest, index)?;
        let step = 0.1 * arm.spring.stiffness;
        println!(
            "    arm of {name:>10}: height {:+8.3} mm, pitch {:+8.4} mrad",
            s.height * step * 1e3,
            s.pitch * step * 1e3
        );
    }
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    sweep::<M113>()?;
    println!();
    sweep::<Marder>()?;
    Ok(())
}
