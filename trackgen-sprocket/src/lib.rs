//! A sprocket's arc tooth profile: its figures and the rules for a profile
//! that can drive a track, in plain numbers so that the compiler checks a
//! declaration with them at compile time and the runtime checks a vehicle
//! built from anything else with the same rules (one owner). The hull's
//! outline has its rule here too ([`convex_outline`]), for the same reason.
//!
//! The profile: `N` teeth; a tip (addendum) circle of radius `r_a`; between
//! every two teeth a circular gap of radius `ρ` centred `d` from the
//! sprocket's centre. A track of pitch `p` seats its joints on the pitch
//! circle `R = p / (2 sin(π/N))`, one per gap, each gap centred on a
//! joint's direction; the shoes' pins (cylinders of radius `r_pin`, given
//! in the link frame, where the link's joints are `ū1` and `ū2`) must then
//! lie inside the gaps, clear of the teeth.

#![warn(missing_docs)]

mod outline;

pub use outline::{OutlineProblem, convex_outline};

use std::f64::consts::PI;
use std::fmt;

/// The pitch radius of a sprocket of `teeth` teeth for a chain of `pitch`
/// (m, joint to joint): the circumradius of the `teeth`-gon of side
/// `pitch`, `p / (2 sin(π/N))`, m.
pub fn pitch_radius(teeth: u32, pitch: f64) -> f64 {
    pitch / (2.0 * (PI / teeth as f64).sin())
}

/// The profile's radii, m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Radii {
    /// Tip circle `r_a`.
    pub addendum: f64,
    /// Distance of each gap arc's centre from the sprocket's `d`.
    pub arc_centre_radius: f64,
    /// Radius of each gap arc `ρ`.
    pub arc_radius: f64,
}

/// A profile of `teeth` teeth for a chain of `pitch` (m) in the M113's
/// proportions: with `R` the pitch radius, the tip circle at `R + 0.073 p`,
/// gap arcs centred `R + 0.33 p` out, each of radius 0.48 of the chord
/// between neighbouring arc centres (so neighbouring gaps never meet). For
/// the M113 (`p` = 0.154 m, 10 teeth): 0.2605, 0.300 and 0.089 m.
pub fn scaled(teeth: u32, pitch: f64) -> Radii {
    let half_angle = PI / teeth as f64;
    let pitch_radius = pitch_radius(teeth, pitch);
    let arc_centre_radius = pitch_radius + 0.33 * pitch;
    Radii {
        addendum: pitch_radius + 0.073 * pitch,
        arc_centre_radius,
        arc_radius: 0.48 * 2.0 * arc_centre_radius * half_angle.sin(),
    }
}

/// A sprocket and the shoe that meets it, for the checks.
#[derive(Debug, Clone, PartialEq)]
pub struct Engagement<'a> {
    /// Teeth `N`.
    pub teeth: u32,
    /// The profile's radii.
    pub radii: Radii,
    /// The shoe's joints in its link frame, `ū1` and `ū2`, m.
    pub joints: [(f64, f64); 2],
    /// The shoe's pins in its link frame, m.
    pub pins: &'a [(f64, f64)],
    /// The pins' radius, m.
    pub pin_radius: f64,
}

/// Why a profile cannot drive the track it is declared with, with what
/// would.
#[derive(Debug, Clone, PartialEq)]
pub enum ProfileProblem {
    /// Neighbouring gaps overlap: `ρ ≥ d sin(π/N)`.
    GapsOverlap {
        /// `ρ`, m.
        gap_radius: f64,
        /// The largest `ρ` for gaps centred at `d`, `d sin(π/N)`, m.
        largest: f64,
    },
    /// A gap reaches past the sprocket's centre: `ρ ≥ d`.
    GapPastCentre {
        /// `ρ`, m.
        gap_radius: f64,
        /// `d`, m.
        gap_centre: f64,
    },
    /// The gaps do not cut into the tip circle, `d − ρ ≥ r_a`: no teeth.
    NoTeeth {
        /// `d − ρ`, m.
        root: f64,
        /// `r_a`, m.
        addendum: f64,
    },
    /// A pin is wider than a gap.
    PinWiderThanGap {
        /// `r_pin`, m.
        pin_radius: f64,
        /// `ρ`, m.
        gap_radius: f64,
    },
    /// A pin of a seated link lies in a tooth.
    PinInTooth {
        /// Which pin (from 1, in the order declared).
        pin: usize,
        /// Its position in the link frame, m.
        at: (f64, f64),
        /// How deep into the tooth it reaches, m.
        depth: f64,
        /// Its distance from the nearer joint along the link, m.
        from_joint: f64,
        /// The farthest from a joint (along the link, on the pitch line)
        /// a pin seats in this profile, m (negative: none does).
        seats_within: f64,
        /// The gap radius that would take this pin, if the gaps would not
        /// overlap at it, m.
        wider_gap: Option<f64>,
    },
    /// No tooth reaches a pin of a seated link: every pin's inner edge
    /// lies outside the tip circle, so the teeth pass under the pins and
    /// cannot push the track.
    TeethMissPins {
        /// `r_a`, m.
        addendum: f64,
        /// The smallest distance from the sprocket's centre to a pin's
        /// inner edge, on a link seated on the pitch circle, m.
        lowest_pin: f64,
    },
}

