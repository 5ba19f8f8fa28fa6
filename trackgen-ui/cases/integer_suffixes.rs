// Integer fields take an unsuffixed literal or their own type's suffix
// (`usize` for counts and link numbers, `u32` for teeth), as number fields
// take none or `f64`: any other suffix is an error.
trackgen::model! {
    pub track Chain {
        links: 8u8,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
    }

    pub track Suffixed {
        links: 8usize,
        link { mass: 18f64, inertia: 0.04f64, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        link[2usize..=4usize by 2usize] { mass: 20.0 },
        link[5i32, 6] { mass: 20.0 },
    }

    pub vehicle Tank {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 10u8 },
        track { links: 8, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }

    pub vehicle Fine {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 10u32 },
        track { links: 8, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }
}

fn main() {}
