//! A vehicle at rest on its ground with its sprocket held: Newton's method
//! on the equations of motion.

use nalgebra::DVector;

use super::AnalysisError;
use super::statics::Statics;
use crate::integrate::SimulationError;
use crate::integrate::{Integrator, OdeSystem};
use crate::vehicle::{Drive, StateLayout, VehicleDynamics, VehicleRecord};

/// How hard [`equilibrium`] tries.
#[derive(Debug, Clone, PartialEq)]
pub struct EquilibriumOptions {
    /// The time at which the drive is asked to hold (its target speed must
    /// be 0 there), s. Default 0.
    pub t: f64,
    /// The largest acceleration left at an equilibrium, m/s² or rad/s².
    /// Default 10⁻⁸ (10⁻⁹ g: the hull then creeps less than a micrometre
    /// in ten seconds from rest).
    pub tolerance: f64,
    /// Newton iterations before giving up. Default 40.
    pub max_iterations: usize,
    /// Simulated time the vehicle settles for before Newton's method
    /// starts, s (the drive holding at [`t`](Self::t)), with
    /// [`relax_damping`](Self::relax_damping). Default 0.5 s: enough for
    /// the contacts to find their places (from the assembled start, the
    /// shoes 1 mm above the ground, Newton's method alone wanders through
    /// contacts that come and go and does not converge), a sixth of the
    /// settling a run needs to stop ringing.
    pub relax: f64,
    /// A damping rate applied to every coordinate while relaxing, 1/s.
    /// Default 10 /s: the hull's bounce and pitch (1–2 Hz) near critically
    /// damped.
    pub relax_damping: f64,
    /// The state to start from; `None` (default): the system's start
    /// (the assembled vehicle, or what [`set_start`](VehicleDynamics::set_start) gave).
    /// The chassis' x and the sprocket's angle stay where the relaxation
    /// leaves them: the equilibria of a track on its wheels form a family
    /// over the track's phase (where the shoes sit under the road wheels
    /// moves the hull by about 0.1 mm and 10⁻⁴ rad on the M113).
    pub start: Option<DVector<f64>>,
}

impl Default for EquilibriumOptions {
    fn default() -> Self {
        EquilibriumOptions {
            t: 0.0,
            tolerance: 1e-8,
            max_iterations: 40,
            relax: 0.5,
            relax_damping: 10.0,
            start: None,
        }
    }
}

/// A vehicle at rest ([`equilibrium`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Equilibrium {
    /// The time it holds at, s.
    pub t: f64,
    /// The state: coordinates at rest, every rate zero, the drive's
    /// integral holding the sprocket, no tangential load held by friction,
    /// the books at zero. Start a run from it with
    /// [`VehicleDynamics::set_start`].
    pub state: DVector<f64>,
    /// Newton iterations taken.
    pub iterations: usize,
    /// The largest rate of change of any state with dynamics left, in its
    /// own unit per second.
    pub residual: f64,
    /// The drive's torque holding the sprocket, N m.
    pub holding_torque: f64,
    /// The ground's normal force on the track, N.
    pub ground_force: f64,
    /// The vehicle's weight (one side, every body of track and chassis), N.
    pub weight: f64,
    /// The hull's height (the chassis centroid's y), m.
    pub height: f64,
    /// The hull's pitch, rad.
    pub pitch: f64,
    /// Whether the ground holds a load along it by stiction (a slope's
    /// share of the weight, a drawbar pull): its points in contact then
    /// share a tangential deflection ([`equilibrium`]).
    pub friction_held: bool,
}

