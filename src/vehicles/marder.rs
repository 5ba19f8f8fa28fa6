//! The second vehicle: a planar Marder, **one side** (the left track set,
//! 77 shoes). Its `tracks` block declares the right side for the spatial
//! vehicle ([`MarderHull`], [`MarderRightTrack`]): 78 shoes, its road
//! wheels and rollers 0.1 m forward, as Chrono's; the whole hull with
//! Chrono's roll and yaw inertias ([`CHASSIS_ROLL_INERTIA`],
//! [`CHASSIS_YAW_INERTIA`]).
//!
//! Figures from Project Chrono's open Marder model (a secondary source:
//! its `Marder_*` files under `src/chrono_models/vehicle/marder/`),
//! converted so: Chrono's x forward and z up are our
//! x and y, angles change sign (a counter-clockwise planar angle is a
//! negative rotation about Chrono's +y), and the planar inertia of every
//! body is Chrono's `Iyy`. The planar model carries one track and the
//! matching half of the chassis: **half its mass and half its pitch
//! inertia**, the hull's mass the 1A3's combat weight less the running
//! gear ([`CHASSIS_MASS`]). Positions are in the track-assembly frame,
//! whose origin is the sprocket centre (and the chassis reference).
//!
//! One figure is not Chrono's: the sprocket's **tip circle**, 0.34 m
//! where Chrono's `Marder_SprocketSinglePin` gives 0.3 m. Chrono centres
//! the gap arcs on the pitch circle itself (0.328 m; its M113's sit 5 cm
//! outside its pitch circle), so on a link seated on the sprocket the
//! shoe's sprocket pins (cylinders of 0.015 m, 0.024 and 0.0315 m from
//! the joint) have their inner edges 0.3067 m from the centre, 7 mm
//! outside a 0.3 m tip circle: no tooth reaches them, and the track
//! rides over the teeth (a profile the compiler and the runtime refuse:
//! [`ProfileProblem::TeethMissPins`](crate::contact::sprocket::ProfileProblem::TeethMissPins)).
//! No drawing of the Marder's sprocket was
//! found; 0.34 m is estimated by giving its teeth the M113's height over
//! the same shoe's pins (3.1–3.3 cm on Chrono's M113 profile).
//!
//! Three translations from Chrono's templates to what a planar declaration
//! has, each documented where it is declared:
//! - the **shock absorbers** (linear dampers of 17 771.53 N s/m on arms 1,
//!   2, 5 and 6) become rotational damping about the arm pivot, `c r²`
//!   with `r` = 0.4015 m the shock line's lever arm at the design position
//!   ([`SHOCK_LEVER`]), added to the torsion bar's 500 N m s/rad;
//! - the **translational tensioner** (2e6 N/m, 1e5 N s/m, 24 525 N preload
//!   along the hull) becomes a 0.2 m swing arm above the idler with the
//!   equivalent torsion spring (`k L²`, `c L²`, `F L`), as for the M113;
//!   like the M113's, the preload is the stated `F0` only (Chrono's
//!   design length sits 0.25 m short of the free length, which would add
//!   0.5 MN; the track settles where its tension balances the spring);
//! - the **torsion preload** `T0 = −2.7e4` N m about Chrono's +y is
//!   +2.7e4 N m counter-clockwise here, pressing the wheels down.
//!
//! The arm centroids are midway between pivot and wheel (as the source
//! gives, (+0.200, +0.0325) m from the wheel). Contact laws are the M113's
//! (no Marder-specific figures exist); the drive's torque limit, 40 kN m,
//! is above what the declared powertrain gives at stall (38.4 kN m at the
//! sprocket: [`powertrain`]), as the M113's is above its own.
//!
//! **Which Marder.** The powertrain is the Marder 1A3's as estimated
//! ([`powertrain`]: the MTU MB 833 Ea-500 through a converter gearbox, the
//! Renk HSWL 194's kind; where a figure was not found it is Chrono's or
//! assumed, each said so); the published figures it is held to are the
//! 1A3's ([`PUBLISHED`]). The running gear is Chrono's, which names no
//! variant; Chrono's masses add up to 29.3 t with both sides' running
//! gear (a Marder 1 or 1A1, 28–30 t). The declaration weighs what the 1A3
//! weighs in combat order, [`COMBAT_WEIGHT`] (33.5 t): the hull takes the
//! 4.2 t more at its centroid and with its radii of gyration, an
//! assumption (the 1A3's added armour is on the hull's front and sides
//! and its turret's roof, not placed from a drawing).
//!
//! Everything that makes it run is declared with it; as a
//! [`Vehicle`](crate::vehicle::Vehicle), `Marder::system(terrain, drive)` assembles
//! it on a terrain (`Marder::config` gives the run-time settings to change
//! first, for `Marder::system_with`), and `Marder::speed_drive` is a speed
//! controller tuned for it: proportional gain 4000 N m s/rad and integral
//! gain 8000 N m/rad on the sprocket speed, torque limited to 40 kN m.

