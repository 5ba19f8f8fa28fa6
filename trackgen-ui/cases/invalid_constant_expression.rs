// Values the macro cannot evaluate are checked by rustc, at their token.
const SHOE_MASS: f64 = -18.02;

trackgen::model! {
    pub track Chain {
        links: 4,
        link { mass: SHOE_MASS, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
    }
}

fn main() {}
