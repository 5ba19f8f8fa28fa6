//! The 2 × 2 block steps of the twisted elimination that every generated
//! [`linear_time_dynamics`](crate::TrackModel::linear_time_dynamics) is made
//! of (spec §5): the joint-force system is eliminated from both ends of the
//! chain at once, each end a [`Sweep`], and solved back outward by
//! [`back`]. `CLOSED` carries the closing joint's two columns along
//! (bordering, for a constrained loop).
//!
//! Blocks are row-major `[a00, a01, a10, a11]`; symmetric ones
//! `[a00, a01, a11]`.

use crate::DynamicsError;

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
    /// `y = D⁻¹ r` and `D⁻¹ z`, writing the last two to `yr` and `yz`.
    /// A block that is singular or not finite is
    /// [`DynamicsError::SingularJointSystem`].
    #[inline(always)]
    pub fn keep<const CLOSED: bool>(
        &mut self,
        joint: usize,
        d: [f64; 3],
        r: [f64; 2],
        z: [f64; 4],
        yr: &mut [f64; 2],
        yz: &mut [f64; 4],
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
        *yr = self.y;
        if CLOSED {
            self.z = [
                self.i00 * z[0] + self.i01 * z[2],
                self.i00 * z[1] + self.i01 * z[3],
                self.i01 * z[0] + self.i11 * z[2],
                self.i01 * z[1] + self.i11 * z[3],
            ];
            *yz = self.z;
        }
        Ok(())
    }
}

/// The back substitution `xⱼ = yⱼ − facᵀ x_nb` of joint `j` from its
/// neighbour `nb` (nearer the sweeps' meeting joint), for the right side
/// and the closing joint's columns, in place.
#[inline(always)]
pub fn back<const CLOSED: bool, const M: usize>(
    fac: &[f64; 4],
    j: usize,
    nb: usize,
    yr: &mut [[f64; 2]; M],
    yz: &mut [[f64; 4]; M],
) {
    let [f00, f01, f10, f11] = *fac;
    let [x0, x1] = yr[nb];
    yr[j][0] -= f00 * x0 + f10 * x1;
    yr[j][1] -= f01 * x0 + f11 * x1;
    if CLOSED {
        let z = yz[nb];
        yz[j][0] -= f00 * z[0] + f10 * z[2];
        yz[j][1] -= f00 * z[1] + f10 * z[3];
        yz[j][2] -= f01 * z[0] + f11 * z[2];
        yz[j][3] -= f01 * z[1] + f11 * z[3];
    }
}