/// Shoe pitch (pin to pin), m.
pub const SHOE_PITCH: f64 = 0.17;
/// Shoe mass, kg.
pub const SHOE_MASS: f64 = 18.02;
/// Shoe pitch inertia (Chrono `Iyy`), kg m².
pub const SHOE_INERTIA: f64 = 0.04;
/// The Marder 1A3's combat weight, kg: 33.5 t "gefechtsbereit" (the
/// German-language encyclopaedia's Marder article, as de.pluspedia.org
/// keeps it; its 13.2 kW/t for the 1A3 with the 441 kW engine is 33.4 t),
/// which the declaration's masses add up to.
pub const COMBAT_WEIGHT: f64 = 33_500.0;
/// Sprocket mass, kg (Chrono's `Marder_SprocketSinglePin`).
pub const SPROCKET_MASS: f64 = 27.68;
/// Road-wheel mass, kg (Chrono's `Marder_RoadWheel`).
pub const WHEEL_MASS: f64 = 35.56;
/// Return-roller mass, kg (Chrono's `Marder_SupportRoller`).
pub const ROLLER_MASS: f64 = 10.56;
/// Idler-wheel mass, kg (Chrono's `Marder_IdlerWheel`).
pub const IDLER_MASS: f64 = 25.76;
/// The idler's carrier, the tensioner arm here, kg (Chrono's `Marder_Idler`).
pub const TENSIONER_ARM_MASS: f64 = 10.0;
/// Both sides' running gear as declared, kg: per side 77 shoes, the
/// sprocket, six road wheels on their arms, three rollers, the idler and
/// its tensioner arm (4 295.16 kg).
pub const RUNNING_GEAR_MASS: f64 = 2.0
    * (77.0 * SHOE_MASS
        + SPROCKET_MASS
        + 6.0 * (WHEEL_MASS + ARM_MASS)
        + 3.0 * ROLLER_MASS
        + IDLER_MASS
        + TENSIONER_ARM_MASS);
