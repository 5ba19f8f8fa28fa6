//! Steady skid steering on firm ground: the general theory of Wong &
//! Chiang ("A general theory for skid steering of tracked vehicles on
//! firm ground", Proc. IMechE Part D 215, 2001; Wong, *Theory of Ground
//! Vehicles*, 4th ed., 2008, ch. 7) with Coulomb friction, and the
//! simplified theory's moment of turning resistance and steerability
//! criterion (Steeds, "Tracked vehicles", *Automobile Engineer* 40, 1950;
//! Wong, ch. 7). The guide's "Steering" states both.
//!
//! A vehicle on two tracks turns at a steady yaw rate `ω` when each
//! track's ground run slides about its own **instantaneous centre**: the
//! run moves with the hull and runs rearward along it at its belt speed
//! `u` (the sprocket's speed times its pitch radius), so a point of the
//! run at `(x, y)` in the hull's frame (origin under the centre of
//! gravity, `x` forward, `y` left) moves over the ground at
//! `(V_x − ω y − u, V_y + ω x)`. That vanishes at
//! `(−V_y/ω, (V_x − u)/ω)`: both tracks' centres share the longitudinal
//! position `x_c = −V_y/ω` (their shift from the centre of gravity, which
//! the centripetal force sets) and each has its own lateral position
//! `y_c = (V_x − u)/ω`, off its centre line by `d = y − y_c` where the
//! track slips or skids. About that centre every point of the run slides,
//! and the ground's friction on it, `μ p` per unit length and opposite
//! its sliding (isotropic), is a function of the point's place alone:
//! the forces and moments are integrals over the run's load, in closed
//! form for a load uniform over each stretch (the module `shear`). The steady turn
//! is where they, with each track's rolling resistance from the ground,
//! give the centripetal force and no moment about the centre of gravity.
//! The running gear's own losses act inside the vehicle: the sprocket
//! overcomes them beyond the shear, and they move no instantaneous
//! centre.
//!
//! This is Wong & Chiang's theory with the shear stress at once at its
//! limit `μ p` (their shear-deformation modulus `K` → 0): the law of the
//! runtime's sliding contact. The loads are given (a planar model's shoe
//! loads at rest, or a turning run's own); the lateral load transfer the
//! centripetal force causes is the caller's to include.

mod shear;
mod turn;

#[cfg(test)]
mod tests;

pub use turn::{SideInTurn, SteadyTurn};

/// A stretch of a track's ground run carrying a uniform load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stretch {
    /// Its rear end, m along the hull from under the centre of gravity.
    pub from: f64,
    /// Its front end, m (more than `from`).
    pub to: f64,
    /// The normal load it carries, N (not negative).
    pub load: f64,
}

/// One track's ground run: its centre line and the stretches that carry
/// its load.
#[derive(Debug, Clone, PartialEq)]
pub struct TrackLoad {
    /// The centre line's lateral place, m (positive to the left).
    pub lateral: f64,
    /// The loaded stretches, in any order (where two overlap their loads
    /// add).
    pub stretches: Vec<Stretch>,
}

impl TrackLoad {
    /// A run of `length` (m) centred under the centre of gravity at
    /// `lateral` (m), carrying `load` (N) uniformly: the simplified
    /// theory's track.
    pub fn uniform(lateral: f64, length: f64, load: f64) -> TrackLoad {
        TrackLoad {
            lateral,
            stretches: vec![Stretch {
                from: -0.5 * length,
                to: 0.5 * length,
                load,
            }],
        }
    }

