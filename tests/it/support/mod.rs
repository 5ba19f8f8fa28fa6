//! Shared helpers of the integration tests.
#![allow(dead_code)]

pub mod contact;
pub mod pinocchio;
pub mod programs;
pub mod twin;
pub mod vehicle;
pub mod x200;

use trackgen::nalgebra::{DMatrix, DVector, SMatrix, SVector};

/// Norm-wise relative agreement: `max |a − b| ≤ rel · max(|b|_max, floor)`.
/// Comparing against the largest entry (not entry by entry) is the right
/// scale for rounding error in sums of products: an entry that is the
/// small difference of large terms carries the large terms' error.
///
/// A NaN or infinity on either side fails: `f64::max` would drop a NaN,
/// so the scale and the worst difference are taken with [`max_of`].
pub fn assert_close(label: &str, got: &[f64], want: &[f64], rel: f64, floor: f64) {
    assert_eq!(got.len(), want.len(), "{label}: length");
    if let Some(i) = got.iter().chain(want).position(|v| !v.is_finite()) {
        let (side, at) = if i < got.len() {
            ("got", i)
        } else {
            ("want", i - got.len())
        };
        panic!(
            "{label}: entry {at} of {side} is not finite (got {:?}, want {:?})",
            got[at], want[at]
        );
    }
    let scale = max_of(want.iter().map(|v| v.abs())).max(floor);
    let (worst, at) = got
        .iter()
        .zip(want)
        .enumerate()
        .map(|(i, (g, w))| ((g - w).abs(), i))
        .fold((0.0f64, 0), |a, b| if b.0 > a.0 { b } else { a });
    assert!(
        worst <= rel * scale,
        "{label}: entry {at} differs by {worst:e} (got {}, want {}), allowed {:e}",
        got[at],
        want[at],
        rel * scale
    );
}

/// The largest value, NaN if any value is NaN (`fold(0.0, f64::max)`
/// silently drops NaN, so a test of "the largest error is small" would pass
/// a run that produced NaN). `-∞` for no values.
pub fn max_of(values: impl IntoIterator<Item = f64>) -> f64 {
    values.into_iter().fold(f64::NEG_INFINITY, |m, v| {
        if v.is_nan() || m.is_nan() {
            f64::NAN
        } else {
            m.max(v)
        }
    })
}

/// The smallest value, NaN if any value is NaN. `+∞` for no values.
pub fn min_of(values: impl IntoIterator<Item = f64>) -> f64 {
    -max_of(values.into_iter().map(|v| -v))
}

/// The largest magnitude, NaN if any value is NaN; 0 for no values.
pub fn max_abs(values: impl IntoIterator<Item = f64>) -> f64 {
    // `max_of` of nothing is −∞; `f64::max` would turn a NaN into 0 here.
    max_of(values.into_iter().map(f64::abs).chain([0.0]))
}

pub fn dvec<const D: usize>(v: &SVector<f64, D>) -> DVector<f64> {
    DVector::from_column_slice(v.as_slice())
}

pub fn dmat<const D: usize>(m: &SMatrix<f64, D, D>) -> DMatrix<f64> {
    DMatrix::from_column_slice(D, D, m.as_slice())
}

/// A deterministic generator for test states where proptest is not used.
pub struct Lcg(u64);

impl Lcg {
    pub fn new(seed: u64) -> Self {
        Lcg(seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407))
    }

    /// Uniform in `[lo, hi)`.
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        lo + (hi - lo) * ((self.0 >> 11) as f64 / (1u64 << 53) as f64)
    }

    pub fn state<const D: usize>(&mut self) -> (SVector<f64, D>, SVector<f64, D>) {
        let q = SVector::from_fn(|i, _| {
            if i < 2 {
                self.uniform(-2.0, 2.0)
            } else {
                self.uniform(-3.2, 3.2)
            }
        });
        let qd = SVector::from_fn(|_, _| self.uniform(-3.0, 3.0));
        (q, qd)
    }
}

/// The compiled arms of a chassis through the runtime's arm element
/// (`trackgen::vehicle::arms`): their torques as loads, their energy,
/// their dampers' power.
pub mod arms {
    use trackgen::multibody::{BodyLoad, ChassisModel};
    use trackgen::nalgebra::SVector;
    use trackgen::vehicle::{arms::apply, arms::declared};

    /// Adds every compiled arm's torque to `loads`.
    pub fn add_arm_torques<M: ChassisModel<D>, const D: usize>(
        q: &SVector<f64, D>,
        qd: &SVector<f64, D>,
        loads: &mut [BodyLoad],
    ) {
        assert_eq!(loads.len(), M::BODIES, "one load per body");
        apply(&declared::<M, D>(), q, qd, loads);
    }

    /// The compiled springs' energy `Σ ½ k φ² − preload φ`, J.
    pub fn arm_energy<M: ChassisModel<D>, const D: usize>(q: &SVector<f64, D>) -> f64 {
        let mut loads = vec![BodyLoad::ZERO; M::BODIES];
        apply(&declared::<M, D>(), q, &SVector::zeros(), &mut loads).potential
    }

    /// The compiled dampers' power `Σ c φ̇²`, W.
    pub fn arm_dissipation<M: ChassisModel<D>, const D: usize>(qd: &SVector<f64, D>) -> f64 {
        let mut loads = vec![BodyLoad::ZERO; M::BODIES];
        apply(&declared::<M, D>(), &SVector::zeros(), qd, &mut loads).dissipation
    }
}

/// A table of points `(x, y)`, x increasing, read at `x`: linear between
/// the points, held beyond the ends (the powertrain's tables' reading,
/// written apart for the tests' independent routes).
pub fn table_at(points: &[(f64, f64)], x: f64) -> f64 {
    if x <= points[0].0 {
        return points[0].1;
    }
    let last = points[points.len() - 1];
    if x >= last.0 {
        return last.1;
    }
    let i = points.iter().position(|p| p.0 > x).unwrap();
    let ((x0, y0), (x1, y1)) = (points[i - 1], points[i]);
    y0 + (y1 - y0) * (x - x0) / (x1 - x0)
}

/// A converter's pump and turbine torques (N m) with the engine at `we`
/// and the turbine at `wt` (rad/s, `wt ≤ we`), read from its declared
/// tables: `(ω_e / K(SR))²` and `TR(SR)` times it, falling linearly to
/// none over the coupling band below `SR = 1`
/// ([`COUPLING_BAND`](trackgen::vehicle::COUPLING_BAND)), the stall's at
/// a turbine turned backwards.
pub fn converter_torques(d: &trackgen::vehicle::Driveline, we: f64, wt: f64) -> (f64, f64) {
    let sr = (wt / we).max(0.0);
    assert!(sr <= 1.0, "written for SR ≤ 1");
    let k = table_at(&d.capacity, sr);
    let taper = ((1.0 - sr) / trackgen::vehicle::COUPLING_BAND).min(1.0);
    let pump = (we / k) * (we / k) * taper;
    (pump, table_at(&d.torque_ratio, sr) * pump)
}
