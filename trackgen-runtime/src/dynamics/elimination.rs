//! The 2 × 2 block steps of the twisted elimination that every generated
//! [`linear_time_dynamics`](crate::multibody::TrackModel::linear_time_dynamics) is made
//! of (formulation §5): the joint-force system is eliminated from both ends of the
//! chain at once, each end a [`Sweep`], and solved back outward by
//! [`back`]. `CLOSED` carries the closing joint's two columns along
//! (bordering, for a constrained loop).
//!
//! Blocks are row-major `[a00, a01, a10, a11]`; symmetric ones
//! `[a00, a01, a11]`.
//!
//! The solve's tables, a [`LinkTerms`] per link and a [`JointTerms`] per
//! joint, live in a workspace kept per thread ([`with_tables`]), so that a
//! solve neither zero-fills them on the stack nor moves them into place:
//! every entry is written before it is read.

use std::cell::RefCell;

use crate::multibody::DynamicsError;

/// One link's terms of the joint-force system (formulation §5), written by every
/// solve before it reads them: the levers `p1 = A_θ ū1`, `p2 = A_θ ū2`,
/// the moment on the link, the blocks `A2 = p2 p2ᵀ/J + I/m` and
/// `A1 = p1 p1ᵀ/J + I/m` (symmetric), the coupling
/// `L = −(p2 p1ᵀ/J + I/m)` (row-major) and the right-side terms `e2`, `e1`.
#[derive(Debug, Default, Clone, Copy)]
pub struct LinkTerms {
    /// `A_θ ū1`, m.
    pub p1: [f64; 2],
    /// `A_θ ū2`, m.
    pub p2: [f64; 2],
    /// The moment on the link (applied, plus a cut joint's), N m.
    pub moment: f64,
    /// `p2 p2ᵀ/J + I/m` as `[xx, xy, yy]`, 1/kg.
    pub a2: [f64; 3],
    /// `p1 p1ᵀ/J + I/m` as `[xx, xy, yy]`, 1/kg.
    pub a1: [f64; 3],
    /// `−(p2 p1ᵀ/J + I/m)`, 1/kg.
    pub coupling: [f64; 4],
    /// `A ū2 ω² − p2 T/J − F/m`, m/s².
    pub e2: [f64; 2],
    /// `A ū1 ω² − p1 T/J − F/m`, m/s².
    pub e1: [f64; 2],
}

/// One joint's terms in the elimination, written before they are read:
/// `fac`, the factor of the coupling block between this joint and the one
/// before it (`Lⱼ Dⱼ₋₁⁻¹` sweeping down, `Lⱼᵀ Ďⱼ⁻¹` up; joint 0 has none);
/// `yr`, `yz`: the reduced right side and the closing joint's two
/// columns, then, after [`back`], the solution.
#[derive(Debug, Default, Clone, Copy)]
pub struct JointTerms {
    /// Row-major, dimensionless.
    pub fac: [f64; 4],
    /// N.
    pub yr: [f64; 2],
    /// Row-major, dimensionless.
    pub yz: [f64; 4],
}

/// The tables of the solves on one thread, grown to the largest chain
/// solved there and then reused.
#[derive(Debug, Default)]
struct Workspace {
    links: Vec<LinkTerms>,
    joints: Vec<JointTerms>,
}

impl Workspace {
    fn tables<const N: usize, const M: usize>(
        &mut self,
    ) -> (&mut [LinkTerms; N], &mut [JointTerms; M]) {
        if self.links.len() < N {
            self.links.resize(N, LinkTerms::default());
        }
        if self.joints.len() < M {
            self.joints.resize(M, JointTerms::default());
        }
        let links = (&mut self.links[..N]).try_into().expect("N links");
        let joints = (&mut self.joints[..M]).try_into().expect("M joints");
        (links, joints)
    }
}

thread_local! {
    static WORKSPACE: RefCell<Workspace> = const {
        RefCell::new(Workspace { links: Vec::new(), joints: Vec::new() })
    };
}

/// Runs `solve` on tables for `N` links and `M` joints from this
/// thread's workspace: allocated the first time a chain of that length
/// is solved on the thread, reused after (a right-hand side allocates
/// nothing). The tables hold the last solve's numbers; a solve writes
/// every entry before it reads it. A solve within a solve (which no
/// generated code does) gets tables of its own.
#[inline(always)]
pub fn with_tables<const N: usize, const M: usize, R>(
    solve: impl FnOnce(&mut [LinkTerms; N], &mut [JointTerms; M]) -> R,
) -> R {
    WORKSPACE.with(|kept| {
        let (mut borrowed, mut own);
        let workspace: &mut Workspace = match kept.try_borrow_mut() {
            Ok(kept) => {
                borrowed = kept;
                &mut borrowed
            }
            Err(_) => {
                own = Workspace::default();
                &mut own
            }
        };
        let (links, joints) = workspace.tables::<N, M>();
        solve(links, joints)
    })
}

