// Hull outlines that make no convex polygon: too few corners, a dent, a
// value that is no list; each an error at the `hull` value.
trackgen::model! {
    pub vehicle TwoCorners {
        hull: [(0.0, 0.0), (1.0, 1.0)],
        chassis { mass: 1000.0, inertia: 500.0 },
        track { links: 4, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }

    pub vehicle Dented {
        hull: [(0.0, 0.0), (2.0, 0.0), (1.0, 0.3), (2.0, 1.0), (0.0, 1.0)],
        chassis { mass: 1000.0, inertia: 500.0 },
        track { links: 4, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }

    pub vehicle NotAList {
        hull: (0.0, 0.0),
        chassis { mass: 1000.0, inertia: 500.0 },
        track { links: 4, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }
}

fn main() {}