/// Chrono's hull (`Marder_Chassis`): 25 000 kg; inertias about its
/// forward, lateral and vertical axes (`Ixx`, `Iyy`, `Izz`) 13 653.39,
/// 98 182.71 and 101 954.43 kg m².
pub const CHRONO_CHASSIS: (f64, [f64; 3]) = (25_000.0, [13_653.39, 98_182.71, 101_954.43]);
/// Whole-vehicle hull mass, kg (the planar model uses half): the combat
/// weight less the running gear, 29 204.84 kg.
pub const CHASSIS_MASS: f64 = COMBAT_WEIGHT - RUNNING_GEAR_MASS;
/// Whole-vehicle hull pitch inertia, kg m² (the planar model uses half):
/// Chrono's `Iyy`, scaled with the mass (its radius of gyration kept).
pub const CHASSIS_INERTIA: f64 = CHRONO_CHASSIS.1[1] * CHASSIS_MASS / CHRONO_CHASSIS.0;
/// Whole-vehicle hull roll inertia (about its forward axis), kg m²: the
/// spatial vehicle's; Chrono's `Ixx`, scaled with the mass.
pub const CHASSIS_ROLL_INERTIA: f64 = CHRONO_CHASSIS.1[0] * CHASSIS_MASS / CHRONO_CHASSIS.0;
/// Whole-vehicle hull yaw inertia (about its vertical axis), kg m²:
/// Chrono's `Izz`, scaled with the mass.
pub const CHASSIS_YAW_INERTIA: f64 = CHRONO_CHASSIS.1[2] * CHASSIS_MASS / CHRONO_CHASSIS.0;
/// The centre guide's lateral play against the road wheels, m, each way:
/// half of Chrono's gap between a road wheel's halves (0.051 m,
/// `Marder_RoadWheel`) less its shoe's guide, 0.0114 m wide
/// (`Marder_TrackShoeSinglePin`); a secondary source, no drawing found.
pub const GUIDE_PLAY: f64 = (0.051 - 0.0114) / 2.0;
/// Sprocket gear inertia plus its axle's, kg m²: the axle spins with it.
pub const SPROCKET_INERTIA: f64 = 0.883 + 0.4;
/// Road-wheel arm mass, kg.
pub const ARM_MASS: f64 = 75.26;
/// Road-wheel arm pitch inertia, kg m².
pub const ARM_INERTIA: f64 = 0.77;
/// Torsion bar stiffness, N m/rad.
pub const TORSION_STIFFNESS: f64 = 84_220.62;
/// Torsion bar damping, N m s/rad.
pub const TORSION_DAMPING: f64 = 500.0;
/// Torsion bar preload, N m, counter-clockwise (Chrono's −2.7e4 N m about
/// its +y): it presses the wheel down.
pub const TORSION_PRELOAD: f64 = 2.7e4;
/// Shock absorber damping, N s/m (arms 1, 2, 5 and 6).
pub const SHOCK_DAMPING: f64 = 17_771.53;
/// The shock's lever arm about the arm pivot at the design position, m:
/// the distance from the pivot (+0.400, +0.065) to the line through the
/// shock's ends (−0.034, +0.152) on the arm and (−0.128, +0.542) on the
/// hull, all from the wheel centre: `|(P − A) × (B − A)| / |B − A|`
/// = 0.161082 / 0.401168.
pub const SHOCK_LEVER: f64 = 0.401_532_2;
/// Track width, m, for soft soil: the shoe's ground pad, 0.40 m
/// (Chrono's `Marder_TrackShoeSinglePin`; 0.48 m over the side pads).
pub const TRACK_WIDTH: f64 = 0.40;
/// The gauge, m: Project Chrono's Marder model places its track
/// assemblies 1.36 m either side of the chassis' centre line
/// (`Marder_Vehicle.cpp`, a secondary source: no published figure was
/// found). What `steer` turns two of this planar track at.
pub const GAUGE: f64 = 2.0 * 1.36;
/// Length of the idler's tensioner arm, m (see the module docs).
pub const TENSIONER_ARM: f64 = 0.2;
/// Tensioner spring (N/m), damper (N s/m) and preload (N) of Chrono's
/// translational tensioner.
pub const TENSIONER: (f64, f64, f64) = (2e6, 1e5, 24_525.0);

/// The driver's seat, m, in the track-assembly frame: an assumption, since
/// Chrono's `Marder_Chassis` gives the driver at its origin (0, 0, 0). The
/// Marder 1's driver sits at the front left, beside the engine, as the
/// M113's does beside its own: placed like the M113's seat, over the front
/// of the track (0.5 m behind the sprocket, over the first road wheel's
/// arm) and 1.75 m above the ground (the ground under the road wheels is
/// at y = −0.73 m; the hull roof, 1.9 m above it, is at about 1.2 m).
pub const DRIVER_SEAT: (f64, f64) = (-0.5, 1.0);

