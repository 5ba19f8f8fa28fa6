//! The second vehicle: a planar Marder, **one side** (the left track set,
//! 77 shoes).
//!
//! Figures from Project Chrono's open Marder model (a secondary source:
//! its `Marder_*` files under `src/chrono_models/vehicle/marder/`),
//! converted so: Chrono's x forward and z up are our
//! x and y, angles change sign (a counter-clockwise planar angle is a
//! negative rotation about Chrono's +y), and the planar inertia of every
//! body is Chrono's `Iyy`. The planar model carries one track and the
//! matching half of the chassis: **half its mass (12 500 kg) and half its
//! pitch inertia (49 091.35 kg m²)**. Positions are in the track-assembly
//! frame, whose origin is the sprocket centre (and the chassis reference).
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
//! (no Marder-specific figures exist); the drive's torque limit is the
//! simple engine's in its one gear, `2400 / 0.1708 / 2 ≈ 7026` N m per
//! sprocket.
//!
//! Everything that makes it run is declared with it; as a
//! [`Vehicle`](crate::vehicle::Vehicle), `Marder::system(terrain, drive)` assembles
//! it on a terrain (`Marder::config` gives the run-time settings to change
//! first, for `Marder::system_with`), and `Marder::speed_drive` is a speed
//! controller tuned for it: proportional gain 4000 N m s/rad and integral
//! gain 8000 N m/rad on the sprocket speed, torque limited to 7026 N m.

/// Shoe pitch (pin to pin), m.
pub const SHOE_PITCH: f64 = 0.17;
/// Shoe mass, kg.
pub const SHOE_MASS: f64 = 18.02;
/// Shoe pitch inertia (Chrono `Iyy`), kg m².
pub const SHOE_INERTIA: f64 = 0.04;
/// Whole-vehicle hull mass, kg (the planar model uses half).
pub const CHASSIS_MASS: f64 = 25_000.0;
/// Whole-vehicle hull pitch inertia (Chrono `Iyy`), kg m² (the planar
/// model uses half).
pub const CHASSIS_INERTIA: f64 = 98_182.71;
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
        // Addendum circle 0.3 m, gap arcs of 0.07 m centred on the
        // 0.328414781 m circle (a 12-gon of 0.17 m sides).
        sprocket sprocket { at: (0.0, 0.0), mass: 27.68, inertia: SPROCKET_INERTIA, radius: 0.275,
            teeth: 12, tip_radius: 0.3, gap_radius: 0.07, gap_centre: 0.328414781 },
        // Wheels 1, 2, 5 and 6 (from the front) carry shock absorbers.
        road_wheel shocked[4] {
            at: [(-0.8458, -0.3759), (-1.6258, -0.3759), (-3.9658, -0.3759), (-4.7458, -0.3759)],
            mass: 35.56, inertia: 2.16, radius: 0.35,
            arm { pivot_offset: (0.4, 0.065), mass: ARM_MASS, inertia: ARM_INERTIA,
                  stiffness: TORSION_STIFFNESS,
                  damping: TORSION_DAMPING + SHOCK_DAMPING * SHOCK_LEVER * SHOCK_LEVER,
                  preload: TORSION_PRELOAD },
        },
        // Wheels 3 and 4: the torsion bar alone.
        road_wheel plain[2] {
            at: [(-2.4058, -0.3759), (-3.1858, -0.3759)],
            mass: 35.56, inertia: 2.16, radius: 0.35,
            arm { pivot_offset: (0.4, 0.065), mass: ARM_MASS, inertia: ARM_INERTIA,
                  stiffness: TORSION_STIFFNESS, damping: TORSION_DAMPING,
                  preload: TORSION_PRELOAD },
        },
        roller roller[3] {
            at: [(-1.2358, 0.1761), (-2.7958, 0.1761), (-4.3106, 0.1761)],
            mass: 10.56, inertia: 1.16, radius: 0.118,
        },
        // The idler's 10 kg carrier is the tensioner arm.
        idler idler { at: (-5.4, -0.0647), mass: 25.76, inertia: 1.12, radius: 0.334,
            arm { pivot: (-5.4, -0.0647 + TENSIONER_ARM), mass: 10.0, inertia: 0.04,
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
        drive { proportional: 4000.0, integral: 8000.0, max_torque: 7026.0 },
    }
}

/// The driveline's efficiency assumed for the powertrain, as the M113's
/// ([`m113::DRIVELINE_EFFICIENCY`](super::m113::DRIVELINE_EFFICIENCY)):
/// the figures give none.
pub const DRIVELINE_EFFICIENCY: f64 = super::m113::DRIVELINE_EFFICIENCY;

/// The Marder's engine and driveline as one side's sprocket sees them
/// (Chrono's `Marder_EngineSimpleMap.cpp` and
/// `Marder_AutomaticTransmissionSimpleMap.cpp`): the MTU MB 833's
/// full-load torque map (700 N m at 702 rpm, 2702 at 1499, 2154 at 2323,
/// cut off to −1000 N m at 2450 rpm), the six forward gears 0.1708 to
/// 1.5361 (no final drive: the simple driveline splits the driveshaft's
/// torque evenly), shifted ideally, and half the engine's power, after
/// [`DRIVELINE_EFFICIENCY`], for this side.
pub fn powertrain() -> trackgen::vehicle::Powertrain {
    const RPM: f64 = std::f64::consts::PI / 30.0; // rad/s
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

/// The real Marder's published mobility figures that the pitch-plane
/// events answer, each with its source: the Bundeswehr's for the Marder
/// 1A3 and its successors, as the German press quotes them (no field
/// manual or manufacturer's sheet with them was found to cite directly).
/// The declaration's masses are Chrono's (29.3 t with both sides'
/// running gear, a Marder 1 or 1A1 of 28–30 t); the 1A3 weighs 33.5 t in
/// combat order.
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
