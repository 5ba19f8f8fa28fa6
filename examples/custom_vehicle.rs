//! Declare your own vehicle: a light tracked carrier (0.12 m shoes, a
//! 9-tooth front sprocket, four sprung road wheels, two return rollers
//! carrying the upper run, a rear idler on a tensioner arm that takes up
//! the track's slack),
//! declared in one `model!` block and run with one call, writing
//! `out/custom_vehicle/carrier.csv`.
//!
//! ```text
//! cargo run --release --example custom_vehicle -- [duration_s] [out_dir]
//! ```
//!
//! It drives up to 2 m/s on flat ground and prints the energy books (the
//! residual of `motor work = ΔE + dissipated`, as a fraction of the
//! work). Should the track not assemble round its wheels, it prints the
//! typed `AssemblyError` and exits non-zero.

use std::error::Error;
use std::path::PathBuf;

use trackgen::integrate::Integrator;
use trackgen::simulate::{EnergyBalance, Output, simulate};
use trackgen::terrain::Terrain;
use trackgen::vehicle::Vehicle;

trackgen::model! {
    /// A light carrier, one side: half its hull on a 55-link track.
    pub vehicle Carrier {
        chassis { mass: 2400.0, inertia: 3800.0, centroid: (-1.3, 0.35) },
        sprocket drive { at: (0.0, 0.0), mass: 15.0, inertia: 0.3, radius: 0.17, teeth: 9 },
        road_wheel rw[4] {
            at: [(-0.45, -0.30), (-1.0, -0.30), (-1.55, -0.30), (-2.1, -0.30)],
            mass: 25.0, inertia: 0.5, radius: 0.2,
            arm { pivot_offset: (0.22, 0.10), mass: 20.0, inertia: 0.2,
                  stiffness: 1.5e4, damping: 300.0, preload: 1.2e3 },
        },
        roller top[2] { at: [(-0.75, 0.12), (-1.75, 0.12)], mass: 5.0, inertia: 0.02, radius: 0.08 },
        idler rear { at: (-2.6, -0.08), mass: 20.0, inertia: 0.4, radius: 0.18,
            arm { pivot: (-2.6, 0.12), mass: 3.0, inertia: 0.02,        // a tensioner,
                  stiffness: 2e4, damping: 600.0, preload: -2e3,         // set by the assembly
                  travel: (-0.6, 0.6) } },                               // within ±0.6 rad
        track {
            links: 55,
            link { mass: 6.0, inertia: 0.01, u1: (-0.06, 0.0), u2: (0.06, 0.0) },
        },
        shoe { ground_points: [(-0.045, -0.02), (0.045, -0.02)], inner_offset: 0.02,
               pins: [(0.045, 0.0), (-0.045, 0.0)], pin_radius: 0.012 },
        contact { ground { stiffness: 1.5e6, chi: 2.0, mu: 0.7 } },
        drive { proportional: 1000.0, integral: 2000.0, max_torque: 5e3 },
    }
}

fn main() -> Result<(), Box<dyn Error>> {
    let mut args = std::env::args().skip(1);
    let duration: f64 = match args.next() {
        Some(a) => a.parse().map_err(|e| format!("duration {a:?}: {e}"))?,
        None => 4.0,
    };
    let out = PathBuf::from(args.next().unwrap_or_else(|| "out/custom_vehicle".into()));

    // The one call: assemble on flat ground, drive to 2 m/s after 0.5 s.
    let drive = Carrier::speed_drive(|t| 2.0 * ((t - 0.5) / 1.5).clamp(0.0, 1.0));
    let mut system = match Carrier::system(Terrain::Flat { height: 0.0 }, drive) {
        Ok(system) => system,
        Err(e) => {
            eprintln!("the carrier does not assemble: {e}");
            std::process::exit(2);
        }
    };
    let rtol = 1e-4;
    let integrator = Integrator::Dopri5 {
        rtol,
        atol: rtol,
        max_step: 0.01,
    };
    let results = simulate(&mut system, integrator, 0.0, duration, Output::Every(0.01))
        .map_err(|f| f.error.to_string())?;

    std::fs::create_dir_all(&out)?;
    let path = out.join("carrier.csv");
    results.save_csv(&path)?;
    let books = results.energy_balance().ok_or("no energy books")?;
    let last = results.last().ok_or("no samples")?;
    println!(
        "carrier: {:.2} m/s after {duration} s; motor work {:.0} J, energy residual {:.2e} of the work",
        last.get("speed").unwrap_or(f64::NAN),
        books.motor_work,
        books.residual(),
    );
    if let Err(e) = books.check(EnergyBalance::bound_for_tolerance(rtol)) {
        println!("warning: {e}");
    }
    println!("wrote {}", path.display());
    Ok(())
}
