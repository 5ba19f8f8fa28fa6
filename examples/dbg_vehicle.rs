use trackgen::closure::ClosureMethod;
use trackgen::contact::sprocket::ToothProfile;
use trackgen::contact::{ShoeGeometry, Terrain};
use trackgen::integrate::Integrator;
use trackgen::simulate::{simulate, Output};
use trackgen::vehicle::{assemble, Drive, VehicleConfig, VehicleSystem};
use trackgen::vehicles::m113::{M113Chassis, M113Track};
use trackgen::{RecursiveModel, TrackModel};
fn main() {
    let terrain = Terrain::Flat { height: 0.0 };
    let a = assemble(&M113Track, &M113Chassis, &ShoeGeometry::m113(), &ToothProfile::m113(), &terrain, 0.0, 0.001).unwrap();
    println!("closure after wrap: {:e}", M113Track.closure(&a.track).norm());
    let total: f64 = M113Track.description().bodies.iter().map(|b| b.mass).sum::<f64>() + M113Chassis.description().bodies.iter().map(|b| b.mass).sum::<f64>();
    println!("weight {:.0} N", total * 9.81);
    let config = VehicleConfig::m113(terrain, Drive::Free);
    let mut sys = VehicleSystem::new(M113Track, M113Chassis, a.track, a.chassis, ClosureMethod::Declared, config).unwrap();
    let t0 = std::time::Instant::now();
    let r = simulate(&mut sys, Integrator::dopri5(1e-6), 0.0, 2.0, Output::Every(0.1));
    let wall = t0.elapsed().as_secs_f64();
    let r = match r { Ok(r) => r, Err(f) => { println!("FAILED {}", f.error); f.results } };
    for s in r.iter() {
        println!("t={:.2} y={:.4} pitch={:.4} speed={:.4} Fn={:.0} pen g={:.2e} w={:.2e} s={:.2e} E={:.1} T={:.0}",
            s.t, s.get("y").unwrap(), s.get("pitch").unwrap(), s.get("speed").unwrap(), s.get("ground_normal").unwrap(),
            s.get("ground_penetration").unwrap(), s.get("wheel_penetration").unwrap(), s.get("sprocket_penetration").unwrap(), s.get("energy").unwrap(), s.get("tension").unwrap());
    }
    println!("wall {wall:.2}s stats {:?} switches {}", r.stats, r.switches.len());
}
#[allow(dead_code)]
fn geometry() {}
