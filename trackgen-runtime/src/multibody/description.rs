use nalgebra::{DMatrix, Vector2};

use crate::laws::{PenaltyJoint, TorsionSpring};
use crate::planar::{Rotation, perp};

/// How a track loop is closed (formulation §2).
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
    /// Whether the loop carries the two constraint rows of formulation §2.
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
/// at `ū1¹` (formulation §2, eq. (17)).
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
/// return theirs from [`RecursiveModel::description`](crate::multibody::RecursiveModel::description); the reference route
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
    /// A chain of links `1..n` with joint points `ū1ⁱ`, `ū2ⁱ` (formulation §1): link
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

    /// The velocity transform `H` at the bodies' rotations `rotations`
    /// (one per body) into `out` (`3 · bodies × (bodies + 2)`), rows
    /// `(ẋ, ẏ, ω)` per body, so that a body's absolute velocity is its
    /// rows times `q̇_i` (eqs. (6), (9)): its lever `∂Rᵇ/∂θₖ` on every
    /// angle `k` is `A_θᵏ (ūₖ(toward b) − ūₖ(self))` for an ancestor `k`
    /// and `−A_θᵇ ūᵇ` for `b` itself.
    ///
    /// # Panics
    /// If `rotations` is not one per body or `out` not of that shape (a
    /// programming error).
    pub fn velocity_transform(&self, rotations: &[Rotation], out: &mut DMatrix<f64>) {
        let bodies = &self.bodies;
        let m = bodies.len();
        assert_eq!(rotations.len(), m, "one rotation per body");
        assert_eq!(
            out.shape(),
            (3 * m, m + 2),
            "H is 3 rows per body by the dof"
        );
        let rows = 3 * m;
        // Column-major: entry (r, c) at `c · rows + r`.
        let h = out.as_mut_slice();
        h.fill(0.0);
        for b in 0..m {
            let (x, y) = (3 * b, 3 * b + 1);
            h[x] = 1.0;
            h[rows + y] = 1.0;
            h[(2 + b) * rows + 3 * b + 2] = 1.0;
            // Walk up: body c (on the path) hangs from its parent p at p's
            // `at_parent` of c, and c's own `at_self`.
            let own = -perp(rotations[b].apply(bodies[b].at_self));
            h[(2 + b) * rows + x] += own.x;
            h[(2 + b) * rows + y] += own.y;
            let mut c = b;
            while let Some(p) = bodies[c].parent {
                let toward = rotations[p].apply(bodies[c].at_parent);
                let own = rotations[p].apply(bodies[p].at_self);
                let lever = perp(toward - own);
                h[(2 + p) * rows + x] += lever.x;
                h[(2 + p) * rows + y] += lever.y;
                c = p;
            }
        }
    }

    /// Number of recursive coordinates, `bodies + 2`.
    pub fn dof(&self) -> usize {
        self.bodies.len() + 2
    }

    /// The joint points of every link of a track, in its own frame:
    /// `(ū1ʲ, ū2ʲ)`, the joint to the previous link and to the next (for
    /// link 1, `ū1` is its side of the closing joint; for link n, `ū2`).
    /// `None` for a tree that is not a chain with a loop joint. The one
    /// place the joints are read from a description.
    pub fn joints(&self) -> Option<Vec<(Vector2<f64>, Vector2<f64>)>> {
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
                    (u1, u2)
                })
                .collect(),
        )
    }

    /// `d̄ʲ = ū2ʲ − ū1ʲ` of every link of a track, the vectors whose rotated
    /// sum is the loop closure `C(q_i)` (formulation §2). `None` for a tree that is
    /// not a chain with a loop joint.
    pub fn link_spans(&self) -> Option<Vec<Vector2<f64>>> {
        Some(self.joints()?.into_iter().map(|(u1, u2)| u2 - u1).collect())
    }

    /// The track's pitch, joint to joint, m, when every link has the same
    /// (to 1e-9 of it): what a sprocket's teeth, a tooth profile and a
    /// shoe's footprint assume. Links of different lengths are a
    /// [`PitchError`] naming the shortest and longest.
    pub fn pitch(&self) -> Result<f64, PitchError> {
        let spans = self.link_spans().ok_or(PitchError::NotATrack)?;
        let lengths = spans.iter().map(|s| s.norm());
        let (shortest, longest) = lengths
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), l| {
                (lo.min(l), hi.max(l))
            });
        let first = spans.first().map_or(f64::NAN, |s| s.norm());
        if longest - shortest <= 1e-9 * longest {
            Ok(first)
        } else {
            Err(PitchError::Uneven { shortest, longest })
        }
    }
}

/// Why a description has no single pitch.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum PitchError {
    /// Not a chain with a loop joint.
    #[error("the tree is not a track (no loop joint)")]
    NotATrack,
    /// The links are of different lengths.
    #[error(
        "the track's links differ in length ({shortest} m to {longest} m): a sprocket needs one pitch"
    )]
    Uneven {
        /// The shortest link, joint to joint, m.
        shortest: f64,
        /// The longest, m.
        longest: f64,
    },
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
    /// The rim radius as declared, m: what road wheels, idler and rollers
    /// roll the track's inner face on. A sprocket's is its declared
    /// `radius` (drawn, not used by the contact: its teeth are its
    /// [`ToothProfile`](crate::contact::sprocket::ToothProfile) and its
    /// pitch radius follows from the teeth and the track's pitch).
    pub radius: f64,
    /// Number of sprocket teeth; 0 for other parts.
    pub teeth: u32,
    /// The sprung arm carrying the part, if any.
    pub arm: Option<ArmSpring>,
}

/// An arm between the chassis and a part (a road wheel's trailing arm, an
/// idler's tensioner arm) with a torsion spring-damper about its pivot
/// ([`TorsionSpring`]): the torque on the arm is `τ = preload − k φ − c φ̇`,
/// with `φ` the arm's angle relative to the chassis from its design
/// position (counter-clockwise positive); the chassis takes `−τ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArmSpring {
    /// Index of the arm's body in the chassis tree.
    pub body: usize,
    /// The spring-damper about the pivot.
    pub spring: TorsionSpring,
    /// The range of `φ` (rad, `low ≤ 0 ≤ high`) the assembly may set the
    /// arm to: for an idler's tensioner, the travel over which it takes up
    /// the track's slack. Declared as the arm's `travel`, default
    /// `(−π/2, π/2)`. Not a stop: the simulation does not limit the arm.
    pub travel: (f64, f64),
}
