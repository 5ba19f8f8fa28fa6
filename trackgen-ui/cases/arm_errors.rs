// Arms: only road wheels and idlers have them, and they need a pivot and a
// positive mass and inertia.
trackgen::model! {
    pub vehicle Tank {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 10,
            arm { pivot: (0.1, 0.1), mass: 5.0, inertia: 0.1, stiffness: 1.0, damping: 0.0 } },
        road_wheel rw1 { at: (-0.74, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305,
            arm { mass: -75.26, inertia: 0.77, stiffness: 2.5e4, damping: 500.0 } },
        track { links: 8, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }
}

fn main() {}