crate::model! {
    /// A planar Marder, left side: 77 shoes, a 12-tooth front sprocket,
    /// six road wheels on torsion-sprung trailing arms (four with shock
    /// absorbers), three return rollers and a rear idler on a tensioner
    /// arm. See the [module docs](self).
    pub vehicle Marder {
        gravity: (0.0, -9.81),
        seat: (DRIVER_SEAT.0, DRIVER_SEAT.1),
        // The hull's side outline in this frame, where the ground under
        // the resting track is at y ≈ −0.79 (road wheels at −0.376,
        // radius 0.35, shoes 0.06 thick). From the Marder 1A3's published
        // figures (Jane's Armour and Artillery): 6.79 m long, the hull
        // roof about 1.9 m (the turret's top 2.98 m) and the belly 0.45 m
        // above the ground; a steep lower and a flat upper glacis meeting
        // in a nose 1.0 m up, read from side-view drawings. For contact:
        // the turret and the stowage are left out.
        hull: [(0.55, 0.25), (-0.25, -0.34), (-6.24, -0.34), (-6.24, 1.11), (-1.0, 1.11)],
        chassis { mass: CHASSIS_MASS / 2.0, inertia: CHASSIS_INERTIA / 2.0, centroid: (-2.7958, 0.0) },
        // Gap arcs of 0.07 m centred on the 0.328414781 m circle (a 12-gon
        // of 0.17 m sides), Chrono's; the tip circle estimated (see the
        // module docs: Chrono's 0.3 m lies under the seated shoe's pins).
        sprocket sprocket { at: (0.0, 0.0), mass: SPROCKET_MASS, inertia: SPROCKET_INERTIA, radius: 0.275,
            teeth: 12, tip_radius: 0.34, gap_radius: 0.07, gap_centre: 0.328414781 },
        // Wheels 1, 2, 5 and 6 (from the front) carry shock absorbers.
        road_wheel shocked[4] {
            at: [(-0.8458, -0.3759), (-1.6258, -0.3759), (-3.9658, -0.3759), (-4.7458, -0.3759)],
            mass: WHEEL_MASS, inertia: 2.16, radius: 0.35,
            arm { pivot_offset: (0.4, 0.065), mass: ARM_MASS, inertia: ARM_INERTIA,
                  stiffness: TORSION_STIFFNESS,
                  damping: TORSION_DAMPING + SHOCK_DAMPING * SHOCK_LEVER * SHOCK_LEVER,
                  preload: TORSION_PRELOAD },
        },
        // Wheels 3 and 4: the torsion bar alone.
        road_wheel plain[2] {
            at: [(-2.4058, -0.3759), (-3.1858, -0.3759)],
            mass: WHEEL_MASS, inertia: 2.16, radius: 0.35,
            arm { pivot_offset: (0.4, 0.065), mass: ARM_MASS, inertia: ARM_INERTIA,
                  stiffness: TORSION_STIFFNESS, damping: TORSION_DAMPING,
                  preload: TORSION_PRELOAD },
        },
        roller roller[3] {
            at: [(-1.2358, 0.1761), (-2.7958, 0.1761), (-4.3106, 0.1761)],
            mass: ROLLER_MASS, inertia: 1.16, radius: 0.118,
        },
        // The idler's 10 kg carrier is the tensioner arm.
        idler idler { at: (-5.4, -0.0647), mass: IDLER_MASS, inertia: 1.12, radius: 0.334,
            arm { pivot: (-5.4, -0.0647 + TENSIONER_ARM), mass: TENSIONER_ARM_MASS, inertia: 0.04,
                  stiffness: TENSIONER.0 * TENSIONER_ARM * TENSIONER_ARM,
                  damping: TENSIONER.1 * TENSIONER_ARM * TENSIONER_ARM,
                  preload: -TENSIONER.2 * TENSIONER_ARM } },
        track {
            links: 77,
            link {
                mass: SHOE_MASS,
                inertia: SHOE_INERTIA,
                u1: (-SHOE_PITCH / 2.0, 0.0),
                u2: (SHOE_PITCH / 2.0, 0.0),
            },
            closure: partitioned,
        },
        // The single-pin shoe: 0.06 m high with the pin axis at
        // mid-height, the 0.11 m ground pad touching at its ends, sprocket
        // cylinders of 0.015 m at x = +0.0535 and −0.061 m.
        shoe {
            ground_points: [(-0.055, -0.03), (0.055, -0.03)],
            inner_offset: 0.03,
            pins: [(0.0535, 0.0), (-0.061, 0.0)],
            pin_radius: 0.015,
            width: TRACK_WIDTH,
        },
        // Both sides in space: this declaration is the left side; the
        // right is its mirror with one shoe more and its road wheels and
        // rollers 0.1 m forward (Chrono's `Marder_TrackAssemblySinglePin`:
        // 78 shoes against 77, `m_right_x_offset`; secondary).
        tracks {
            side: left,
            gauge: GAUGE,
            guide_play: GUIDE_PLAY,
            hull { mass: CHASSIS_MASS, inertia: (CHASSIS_ROLL_INERTIA, CHASSIS_INERTIA, CHASSIS_YAW_INERTIA) },
            // The shoe and the road wheels about their forward and normal
            // axes: Chrono's `Marder_TrackShoeSinglePin` (0.22, 0.25 kg m²)
            // and `Marder_RoadWheel` (1.14 kg m² both). The other bodies
            // take the default rule.
            across { link: (0.22, 0.25), shocked: (1.14, 1.14), plain: (1.14, 1.14) },
            right {
                links: 78,
                shocked { at: [(-0.7458, -0.3759), (-1.5258, -0.3759), (-3.8658, -0.3759), (-4.6458, -0.3759)] },
                plain { at: [(-2.3058, -0.3759), (-3.0858, -0.3759)] },
                roller { at: [(-1.1358, 0.1761), (-2.6958, 0.1761), (-4.2106, 0.1761)] },
            },
        },
        // The M113's laws (Hunt-Crossley, exponent 1): no Marder figures.
        contact {
            ground { stiffness: 2e6, chi: 2.0, mu: 0.8 },     // stiction: tangential fitted
            wheels { stiffness: 1e7, chi: 0.5, mu: 0.4, slip: 0.5 },
            sprocket { stiffness: 1e7, chi: 0.5, mu: 0.4, slip: 0.5 },
        },
        // A speed loop of ~2.5 rad/s on the vehicle's 1580 kg m² of
        // inertia reflected through the sprocket; a higher gain acts on
        // the sprocket's own 1.28 kg m² first and sets the explicit
        // integrator's step (4000 / 1.283 ≈ 3100 /s, as stiff as the
        // idler's rim friction).
        drive { proportional: 4000.0, integral: 8000.0, max_torque: 4e4 },
        // The Marder 1A3's, as estimated: see `powertrain()` and the
        // guide's table for each figure's source.
        powertrain {
            engine: [
                (702.26 * RPM, 700.0 * SCALE_MB833),
                (1099.0 * RPM, 2044.0 * SCALE_MB833),
                (1158.0 * RPM, 2149.0 * SCALE_MB833),
                (1207.0 * RPM, 2250.0 * SCALE_MB833),
                (1233.0 * RPM, 2350.0 * SCALE_MB833),
                (1263.0 * RPM, 2450.0 * SCALE_MB833),
                (1300.0 * RPM, 2545.0 * SCALE_MB833),
                (1352.0 * RPM, 2628.0 * SCALE_MB833),
                (1403.0 * RPM, 2683.0 * SCALE_MB833),
                (1499.0 * RPM, 2702.0 * SCALE_MB833),
                (1628.0 * RPM, 2683.0 * SCALE_MB833),
                (1757.0 * RPM, 2650.0 * SCALE_MB833),
                (1901.0 * RPM, 2569.0 * SCALE_MB833),
                (2004.0 * RPM, 2472.0 * SCALE_MB833),
                (2099.0 * RPM, 2386.0 * SCALE_MB833),
                (2195.0 * RPM, 2298.0 * SCALE_MB833),
                (2323.0 * RPM, 2154.0 * SCALE_MB833),
                (2450.0 * RPM, 0.0),
            ],
            capacity: [
                (0.0, 3.023 * CAPACITY_SCALE),
                (0.105301, 3.01349 * CAPACITY_SCALE),
                (0.20916, 3.023 * CAPACITY_SCALE),
                (0.320936, 3.06102 * CAPACITY_SCALE),
                (0.435681, 3.10856 * CAPACITY_SCALE),
                (0.556364, 3.1751 * CAPACITY_SCALE),
                (0.647369, 3.21312 * CAPACITY_SCALE),
                (0.724529, 3.27016 * CAPACITY_SCALE),
                (0.786849, 3.30819 * CAPACITY_SCALE),
                (0.843236, 3.35572 * CAPACITY_SCALE),
                (0.891714, 3.43177 * CAPACITY_SCALE),
                (0.912552, 3.86906 * CAPACITY_SCALE),
                (0.928444, 4.30635 * CAPACITY_SCALE),
                (0.93938, 4.67709 * CAPACITY_SCALE),
                (1.0, 5.61822 * CAPACITY_SCALE),
            ],
            torque_ratio: [(0.0, 2.5), (0.85, 1.0), (1.0, 1.0)],
            ranges: [RANGES[0], RANGES[1], RANGES[2], RANGES[3]],
            reverse: REVERSE,
            lockup: [2, 3, 4],
            lockup_speed_ratio: 0.9,
            final_drive: FINAL_DRIVE,
            gearbox_efficiency: super::m113::GEARBOX_EFFICIENCY,
            final_drive_efficiency: super::m113::FINAL_DRIVE_EFFICIENCY,
            engine_inertia: ENGINE_INERTIA,
            engine_drag: [
                (0.0, 0.0),
                (50.0 * RPM, -30.0 * DRAG_SCALE),
                (1000.0 * RPM, -50.0 * DRAG_SCALE),
                (2000.0 * RPM, -70.0 * DRAG_SCALE),
                (3000.0 * RPM, -90.0 * DRAG_SCALE),
            ],
        },
    }
}

