use trackgen::Vehicle;
use trackgen::contact::Terrain;
use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::simulate::Simulated;
use trackgen::vehicles::m113::M113;

fn main() {
    let drive = M113::speed_drive(|t| 2.0 * ((t - 0.5) / 2.0).clamp(0.0, 1.0));
    let config = M113::config(Terrain::Flat { height: 0.0 }, drive);
    let mut v = M113::system_with(config).unwrap();
    let integ = Integrator::Bs23 { rtol: 1e-4, atol: 1e-4, max_step: 0.01 };
    let mut st = integ.stepper(v.dimension());
    let (mut t, mut y) = (0.0, v.initial_state());
    let n = y.len();
    let zs = n - 128;
    let mut next = 10.0;
    while t < 11.0 {
        st.step(&mut v, &mut t, &mut y, 11.0).unwrap();
        if v.after_step(t, y.as_mut_slice(), &mut |_| {}).unwrap() { st.restart(); }
        if t >= next {
            next += 0.25;
            let z: Vec<f64> = y.as_slice()[zs..].to_vec();
            let mut dy = vec![0.0; n];
            v.derivative(t, y.as_slice(), &mut dy).unwrap();
            let zd = &dy[zs..];
            let big: Vec<String> = (0..128).filter(|&i| z[i].abs() > 1e-5).map(|i| format!("{}:{:.3}mm/{:.1}mm/s", i, z[i]*1e3, zd[i]*1e3)).collect();
            println!("t {t:.2}: {}", big.join(" "));
        }
    }
}
