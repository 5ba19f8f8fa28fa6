//! Numeric fields accept constant expressions: named constants, arithmetic
//! on them, `const` blocks. The macro cannot evaluate these; rustc folds
//! them, and the result must equal the same track declared with literals.

use trackgen::multibody::RecursiveModel;
use trackgen::nalgebra::{SMatrix, SVector};

const PITCH: f64 = 0.154;
const SHOE_MASS: f64 = 18.02;
const SHOE_INERTIA: f64 = 0.04;

mod shoe {
    pub const HEAVY: f64 = 2.0 * super::SHOE_MASS;
    pub const DAMPING: f64 = 2.0;
}

trackgen::model! {
    /// Named constants.
    pub track Named {
        links: 5,
        link { mass: SHOE_MASS, inertia: SHOE_INERTIA, u1: (-PITCH / 2.0, 0.0), u2: (PITCH / 2.0, 0.0) },
        link[2] { mass: shoe::HEAVY, inertia: const { SHOE_INERTIA * 3.0 } },
        closure: penalty { stiffness: 1.0e6 * 2.0, damping: shoe::DAMPING },
    }

    /// The same, in literals.
    pub track Literal {
        links: 5,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        link[2] { mass: 36.04, inertia: 0.12, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        closure: penalty { stiffness: 2.0e6, damping: 2.0 },
    }
}

#[test]
fn constant_expressions_fold_to_the_literal_model() {
    assert_eq!(Named.description(), Literal.description());
    let q = SVector::<f64, 7>::from_fn(|i, _| 0.3 * i as f64 - 0.7);
    let qd = SVector::<f64, 7>::from_fn(|i, _| 0.2 * i as f64 + 0.1);
    let (mut m1, mut m2) = (SMatrix::<f64, 7, 7>::zeros(), SMatrix::<f64, 7, 7>::zeros());
    let (mut f1, mut f2) = (SVector::<f64, 7>::zeros(), SVector::<f64, 7>::zeros());
    Named.equations_of_motion(&q, &qd, &[], &mut m1, &mut f1);
    Literal.equations_of_motion(&q, &qd, &[], &mut m2, &mut f2);
    // The same constants reach the same arithmetic: agreement to rounding
    // of the constants themselves (the macro folds literal arithmetic in
    // its own order).
    assert!(
        (m1 - m2).amax() <= 1e-13 * m2.amax(),
        "{}",
        (m1 - m2).amax()
    );
    assert!(
        (f1 - f2).amax() <= 1e-13 * f2.amax(),
        "{}",
        (f1 - f2).amax()
    );
}
