use trackgen::Vehicle;
use trackgen::contact::{NormalLaw, Terrain, GroundFriction};
use trackgen::integrate::Integrator;
use trackgen::simulate::{Output, simulate};
use trackgen::vehicles::m113::M113;

fn ratio(label: &str, f: impl Fn(&mut trackgen::vehicle::VehicleConfig)) {
    let drive = if label.starts_with("towed") { trackgen::vehicle::Drive::Free } else { M113::speed_drive(|t| 2.0 * ((t - 0.5) / 2.0).clamp(0.0, 1.0)) };
    let mut config = M113::config(Terrain::Flat { height: 0.0 }, drive);
    f(&mut config);
    let mut v = M113::system_with(config).unwrap();
    let r = simulate(&mut v, Integrator::Bs23 { rtol: 1e-4, atol: 1e-4, max_step: 0.01 }, 0.0, 20.0, Output::Every(0.01)).unwrap();
    let mean = |c: &str| { let x: Vec<f64> = r.times().iter().zip(r.column(c).unwrap()).filter(|(t,_)| **t >= 8.0).map(|(_,v)| v).collect(); x.iter().sum::<f64>()/x.len() as f64 };
    println!("{label:30} ratio {:.5} (speed {:.3})", mean("speed")/mean("track_speed"), mean("speed"));
}
fn main() {
    ratio("as declared", |_| {});
    ratio("towed -1500 N", |c| { c.drawbar_pull = -1500.0; });
    ratio("towed -3000 N", |c| { c.drawbar_pull = -3000.0; });
}