/// The driveline's efficiency assumed for Chrono's simple map
/// ([`chrono_simple_map`]), as the M113's
/// ([`m113::DRIVELINE_EFFICIENCY`](super::m113::DRIVELINE_EFFICIENCY)):
/// the figures give none.
pub const DRIVELINE_EFFICIENCY: f64 = super::m113::DRIVELINE_EFFICIENCY;

/// Project Chrono's Marder engine and gearbox (a secondary source), as one
/// side's sprocket sees them: `Marder_EngineSimpleMap.cpp` and
/// `Marder_AutomaticTransmissionSimpleMap.cpp`: the MTU MB 833's
/// full-load torque map (700 N m at 702 rpm, 2702 at 1499, 2154 at 2323,
/// cut off to −1000 N m at 2450 rpm), the six forward gears 0.1708 to
/// 1.5361 (no final drive: the simple driveline splits the driveshaft's
/// torque evenly), shifted ideally, and half the engine's power, after
/// [`DRIVELINE_EFFICIENCY`], for this side. It has no torque converter:
/// it reaches the sprocket with 6.7 kN m at a crawl. Kept to compare
/// against; the vehicle's own is [`powertrain`].
pub fn chrono_simple_map() -> trackgen::vehicle::Powertrain {
    let map = [
        (702.0, 700.0),
        (1099.0, 2044.0),
        (1300.0, 2545.0),
        (1499.0, 2702.0),
        (2004.0, 2472.0),
        (2323.0, 2154.0),
        (2450.0, -1000.0),
    ];
    trackgen::vehicle::Powertrain::Engine {
        map: map.iter().map(|&(n, t)| (n * RPM, t)).collect(),
        ratios: vec![0.1708, 0.2791, 0.4218, 0.6223, 1.0173, 1.5361],
        fraction: DRIVELINE_EFFICIENCY * 0.5,
    }
}

