//! The set's work: each event at each of its parameters a task, and the
//! rows a task's answer becomes.

use std::time::Instant;

use trackgen::mobility::search::{Limit, Search};
use trackgen::mobility::turning::PivotTurn;
use trackgen::mobility::{
    EventError, EventSettings, Footprint, grade, obstacle, quantity, ride, soil,
};
use trackgen::terrain::soil::SoilPreset;
use trackgen::vehicle::Vehicle;
use trackgen_draw::vehicle;

use crate::offered::SpatialEvents;

/// Every event, in the order they are reported.
pub(super) const EVENTS: [&str; 11] = [
    "ride",
    "half-round",
    "step",
    "gap",
    "ditch",
    "barrier",
    "grade",
    "soil",
    SIDE_SLOPE,
    TURNING,
    CORNERING,
];

/// The events in the order the workers take them, the costliest first
/// (each event's longest task on the M113, 2026-12-07, in wall seconds:
/// cornering 82, ride 48, grade 34, side slope 20, half-round 20, ditch
/// 15, barrier 9, gap 9, step 5, turning 5, soil 3). Two workers taking
/// the longest first finish together; the cornering search taken last,
/// as the report's order has it, ran alone for its last minute.
const QUEUE: [&str; 11] = [
    CORNERING,
    "ride",
    "grade",
    SIDE_SLOPE,
    "half-round",
    "ditch",
    "barrier",
    "gap",
    "step",
    TURNING,
    "soil",
];

/// Where `event` stands in the workers' queue ([`QUEUE`]); an event not
/// in it last.
pub(super) fn queue_rank(event: &str) -> usize {
    QUEUE
        .iter()
        .position(|e| *e == event)
        .unwrap_or(QUEUE.len())
}

/// The side slope's event, run in 3-D.
pub(super) const SIDE_SLOPE: &str = trackgen::mobility::side_slope::EVENT;
/// The turning event, run in 3-D.
pub(super) const TURNING: &str = trackgen::mobility::turning::EVENT;
/// The cornering event, run in 3-D.
pub(super) const CORNERING: &str = trackgen::mobility::cornering::EVENT;
/// The events only a vehicle with a spatial model answers.
pub(super) const SPATIAL: [&str; 3] = [SIDE_SLOPE, TURNING, CORNERING];
/// The circle the cornering event turns on, m: a tight corner (a
/// search is some ten runs of up to 25 s simulated in 3-D; `cornering::
/// fastest` takes any radius).
const CORNERING_RADIUS: f64 = 15.0;

pub(super) fn event_name(s: &str) -> Result<&'static str, String> {
    EVENTS
        .iter()
        .find(|e| **e == s)
        .copied()
        .ok_or_else(|| format!("unknown event `{s}`: the events are {}", EVENTS.join(", ")))
}

/// One answer: a limit, a quantity at a parameter, or why there is none.
#[derive(Debug, Clone)]
pub(super) struct Row {
    pub(super) event: &'static str,
    /// What was held fixed, with its unit (`roughness 0.0254 m`), or
    /// empty.
    pub(super) parameter: Option<(&'static str, f64, &'static str)>,
    /// What was found and its unit.
    pub(super) quantity: &'static str,
    pub(super) value: f64,
    /// `=`, `>` (beyond the searched range), `<` (before it), or, without
    /// an answer, `stalled` or `failed`.
    pub(super) relation: &'static str,
    pub(super) unit: &'static str,
    pub(super) runs: usize,
    pub(super) wall: f64,
    pub(super) search: Option<Search>,
    /// The vehicle at the limit, drawn (SVG), for the searches that show
    /// it.
    pub(super) picture: Option<String>,
    /// Why there is no answer.
    pub(super) failure: Option<String>,
}

/// What a task found: a limit's search, or a curve: quantities at
/// parameters from `runs` runs.
pub(super) enum Found {
    Limit(Search),
    Curve {
        points: Vec<Point>,
        runs: usize,
        /// The search behind the first point, if it is a limit.
        search: Option<Search>,
    },
}

/// A curve's point: what was held fixed, the quantity, its value, how the
/// value stands (`=`, or why there is none) and its unit.
type Point = (Parameter, &'static str, f64, &'static str, &'static str);

/// What was held fixed: its name, value and unit.
type Parameter = Option<(&'static str, f64, &'static str)>;

/// One piece of work: an event at one parameter, and what it reports.
pub(super) struct Task<'a> {
    event: &'static str,
    parameter: Option<(&'static str, f64, &'static str)>,
    quantity: &'static str,
    unit: &'static str,
    run: Box<dyn Fn() -> Result<Found, EventError> + Send + Sync + 'a>,
}

