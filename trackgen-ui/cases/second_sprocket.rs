// The runtime drives and meshes one sprocket: a second (or third) is an
// error at its keyword, and the parts' other errors are still reported.
trackgen::model! {
    pub vehicle Tank {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket front { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 10 },
        road_wheel rw1 { at: (-1.0, -0.2), mass: 35.56, inertia: 2.16, radius: 0.305 },
        sprocket rear { at: (-2.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 10 },
        sprocket spare { at: (-3.0, 0.0), mass: -27.68, inertia: 0.883, radius: 0.245, teeth: 10 },
        track { links: 8, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }
}

fn main() {}
