//! The default vehicle: a planar M113, **one side** (the right).
//!
//! Figures from `shared/spec/m113.md` (Project Chrono's open M113 model).
//! The planar model carries one track and the matching half of the chassis:
//! half its mass and half its pitch inertia. Positions are given in
//! Chrono's track-assembly frame (x forward, y up, origin at the sprocket
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
/// Whole-vehicle chassis mass, kg (the planar model uses half).
pub const CHASSIS_MASS: f64 = 7819.24;
/// Whole-vehicle chassis pitch inertia, kg m² (the planar model uses half).
pub const CHASSIS_INERTIA: f64 = 27287.61;
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
/// and `shared/spec/m113.md` give none.
pub const TRACK_WIDTH: f64 = 0.381;
/// The driver's seat, m, in the track-assembly frame: Chrono's
/// `M113_Chassis` puts the driver at (0, 0.5, 1.2) m in the chassis
/// reference frame, whose x-z positions this frame shares
/// (`shared/spec/mobility.md` §4): over the sprocket, 1.2 m up.
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
        sprocket sprocket { at: (0.0, 0.0), mass: 27.68, inertia: SPROCKET_INERTIA, radius: 0.245,
            teeth: 10, tip_radius: 0.2605, gap_radius: 0.089, gap_centre: 0.3 },
        road_wheel rw[5] {
            at: [(-0.740, -0.215), (-1.407, -0.215), (-2.074, -0.215), (-2.740, -0.215), (-3.407, -0.215)],
            mass: 35.56, inertia: 2.16, radius: 0.305,
            arm { pivot_offset: (0.288, 0.134), mass: ARM_MASS, inertia: ARM_INERTIA,
                  stiffness: TORSION_STIFFNESS, damping: TORSION_DAMPING, preload: TORSION_PRELOAD },
        },
        idler idler { at: (-3.95, -0.12), mass: 25.76, inertia: 1.12, radius: 0.255,
            arm { pivot: (-3.95, -0.12 + TENSIONER_ARM), mass: 5.0, inertia: 0.05,
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
    }
}

/// The driveline's efficiency assumed for the powertrain (the figures give
/// none): a mechanical gearbox and final drive lose some 10–20 % of the
/// engine's power.
pub const DRIVELINE_EFFICIENCY: f64 = 0.85;

/// The M113's engine and driveline as one side's sprocket sees them
/// (`shared/spec/mobility.md` §4, from Chrono's
/// `M113_EngineSimpleMap.cpp`, `M113_AutomaticTransmissionSimpleMap.cpp`
/// and `M113_DrivelineBDS.cpp`): the full-load torque map of the Detroit
/// Diesel 6V53 (450 lb·ft at 500–1000 rpm, falling to 380 at 3000 and
/// cut off to −100 at 3200 rpm), the four forward gears 0.240, 0.427,
/// 0.685, 0.962 times the conical gear's 0.5, shifted ideally, and half
/// the engine's power, after [`DRIVELINE_EFFICIENCY`], for this side.
pub fn powertrain() -> trackgen::vehicle::Powertrain {
    const LB_FT: f64 = 1.355_817_948_331_400_4; // N m
    const RPM: f64 = std::f64::consts::PI / 30.0; // rad/s
    let map = [
        (500.0, 450.0),
        (1000.0, 450.0),
        (1500.0, 445.0),
        (2000.0, 435.0),
        (2500.0, 410.0),
        (2800.0, 395.0),
        (3000.0, 380.0),
        (3200.0, -100.0),
    ];
    trackgen::vehicle::Powertrain::Engine {
        map: map.iter().map(|&(n, t)| (n * RPM, t * LB_FT)).collect(),
        ratios: [0.240, 0.427, 0.685, 0.962].map(|r| r * 0.5).to_vec(),
        fraction: DRIVELINE_EFFICIENCY * 0.5,
    }
}
