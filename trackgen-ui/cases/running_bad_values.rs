// Running keys with values that make no vehicle: non-positive radii and
// rates, gaps that cut no teeth, pins wider than the gaps, a law given
// twice, repeated blocks with the wrong number of positions.
trackgen::model! {
    pub vehicle Tank {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 10,
            tip_radius: 0.2, gap_radius: 0.01, gap_centre: 0.3 },
        road_wheel rw[3] { at: [(-1.0, -0.2), (-2.0, -0.2)], mass: 35.56, inertia: 2.16, radius: 0.305 },
        road_wheel zero[2] { at: [(-1.0, -0.2), (-2.0, -0.2)], mass: 35.56, inertia: 2.16, radius: 0.305,
            arm { pivot_offset: (0.0, 0.0), mass: 75.26, inertia: 0.77, stiffness: 2.5e4, damping: 500.0 } },
        road_wheel none[0] { at: [], mass: 35.56, inertia: 2.16, radius: 0.305 },
        idler front { at: (-3.0, 0.0), mass: 20.0, inertia: 1.0, radius: 0.2,
            arm { pivot: (-3.0, 0.2), pivot_offset: (0.0, 0.2), mass: 5.0, inertia: 0.05, stiffness: 1e4, damping: 10.0 } },
        track { links: 8, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
        shoe { ground_points: [], inner_offset: -0.03, pins: [(0.0, 0.0)], pin_radius: 0.0 },
        contact {
            ground { stiffness: 0.0, chi: -1.0, mu: -0.8, slip: -0.1 },
            wheels { stiffness: 1e7, chi: 0.5, damping: 1e3 },
            sprocket { stiffness: 1e7, exponent: 0.0, chi: 0.5 },
        },
        drive { proportional: -1.0, max_torque: 0.0 },
    }

    pub vehicle Pins {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 10, gap_radius: 0.01 },
        track { links: 8, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
        shoe { ground_points: [(0.0, -0.03)], inner_offset: 0.03, pins: [(0.0, 0.0)], pin_radius: 0.02 },
    }
}

fn main() {}
