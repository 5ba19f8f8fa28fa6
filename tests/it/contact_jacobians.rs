//! Each contact's Jacobian (`trackgen::contact::tangent`: the detectors'
//! geometry tangents through the laws' slopes) against central differences
//! of the same contact's load, found anew by detection and the law at
//! every shifted state: the ground (stiction sticking and sliding, and
//! regularised friction on a curved bump), the rims (the face's inside
//! and its ends), the teeth (flank and tip) and soft soil (fresh, a
//! pressed patch loading and unloading, a sloping rut's memory), at
//! random states of the M113's shoe and laws on dry sand.
//!
//! Tolerance: 1e-6 of the largest entry of each row (the bound).
//! The central step is 1e-7 (m, rad, m/s, rad/s) on a scale of 1: its
//! truncation `h² f‴/6`, with the Hunt-Crossley force's third derivative
//! of order `k δ^{-1.5}` at δ ≥ 1 mm, is below 1e-8 of the slope, and its
//! rounding `ε |F| / h` (F of order 10⁴ N) below 1e-7 of the row's scale;
//! states within a step of a kink (the normal force's clip, the stick-slip
//! limit, a face's end, the flank–tip boundary, the nearest gap's switch,
//! the soil's deepest sinkage and its pressure's clip, a rut cell's
//! centre) are skipped, as the derivative is one-sided there. On the
//! soil's kink itself, where a point just pressed sits, the slope of the
//! side it moves toward is checked against that side's one-sided
//! difference.

use crate::support;

use support::Lcg;
use trackgen::contact::{
    BodyState, Contact, ContactJacobian, ContactLaws, GroundFriction, GroundLaws, ShoeGeometry,
    ground, soft_ground::Rut, soft_ground::SoftGround, sprocket, sprocket::ToothProfile, wheel,
};
use trackgen::multibody::BodyLoad;
use trackgen::nalgebra::{SMatrix, Vector2};
use trackgen::terrain::profile::{Course, ProfileError};
use trackgen::terrain::{Terrain, soil::SoilMemory, soil::SoilPreset};
use trackgen::vehicle::Vehicle;
use trackgen::vehicles::m113::M113;

const STEP: f64 = 1e-7;

/// The contact Jacobian's columns.
const INPUTS: usize = ContactJacobian::INPUTS;
const DEFLECTION: usize = ContactJacobian::DEFLECTION;
const LINK_POSE: usize = ContactJacobian::LINK_POSE;
const OTHER_POSE: usize = ContactJacobian::OTHER_POSE;

/// The inputs of a contact: link pose and rates, other pose and rates,
/// deflection.
type Inputs = [f64; INPUTS];

fn states(x: &Inputs) -> (BodyState, BodyState) {
    (
        BodyState::new(
            Vector2::new(x[0], x[1]),
            x[2],
            Vector2::new(x[3], x[4]),
            x[5],
        ),
        BodyState::new(
            Vector2::new(x[6], x[7]),
            x[8],
            Vector2::new(x[9], x[10]),
            x[11],
        ),
    )
}

/// What a contact gives: the link's load, the other body's, the
/// deflection's rate (7 values).
type Output = [f64; 7];

fn output(link: BodyLoad, other: BodyLoad, rate: f64) -> Output {
    [
        link.force.x,
        link.force.y,
        link.moment,
        other.force.x,
        other.force.y,
        other.moment,
        rate,
    ]
}

/// One kind of contact: finds the contact of `feature` at `x` (None if
/// there is none), responds, and linearises.
trait Pair {
    fn find(&self, x: &Inputs, feature: usize) -> Option<Contact>;
    fn respond(&self, x: &Inputs, contact: &Contact) -> Output;
    fn linearise(&self, x: &Inputs, contact: &Contact) -> ContactJacobian;
    /// Whether the state is within `margin` of a kink of this pair.
    fn near_kink(&self, x: &Inputs, contact: &Contact, margin: f64) -> bool;
    /// Which branch of its law or geometry the contact is on.
    fn branch(&self, x: &Inputs, contact: &Contact) -> &'static str;
}

