//! Random run settings of the M113 (issue 12, part 4b): whatever the
//! integrator and its settings, the start and the duration, the output
//! times, the target speed and the terrain, building the vehicle and
//! simulating it either completes with every recorded value finite, or
//! stops with a typed error (keeping only finite samples), and never
//! panics.
//!
//! The values drawn mix sensible ones with the edges: tolerances from
//! 1e-12 to 10 and 0, negative, NaN and infinite; `max_step` 0, negative,
//! NaN, infinite; fixed steps from 1e-9 s to 1000 s, 0, negative, NaN;
//! durations of at most 0.2 s (so a case stays cheap), 0, negative, NaN,
//! infinite; starts at 0, negative, far from 0 (where a short step does
//! not change `t`) and NaN; target speeds negative, huge, NaN, infinite;
//! output intervals and time lists out of order or NaN; flat ground,
//! ramps (steep to 1000:1), bumps (negative, zero and negative width),
//! sines (zero and tiny wavelength) and tables (unordered, duplicate,
//! NaN and infinite points, built with `Terrain::table`), each with NaN
//! parameters too.
//!
//! Beyond "no panic, no NaN", each case checks what the documentation
//! promises about it:
//!
//! * settings that `simulate` documents as invalid (`t_end` not after a
//!   finite `t0`, a fixed step that is not positive and finite or does
//!   not advance `t0`, tolerances negative, non-finite or both zero
//!   (`Integrator::Auto`'s two each its method's rtol and atol: either
//!   zero), a
//!   `max_step` NaN or not positive, an output interval not positive and
//!   finite, output times not finite and non-decreasing) stop the run
//!   with `SimulationError::Setup` before any sample;
//! * a terrain with a NaN or infinite parameter, or a table that is not
//!   two finite points or more in strictly increasing x, is refused when
//!   the vehicle is built;
//! * a non-finite target speed never makes a finished run: the speed
//!   controller refuses it (`SimulationError::NonFinite`, "target speed").
//! * valid settings are never refused as a set-up error; a run may still
//!   stop for a physical reason (a step-size underflow on a terrain that
//!   buries the track, a failed closure at a tolerance of 10).
//!
//! Cost. One evaluation of the M113's right-hand side takes ~40 µs in the
//! dev profile; a case gets a budget of [`BUDGET`] evaluations (about
//! 0.2 s; a 0.2 s run at a tolerance of 1e-6 needs ~7000, a Rosenbrock
//! step ~170) enforced by a wrapper around the system, whose refusal
//! ends the run like any failing evaluation. A case that spends its budget
//! is still checked for panics and NaN up to that point, just not to its
//! end. The 48 cases take 7 to 10 s in the dev profile.
//!
//! What the property found is fixed in the runtime, each with a
//! regression test below: terrains with NaN or infinite parameters were
//! accepted (NaN heights); a NaN target speed was recorded as a NaN
//! torque, an infinite one ran on saturated; a negative or NaN torque
//! limit made `f64::clamp` panic; the span tensions were recorded as NaN
//! when the track jumped the sprocket's teeth; a row computed from a finite
//! state could hold a NaN (contact forces overflowing on a sine of
//! wavelength 1e-300); and a pure relative tolerance (`atol = 0`) divided
//! 0 by 0 in the error norm of the adaptive integrators.

use std::panic::{AssertUnwindSafe, catch_unwind};

use proptest::prelude::*;
use trackgen::closure::Switch;
use trackgen::integrate::{Integrator, OdeSystem, SimulationError};
use trackgen::nalgebra::DVector;
use trackgen::simulate::{Output, Results, SimulationFailure, simulate};
use trackgen::system::Simulated;
use trackgen::terrain::Terrain;
use trackgen::vehicle::Vehicle;
use trackgen::vehicles::m113::M113;

/// Right-hand-side evaluations a case may spend.
const BUDGET: u64 = 5000;

/// A system that refuses to be evaluated more than `left` more times.
struct Budgeted<S> {
    inner: S,
    left: u64,
    spent: bool,
}

impl<S: OdeSystem> OdeSystem for Budgeted<S> {
    fn dimension(&self) -> usize {
        self.inner.dimension()
    }

    fn derivative(&mut self, t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), SimulationError> {
        if self.left == 0 {
            self.spent = true;
            return Err(SimulationError::Stopped {
                t,
                reason: "the test's evaluation budget is spent",
            });
        }
        self.left -= 1;
        self.inner.derivative(t, y, dy)
    }
}

impl<S: Simulated> Simulated for Budgeted<S> {
    fn initial_state(&self) -> DVector<f64> {
        self.inner.initial_state()
    }

