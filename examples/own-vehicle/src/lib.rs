//! The Mule: a light tracked carrier of about 4 t, one side of it
//! declared for the pitch plane and both in 3-D (its `tracks` block). A
//! made-up vehicle, not a real one: its figures are round numbers of the
//! right size for its class, chosen to show a declaration that is not the
//! M113's.

/// Engine speed per rpm, rad/s.
const RPM: f64 = std::f64::consts::PI / 30.0;

trackgen::model! {
    /// The Mule, one side: 49 shoes of 0.12 m, a 9-tooth front sprocket,
    /// three road wheels on torsion arms, one return roller, a rear idler
    /// on a tensioner arm; a diesel through a torque converter and three
    /// ranges.
    pub vehicle Mule {
        gravity: (0.0, -9.81),
        // The driver sits over the front road wheel, 0.9 m up.
        seat: (-0.55, 0.9),
        // The hull's side outline: a sloped nose over the sprocket, the
        // belly 0.1 m above the road wheels' centres, a square tail.
        hull: [(0.30, 0.25), (0.05, -0.20), (-2.45, -0.20), (-2.45, 1.05), (-0.35, 1.05)],
        // Half the vehicle's sprung mass, in the track's frame.
        chassis { mass: 1500.0, inertia: 1400.0, centroid: (-1.15, 0.30) },
        sprocket drive { at: (0.0, 0.0), mass: 15.0, inertia: 0.3, radius: 0.17, teeth: 9 },
        road_wheel rw[3] {
            at: [(-0.55, -0.30), (-1.20, -0.30), (-1.85, -0.30)],
            mass: 30.0, inertia: 0.6, radius: 0.22,
            arm { pivot_offset: (0.24, 0.10), mass: 20.0, inertia: 0.2,
                  stiffness: 3.5e4, damping: 1.2e3, preload: 3.0e3 },
        },
        roller top { at: (-1.20, 0.14), mass: 5.0, inertia: 0.02, radius: 0.08 },
        idler rear { at: (-2.30, -0.08), mass: 20.0, inertia: 0.4, radius: 0.18,
            arm { pivot: (-2.30, 0.12), mass: 3.0, inertia: 0.02,
                  stiffness: 2e4, damping: 600.0, preload: -2e3,
                  travel: (-0.6, 0.6) } },
        track {
            links: 49,
            link { mass: 7.0, inertia: 0.012, u1: (-0.06, 0.0), u2: (0.06, 0.0) },
        },
        shoe { ground_points: [(-0.045, -0.02), (0.045, -0.02)], inner_offset: 0.02,
               pins: [(0.045, 0.0), (-0.045, 0.0)], pin_radius: 0.012, width: 0.3 },
        contact { ground { stiffness: 1.5e6, chi: 2.0, mu: 0.7 } },
        drive { proportional: 1500.0, integral: 3000.0, max_torque: 8e3 },
        // A 90 kW diesel (full-load torque in N m against speed in rad/s,
        // governed to 0 at 3300 rpm) through a converter stalling at about
        // 1800 rpm with a torque ratio of 2.5, three ranges and a final
        // drive of 4.5: about 12 m/s in third at 3000 rpm.
        powertrain {
            engine: [
                (800.0 * RPM, 250.0),
                (1200.0 * RPM, 340.0),
                (2000.0 * RPM, 350.0),
                (3000.0 * RPM, 290.0),
                (3300.0 * RPM, 0.0),
            ],
            capacity: [(0.0, 10.0), (0.6, 10.0), (0.9, 12.0), (1.0, 24.0)],
            torque_ratio: [(0.0, 2.5), (0.4, 1.6), (0.8, 1.0), (1.0, 1.0)],
            ranges: [3.0, 1.6, 1.0],
            reverse: 3.5,
            lockup: [2, 3],
            lockup_speed_ratio: 0.9,
            final_drive: 4.5,
            gearbox_efficiency: 0.92,
            final_drive_efficiency: 0.97,
        },
        // Both sides in space: the tracks 1.6 m apart, the guides 10 mm
        // of play each way, the whole hull (twice the side's share) with
        // its roll, pitch and yaw inertias those of a uniform box 2.75 m
        // long, 2.0 m wide and 1.2 m high.
        tracks {
            gauge: 1.6,
            guide_play: 0.01,
            hull { mass: 3000.0, inertia: (1360.0, 2800.0, 2890.0) },
        },
    }
}

// The FMU's C functions for the Mule, driving through its declared
// powertrain when the importer sets `engine = 1`.
trackgen_fmu::export_fmu!(Mule);