impl<'a> Task<'a> {
    /// `run`, asked of `event` at `parameter`, answering `quantity` in
    /// `unit`.
    fn new(
        event: &'static str,
        parameter: Parameter,
        (quantity, unit): (&'static str, &'static str),
        run: Box<dyn Fn() -> Result<Found, EventError> + Send + Sync + 'a>,
    ) -> Task<'a> {
        Task {
            event,
            parameter,
            quantity,
            unit,
            run,
        }
    }
}

impl Task<'_> {
    /// Its event.
    pub(super) fn event(&self) -> &'static str {
        self.event
    }

    /// Runs it: its rows, with the wall time it took.
    pub(super) fn rows(&self) -> Vec<Row> {
        let start = Instant::now();
        let found = (self.run)();
        let wall = start.elapsed().as_secs_f64();
        let row = |value, relation, runs, search: Option<Search>, failure| Row {
            event: self.event,
            parameter: self.parameter,
            quantity: self.quantity,
            value,
            relation,
            unit: self.unit,
            runs,
            wall,
            picture: search
                .as_ref()
                .and_then(|s| s.picture.as_ref())
                .map(vehicle::picture),
            search,
            failure,
        };
        match found {
            Ok(Found::Limit(s)) => vec![row(
                s.limit.value(),
                s.limit.relation(),
                s.runs(),
                Some(s),
                None,
            )],
            Ok(Found::Curve {
                points,
                runs,
                mut search,
            }) => points
                .into_iter()
                .enumerate()
                .map(|(k, (parameter, quantity, value, relation, unit))| Row {
                    parameter,
                    quantity,
                    unit,
                    // The runs and the time are the curve's, on its first row.
                    runs: if k == 0 { runs } else { 0 },
                    wall: if k == 0 { wall } else { 0.0 },
                    ..row(value, relation, 0, search.take(), None)
                })
                .collect(),
            Err(e) => {
                let relation = match e {
                    EventError::Stalled { .. } => "stalled",
                    _ => "failed",
                };
                vec![row(f64::NAN, relation, 0, None, Some(e.to_string()))]
            }
        }
    }
}

