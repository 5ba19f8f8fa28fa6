// An override whose range selects no link is an error at the range, not a
// silent no-op; every such range is reported, beside the valid ones.
trackgen::model! {
    pub track Chain {
        links: 8,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        link[2..=1] { mass: 20.0 },
        link[3..3] { mass: 20.0 },
        link[1, 6..2, 7..=8] { inertia: 0.05 },
        link[4..5 by 2] { mass: 21.0 },
        closure: partitioned,
    }
}

fn main() {}