impl fmt::Display for ProfileProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            ProfileProblem::GapsOverlap {
                gap_radius,
                largest,
            } => write!(
                f,
                "the sprocket's gaps overlap: `gap_radius` {gap_radius} m is wider than half the space between two gaps' centres; at most {largest:.4} m for this `gap_centre` and `teeth`"
            ),
            ProfileProblem::GapPastCentre {
                gap_radius,
                gap_centre,
            } => write!(
                f,
                "the sprocket's gaps reach past its centre: `gap_radius` {gap_radius} m must be less than `gap_centre` {gap_centre} m"
            ),
            ProfileProblem::NoTeeth { root, addendum } => write!(
                f,
                "the gaps do not cut into the tip circle (their bottom at {root:.4} m, the tip at {addendum:.4} m): no teeth; bring `gap_centre` in or widen `gap_radius`"
            ),
            ProfileProblem::PinWiderThanGap {
                pin_radius,
                gap_radius,
            } => write!(
                f,
                "the pins (radius {pin_radius} m) do not fit the sprocket's gaps (radius {gap_radius} m)"
            ),
            ProfileProblem::PinInTooth {
                pin,
                at,
                depth,
                from_joint,
                seats_within,
                wider_gap,
            } => {
                write!(
                    f,
                    "pin {pin} at ({}, {}) lies {:.1} mm inside a tooth when its link is seated on the sprocket: the gaps are centred on the joints, and this pin is {from_joint:.4} m from the nearer one",
                    at.0,
                    at.1,
                    depth * 1e3
                )?;
                if seats_within > 0.0 {
                    write!(f, "; move `pins` to within {seats_within:.4} m of a joint")?;
                }
                match wider_gap {
                    Some(gap) => write!(f, ", or widen `gap_radius` to {gap:.4} m"),
                    None => write!(
                        f,
                        " (no gap wide enough to take it would leave the teeth between the gaps)"
                    ),
                }
            }
            ProfileProblem::TeethMissPins {
                addendum,
                lowest_pin,
            } => write!(
                f,
                "the teeth do not reach the pins: on a link seated on the sprocket the pins' inner edges lie {lowest_pin:.4} m from its centre, outside the tip circle ({addendum:.4} m), so the teeth pass under them and cannot drive the track; raise `tip_radius` above {lowest_pin:.4} m"
            ),
        }
    }
}

impl std::error::Error for ProfileProblem {}

impl Radii {
    /// The gaps of a sprocket of `teeth` teeth: they must not overlap,
    /// must stay inside the sprocket and must cut into the tip circle.
    pub fn check(&self, teeth: u32) -> Result<(), ProfileProblem> {
        let Radii {
            addendum,
            arc_centre_radius: d,
            arc_radius: rho,
        } = *self;
        let largest = d * (PI / teeth as f64).sin();
        if rho >= largest {
            return Err(ProfileProblem::GapsOverlap {
                gap_radius: rho,
                largest,
            });
        }
        if rho >= d {
            return Err(ProfileProblem::GapPastCentre {
                gap_radius: rho,
                gap_centre: d,
            });
        }
        if d - rho >= addendum {
            return Err(ProfileProblem::NoTeeth {
                root: d - rho,
                addendum,
            });
        }
        Ok(())
    }
}

