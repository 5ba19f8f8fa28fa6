// A constant expression is emitted once, as a named constant, however many
// places of the generated code use it: a template's bad mass, copied to
// every link, is one error; each override's is one more.
trackgen::model! {
    pub track Chain {
        links: 64,
        link { mass: np.float64(18.02), inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        link[2] { inertia: np.float64(0.05) },
        closure: partitioned,
    }
}

fn main() {}