fn loads_of(
    contact: &Contact,
    force: &trackgen::contact::ContactForce,
    other: Option<Vector2<f64>>,
) -> (BodyLoad, BodyLoad) {
    let (mut link, mut on_other) = (BodyLoad::ZERO, BodyLoad::ZERO);
    force.apply(
        contact,
        &mut link,
        other.map(|position| (&mut on_other, position)),
    );
    (link, on_other)
}

/// The contact of the link at `x`'s ground point `feature` with the
/// ground, if it is below the surface.
fn ground_contact(
    terrain: &Terrain,
    shoe: &ShoeGeometry,
    x: &Inputs,
    feature: usize,
) -> Option<Contact> {
    let (link, _) = states(x);
    let mut contacts = Vec::new();
    ground::detect(terrain, &[link], shoe, &mut contacts);
    contacts.into_iter().find(|c| c.feature == feature)
}

struct Ground {
    terrain: Terrain,
    laws: GroundLaws,
    shoe: ShoeGeometry,
}

impl Pair for Ground {
    fn find(&self, x: &Inputs, feature: usize) -> Option<Contact> {
        ground_contact(&self.terrain, &self.shoe, x, feature)
    }

    fn respond(&self, x: &Inputs, contact: &Contact) -> Output {
        let (force, rate) = self.laws.respond(contact, x[DEFLECTION]);
        let (link, other) = loads_of(contact, &force, None);
        output(link, other, rate)
    }

    fn linearise(&self, x: &Inputs, contact: &Contact) -> ContactJacobian {
        let (link, _) = states(x);
        let geometry = ground::tangent(&self.terrain, contact);
        let mut out = ContactJacobian::ZERO;
        self.laws
            .linearise(contact, x[DEFLECTION], &geometry, &link, &mut out);
        out
    }

    fn near_kink(&self, x: &Inputs, contact: &Contact, margin: f64) -> bool {
        let GroundFriction::Stiction(s) = self.laws.friction else {
            return contact.depth < margin;
        };
        let (force, _) = self.laws.respond(contact, x[DEFLECTION]);
        let slip = contact.velocity.dot(&-contact.tangent());
        let stick = s.stiffness * x[DEFLECTION] + s.damping * slip;
        let limit = s.mu * force.normal;
        contact.depth < margin || (stick.abs() - limit).abs() < 1e-4 * limit.max(1.0)
    }

    fn branch(&self, x: &Inputs, contact: &Contact) -> &'static str {
        let GroundFriction::Stiction(s) = self.laws.friction else {
            return "regularised";
        };
        let (force, _) = self.laws.respond(contact, x[DEFLECTION]);
        let slip = contact.velocity.dot(&-contact.tangent());
        if (s.stiffness * x[DEFLECTION] + s.damping * slip).abs() <= s.mu * force.normal {
            "sticking"
        } else {
            "sliding"
        }
    }
}

struct Rim {
    laws: ContactLaws,
    radius: f64,
    shoe: ShoeGeometry,
}

impl Pair for Rim {
    fn find(&self, x: &Inputs, _: usize) -> Option<Contact> {
        let (link, wheel_state) = states(x);
        let mut contacts = Vec::new();
        wheel::detect(
            (&wheel_state, 1, self.radius),
            &[link],
            &self.shoe,
            &mut contacts,
        );
        contacts.into_iter().next()
    }

    fn respond(&self, x: &Inputs, contact: &Contact) -> Output {
        let (_, wheel_state) = states(x);
        let force = self.laws.respond(contact);
        let (link, other) = loads_of(contact, &force, Some(wheel_state.position));
        output(link, other, 0.0)
    }

    fn linearise(&self, x: &Inputs, contact: &Contact) -> ContactJacobian {
        let (link, wheel_state) = states(x);
        let geometry = wheel::tangent(contact, &link, &wheel_state, &self.shoe);
        let mut out = ContactJacobian::ZERO;
        self.laws
            .linearise(contact, &geometry, &link, Some(&wheel_state), &mut out);
        out
    }

    fn near_kink(&self, x: &Inputs, contact: &Contact, margin: f64) -> bool {
        let (link, wheel_state) = states(x);
        let (a, b) = (
            link.point(self.shoe.inner_face[0]),
            link.point(self.shoe.inner_face[1]),
        );
        let s = (wheel_state.position - a).dot(&(b - a)) / (b - a).norm_squared();
        contact.depth < margin || s.abs() < margin || (s - 1.0).abs() < margin
    }

