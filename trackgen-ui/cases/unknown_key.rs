trackgen::model! {
    pub track Chain {
        links: 4,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0), pitch: 0.154 },
        closure: open,
    }
}

fn main() {}
