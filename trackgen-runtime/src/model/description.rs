use crate::closure::penalty::PenaltyJoint;
use nalgebra::Vector2;

/// How a track loop is closed (spec §2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Closure {
    /// A plain open chain: link `n` and link 1 are not joined.
    Open,
    /// The closing joint is a constraint `C(q_i) = 0`, handled by generalised
    /// coordinate partitioning (or, equivalently, multipliers).
    Partitioned,
    /// The closing joint is cut and replaced by a spring-damper between the
    /// two joint points (paper Fig. 5): `F = −k (P_n − P_1) − c (Ṗ_n − Ṗ_1)`.
    Penalty(PenaltyJoint),
}

impl Closure {
    /// Whether the loop carries the two constraint rows of spec §2.
    pub fn is_constrained(self) -> bool {
        matches!(self, Closure::Partitioned)
    }
}

/// One rigid body of a tree, in the form both routes share.
///
/// The body's position follows its parent's:
/// `R^b = R^p + A^p ū_p − A^b ū_b`, with `ū_p = at_parent` (on the parent, in
/// the parent's frame) and `ū_b = at_self` (on this body, in its own frame),
/// the two coinciding at the joint. The root has no parent; its
/// translational coordinates are its centroid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyDescription {
    /// Mass, kg.
    pub mass: f64,
    /// Centroidal moment of inertia, kg m².
    pub inertia: f64,
    /// Index of the parent body (always lower than this body's), `None` for
    /// the root.
    pub parent: Option<usize>,
    /// Joint point on the parent, parent frame, m. Zero for the root.
    pub at_parent: Vector2<f64>,
    /// Joint point on this body, own frame, m. Zero for the root.
    pub at_self: Vector2<f64>,
}

/// The loop-closing joint of a track: it joins link `n` at `ū2ⁿ` to link 1
/// at `ū1¹` (spec §2, eq. (17)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoopJoint {
    /// How the joint is treated.
    pub closure: Closure,
    /// `ū1¹`, link 1's joint point to link `n`, m.
    pub first_u1: Vector2<f64>,
    /// `ū2ⁿ`, link `n`'s joint point to link 1, m.
    pub last_u2: Vector2<f64>,
}

/// A tree of rigid bodies in recursive coordinates, as data. Generated models
/// return theirs from [`RecursiveModel::description`](crate::RecursiveModel::description); the reference route
/// evaluates the dynamics from it.
#[derive(Debug, Clone, PartialEq)]
pub struct TreeDescription {
    /// Bodies in topological order (parents first); body 0 is the root.
    pub bodies: Vec<BodyDescription>,
    /// Gravitational acceleration, m/s² (default `(0, −9.81)`).
    pub gravity: Vector2<f64>,
    /// The track's loop joint, if the tree is a track.
    pub loop_joint: Option<LoopJoint>,
}

impl TreeDescription {
    /// A chain of links `1..n` with joint points `ū1ⁱ`, `ū2ⁱ` (spec §1): link
    /// `i` hangs from link `i − 1` at `ū2^{i−1}` by its own `ū1ⁱ`.
    ///
    /// `links` holds `(m, J, ū1, ū2)` per link.
    pub fn chain(
        links: &[(f64, f64, Vector2<f64>, Vector2<f64>)],
        gravity: Vector2<f64>,
        closure: Closure,
    ) -> Self {
        let bodies = links
            .iter()
            .enumerate()
            .map(|(i, &(mass, inertia, u1, _))| BodyDescription {
                mass,
                inertia,
                parent: i.checked_sub(1),
                at_parent: if i == 0 {
                    Vector2::zeros()
                } else {
                    links[i - 1].3
                },
                at_self: if i == 0 { Vector2::zeros() } else { u1 },
            })
            .collect();
        let loop_joint = match (links.first(), links.last()) {
            (Some(first), Some(last)) => Some(LoopJoint {
                closure,
                first_u1: first.2,
                last_u2: last.3,
            }),
            _ => None,
        };
        TreeDescription {
            bodies,
            gravity,
            loop_joint,
        }
    }

    /// Number of bodies.
    pub fn len(&self) -> usize {
        self.bodies.len()
    }

    /// Whether the tree has no bodies.
    pub fn is_empty(&self) -> bool {
        self.bodies.is_empty()
    }

    /// Number of recursive coordinates, `bodies + 2`.
    pub fn dof(&self) -> usize {
        self.bodies.len() + 2
    }

    /// `d̄ʲ = ū2ʲ − ū1ʲ` of every link of a track, the vectors whose rotated
    /// sum is the loop closure `C(q_i)` (spec §2). `None` for a tree that is
    /// not a chain with a loop joint.
    pub fn link_spans(&self) -> Option<Vec<Vector2<f64>>> {
        let joint = self.loop_joint?;
        let n = self.bodies.len();
        Some(
            (0..n)
                .map(|j| {
                    let u1 = if j == 0 {
                        joint.first_u1
                    } else {
                        self.bodies[j].at_self
                    };
                    let u2 = if j + 1 == n {
                        joint.last_u2
                    } else {
                        self.bodies[j + 1].at_parent
                    };
                    u2 - u1
                })
                .collect(),
        )
    }
}

/// What a body pinned to the chassis is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PartKind {
    /// The driving sprocket.
    Sprocket,
    /// The idler (front or rear wheel that tensions the track).
    Idler,
    /// A road wheel.
    RoadWheel,
    /// A support (return) roller.
    Roller,
}

/// A named body pinned to the chassis, with the data contact will need.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChassisPart {
    /// The name given in the declaration.
    pub name: &'static str,
    /// What the part is.
    pub kind: PartKind,
    /// Index of the part's body in the chassis tree (the chassis frame is 0).
    pub body: usize,
    /// Rolling (for a sprocket: pitch) radius, m.
    pub radius: f64,
    /// Number of sprocket teeth; 0 for other parts.
    pub teeth: u32,
    /// The sprung arm carrying the part, if any.
    pub arm: Option<ArmSpring>,
}

/// An arm between the chassis and a part (a road wheel's trailing arm, an
/// idler's tensioner arm) with a torsion spring-damper about its pivot:
/// the torque on the arm is `τ = preload − k φ − c φ̇`, with `φ` the arm's
/// angle relative to the chassis from its design position (counter-clockwise
/// positive); the chassis takes `−τ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArmSpring {
    /// Index of the arm's body in the chassis tree.
    pub body: usize,
    /// `k`, N m/rad.
    pub stiffness: f64,
    /// `c`, N m s/rad.
    pub damping: f64,
    /// Torque at the design position, N m.
    pub preload: f64,
    /// The range of `φ` (rad, `low ≤ 0 ≤ high`) the assembly may set the
    /// arm to: for an idler's tensioner, the travel over which it takes up
    /// the track's slack ([`assemble`](crate::vehicle::assemble)). Declared
    /// as the arm's `travel`, default `(−π/2, π/2)`. Not a stop: the
    /// simulation does not limit the arm.
    pub travel: (f64, f64),
}