    fn branch(&self, x: &Inputs, _: &Contact) -> &'static str {
        let (link, wheel_state) = states(x);
        let (a, b) = (
            link.point(self.shoe.inner_face[0]),
            link.point(self.shoe.inner_face[1]),
        );
        let s = (wheel_state.position - a).dot(&(b - a)) / (b - a).norm_squared();
        if (0.0..=1.0).contains(&s) {
            "inside the face"
        } else {
            "a face's end"
        }
    }
}

struct Teeth {
    laws: ContactLaws,
    profile: ToothProfile,
    shoe: ShoeGeometry,
}

impl Teeth {
    /// The two depths detection compares, and the gap's angle from the
    /// pin's half-way to the next gap (1 = on the switch).
    fn branches(&self, x: &Inputs, feature: usize) -> (f64, f64, f64) {
        let (link, sprocket_state) = states(x);
        let pin = link.point(self.shoe.pins[feature]);
        let gap = self.profile.nearest_gap(&sprocket_state, pin);
        let (c, r) = (sprocket_state.position, self.profile.pitch_angle());
        let angle = |p: Vector2<f64>| (p - c).y.atan2((p - c).x);
        let mut off = (angle(pin) - angle(gap)).abs();
        off = off.min(2.0 * std::f64::consts::PI - off);
        (
            (pin - gap).norm() + self.shoe.pin_radius - self.profile.arc_radius,
            self.profile.addendum + self.shoe.pin_radius - (pin - c).norm(),
            off / (0.5 * r),
        )
    }
}

impl Pair for Teeth {
    fn find(&self, x: &Inputs, feature: usize) -> Option<Contact> {
        let (link, sprocket_state) = states(x);
        let mut contacts = Vec::new();
        sprocket::detect(
            (&sprocket_state, 1),
            &self.profile,
            &[link],
            &self.shoe,
            &mut contacts,
        );
        contacts.into_iter().find(|c| c.feature == feature)
    }

    fn respond(&self, x: &Inputs, contact: &Contact) -> Output {
        let (_, sprocket_state) = states(x);
        let force = self.laws.respond(contact);
        let (link, other) = loads_of(contact, &force, Some(sprocket_state.position));
        output(link, other, 0.0)
    }

    fn linearise(&self, x: &Inputs, contact: &Contact) -> ContactJacobian {
        let (link, sprocket_state) = states(x);
        let geometry =
            sprocket::tangent(contact, &link, &sprocket_state, &self.profile, &self.shoe);
        let mut out = ContactJacobian::ZERO;
        self.laws
            .linearise(contact, &geometry, &link, Some(&sprocket_state), &mut out);
        out
    }

    fn near_kink(&self, x: &Inputs, contact: &Contact, margin: f64) -> bool {
        let (flank, tip, off) = self.branches(x, contact.feature);
        contact.depth < margin || (flank - tip).abs() < margin || off > 0.99
    }

    fn branch(&self, x: &Inputs, contact: &Contact) -> &'static str {
        let (flank, tip, _) = self.branches(x, contact.feature);
        if flank <= tip { "flank" } else { "tip" }
    }
}

/// The Jacobian as 7 rows over the inputs.
fn rows(j: &ContactJacobian) -> SMatrix<f64, 7, INPUTS> {
    let mut m = SMatrix::<f64, 7, INPUTS>::zeros();
    m.fixed_rows_mut::<3>(0).copy_from(&j.link);
    m.fixed_rows_mut::<3>(3).copy_from(&j.other);
    m.set_row(6, &j.rate);
    m
}