/// rad/s per rpm.
const RPM: f64 = std::f64::consts::PI / 30.0;

/// The Marder's engine's power, W: the MTU MB 833 Ea-500's 441 kW (600 PS),
/// the figure published for the Marder 1 and its successors (as
/// de.pluspedia.org's article and the German press give it; no
/// manufacturer's sheet was found).
pub const ENGINE_RATED_POWER: f64 = 441e3;
/// Where Chrono's MB 833 map gives its most power, rad/s: 2195 rpm (its
/// 2298 N m there, 528 kW: Chrono's map is a fifth over the published
/// power). The declared map is Chrono's × [`SCALE_MB833`], its most power
/// the published 441 kW here.
pub const ENGINE_RATED_SPEED: f64 = 2195.0 * RPM;
/// Chrono's MB 833 map scaled to the published power: 441 kW over its
/// 2298 N m at 2195 rpm, 0.835 (the map's shape is Chrono's, estimated:
/// no published MB 833 curve was found).
pub const SCALE_MB833: f64 = ENGINE_RATED_POWER / (2298.0 * ENGINE_RATED_SPEED);
/// The Marder 1A3's top speed on roads, m/s: 65 km/h ([`PUBLISHED`]).
pub const TOP_SPEED: f64 = 65.0 / 3.6;
/// The sprocket's pitch radius, m: twelve teeth on the 0.17 m shoe pitch,
/// `p / (2 sin(π/12))`.
pub const SPROCKET_PITCH_RADIUS: f64 = 0.328_414_780_938_283_25;
/// The gearbox's four forward ranges, reductions: Chrono's Marder shafts
/// powertrain's (`Marder_AutomaticTransmissionShafts.cpp`, a secondary
/// source: its output-over-input ratios 0.27, 0.45, 0.63 and 1.0). No
/// figure of the Renk HSWL 194's ranges was found.
pub const RANGES: [f64; 4] = [1.0 / 0.27, 1.0 / 0.45, 1.0 / 0.63, 1.0];
/// The reverse range's reduction: Chrono's (−0.25, the same file).
pub const REVERSE: f64 = 1.0 / 0.25;
/// The final drive's reduction: derived, not published — the reduction
/// that turns the sprocket at [`TOP_SPEED`] with the engine at
/// [`ENGINE_RATED_SPEED`] in the fourth range, locked: `ω_e r / v` = 4.181.
pub const FINAL_DRIVE: f64 = ENGINE_RATED_SPEED * SPROCKET_PITCH_RADIUS / (RANGES[3] * TOP_SPEED);
/// The converter's capacity factors over Chrono's, `1 / √`[`SCALE_MB833`]
/// = 1.0944: the engine's torque scaled by `s` meets a pump of capacity
/// `K / √s` at the same engine speeds (`T_p = (ω / K)²`), so the scaled
/// engine and converter match where Chrono's pair does (its stall at some
/// 1 500 rpm, at the map's peak torque). Unscaled, the pump would absorb
/// the scaled engine's whole torque at idle and hold it there at stall.
pub const CAPACITY_SCALE: f64 = 1.094_428_234_737_245_8;

