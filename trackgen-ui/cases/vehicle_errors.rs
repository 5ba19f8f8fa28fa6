// Every problem is reported at once, each at its token.
trackgen::model! {
    pub vehicle Tank {
        chassis { mass: 3909.62 },
        sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245 },
        road_wheel rw1 { at: (-0.74, -0.215), mass: 35.56, inertia: 2.16, radius: -0.305 },
        road_wheel rw1 { at: (-1.4, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305 },
        turret top { mass: 1.0 },
    }
}

fn main() {}