    fn columns(&self) -> Vec<String> {
        self.inner.columns()
    }

    fn observe(&mut self, t: f64, y: &[f64], row: &mut Vec<f64>) -> Result<(), SimulationError> {
        self.inner.observe(t, y, row)
    }

    fn after_step(
        &mut self,
        t: f64,
        y: &mut [f64],
        switched: &mut dyn FnMut(Switch),
    ) -> Result<bool, SimulationError> {
        self.inner.after_step(t, y, switched)
    }
}

/// The terrain as the user gives it: a variant written out, or table
/// points for `Terrain::table`.
#[derive(Debug, Clone)]
enum Ground {
    Given(Terrain),
    Table(Vec<(f64, f64)>),
}

impl Ground {
    /// Whether the documentation says this terrain is refused.
    fn invalid(&self) -> bool {
        match self {
            Ground::Given(Terrain::Flat { height }) => !height.is_finite(),
            Ground::Given(Terrain::Ramp {
                height,
                start,
                slope,
            }) => ![height, start, slope].iter().all(|v| v.is_finite()),
            Ground::Given(Terrain::Bump {
                centre,
                width,
                height,
            }) => ![centre, width, height].iter().all(|v| v.is_finite()),
            Ground::Given(Terrain::Sine {
                amplitude,
                wavelength,
            }) => !(amplitude.is_finite() && wavelength.is_finite()),
            Ground::Given(Terrain::Table(points)) | Ground::Table(points) => {
                points.len() < 2
                    || points.iter().any(|p| !(p.0.is_finite() && p.1.is_finite()))
                    || points.windows(2).any(|w| w[1].0 <= w[0].0)
            }
            // A profile is checked when it is made: it cannot be invalid.
            Ground::Given(Terrain::Profile(_)) => false,
        }
    }
}

/// One run's settings.
#[derive(Debug, Clone)]
struct Case {
    integrator: Integrator,
    t0: f64,
    duration: f64,
    output: Output,
    speed: f64,
    ground: Ground,
}

impl Case {
    fn t_end(&self) -> f64 {
        self.t0 + self.duration
    }

    /// Why `simulate` must refuse these settings, if it must.
    fn invalid_settings(&self) -> Option<&'static str> {
        let (t0, t_end) = (self.t0, self.t_end());
        if !(t0.is_finite() && t_end.is_finite() && t0 < t_end) {
            return Some("times");
        }
        match self.integrator {
            Integrator::Rk4 { step } | Integrator::Rosenbrock2 { step } => {
                if !(step.is_finite() && step > 0.0 && t0 + step > t0) {
                    return Some("step");
                }
            }
            Integrator::Dopri5 {
                rtol,
                atol,
                max_step,
            }
            | Integrator::Bs23 {
                rtol,
                atol,
                max_step,
            }
            | Integrator::Ros34pw2 {
                rtol,
                atol,
                max_step,
            } => {
                if !(rtol.is_finite() && atol.is_finite() && rtol >= 0.0 && atol >= 0.0)
                    || rtol + atol == 0.0
                {
                    return Some("tolerances");
                }
                if max_step.is_nan() || max_step <= 0.0 {
                    return Some("max_step");
                }
            }
            Integrator::Auto {
                explicit_tolerance,
                implicit_tolerance,
                max_step,
            } => {
                // Each tolerance is its method's rtol and atol at once.
                if ![explicit_tolerance, implicit_tolerance]
                    .iter()
                    .all(|t| t.is_finite() && *t > 0.0)
                {
                    return Some("tolerances");
                }
                if max_step.is_nan() || max_step <= 0.0 {
                    return Some("max_step");
                }
            }
        }
        match &self.output {
            Output::Every(dt) if !(dt.is_finite() && *dt > 0.0 && t0 + dt > t0) => {
                Some("output interval")
            }
            Output::Times(times)
                if times.iter().any(|t| !t.is_finite())
                    || times.windows(2).any(|w| w[1] < w[0]) =>
            {
                Some("output times")
            }
            _ => None,
        }
    }
}

/// What became of a case.
enum Outcome {
    /// The vehicle was not built.
    Refused(String),
    /// The run, and whether it ran out of budget.
    Ran(Result<Results, SimulationFailure>, bool),
}

fn run(case: &Case) -> Outcome {
    let terrain = match &case.ground {
        Ground::Given(t) => t.clone(),
        Ground::Table(points) => match Terrain::table(points.clone()) {
            Ok(t) => t,
            Err(e) => return Outcome::Refused(e.to_string()),
        },
    };
    let speed = case.speed;
    let system = match M113::system(terrain, M113::speed_drive(move |_| speed)) {
        Ok(s) => s,
        Err(e) => return Outcome::Refused(e.to_string()),
    };
    let mut system = Budgeted {
        inner: system,
        left: BUDGET,
        spent: false,
    };
    let result = simulate(
        &mut system,
        case.integrator,
        case.t0,
        case.t_end(),
        case.output.clone(),
    );
    Outcome::Ran(result, system.spent)
}

