//! Helpers of the vehicle tests: building the M113 with any closure and
//! drive (through the one path users call, `trackgen::vehicle::build`),
//! and reading its energy books and time windows from the results.

use trackgen::closure::ClosureMethod;
use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::multibody::RecursiveModel;
use trackgen::nalgebra::DVector;
use trackgen::simulate::{Output, Results, simulate};
use trackgen::system::Simulated;
use trackgen::terrain::Terrain;
use trackgen::vehicle::{Drive, Driveline, Powertrain, Vehicle, VehicleConfig, build};
use trackgen::vehicles::{m113, m113::M113, m113::M113Chassis, m113::M113System, m113::M113Track};

use super::{max_abs, min_of};

/// The M113 as it ships (`M113::system`: its declared configuration,
/// assembled with its tensioner set), its loop closed by `closure`.
pub fn m113_with(terrain: Terrain, drive: Drive, closure: ClosureMethod) -> M113System {
    let mut config = M113::declared_config(terrain, drive);
    config.closure = closure;
    build::<M113>(config).expect("the M113 builds")
}

/// The planar M113's mass, kg, from the masses declared in
/// `src/vehicles/m113.rs` as compiled (one side: 64 shoes, the half hull,
/// sprocket, five road wheels and arms, idler and tensioner arm).
pub fn m113_mass() -> f64 {
    side_mass(&M113Track, &M113Chassis)
}

/// A planar side's mass, kg: every compiled body of its track and its
/// chassis (the half hull and its running gear).
pub fn side_mass<const DT: usize, const DC: usize>(
    track: &impl RecursiveModel<DT>,
    chassis: &impl RecursiveModel<DC>,
) -> f64 {
    [track.description(), chassis.description()]
        .iter()
        .flat_map(|d| d.bodies.iter().map(|b| b.mass))
        .sum()
}

/// The planar M113's weight, N: [`m113_mass`] under 9.81 m/s².
pub fn m113_weight() -> f64 {
    m113_mass() * 9.81
}

/// The M113 sprocket's pitch radius, m, from the shoe pitch and the tooth
/// count alone: the joints seated in the gaps form a regular polygon of
/// side `p` with `N` sides, whose circumradius is `p / (2 sin(π/N))`
/// (0.2492 m; the declared rim radius is 0.245 m).
pub fn m113_pitch_radius() -> f64 {
    m113::SHOE_PITCH / (2.0 * (std::f64::consts::PI / 10.0).sin())
}

/// The values of `column` at samples with `t0 ≤ t ≤ t1`.
pub fn window(results: &Results, column: &str, t0: f64, t1: f64) -> Vec<f64> {
    let values = results
        .column(column)
        .unwrap_or_else(|| panic!("no column {column}"));
    results
        .times()
        .iter()
        .zip(values)
        .filter(|(t, _)| (t0..=t1).contains(*t))
        .map(|(_, v)| v)
        .collect()
}

/// The mean of a non-empty list (NaN propagates).
pub fn mean(values: &[f64]) -> f64 {
    assert!(!values.is_empty(), "mean of nothing");
    values.iter().sum::<f64>() / values.len() as f64
}

/// The energy books of a vehicle run: the largest `|W − ΔE − D|` over
/// the samples (J), the motor's final work `W` (J), and the smallest
/// increase of the dissipated work `D` between samples (J; negative if a
/// law gave energy back).
pub struct Books {
    /// Largest residual of `W = ΔE + D`, J.
    pub residual: f64,
    /// The motor's work at the end, J.
    pub work: f64,
    /// Smallest step of `D` between samples, J.
    pub least_dissipation_step: f64,
}

impl Books {
    /// Reads the books from a vehicle's results.
    pub fn of(results: &Results) -> Books {
        let column = |c: &str| results.column(c).unwrap_or_else(|| panic!("no column {c}"));
        let (energy, work, dissipated) =
            (column("energy"), column("motor_work"), column("dissipated"));
        Books {
            residual: max_abs(
                (0..energy.len()).map(|i| work[i] - (energy[i] - energy[0]) - dissipated[i]),
            ),
            work: *work.last().expect("samples"),
            least_dissipation_step: min_of(dissipated.windows(2).map(|d| d[1] - d[0])),
        }
    }

    /// The residual as a fraction of the work.
    pub fn relative(&self) -> f64 {
        self.residual / self.work.abs()
    }
}

/// `V` on `terrain` driven from rest toward 2 m/s (reached at 1 s) for
/// `duration` s by Bogacki-Shampine at `tolerance` (relative and
/// absolute), a partition switch restarting it as in a run: a moving state
/// for the tests of what the vehicle gives besides its right-hand side.
/// Returns the system, the time reached (`duration`) and the state.
pub fn driven<V: Vehicle>(
    terrain: Terrain,
    duration: f64,
    tolerance: f64,
) -> (V::System, f64, DVector<f64>) {
    driven_with::<V>(terrain, |_| {}, duration, tolerance)
}

/// [`driven`], its configuration changed by `change` first (soil, laws).
pub fn driven_with<V: Vehicle>(
    terrain: Terrain,
    change: impl FnOnce(&mut VehicleConfig),
    duration: f64,
    tolerance: f64,
) -> (V::System, f64, DVector<f64>) {
    driven_toward::<V>(terrain, |t| 2.0 * t.min(1.0), change, duration, tolerance)
}

