//! The mirrored light carrier (`Twin`) driven straight in 3-D over a bump
//! across its whole width, against the planar model of one of its sides
//! driven the same way: both start from the same assembled rest, settle,
//! ramp their belts to 2 m/s and cross a cosine bump 60 mm high and 1 m
//! long. The spatial run must reproduce the planar one (#41's check:
//! pitch within 1 mrad, heave within 0.5 mm, sprocket torque within
//! 0.5 %), and by symmetry neither roll, yaw nor drift sideways (below
//! 1e-9).
//!
//! The two are separate programs: the planar vehicle's generated closed
//! chain with coordinate partitioning and its planar contacts, against
//! the three floating trees, the ground split across the shoe's width and
//! the contacts in space. Their right-hand sides agree to 1e-9 at a state
//! (`spatial_dynamics`); this is the same over a run, through the
//! integrator, the drive controllers and the bump. Both are integrated by
//! Bogacki-Shampine at 1e-6 with steps of at most 1 ms, so each run's own
//! error is far below the bounds, and the bounds measure the models.
//!
//! The same carrier through an engine's envelope (a power and a torque
//! cap per side, [`EngineEnvelope`]) accelerates along the planar run's
//! line until the power caps it, both with a drive on each side and
//! through a differential (which takes twice a side's cap at the
//! sprockets' mean speed). Through an engine whose speed is a state
//! ([`SpatialEngine`]: the governor, the converter, the scheduled ranges
//! and the lock-up on the differential's box) it runs as the planar side
//! through the same engine, its half: the engine's speed, the shifts and
//! the lock-up as well. Pulled back by a drawbar load in dry sand, it
//! runs as its side pulled by half the load.

use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::spatial_vehicle::{
    Differential, Driveline, EngineEnvelope, FullSteer, SideDrives, SpatialEngine, SpatialLaws,
    SpatialSimulated, SpatialVehicleSystem,
};
use trackgen::system::Simulated;
use trackgen::terrain::Terrain;
use trackgen::terrain::field::{FieldShape, HeightField};
use trackgen::terrain::soil::SoilPreset;
use trackgen::vehicle::{Drive, Powertrain, Vehicle, VehicleConfig, build, speed_ramp};

use crate::support::twin::Twin;

/// When the belts start, s; how long they take to reach the speed, s; the
/// speed, m/s.
const SETTLE: f64 = 0.5;
const RAMP: f64 = 1.0;
const SPEED: f64 = 2.0;
/// How long each run lasts, s: the rear idler leaves the bump by 3.9 s.
const DURATION: f64 = 4.4;
/// The rows' interval, s.
const EVERY: f64 = 0.01;

/// The bump across the whole width: 60 mm high, 1 m long, its crest 2.5 m
/// ahead of the sprocket's start.
fn course() -> Terrain {
    Terrain::Bump {
        centre: 2.5,
        width: 1.0,
        height: 0.06,
    }
}

/// Bogacki-Shampine at 1e-6, steps of at most 1 ms.
const METHOD: Integrator = Integrator::Bs23 {
    rtol: 1e-6,
    atol: 1e-6,
    max_step: 1e-3,
};

/// What both runs show at a row: the frame's height (m), its pitch (rad),
/// each sprocket's torque (N m, planar sense) and speed (rad/s), and, from
/// the spatial run, the roll, the heading and the sideways place of the
/// hull (rad, rad, m).
#[derive(Debug, Clone, Copy, Default)]
struct Row {
    height: f64,
    pitch: f64,
    torque: [f64; 2],
    speed: [f64; 2],
    forward: f64,
    across: [f64; 3],
    /// The engine's speed (rad/s), its range (from 1) and its lock-up (1
    /// or 0), through an engine whose speed is a state (NaN else).
    engine: [f64; 3],
    /// The work the drawbar load has taken out, J (the spatial run's
    /// books; 0 in the planar run's rows).
    drawbar: f64,
}