/// The first non-finite time or value of `results`, as a message.
fn first_non_finite(results: &Results) -> Option<String> {
    results.iter().find_map(|s| {
        if !s.t.is_finite() {
            return Some(format!("time {}", s.t));
        }
        s.values
            .iter()
            .zip(results.columns())
            .find(|(v, _)| !v.is_finite())
            .map(|(v, c)| format!("{c} = {v} at t = {}", s.t))
    })
}

/// The error and its causes, as one message.
fn chain(error: &SimulationError) -> String {
    match error {
        SimulationError::StepSizeUnderflow {
            cause: Some(cause), ..
        } => format!("{error} <- {}", chain(cause)),
        _ => error.to_string(),
    }
}

fn check(case: &Case) -> Result<(), TestCaseError> {
    let outcome = catch_unwind(AssertUnwindSafe(|| run(case))).map_err(|p| {
        let message = p
            .downcast_ref::<String>()
            .cloned()
            .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
            .unwrap_or_default();
        TestCaseError::fail(format!("panicked: {message}"))
    })?;
    let (result, spent) = match outcome {
        Outcome::Refused(message) => {
            // A valid terrain may still refuse the start: rough or steep
            // ground under the assembled track (`StartsInside`).
            prop_assert!(
                case.ground.invalid() || message.contains("mm inside the ground"),
                "a valid terrain was refused: {message}"
            );
            return Ok(());
        }
        Outcome::Ran(result, spent) => (result, spent),
    };
    prop_assert!(
        !case.ground.invalid(),
        "an invalid terrain was accepted: {:?}",
        case.ground
    );
    let results = match &result {
        Ok(r) => r,
        Err(f) => &f.results,
    };
    if let Some(bad) = first_non_finite(results) {
        return Err(TestCaseError::fail(format!(
            "non-finite value recorded: {bad} ({})",
            match &result {
                Ok(_) => "the run finished".to_string(),
                Err(f) => format!("the run stopped: {}", chain(&f.error)),
            }
        )));
    }
    if let Some(what) = case.invalid_settings() {
        match &result {
            Err(f) => {
                prop_assert!(
                    matches!(f.error, SimulationError::Settings(_)) && f.results.is_empty(),
                    "invalid {what}: expected a set-up error before any sample, got {} with {} samples",
                    f.error,
                    f.results.len()
                );
            }
            Ok(r) => {
                return Err(TestCaseError::fail(format!(
                    "invalid {what} accepted: a run of {} samples",
                    r.len()
                )));
            }
        }
        return Ok(());
    }
    match &result {
        Ok(r) => {
            prop_assert!(!spent, "a run that spent its budget finished");
            prop_assert!(
                case.speed.is_finite(),
                "a run with a target speed of {} finished",
                case.speed
            );
            let (t0, t_end) = (case.t0, case.t_end());
            let slack = 1e-12 * t_end.abs().max(t0.abs()).max(1.0);
            prop_assert!(
                r.times()
                    .iter()
                    .all(|&t| t >= t0 - slack && t <= t_end + slack),
                "recorded times outside [{t0}, {t_end}]"
            );
            prop_assert!(
                r.times().windows(2).all(|w| w[1] >= w[0]),
                "recorded times out of order"
            );
        }
        Err(f) => {
            let message = chain(&f.error);
            if spent {
                // The test's budget stopped it: nothing to say about why.
            } else if !case.speed.is_finite() {
                prop_assert!(
                    message.contains("target speed"),
                    "a target speed of {} stopped the run with another error: {message}",
                    case.speed
                );
            } else {
                prop_assert!(
                    !matches!(f.error, SimulationError::Settings(_)),
                    "valid settings refused: {message}"
                );
            }
        }
    }
    Ok(())
}

/// `10^e` for `e` uniform in `[lo, hi]`.
fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo..=hi).prop_map(|e| 10f64.powf(e))
}

fn tolerance() -> impl Strategy<Value = f64> {
    prop_oneof![
        40 => log_uniform(-12.0, 1.0),
        1 => Just(0.0),
        1 => Just(-1e-6),
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
    ]
}

fn max_step() -> impl Strategy<Value = f64> {
    prop_oneof![
        20 => log_uniform(-5.0, 0.0),
        10 => Just(f64::INFINITY),
        1 => Just(0.0),
        1 => Just(-0.01),
        1 => Just(f64::NAN),
    ]
}