    /// A run at `lateral` (m) from point loads along it, `(x, N)` (x in m
    /// along the hull, from under the centre of gravity): each spread
    /// uniformly over its own cell, which reaches halfway to its
    /// neighbours but no further than half the median spacing of the
    /// points (so a load next to a gap between wheels stays under its
    /// wheel). Points at one place share a cell. The loads and their
    /// first moment are kept exactly; the spread only rounds the ends of
    /// the friction's pattern, where a point load's would be sharp.
    pub fn from_points(lateral: f64, points: &[(f64, f64)]) -> TrackLoad {
        let mut sorted: Vec<(f64, f64)> = points.to_vec();
        sorted.sort_by(|a, b| a.0.total_cmp(&b.0));
        // Points at one place merge.
        let mut merged: Vec<(f64, f64)> = Vec::with_capacity(sorted.len());
        for (x, n) in sorted {
            match merged.last_mut() {
                Some(last) if last.0 == x => last.1 += n,
                _ => merged.push((x, n)),
            }
        }
        let mut gaps: Vec<f64> = merged.windows(2).map(|w| w[1].0 - w[0].0).collect();
        gaps.sort_by(f64::total_cmp);
        let half = match gaps.len() {
            0 => 0.5e-3,
            n => 0.5 * gaps[n / 2],
        };
        let stretches = merged
            .iter()
            .enumerate()
            .map(|(i, &(x, load))| {
                let before = i
                    .checked_sub(1)
                    .map_or(half, |j| (0.5 * (x - merged[j].0)).min(half));
                let after = merged
                    .get(i + 1)
                    .map_or(half, |next| (0.5 * (next.0 - x)).min(half));
                // A symmetric cell keeps the load's moment at x.
                let reach = before.min(after);
                Stretch {
                    from: x - reach,
                    to: x + reach,
                    load,
                }
            })
            .collect();
        TrackLoad { lateral, stretches }
    }

    /// The normal load the run carries, N.
    pub fn load(&self) -> f64 {
        self.stretches.iter().map(|s| s.load).sum()
    }

    /// The run's loaded length, from the rearmost to the foremost end, m.
    pub fn length(&self) -> f64 {
        let from = self
            .stretches
            .iter()
            .map(|s| s.from)
            .fold(f64::INFINITY, f64::min);
        let to = self
            .stretches
            .iter()
            .map(|s| s.to)
            .fold(f64::NEG_INFINITY, f64::max);
        (to - from).max(0.0)
    }

    /// The same run mirrored across the hull's centre line.
    pub fn mirrored(&self) -> TrackLoad {
        TrackLoad {
            lateral: -self.lateral,
            stretches: self.stretches.clone(),
        }
    }
}

/// A vehicle steered by the speeds of its two tracks, on firm level
/// ground.
#[derive(Debug, Clone, PartialEq)]
pub struct SkidSteer {
    /// The vehicle's mass, kg: the centripetal force's.
    pub mass: f64,
    /// The coefficient of friction between the track and the ground, the
    /// same in every direction.
    pub friction: f64,
    /// The coefficient of the ground's rolling resistance (a soil's, Wong
    /// & Chiang's): each track's resistance is this times its normal load,
    /// on its centre line against the way it moves over the ground (none
    /// where it stands still), in the vehicle's balance of forces.
    pub rolling_resistance: f64,
    /// The coefficient of the running gear's resistance (the rims', the
    /// teeth's and the pins' losses as the belt runs round the hull: all
    /// a vehicle loses on rigid ground): each track's is this times its
    /// normal load against the belt's motion round the hull (none where
    /// the belt stands), a force inside the vehicle that the sprocket
    /// overcomes beyond the ground's shear
    /// ([`SideInTurn::sprocket_force`]), not in the balance of forces.
    pub belt_resistance: f64,
    /// The left track (`lateral` > 0) and the right (`lateral` < 0).
    pub tracks: [TrackLoad; 2],
}

/// Why a steady turn cannot be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SteeringError {
    /// A figure is out of its range.
    #[error("{what} must be {range}, got {value}")]
    Input {
        /// The figure.
        what: &'static str,
        /// Its allowed range.
        range: &'static str,
        /// The value given.
        value: f64,
    },
    /// No steady turn was found: the tracks cannot give the centripetal
    /// force, or the turn asked for lies beyond the friction.
    #[error(
        "no steady turn at yaw rate {yaw_rate} rad/s and {speed} m/s: \
         after {iterations} Newton iterations the forces are out of balance by {residual} N"
    )]
    NoSolution {
        /// The yaw rate, rad/s.
        yaw_rate: f64,
        /// The forward speed of the centre of gravity, m/s.
        speed: f64,
        /// Newton iterations made.
        iterations: usize,
        /// The last residual's largest component, N (or N m / m).
        residual: f64,
    },
}