/// The vehicle `system` at rest on its ground, its sprocket held by the
/// speed drive's integral (so the state is one a simulation stays at: the
/// controller supplies exactly the holding torque, and starting a run
/// there needs no settling).
///
/// Unknowns: every coordinate but the free ones, and the drive's integral.
/// Held where they are: the chassis' x (the vehicle may stand anywhere
/// along the ground), the sprocket's angle (the track may stand at any
/// phase round its wheels; the held sprocket fixes it), and the spin of
/// every other wheel on its axle (round rims turn freely). Equations:
/// every coordinate's acceleration zero but the wheels' spins (no torque
/// acts on a round rim at rest). Rates and books are zero.
///
/// Friction: first the rest that holds nothing in friction (the chassis'
/// acceleration along x left out: on level ground with nothing pulling it
/// follows from the others). If the chassis' x then does not settle and
/// the ground holds by stiction
/// ([`GroundFriction::Stiction`](crate::contact::GroundFriction::Stiction)),
/// every ground point in contact takes one shared tangential deflection,
/// one more unknown, paired with the chassis' acceleration along x: the
/// ground holds what pushes along it (a slope's share of the weight, a
/// drawbar pull) with its points equally deflected, each up to its
/// Coulomb limit ([`Equilibrium::friction_held`]). Friction is statically
/// indeterminate (any deflections within `μ F_n` could rest); this is the
/// rest of a vehicle let down onto the ground and then loaded along it
/// uniformly. With regularised friction, on a slope or under a pull there
/// is no rest ([`AnalysisError::NotConverged`]: regularised friction holds
/// nothing at rest).
///
/// The start: the built state lowered rigidly until the ground carries
/// the weight (bisection on the height, so the first Jacobian is not that
/// of a vehicle in the air), relaxed ([`EquilibriumOptions::relax`]); then
/// Newton's method with the Jacobian by central differences
/// ([`step_for`](super::step_for)), safeguarded by pseudo-transient
/// continuation.
///
/// Errors: [`AnalysisError::NoHold`], [`AnalysisError::Moving`] or
/// [`AnalysisError::NoSprocket`] for a vehicle whose sprocket is not held,
/// [`AnalysisError::SoftSoil`] on soil, [`AnalysisError::NotConverged`]
/// naming the largest acceleration left (on a slope, or under a drawbar
/// pull, there is no equilibrium without stiction),
/// [`AnalysisError::Singular`].
pub fn equilibrium<S: VehicleDynamics>(
    system: &mut S,
    options: &EquilibriumOptions,
) -> Result<Equilibrium, AnalysisError> {
    let t = options.t;
    if system.rut().is_some() {
        return Err(AnalysisError::SoftSoil);
    }
    match &system.config().drive {
        Drive::Speed { target, .. } => {
            let target = target(t);
            if target != 0.0 {
                return Err(AnalysisError::Moving { target, t });
            }
        }
        Drive::Free => return Err(AnalysisError::NoHold { drive: "free" }),
        Drive::Torque(_) => {
            return Err(AnalysisError::NoHold {
                drive: "a torque schedule",
            });
        }
    }
    let layout = system.layout();
    layout.sprocket_angle().ok_or(AnalysisError::NoSprocket)?;
    let weight = weight::<S>();
    let mut y = options
        .start
        .clone()
        .unwrap_or_else(|| system.initial_state());
    for i in layout.rates().chain(layout.tangential.clone()) {
        y[i] = 0.0;
    }
    lower_onto_ground(system, t, &layout, weight, &mut y)?;
    relax(system, t, (options.relax, options.relax_damping), &mut y)?;
    // Settling may have switched the track's partition.
    let layout = system.layout();
    for i in layout.rates().chain(layout.tangential.clone()) {
        y[i] = 0.0;
    }
    for &book in &layout.books {
        y[book] = 0.0;
    }

    let points = system.geometry().shoe.ground_points.len();
    // First the rest that holds nothing in friction; then, if something
    // pushes along the ground (the chassis' x does not settle) and the
    // ground holds by stiction, the rest with the shared deflection.
    let unstrained = newton(system, t, y.clone(), options, false);
    let (y, statics, iterations, friction_held) = match unstrained {
        Ok((y, statics, iterations))
            if full_residual(system, t, &y, &statics)?.1 <= 100.0 * options.tolerance =>
        {
            (y, statics, iterations, false)
        }
        first if system.holds_by_stiction() => {
            // From the relaxed state: the unstrained rest leans on what
            // the friction would hold, a poorer start.
            let done = first.map_or(0, |(_, _, iterations)| iterations);
            let (y, statics, more) = newton(system, t, y, options, true)?;
            (y, statics, done + more, true)
        }
        Ok((y, statics, iterations)) => (y, statics, iterations, false),
        Err(e) => return Err(e),
    };
    // The equations left out (the chassis' x without stiction, the wheels'
    // spins) follow from the others only where nothing outside pushes
    // along the ground: a drawbar pull or a slope shows here.
    let (worst, residual) = full_residual(system, t, &y, &statics)?;
    if residual > 100.0 * options.tolerance {
        return Err(AnalysisError::NotConverged {
            iterations,
            residual,
            state: statics.layout.name(worst, points),
        });
    }
    let record = record_at(system, t, &y)?;
    Ok(Equilibrium {
        t,
        iterations,
        residual,
        holding_torque: record.sprocket_torque,
        ground_force: record.ground_normal,
        weight,
        height: record.y,
        pitch: record.pitch,
        friction_held,
        state: y,
    })
}

