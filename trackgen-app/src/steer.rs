//! How the vehicle turns, estimated from its pitch-plane model: the
//! `steer` subcommand. The vehicle at rest on flat ground gives each
//! track's ground load along its run; the general theory of skid steering
//! on firm ground ([`trackgen::steering`]) turns two such tracks a gauge
//! apart at a set of radii: the sprocket speed ratio, torques and powers
//! each turn takes, and the moment of turning resistance beside Steeds'.

use std::error::Error;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use trackgen::mobility::{EventSettings, soil};
use trackgen::scenario::Range;
use trackgen::steering::{
    SkidSteer, SteadyTurn, TrackLoad, largest_length_to_gauge, steeds_resisting_moment,
};
use trackgen::terrain::Terrain;
use trackgen::vehicle::{Vehicle, VehicleDynamics};

use crate::console::say;
use crate::offered::{Offered, TurnRuns};

/// Estimate the vehicle's steady turns on firm level ground: its two
/// tracks, each loaded as the planar model rests, a gauge apart, turned at
/// radii of 0 (a pivot), 1, 2, 5 and 10 gauges by the general theory of
/// skid steering (Wong & Chiang, 2001) with the declared shoe-on-ground
/// friction; the table and `steer.csv`.
#[derive(clap::Args, Debug)]
pub struct SteerArgs {
    /// The vehicle (the application's first by default).
    #[arg(long, value_name = "NAME")]
    pub vehicle: Option<String>,
    /// The gauge, m: the distance between the tracks' centre lines, from
    /// 0.2 to 10 (default: the vehicle's published gauge, if the
    /// application gives one).
    #[arg(long, value_name = "M", value_parser = gauge)]
    pub gauge: Option<f64>,
    /// The centre of gravity's speed in the turns, m/s, from 0.1 to 10;
    /// a pivot turns at the yaw rate that moves the tracks' centre lines
    /// at this speed.
    #[arg(long, default_value_t = 2.0, value_name = "M/S", value_parser = turn_speed)]
    pub speed: f64,
    /// The coefficient of rolling resistance, from 0 to 0.5, all of it
    /// the running gear's, lost at the belt (default: the model's own,
    /// measured holding its track at 1.5 m/s on rigid ground, which needs
    /// the vehicle's powertrain).
    #[arg(long, value_name = "F", value_parser = rolling_resistance)]
    pub rolling_resistance: Option<f64>,
    /// Also turn at this sprocket speed ratio (outer over inner), from
    /// 1.01 to 100: the turn a steer ratio of the transmission drives, its
    /// radius found (repeatable: `--ratio 2.31 --ratio 1.58`; default:
    /// the vehicle's published steer ratios, if the application gives
    /// them).
    #[arg(long = "ratio", value_name = "RATIO", value_parser = crate::cli::speed_ratio)]
    pub ratios: Vec<f64>,
    /// Also run each turn on the vehicle's spatial model (both tracks,
    /// the hull in space; a vehicle declared with a `tracks` block): its
    /// sprockets held at the theory's belt speeds, the steady turn's
    /// radius, yaw rate and torques beside the theory's, and
    /// `steer-spatial.csv`.
    #[arg(long)]
    pub spatial: bool,
    /// Output folder (created if missing); default `out/<vehicle>`.
    #[arg(long, value_name = "DIR", value_parser = crate::cli::folder)]
    pub out: Option<PathBuf>,
}

/// The radii turned, in gauges (0: the pivot turn).
pub const RADII: [f64; 5] = [0.0, 1.0, 2.0, 5.0, 10.0];

/// What a turn was asked for.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Asked {
    /// A radius, in gauges (0: the pivot).
    Radius(f64),
    /// A sprocket speed ratio, outer over inner.
    Ratio(f64),
}

impl Asked {
    /// The table's name for it.
    pub(crate) fn label(self) -> String {
        match self {
            Asked::Radius(0.0) => "pivot".to_string(),
            Asked::Radius(r) => format!("R/B {r}"),
            Asked::Ratio(k) => format!("ratio {k}"),
        }
    }
}

