//! The default vehicle: a planar M113, **one side** (the right).
//!
//! **Which M113.** The powertrain is the M113A3's ([`powertrain`]: the
//! 6V53T and the X200-4 with its torque converter, each figure sourced
//! there). The running gear, the masses and the contact are Project
//! Chrono's open M113 model (a secondary source: `M113_TrackShoeSinglePin`,
//! `M113_SprocketSinglePin`, `M113_RoadWheel`, `M113_Suspension`,
//! `M113_IdlerWheel`, `M113_Idler`, `M113_Chassis` and
//! `M113_TrackAssemblySinglePin`), which names no variant. Chrono's masses
//! add up to 11.35 t (its hull's 7 819 kg and both sides' running gear);
//! the declaration weighs what the M113A3 weighs in combat order,
//! [`COMBAT_WEIGHT`] (27 200 lb), with the running gear as Chrono's and
//! the hull taking the rest ([`CHASSIS_MASS`]: 987 kg more than Chrono's,
//! at its centroid and with its radius of gyration, an assumption: the
//! A3's additions, spall liners and external fuel tanks among them, are
//! not placed from a drawing).
//!
//! The planar model carries one track and the matching half of the chassis:
//! half its mass and half its pitch inertia. Its `tracks` block declares
//! the other side for the spatial vehicle ([`M113Hull`], [`M113LeftTrack`],
//! `<M113 as SpatialVehicle>::layout()`): the gauge ([`GAUGE`]), the whole
//! hull with its roll and yaw inertias scaled from Chrono's as its pitch
//! inertia is ([`CHASSIS_ROLL_INERTIA`], [`CHASSIS_YAW_INERTIA`]), the
//! guide's play ([`GUIDE_PLAY`]), the shoe's and road wheels' inertias
//! about their own axes from Chrono, and the left side as built: 63
//! shoes, its road wheels 0.084–0.085 m forward of the right's.
//!
//! Positions are given in Chrono's track-assembly frame (x forward, y up, origin at the sprocket
//! centre) and the chassis centroid is declared in the same frame.
//!
//! The arms' centroids are taken midway between pivot and wheel (the source
//! does not give them), and the idler's tensioner arm (mass 5 kg, 0.05 kg
//! m²) is an assumption of this model; see [`TENSIONER_ARM`].
//!
//! Everything that makes it run is declared with it: shoe, sprocket
//! profile, contact laws and drive gains. As a [`Vehicle`](crate::vehicle::Vehicle),
//! `M113::system(terrain, drive)` assembles it on a terrain, ready to
//! simulate (`M113::config` gives the run-time settings to change first,
//! for `M113::system_with`), and `M113::speed_drive` is a speed controller
//! tuned for it: proportional gain 3000 N m s/rad and integral gain
//! 6000 N m/rad on the sprocket speed, torque limited to 20 kN m.

/// Shoe pitch (pin to pin), m.
pub const SHOE_PITCH: f64 = 0.154;
/// Shoe mass, kg.
pub const SHOE_MASS: f64 = 18.02;
/// Shoe pitch inertia about its centroid, kg m².
pub const SHOE_INERTIA: f64 = 0.04;
/// The M113A3's combat weight, kg: 27 200 lb (power-projection.com,
/// M113A3, the manufacturer's figures), which the declaration's masses add
/// up to.
pub const COMBAT_WEIGHT: f64 = 27_200.0 * 0.453_592_37;
/// Sprocket mass, kg (Chrono's `M113_SprocketSinglePin`).
pub const SPROCKET_MASS: f64 = 27.68;
/// Road-wheel mass, kg (Chrono's `M113_RoadWheel`).
pub const WHEEL_MASS: f64 = 35.56;
/// Idler-wheel mass, kg (Chrono's `M113_IdlerWheel`).
pub const IDLER_MASS: f64 = 25.76;
/// The idler's tensioner arm's mass, kg: an assumption of this model
/// ([`TENSIONER_ARM`]).
pub const TENSIONER_ARM_MASS: f64 = 5.0;
/// Both sides' running gear as declared, kg: per side 64 shoes, the
/// sprocket, five road wheels on their arms, the idler and its tensioner
/// arm (3 531.64 kg).
pub const RUNNING_GEAR_MASS: f64 = 2.0
    * (64.0 * SHOE_MASS
        + SPROCKET_MASS
        + 5.0 * (WHEEL_MASS + ARM_MASS)
        + IDLER_MASS
        + TENSIONER_ARM_MASS);