fn fixed_step() -> impl Strategy<Value = f64> {
    prop_oneof![
        30 => log_uniform(-5.0, -2.0),
        2 => Just(1e-9),
        2 => Just(1e3),
        1 => Just(0.0),
        1 => Just(-1e-3),
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
    ]
}

fn integrator() -> impl Strategy<Value = Integrator> {
    prop_oneof![
        fixed_step().prop_map(|step| Integrator::Rk4 { step }),
        fixed_step().prop_map(|step| Integrator::Rosenbrock2 { step }),
        (tolerance(), tolerance(), max_step()).prop_map(|(rtol, atol, max_step)| {
            Integrator::Dopri5 {
                rtol,
                atol,
                max_step,
            }
        }),
        (tolerance(), tolerance(), max_step()).prop_map(|(rtol, atol, max_step)| {
            Integrator::Bs23 {
                rtol,
                atol,
                max_step,
            }
        }),
        (tolerance(), tolerance(), max_step()).prop_map(|(rtol, atol, max_step)| {
            Integrator::Ros34pw2 {
                rtol,
                atol,
                max_step,
            }
        }),
        (tolerance(), tolerance(), max_step()).prop_map(
            |(explicit_tolerance, implicit_tolerance, max_step)| Integrator::Auto {
                explicit_tolerance,
                implicit_tolerance,
                max_step,
            }
        ),
    ]
}

fn start() -> impl Strategy<Value = f64> {
    prop_oneof![
        30 => Just(0.0),
        10 => -1.0..1.0f64,
        1 => Just(1e9),
        1 => Just(1e300),
        1 => Just(f64::NAN),
    ]
}

fn duration() -> impl Strategy<Value = f64> {
    prop_oneof![
        40 => 1e-3..=0.2f64,
        2 => Just(1e-9),
        1 => Just(0.0),
        1 => Just(-0.1),
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
    ]
}

fn output() -> impl Strategy<Value = Output> {
    let time = prop_oneof![20 => -0.05..0.25f64, 1 => Just(f64::NAN), 1 => Just(f64::INFINITY)];
    prop_oneof![
        24 => Just(Output::Every(0.01)),
        8 => log_uniform(-4.0, 0.0).prop_map(Output::Every),
        2 => prop_oneof![Just(0.0), Just(-0.01), Just(f64::NAN), Just(f64::INFINITY)]
            .prop_map(Output::Every),
        4 => Just(Output::Steps),
        4 => (proptest::collection::vec(time, 0..6), any::<bool>()).prop_map(|(mut t, sort)| {
            if sort {
                t.sort_by(f64::total_cmp);
            }
            Output::Times(t)
        }),
    ]
}

fn speed() -> impl Strategy<Value = f64> {
    prop_oneof![
        30 => -20.0..20.0f64,
        3 => Just(0.0),
        2 => Just(1e9),
        2 => Just(-1e9),
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
        1 => Just(f64::NEG_INFINITY),
    ]
}

/// A finite value from `range`, or now and then NaN or infinite.
fn or_bad(range: std::ops::Range<f64>) -> impl Strategy<Value = f64> {
    prop_oneof![
        40 => range,
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
    ]
}

fn table() -> impl Strategy<Value = Vec<(f64, f64)>> {
    let point = (or_bad(-10.0..10.0), or_bad(-0.5..0.5));
    (
        proptest::collection::vec(point, 0..8),
        0..6u8,
        any::<prop::sample::Index>(),
    )
        .prop_map(|(mut points, order, dup)| {
            match order {
                // Sorted with one point repeated.
                0 if !points.is_empty() => {
                    let i = dup.index(points.len());
                    points.insert(i, points[i]);
                    points.sort_by(|a, b| a.0.total_cmp(&b.0));
                }
                // As drawn: out of order, most likely.
                1 => {}
                // Sorted, as most tables are: valid unless a point is bad
                // or there are fewer than two.
                _ => points.sort_by(|a, b| a.0.total_cmp(&b.0)),
            }
            points
        })
}