/// The state of one sweep: the inverse of the last reduced diagonal block
/// `D` (symmetric) and that joint's reduced right side `D⁻¹ r̂` and
/// closing-joint columns `D⁻¹ ẑ`.
#[derive(Debug, Default, Clone, Copy)]
pub struct Sweep {
    i00: f64,
    i01: f64,
    i11: f64,
    y: [f64; 2],
    z: [f64; 4],
}

impl Sweep {
    /// Eliminates the sweep's last joint from the next joint's row, through
    /// the coupling block `l` between them: it couples the new joint to the
    /// last as `K = L` sweeping down the chain, `K = Lᵀ` sweeping up.
    /// Stores the factor `K D⁻¹` in `fac` and updates the row:
    /// `d −= K D⁻¹ Kᵀ`, `r −= K y`, `z −= K z`.
    #[inline(always)]
    pub fn eliminate_into<const CLOSED: bool>(
        &self,
        down: bool,
        l: [f64; 4],
        fac: &mut [f64; 4],
        d: &mut [f64; 3],
        r: &mut [f64; 2],
        z: &mut [f64; 4],
    ) {
        let k = if down { l } else { [l[0], l[2], l[1], l[3]] };
        let f00 = k[0] * self.i00 + k[1] * self.i01;
        let f01 = k[0] * self.i01 + k[1] * self.i11;
        let f10 = k[2] * self.i00 + k[3] * self.i01;
        let f11 = k[2] * self.i01 + k[3] * self.i11;
        *fac = [f00, f01, f10, f11];
        d[0] -= f00 * k[0] + f01 * k[1];
        d[1] -= f00 * k[2] + f01 * k[3];
        d[2] -= f10 * k[2] + f11 * k[3];
        r[0] -= k[0] * self.y[0] + k[1] * self.y[1];
        r[1] -= k[2] * self.y[0] + k[3] * self.y[1];
        if CLOSED {
            let p = self.z;
            z[0] -= k[0] * p[0] + k[1] * p[2];
            z[1] -= k[0] * p[1] + k[1] * p[3];
            z[2] -= k[2] * p[0] + k[3] * p[2];
            z[3] -= k[2] * p[1] + k[3] * p[3];
        }
    }

    /// Inverts the reduced diagonal `d` of `joint` and keeps `D⁻¹`,
    /// `y = D⁻¹ r` and `D⁻¹ z`, writing the last two to `terms.yr` and
    /// `terms.yz`.
    /// A block that is singular or not finite is
    /// [`DynamicsError::SingularJointSystem`].
    #[inline(always)]
    pub fn keep<const CLOSED: bool>(
        &mut self,
        joint: usize,
        d: [f64; 3],
        r: [f64; 2],
        z: [f64; 4],
        terms: &mut JointTerms,
    ) -> Result<(), DynamicsError> {
        let det = d[0] * d[2] - d[1] * d[1];
        if !(det != 0.0 && det.is_finite()) {
            return Err(DynamicsError::SingularJointSystem { joint });
        }
        let inverse = 1.0 / det;
        self.i00 = d[2] * inverse;
        self.i01 = -d[1] * inverse;
        self.i11 = d[0] * inverse;
        self.y = [
            self.i00 * r[0] + self.i01 * r[1],
            self.i01 * r[0] + self.i11 * r[1],
        ];
        terms.yr = self.y;
        if CLOSED {
            self.z = [
                self.i00 * z[0] + self.i01 * z[2],
                self.i00 * z[1] + self.i01 * z[3],
                self.i01 * z[0] + self.i11 * z[2],
                self.i01 * z[1] + self.i11 * z[3],
            ];
            terms.yz = self.z;
        }
        Ok(())
    }
}

/// The back substitution `xⱼ = yⱼ − facᵀ x_nb` of joint `j` from its
/// neighbour `nb` (nearer the sweeps' meeting joint), through the factor
/// of the coupling block between them (kept by the later joint of the
/// two), for the right side and the closing joint's columns, in place.
#[inline(always)]
pub fn back<const CLOSED: bool, const M: usize>(joints: &mut [JointTerms; M], j: usize, nb: usize) {
    let [f00, f01, f10, f11] = joints[j.max(nb)].fac;
    let (x, z) = (joints[nb].yr, joints[nb].yz);
    let y = &mut joints[j];
    y.yr[0] -= f00 * x[0] + f10 * x[1];
    y.yr[1] -= f01 * x[0] + f11 * x[1];
    if CLOSED {
        y.yz[0] -= f00 * z[0] + f10 * z[2];
        y.yz[1] -= f00 * z[1] + f10 * z[3];
        y.yz[2] -= f01 * z[0] + f11 * z[2];
        y.yz[3] -= f01 * z[1] + f11 * z[3];
    }
}
