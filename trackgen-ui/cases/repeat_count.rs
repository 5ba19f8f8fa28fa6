// The count of a repeated part block is one integer literal.
trackgen::model! {
    pub vehicle Tank {
        chassis { mass: 1000.0, inertia: 500.0 },
        roller r[2.5] { at: [(-1.0, 0.2), (-2.0, 0.2)], mass: 10.0, inertia: 0.2, radius: 0.1 },
        track { links: 8, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }
}

fn main() {}