/// The largest rate of any state with dynamics at `y`, and which.
fn full_residual<S: VehicleDynamics>(
    system: &mut S,
    t: f64,
    y: &DVector<f64>,
    statics: &Statics,
) -> Result<(usize, f64), AnalysisError> {
    let mut rates = DVector::zeros(y.len());
    system.derivative(t, y.as_slice(), rates.as_mut_slice())?;
    Ok(statics
        .layout
        .dynamic()
        .map(|i| (i, rates[i].abs()))
        .fold((0, 0.0), |a, b| if b.1 > a.1 { b } else { a }))
}

/// Newton's method on the statics from `y` (with the ground points'
/// shared deflection as an unknown if `friction`): the state at rest, its
/// statics and the iterations taken.
///
/// Newton's step `−J δ = r`, safeguarded by pseudo-transient continuation
/// (Kelley & Keyes 1998, "Convergence analysis of pseudo-transient
/// continuation", SIAM J. Numer. Anal. 35): a step that raises the
/// residual tenfold, or that the loop closure cannot recover, is retried
/// as `(I/Δτ − J) δ = r` with a shorter pseudo-time step `Δτ` (a stable
/// implicit relaxation step), and `Δτ` grows back as the residual falls
/// (switched evolution relaxation).
fn newton<S: VehicleDynamics>(
    system: &mut S,
    t: f64,
    mut y: DVector<f64>,
    options: &EquilibriumOptions,
    friction: bool,
) -> Result<(DVector<f64>, Statics, usize), AnalysisError> {
    let points = system.geometry().shoe.ground_points.len();
    let mut statics = Statics::at(system, t, &y, friction)?;
    let mut iterations = 0;
    let mut inverse_dtau = 0.0;
    loop {
        // Which points touch, and what each holds, at this iterate: the
        // shared deflection written again under them.
        let u = statics.read(&y);
        statics = Statics::at(system, t, &y, friction)?;
        statics.write(&u, &mut y);
        let r = statics.residual(system, t, &y)?;
        if r.amax() <= options.tolerance {
            return Ok((y, statics, iterations));
        }
        if iterations == options.max_iterations {
            let k = r.iamax();
            return Err(AnalysisError::NotConverged {
                iterations,
                residual: r[k].abs(),
                state: statics.equation_name(k, points),
            });
        }
        iterations += 1;
        let jacobian = statics.jacobian(system, t, &y)?;
        let u = statics.read(&y);
        loop {
            let mut shifted = -&jacobian;
            for k in 0..shifted.nrows() {
                shifted[(k, k)] += inverse_dtau;
            }
            let step = shifted.lu().solve(&r).ok_or(AnalysisError::Singular)?;
            if step.iter().any(|v| !v.is_finite()) {
                return Err(AnalysisError::Singular);
            }
            let mut trial = y.clone();
            statics.write(&(&u + &step), &mut trial);
            match statics.residual(system, t, &trial) {
                Ok(rt) if rt.norm() < 10.0 * r.norm() => {
                    inverse_dtau *= (rt.norm() / r.norm()).clamp(0.1, 10.0);
                    y = trial;
                    break;
                }
                _ if inverse_dtau < 1e3 * jacobian.diagonal().amax() => {
                    inverse_dtau = (4.0 * inverse_dtau).max(1e-6 * jacobian.diagonal().amax());
                }
                Ok(_) => {
                    let k = r.iamax();
                    return Err(AnalysisError::NotConverged {
                        iterations,
                        residual: r[k].abs(),
                        state: statics.equation_name(k, points),
                    });
                }
                Err(e) => return Err(e),
            }
        }
    }
}

