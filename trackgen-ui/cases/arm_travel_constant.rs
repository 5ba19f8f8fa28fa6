// A travel the macro cannot evaluate (constant expressions) is checked by
// rustc: past a half turn, refused at the key's value.
const WIDE: f64 = 4.0;

trackgen::model! {
    pub vehicle Tank {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 10 },
        idler rear { at: (-3.0, 0.0), mass: 25.76, inertia: 1.12, radius: 0.255,
            arm { pivot: (-3.0, 0.2), mass: 5.0, inertia: 0.05, stiffness: 4e4, damping: 560.0,
                  travel: (-WIDE, 0.5) } },
        track { links: 8, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }
}

fn main() {}