/// Chrono's hull (`M113_Chassis`): 7 819.24 kg, pitch inertia
/// 27 287.61 kg m².
pub const CHRONO_CHASSIS: (f64, f64) = (7819.24, 27287.61);
/// Whole-vehicle chassis mass, kg (the planar model uses half): the
/// combat weight less the running gear, 8 806.07 kg.
pub const CHASSIS_MASS: f64 = COMBAT_WEIGHT - RUNNING_GEAR_MASS;
/// Whole-vehicle chassis pitch inertia, kg m² (the planar model uses half):
/// Chrono's, scaled with the mass (its radius of gyration kept).
pub const CHASSIS_INERTIA: f64 = CHRONO_CHASSIS.1 * CHASSIS_MASS / CHRONO_CHASSIS.0;
/// Sprocket gear inertia plus its axle's, kg m²: the axle spins with it.
pub const SPROCKET_INERTIA: f64 = 0.883 + 0.4;
/// Road-wheel trailing arm mass, kg.
pub const ARM_MASS: f64 = 75.26;
/// Road-wheel trailing arm inertia, kg m².
pub const ARM_INERTIA: f64 = 0.77;
/// Torsion bar stiffness, N m/rad.
pub const TORSION_STIFFNESS: f64 = 2.5e4;
/// Torsion bar damping, N m s/rad. (Chrono adds 100 N s/m shock dampers on
/// arms 1, 2 and 5; at the arm's 0.3 m lever that is under 10 N m s/rad,
/// left out.)
pub const TORSION_DAMPING: f64 = 500.0;
/// Torsion bar preload, N m, counter-clockwise in our x-forward, y-up
/// plane: it presses the wheel down. (Chrono's −1e4 N m is about its
/// lateral axis, which points the other way.)
pub const TORSION_PRELOAD: f64 = 1.0e4;
/// Track width, m, for soft soil (which the planar model otherwise does
/// not see): the M113's 15-inch (0.381 m) single-pin track; Chrono's model
/// gives none (the 15 in: AFV Database, M113, track T130E1).
pub const TRACK_WIDTH: f64 = 0.381;
/// The gauge (tread), m: the tracks' centre lines 85.0 in apart (AFV
/// Database, M113, "Tread 85.0 in, 216 cm"; the same hull and running
/// gear through the M113A3). What `steer` turns two of this planar
/// track at.
pub const GAUGE: f64 = 85.0 * 0.0254;
/// Chrono's hull's roll and yaw inertias, kg m², about its forward and
/// vertical axes (`M113_Chassis`: 13 983.08 and 28 805.57; a secondary
/// source), for its 7 819.24 kg ([`CHRONO_CHASSIS`]).
pub const CHRONO_CHASSIS_ROLL_YAW: (f64, f64) = (13_983.08, 28_805.57);
/// The whole hull's roll inertia, kg m²: Chrono's scaled with the mass, as
/// [`CHASSIS_INERTIA`] is.
pub const CHASSIS_ROLL_INERTIA: f64 = CHRONO_CHASSIS_ROLL_YAW.0 * CHASSIS_MASS / CHRONO_CHASSIS.0;
/// The whole hull's yaw inertia, kg m²: Chrono's scaled with the mass.
pub const CHASSIS_YAW_INERTIA: f64 = CHRONO_CHASSIS_ROLL_YAW.1 * CHASSIS_MASS / CHRONO_CHASSIS.0;
/// The centre guide's lateral play against the road wheels, m, each way:
/// half of Chrono's gap between a dual road wheel's halves (0.051 m,
/// `M113_RoadWheel`) less its shoe's guide, 0.0114 m wide
/// (`M113_TrackShoeSinglePin`); a secondary source, no drawing found.
pub const GUIDE_PLAY: f64 = (0.051 - 0.0114) / 2.0;
/// The M113A3's X200-4 transmission's minimum steer ratios in ranges 1
/// to 4 (it pivots in neutral): US Army Ordnance subcourse OD1714, lesson
/// 1 ("an infinitely variable, hydrostatically controlled differential
/// with a minimum steer ratio ... First 2.31:1 ... Fourth 1.22:1"), read
/// as the outer sprocket's speed over the inner's at full steer.
/// Declared with the powertrain (its `steer_ratios`), which every 3-D
/// driveline, the pivot event, `steer` and the spatial FMU read.
pub const STEER_RATIOS: [f64; 4] = [2.31, 1.58, 1.32, 1.22];
/// The driver's seat, m, in the track-assembly frame: Chrono's
/// `M113_Chassis` puts the driver at (0, 0.5, 1.2) m in the chassis
/// reference frame, whose x-z positions this frame shares: over the
/// sprocket, 1.2 m up.
pub const DRIVER_SEAT: (f64, f64) = (0.0, 1.2);
/// Length of the idler's tensioner arm, m. Chrono's tensioner is a
/// translational spring-damper (1e6 N/m, 1.4e4 N s/m, 2e4 N preload); here
/// the idler swings on a vertical arm of this length from a pivot above
/// it, whose torsion spring is the equivalent (`k L²`, `c L²`, `F L`): for
/// small swings the idler moves fore and aft as on the slide.
pub const TENSIONER_ARM: f64 = 0.2;