fn ground() -> impl Strategy<Value = Ground> {
    let flat = or_bad(-1.0..1.0).prop_map(|height| Terrain::Flat { height });
    let ramp = (
        or_bad(-0.5..0.5),
        or_bad(-5.0..5.0),
        prop_oneof![4 => or_bad(-0.5..0.5), 1 => Just(1e3), 1 => Just(-1e3)],
    )
        .prop_map(|(height, start, slope)| Terrain::Ramp {
            height,
            start,
            slope,
        });
    let bump = (
        or_bad(-3.0..3.0),
        prop_oneof![4 => or_bad(0.1..3.0), 1 => Just(0.0), 1 => Just(-1.0), 1 => Just(1e-9)],
        or_bad(-0.3..0.3),
    )
        .prop_map(|(centre, width, height)| Terrain::Bump {
            centre,
            width,
            height,
        });
    let sine = (
        or_bad(-0.2..0.2),
        prop_oneof![4 => or_bad(0.05..5.0), 1 => Just(0.0), 1 => Just(1e-300), 1 => Just(-1.0)],
    )
        .prop_map(|(amplitude, wavelength)| Terrain::Sine {
            amplitude,
            wavelength,
        });
    prop_oneof![
        1 => flat.prop_map(Ground::Given),
        1 => ramp.prop_map(Ground::Given),
        1 => bump.prop_map(Ground::Given),
        1 => sine.prop_map(Ground::Given),
        2 => table().prop_map(Ground::Table),
    ]
}

