// A tensioner's `travel` is (low, high) in rad from the design position,
// low ≤ 0 ≤ high, within a half turn each way: a range that leaves out the
// design position, one past a half turn, one that is not a pair.

trackgen::model! {
    pub vehicle Tank {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 10 },
        road_wheel rw1 { at: (-0.74, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305,
            arm { pivot: (-0.4, -0.1), mass: 75.26, inertia: 0.77, stiffness: 2.5e4, damping: 500.0,
                  travel: (0.1, 0.5) } },
        road_wheel rw2 { at: (-1.4, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305,
            arm { pivot: (-1.1, -0.1), mass: 75.26, inertia: 0.77, stiffness: 2.5e4, damping: 500.0,
                  travel: (-4.0, 1.0) } },
        road_wheel rw3 { at: (-2.1, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305,
            arm { pivot: (-1.8, -0.1), mass: 75.26, inertia: 0.77, stiffness: 2.5e4, damping: 500.0,
                  travel: 0.5 } },
        track { links: 8, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }
}

fn main() {}