crate::model! {
    /// A planar M113, right side: 64 shoes, a 10-tooth front sprocket,
    /// five road wheels on torsion-sprung trailing arms and a rear idler on
    /// a tensioner arm. See the [module docs](self).
    pub vehicle M113 {
        gravity: (0.0, -9.81),
        seat: (DRIVER_SEAT.0, DRIVER_SEAT.1),
        // The hull's side outline in this frame, where the ground under
        // the resting track is at y ≈ −0.58 (road wheels at −0.215, radius
        // 0.305, shoes 0.06 thick). From the M113A1's published figures
        // (TM 9-2300-257-10; Jane's Armour and Artillery): 4.863 m long,
        // the roof 1.85 m and the belly 0.43 m above the ground; a lower
        // and an upper glacis at about 45° meeting in a nose 0.93 m up,
        // read from side-view drawings. For contact: the cupola, the trim
        // vane and the ramp's hinge are left out.
        hull: [(0.45, 0.35), (-0.05, -0.15), (-4.41, -0.15), (-4.41, 1.27), (-0.55, 1.27)],
        chassis { mass: CHASSIS_MASS / 2.0, inertia: CHASSIS_INERTIA / 2.0, centroid: (-2.006, 0.406) },
        // Tip circle 0.2605 m, gap arcs of 0.089 m centred 0.3 m out.
        sprocket sprocket { at: (0.0, 0.0), mass: SPROCKET_MASS, inertia: SPROCKET_INERTIA, radius: 0.245,
            teeth: 10, tip_radius: 0.2605, gap_radius: 0.089, gap_centre: 0.3 },
        road_wheel rw[5] {
            at: [(-0.740, -0.215), (-1.407, -0.215), (-2.074, -0.215), (-2.740, -0.215), (-3.407, -0.215)],
            mass: WHEEL_MASS, inertia: 2.16, radius: 0.305,
            arm { pivot_offset: (0.288, 0.134), mass: ARM_MASS, inertia: ARM_INERTIA,
                  stiffness: TORSION_STIFFNESS, damping: TORSION_DAMPING, preload: TORSION_PRELOAD },
        },
        idler idler { at: (-3.95, -0.12), mass: IDLER_MASS, inertia: 1.12, radius: 0.255,
            arm { pivot: (-3.95, -0.12 + TENSIONER_ARM), mass: TENSIONER_ARM_MASS, inertia: 0.05,
                  stiffness: 1.0e6 * TENSIONER_ARM * TENSIONER_ARM,
                  damping: 1.4e4 * TENSIONER_ARM * TENSIONER_ARM,
                  preload: -2.0e4 * TENSIONER_ARM } },
        track {
            links: 64,
            link {
                mass: SHOE_MASS,
                inertia: SHOE_INERTIA,
                u1: (-SHOE_PITCH / 2.0, 0.0),
                u2: (SHOE_PITCH / 2.0, 0.0),
            },
            closure: partitioned,
        },
        // The single-pin shoe: 0.06 m high with the pin axis at
        // mid-height, the ground face touching at two points 0.12 m apart,
        // sprocket cylinders of 0.015 m at x = +0.0535 and -0.061 m.
        shoe {
            ground_points: [(-0.06, -0.03), (0.06, -0.03)],
            inner_offset: 0.03,
            pins: [(0.0535, 0.0), (-0.061, 0.0)],
            pin_radius: 0.015,
            width: TRACK_WIDTH,
        },
        // Hunt-Crossley with exponent 1 throughout, close to what the
        // fitted defaults give this vehicle (`vehicle::ContactFit`: 1.3e6,
        // 2.1, 1.1e7, 0.5, 0.5).
        contact {
            ground { stiffness: 2e6, chi: 2.0, mu: 0.8 },     // stiction: tangential fitted
            wheels { stiffness: 1e7, chi: 0.5, mu: 0.4, slip: 0.5 },
            sprocket { stiffness: 1e7, chi: 0.5, mu: 0.4, slip: 0.5 },
        },
        // Half the vehicle's mass reflected through the 0.25 m sprocket
        // is ~250 kg m²: a closed loop of about 12 rad/s, well damped.
        drive { proportional: 3000.0, integral: 6000.0, max_torque: 2e4 },
        // Both sides in space: the right is this declaration, the left
        // its mirror with one shoe fewer and its road wheels staggered.
        tracks {
            gauge: GAUGE,
            guide_play: GUIDE_PLAY,
            hull { mass: CHASSIS_MASS, inertia: (CHASSIS_ROLL_INERTIA, CHASSIS_INERTIA, CHASSIS_YAW_INERTIA) },
            // The shoe and the road wheels about their forward and normal
            // axes: Chrono's `M113_TrackShoeSinglePin` (0.22, 0.25 kg m²)
            // and `M113_RoadWheel` (1.14 kg m² both); secondary. The
            // other bodies take the default rule.
            across { link: (0.22, 0.25), rw: (1.14, 1.14) },
            left {
                // 63 shoes against the right's 64 (AFV Database, M113,
                // track T130E1: "Left side: 63 Right side: 64"; Chrono's
                // the same).
                links: 63,
                // The road wheels 0.084–0.085 m forward of the right's, the
                // torsion bars crossing the hull side by side (Chrono's
                // `M113_TrackAssemblySinglePin`, `m_susp_locs_L`;
                // secondary).
                rw { at: [(-0.655, -0.215), (-1.322, -0.215), (-1.989, -0.215), (-2.656, -0.215), (-3.322, -0.215)] },
            },
        },
        // The M113A3's: the 6V53T's full-load torque (N m) against engine
        // speed (rad/s) through the X200-4's converter, ranges and lock-up
        // and the final drive; each figure's source is at `powertrain()`.
        powertrain {
            engine: [
                (500.0 * RPM, 450.0 * LB_FT * SCALE_6V53T),
                (1000.0 * RPM, 450.0 * LB_FT * SCALE_6V53T),
                (1500.0 * RPM, 445.0 * LB_FT * SCALE_6V53T),
                (2000.0 * RPM, 435.0 * LB_FT * SCALE_6V53T),
                (2500.0 * RPM, 410.0 * LB_FT * SCALE_6V53T),
                (ENGINE_RATED_SPEED, 395.0 * LB_FT * SCALE_6V53T),
                (ENGINE_HIGH_IDLE, 0.0),
            ],
            capacity: [
                (0.0, STALL_CAPACITY),
                (0.5, STALL_CAPACITY),
                (0.75, STALL_CAPACITY * 8.0 / 7.0),
                (0.9, STALL_CAPACITY * 9.0 / 7.0),
                (1.0, STALL_CAPACITY * 18.0 / 7.0),
            ],
            torque_ratio: [(0.0, 3.32), (0.25, 2.45), (0.5, 1.66), (0.725, 1.17), (0.85, 1.0), (1.0, 1.0)],
            ranges: [4.16, 2.34, 1.46, 1.04],
            reverse: REVERSE,
            lockup: [2, 3, 4],
            lockup_speed_ratio: 0.9,
            final_drive: FINAL_DRIVE,
            gearbox_efficiency: GEARBOX_EFFICIENCY,
            final_drive_efficiency: FINAL_DRIVE_EFFICIENCY,
            upshift: [UPSHIFT[0], UPSHIFT[1], UPSHIFT[2], UPSHIFT[3]],
            downshift: [DOWNSHIFT[0], DOWNSHIFT[1], DOWNSHIFT[2], DOWNSHIFT[3]],
            shift_time: SHIFT_TIME,
            steer_ratios: [STEER_RATIOS[0], STEER_RATIOS[1], STEER_RATIOS[2], STEER_RATIOS[3]],
            engine_inertia: ENGINE_INERTIA,
            engine_drag: [
                (0.0, 0.0),
                (50.0 * RPM, -30.0),
                (1000.0 * RPM, -50.0),
                (2000.0 * RPM, -70.0),
                (3000.0 * RPM, -90.0),
            ],
        },
    }
}

