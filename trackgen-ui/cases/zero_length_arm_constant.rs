// A zero-length arm the macro cannot see (the points are constant
// expressions) is refused by rustc, at the pivot.
const WHEEL_X: f64 = -1.0;
const ARM_LENGTH: f64 = 0.0;

trackgen::model! {
    pub vehicle Tank {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 10 },
        idler rear { at: (WHEEL_X, 0.3), mass: 25.76, inertia: 1.12, radius: 0.255,
            arm { pivot: (-1.0, 0.3 + ARM_LENGTH), mass: 5.0, inertia: 0.05, stiffness: 4e4, damping: 560.0 } },
        track { links: 8, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }
}

fn main() {}
