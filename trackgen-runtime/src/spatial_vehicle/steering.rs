//! The driver's steering of a skid-steered vehicle: a heading to hold,
//! turned into a difference of the two belts' speeds that the sides'
//! speed drives track.
//!
//! Two belts `Δu` apart turn a vehicle of gauge `B` at `Δu / B` if the
//! tracks do not slip (the kinematic yaw rate); on real ground they slip
//! and the vehicle turns slower (Wong, *Theory of Ground Vehicles*, 4th
//! ed., §7.2). The driver asks for the kinematic rate of the heading
//! wanted and corrects what the slip takes away in proportion to the
//! heading's error:
//!
//! `Δu = B (ψ̇_ref + k (ψ_ref − ψ))`, held to `±Δu_max`,
//!
//! the right belt `+Δu/2` above the speed wanted and the left `−Δu/2`
//! below it (a left turn, `ψ` growing, runs the right track outside).

use thiserror::Error;

/// A steering setting out of its range.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum SteeringError {
    /// The heading gain is not finite and positive.
    #[error("the steering's heading gain must be finite and more than 0 1/s, got {gain}")]
    Gain {
        /// 1/s.
        gain: f64,
    },
    /// The belts' largest difference is not finite and positive.
    #[error(
        "the steering's largest belt-speed difference must be finite and more than 0 m/s, got {difference}"
    )]
    Difference {
        /// m/s.
        difference: f64,
    },
    /// A side's drive is not a speed drive: steering moves the speeds
    /// wanted.
    #[error("the steering moves the belts' target speeds: both sides need speed drives")]
    NotSpeedDrives,
}

/// The heading wanted against time: `(ψ_ref, ψ̇_ref)`, rad and rad/s.
pub type HeadingSchedule = Box<dyn Fn(f64) -> (f64, f64) + Send>;

/// A driver holding the hull to a heading by skid steering.
pub struct HeadingHold {
    /// The heading wanted and its rate at time `t` (s): rad, rad/s
    /// (counter-clockwise seen from above, the hull's yaw).
    pub heading: HeadingSchedule,
    /// How fast an error of heading is taken out, 1/s.
    pub gain: f64,
    /// The largest difference of the belts' speeds asked for, m/s.
    pub max_difference: f64,
}

impl HeadingHold {
    /// The driver's heading gain of [`driver`](Self::driver), 1/s: an
    /// error of heading halves in about 0.5 s.
    pub const DRIVER_GAIN: f64 = 1.5;
    /// The yaw rate the largest belt-speed difference of
    /// [`driver`](Self::driver) asks for, rad/s: the difference is the
    /// gauge times it.
    pub const DRIVER_MAX_YAW_RATE: f64 = 1.0;

    /// The applications' driver on a gauge of `gauge` m: [`turn`](Self::turn)
    /// at [`DRIVER_GAIN`](Self::DRIVER_GAIN), its belts at most
    /// `gauge` × [`DRIVER_MAX_YAW_RATE`](Self::DRIVER_MAX_YAW_RATE) apart.
    pub fn driver(angle: f64, (start, duration): (f64, f64), gauge: f64) -> Self {
        HeadingHold::turn(
            angle,
            (start, duration),
            Self::DRIVER_GAIN,
            gauge * Self::DRIVER_MAX_YAW_RATE,
        )
    }

    /// A driver turning through `angle` (rad, to the left positive) from
    /// heading 0, starting at `start` s and taking `duration` s, its
    /// heading wanted along the half-cosine `ψ_ref = angle (1 − cos(π s))
    /// / 2`, `s = (t − start) / duration` (no jump of the yaw rate asked
    /// for at either end), at `gain` (1/s) and belts at most
    /// `max_difference` m/s apart.
    pub fn turn(angle: f64, (start, duration): (f64, f64), gain: f64, max_difference: f64) -> Self {
        HeadingHold {
            heading: Box::new(move |t| half_cosine(angle, start, duration, t)),
            gain,
            max_difference,
        }
    }

    /// Why the setting makes no driver.
    pub fn check(&self) -> Result<(), SteeringError> {
        if !(self.gain.is_finite() && self.gain > 0.0) {
            return Err(SteeringError::Gain { gain: self.gain });
        }
        if !(self.max_difference.is_finite() && self.max_difference > 0.0) {
            return Err(SteeringError::Difference {
                difference: self.max_difference,
            });
        }
        Ok(())
    }