/// The X200-4's upshift speeds of its input (the converter's turbine),
/// rad/s, ranges 1 to 3 (the fourth's is not read): where the next range's
/// full-load torque overtakes this one's, the envelope's crossovers
/// (`Driveline::ideal_schedule`; a test holds these to it). Derived, not
/// published: no X200-4 shift points were found.
pub const UPSHIFT: [f64; 4] = [
    268.671_479_760_973_7,
    297.644_828_098_624_5,
    297.266_455_361_766_25,
    0.0,
];
/// The X200-4's downshift speeds of its input, rad/s, ranges 2 to 4 (the
/// first's is not read): at [`DOWNSHIFT_FRACTION`] of the sprocket speed
/// of the upshift into the range, the hysteresis (assumed).
pub const DOWNSHIFT: [f64; 4] = [
    0.0,
    120.902_165_892_438_16,
    148.568_016_760_339_08,
    169.401_158_123_965_42,
];
/// The sprocket speed of a downshift over that of the upshift it undoes:
/// 0.8, a 20 % band (assumed: an automatic gearbox's usual hysteresis).
pub const DOWNSHIFT_FRACTION: f64 = 0.8;
/// How long a shift takes, s: 0.5 (assumed: a clutch-to-clutch power
/// shift of a planetary range box hands over in some 0.3–0.8 s).
pub const SHIFT_TIME: f64 = 0.5;

