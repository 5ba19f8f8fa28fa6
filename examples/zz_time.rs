use trackgen::contact::Terrain;
use trackgen::integrate::Integrator;
use trackgen::simulate::{Output, simulate};
use trackgen::vehicles::m113;
fn main() {
    let reps: usize = std::env::args()
        .nth(1)
        .map(|s| s.parse().unwrap())
        .unwrap_or(5);
    let mut times = Vec::new();
    let mut evals = 0;
    for _ in 0..reps {
        let drive = m113::speed_drive(|t| 3.0 * ((t - 0.5) / 1.0).clamp(0.0, 1.0));
        let terrain = Terrain::Bump {
            centre: 2.5,
            width: 1.0,
            height: 0.1,
        };
        let mut system = m113::system(terrain, drive).unwrap();
        let t0 = std::time::Instant::now();
        let r = simulate(
            &mut system,
            Integrator::Bs23 {
                rtol: 1e-3,
                atol: 1e-3,
                max_step: 0.01,
            },
            0.0,
            3.0,
            Output::Every(0.01),
        )
        .unwrap();
        times.push(t0.elapsed().as_secs_f64());
        evals = r.stats.evaluations;
    }
    times.sort_by(f64::total_cmp);
    println!(
        "min {:.4} s median {:.4} s; {} evaluations, {:.3} us per evaluation (min)",
        times[0],
        times[reps / 2],
        evals,
        times[0] / evals as f64 * 1e6
    );
}