fn case() -> impl Strategy<Value = Case> {
    (
        integrator(),
        start(),
        duration(),
        output(),
        speed(),
        ground(),
    )
        .prop_map(|(integrator, t0, duration, output, speed, ground)| Case {
            integrator,
            t0,
            duration,
            output,
            speed,
            ground,
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn any_run_settings_finish_or_fail_typed(case in case()) {
        check(&case)?;
    }
}

// Regression tests: what the property found, case by case.

/// A flat, ramp, bump or sine terrain with a NaN or infinite parameter is
/// refused when the vehicle is built (it made NaN heights, and NaN contact
/// forces at the first step), by `Terrain::check`, by `assemble` and by
/// `VehicleSystem::new`, naming the parameter. Degenerate but finite
/// shapes stay valid: a bump of zero or negative width is no bump, a sine
/// of zero wavelength is flat.
#[test]
fn terrain_with_a_non_finite_parameter_is_refused() {
    use trackgen::assembly::{AssemblyError, assemble};
    use trackgen::terrain::TerrainError;
    use trackgen::vehicle::{ConfigError, Drive, VehicleSystem};
    use trackgen::vehicles::{m113::M113Chassis, m113::M113Track};

    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let cases = [
            (Terrain::Flat { height: bad }, "flat", "height"),
            (
                Terrain::Ramp {
                    height: bad,
                    start: 0.0,
                    slope: 0.1,
                },
                "ramp",
                "height",
            ),
            (
                Terrain::Ramp {
                    height: 0.0,
                    start: bad,
                    slope: 0.1,
                },
                "ramp",
                "start",
            ),
            (
                Terrain::Ramp {
                    height: 0.0,
                    start: 0.0,
                    slope: bad,
                },
                "ramp",
                "slope",
            ),
            (
                Terrain::Bump {
                    centre: bad,
                    width: 1.0,
                    height: 0.1,
                },
                "bump",
                "centre",
            ),
            (
                Terrain::Bump {
                    centre: 0.0,
                    width: bad,
                    height: 0.1,
                },
                "bump",
                "width",
            ),
            (
                Terrain::Bump {
                    centre: 0.0,
                    width: 1.0,
                    height: bad,
                },
                "bump",
                "height",
            ),
            (
                Terrain::Sine {
                    amplitude: bad,
                    wavelength: 1.0,
                },
                "sine",
                "amplitude",
            ),
            (
                Terrain::Sine {
                    amplitude: 0.1,
                    wavelength: bad,
                },
                "sine",
                "wavelength",
            ),
        ];
        for (terrain, kind, parameter) in cases {
            let e = terrain.check().unwrap_err();
            match e {
                TerrainError::NonFiniteParameter {
                    terrain: k,
                    parameter: p,
                    value,
                } => {
                    assert_eq!((k, p), (kind, parameter), "{terrain:?}");
                    assert!(value.is_nan() == bad.is_nan() && (value == bad || bad.is_nan()));
                }
                other => panic!("{terrain:?}: {other}"),
            }
            let built = M113::system(terrain.clone(), Drive::Free);
            let message = built.err().map(|e| e.to_string()).unwrap_or_default();
            assert!(
                message.contains(kind) && message.contains(parameter),
                "{terrain:?}: m113::system says {message:?}"
            );
            let assembled = assemble(
                &M113Track,
                &M113Chassis,
                &M113::geometry().shoe,
                &M113::geometry().sprocket,
                &terrain,
                0.0,
                0.001,
            );
            assert!(
                matches!(assembled, Err(AssemblyError::Terrain(_))),
                "{terrain:?}: assemble gives {assembled:?}"
            );
            // Assembled on good ground, simulated on the bad: refused too.
            let a = assemble(
                &M113Track,
                &M113Chassis,
                &M113::geometry().shoe,
                &M113::geometry().sprocket,
                &Terrain::Flat { height: 0.0 },
                0.0,
                0.001,
            )
            .unwrap();
            let system = VehicleSystem::new(
                M113Track,
                M113Chassis,
                &a,
                M113::geometry(),
                M113::declared_config(terrain.clone(), Drive::Free),
            );
            assert!(
                matches!(&system, Err(ConfigError::Terrain(TerrainError::NonFiniteParameter {
                    parameter: p, ..
                })) if *p == parameter),
                "{terrain:?}: VehicleSystem::new gives {:?}",
                system.err()
            );
        }
    }
    // A table built by hand, not by `Terrain::table`, is checked the same.
    assert_eq!(
        Terrain::Table(vec![(0.0, 0.0), (0.0, 1.0)]).check(),
        Err(TerrainError::OutOfOrder {
            index: 1,
            x: 0.0,
            previous: 0.0
        })
    );
    for fine in [
        Terrain::Bump {
            centre: 0.0,
            width: 0.0,
            height: 0.1,
        },
        Terrain::Bump {
            centre: 0.0,
            width: -1.0,
            height: 0.1,
        },
        Terrain::Bump {
            centre: 0.0,
            width: 1.0,
            height: -0.1,
        },
        Terrain::Sine {
            amplitude: 0.1,
            wavelength: 0.0,
        },
        Terrain::Ramp {
            height: 0.0,
            start: 2.0,
            slope: 1e3,
        },
    ] {
        assert_eq!(fine.check(), Ok(()), "{fine:?}");
        // The wall of a 1000:1 ramp right ahead of the sprocket is inside
        // the assembled track: a typed refusal of the start, not a panic.
        match M113::system(fine.clone(), Drive::Free) {
            Ok(_) => {}
            Err(e) => assert!(
                matches!(fine, Terrain::Ramp { slope, .. } if slope > 10.0)
                    && e.to_string().contains("inside the ground"),
                "{fine:?}: {e}"
            ),
        }
    }
}

/// The rows of `results` are all finite.
fn assert_finite(what: &str, results: &Results) {
    if let Some(bad) = first_non_finite(results) {
        panic!("{what}: {bad}");
    }
}

/// A target speed that is NaN or infinite, from the start or from some
/// time on, stops the run with `NonFinite` naming the target speed (it
/// recorded a NaN torque, and with an adaptive integrator shrank the step
/// to underflow on NaN derivatives); the rows before it are kept and
/// finite. A torque schedule likewise.
#[test]
fn non_finite_drive_demand_stops_the_run_typed() {
    use trackgen::vehicle::Drive;

    let names_the_target = |error: &SimulationError, what: &str| match error {
        SimulationError::NonFinite { what: w, .. } => w.contains(what),
        SimulationError::StepSizeUnderflow { cause: Some(c), .. } => {
            matches!(&**c, SimulationError::NonFinite { what: w, .. } if w.contains(what))
        }
        _ => false,
    };
    let integrators = [
        Integrator::Rk4 { step: 1e-3 },
        Integrator::Bs23 {
            rtol: 1e-3,
            atol: 1e-3,
            max_step: 0.01,
        },
    ];
    for integrator in integrators {
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            // From the start: refused at the first row, at t = 0.
            let mut system = M113::system(
                Terrain::Flat { height: 0.0 },
                M113::speed_drive(move |_| bad),
            )
            .unwrap();
            let f = simulate(&mut system, integrator, 0.0, 0.05, Output::Every(0.01)).unwrap_err();
            assert!(
                names_the_target(&f.error, "target speed"),
                "{integrator:?}, target {bad}: {}",
                f.error
            );
            assert_eq!(f.error.time(), Some(0.0), "{}", f.error);
            assert!(f.results.is_empty());

            // From t = 0.03 on: the rows before are kept.
            let target = move |t: f64| if t < 0.03 { 1.0 } else { bad };
            let mut system =
                M113::system(Terrain::Flat { height: 0.0 }, M113::speed_drive(target)).unwrap();
            let f = simulate(&mut system, integrator, 0.0, 0.05, Output::Every(0.01)).unwrap_err();
            assert!(
                names_the_target(&f.error, "target speed"),
                "{integrator:?}, target {bad} from 0.03 s: {}",
                f.error
            );
            let t = f.error.time().unwrap();
            // At the first evaluation past 0.03 s (a step's last stage,
            // 0.03 s to rounding, or a trial step beyond it).
            assert!((0.02..=0.035).contains(&t), "stopped at {t}");
            assert!(
                f.results.len() >= 3 && f.results.times().iter().all(|&r| r <= t),
                "rows at 0, 0.01, 0.02 s (and 0.03 s if reached) before the stop at {t}: {:?}",
                f.results.times()
            );
            assert_finite("rows before the NaN target", &f.results);
        }
    }
    let schedule = Drive::Torque(Box::new(|t| if t < 0.03 { 100.0 } else { f64::NAN }));
    let mut system = M113::system(Terrain::Flat { height: 0.0 }, schedule).unwrap();
    let f = simulate(
        &mut system,
        Integrator::Rk4 { step: 1e-3 },
        0.0,
        0.05,
        Output::Every(0.01),
    )
    .unwrap_err();
    assert!(names_the_target(&f.error, "torque schedule"), "{}", f.error);
    assert_finite("rows before the NaN torque", &f.results);
}

