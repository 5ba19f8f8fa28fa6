// Integer literals too large for their field are reported against the
// field's own bound, not as a malformed number or a too-small value.
trackgen::model! {
    pub track Huge {
        links: 99999999999999999999999,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
    }

    pub track Chain {
        links: 8,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        link[99999999999999999999999] { mass: 20.0 },
        link[2..=99999999999999999999999] { mass: 20.0 },
        link[1..=8 by 99999999999999999999999] { mass: 20.0 },
    }

    pub vehicle Tank {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 4294967296 },
        track { links: 8, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }
}

fn main() {}