/// Checks `pair` at `x` for `feature`; returns the branch if the state
/// was used (a contact, no kink within the differences' reach).
fn check(label: &str, pair: &dyn Pair, x: &Inputs, feature: usize) -> Option<&'static str> {
    let contact = pair.find(x, feature)?;
    if pair.near_kink(x, &contact, 1e-4) {
        return None;
    }
    let exact = rows(&pair.linearise(x, &contact));
    let mut differences = SMatrix::<f64, 7, INPUTS>::zeros();
    for column in 0..INPUTS {
        let at = |sign: f64| {
            let mut shifted = *x;
            shifted[column] += sign * STEP;
            let contact = pair
                .find(&shifted, feature)
                .expect("the contact persists within a step");
            pair.respond(&shifted, &contact)
        };
        let (plus, minus) = (at(1.0), at(-1.0));
        for r in 0..7 {
            differences[(r, column)] = (plus[r] - minus[r]) / (2.0 * STEP);
        }
    }
    for r in 0..7 {
        let scale = (0..INPUTS)
            .map(|c| differences[(r, c)].abs())
            .fold(0.0, f64::max);
        for c in 0..INPUTS {
            let (got, want) = (exact[(r, c)], differences[(r, c)]);
            assert!(
                (got - want).abs() <= 1e-6 * scale.max(1e-9),
                "{label}: row {r} column {c}: exact {got:e}, differences {want:e} \
                 (row scale {scale:e})\nstate {x:?}"
            );
        }
    }
    Some(pair.branch(x, &contact))
}

/// Random link states near the ground, wheel or sprocket at `centre`
/// (within `reach` m), the other body at `centre` with random pose and
/// rates, and a random deflection `z` within `deflection` m.
fn random_inputs(
    rng: &mut Lcg,
    centre: Vector2<f64>,
    reach: (f64, f64),
    deflection: f64,
) -> Inputs {
    let mut x = [0.0; INPUTS];
    let angle = rng.uniform(-3.2, 3.2);
    let distance = rng.uniform(reach.0, reach.1);
    x[LINK_POSE] = centre.x + distance * angle.cos();
    x[LINK_POSE + 1] = centre.y + distance * angle.sin();
    // The link's left (its inner face) toward the centre, give or take.
    x[LINK_POSE + 2] = angle + std::f64::consts::PI / 2.0 + rng.uniform(-0.3, 0.3);
    for v in &mut x[3..6] {
        *v = rng.uniform(-2.0, 2.0);
    }
    x[OTHER_POSE] = centre.x;
    x[OTHER_POSE + 1] = centre.y;
    x[OTHER_POSE + 2] = rng.uniform(-3.2, 3.2);
    for v in &mut x[9..12] {
        *v = rng.uniform(-2.0, 2.0);
    }
    x[DEFLECTION] = rng.uniform(-deflection, deflection);
    x
}

fn m113_config() -> trackgen::vehicle::VehicleConfig {
    M113::declared_config(Terrain::Flat { height: 0.0 }, M113::speed_drive(|_| 0.0))
}

/// Runs `pair` at random states until each of `branches` has been
/// checked at `wanted` states.
fn sweep(
    label: &str,
    pair: &dyn Pair,
    (branches, wanted): (&[&str], usize),
    mut draw: impl FnMut(&mut Lcg) -> (Inputs, usize),
) {
    let mut rng = Lcg::new(label.len() as u64 * 7919);
    let mut used = vec![0; branches.len()];
    for _ in 0..50_000 {
        let (x, feature) = draw(&mut rng);
        if let Some(branch) = check(label, pair, &x, feature) {
            let k = branches
                .iter()
                .position(|b| *b == branch)
                .unwrap_or_else(|| panic!("{label}: unexpected branch {branch}"));
            used[k] += 1;
            if used.iter().all(|&u| u >= wanted) {
                return;
            }
        }
    }
    panic!("{label}: states checked per branch {branches:?}: {used:?}, wanted {wanted} each");
}

