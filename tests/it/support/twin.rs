//! A light carrier declared with both sides, its left its right's
//! mirror (the guide's example carrier's running gear, with the shoe's
//! width, regularised ground friction and a `tracks` block): the spatial
//! tests' vehicle.

trackgen::model! {
    /// A light carrier, its left side its right's mirror.
    pub vehicle Twin {
        chassis { mass: 1200.0, inertia: 1900.0, centroid: (-1.3, 0.35) },
        sprocket drive { at: (0.0, 0.0), mass: 15.0, inertia: 0.3, radius: 0.17, teeth: 9 },
        road_wheel rw[4] {
            at: [(-0.45, -0.30), (-1.0, -0.30), (-1.55, -0.30), (-2.1, -0.30)],
            mass: 25.0, inertia: 0.5, radius: 0.2,
            arm { pivot_offset: (0.22, 0.10), mass: 20.0, inertia: 0.2,
                  stiffness: 1.5e4, damping: 300.0, preload: 1.2e3 },
        },
        idler rear { at: (-2.6, -0.08), mass: 20.0, inertia: 0.4, radius: 0.18,
            arm { pivot: (-2.6, 0.12), mass: 3.0, inertia: 0.02,
                  stiffness: 2e4, damping: 600.0, preload: -2e3,
                  travel: (-0.6, 0.6) } },
        track { links: 55, link { mass: 6.0, inertia: 0.01, u1: (-0.06, 0.0), u2: (0.06, 0.0) } },
        shoe { ground_points: [(-0.045, -0.02), (0.045, -0.02)], inner_offset: 0.02,
               pins: [(0.045, 0.0), (-0.045, 0.0)], pin_radius: 0.012, width: 0.3 },
        contact { ground { stiffness: 1.5e6, chi: 2.0, mu: 0.7, slip: 0.1 } },
        tracks {
            gauge: 1.8,
            guide_play: 0.01,
            hull { mass: 2400.0, inertia: (1500.0, 3800.0, 4200.0) },
        },
    }
}

use trackgen::assembly::{AssembledSides, assemble_sides};
use trackgen::contact::GroundFriction;
use trackgen::contact::axial::GuideLaw;
use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::laws::Stiction;
use trackgen::nalgebra::{DVector, Matrix3, SVector, Vector3};
use trackgen::spatial::{PlanePose, PlaneRates, SpatialError, SpatialLayout, SpatialVehicle};
use trackgen::spatial_vehicle::{
    SideDrives, SpatialDynamics, SpatialLaws, SpatialSystem, TreeState,
};
use trackgen::terrain::Terrain;
use trackgen::terrain::field::HeightField;
use trackgen::vehicle::{Drive, Vehicle};

/// The hull's planar coordinates.
pub const DH: usize = <Twin as SpatialVehicle>::HULL_DOF;
/// A track's.
pub const DT: usize = Twin::TRACK_DOF;

/// The three trees' states.
pub type States = (TreeState<DH>, TreeState<DT>, TreeState<DT>);

/// The `Twin` in time.
pub type System = SpatialSystem<'static, TwinHull, DH, TwinTrack, DT, TwinTrack, DT>;

/// The hull's model, for the trees' borrows.
pub static HULL: TwinHull = TwinHull;
/// A track's.
pub static TRACK: TwinTrack = TwinTrack;

/// A tree upright at yaw 0, its root at `origin`, with planar `(q, q̇)`
/// and nothing across its plane.
pub fn upright<const D: usize>(
    origin: Vector3<f64>,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
) -> TreeState<D> {
    let mut planar = *q;
    (planar[0], planar[1]) = (0.0, 0.0);
    TreeState {
        pose: PlanePose {
            origin,
            yaw: 0.0,
            roll: 0.0,
            planar,
        },
        rates: PlaneRates {
            planar: *qd,
            across: Vector3::zeros(),
        },
    }
}

/// The `Twin` assembled on level ground.
pub fn assembled() -> AssembledSides<DH, DT, DT> {
    let geometry = Twin::geometry();
    assemble_sides(
        &TwinHull,
        (&TwinTrack, &TwinTrack),
        &Twin::layout().part_sides,
        &geometry.shoe,
        &geometry.sprocket,
        &Terrain::Flat { height: 0.0 },
        0.0,
        1e-3,
    )
    .expect("both sides assemble")
}

