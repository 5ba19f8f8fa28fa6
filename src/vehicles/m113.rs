//! The default vehicle: a planar M113, **one side** (the right).
//!
//! Figures from `shared/spec/m113.md` (Project Chrono's open M113 model).
//! The planar model carries one track and the matching half of the chassis:
//! half its mass and half its pitch inertia. Positions are given in
//! Chrono's track-assembly frame (x forward, y up, origin at the sprocket
//! centre) and the chassis centroid is declared in the same frame.
//!
//! What is not here yet: the road wheels' trailing arms and torsion
//! springs, the idler's tensioner, and contact (so the track and chassis do
//! not yet interact); the wheels are pinned to the chassis as in the paper's
//! part I.

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

crate::model! {
    /// A planar M113, right side: 64 shoes, a 10-tooth front sprocket,
    /// five road wheels and a rear idler. See the [module docs](self).
    pub vehicle M113 {
        gravity: (0.0, -9.81),
        chassis { mass: CHASSIS_MASS / 2.0, inertia: CHASSIS_INERTIA / 2.0, centroid: (-2.006, 0.406) },
        sprocket sprocket { at: (0.0, 0.0), mass: 27.68, inertia: SPROCKET_INERTIA, radius: 0.245, teeth: 10 },
        road_wheel rw1 { at: (-0.740, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305 },
        road_wheel rw2 { at: (-1.407, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305 },
        road_wheel rw3 { at: (-2.074, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305 },
        road_wheel rw4 { at: (-2.740, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305 },
        road_wheel rw5 { at: (-3.407, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305 },
        idler idler { at: (-3.95, -0.12), mass: 25.76, inertia: 1.12, radius: 0.255 },
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
    }
}