/// The vehicle's weight, N: every body of track and chassis under its
/// description's gravity.
pub(super) fn weight<S: VehicleDynamics>() -> f64 {
    [S::track_description(), S::chassis_description()]
        .iter()
        .map(|d| d.gravity.norm() * d.bodies.iter().map(|b| b.mass).sum::<f64>())
        .sum()
}

/// Lets the vehicle settle from `y` for `duration` s of simulated time,
/// the clock held at `t` (so the drive holds as it does at `t`), every
/// coordinate's acceleration less `damping` times its rate (a damping of
/// the relaxation only, so the hull's slow bounce and pitch die out in a
/// fraction of a second): Bogacki-Shampine at the main job's tolerance,
/// the partition switching as in any run.
fn relax<S: VehicleDynamics>(
    system: &mut S,
    t: f64,
    (duration, damping): (f64, f64),
    y: &mut DVector<f64>,
) -> Result<(), AnalysisError> {
    struct Frozen<'s, S> {
        system: &'s mut S,
        t: f64,
        rates: Vec<usize>,
        damping: f64,
    }
    impl<S: VehicleDynamics> OdeSystem for Frozen<'_, S> {
        fn dimension(&self) -> usize {
            self.system.dimension()
        }
        fn derivative(&mut self, _: f64, y: &[f64], dy: &mut [f64]) -> Result<(), SimulationError> {
            self.system.derivative(self.t, y, dy)?;
            for &i in &self.rates {
                dy[i] -= self.damping * y[i];
            }
            Ok(())
        }
        fn is_quadrature(&self, i: usize) -> bool {
            self.system.is_quadrature(i)
        }
        fn is_passive(&self, i: usize) -> bool {
            self.system.is_passive(i)
        }
    }
    if duration <= 0.0 {
        return Ok(());
    }
    let integrator = Integrator::Bs23 {
        rtol: 1e-4,
        atol: 1e-4,
        max_step: 0.01,
    };
    let mut stepper = integrator.stepper(y.len());
    let layout = system.layout();
    let rates = layout.rates().collect();
    let mut frozen = Frozen {
        system,
        t,
        rates,
        damping,
    };
    let mut clock = 0.0;
    while clock < duration {
        stepper.step(&mut frozen, &mut clock, y, duration)?;
        if frozen.system.after_step(t, y.as_mut_slice(), &mut |_| {})? {
            stepper.restart();
        }
    }
    Ok(())
}

/// What the vehicle records at `(t, y)`.
pub(super) fn record_at<S: VehicleDynamics>(
    system: &mut S,
    t: f64,
    y: &DVector<f64>,
) -> Result<VehicleRecord, AnalysisError> {
    let mut row = Vec::new();
    system.observe(t, y.as_slice(), &mut row)?;
    let tail = &row[row.len() - VehicleRecord::COLUMNS.len()..];
    let at = |name: &str| {
        let k = VehicleRecord::COLUMNS.iter().position(|c| *c == name);
        k.map_or(f64::NAN, |k| tail[k])
    };
    Ok(VehicleRecord {
        y: at("y"),
        pitch: at("pitch"),
        sprocket_torque: at("sprocket_torque"),
        ground_normal: at("ground_normal"),
        ..VehicleRecord::default()
    })
}

/// Lowers the whole vehicle (chassis and track together) until the ground
/// carries its weight: bisection on the drop, up to 0.2 m.
fn lower_onto_ground<S: VehicleDynamics>(
    system: &mut S,
    t: f64,
    layout: &StateLayout,
    weight: f64,
    y: &mut DVector<f64>,
) -> Result<(), AnalysisError> {
    let heights = [layout.track.start + 1, layout.chassis.start + 1];
    let ground = |system: &mut S, drop: f64| -> Result<f64, AnalysisError> {
        let mut lowered = y.clone();
        for &i in &heights {
            lowered[i] -= drop;
        }
        Ok(record_at(system, t, &lowered)?.ground_normal)
    };
    if ground(system, 0.0)? >= weight {
        return Ok(());
    }
    let (mut low, mut high) = (0.0, 0.2);
    if ground(system, high)? < weight {
        return Ok(());
    }
    for _ in 0..40 {
        let mid = 0.5 * (low + high);
        if ground(system, mid)? < weight {
            low = mid;
        } else {
            high = mid;
        }
    }
    for &i in &heights {
        y[i] -= high;
    }
    Ok(())
}
