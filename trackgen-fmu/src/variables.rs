//! The FMU's variables: one table, generated from the vehicle, that both
//! the model description and the instance read, so the two cannot
//! disagree on a value reference.

use trackgen::scenario::Scenario;
use trackgen::system::Simulated;
use trackgen::vehicle::{Vehicle, VehicleDynamics};

use crate::error::FmuError;

/// A variable's type in the C API.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// `fmi3Float64` / `fmi2Real`.
    Float64,
    /// `fmi3Int32` / `fmi2Integer`.
    Int32,
    /// `fmi3String` / `fmi2String`.
    String,
}

/// What a variable is to the master.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Causality {
    /// Set before the run starts (in initialisation mode at the latest):
    /// variability `fixed`.
    Parameter,
    /// Set by the master at any communication point: variability
    /// `continuous`, held constant over a communication step.
    Input,
    /// Computed: variability `continuous`.
    Output,
    /// Time, s: FMI 3.0's one independent variable.
    Independent,
}

/// A start value.
#[derive(Debug, Clone, PartialEq)]
pub enum Start {
    /// A number.
    Float64(f64),
    /// An integer.
    Int32(i32),
    /// A string.
    String(String),
    /// None: an output, computed.
    Computed,
}

/// What a parameter or input sets (the instance's meaning of a variable).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    /// A run setting ([`Setting`]).
    Setting(Setting),
    /// The torsion spring's rate of the `i`-th arm of the declared parts, N m/rad.
    ArmStiffness(usize),
    /// The damper's rate of the `i`-th arm, N m s/rad.
    ArmDamping(usize),
    /// An input.
    Input(Input),
    /// The `i`-th recorded column.
    Column(usize),
    /// The energy books' residual since the start.
    BooksResidual,
    /// The communication point reached.
    Time,
}

/// The run's settings, as parameters.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Setting {
    /// `course`: flat, bump, file, random or obstacle.
    Course,
    /// `bump_height`, m.
    BumpHeight,
    /// `bump_at`, m.
    BumpAt,
    /// `course_file`: a profile CSV.
    CourseFile,
    /// `roughness`: ISO 8608 class or RMS with its unit.
    Roughness,
    /// `seed`.
    Seed,
    /// `course_length`, m (0: what the run covers).
    CourseLength,
    /// `obstacle`: the main job's obstacle syntax.
    Obstacle,
    /// `obstacle_at`, m.
    ObstacleAt,
    /// `soil`: rigid or a soil of Wong's table.
    Soil,
    /// `tolerance` (0: the main job's defaults).
    Tolerance,
    /// `drive`: profile, speed or torque.
    Drive,
    /// `profile_speed`, m/s: the profile's target.
    Speed,
    /// `profile_settle`, s.
    Settle,
    /// `profile_ramp`, s.
    Ramp,
    /// `engine`: 1 drives through the vehicle's engine.
    Engine,
    /// `side_slope`: the ground's rise over run to the left (3-D).
    SideSlope,
    /// `steering`: profile or yaw_rate (3-D).
    Steering,
    /// `turn`, degrees to the left (3-D, steering = profile).
    Turn,
    /// `turn_at`, s.
    TurnAt,
    /// `turn_time`, s.
    TurnTime,
    /// `driveline`: sides, brakes, steer-ratio or neutral-pivot (3-D).
    Driveline,
    /// `steer_ratio`: the steer unit's minimum steer ratio (3-D).
    SteerRatio,
    /// `left_course_file`: a profile CSV under the left track alone (3-D;
    /// empty: the course).
    LeftCourseFile,
    /// `right_course_file`: under the right track alone.
    RightCourseFile,
    /// `field_file`: an ESRI ASCII grid, the whole ground (3-D; empty:
    /// the course).
    FieldFile,
}

/// The inputs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Input {
    /// `target_speed`, m/s (drive `speed`).
    TargetSpeed,
    /// `drive_torque`, N m (drive `torque`).
    DriveTorque,
    /// `drawbar_pull`, N.
    DrawbarPull,
    /// `target_yaw_rate`, rad/s (3-D, steering = yaw_rate).
    TargetYawRate,
}

/// One variable of the FMU.
#[derive(Debug, Clone, PartialEq)]
pub struct Variable {
    /// Its name.
    pub name: String,
    /// Its value reference (its index in the table).
    pub value_reference: u32,
    /// Its type.
    pub kind: Kind,
    /// Parameter, input or output.
    pub causality: Causality,
    /// Its unit (SI; `1` for a pure number; empty for a string).
    pub unit: &'static str,
    /// What it is.
    pub description: String,
    /// Its start value.
    pub start: Start,
    /// What the instance does with it.
    pub role: Role,
}

