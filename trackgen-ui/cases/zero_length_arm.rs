// An arm carries its part at a distance: a pivot at the part's centre (to
// within a nanometre) is refused at the pivot; a micrometre is an arm.

trackgen::model! {
    pub vehicle Tank {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 10 },
        road_wheel rw1 { at: (-1.0, -0.2), mass: 35.56, inertia: 2.16, radius: 0.305,
            arm { pivot: (-1.0, -0.2), mass: 5.0, inertia: 0.1, stiffness: 2.5e4, damping: 500.0 } },
        road_wheel rw2 { at: (-2.0, -0.2), mass: 35.56, inertia: 2.16, radius: 0.305,
            arm { pivot: (-2.0 + 1e-12, -0.2), mass: 5.0, inertia: 0.1, stiffness: 2.5e4, damping: 500.0 } },
        road_wheel fine { at: (-3.0, -0.2), mass: 35.56, inertia: 2.16, radius: 0.305,
            arm { pivot: (-3.0 + 1e-6, -0.2), mass: 5.0, inertia: 0.1, stiffness: 2.5e4, damping: 500.0 } },
        track { links: 8, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }
}

fn main() {}