/// Pins of `pin_radius` (m) must be narrower than gaps of `gap_radius`.
pub fn check_pin_radius(pin_radius: f64, gap_radius: f64) -> Result<(), ProfileProblem> {
    if pin_radius >= gap_radius {
        Err(ProfileProblem::PinWiderThanGap {
            pin_radius,
            gap_radius,
        })
    } else {
        Ok(())
    }
}

impl Engagement<'_> {
    /// Whether the profile can drive the track: the gaps
    /// ([`Radii::check`]), the pins narrower than the gaps
    /// ([`check_pin_radius`]), every pin of a link seated on the pitch
    /// circle (its joints one gap apart) inside a gap, clear of the teeth,
    /// and the tip circle reaching past the inner edge of at least one of
    /// them, so that a tooth meets a pin as the sprocket turns.
    pub fn check(&self) -> Result<(), ProfileProblem> {
        self.radii.check(self.teeth)?;
        check_pin_radius(self.pin_radius, self.radii.arc_radius)?;
        let Radii {
            addendum,
            arc_centre_radius: d,
            arc_radius: rho,
        } = self.radii;
        let half = PI / self.teeth as f64;
        let largest = d * half.sin();
        let [(x1, y1), (x2, y2)] = self.joints;
        let span = (x2 - x1).hypot(y2 - y1);
        let r = pitch_radius(self.teeth, span);
        // The link seated: its joints on the pitch circle at angles ∓π/N,
        // the chord along +y of the sprocket frame... placed so that the
        // link's rear joint is at angle −π/N and its front at +π/N (the
        // loop runs counter-clockwise round the sprocket, its inside, the
        // links' left, toward the centre).
        let (a, b) = (
            (r * half.cos(), -r * half.sin()),
            (r * half.cos(), r * half.sin()),
        );
        let gaps = [
            (d * half.cos(), -d * half.sin()),
            (d * half.cos(), d * half.sin()),
        ];
        // The link frame to the sprocket frame: ū1 → a, ū2 → b.
        let (ux, uy) = ((x2 - x1) / span, (y2 - y1) / span);
        let (cx, cy) = ((b.0 - a.0) / span, (b.1 - a.1) / span);
        let to_sprocket = |(px, py): (f64, f64)| {
            // Along and across the link, from ū1.
            let (along, across) = (
                (px - x1) * ux + (py - y1) * uy,
                -(px - x1) * uy + (py - y1) * ux,
            );
            (
                a.0 + along * cx - across * cy,
                a.1 + along * cy + across * cx,
            )
        };
        // How far a pin on the pitch line may be from a joint and still
        // seat: |g − j| along the radial direction is d − R, so the offset
        // e along the chord (nearly perpendicular) seats while
        // √((d − R)² + e²) + r_pin ≤ ρ.
        let seats_within = {
            let room = rho - self.pin_radius;
            let radial = (d - r).abs();
            if room > radial {
                (room * room - radial * radial).sqrt()
            } else {
                -1.0
            }
        };
        let mut lowest_pin = f64::INFINITY;
        for (k, &pin) in self.pins.iter().enumerate() {
            let p = to_sprocket(pin);
            let inner_edge = p.0.hypot(p.1) - self.pin_radius;
            lowest_pin = lowest_pin.min(inner_edge);
            let nearest = gaps
                .iter()
                .map(|g| (p.0 - g.0).hypot(p.1 - g.1))
                .fold(f64::INFINITY, f64::min);
            let depth = nearest + self.pin_radius - rho;
            // Inside the gap's circle, or outside the tip circle (a pin
            // riding high, which no tooth strikes).
            let outside_tip = inner_edge >= addendum;
            if depth > 0.0 && !outside_tip {
                let along = (pin.0 - x1) * ux + (pin.1 - y1) * uy;
                let from_joint = along.abs().min((span - along).abs());
                let wanted = nearest + self.pin_radius;
                return Err(ProfileProblem::PinInTooth {
                    pin: k + 1,
                    at: pin,
                    depth,
                    from_joint,
                    seats_within,
                    wider_gap: (wanted < largest).then_some(wanted),
                });
            }
        }
        // A shoe without pins is not driven through them: nothing to reach.
        if lowest_pin.is_finite() && lowest_pin >= addendum {
            return Err(ProfileProblem::TeethMissPins {
                addendum,
                lowest_pin,
            });
        }
        Ok(())
    }
}