/// The planar side on `terrain` driven by `drive`, a configuration change
/// first: its rows.
fn planar(drive: Drive, change: impl FnOnce(&mut VehicleConfig)) -> Vec<Row> {
    let mut config = Twin::declared_config(course(), drive);
    change(&mut config);
    let mut system = build::<Twin>(config).expect("builds");
    let columns = system.columns();
    let at = |name: &str| {
        columns
            .iter()
            .position(|c| c == name)
            .unwrap_or_else(|| panic!("no column {name}"))
    };
    let (y_at, pitch_at, x_at) = (at("y"), at("pitch"), at("x"));
    let (torque_at, speed_at) = (at("sprocket_torque"), at("sprocket_speed"));
    let engine_at = [at("engine_speed"), at("gear"), at("locked")];
    let mut y = system.initial_state();
    let mut stepper = METHOD.stepper(system.dimension());
    let (mut t, mut rows, mut row) = (0.0, Vec::new(), Vec::new());
    for k in 0..=(DURATION / EVERY).round() as usize {
        let next = k as f64 * EVERY;
        while t < next {
            stepper
                .step(&mut system, &mut t, &mut y, next)
                .expect("steps");
            if system
                .after_step(t, y.as_mut_slice(), &mut |_| {})
                .expect("after a step")
            {
                stepper.restart();
            }
        }
        row.clear();
        system.observe(t, y.as_slice(), &mut row).expect("observes");
        rows.push(Row {
            height: row[y_at],
            pitch: row[pitch_at],
            torque: [row[torque_at]; 2],
            speed: [row[speed_at]; 2],
            forward: row[x_at],
            across: [0.0; 3],
            engine: engine_at.map(|i| row[i]),
            drawbar: 0.0,
        });
    }
    rows
}

/// The spatial vehicle on the bump extruded across the width, driven
/// through `driveline` (and an engine's `envelope`): its rows.
fn spatial(driveline: Driveline, envelope: Option<EngineEnvelope>) -> Vec<Row> {
    spatial_under(Twin::declared_laws(), driveline, envelope, 0.0)
}

/// [`spatial`] under `laws`, a drawbar load of `pull` (N) on the hull.
fn spatial_under(
    laws: SpatialLaws,
    driveline: Driveline,
    envelope: Option<EngineEnvelope>,
    pull: f64,
) -> Vec<Row> {
    let field = HeightField {
        base: FieldShape::Profile(course()),
        ..HeightField::level()
    };
    let mut system = Twin::spatial(laws, field).expect("the spatial vehicle");
    let mut y = system.assembled(&course()).expect("assembled");
    system.set_driveline(driveline).expect("a driveline");
    system.set_envelope(envelope);
    system.set_drawbar_pull(pull).expect("a pull");
    system.start_engine(y.as_mut_slice());
    let mut stepper = METHOD.stepper(system.dimension());
    let (mut t, mut rows) = (0.0, Vec::new());
    for k in 0..=(DURATION / EVERY).round() as usize {
        let next = k as f64 * EVERY;
        while t < next {
            stepper
                .step(&mut system, &mut t, &mut y, next)
                .expect("steps");
            if system.after_step(t, y.as_slice()) {
                stepper.restart();
            }
        }
        let out = system.outputs(t, y.as_slice()).expect("outputs");
        let (hull, ..) = system.states(y.as_slice());
        let root = hull.pose.origin;
        rows.push(Row {
            height: root.z,
            pitch: out.pitch,
            torque: [out.sides[0].sprocket_torque, out.sides[1].sprocket_torque],
            speed: [out.sides[0].sprocket_speed, out.sides[1].sprocket_speed],
            forward: root.x,
            across: [out.roll, out.heading, root.y],
            engine: match out.engine {
                Some(e) => [
                    e.engine_speed,
                    out.gear,
                    f64::from(u8::from(e.locked == Some(true))),
                ],
                None => [f64::NAN; 3],
            },
            drawbar: system.energy(y.as_slice()).drawbar,
        });
    }
    rows
}

/// Each row's height from the first row's.
fn heaved(rows: &mut [Row]) {
    let start = rows[0].height;
    for r in rows {
        r.height -= start;
    }
}

