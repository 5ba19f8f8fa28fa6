// A part hangs from at most one arm: a second `arm` block is an error at
// its keyword, on a road wheel and on an idler alike.
trackgen::model! {
    pub vehicle Tank {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 10 },
        road_wheel rw1 { at: (-0.74, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305,
            arm { pivot: (-0.452, -0.081), mass: 75.26, inertia: 0.77, stiffness: 2.5e4, damping: 500.0 },
            arm { pivot: (-0.452, -0.081), mass: 75.26, inertia: 0.77, stiffness: 2.5e4, damping: 500.0 } },
        idler rear { at: (-3.95, -0.12), mass: 25.76, inertia: 1.12, radius: 0.255,
            arm { pivot: (-3.95, 0.08), mass: 5.0, inertia: 0.05, stiffness: 4e4, damping: 560.0 }
            arm { pivot: (-3.95, 0.08), mass: 5.0, inertia: 0.05, stiffness: 4e4, damping: 560.0 } },
        track { links: 8, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }
}

fn main() {}