/// A speed drive whose torque limit is negative or NaN made
/// `f64::clamp` panic at the first evaluation; NaN gains made NaN torques.
/// Now the vehicle is refused when it is built, and `Drive::torque`
/// itself does not panic.
#[test]
fn speed_drive_with_a_bad_limit_or_gain_is_refused_not_a_panic() {
    use trackgen::vehicle::Drive;

    let drive = |proportional: f64, integral: f64, max_torque: f64| Drive::Speed {
        target: Box::new(|_| 1.0),
        proportional,
        integral,
        max_torque,
    };
    for (p, i, limit, mention) in [
        (3000.0, 6000.0, -1.0, "torque limit"),
        (3000.0, 6000.0, f64::NAN, "torque limit"),
        (f64::NAN, 6000.0, 2e4, "gains"),
        (3000.0, f64::INFINITY, 2e4, "gains"),
    ] {
        let built = M113::system(Terrain::Flat { height: 0.0 }, drive(p, i, limit));
        let message = built.err().map(|e| e.to_string()).unwrap_or_default();
        assert!(
            message.contains(mention),
            "gains {p}, {i}, limit {limit}: {message:?}"
        );
        let (torque, _) = drive(p, i, limit).torque(0.0, 0.0, 0.25, 0.0);
        // No panic; what the torque is does not matter.
        let _ = torque;
    }
    // An infinite limit is no limit: valid.
    assert!(
        M113::system(
            Terrain::Flat { height: 0.0 },
            drive(3000.0, 6000.0, f64::INFINITY)
        )
        .is_ok()
    );
}

/// Found at a loose tolerance (rtol 0.34), where the track jumped the
/// sprocket's teeth within 0.08 s: with no joint within 2 cm of the pitch
/// circle, the span tensions `tension_tight` and `tension_slack` were
/// recorded as NaN. Now the joint nearest the pitch circle stands for the
/// seated run. The regression is made deterministic: the assembled M113's
/// chassis is lifted 1 m off its track, so no joint is near the sprocket
/// (nor any tooth in a shoe), and the first row must be finite.
#[test]
fn span_tensions_stay_finite_when_the_track_is_off_the_teeth() {
    use trackgen::assembly::assemble;
    use trackgen::vehicle::VehicleSystem;
    use trackgen::vehicles::{m113::M113Chassis, m113::M113Track};

    let flat = Terrain::Flat { height: 0.0 };
    let start = assemble(
        &M113Track,
        &M113Chassis,
        &M113::geometry().shoe,
        &M113::geometry().sprocket,
        &flat,
        0.0,
        0.001,
    )
    .unwrap();
    let mut lifted = start;
    lifted.chassis[1] += 1.0;
    let mut system = VehicleSystem::new(
        M113Track,
        M113Chassis,
        &lifted,
        M113::geometry(),
        M113::declared_config(flat, M113::speed_drive(|_| 1.0)),
    )
    .unwrap();
    let results = simulate(
        &mut system,
        Integrator::Rk4 { step: 1e-4 },
        0.0,
        1e-4,
        Output::Every(1e-4),
    )
    .unwrap();
    let first = results.get(0).unwrap();
    assert_eq!(
        first.get("sprocket_penetration"),
        Some(0.0),
        "off the teeth"
    );
    for column in ["tension", "tension_tight", "tension_slack"] {
        let value = first.get(column).unwrap();
        assert!(value.is_finite(), "{column} = {value}");
    }
}

