// An override range must advance: `by 0` is refused at the step.
trackgen::model! {
    pub track Chain {
        links: 8,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        link[1..=4 by 0] { mass: 20.0 },
        link[5..8 by 2] { mass: 20.0 },
    }
}

fn main() {}