/// The `Twin`'s declared laws, and a guide.
pub fn laws() -> SpatialLaws {
    let config = Twin::declared_config(
        Terrain::Flat { height: 0.0 },
        Drive::Torque(Box::new(|_| 0.0)),
    );
    SpatialLaws {
        ground: config.ground,
        wheels: config.wheels,
        sprocket: config.sprocket,
        guide: GuideLaw {
            play: Twin::layout().guide_play,
            stiffness: 1e7,
            damping: 1e3,
            height: 0.06,
        },
        soil: None,
    }
}

/// The spatial `Twin` on `field` under `laws`, or why not.
pub fn built(
    laws: SpatialLaws,
    field: HeightField,
) -> Result<SpatialDynamics<'static, TwinHull, DH, TwinTrack, DT, TwinTrack, DT>, SpatialError> {
    built_on(laws, field, &Twin::layout())
}

/// The `Twin`'s layout with its tracks `gauge` m apart: each side's
/// running gear moved out or in with its track (the frame's inertia
/// kept).
pub fn layout_at(gauge: f64) -> SpatialLayout {
    let mut layout = Twin::layout();
    let scale = gauge / layout.gauge;
    layout.gauge = gauge;
    for offset in &mut layout.hull_offsets {
        *offset *= scale;
    }
    layout
}

/// [`built`] on `layout`.
pub fn built_on(
    laws: SpatialLaws,
    field: HeightField,
    layout: &SpatialLayout,
) -> Result<SpatialDynamics<'static, TwinHull, DH, TwinTrack, DT, TwinTrack, DT>, SpatialError> {
    let geometry = Twin::geometry();
    SpatialDynamics::new(
        &HULL,
        (&TRACK, &TRACK),
        layout,
        geometry.shoe.clone(),
        geometry.sprocket,
        laws,
        field,
    )
}

/// The spatial `Twin` on level ground with its declared laws.
pub fn spatial() -> SpatialDynamics<'static, TwinHull, DH, TwinTrack, DT, TwinTrack, DT> {
    built(laws(), HeightField::level()).expect("the spatial vehicle")
}

/// A speed drive tracking `speed` (m/s of belt, forward) reached by a
/// ramp over `ramp` s, with gains stiff enough to hold it.
pub fn belt(speed: f64, ramp: f64) -> Drive {
    Drive::Speed {
        target: Box::new(move |t| speed * (t / ramp).min(1.0)),
        proportional: 400.0,
        integral: 4000.0,
        max_torque: 3000.0,
    }
}

/// The `Twin` at rest on level ground, its hull's root at `(x, y)` and
/// turned `heading` rad about the vertical.
pub fn at_rest(heading: f64, (x, y): (f64, f64)) -> States {
    at_rest_apart(Twin::layout().gauge, heading, (x, y))
}

/// [`at_rest`] with the tracks `gauge` m apart ([`layout_at`]).
pub fn at_rest_apart(gauge: f64, heading: f64, (x, y): (f64, f64)) -> States {
    let start = assembled();
    let half = gauge / 2.0;
    let (qh, qt) = (start.hull, start.right);
    let (s, c) = heading.sin_cos();
    let placed =
        |px: f64, py: f64, z: f64| Vector3::new(c * px - s * py + x, s * px + c * py + y, z);
    let mut hull = upright(placed(qh[0], 0.0, qh[1]), &qh, &SVector::zeros());
    hull.pose.yaw = heading;
    let track = |lateral: f64| {
        let mut state = upright(placed(qt[0], lateral, qt[1]), &qt, &SVector::zeros());
        state.pose.yaw = heading;
        state
    };
    (hull, track(-half), track(half))
}

/// The shoes' friction coefficient on the ground under stiction.
pub const MU: f64 = 0.7;

/// A tree's state turned `roll` rad about the world's `x` axis (its yaw
/// 0): its plane rolled, its root's place turned with it.
fn rolled<const D: usize>(mut state: TreeState<D>, roll: f64) -> TreeState<D> {
    let (s, c) = roll.sin_cos();
    let turn = Matrix3::new(1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c);
    state.pose.origin = turn * state.pose.origin;
    state.pose.roll += roll;
    state
}