/// [`driven_with`], its speed drive aiming at `target(t)` (m/s).
pub fn driven_toward<V: Vehicle>(
    terrain: Terrain,
    target: impl Fn(f64) -> f64 + Send + 'static,
    change: impl FnOnce(&mut VehicleConfig),
    duration: f64,
    tolerance: f64,
) -> (V::System, f64, DVector<f64>) {
    let mut config = V::declared_config(terrain, V::speed_drive(target));
    change(&mut config);
    let mut system = build::<V>(config).expect("builds");
    let mut y = system.initial_state();
    let mut stepper = Integrator::Bs23 {
        rtol: tolerance,
        atol: tolerance,
        max_step: 0.01,
    }
    .stepper(system.dimension());
    let mut t = 0.0;
    while t < duration {
        stepper
            .step(&mut system, &mut t, &mut y, duration)
            .expect("steps");
        if system
            .after_step(t, y.as_mut_slice(), &mut |_| {})
            .expect("after a step")
        {
            stepper.restart();
        }
    }
    (system, t, y)
}

/// The hull's centroid along the slope of `grade` (rise over run), m, at
/// every sample.
pub fn along_slope(results: &Results, grade: f64) -> Vec<f64> {
    let norm = (1.0 + grade * grade).sqrt();
    let (x, y) = (results.column("x").unwrap(), results.column("y").unwrap());
    x.iter()
        .zip(&y)
        .map(|(x, y)| (x + grade * y) / norm)
        .collect()
}

/// Flat ground up to a wall `height` m tall whose face is at x = 4 m (the
/// M113's nose starts at about 2.46 m), flat again on top
/// (`tests/it/hull.rs`, the Jacobian's and `W`'s tests on the hull).
pub fn wall(height: f64) -> Terrain {
    let course = trackgen::terrain::profile::Course::starting_at(-20.0, 0.0)
        .unwrap()
        .flat(24.0)
        .unwrap()
        .step(height)
        .unwrap()
        .flat(10.0)
        .unwrap();
    Terrain::profile(course.profile().unwrap())
}

/// The M113 asked for 1 m/s (reached in 1 s) at a 1.2 m [`wall`]: at
/// 3.0 s it leans on the wall with its hull (the wall's top edge in the
/// glacis), its tracks still driving. The state, and the hull's normal
/// force there, N.
pub fn m113_leaning_on_a_wall() -> (M113System, f64, DVector<f64>, f64) {
    let (mut system, t, y) = driven_with::<M113>(
        wall(1.2),
        |config| config.drive = M113::speed_drive(|t| t.min(1.0)),
        3.0,
        1e-4,
    );
    let columns = system.columns();
    let mut row = Vec::new();
    system.observe(t, y.as_slice(), &mut row).expect("observes");
    let hull = row[columns.iter().position(|c| c == "hull_normal").unwrap()];
    (system, t, y, hull)
}

/// The M113A3's driveline as the M113 declares it
/// (`m113::powertrain()`).
pub fn m113a3_driveline() -> Driveline {
    match m113::powertrain() {
        Powertrain::Converter(driveline) => *driveline,
        other => panic!("the M113A3 has a torque converter, not {other:?}"),
    }
}

/// A step of `height` m on flat ground 28 m from the start (the M113
/// starting 20 m before the origin), 150 m of flat beyond: the course the
/// engine's books are kept over.
pub fn step_course(height: f64) -> Terrain {
    let course = trackgen::terrain::profile::Course::starting_at(-20.0, 0.0)
        .and_then(|c| c.flat(28.0))
        .and_then(|c| c.step(height))
        .and_then(|c| c.flat(150.0))
        .and_then(trackgen::terrain::profile::Course::profile)
        .expect("a step");
    Terrain::profile(course)
}

/// The M113A3's driveline as a quasi-static converter: no engine
/// inertia (the engine where the converter's steady match puts it) and
/// ideal shifting, what the M113 declared before its engine's speed became
/// a state — for the checks of that model.
pub fn m113a3_quasi_static() -> Driveline {
    Driveline {
        dynamics: None,
        shift: None,
        ..m113a3_driveline()
    }
}

/// The M113 through `driveline` on `terrain`, its speed drive aiming at
/// `target(t)` (m/s), run `duration` s by Bogacki-Shampine at 1e-4 (max
/// step 10 ms), a row every `every` s.
pub fn m113_through(
    driveline: &Driveline,
    terrain: Terrain,
    target: impl Fn(f64) -> f64 + Send + 'static,
    duration: f64,
    every: f64,
) -> Results {
    let powertrain = Powertrain::Converter(Box::new(driveline.clone()));
    m113_run(Some(powertrain), terrain, target, duration, every, 0.0)
}

/// [`m113_through`] under any `powertrain` (`None`: the speed drive alone),
/// a drawbar pull of `drawbar_pull` N on the hull throughout.
pub fn m113_run(
    powertrain: Option<Powertrain>,
    terrain: Terrain,
    target: impl Fn(f64) -> f64 + Send + 'static,
    duration: f64,
    every: f64,
    drawbar_pull: f64,
) -> Results {
    let mut config = M113::declared_config(terrain, M113::speed_drive(target));
    config.powertrain = powertrain;
    config.drawbar_pull = drawbar_pull;
    let mut system = build::<M113>(config).expect("the M113 builds");
    simulate(
        &mut system,
        Integrator::Bs23 {
            rtol: 1e-4,
            atol: 1e-4,
            max_step: 0.01,
        },
        0.0,
        duration,
        Output::Every(every),
    )
    .expect("the run finishes")
}
