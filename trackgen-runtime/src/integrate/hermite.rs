use nalgebra::DVector;

/// A step's end points and slopes, for cubic Hermite dense output (third
/// order, enough for the fixed-step methods' output between steps).
#[derive(Debug, Clone)]
pub(crate) struct HermiteStep {
    pub t0: f64,
    pub t1: f64,
    pub y0: DVector<f64>,
    pub y1: DVector<f64>,
    pub f0: DVector<f64>,
    pub f1: DVector<f64>,
}

impl HermiteStep {
    pub fn empty(n: usize) -> Self {
        let z = DVector::zeros(n);
        HermiteStep {
            t0: 0.0,
            t1: 0.0,
            y0: z.clone(),
            y1: z.clone(),
            f0: z.clone(),
            f1: z,
        }
    }

    pub fn evaluate(&self, t: f64) -> DVector<f64> {
        let h = self.t1 - self.t0;
        if h == 0.0 {
            return self.y1.clone();
        }
        let s = (t - self.t0) / h;
        let (s2, s3) = (s * s, s * s * s);
        let h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
        let h10 = s3 - 2.0 * s2 + s;
        let h01 = -2.0 * s3 + 3.0 * s2;
        let h11 = s3 - s2;
        &self.y0 * h00 + &self.f0 * (h10 * h) + &self.y1 * h01 + &self.f1 * (h11 * h)
    }
}
