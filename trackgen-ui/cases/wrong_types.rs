trackgen::model! {
    pub track Chain {
        links: 4.5,
        link { mass: "heavy", inertia: 0.04f32, u1: 0.077, u2: (0.077, 0.0, 0.0) },
        closure: closed,
    }
}

fn main() {}