/// A shoe's ground point below flat ground and a bump: its pose around the
/// point, random rates and deflections (sticking and sliding both drawn:
/// the deflection's force ranges round the Coulomb limit).
#[test]
fn ground_contacts_match_their_differences() {
    let config = m113_config();
    let shoe = M113::geometry().shoe;
    let GroundFriction::Stiction(stiction) = config.ground.friction else {
        panic!("the M113 declares stiction");
    };
    let limit = stiction.mu * 2e3 / stiction.stiffness;
    let cases = [
        (
            "flat, stiction",
            Terrain::Flat { height: 0.0 },
            config.ground,
        ),
        (
            "bump, stiction",
            Terrain::Bump {
                centre: 0.0,
                width: 1.0,
                height: 0.1,
            },
            config.ground,
        ),
        (
            "bump, regularised",
            Terrain::Bump {
                centre: 0.0,
                width: 1.0,
                height: 0.1,
            },
            GroundLaws {
                friction: GroundFriction::Regularised(trackgen::laws::Friction {
                    mu: 0.8,
                    slip: 0.1,
                }),
                ..config.ground
            },
        ),
    ];
    for (label, terrain, laws) in cases {
        let pair = Ground {
            terrain: terrain.clone(),
            laws,
            shoe: shoe.clone(),
        };
        let branches: &[&str] = match laws.friction {
            GroundFriction::Stiction(_) => &["sticking", "sliding"],
            GroundFriction::Regularised(_) => &["regularised"],
        };
        sweep(label, &pair, (branches, 30), |rng| {
            let feature = (rng.uniform(0.0, 2.0) as usize).min(1);
            let mut x = random_inputs(rng, Vector2::zeros(), (0.0, 0.0), 2.0 * limit);
            // Over the bump's flank, the link level give or take, its
            // point 0.5 – 6 mm into the ground.
            x[0] = rng.uniform(-0.4, 0.4);
            x[2] = rng.uniform(-0.2, 0.2);
            let local = shoe.ground_points[feature];
            let arm = BodyState::new(Vector2::zeros(), x[2], Vector2::zeros(), 0.0).arm(local);
            let h = terrain.height(x[0] + arm.x);
            x[1] = h - arm.y - rng.uniform(0.0005, 0.006);
            (x, feature)
        });
    }
}

/// A ground point against a polyline with vertical faces, near a step
/// up's foot and face, a step down's face, and a half-round's facets: the
/// depth is the distance to the nearest edge (an edge's normal is fixed;
/// at a vertex it turns), its Jacobian against central differences like
/// the smooth terrains'. Points are drawn 0.5 – 6 mm inside the ground
/// within 1 cm of a face, so edges, faces and the step's foot (a vertex:
/// the corner where floor and face meet) all come up.
#[test]
fn ground_contacts_on_polylines_match_their_differences() {
    let config = m113_config();
    let shoe = M113::geometry().shoe;
    let GroundFriction::Stiction(stiction) = config.ground.friction else {
        panic!("the M113 declares stiction");
    };
    let limit = stiction.mu * 2e3 / stiction.stiffness;
    let course = |build: fn(Course) -> Result<Course, ProfileError>| {
        let course = Course::starting_at(-1.0, 0.0)
            .and_then(|c| c.flat(1.0))
            .unwrap();
        Terrain::profile(
            build(course)
                .and_then(|c| c.flat(1.0))
                .unwrap()
                .profile()
                .unwrap(),
        )
    };
    // Each terrain with the x of the face the points are drawn near, and
    // the height they are drawn under (`None`: the surface's there).
    let cases = [
        ("step up 0.1 m", course(|c| c.step(0.1)), 0.0, None),
        // Right of the face, below the floor's level: nearest the corner
        // where floor and face meet, a vertex whose normal turns.
        (
            "step up 0.1 m, at its foot",
            course(|c| c.step(0.1)),
            0.005,
            Some(0.0),
        ),
        ("step down 0.1 m", course(|c| c.step(-0.1)), 0.0, None),
        (
            "half-round 0.1 m",
            course(|c| c.half_round(0.1)),
            0.05,
            None,
        ),
        // The half-round's foot: where it rises from the floor.
        (
            "half-round 0.1 m, at its foot",
            course(|c| c.half_round(0.1)),
            0.005,
            Some(0.0),
        ),
    ];
    for (label, terrain, face, level) in cases {
        let pair = Ground {
            terrain: terrain.clone(),
            laws: config.ground,
            shoe: shoe.clone(),
        };
        sweep(label, &pair, (&["sticking", "sliding"], 30), |rng| {
            let feature = (rng.uniform(0.0, 2.0) as usize).min(1);
            let mut x = random_inputs(rng, Vector2::zeros(), (0.0, 0.0), 2.0 * limit);
            x[2] = rng.uniform(-0.2, 0.2);
            let local = shoe.ground_points[feature];
            let arm = BodyState::new(Vector2::zeros(), x[2], Vector2::zeros(), 0.0).arm(local);
            // The point within 5 mm of `face` (1 cm of it beside the
            // foot of a face), below the surface there (or `level`).
            let spread = if level.is_some() { 0.005 } else { 0.01 };
            let px = face + rng.uniform(-spread, spread);
            let top = level.unwrap_or_else(|| terrain.height(px));
            x[0] = px - arm.x;
            x[1] = top - arm.y - rng.uniform(0.0005, 0.006);
            (x, feature)
        });
    }
}

