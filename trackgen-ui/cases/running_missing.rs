// The keys that make a vehicle run: each missing one is reported at its
// block, all at once.
trackgen::model! {
    pub vehicle Tank {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 10 },
        road_wheel rw[2] { mass: 35.56, inertia: 2.16, radius: 0.305,
            arm { mass: 75.26, inertia: 0.77, stiffness: 2.5e4, damping: 500.0 } },
        track { links: 8, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
        // No `pins`, no `pin_radius`.
        shoe { ground_points: [(-0.06, -0.03)], inner_offset: 0.03 },
        contact {
            // A Hunt-Crossley law needs its `chi`; a Kelvin-Voigt law its
            // `stiffness`.
            ground { stiffness: 2e6 },
            wheels { damping: 1e3 },
        },
    }

    // Contact and drive without a shoe, and a shoe without a sprocket.
    pub vehicle NoShoe {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 10 },
        track { links: 8, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
        contact { ground { mu: 0.5 } },
        drive { max_torque: 1e3 },
    }

    pub vehicle NoSprocket {
        chassis { mass: 1000.0, inertia: 500.0 },
        idler front { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245 },
        track { links: 8, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
        shoe { ground_points: [(-0.06, -0.03)], inner_offset: 0.03, pins: [(0.0, 0.0)], pin_radius: 0.015 },
    }
}

fn main() {}