/// The engine's rotating inertia with the converter's pump, kg m²: Project
/// Chrono's M113 shafts powertrain (a secondary source), its engine's
/// crankshaft, 1.1 kg m² (`M113_EngineShafts`), and its transmission's
/// input shaft, the converter's pump, 0.5 kg m²
/// (`M113_AutomaticTransmissionShafts`). No 6V53T or X200-4 figure was
/// found. The engine's torque at no fuel (`engine_drag`) is the same
/// model's losses map, 30 N m at 50 rpm rising to 90 N m at 3000 rpm,
/// unscaled: the 6V53T shares the 6V53's displacement and running gear.
pub const ENGINE_INERTIA: f64 = 1.1 + 0.5;

/// The driveline's efficiency assumed for Chrono's simple map
/// ([`chrono_simple_map`]; its figures give none): a mechanical gearbox
/// and final drive lose some 10–20 % of the engine's power.
pub const DRIVELINE_EFFICIENCY: f64 = 0.85;

/// Project Chrono's M113 engine and gearbox (a secondary source), as one
/// side's sprocket sees them: `M113_EngineSimpleMap.cpp`,
/// `M113_AutomaticTransmissionSimpleMap.cpp` and `M113_DrivelineBDS.cpp`.
/// The full-load torque map of a Detroit Diesel 6V53 (450 lb·ft at
/// 500–1000 rpm, falling to 380 at 3000 and cut off to −100 at 3200 rpm),
/// the four forward gears 0.240, 0.427, 0.685, 0.962 times the conical
/// gear's 0.5, shifted ideally, and half the engine's power, after
/// [`DRIVELINE_EFFICIENCY`], for this side. It has no torque converter
/// and no final drive: it reaches the sprocket with about 0.16 of the
/// weight at a crawl and twice the real top speed. Kept to compare
/// against; the vehicle's own is [`powertrain`].
pub fn chrono_simple_map() -> trackgen::vehicle::Powertrain {
    let map = CHRONO_6V53_MAP.iter().map(|&(n, t)| (n * RPM, t * LB_FT));
    trackgen::vehicle::Powertrain::Engine {
        map: map.collect(),
        ratios: [0.240, 0.427, 0.685, 0.962].map(|r| r * 0.5).to_vec(),
        fraction: DRIVELINE_EFFICIENCY * 0.5,
    }
}

/// N m per lb·ft.
const LB_FT: f64 = 1.355_817_948_331_400_4;
/// rad/s per rpm.
const RPM: f64 = std::f64::consts::PI / 30.0;
/// W per (mechanical) horsepower.
const HP: f64 = 745.699_871_582_270_2;