/// A sine of wavelength 1e-300 has slopes of 1e299: the ground forces
/// overflow, and the first row held a NaN tension. Now that row stops
/// the run with `NonFinite` at t = 0, and nothing non-finite is kept.
/// (Assembled on such ground the start is refused, `StartsInside`: the
/// vehicle is assembled on flat ground here and then put on it, to reach
/// the run.)
#[test]
fn a_terrain_that_overflows_the_contact_stops_the_run_typed() {
    use trackgen::assembly::assemble;
    use trackgen::vehicle::VehicleSystem;
    use trackgen::vehicles::{m113::M113Chassis, m113::M113Track};

    let terrain = Terrain::Sine {
        amplitude: -0.12631214995546478,
        wavelength: 1e-300,
    };
    let refused = M113::system(terrain.clone(), M113::speed_drive(|_| 1.0));
    assert!(refused.is_err_and(|e| e.to_string().contains("inside the ground")));
    let flat = assemble(
        &M113Track,
        &M113Chassis,
        &M113::geometry().shoe,
        &M113::geometry().sprocket,
        &Terrain::Flat { height: 0.0 },
        0.0,
        0.001,
    )
    .unwrap();
    let mut system = VehicleSystem::new(
        M113Track,
        M113Chassis,
        &flat,
        M113::geometry(),
        M113::declared_config(terrain, M113::speed_drive(|_| 1.0)),
    )
    .unwrap();
    let f = simulate(
        &mut system,
        Integrator::Rk4 { step: 1e-3 },
        0.0,
        0.05,
        Output::Every(0.01),
    )
    .unwrap_err();
    assert!(
        matches!(
            f.error,
            SimulationError::NonFinite { t, .. } | SimulationError::NonFiniteRecord { t, .. }
                if t == 0.0
        ),
        "{}",
        f.error
    );
    assert_finite("rows kept", &f.results);
}

/// `y' = (−y₀, 0)` from `(1, 0)`: the second component is 0 throughout.
struct Decay;

impl OdeSystem for Decay {
    fn dimension(&self) -> usize {
        2
    }

    fn derivative(&mut self, _t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), SimulationError> {
        dy[0] = -y[0];
        dy[1] = 0.0;
        Ok(())
    }
}

impl Simulated for Decay {
    fn initial_state(&self) -> DVector<f64> {
        DVector::from_vec(vec![1.0, 0.0])
    }

    fn columns(&self) -> Vec<String> {
        vec!["y0".into(), "y1".into()]
    }

    fn observe(&mut self, _t: f64, y: &[f64], row: &mut Vec<f64>) -> Result<(), SimulationError> {
        row.extend(y.iter());
        Ok(())
    }
}

/// A pure relative tolerance (`atol = 0`, which `simulate` accepts) on a
/// state with a component that is exactly 0: the error norm divided 0 by a
/// scale of 0 (NaN), so every step was rejected down to a step-size
/// underflow at t = 0, and the starting-step heuristic divided by an
/// infinite norm (a first step of 0). Now an exact zero is no error, and
/// the run finishes: `e^{−1}` to the tolerance.
#[test]
fn pure_relative_tolerance_runs_with_a_zero_component() {
    for integrator in [
        Integrator::Dopri5 {
            rtol: 1e-8,
            atol: 0.0,
            max_step: f64::INFINITY,
        },
        Integrator::Bs23 {
            rtol: 1e-6,
            atol: 0.0,
            max_step: f64::INFINITY,
        },
    ] {
        let results = simulate(&mut Decay, integrator, 0.0, 1.0, Output::Every(0.5))
            .unwrap_or_else(|f| panic!("{integrator:?}: {f}"));
        let last = results.last().unwrap();
        let y0 = last.get("y0").unwrap();
        assert!(
            (y0 - (-1f64).exp()).abs() < 1e-4 * (-1f64).exp(),
            "{integrator:?}: y(1) = {y0}"
        );
        assert_eq!(last.get("y1"), Some(0.0));
    }
}

/// `Integrator::Auto` with either tolerance zero (each is its method's
/// rtol and atol at once: zero leaves nothing) is refused before any
/// sample, by the tolerance's own name and value. It was reported as an
/// rtol/atol pair of the same number, naming neither.
#[test]
fn auto_names_the_tolerance_it_refuses() {
    for (explicit_tolerance, implicit_tolerance, name) in [
        (0.0, 1e-3, "explicit_tolerance"),
        (1e-3, f64::NAN, "implicit_tolerance"),
    ] {
        let integrator = Integrator::Auto {
            explicit_tolerance,
            implicit_tolerance,
            max_step: 0.01,
        };
        let f = simulate(&mut Decay, integrator, 0.0, 1.0, Output::Every(0.5)).unwrap_err();
        let message = f.error.to_string();
        assert!(
            matches!(f.error, SimulationError::Settings(_)) && f.results.is_empty(),
            "{message}"
        );
        assert!(message.contains(name), "{message}");
    }
}