/// A ground point at a vertical face is pushed sideways, as a wall does,
/// by its distance to the face: 3 mm into the face of a 0.1 m step, 5 cm
/// below its top, it is 3 mm deep with the normal −x; the vertical depth
/// (0.05 m) would have lifted it onto the step.
#[test]
fn a_vertical_face_pushes_a_point_sideways() {
    let profile = Course::new()
        .flat(1.0)
        .and_then(|c| c.step(0.1))
        .and_then(|c| c.flat(1.0))
        .and_then(Course::profile)
        .unwrap();
    let terrain = Terrain::profile(profile);
    let shoe = ShoeGeometry {
        ground_points: vec![Vector2::zeros()],
        ..M113::geometry().shoe
    };
    let link = BodyState::at_rest(Vector2::new(1.003, 0.05), 0.0);
    let mut contacts = Vec::new();
    ground::detect(&terrain, &[link], &shoe, &mut contacts);
    let [contact] = contacts.as_slice() else {
        panic!("one contact, got {contacts:?}");
    };
    assert!((contact.depth - 0.003).abs() < 1e-15, "{}", contact.depth);
    assert_eq!(contact.gradient, Vector2::new(-1.0, 0.0));
    assert_eq!(contact.gradient_norm, 1.0);
}

#[test]
fn rim_contacts_match_their_differences() {
    let config = m113_config();
    let shoe = M113::geometry().shoe;
    let pair = Rim {
        laws: config.wheels,
        radius: 0.305,
        shoe: shoe.clone(),
    };
    // The link's inner face 0.5 – 4 mm into the rim: its centroid at the
    // rim's radius plus the face's offset, less that.
    let offset = shoe.inner_offset();
    // The face's ends too: every other draw moves the link 8 – 10 cm
    // along itself, beyond the wheel's tangent point.
    let mut beyond = false;
    let branches: &[&str] = &["inside the face", "a face's end"];
    sweep("rim", &pair, (branches, 30), |rng| {
        let depth = rng.uniform(0.0005, 0.004);
        let r = 0.305 + offset - depth;
        let mut x = random_inputs(rng, Vector2::new(0.3, -0.2), (r, r), 0.0);
        beyond = !beyond;
        if beyond {
            let along = rng.uniform(0.08, 0.1) * (rng.uniform(0.0, 2.0).floor() * 2.0 - 1.0);
            x[0] += along * x[2].cos();
            x[1] += along * x[2].sin();
        }
        (x, 0)
    });
}

#[test]
fn tooth_contacts_match_their_differences() {
    let config = m113_config();
    let geometry = M113::geometry();
    let pair = Teeth {
        laws: config.sprocket,
        profile: geometry.sprocket,
        shoe: geometry.shoe.clone(),
    };
    let seat = sprocket::pitch_radius(10, 0.154);
    sweep("teeth", &pair, (&["flank", "tip"], 30), |rng| {
        let feature = (rng.uniform(0.0, 2.0) as usize).min(1);
        let r = rng.uniform(seat - 0.02, seat + 0.02);
        (
            random_inputs(rng, Vector2::new(-0.1, 0.2), (r, r), 0.0),
            feature,
        )
    });
}

/// Soft soil under one link: its memory under each ground point (`None`:
/// the rut's, before the patches are kept).
struct Soft {
    ground: SoftGround,
    terrain: Terrain,
    shoe: ShoeGeometry,
    patches: Option<Vec<SoilMemory>>,
}

/// The M113's track width, m.
const WIDTH: f64 = 0.38;

impl Soft {
    fn new(rut: Option<Rut>) -> Soft {
        let shoe = M113::geometry().shoe;
        let mut ground =
            SoftGround::new(SoilPreset::DrySand.soil(), WIDTH, 0.154, &shoe).expect("a soil");
        if let Some(rut) = rut {
            ground.rut = rut;
        }
        Soft {
            ground,
            terrain: Terrain::Flat { height: 0.0 },
            shoe,
            patches: None,
        }
    }

