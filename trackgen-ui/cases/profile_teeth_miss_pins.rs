// A tip circle below the pins of a seated link: the teeth pass under the
// pins and cannot drive the track. The error points at `tip_radius` and
// says how high it must reach.
trackgen::model! {
    pub vehicle Carrier {
        chassis { mass: 2400.0, inertia: 3800.0, centroid: (-1.3, 0.35) },
        sprocket drive { at: (0.0, 0.0), mass: 15.0, inertia: 0.3, radius: 0.14, teeth: 9,
            tip_radius: 0.15 },
        road_wheel rw[4] { at: [(-0.45, -0.30), (-1.0, -0.30), (-1.55, -0.30), (-2.1, -0.30)],
            mass: 25.0, inertia: 0.5, radius: 0.2 },
        idler rear { at: (-2.6, -0.08), mass: 20.0, inertia: 0.4, radius: 0.18 },
        track { links: 55, link { mass: 6.0, inertia: 0.01, u1: (-0.06, 0.0), u2: (0.06, 0.0) } },
        shoe { ground_points: [(-0.045, -0.02), (0.045, -0.02)], inner_offset: 0.02,
               pins: [(0.04, 0.0), (-0.04, 0.0)], pin_radius: 0.012 },
    }
}

fn main() {}