/// The largest difference between the two runs' `what`, each row's
/// (scaled by `scale`).
fn largest(planar: &[Row], spatial: &[Row], what: impl Fn(&Row) -> f64) -> f64 {
    planar
        .iter()
        .zip(spatial)
        .map(|(p, s)| (what(p) - what(s)).abs())
        .fold(0.0, f64::max)
}

fn speed_drive() -> Drive {
    Twin::speed_drive(speed_ramp(SETTLE, RAMP, SPEED))
}

/// How far apart two runs are: the frame's heave (m) and pitch (rad),
/// each sprocket's torque (N m), the hull's place along (m); and the
/// planar run's largest torque (N m) and rise (m).
#[derive(Debug)]
struct Apart {
    heave: f64,
    pitch: f64,
    torque: [f64; 2],
    forward: f64,
    most_torque: f64,
    rise: f64,
}

fn apart(mut plane: Vec<Row>, mut space: Vec<Row>) -> Apart {
    heaved(&mut plane);
    heaved(&mut space);
    let start = [plane[0].forward, space[0].forward];
    let apart = Apart {
        heave: largest(&plane, &space, |r| r.height),
        pitch: largest(&plane, &space, |r| r.pitch),
        torque: [0, 1].map(|s| largest(&plane, &space, |r| r.torque[s])),
        forward: plane
            .iter()
            .zip(&space)
            .map(|(p, s)| ((p.forward - start[0]) - (s.forward - start[1])).abs())
            .fold(0.0, f64::max),
        most_torque: plane.iter().map(|r| r.torque[0].abs()).fold(0.0, f64::max),
        rise: plane.iter().map(|r| r.height).fold(0.0, f64::max),
    };
    println!("{apart:?}");
    let asymmetry = space
        .iter()
        .flat_map(|r| r.across)
        .map(f64::abs)
        .fold(0.0, f64::max);
    println!("roll, heading and sideways place at most {asymmetry:.1e}");
    assert!(
        asymmetry <= 1e-9,
        "the mirrored run leaves its plane: {asymmetry}"
    );
    apart
}

/// #41's bounds: pitch within 1 mrad, heave within 0.5 mm, each
/// sprocket's torque within 0.5 % of the largest.
fn within_bounds(apart: &Apart) {
    assert!(
        apart.rise > 0.01,
        "the bump lifts the frame: {} m",
        apart.rise
    );
    models_agree(apart);
}

/// The models' part of [`within_bounds`]: the heave, pitch and torques.
fn models_agree(apart: &Apart) {
    assert!(apart.heave <= 0.5e-3, "heave apart by {} m", apart.heave);
    assert!(apart.pitch <= 1e-3, "pitch apart by {} rad", apart.pitch);
    for t in apart.torque {
        assert!(
            t <= 5e-3 * apart.most_torque,
            "sprocket torque apart by {t} N m of {}",
            apart.most_torque
        );
    }
}

/// The planar side and the spatial vehicle on dry sand, each on its
/// speed drives, the spatial hull pulled back by a drawbar load of `pull`
/// (N) and the planar chassis by half of it: their rows.
fn on_sand(pull: f64) -> (Vec<Row>, Vec<Row>) {
    let soil = SoilPreset::DrySand.soil();
    let plane = planar(speed_drive(), |c| {
        c.soil = Some(soil);
        c.drawbar_pull = 0.5 * pull;
    });
    let sides = Driveline::Sides(SideDrives {
        right: speed_drive(),
        left: speed_drive(),
    });
    let laws = SpatialLaws {
        soil: Some(soil),
        ..Twin::declared_laws()
    };
    (plane, spatial_under(laws, sides, None, pull))
}