    /// Presses the ground under the link at `x`: from then on each point
    /// carries its patch.
    fn press(&mut self, x: &Inputs) {
        let (link, _) = states(x);
        let mut shear = vec![0.0; self.shoe.ground_points.len()];
        self.ground
            .press(&self.terrain, &[link], &self.shoe, &mut shear);
        let soil = self.ground.soil;
        self.patches = Some(
            self.shoe
                .ground_points
                .iter()
                .map(|&g| SoilMemory::default().pressed_to(&soil, -link.point(g).y, WIDTH))
                .collect(),
        );
    }

    /// The memory under the contact's point and its slope along x.
    fn memory(&self, contact: &Contact) -> (SoilMemory, SoilMemory) {
        match &self.patches {
            Some(patches) => (patches[contact.feature], SoilMemory::default()),
            None => self.ground.rut.memory_and_slopes(contact.point.x),
        }
    }
}

impl Pair for Soft {
    fn find(&self, x: &Inputs, feature: usize) -> Option<Contact> {
        ground_contact(&self.terrain, &self.shoe, x, feature)
    }

    fn respond(&self, x: &Inputs, contact: &Contact) -> Output {
        let points = self.shoe.ground_points.len();
        let (force, rate) = self.ground.respond(contact, points, x[DEFLECTION]);
        let (link, other) = force.map_or((BodyLoad::ZERO, BodyLoad::ZERO), |force| {
            loads_of(contact, &force, None)
        });
        output(link, other, rate)
    }

    fn linearise(&self, x: &Inputs, contact: &Contact) -> ContactJacobian {
        let (link, _) = states(x);
        let geometry = ground::tangent(&self.terrain, contact);
        let mut out = ContactJacobian::ZERO;
        let points = self.shoe.ground_points.len();
        self.ground
            .linearise(contact, points, x[DEFLECTION], &geometry, &link, &mut out);
        out
    }

    fn near_kink(&self, _: &Inputs, contact: &Contact, margin: f64) -> bool {
        let soil = &self.ground.soil;
        let (memory, _) = self.memory(contact);
        let z = contact.depth;
        let pressure = memory.pressure(soil, z, WIDTH);
        let damped = pressure + soil.damping * contact.rate();
        let cell = self.ground.rut.cell();
        let from_centre = (contact.point.x / cell - 0.5).rem_euclid(1.0);
        let rut_cell = self.patches.is_none() && memory != SoilMemory::default();
        z < margin
            || (z - memory.deepest(soil)).abs() < margin
            || (z - memory.plastic).abs() < margin
            || damped.abs() < margin * soil.unloading_stiffness
            || (rut_cell && from_centre.min(1.0 - from_centre) * cell < margin)
    }

    fn branch(&self, _: &Inputs, contact: &Contact) -> &'static str {
        let soil = &self.ground.soil;
        let (memory, _) = self.memory(contact);
        let z = contact.depth;
        if memory.pressure(soil, z, WIDTH) + soil.damping * contact.rate() <= 0.0 {
            "not bearing"
        } else if z > memory.deepest(soil) {
            "loading"
        } else {
            "unloading"
        }
    }
}

/// A level link with its ground point `feature` at depth `z` (m), moving
/// at random rates (±0.4 m/s, ±2 rad/s) with a random shear displacement
/// (±3 K).
fn sunk_link(rng: &mut Lcg, shoe: &ShoeGeometry, feature: usize, z: f64) -> Inputs {
    let mut x = random_inputs(rng, Vector2::zeros(), (0.0, 0.0), 0.075);
    x[0] = rng.uniform(-0.4, 0.4);
    x[2] = rng.uniform(-0.05, 0.05);
    x[3] *= 0.2;
    x[4] *= 0.2;
    let local = shoe.ground_points[feature];
    let arm = BodyState::new(Vector2::zeros(), x[2], Vector2::zeros(), 0.0).arm(local);
    x[1] = -arm.y - z;
    x
}

