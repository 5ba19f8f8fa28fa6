// `teeth` is an integer literal of at least 3: each bad count is reported
// at its token, all at once.
const TEETH: u32 = 10;

trackgen::model! {
    pub vehicle Tank {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket fractional { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 10.5 },
        sprocket none { at: (-0.5, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 0 },
        sprocket two { at: (-1.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 2 },
        sprocket three { at: (-1.5, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 3 },
        sprocket negative { at: (-2.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: -4 },
        sprocket named { at: (-2.5, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: TEETH },
        track { links: 8, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }
}

fn main() {}
