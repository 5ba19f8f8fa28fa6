// A steer unit's bad minimum steer ratios, each an error at its token: a
// list that is not one per range, and a ratio of 1 or less (at 1 the
// sprockets turn alike: no steer).
trackgen::model! {
    pub vehicle Miscounted {
        chassis { mass: 1000.0, inertia: 500.0, centroid: (-1.0, 0.3) },
        sprocket drive { at: (0.0, 0.0), mass: 20.0, inertia: 0.5, radius: 0.2, teeth: 9 },
        road_wheel rw[2] { at: [(-0.5, -0.2), (-1.0, -0.2)], mass: 30.0, inertia: 1.5, radius: 0.25,
            arm { pivot_offset: (0.25, 0.1), mass: 40.0, inertia: 0.5, stiffness: 2e4, damping: 400.0 } },
        idler rear { at: (-1.6, 0.0), mass: 20.0, inertia: 1.0, radius: 0.2 },
        track { links: 3, link { mass: 10.0, inertia: 0.02, u1: (-0.06, 0.0), u2: (0.06, 0.0) } },
        shoe { ground_points: [(-0.05, -0.025), (0.05, -0.025)], inner_offset: 0.025,
               pins: [(0.055, 0.0)], pin_radius: 0.012 },
        powertrain {
            engine: [(100.0, 500.0), (300.0, 600.0)],
            capacity: [(0.0, 9.0), (1.0, 18.0)],
            torque_ratio: [(0.0, 2.5), (1.0, 1.0)],
            ranges: [3.0, 1.5, 1.0],
            final_drive: 4.0,
            gearbox_efficiency: 0.95,
            final_drive_efficiency: 0.97,
            steer_ratios: [2.3, 1.6],
        },
    }
}

trackgen::model! {
    pub vehicle Unsteered {
        chassis { mass: 1000.0, inertia: 500.0, centroid: (-1.0, 0.3) },
        sprocket drive { at: (0.0, 0.0), mass: 20.0, inertia: 0.5, radius: 0.2, teeth: 9 },
        road_wheel rw[2] { at: [(-0.5, -0.2), (-1.0, -0.2)], mass: 30.0, inertia: 1.5, radius: 0.25,
            arm { pivot_offset: (0.25, 0.1), mass: 40.0, inertia: 0.5, stiffness: 2e4, damping: 400.0 } },
        idler rear { at: (-1.6, 0.0), mass: 20.0, inertia: 1.0, radius: 0.2 },
        track { links: 3, link { mass: 10.0, inertia: 0.02, u1: (-0.06, 0.0), u2: (0.06, 0.0) } },
        shoe { ground_points: [(-0.05, -0.025), (0.05, -0.025)], inner_offset: 0.025,
               pins: [(0.055, 0.0)], pin_radius: 0.012 },
        powertrain {
            engine: [(100.0, 500.0), (300.0, 600.0)],
            capacity: [(0.0, 9.0), (1.0, 18.0)],
            torque_ratio: [(0.0, 2.5), (1.0, 1.0)],
            ranges: [3.0, 1.5],
            final_drive: 4.0,
            gearbox_efficiency: 0.95,
            final_drive_efficiency: 0.97,
            steer_ratios: [1.0, 0.8],
        },
    }
}

fn main() {}