/// Soft soil: fresh (Bekker), a patch pressed to 3 cm (loading beyond it,
/// unloading short of it), and a rut whose memory slopes along x (before
/// the patches are kept: the pressure and the rut's wall vary with x).
#[test]
fn soil_contacts_match_their_differences() {
    let fresh = Soft::new(None);
    let shoe = fresh.shoe.clone();
    sweep(
        "soil, fresh",
        &fresh,
        (&["loading", "not bearing"], 30),
        |rng| {
            let feature = (rng.uniform(0.0, 2.0) as usize).min(1);
            let z = rng.uniform(0.002, 0.05);
            (sunk_link(rng, &shoe, feature, z), feature)
        },
    );

    let mut pressed = Soft::new(None);
    let mut at = [0.0; INPUTS];
    at[1] = -shoe.ground_points[0].y - 0.03;
    pressed.press(&at);
    let patches = pressed.patches.clone().expect("pressed");
    let soil = pressed.ground.soil;
    sweep(
        "soil, pressed",
        &pressed,
        (&["loading", "unloading", "not bearing"], 30),
        |rng| {
            let feature = (rng.uniform(0.0, 2.0) as usize).min(1);
            let memory = patches[feature];
            let (plastic, deepest) = (memory.plastic, memory.deepest(&soil));
            let z = rng.uniform(plastic, deepest + 0.5 * (deepest - plastic));
            let mut x = sunk_link(rng, &shoe, feature, z);
            // The patch moves with the point: the link stays over it.
            x[0] = 0.0;
            (x, feature)
        },
    );

    let mut rut = Rut::new(0.02);
    let mut centre = -0.6;
    while centre < 0.6 {
        rut.press(&soil, centre, 0.02 + 0.03 * (centre + 0.6), WIDTH);
        centre += rut.cell();
    }
    let rutted = Soft::new(Some(rut.clone()));
    sweep(
        "soil, rut",
        &rutted,
        (&["loading", "unloading", "not bearing"], 30),
        |rng| {
            let feature = (rng.uniform(0.0, 2.0) as usize).min(1);
            let mut x = sunk_link(rng, &shoe, feature, 0.0);
            let local = shoe.ground_points[feature];
            let point = states(&x).0.point(local);
            let memory = rut.memory(point.x);
            let (plastic, deepest) = (memory.plastic, memory.deepest(&soil));
            x[1] -= rng.uniform(plastic, deepest + 0.5 * (deepest - plastic));
            (x, feature)
        },
    );
}

/// A point just pressed sits on the soil's kink (its sinkage the deepest
/// it reached): sinking, its slope is Bekker's, rising the unloading
/// stiffness's, each equal to the one-sided difference on that side
/// (step 1e-7 m: its truncation, `h F″/2` with `F″/F′ ~ (n − 1)/z`, is
/// 3e-7 of the slope at 3 cm; bound 1e-5 of it).
#[test]
fn a_just_pressed_point_takes_the_slope_of_the_side_it_moves_toward() {
    let mut soft = Soft::new(None);
    let shoe = soft.shoe.clone();
    let mut x = [0.0; INPUTS];
    x[1] = -shoe.ground_points[0].y - 0.03;
    soft.press(&x);
    let ky = LINK_POSE + 1;
    let (mut bekker, mut elastic) = (0.0, 0.0);
    for sinking in [true, false] {
        // Slowly, so the damping does not clip the pressure.
        x[4] = if sinking { -0.01 } else { 0.01 };
        let contact = soft.find(&x, 0).expect("in the soil");
        let exact = rows(&soft.linearise(&x, &contact))[(1, ky)];
        let here = soft.respond(&x, &contact)[1];
        // Toward the side the point moves: down (−y) sinking.
        let h = if sinking { -STEP } else { STEP };
        let mut shifted = x;
        shifted[ky] += h;
        let moved = soft.find(&shifted, 0).expect("in the soil");
        let one_sided = (soft.respond(&shifted, &moved)[1] - here) / h;
        println!("sinking {sinking}: exact {exact:e}, one-sided {one_sided:e}");
        assert!(
            (exact - one_sided).abs() <= 1e-5 * one_sided.abs(),
            "sinking {sinking}: exact {exact:e}, one-sided difference {one_sided:e}"
        );
        if sinking {
            bekker = exact;
        } else {
            elastic = exact;
        }
    }
    // The two sides differ (else the test could not tell them apart).
    assert!((bekker - elastic).abs() > 0.1 * elastic.abs());
}
