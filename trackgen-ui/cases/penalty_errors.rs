// The keys of a penalty closure: both required, no others, stiffness
// positive and damping non-negative; each error at its token, all at once.
trackgen::model! {
    pub track NoStiffness {
        links: 4,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        closure: penalty { damping: 1e3 },
    }

    pub track NoDamping {
        links: 4,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        closure: penalty { stiffness: 1e7 },
    }

    pub track UnknownKey {
        links: 4,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        closure: penalty { stiffness: 1e7, damping: 1e3, preload: 5.0 },
    }

    pub track DuplicateKey {
        links: 4,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        closure: penalty { stiffness: 1e7, damping: 1e3, stiffness: 2e7 },
    }

    pub track NonPositive {
        links: 4,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        closure: penalty { stiffness: 0.0, damping: -1e3 },
    }

    pub track Negative {
        links: 4,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        closure: penalty { stiffness: -1e7, damping: 0.0 },
    }
}

fn main() {}