pub(super) fn tasks<'a, V: Vehicle>(
    settings: &'a EventSettings,
    footprint: &'a Footprint,
    events: &[&'static str],
    quick: bool,
    spatial: Option<SpatialEvents>,
) -> Vec<Task<'a>> {
    const INCH: f64 = 0.0254;
    let pick = |all: &'static [f64], one: &'static [f64]| if quick { one } else { all };
    let roughnesses = pick(&[0.5, 1.0, 1.5, 2.0, 3.0, 4.0], &[1.0]);
    let heights = pick(&[4.0, 6.0, 8.0, 10.0, 12.0], &[8.0]);
    let grades = pick(&[0.1, 0.2, 0.3, 0.4, 0.5, 0.6], &[0.1]);
    let mut out: Vec<Task<'a>> = Vec::new();
    for &event in events {
        let task =
            |parameter, quantity, unit, run| Task::new(event, parameter, (quantity, unit), run);
        match event {
            "ride" => {
                for &r in roughnesses {
                    let roughness = ride::Roughness {
                        rms: r * INCH,
                        seed: 1,
                    };
                    out.push(task(
                        Some(("roughness", r * INCH, "m")),
                        "ride-limiting speed",
                        "m/s",
                        Box::new(move || {
                            ride::limiting_speed::<V>(settings, footprint, roughness)
                                .map(Found::Limit)
                        }),
                    ));
                }
            }
            "half-round" => {
                for &h in heights {
                    out.push(task(
                        Some(("height", h * INCH, "m")),
                        "speed at the peak limit",
                        "m/s",
                        Box::new(move || {
                            obstacle::half_round_speed::<V>(settings, footprint, h * INCH)
                                .map(Found::Limit)
                        }),
                    ));
                }
            }
            "step" | "gap" | "ditch" | "barrier" => {
                let (search, quantity): (fn(&EventSettings, &Footprint) -> _, _) = match event {
                    "step" => (obstacle::step::<V>, quantity::HIGHEST_STEP),
                    "gap" => (obstacle::gap::<V>, quantity::WIDEST_GAP),
                    "ditch" => (obstacle::ditch::<V>, quantity::DEEPEST_DITCH),
                    _ => (obstacle::barrier::<V>, quantity::HIGHEST_BARRIER),
                };
                out.push(task(
                    None,
                    quantity,
                    "m",
                    Box::new(move || search(settings, footprint).map(Found::Limit)),
                ));
            }
            // One task: the steepest grade first, then the speed on each
            // grade no steeper (a steady speed up a steeper one is 0: it
            // is not climbed even from a crawl at full load), so the runs
            // that would only stall are not made.
            "grade" => {
                out.push(task(
                    None,
                    quantity::TOP_SPEED,
                    "m/s",
                    Box::new(move || {
                        let run = grade::top_speed::<V>(settings, footprint)?;
                        Ok(Found::Curve {
                            points: vec![(None, quantity::TOP_SPEED, run.speed, "=", "m/s")],
                            runs: 1,
                            search: None,
                        })
                    }),
                ));
                out.push(task(
                    None,
                    quantity::STEEPEST_GRADE,
                    "rise over run",
                    Box::new(move || grade_curve::<V>(settings, footprint, grades)),
                ));
            }
            "soil" => {
                let soils: &[SoilPreset] = if quick {
                    &[SoilPreset::DrySand]
                } else {
                    &[SoilPreset::DrySand, SoilPreset::Clay]
                };
                let fractions = pick(&[0.1, 0.2, 0.3, 0.4, 0.5], &[0.2]);
                for &preset in soils {
                    out.push(task(
                        None,
                        "drawbar curve",
                        "",
                        Box::new(move || soil_curve::<V>(settings, preset, fractions)),
                    ));
                }
            }
            // `mobility` refuses a 3-D event for a vehicle without a
            // spatial model before it makes the tasks.
            SIDE_SLOPE | TURNING | CORNERING => {
                if let Some(spatial) = spatial {
                    out.extend(spatial_tasks(event, settings, spatial));
                }
            }
            _ => unreachable!("events are parsed from EVENTS"),
        }
    }
    out
}

/// The tasks of a 3-D event (`side-slope`, `turning`, `cornering`) of a
/// vehicle with a spatial model; a steer unit's turns at the first of
/// the settings' powertrain's minimum steer ratios, where it declares
/// them.
fn spatial_tasks<'a>(
    event: &'static str,
    settings: &'a EventSettings,
    events: SpatialEvents,
) -> Vec<Task<'a>> {
    let ratio = settings.powertrain.steer_ratios().first().copied();
    let task = |parameter, quantity, unit, run| Task::new(event, parameter, (quantity, unit), run);
    match event {
        SIDE_SLOPE => vec![task(
            None,
            quantity::STEEPEST_SIDE_SLOPE,
            "rise over run",
            Box::new(move || (events.side_slope)(settings).map(Found::Limit)),
        )],
        CORNERING => {
            let radius = CORNERING_RADIUS;
            vec![task(
                Some(("radius", radius, "m")),
                quantity::CORNERING_SPEED,
                "m/s",
                Box::new(move || (events.cornering)(settings, (radius, ratio)).map(Found::Limit)),
            )]
        }
        _ => vec![
            task(
                None,
                quantity::SMALLEST_TURNING_RADIUS,
                "m",
                Box::new(move || smallest_turn(events, settings, ratio)),
            ),
            task(
                None,
                quantity::PIVOT_YAW_RATE,
                "rad/s",
                Box::new(move || pivot_turn(events, settings)),
            ),
        ],
    }
}

/// The steepest grade climbed, then the speed at full power on each of
/// `grades` no steeper (a steady speed up a steeper one is 0: it is not
/// climbed even from a crawl at full load, so the runs that would only
/// stall are not made).
fn grade_curve<V: Vehicle>(
    settings: &EventSettings,
    footprint: &Footprint,
    grades: &[f64],
) -> Result<Found, EventError> {
    let steepest = grade::steepest::<V>(settings, footprint)?;
    let climbed = match steepest.limit {
        Limit::Found { passed, .. } => passed,
        Limit::Beyond { end } => end,
        Limit::Before { .. } => 0.0,
    };
    let mut runs = steepest.runs();
    let mut points = vec![(
        None,
        quantity::STEEPEST_GRADE,
        steepest.limit.value(),
        steepest.limit.relation(),
        "rise over run",
    )];
    for &g in grades {
        let parameter = Some(("grade", g, "rise over run"));
        if g > climbed {
            points.push((parameter, "speed at full power", 0.0, "stalls", "m/s"));
            continue;
        }
        let climb = grade::speed_on::<V>(settings, footprint, g)?;
        runs += 1;
        points.push((parameter, "speed at full power", climb.speed, "=", "m/s"));
    }
    Ok(Found::Curve {
        points,
        runs,
        search: Some(steepest),
    })
}