/// `steer` for the vehicle `V`: exits 1, saying why, when the rest, the
/// resistance or a turn cannot be found or the table cannot be written.
pub fn main<V: Vehicle>(entry: &Offered, args: &SteerArgs) -> ExitCode {
    let dir = args
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from("out").join(entry.name()));
    match estimate::<V>(entry, args, &dir) {
        Ok(file) => {
            say!("wrote {}", dir.join(file).display());
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn estimate<V: Vehicle>(
    entry: &Offered,
    args: &SteerArgs,
    dir: &Path,
) -> Result<&'static str, Box<dyn Error>> {
    let gauge = args.gauge.or(entry.gauge).ok_or_else(|| {
        format!(
            "the vehicle `{}` has no published gauge: give one with `--gauge` (or `Entry::gauge`)",
            entry.name()
        )
    })?;
    let mut system = V::system(Terrain::Flat { height: 0.0 }, V::speed_drive(|_| 0.0))?;
    let (rest, _) = crate::modes::find_rest(&mut system)?;
    let friction = system.config().ground.friction.mu();
    let points = system.ground_loads(rest.t, rest.state.as_slice())?;
    // At rest on level ground the loads' centre is under the centre of
    // gravity: nothing else acts along the hull or turns it.
    let load: f64 = points.iter().map(|p| p.1).sum();
    let centre = points.iter().map(|p| p.0.x * p.1).sum::<f64>() / load;
    let along: Vec<(f64, f64)> = points.iter().map(|p| (p.0.x - centre, p.1)).collect();
    let run = TrackLoad::from_points(0.5 * gauge, &along);
    let rolling_resistance = match args.rolling_resistance {
        Some(f) => f,
        None => {
            let settings = EventSettings::new(entry.engine().map_err(|e| {
                format!("{e}; or give the rolling resistance with `--rolling-resistance`")
            })?);
            let point = soil::motion_resistance::<V>(&settings)?;
            say!(
                "rolling resistance {:.4} of the weight: the model's own, holding its track at {} m/s on rigid ground",
                point.resistance_coefficient(),
                soil::TRACK_SPEED
            );
            point.resistance_coefficient()
        }
    };
    let vehicle = SkidSteer {
        // Both sides' mass, under the model's own gravity.
        mass: 2.0 * rest.weight
            / <V::System as VehicleDynamics>::track_description()
                .gravity
                .norm(),
        friction,
        // On rigid ground the model loses only in its running gear, at
        // the belt: none of it is the ground's.
        rolling_resistance: 0.0,
        belt_resistance: rolling_resistance,
        tracks: [run.clone(), run.mirrored()],
    };
    let length = run.length();
    let steeds = steeds_resisting_moment(friction, vehicle.load(), length);
    let largest = largest_length_to_gauge(friction, rolling_resistance, friction);
    say!(
        "{}: two tracks {gauge:.3} m apart, each loaded as the planar model rests ({:.1} kN over {length:.3} m); shoe on ground μ {friction}",
        entry.name(),
        run.load() / 1e3
    );
    say!(
        "length over gauge {:.3}: the simplified theory (Steeds) steers up to 2 (μ − f_r)/μ = {largest:.3}: {}",
        length / gauge,
        if length / gauge <= largest {
            "it steers"
        } else {
            "it does not steer"
        }
    );
    let sprocket = system.sprocket_rolling_radius();
    let mut turns = Vec::new();
    for &radius in &RADII {
        let turn = if radius == 0.0 {
            vehicle.turn(args.speed / (0.5 * gauge), 0.0)?
        } else {
            vehicle.turn(args.speed / (radius * gauge), args.speed)?
        };
        turns.push((Asked::Radius(radius), turn));
    }
    let ratios = if args.ratios.is_empty() {
        entry
            .powertrain
            .as_ref()
            .map_or(&[][..], |p| p.steer_ratios())
    } else {
        &args.ratios
    };
    for &ratio in ratios {
        // Turning left: the left belt is the inner; their mean is about
        // the speed asked.
        let outer = 2.0 * args.speed / (1.0 + 1.0 / ratio);
        turns.push((Asked::Ratio(ratio), vehicle.drive([outer / ratio, outer])?));
    }
    say!(
        "  asked        radius m   yaw rad/s   ratio (kinematic)   slip out/in     torque out/in kN m   power out/in kW   M_r / Steeds"
    );
    for (asked, turn) in &turns {
        let [outer, inner] = turn.outer_inner();
        say!(
            "  {:10}   {:8.3}   {:9.4}   {:7.3} ({:>7})   {:6.3} {:7.3}   {:8.2} {:8.2}   {:7.1} {:7.1}   {:.3}",
            asked.label(),
            turn.radius,
            turn.yaw_rate,
            turn.speed_ratio(),
            kinematic(turn, gauge).map_or("-1".to_string(), |k| format!("{k:.3}")),
            outer.slip,
            inner.slip,
            outer.sprocket_force() * sprocket / 1e3,
            inner.sprocket_force() * sprocket / 1e3,
            outer.power / 1e3,
            inner.power / 1e3,
            turn.resisting_moment / steeds
        );
    }
    if let Some(powertrain) = &entry.powertrain {
        let stall = powertrain.limit(0.0).0;
        let most = turns
            .iter()
            .map(|(_, t)| t.outer_inner()[0].sprocket_force() * sprocket)
            .fold(0.0, f64::max);
        say!(
            "the powertrain gives a sprocket at most {:.2} kN m at a crawl: the outer sprocket's largest above is {:.0} % of it",
            stall / 1e3,
            100.0 * most / stall
        );
    }
    std::fs::create_dir_all(dir).map_err(|e| format!("creating {}: {e}", dir.display()))?;
    write_csv(&dir.join("steer.csv"), &turns, gauge, sprocket, steeds)?;
    if args.spatial {
        let run = entry.turn_runs.ok_or_else(|| {
            format!(
                "the vehicle `{}` has no spatial model: declare it with a `tracks` block and \
                 offer it with `Entry::of_spatial`",
                entry.name()
            )
        })?;
        compare_in_space(run, &turns, sprocket, &dir.join("steer-spatial.csv"))?;
        return Ok("steer.csv and steer-spatial.csv");
    }
    Ok("steer.csv")
}

/// The speed ratio with no slip, `(R + B/2)/(R − B/2)` at the turn's
/// radius (`None` for a pivot, where it is −1).
fn kinematic(turn: &SteadyTurn, gauge: f64) -> Option<f64> {
    let r = turn.radius;
    (turn.velocity.x != 0.0).then(|| (r + 0.5 * gauge) / (r - 0.5 * gauge))
}

fn write_csv(
    path: &Path,
    turns: &[(Asked, SteadyTurn)],
    gauge: f64,
    sprocket: f64,
    steeds: f64,
) -> Result<(), Box<dyn Error>> {
    let mut w = csv::Writer::from_path(path)?;
    w.write_record([
        "radius_over_gauge_asked",
        "speed_ratio_asked",
        "radius",
        "yaw_rate",
        "speed",
        "sideslip_speed",
        "speed_ratio",
        "kinematic_speed_ratio",
        "outer_belt_speed",
        "inner_belt_speed",
        "outer_slip",
        "inner_slip",
        "outer_thrust",
        "inner_thrust",
        "outer_sprocket_torque",
        "inner_sprocket_torque",
        "outer_power",
        "inner_power",
        "friction_dissipation",
        "rolling_loss",
        "resisting_moment",
        "steeds_moment",
    ])?;
    for (asked, turn) in turns {
        let [outer, inner] = turn.outer_inner();
        let (radius, ratio) = match asked {
            Asked::Radius(r) => (*r, f64::NAN),
            Asked::Ratio(k) => (f64::NAN, *k),
        };
        let row = [
            radius,
            ratio,
            turn.radius,
            turn.yaw_rate,
            turn.velocity.x,
            turn.velocity.y,
            turn.speed_ratio(),
            kinematic(turn, gauge).unwrap_or(-1.0),
            outer.belt_speed,
            inner.belt_speed,
            outer.slip,
            inner.slip,
            outer.thrust,
            inner.thrust,
            outer.sprocket_force() * sprocket,
            inner.sprocket_force() * sprocket,
            outer.power,
            inner.power,
            turn.dissipation,
            turn.rolling_loss,
            turn.resisting_moment,
            steeds,
        ];
        // Not asked: an empty field.
        w.write_record(row.iter().map(|v| {
            if v.is_nan() {
                String::new()
            } else {
                format!("{v}")
            }
        }))?;
    }
    w.flush()?;
    Ok(())
}

fn gauge(s: &str) -> Result<f64, String> {
    crate::cli::within(s, Range::closed(0.2, 10.0, "from 0.2 to 10 m"), "a gauge")
}

fn turn_speed(s: &str) -> Result<f64, String> {
    crate::cli::within(s, Range::closed(0.1, 10.0, "from 0.1 to 10 m/s"), "a speed")
}

fn rolling_resistance(s: &str) -> Result<f64, String> {
    crate::cli::within(
        s,
        Range::closed(0.0, 0.5, "from 0 to 0.5"),
        "a rolling resistance",
    )
}

/// Runs each of the theory's `turns` on the spatial model by `run`
/// (turning left: the right belt the outer, at the theory's belt
/// speeds), prints what each run showed beside the theory and writes
/// `file`; the theory's torques are its shear times the sprockets'
/// rolling radius `sprocket` (m). A run that fails is reported as failed
/// and the others kept.
fn compare_in_space(
    run: TurnRuns,
    turns: &[(Asked, SteadyTurn)],
    sprocket: f64,
    file: &std::path::Path,
) -> Result<(), Box<dyn std::error::Error>> {
    let belts: Vec<[f64; 2]> = turns
        .iter()
        .map(|(_, turn)| {
            let [outer, inner] = turn.outer_inner();
            [outer.belt_speed, inner.belt_speed]
        })
        .collect();
    say!(
        "the same turns in 3-D (both tracks, the hull in space; each sprocket held at the theory's belt speed, settled {} s, ramped over {} s, averaged over {} s once two such stretches' yaw rates agree to 1 %):",
        trackgen::mobility::turning::SETTLE,
        trackgen::mobility::turning::RAMP,
        trackgen::mobility::turning::WINDOW
    );
    say!(
        "  asked        radius m (theory)    yaw rad/s (theory)    torque out/in kN m (theory)          power out/in kW   steady by"
    );
    let runs = run(&belts);
    let mut w = csv::Writer::from_path(file)?;
    w.write_record([
        "asked",
        "outer_belt_speed",
        "inner_belt_speed",
        "radius",
        "theory_radius",
        "yaw_rate",
        "theory_yaw_rate",
        "outer_sprocket_torque",
        "theory_outer_sprocket_torque",
        "inner_sprocket_torque",
        "theory_inner_sprocket_torque",
        "outer_power",
        "inner_power",
        "until",
        "steady",
    ])?;
    for ((asked, turn), ran) in turns.iter().zip(runs) {
        let [outer, inner] = turn.outer_inner();
        let theory = [
            outer.sprocket_force() * sprocket,
            inner.sprocket_force() * sprocket,
        ];
        let ran = match ran {
            Ok(ran) => ran,
            Err(e) => {
                say!("  {:10}   the run failed: {e}", asked.label());
                continue;
            }
        };
        // The run's torques in the theory's sense: driving forward positive.
        let torque = [-ran.torques[0], -ran.torques[1]];
        say!(
            "  {:10}   {:8.3} ({:7.3})   {:8.4} ({:8.4})   {:7.2} {:7.2} ({:7.2} {:7.2})   {:7.1} {:7.1}   {}",
            asked.label(),
            ran.radius,
            turn.radius,
            ran.yaw_rate,
            turn.yaw_rate,
            torque[0] / 1e3,
            torque[1] / 1e3,
            theory[0] / 1e3,
            theory[1] / 1e3,
            ran.powers[0] / 1e3,
            ran.powers[1] / 1e3,
            if ran.steady {
                format!("{:.1} s", ran.until)
            } else {
                format!("not steady by {:.0} s", ran.until)
            }
        );
        let row = [
            ran.belts[0],
            ran.belts[1],
            ran.radius,
            turn.radius,
            ran.yaw_rate,
            turn.yaw_rate,
            torque[0],
            theory[0],
            torque[1],
            theory[1],
            ran.powers[0],
            ran.powers[1],
            ran.until,
            if ran.steady { 1.0 } else { 0.0 },
        ];
        let mut record = vec![asked.label()];
        record.extend(row.iter().map(|v| format!("{v}")));
        w.write_record(record)?;
    }
    w.flush()?;
    Ok(())
}
