//! Soils (Bekker–Wong: Wong, *Theory of Ground Vehicles*, 4th ed., 2008,
//! ch. 2; NRMM's drawbar and motion-resistance figures; the guide's "Soft
//! soil" and "Mobility events"): drawbar
//! pull against slip, and the motion resistance, on a soft soil.
//!
//! These measure the soil and the running gear, not the engine: the
//! track's mean speed is held at [`TRACK_SPEED`] by the speed controller
//! (its own torque limit, no powertrain), as a drawbar test holds a
//! vehicle's track speed while the load is raised. Each run starts at
//! rest, the track speed ramped up over the first second, and lasts
//! [`HOLD`] s; its figures are means over the last [`STEADY`] s. In
//! steady motion the drawbar pull equals the load applied.

use super::runs::run_config;
use super::{EventError, EventSettings};
use crate::scenario::{Scenario, Soil};
use crate::simulate::{Sink, SinkError};
use crate::terrain::Terrain;
use crate::terrain::soil::SoilPreset;
use crate::vehicle::{Vehicle, slip};

/// The event's name in results.
pub const EVENT: &str = "soil";
/// The track's mean speed held, m/s (the drawbar example's, a towing
/// test's walking pace).
pub const TRACK_SPEED: f64 = 1.5;
/// A run's length, s.
pub const HOLD: f64 = 10.0;
/// The steady stretch averaged at a run's end, s.
pub const STEADY: f64 = 4.0;

/// One drawbar load held on a soil.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DrawbarPoint {
    /// The drawbar load, N.
    pub pull: f64,
    /// The track's slip, `1 − v / v_track`.
    pub slip: f64,
    /// The hull's mean speed, m/s.
    pub speed: f64,
    /// The track's mean speed, m/s.
    pub track_speed: f64,
    /// The sprocket's mean driving force, `τ ω / v_track`, N.
    pub tractive_force: f64,
    /// The ground's mean normal force on the track, N: the weight it
    /// carries.
    pub weight: f64,
    /// Whether the drive held the track's speed (its mean within
    /// [`HELD`] of [`TRACK_SPEED`]): if not, the drive's own torque limit,
    /// not the soil, set the motion, and the slip is no drawbar point.
    pub held: bool,
}

/// How close to [`TRACK_SPEED`] the track's mean speed must be for a
/// point to count as held, relative: 2 %.
pub const HELD: f64 = 0.02;

/// `V` on `soil` holding [`TRACK_SPEED`] against a drawbar load of `pull`
/// N: its slip and speeds over the run's last [`STEADY`] s.
pub fn drawbar_at<V: Vehicle>(
    settings: &EventSettings,
    soil: SoilPreset,
    pull: f64,
) -> Result<DrawbarPoint, EventError> {
    hold::<V>(settings, Soil::Soft(soil), pull)
}

/// `V` on rigid ground holding [`TRACK_SPEED`] with no drawbar load: its
/// running gear's own motion resistance
/// ([`DrawbarPoint::resistance_coefficient`]), what a steady turn's
/// tracks roll against ([`steering`](crate::steering)).
pub fn motion_resistance<V: Vehicle>(settings: &EventSettings) -> Result<DrawbarPoint, EventError> {
    hold::<V>(settings, Soil::Rigid, 0.0)
}

/// `V` on `soil` holding [`TRACK_SPEED`] against `pull` (N).
fn hold<V: Vehicle>(
    settings: &EventSettings,
    soil: Soil,
    pull: f64,
) -> Result<DrawbarPoint, EventError> {
    settings.check(EVENT)?;
    if !(pull.is_finite() && pull >= 0.0) {
        return Err(EventError::Setting {
            event: EVENT,
            what: "the drawbar pull (N)",
            range: "finite and 0 or more",
            value: pull,
        });
    }
    let terrain = Terrain::Flat { height: 0.0 };
    let scenario = Scenario {
        soil,
        engine: false,
        drawbar_pull: pull,
        ..settings.trial(terrain.clone(), HOLD, 0.01)
    };
    let drive = V::speed_drive(|t| TRACK_SPEED * t.clamp(0.0, 1.0));
    let config = scenario.config_with::<V>(terrain, drive, None);
    let mut means = Means::new(HOLD - STEADY);
    run_config::<V>(&scenario, config, &mut means, (EVENT, pull, "N"))?;
    let [speed, track_speed, power, weight] = means.means();
    Ok(DrawbarPoint {
        pull,
        slip: slip(speed, track_speed),
        speed,
        track_speed,
        tractive_force: power / track_speed,
        weight,
        held: (track_speed - TRACK_SPEED).abs() <= HELD * TRACK_SPEED,
    })
}

/// The drawbar curve on `soil`: [`drawbar_at`] at each load, given as a
/// fraction of `V`'s weight on the ground (measured at no load: the
/// first point is the zero load's).
pub fn drawbar_curve<V: Vehicle>(
    settings: &EventSettings,
    soil: SoilPreset,
    fractions: &[f64],
) -> Result<Vec<DrawbarPoint>, EventError> {
    let free = drawbar_at::<V>(settings, soil, 0.0)?;
    let mut points = vec![free];
    for &f in fractions {
        points.push(drawbar_at::<V>(settings, soil, f * free.weight)?);
    }
    Ok(points)
}

impl DrawbarPoint {
    /// The motion resistance at no drawbar load, as a fraction of the
    /// weight: the sprocket's driving force over the weight (all of it
    /// goes into the soil's compaction and the running gear's losses).
    pub fn resistance_coefficient(&self) -> f64 {
        self.tractive_force / self.weight
    }
}

/// Means of the speed, the track's speed, the sprocket's power (`τ ω`)
/// and the ground's normal force over the rows from a time on.
struct Means {
    from: f64,
    columns: Option<[usize; 5]>,
    sums: [f64; 4],
    rows: usize,
}

impl Means {
    fn new(from: f64) -> Means {
        Means {
            from,
            columns: None,
            sums: [0.0; 4],
            rows: 0,
        }
    }

    fn means(&self) -> [f64; 4] {
        self.sums.map(|s| s / self.rows as f64)
    }
}

impl Sink for Means {
    fn begin(&mut self, columns: &[String]) -> Result<(), SinkError> {
        let find = |name: &str| {
            columns
                .iter()
                .position(|c| c == name)
                .ok_or_else(|| SinkError::Columns(format!("soil: no column `{name}`")))
        };
        self.columns = Some([
            find("speed")?,
            find("track_speed")?,
            find("sprocket_torque")?,
            find("sprocket_speed")?,
            find("ground_normal")?,
        ]);
        Ok(())
    }

    fn row(&mut self, t: f64, values: &[f64]) -> Result<(), SinkError> {
        let Some([v, vt, tau, omega, normal]) = self.columns else {
            return Err(SinkError::Columns("soil: a row before `begin`".into()));
        };
        if t >= self.from {
            let row = [
                values[v],
                values[vt],
                values[tau] * values[omega],
                values[normal],
            ];
            for (sum, x) in self.sums.iter_mut().zip(row) {
                *sum += x;
            }
            self.rows += 1;
        }
        Ok(())
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        Ok(())
    }
}