/// The engine's torque at no fuel over the M113A3's (Chrono's M113 losses
/// map, [`m113`](super::m113)'s `engine_drag`): the two engines' largest
/// full-load torques' ratio, 2256 / 797 N m, an estimate (friction grows
/// with an engine's size). Chrono's own Marder losses map is its M113's
/// times ten, a quarter of the engine's peak torque at 2000 rpm and, at
/// idle, three quarters of what the engine gives there at full fuel.
pub const DRAG_SCALE: f64 = 2.83;

/// The engine's rotating inertia with the converter's pump, kg m²:
/// Chrono's Marder shafts powertrain (a secondary source): its engine's
/// crankshaft, 2.1 kg m² (`Marder_EngineShafts`), and its transmission's
/// input shaft, the pump, 0.5 kg m².
pub const ENGINE_INERTIA: f64 = 2.1 + 0.5;

/// The Marder's powertrain as one side's sprocket sees it, at full load:
/// the declared `powertrain`, the Marder 1A3's as estimated (the MTU MB 833
/// Ea-500 through a hydrodynamic-mechanical gearbox with a torque
/// converter and a lock-up clutch, as the Renk HSWL 194 is; no figure of
/// its converter, ranges or final drive was found), each figure stated at
/// its declaration and in the guide's table ([`Marder::powertrain`](crate::vehicle::Vehicle::powertrain)):
/// * the engine: Chrono's MB 833 map × [`SCALE_MB833`] to the published
///   441 kW, cut off to 0 at 2450 rpm; its inertia [`ENGINE_INERTIA`] and
///   its torque at no fuel the M113A3's × [`DRAG_SCALE`];
/// * the converter: Chrono's Marder shafts converter (its file names it an
///   Allison TC-521 "calculated from SAE TC example curve"): stall torque
///   ratio 2.5, falling linearly to 1.0 at the coupling, `SR` 0.85, and
///   its capacity factor map × [`CAPACITY_SCALE`];
/// * lock-up in ranges 2 to 4 at a speed ratio of 0.9 (assumed, as the
///   M113A3's X200-4);
/// * the four ranges and reverse [`RANGES`], [`REVERSE`]; the final drive
///   [`FINAL_DRIVE`], derived from the published top speed; the
///   efficiencies the M113A3's (assumed); shifted by the ideal schedule
///   (an engine whose speed is a state shifts by one; none is published).
pub fn powertrain() -> trackgen::vehicle::Powertrain {
    use trackgen::vehicle::Vehicle;
    Marder::powertrain()
        .unwrap_or_else(|| unreachable!("the Marder's declaration has a powertrain"))
}