/// The `Twin` at rest heading along `x` across a side slope of `slope`
/// (rise over run along `y`, the field `z = slope · y`): level ground
/// through the origin turned by `atan slope` about `x` is that slope, so
/// [`at_rest`]'s start turned with it sits on the slope as it sat on the
/// level.
pub fn across_slope(slope: f64) -> States {
    let roll = slope.atan();
    let (hull, right, left) = at_rest(0.0, (0.0, 0.0));
    (rolled(hull, roll), rolled(right, roll), rolled(left, roll))
}

/// The `Twin`'s laws with stiction on the ground (`k_t` 1e5 N/m and
/// `c_t` 2e3 N s/m per point: about 2 mm of deflection at the Coulomb
/// limit under the quarter-tonne each point carries).
pub fn sticking() -> SpatialLaws {
    let mut laws = laws();
    laws.ground.friction = GroundFriction::Stiction(Stiction {
        mu: MU,
        stiffness: 1e5,
        damping: 2e3,
    });
    laws
}

/// The `Twin`'s laws on firm ground: stiction of 2e6 N/m and 4e3 N s/m
/// per planar ground point, each of its two points across the shoe's
/// width taking half (1e6 N/m: 0.14 mm of slide to the limit under the
/// 200 N such a point carries), the guides' play 1 mm. The steady turns
/// were set against the general theory, which has no shear of the
/// ground at all, on this ground; on one half as stiff (1e6 N/m per
/// planar point) the clutch-brake turn's standing inner belt takes
/// 8.3 % more torque than the theory's, where it takes 2 % more here:
/// the ground's give under a held belt is what the theory leaves out.
pub fn firm() -> SpatialLaws {
    let mut laws = sticking();
    laws.ground.friction = GroundFriction::Stiction(Stiction {
        mu: MU,
        stiffness: 2e6,
        damping: 4e3,
    });
    laws.guide.play = 1e-3;
    laws
}

/// The `Twin` on `field` under `laws`, its sprockets driven by `drives`.
pub fn on(field: HeightField, laws: SpatialLaws, drives: SideDrives) -> System {
    on_layout(field, laws, drives, &Twin::layout())
}

/// [`on`] laid out as `layout` says ([`layout_at`]).
pub fn on_layout(
    field: HeightField,
    laws: SpatialLaws,
    drives: SideDrives,
    layout: &SpatialLayout,
) -> System {
    SpatialSystem::new(built_on(laws, field, layout).expect("the spatial vehicle"))
        .with_drives(drives)
        .expect("drives that make controllers")
}

/// `system` run from `start` for `end` s by `method`: its final state.
pub fn run(system: &mut System, start: &States, end: f64, method: Integrator) -> DVector<f64> {
    let mut y = system.state(&start.0, &start.1, &start.2);
    let mut stepper = method.stepper(system.dimension());
    let mut t = 0.0;
    while t < end {
        stepper.step(system, &mut t, &mut y, end).expect("the run");
    }
    y
}

/// A hull vector's sides exchanged: the frame's values (the root's two
/// and the frame's angle) kept, the right side's bodies' and the left's
/// swapped.
pub fn swap_sides(v: &SVector<f64, DH>) -> SVector<f64, DH> {
    let side = (DH - 3) / 2;
    SVector::<f64, DH>::from_fn(|i, _| match i {
        _ if i < 3 => v[i],
        _ if i < 3 + side => v[i + side],
        _ => v[i - side],
    })
}

/// The vehicle's mirror image across its centre plane: each tree's
/// origin's `y`, yaw and roll reversed, its rates across its plane
/// reversed, the hull's right and left bodies and the two tracks
/// exchanged.
pub fn mirror((hull, right, left): &States) -> States {
    let flip = |state: &TreeState<DT>| {
        let mut state = state.clone();
        state.pose.origin.y = -state.pose.origin.y;
        (state.pose.yaw, state.pose.roll) = (-state.pose.yaw, -state.pose.roll);
        state.rates.across = -state.rates.across;
        state
    };
    let mut h = hull.clone();
    h.pose.origin.y = -h.pose.origin.y;
    (h.pose.yaw, h.pose.roll) = (-h.pose.yaw, -h.pose.roll);
    h.pose.planar = swap_sides(&h.pose.planar);
    h.rates.planar = swap_sides(&h.rates.planar);
    h.rates.across = -h.rates.across;
    (h, flip(left), flip(right))
}
