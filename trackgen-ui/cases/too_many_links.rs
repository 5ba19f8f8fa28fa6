// A track is unrolled into straight-line code: more than 1024 links is
// refused at the count, before any code is generated.
trackgen::model! {
    pub track Chain {
        links: 1025,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        closure: partitioned,
    }
}

fn main() {}