/// The real Marder's published mobility figures that the pitch-plane
/// events answer, each with its source: the Bundeswehr's for the Marder
/// 1A3 and its successors, as the German press quotes them (no field
/// manual or manufacturer's sheet with them was found to cite directly).
/// The declaration weighs what the 1A3 does in combat order
/// ([`COMBAT_WEIGHT`]).
pub const PUBLISHED: [trackgen::mobility::Published; 4] = {
    use trackgen::mobility::quantity;
    [
        trackgen::mobility::Published {
            quantity: quantity::TOP_SPEED,
            value: 65.0 / 3.6,
            unit: "m/s",
            source: "the Bundeswehr's figure for the Marder 1A3, about 65 km/h on roads, as \
                 hna.de and gentside.de quote it",
        },
        trackgen::mobility::Published {
            quantity: quantity::STEEPEST_GRADE,
            value: 0.60,
            unit: "rise over run",
            source: "the Bundeswehr's figures for the Schützenpanzer Marder, as Merkur.de \
                 quotes them (April 2022): slopes of up to 60 %",
        },
        trackgen::mobility::Published {
            quantity: quantity::HIGHEST_STEP,
            value: 1.0,
            unit: "m",
            source: "the Bundeswehr's figures, as Merkur.de quotes them (April 2022): \
                 obstacles 1 m high",
        },
        trackgen::mobility::Published {
            quantity: quantity::WIDEST_GAP,
            value: 2.5,
            unit: "m",
            source: "the Bundeswehr's figures, as Merkur.de quotes them (April 2022): \
                 trenches 2.50 m wide",
        },
    ]
};