    /// The belts' speed difference asked for at time `t` with the hull at
    /// heading `psi` (rad) on a gauge of `gauge` m: the right belt's speed
    /// less the left's, m/s; a heading wanted that is not finite is `None`.
    pub fn difference(&self, t: f64, psi: f64, gauge: f64) -> Option<f64> {
        let (wanted, rate) = (self.heading)(t);
        let asked = gauge * (rate + self.gain * (wanted - psi));
        asked
            .is_finite()
            .then(|| asked.clamp(-self.max_difference, self.max_difference))
    }
}

/// The half-cosine ramp of `angle` over `[start, start + duration]`: its
/// value and rate at `t`.
fn half_cosine(angle: f64, start: f64, duration: f64, t: f64) -> (f64, f64) {
    if duration <= 0.0 {
        return (if t >= start { angle } else { 0.0 }, 0.0);
    }
    let s = ((t - start) / duration).clamp(0.0, 1.0);
    let (sin, cos) = (std::f64::consts::PI * s).sin_cos();
    let inside = t > start && t < start + duration;
    let rate = if inside {
        angle * std::f64::consts::PI * sin / (2.0 * duration)
    } else {
        0.0
    };
    (angle * (1.0 - cos) / 2.0, rate)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ramp's rate is its value's derivative (central differences of
    /// 1e-6 s, error O(h²) ≈ 1e-12 of the ramp's curvature, bound 1e-8),
    /// it starts at 0 and ends at the angle, and it holds outside.
    #[test]
    fn the_half_cosine_ramp_has_its_own_rate() {
        let (angle, start, duration) = (1.5, 2.0, 4.0);
        let h = 1e-6;
        for k in 1..40 {
            let t = start + duration * f64::from(k) / 40.0;
            let (_, rate) = half_cosine(angle, start, duration, t);
            let slope = (half_cosine(angle, start, duration, t + h).0
                - half_cosine(angle, start, duration, t - h).0)
                / (2.0 * h);
            assert!((rate - slope).abs() < 1e-8, "t {t}: {rate} vs {slope}");
        }
        assert_eq!(half_cosine(angle, start, duration, 1.0), (0.0, 0.0));
        assert_eq!(half_cosine(angle, start, duration, 7.0), (angle, 0.0));
        let (middle, _) = half_cosine(angle, start, duration, 4.0);
        assert!((middle - angle / 2.0).abs() < 1e-15);
    }

    /// On its schedule the driver asks for the kinematic difference
    /// `B ψ̇_ref`; behind it, more in proportion; never beyond its bound;
    /// and a heading wanted that is not finite is refused.
    #[test]
    fn the_driver_asks_the_kinematic_difference_and_corrects_the_error() {
        // At t = 1 s the rate wanted is π/4 rad/s: B ψ̇_ref = 1.57 m/s,
        // within the bound of 3 m/s.
        let hold = HeadingHold::turn(1.0, (0.0, 2.0), 2.0, 3.0);
        hold.check().expect("in range");
        let gauge = 2.0;
        let (wanted, rate) = (hold.heading)(1.0);
        let on = hold.difference(1.0, wanted, gauge).expect("finite");
        assert!((on - gauge * rate).abs() < 1e-15);
        let behind = hold.difference(1.0, wanted - 0.1, gauge).expect("finite");
        assert!((behind - on - gauge * 2.0 * 0.1).abs() < 1e-12);
        assert_eq!(hold.difference(1.0, wanted - 3.0, gauge), Some(3.0));
        assert_eq!(hold.difference(1.0, wanted + 3.0, gauge), Some(-3.0));
        let lost = HeadingHold {
            heading: Box::new(|_| (f64::NAN, 0.0)),
            gain: 1.0,
            max_difference: 1.0,
        };
        assert_eq!(lost.difference(0.0, 0.0, gauge), None);
    }

    /// Out-of-range settings are refused, naming the setting.
    #[test]
    fn out_of_range_settings_are_refused() {
        for gain in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            let hold = HeadingHold::turn(1.0, (0.0, 1.0), gain, 1.0);
            assert!(matches!(hold.check(), Err(SteeringError::Gain { .. })));
        }
        for difference in [0.0, -1.0, f64::NAN] {
            let hold = HeadingHold::turn(1.0, (0.0, 1.0), 1.0, difference);
            assert!(matches!(
                hold.check(),
                Err(SteeringError::Difference { .. })
            ));
        }
    }
}
