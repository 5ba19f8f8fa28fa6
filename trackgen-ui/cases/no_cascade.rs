// After an error the type still exists: code that uses it reports nothing
// more than the one real error.
trackgen::model! {
    pub track Chain {
        links: 4,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0) },
    }
}

fn main() {
    let _chain = Chain;
}