/// The table for the vehicle `V`: parameters, inputs, then one output per
/// recorded column and the books' residual. The columns are those of the
/// vehicle built with its declared configuration on flat ground; building
/// it is the one thing that can fail.
pub fn table<V: Vehicle>() -> Result<Vec<Variable>, FmuError> {
    let system = V::system_with(V::declared_config(
        trackgen::terrain::Terrain::Flat { height: 0.0 },
        trackgen::vehicle::Drive::Free,
    ))
    .map_err(|e| FmuError::Build(e.to_string()))?;
    let mut table = Table::new();
    let mut push = |name: String,
                    kind: Kind,
                    causality: Causality,
                    unit: &'static str,
                    description: String,
                    start: Start,
                    role: Role| {
        table.push(name, (kind, causality, unit), description, start, role);
    };
    use Causality::Parameter as P;
    for (name, kind, unit, description, start, setting) in scenario_settings() {
        push(
            name.into(),
            kind,
            P,
            unit,
            description.into(),
            start,
            Role::Setting(setting),
        );
    }
    let config = system.config();
    let arms = arm_names::<V>();
    for (i, (part, body)) in arms.iter().enumerate() {
        let spring = config
            .arms
            .iter()
            .find(|a| a.body == *body)
            .map(|a| a.spring)
            .ok_or_else(|| FmuError::Build(format!("no spring for {part}'s arm")))?;
        push(
            format!("{part}.arm_stiffness"),
            Kind::Float64,
            P,
            "N.m/rad",
            format!(
                "{part}'s arm: the torsion spring's rate, > 0 (declared {})",
                spring.stiffness
            ),
            Start::Float64(spring.stiffness),
            Role::ArmStiffness(i),
        );
        push(
            format!("{part}.arm_damping"),
            Kind::Float64,
            P,
            "N.m.s/rad",
            format!(
                "{part}'s arm: the damper's rate, >= 0 (declared {})",
                spring.damping
            ),
            Start::Float64(spring.damping),
            Role::ArmDamping(i),
        );
    }
    let inputs = [
        (
            "target_speed",
            "m/s",
            "drive = speed: the forward speed the controller holds",
            Input::TargetSpeed,
        ),
        (
            "drive_torque",
            "N.m",
            "drive = torque: the torque on the sprocket",
            Input::DriveTorque,
        ),
        (
            "drawbar_pull",
            "N",
            "a horizontal force pulling the chassis back at its centroid (negative pushes)",
            Input::DrawbarPull,
        ),
    ];
    for (name, unit, description, input) in inputs {
        push(
            name.into(),
            Kind::Float64,
            Causality::Input,
            unit,
            description.into(),
            Start::Float64(0.0),
            Role::Input(input),
        );
    }
    for (i, column) in system.columns().into_iter().enumerate() {
        let (unit, description) = describe_column(&column);
        push(
            column,
            Kind::Float64,
            Causality::Output,
            unit,
            description,
            Start::Computed,
            Role::Column(i),
        );
    }
    table.books_residual("motor work");
    Ok(table.0)
}

/// A table being written: each variable's value reference is its place,
/// the independent variable `time` first.
pub(crate) struct Table(pub(crate) Vec<Variable>);

impl Table {
    /// A table holding `time` alone.
    pub(crate) fn new() -> Table {
        let mut table = Table(Vec::new());
        table.push(
            "time".into(),
            (Kind::Float64, Causality::Independent, "s"),
            "time".into(),
            Start::Computed,
            Role::Time,
        );
        table
    }