/// The motion resistance on `preset` and the slip at each drawbar load
/// (`fractions` of the weight).
fn soil_curve<V: Vehicle>(
    settings: &EventSettings,
    preset: SoilPreset,
    fractions: &[f64],
) -> Result<Found, EventError> {
    let curve = soil::drawbar_curve::<V>(settings, preset, fractions)?;
    let name = preset.name();
    let mut points = vec![(
        Some((name, 0.0, "drawbar pull / weight")),
        "motion resistance / weight",
        curve[0].resistance_coefficient(),
        if curve[0].held { "=" } else { "not held" },
        "",
    )];
    for p in &curve[1..] {
        // A load the drive could not hold is no point
        // of the soil's curve.
        points.push((
            Some((name, p.pull / curve[0].weight, "drawbar pull / weight")),
            "slip",
            if p.held && p.slip < 1.0 {
                p.slip
            } else {
                f64::NAN
            },
            // A slip of 1 or more: the load drags the
            // vehicle back, beyond what the soil holds.
            match (p.held, p.slip < 1.0) {
                (false, _) => "not held",
                (true, false) => "dragged back",
                (true, true) => "=",
            },
            "",
        ));
    }
    Ok(Found::Curve {
        runs: curve.len(),
        points,
        search: None,
    })
}

/// How a steady turn's answer stands: `=`, or `unsteady` where its yaw
/// rate had not settled by the longest run.
fn steady(run: &trackgen::mobility::turning::SteadyTurnRun) -> &'static str {
    if run.steady { "=" } else { "unsteady" }
}

/// The smallest radius at a crawl at full steer (the steer unit's
/// `ratio`, or the braked differential's), and its radius without slip.
fn smallest_turn(
    events: SpatialEvents,
    settings: &EventSettings,
    ratio: Option<f64>,
) -> Result<Found, EventError> {
    let turn = (events.smallest_radius)(settings, ratio)?;
    let parameter = Some(match ratio {
        Some(rho) => ("minimum steer ratio", rho, ""),
        None => ("inner belt held", 0.0, "m/s"),
    });
    let relation = steady(&turn.run);
    Ok(Found::Curve {
        points: vec![
            (
                parameter,
                quantity::SMALLEST_TURNING_RADIUS,
                turn.run.radius,
                relation,
                "m",
            ),
            (
                parameter,
                quantity::RADIUS_WITHOUT_SLIP,
                turn.kinematic,
                "=",
                "m",
            ),
        ],
        runs: 1,
        search: None,
    })
}

/// The pivot turn (in neutral at full steer where the settings'
/// powertrain declares steer ratios, else at the crawl's belt speeds):
/// its yaw rate and the power at both sprockets, named by the belts'
/// speed.
fn pivot_turn(events: SpatialEvents, settings: &EventSettings) -> Result<Found, EventError> {
    let PivotTurn { belts, run } = (events.pivot)(settings)?;
    let parameter = Some(("belts at ±", belts, "m/s"));
    let relation = steady(&run);
    Ok(Found::Curve {
        points: vec![
            (
                parameter,
                quantity::PIVOT_YAW_RATE,
                run.yaw_rate,
                relation,
                "rad/s",
            ),
            (
                parameter,
                quantity::PIVOT_POWER,
                (run.powers[0] + run.powers[1]) / 1e3,
                relation,
                "kW",
            ),
        ],
        runs: 1,
        search: None,
    })
}

#[cfg(test)]
mod tests {
    use super::{EVENTS, QUEUE, queue_rank};

    /// The queue holds every event once: a new event is queued where its
    /// cost puts it, not left last by default.
    #[test]
    fn the_queue_holds_every_event_once() {
        let mut queued = QUEUE.to_vec();
        let mut events = EVENTS.to_vec();
        queued.sort_unstable();
        events.sort_unstable();
        assert_eq!(queued, events);
        assert_eq!(queue_rank("no such event"), QUEUE.len());
    }
}
