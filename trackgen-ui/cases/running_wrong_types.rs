// The running keys of the wrong type: lists where lists are due, numbers
// where numbers are, each at its token.
trackgen::model! {
    pub vehicle Tank {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 10,
            tip_radius: (0.26, 0.0), gap_radius: "wide" },
        // One position where a list of two is due.
        road_wheel rw[2] { at: (-1.0, -0.2), mass: 35.56, inertia: 2.16, radius: 0.305 },
        track { links: 8, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
        shoe {
            ground_points: (-0.06, -0.03),
            inner_offset: [0.03],
            pins: [0.0535, (-0.061, 0.0)],
            pin_radius: 15u32,
        },
        contact { ground { stiffness: 2e6, chi: 2.0, mu: true }, tyres { mu: 0.5 } },
        drive { proportional: [3000.0], gain: 1.0 },
    }
}

fn main() {}