/// On soft soil (dry sand, Wong's Table 2.3) the same: the planar side's
/// soft ground (Bekker's pressure on each point's patch, the shear along
/// the surface, the rut along `x`) against the spatial vehicle's soil at
/// two points across each shoe, each with half the patch, its shear
/// displacement a vector and its rut an area; the soil pressed after
/// every step in both. Both sink some 7 cm at speed, then the bump
/// lifts the frame out of its settled height.
#[test]
fn a_mirrored_vehicle_crosses_a_bump_in_soft_soil_as_the_planar_one() {
    let (plane, space) = on_sand(0.0);
    let driving = ((SETTLE + RAMP) / EVERY).round() as usize;
    let settled = plane[driving].height;
    let (sunk, lifted) = (
        plane[0].height - settled,
        plane[driving..]
            .iter()
            .map(|r| r.height)
            .fold(f64::MIN, f64::max)
            - settled,
    );
    println!("sunk {sunk:.4} m at speed, lifted by the bump {lifted:.4} m");
    assert!(sunk > 0.03, "the soil bears the carrier at {sunk} m");
    assert!(lifted > 0.005, "the bump lifts the frame by {lifted} m");
    models_agree(&apart(plane, space));
}

/// A drawbar load in dry sand: the spatial carrier pulled back by 7 kN
/// (a fifth of its weight) against its planar side pulled by half that,
/// both from the start, the belts driven to 2 m/s over the bump. The two
/// agree to the same bounds (10 N m of 2 877 apart at 1e-6, 9 N m at
/// 1e-7: the models', not the integration's); the drawbar's work in the
/// spatial books is the pull times the hull's centroid's travel along
/// `x` (its heading, straight: `∫ P (ĥ · v) dt = P Δx`), to 1e-7 of it
/// (measured 1e-8 or less: the quadrature's own error).
#[test]
fn a_mirrored_vehicle_pulls_a_drawbar_load_in_soft_soil_as_the_planar_one() {
    const PULL: f64 = 7e3;
    let (plane, space) = on_sand(PULL);
    let (first, last) = (space[0], space[space.len() - 1]);
    let travel = last.forward - first.forward;
    let work = last.drawbar - first.drawbar;
    println!(
        "pulled {travel:.4} m: the drawbar's work {work:.3} J against P Δx {:.3} J",
        PULL * travel
    );
    assert!(travel > 3.0, "the carrier pulls its load {travel} m");
    assert!(
        (work - PULL * travel).abs() <= 1e-7 * PULL * travel,
        "the drawbar's work {work} J against P Δx = {} J",
        PULL * travel
    );
    models_agree(&apart(plane, space));
}

#[test]
fn a_mirrored_vehicle_crosses_a_bump_as_the_planar_one() {
    let plane = planar(speed_drive(), |_| {});
    let space = spatial(
        Driveline::Sides(SideDrives {
            right: speed_drive(),
            left: speed_drive(),
        }),
        None,
    );
    within_bounds(&apart(plane, space));
}

/// A side's power, W, and torque, N m: the torque caps the start (1.2
/// m/s² where the belts ask 2), the power from 1.3 m/s.
const POWER: f64 = 3e3;
const MAX_TORQUE: f64 = 400.0;

/// Through an engine's envelope (a power and torque limit), with a drive
/// on each side and through a differential with a steer unit asked to go
/// straight: the envelope caps the drive as the planar one's caps its
/// side, so the runs agree to the same bounds, and the hull's place
/// along to 1 mm. The planar run's driving torque reaches the cap and
/// never passes it (the torque cap from 0.6 s, the power's from 2.0 s
/// until the belts reach 2 m/s at 3.4 s).
#[test]
fn a_mirrored_vehicle_on_an_engine_s_envelope_runs_as_the_planar_one() {
    let powertrain = Powertrain::Power {
        power: POWER,
        max_torque: MAX_TORQUE,
    };
    let plane = planar(speed_drive(), |c| c.powertrain = Some(powertrain.clone()));
    let cap = |r: &Row| MAX_TORQUE.min(POWER / r.speed[0].abs());
    // Driving (the torque the way the sprocket turns); braking past the
    // target is the brakes', not the engine's.
    let over = plane
        .iter()
        .filter(|r| r.torque[0] * r.speed[0] > 0.0)
        .map(|r| r.torque[0].abs() - cap(r))
        .fold(f64::NEG_INFINITY, f64::max);
    println!("the planar torque's largest excess over the cap: {over:.3e} N m");

    assert!(over <= 1e-9 * MAX_TORQUE, "the cap is passed by {over} N m");
    assert!(
        over >= -1e-6 * MAX_TORQUE,
        "the cap never bites: {over} N m"
    );
    let envelope = || Some(EngineEnvelope::new(powertrain.clone()).expect("an envelope"));
    let sides = Driveline::Sides(SideDrives {
        right: speed_drive(),
        left: speed_drive(),
    });
    let differential = Driveline::Differential(
        Differential::with_steer_unit(
            &speed_drive(),
            Box::new(speed_ramp(SETTLE, RAMP, SPEED)),
            FullSteer::Ratio(2.0),
        )
        .expect("a speed drive"),
    );
    for (what, driveline) in [("sides", sides), ("differential", differential)] {
        println!("{what}:");
        let apart = apart(plane.clone(), spatial(driveline, envelope()));
        within_bounds(&apart);
        assert!(
            apart.forward <= 1e-3,
            "{what}: apart along by {} m",
            apart.forward
        );
    }
}