    /// Adds a variable: its name, its type, causality and unit, what it
    /// is, its start value and what the instance does with it.
    pub(crate) fn push(
        &mut self,
        name: String,
        (kind, causality, unit): (Kind, Causality, &'static str),
        description: String,
        start: Start,
        role: Role,
    ) {
        let value_reference = self.0.len() as u32;
        self.0.push(Variable {
            name,
            value_reference,
            kind,
            causality,
            unit,
            description,
            start,
            role,
        });
    }

    /// Adds the output `books_residual`, the books weighed against the
    /// `work` put in (the drive's, in words).
    pub(crate) fn books_residual(&mut self, work: &str) {
        self.push(
            "books_residual".into(),
            (Kind::Float64, Causality::Output, "1"),
            format!(
                "the energy books since the start: ({work} - change of energy - dissipated) / \
                 the largest of the three"
            ),
            Start::Computed,
            Role::BooksResidual,
        );
    }
}

/// A parameter as a table lists it: its name, kind, unit, description,
/// start value and setting.
pub(crate) type SettingRow = (
    &'static str,
    Kind,
    &'static str,
    &'static str,
    Start,
    Setting,
);

/// The scenario's settings as the FMU's parameters: name, kind, unit,
/// description and start value (the scenario's defaults).
pub(crate) fn scenario_settings() -> [SettingRow; 16] {
    use Setting as S;
    [
        (
            "course",
            Kind::String,
            "",
            "the course: flat, bump (a cosine bump 1 m wide), file (course_file), random (roughness, seed, course_length) or obstacle (obstacle, obstacle_at)",
            Start::String("bump".into()),
            S::Course,
        ),
        (
            "bump_height",
            Kind::Float64,
            "m",
            "the bump's height (negative: a dip), -0.5 to 0.5",
            Start::Float64(Scenario::BUMP_HEIGHT),
            S::BumpHeight,
        ),
        (
            "bump_at",
            Kind::Float64,
            "m",
            "the bump's centre, -10000 to 10000",
            Start::Float64(Scenario::BUMP_AT),
            S::BumpAt,
        ),
        (
            "course_file",
            Kind::String,
            "",
            "a profile CSV (header x,z, metres, x never decreasing) for course = file",
            Start::String(String::new()),
            S::CourseFile,
        ),
        (
            "roughness",
            Kind::String,
            "",
            "for course = random: an ISO 8608 class A to H, or a detrended RMS elevation with its unit (1in, 25mm, 0.03m)",
            Start::String("1in".into()),
            S::Roughness,
        ),
        (
            "seed",
            Kind::Int32,
            "1",
            "the random course's seed (the same seed, the same course, bit for bit)",
            Start::Int32(1),
            S::Seed,
        ),
        (
            "course_length",
            Kind::Float64,
            "m",
            "the random course's length, 10 to 100000 (0: 1.2 |profile_speed| (stop - start) + 20)",
            Start::Float64(0.0),
            S::CourseLength,
        ),
        (
            "obstacle",
            Kind::String,
            "",
            "for course = obstacle: half-round:R, step:H, gap:WIDTH:DEPTH, ditch:DEPTH:BOTTOM:ANGLE, barrier:HEIGHT:TOP:ANGLE or grade:SLOPE:LENGTH (m, degrees)",
            Start::String("step:0.2".into()),
            S::Obstacle,
        ),
        (
            "obstacle_at",
            Kind::Float64,
            "m",
            "where the obstacle starts, -10000 to 10000",
            Start::Float64(Scenario::OBSTACLE_AT),
            S::ObstacleAt,
        ),
        (
            "soil",
            Kind::String,
            "",
            "rigid, or a soil of Wong's table: dry-sand, sandy-loam, clay, heavy-clay, lete-sand, snow",
            Start::String("rigid".into()),
            S::Soil,
        ),
        (
            "tolerance",
            Kind::Float64,
            "1",
            "the integrator's relative and absolute tolerance, 1e-12 to 0.1 (0: 1e-3 for the explicit method, 1e-2 for the implicit, chosen by stiffness, as the main job)",
            Start::Float64(0.0),
            S::Tolerance,
        ),
        (
            "drive",
            Kind::String,
            "",
            "what turns the sprocket: profile (the speed controller on profile_speed, profile_settle, profile_ramp), speed (the controller on the input target_speed) or torque (the input drive_torque)",
            Start::String("profile".into()),
            S::Drive,
        ),
        (
            "profile_speed",
            Kind::Float64,
            "m/s",
            "drive = profile: the target speed, -20 to 20",
            Start::Float64(Scenario::SPEED),
            S::Speed,
        ),
        (
            "profile_settle",
            Kind::Float64,
            "s",
            "drive = profile: the time at rest before the ramp, 0 to 1e6",
            Start::Float64(Scenario::SETTLE),
            S::Settle,
        ),
        (
            "profile_ramp",
            Kind::Float64,
            "s",
            "drive = profile: the ramp's duration, 0 to 1e6 (0: a step)",
            Start::Float64(Scenario::RAMP),
            S::Ramp,
        ),
        (
            "engine",
            Kind::Int32,
            "1",
            "1: the vehicle's engine caps the drive's torque (its power, not the controller, sets the speed where they disagree; engine_load is 1 there); 0: the controller alone",
            Start::Int32(0),
            S::Engine,
        ),
    ]
}

/// The arms of the declared parts, in declaration order: the part's name
/// and the arm's body.
pub fn arm_names<V: Vehicle>() -> Vec<(&'static str, usize)> {
    <V::System as VehicleDynamics>::parts()
        .iter()
        .filter_map(|p| p.arm.map(|arm| (p.name, arm.body)))
        .collect()
}

/// A recorded column's unit and description, from its name.
fn describe_column(column: &str) -> (&'static str, String) {
    let leaf = column.rsplit('.').next().unwrap_or(column);
    let known: Option<(&'static str, &str)> = match leaf {
        "x" => Some(("m", "horizontal position")),
        "y" => Some(("m", "height")),
        "vx" => Some(("m/s", "horizontal velocity")),
        "vy" => Some(("m/s", "vertical velocity")),
        "pitch" => Some(("rad", "the hull's pitch angle")),
        "speed" => Some(("m/s", "the hull's forward speed")),
        "sprocket_speed" => Some(("rad/s", "the sprocket's speed relative to the hull")),
        "track_speed" => Some(("m/s", "the track's speed round the hull")),
        "sprocket_torque" => Some(("N.m", "the drive's torque on the sprocket")),
        "engine_load" => Some((
            "1",
            "1 where the engine, not the controller, sets the torque",
        )),
        "tension" => Some(("N", "the tension in the recorded link's joint")),
        "tension_tight" => Some(("N", "the tension on the tight span")),
        "tension_slack" => Some(("N", "the tension on the slack span")),
        "ground_normal" => Some(("N", "the ground's normal force on the track")),
        "ground_penetration" => Some(("m", "the deepest ground contact")),
        "wheel_penetration" => Some(("m", "the deepest wheel contact")),
        "sprocket_penetration" => Some(("m", "the deepest sprocket contact")),
        "energy" => Some(("J", "the vehicle's mechanical energy")),
        "kinetic" => Some(("J", "kinetic energy")),
        "potential" => Some(("J", "potential energy")),
        "motor_work" => Some(("J", "the drive's work since the start")),
        "dissipated" => Some(("J", "the energy dissipated since the start")),
        "engine_work" => Some((
            "J",
            "this side's share of the engine's work since the start",
        )),
        "engine_power" => Some(("W", "this side's share of the engine's power")),
        "turbine_power" => Some(("W", "this side's share of the converter's output power")),
        "engine_speed" => Some(("rad/s", "the engine's speed")),
        "engine_torque" => Some(("N.m", "the engine's torque")),
        "gear" => Some(("1", "the gear or range engaged, from 1")),
        "speed_ratio" => Some(("1", "the converter's speed ratio, turbine over pump")),
        "torque_ratio" => Some(("1", "the converter's torque ratio, turbine over pump")),
        "converter_efficiency" => Some(("1", "the converter's efficiency")),
        "locked" => Some(("1", "1 with the converter's lock-up clutch engaged")),
        "seat_x" => Some(("m", "the driver's seat, horizontal position")),
        "seat_y" => Some(("m", "the driver's seat, height")),
        "seat_ax" => Some((
            "m/s2",
            "the seat's longitudinal acceleration in the hull's frame",
        )),
        "seat_az" => Some((
            "m/s2",
            "the seat's vertical acceleration in the hull's frame",
        )),
        "momentum_x" | "momentum_y" => Some(("N.s", "linear momentum")),
        "angular_momentum" => Some(("N.m.s", "angular momentum about the origin")),
        "closure_error" => Some(("m", "the loop's closure error")),
        "closure_rate_error" => Some(("m/s", "the loop's closure rate error")),
        "conditioning" => Some(("1", "the closure's conditioning")),
        _ => None,
    };
    if let Some((unit, what)) = known {
        return (unit, what.to_string());
    }
    if let Some(body) = leaf.strip_prefix("theta_") {
        return ("rad", format!("angle of {body}"));
    }
    if let Some(body) = leaf.strip_prefix("omega_") {
        return ("rad/s", format!("angular velocity of {body}"));
    }
    ("1", column.to_string())
}

/// Checks that the recorded columns of a built system are the table's.
pub(crate) fn check_columns(table: &[Variable], system: &dyn Simulated) -> Result<(), FmuError> {
    let columns = system.columns();
    let declared: Vec<&str> = table
        .iter()
        .filter(|v| matches!(v.role, Role::Column(_)))
        .map(|v| v.name.as_str())
        .collect();
    if declared.len() == columns.len() && declared.iter().zip(&columns).all(|(a, b)| a == b) {
        Ok(())
    } else {
        Err(FmuError::Build(
            "this configuration records other columns than the model description declares \
             (a soil adds none; report it)"
                .into(),
        ))
    }
}