/// Chrono's full-load torque map of the Detroit Diesel 6V53 (lb·ft
/// against rpm, `M113_EngineSimpleMap.cpp`; a secondary source).
const CHRONO_6V53_MAP: [(f64, f64); 8] = [
    (500.0, 450.0),
    (1000.0, 450.0),
    (1500.0, 445.0),
    (2000.0, 435.0),
    (2500.0, 410.0),
    (2800.0, 395.0),
    (3000.0, 380.0),
    (3200.0, -100.0),
];

/// The M113A3's engine, a Detroit Diesel 6V53T, rated 275 hp at 2800 rpm
/// (US Army Ordnance subcourse OD1712, *Introduction to the M113A3
/// Armored Personnel Carrier*, lesson 1).
pub const ENGINE_RATED_POWER: f64 = 275.0 * HP;
/// The 6V53T's rated (governed full-load) speed, rad/s: 2800 rpm (OD1712).
pub const ENGINE_RATED_SPEED: f64 = 2800.0 * RPM;
/// The governor's high-idle speed, rad/s: 3000 rpm, where the full-load
/// torque has fallen to 0. Assumed: a droop of about 7 % above the rated
/// speed, usual for the mechanical governors of Detroit Diesel's Series 53
/// (no M113A3 figure found).
pub const ENGINE_HIGH_IDLE: f64 = 3000.0 * RPM;
/// The X200-4 converter's stall torque ratio (US Army Ordnance subcourse
/// OD1714, *M113A3 power train*, lesson 1: "a single-stage, three-element,
/// polyphase hydraulic torque converter with a stall torque ratio of
/// 3.32:1").
pub const STALL_TORQUE_RATIO: f64 = 3.32;
/// The engine speed at which the converter stalls at full load, rad/s:
/// 2300 rpm. Assumed (no X200-4 stall-test figure found): a heavy-duty
/// converter is matched to stall at some 80 % of the engine's rated speed,
/// near its peak torque; it sets the capacity factor at stall,
/// `K(0) = ω / √T_e(ω)`.
pub const STALL_SPEED: f64 = 2300.0 * RPM;
/// The X200-4's range reductions, first to fourth (OD1714: 4.16, 2.34,
/// 1.46, 1.04:1; reverse 6.62:1).
pub const RANGES: [f64; 4] = [4.16, 2.34, 1.46, 1.04];
/// The X200-4's reverse reduction (OD1714: 6.62:1), through the converter
/// (reverse does not lock up: OD1714 names ranges 2 to 4).
pub const REVERSE: f64 = 6.62;
/// The M113A3's top speed on a level road, m/s: 41 mph (US Army Center of
/// Military History, *Weapon Systems*, "M113 Series Armored Personnel
/// Carrier": M113A3).
pub const TOP_SPEED: f64 = 41.0 * 0.447_04;
/// The sprocket's pitch radius, m: ten teeth on the 0.154 m shoe pitch,
/// `p / (2 sin(π/10))`.
pub const SPROCKET_PITCH_RADIUS: f64 = 0.249_177_234_267_483_8;
/// The final drive's reduction: derived, not published (none found for
/// the M113A3) — the reduction that turns the sprocket at [`TOP_SPEED`]
/// with the engine at its rated speed in fourth range, locked up:
/// `ω_e r / (1.04 v)` = 3.833.
pub const FINAL_DRIVE: f64 = ENGINE_RATED_SPEED * SPROCKET_PITCH_RADIUS / (RANGES[3] * TOP_SPEED);
/// The X200-4 gearbox's efficiency (its gears, bearings, pumps and the
/// hydrostatic steer unit idling), assumed: 0.92, the usual figure for a
/// planetary range box of four ranges (Wong, *Theory of Ground Vehicles*,
/// 4th ed., §3.3, gives 0.90–0.95 for a transmission in a high gear).
pub const GEARBOX_EFFICIENCY: f64 = 0.92;
/// The final drive's efficiency, assumed: 0.97, a single-stage gear
/// reduction (Wong, §3.3: about 0.97 a stage).
pub const FINAL_DRIVE_EFFICIENCY: f64 = 0.97;

/// The 6V53T's full-load torque as Chrono's 6V53 map scaled: ×1.306, so
/// that 395 lb·ft at 2800 rpm becomes the rated 275 hp there (the map's
/// shape is estimated: no published 6V53T curve was found).
pub const SCALE_6V53T: f64 = ENGINE_RATED_POWER / (395.0 * LB_FT * ENGINE_RATED_SPEED);

