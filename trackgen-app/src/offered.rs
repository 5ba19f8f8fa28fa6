//! What the subcommands know of the vehicle they run besides its type:
//! its name, its powertrain, the real vehicle's published figures and
//! gauge.

use trackgen::mobility::cornering::Circle;
use trackgen::mobility::search::Search;
use trackgen::mobility::turning::{PivotTurn, SmallestTurn, SteadyTurnRun};
use trackgen::mobility::{EventError, EventSettings, Published};
use trackgen::vehicle::Powertrain;

/// A vehicle as the application offers it.
pub struct Offered {
    /// The name `--vehicle` takes and the output folders use.
    pub name: String,
    /// The powertrain `run --engine` and the mobility events drive
    /// through, if any.
    pub powertrain: Option<Powertrain>,
    /// The real vehicle's published figures.
    pub published: Vec<Published>,
    /// The real vehicle's gauge (its tracks' centre lines apart), m, if
    /// published: what `steer` turns two of the planar tracks at.
    pub gauge: Option<f64>,
    /// Steady turns of its spatial model at belt speeds (right, left,
    /// m/s), for a vehicle declared with both tracks: what `steer
    /// --spatial` runs.
    pub turn_runs: Option<TurnRuns>,
    /// The mobility events of its spatial model, for a vehicle declared
    /// with both tracks: what `mobility` runs as `side-slope` and
    /// `turning`.
    pub spatial_events: Option<SpatialEvents>,
    /// The spatial model's modes at rest, for a vehicle declared with
    /// both tracks: what `modes --spatial` finds.
    pub spatial_modes: Option<fn() -> Result<SpatialModes, String>>,
    /// Packs the spatial model's FMU library (`export_spatial_fmu!`) into
    /// its archives, for a vehicle declared with both tracks: what `fmu
    /// --spatial` does (the library, the folder; the archives written).
    pub spatial_fmu: Option<SpatialFmu>,
}

/// Packs a spatial FMU library (the library, the folder): the archives
/// written.
pub type SpatialFmu =
    fn(&std::path::Path, &std::path::Path) -> Result<Vec<std::path::PathBuf>, String>;

/// The spatial vehicle's modes at rest, and the largest acceleration
/// left where it settled (m/s², rad/s²).
pub type SpatialModes = (f64, Vec<trackgen::analysis::SpatialMode>);

/// The mobility events a spatial vehicle answers under its declared
/// laws (`trackgen::mobility::{side_slope, turning}`).
#[derive(Clone, Copy)]
pub struct SpatialEvents {
    /// The steepest side slope held (`side_slope::steepest`).
    pub side_slope: fn(&EventSettings) -> Result<Search, EventError>,
    /// The smallest radius at a crawl at full steer, through a steer unit
    /// of the ratio given or else the braked differential
    /// (`turning::smallest_radius`).
    pub smallest_radius: fn(&EventSettings, Option<f64>) -> Result<SmallestTurn, EventError>,
    /// The pivot turn (`turning::pivot`: in neutral where the settings'
    /// powertrain declares steer ratios).
    pub pivot: fn(&EventSettings) -> Result<PivotTurn, EventError>,
    /// The fastest steady turn on a circle of the radius given (m),
    /// through a steer unit of the ratio given or else the side drives
    /// (`cornering::fastest`).
    pub cornering: fn(&EventSettings, Circle) -> Result<Search, EventError>,
}

/// Runs steady turns of a spatial vehicle at belt speeds (right, left,
/// m/s), each its result or its error in words.
pub type TurnRuns = fn(&[[f64; 2]]) -> Vec<Result<RunTurn, String>>;

/// What a steady turn of the spatial vehicle showed (the runtime's
/// [`SteadyTurnRun`]).
pub type RunTurn = SteadyTurnRun;

impl Offered {
    /// Its name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Its powertrain, or why it has none.
    pub fn engine(&self) -> Result<Powertrain, String> {
        self.powertrain.clone().ok_or_else(|| {
            format!(
                "the vehicle `{}` has no powertrain: declare one (`powertrain {{ … }}`) or give \
                 one with `Entry::powertrain`",
                self.name
            )
        })
    }

    /// Its published figures.
    pub fn figures(&self) -> &[Published] {
        &self.published
    }
}