impl SkidSteer {
    /// The same vehicle with both tracks' loads the same, a run of
    /// `length` (m) on each side of a `gauge` (m, centre to centre),
    /// each carrying half the weight of `mass` (kg) uniformly: the
    /// simplified theory's vehicle.
    pub fn uniform(
        mass: f64,
        gauge: f64,
        length: f64,
        friction: f64,
        rolling_resistance: f64,
    ) -> SkidSteer {
        let half = 0.5 * mass * crate::ride::G;
        SkidSteer {
            mass,
            friction,
            rolling_resistance,
            belt_resistance: 0.0,
            tracks: [
                TrackLoad::uniform(0.5 * gauge, length, half),
                TrackLoad::uniform(-0.5 * gauge, length, half),
            ],
        }
    }

    /// The normal load on both tracks, N.
    pub fn load(&self) -> f64 {
        self.tracks.iter().map(TrackLoad::load).sum()
    }

    /// The vehicle checked: every figure finite and in its range, the left
    /// track left of the right, every stretch's ends in order.
    pub fn check(&self) -> Result<(), SteeringError> {
        let input = check;
        input("the mass (kg)", "positive", self.mass, self.mass > 0.0)?;
        input(
            "the friction",
            "positive",
            self.friction,
            self.friction > 0.0,
        )?;
        input(
            "the rolling resistance",
            "at least 0",
            self.rolling_resistance,
            self.rolling_resistance >= 0.0,
        )?;
        input(
            "the running gear's resistance",
            "at least 0",
            self.belt_resistance,
            self.belt_resistance >= 0.0,
        )?;
        let [left, right] = &self.tracks;
        input(
            "the left track's place (m)",
            "positive",
            left.lateral,
            left.lateral > 0.0,
        )?;
        input(
            "the right track's place (m)",
            "negative",
            right.lateral,
            right.lateral < 0.0,
        )?;
        for track in &self.tracks {
            for s in &track.stretches {
                input("a stretch's rear end (m)", "finite", s.from, true)?;
                input(
                    "a stretch's front end (m)",
                    "more than its rear end",
                    s.to,
                    s.to > s.from,
                )?;
                input("a stretch's load (N)", "at least 0", s.load, s.load >= 0.0)?;
            }
        }
        input(
            "the total load (N)",
            "positive",
            self.load(),
            self.load() > 0.0,
        )
    }
}

/// `Ok` where `value` is finite and `ok`; otherwise the input error.
fn check(
    what: &'static str,
    range: &'static str,
    value: f64,
    ok: bool,
) -> Result<(), SteeringError> {
    if ok && value.is_finite() {
        Ok(())
    } else {
        Err(SteeringError::Input { what, range, value })
    }
}

/// The simplified theory's moment of turning resistance, N m: the lateral
/// friction `μ_t` on two runs of length `length` (m), each carrying half
/// of `weight` (N) uniformly, turning about their middles:
/// `μ_t W L / 4` (Steeds, 1950; Wong, ch. 7).
pub fn steeds_resisting_moment(lateral_friction: f64, weight: f64, length: f64) -> f64 {
    0.25 * lateral_friction * weight * length
}

/// The simplified theory's steerability criterion: a vehicle turns only
/// if the outer track's thrust for a slow turn,
/// `W/2 (f_r + μ_t L / (2B))`, is within its grip `μ W/2`, that is if
/// `L/B ≤ 2 (μ − f_r)/μ_t` (Steeds, 1950; Wong, ch. 7). Returns that
/// largest length-to-gauge ratio.
pub fn largest_length_to_gauge(
    friction: f64,
    rolling_resistance: f64,
    lateral_friction: f64,
) -> f64 {
    2.0 * (friction - rolling_resistance) / lateral_friction
}