/// The converter's capacity factor at stall, rad/s per √(N m): the one
/// that stalls the engine at [`STALL_SPEED`], `K(0) = ω / √T_e(ω)` with
/// the declared map's 743.64 N m there (a test holds the figure to that
/// derivation).
pub const STALL_CAPACITY: f64 = 8.832_330_266_045_645;

/// The M113A3's powertrain as one side's sprocket sees it, at full load:
/// the declared `powertrain` (the Detroit Diesel 6V53T through the Allison
/// X200-4's torque converter, stall torque ratio [`STALL_TORQUE_RATIO`],
/// lock-up in ranges 2 to 4 (OD1714), its four ranges ([`RANGES`]) chosen
/// ideally, reverse ([`REVERSE`]) where the driver asks to back, and the
/// final drive ([`FINAL_DRIVE`]), half of it for this
/// side), [`M113::powertrain`](crate::vehicle::Vehicle::powertrain).
///
/// The engine's curve and the converter's are estimated (no published
/// 6V53T or X200-4 curves were found), each point stated in the
/// declaration:
/// * the engine: Chrono's 6V53 map × [`SCALE_6V53T`] to 2800 rpm, then
///   the governor's droop to 0 at [`ENGINE_HIGH_IDLE`];
/// * torque ratio 3.32 at stall (published), then 2.45, 1.66, 1.17 and
///   1.00 at speed ratios 0.25, 0.5, 0.725 and 0.85 (the coupling point),
///   1.00 beyond: the efficiency `SR · TR` peaks at 0.85 between 0.725 and
///   0.85, the figures of the Allison TX-200 family's single-stage
///   converters;
/// * capacity factor `K` flat from stall to a speed ratio of 0.5, rising
///   to 8/7, 9/7 and 18/7 of it at 0.75, 0.9 and 1 (the shape of Chrono's
///   M113 converter map, `M113_AutomaticTransmissionShafts.cpp`), from
///   [`STALL_CAPACITY`] at stall;
/// * the lock-up clutch engages at a speed ratio of 0.9.
///
/// Chrono's own M113 shafts powertrain has a converter of stall ratio 2.0
/// and no final drive (its gear ratios are overall ratios of 0.240 to
/// 0.962, sprocket over engine speed): it reaches about a third of this
/// one's torque at stall.
pub fn powertrain() -> trackgen::vehicle::Powertrain {
    use trackgen::vehicle::Vehicle;
    M113::powertrain().unwrap_or_else(|| unreachable!("the M113's declaration has a powertrain"))
}

/// The real M113A3's published mobility figures that the events answer,
/// each with its source. The grade, the vertical obstacle, the trench and
/// the side slope are the M113 family's (the A3 keeps them: its heavier
/// hull came with the larger engine and the converter transmission).
pub const PUBLISHED: [trackgen::mobility::Published; 5] = {
    use trackgen::mobility::quantity;
    [
        trackgen::mobility::Published {
            quantity: quantity::TOP_SPEED,
            value: TOP_SPEED,
            unit: "m/s",
            source: "US Army Center of Military History, Weapon Systems, M113 series: \
                 M113A3, 41 mph (also the figure the final drive is derived from)",
        },
        trackgen::mobility::Published {
            quantity: quantity::STEEPEST_GRADE,
            value: 0.60,
            unit: "rise over run",
            source: "AFV Database, M113 (afvdatabase.com/usa/m113.html): maximum grade 60 %",
        },
        trackgen::mobility::Published {
            quantity: quantity::HIGHEST_STEP,
            value: 0.61,
            unit: "m",
            source: "power-projection.com, M113A3 (the manufacturer's figures): vertical \
                 obstacle 0.61 m; AFV Database, M113: 24 in",
        },
        trackgen::mobility::Published {
            quantity: quantity::WIDEST_GAP,
            value: 1.68,
            unit: "m",
            source: "power-projection.com, M113A3 (the manufacturer's figures): trench \
                 crossing 1.68 m; AFV Database, M113: 66 in",
        },
        trackgen::mobility::Published {
            quantity: quantity::STEEPEST_SIDE_SLOPE,
            value: 0.30,
            unit: "rise over run",
            source: "AFV Database, M113 (afvdatabase.com/usa/m113.html): maximum side slope \
                 30 % (a rating: no criterion given)",
        },
    ]
};