/// The M113A3's engine, converter and ranges with a final drive of
/// [`FINAL_DRIVE`]: on the light carrier at 2 m/s it shifts from the
/// first range to the second and locks up there, so that the run crosses
/// every law of the engine.
const FINAL_DRIVE: f64 = 12.0;

/// Through an engine whose speed is a state, on the differential's box
/// with its steer unit asked to go straight, against the planar side
/// through the same engine (its share, a half, as the box's halves): the
/// same bounds, the hull's place along within 1 mm, the engine's speed
/// within 1e-4 of its largest (measured 6e-7: the two models' states
/// agree to about 1e-6 over the run), and the same range and lock-up at
/// every row but those a shift or the clutch's step falls between (at
/// most two rows each; measured none). Both runs shift from the first
/// range to the second and the third, and lock up (briefly, in the
/// second).
#[test]
fn a_mirrored_vehicle_through_an_engine_whose_speed_is_a_state_runs_as_the_planar_one() {
    let mut powertrain = trackgen::vehicles::m113::powertrain();
    if let Powertrain::Converter(d) = &mut powertrain {
        d.final_drive = FINAL_DRIVE;
        d.shift = None;
    }
    let plane = planar(speed_drive(), |c| c.powertrain = Some(powertrain.clone()));
    let mut differential = Differential::with_steer_unit(
        &speed_drive(),
        Box::new(speed_ramp(SETTLE, RAMP, SPEED)),
        FullSteer::Ratio(2.0),
    )
    .expect("a speed drive");
    differential.engine = Some(SpatialEngine::new(powertrain).expect("an engine with dynamics"));
    let space = spatial(Driveline::Differential(differential), None);
    for (what, rows) in [("planar", &plane), ("spatial", &space)] {
        let ranges: Vec<f64> = rows.iter().map(|r| r.engine[1]).collect();
        let locked = rows.iter().filter(|r| r.engine[2] == 1.0).count();
        println!(
            "{what}: ranges {:?}, locked at {locked} rows",
            ranges.iter().fold(Vec::new(), |mut v: Vec<f64>, &g| {
                if v.last() != Some(&g) {
                    v.push(g);
                }
                v
            })
        );
        assert!(
            ranges.contains(&2.0),
            "{what}: no shift to the second range"
        );
        assert!(locked > 0, "{what}: never locks up");
    }
    let most = plane.iter().map(|r| r.engine[0]).fold(0.0, f64::max);
    let engine = largest(&plane, &space, |r| r.engine[0]);
    println!("the engine's speed apart by {engine:.3e} rad/s of {most:.1}");
    assert!(
        engine <= 1e-4 * most,
        "the engine's speed apart by {engine} rad/s"
    );
    for (k, what) in [(1, "range"), (2, "lock-up")] {
        let differ = plane
            .iter()
            .zip(&space)
            .filter(|(p, s)| p.engine[k] != s.engine[k])
            .count();
        assert!(differ <= 2, "the {what} differs at {differ} rows");
    }
    let apart = apart(plane, space);
    within_bounds(&apart);
    assert!(apart.forward <= 1e-3, "apart along by {} m", apart.forward);
}
