// A `tracks` block that makes no spatial vehicle: a gauge narrower than
// the track, a hull no rigid body has, inertias across the plane that are
// not positive definite or name no body, and a left side that cannot
// mirror the right (a part it does not have, a repeated part given the
// wrong number of places, a link override beyond its shorter track);
// overrides for the declared side itself, a side that is neither; and a
// block without the shoe's width. Each an error at its token.
trackgen::model! {
    pub vehicle Narrow {
        chassis { mass: 1000.0, inertia: 500.0, centroid: (-1.0, 0.3) },
        sprocket drive { at: (0.0, 0.0), mass: 20.0, inertia: 0.5, radius: 0.2, teeth: 9 },
        road_wheel rw[2] { at: [(-0.5, -0.2), (-1.0, -0.2)], mass: 30.0, inertia: 1.5, radius: 0.25 },
        idler rear { at: (-1.6, 0.0), mass: 20.0, inertia: 1.0, radius: 0.2 },
        track {
            links: 4,
            link { mass: 10.0, inertia: 0.02, u1: (-0.06, 0.0), u2: (0.06, 0.0) },
            link[4] { mass: 12.0 },
        },
        shoe { ground_points: [(-0.05, -0.025), (0.05, -0.025)], inner_offset: 0.025,
               pins: [(0.055, 0.0)], pin_radius: 0.012, width: 0.4 },
        tracks {
            side: right,
            gauge: 0.35,
            hull { mass: 2000.0, inertia: (100.0, 1000.0, 1200.0) },
            across { rw: (1.0, 2.0, 1.5), wheel: (1.0, 1.0) },
            left {
                links: 3,
                front { at: (0.0, 0.0) },
                rw { at: [(-0.45, -0.2)] },
            },
            right { links: 5 },
        },
    }

    pub vehicle Widthless {
        chassis { mass: 1000.0, inertia: 500.0 },
        track { links: 4, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
        tracks {
            side: middle,
            gauge: 2.0,
            hull { mass: 2000.0, inertia: (600.0, 1000.0, 1200.0) },
        },
    }
}

fn main() {}
