//! Why a track cannot be wrapped or a vehicle placed: typed, with the
//! figures that say by how much and what would fit.

use std::fmt;

use thiserror::Error;

use crate::multibody::PartKind;

/// How deep (m) an assembled start may put a shoe feature into a wheel,
/// the sprocket's teeth or the ground. The wrap lays the joints on pitch
/// circles from which the faces and pins just touch, and the closure's
/// Newton-Raphson moves them by a fraction of a millimetre; 2 mm is well
/// above that and well below what a wrong wrap gives (a sagging span laid
/// through a roller: centimetres), and below the 2–4 mm a shoe sinks under
/// its static load, so a start within it is not a jolt.
pub const START_PENETRATION: f64 = 2e-3;

/// What limits how much track the wheels take up.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SlackLimit {
    /// The upper run's sag: at most a quarter of a span ([`MAX_SAG`](super::MAX_SAG)),
    /// clear of the wheels below it.
    Sag,
    /// The tensioner's travel (the idler arm's declared `travel`), with
    /// the upper run nearly tight.
    Tensioner,
}

impl fmt::Display for SlackLimit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            SlackLimit::Sag => {
                "for the upper run to sag clear of the wheels and at most a quarter of a span"
            }
            SlackLimit::Tensioner => "for the tensioner's travel",
        })
    }
}

/// The link counts that fit a set of wheels: between `tight` and `slack`
/// links of `pitch` (real numbers: the belt's length in chords of the
/// pitch, tight and at the most slack taken up).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinkCounts {
    /// The track's mean link pitch, m.
    pub pitch: f64,
    /// Links of `pitch` round the tightest belt.
    pub tight: f64,
    /// Links of `pitch` round the belt with the most slack taken up.
    pub slack: f64,
}

impl LinkCounts {
    /// The whole numbers of links that fit.
    pub fn range(&self) -> std::ops::RangeInclusive<usize> {
        // A count within rounding of an end fits: the Newton-Raphson
        // closes what is left.
        let lo = (self.tight - 1e-9).ceil().max(0.0) as usize;
        let hi = (self.slack + 1e-9).floor().max(0.0) as usize;
        lo..=hi
    }
}

impl fmt::Display for LinkCounts {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let range = self.range();
        let (lo, hi) = (*range.start(), *range.end());
        if range.is_empty() {
            write!(
                f,
                "no whole number of {:.3} m links fits (from {:.2} to {:.2} would)",
                self.pitch, self.tight, self.slack
            )
        } else if lo == hi {
            write!(f, "{lo} fit")
        } else if hi == lo + 1 {
            write!(f, "{lo} or {hi} fit")
        } else {
            write!(f, "{lo} to {hi} fit")
        }
    }
}

/// Why a track cannot be wrapped.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum AssemblyError {
    /// Fewer than two wheels to wrap.
    #[error("a track needs at least two wheels to wrap, got {0}")]
    TooFewWheels(usize),
    /// One wheel's pitch circle lies inside another's.
    #[error("wheel {a} and wheel {b} are one inside the other: centres {distance:.3} m apart")]
    WheelInside {
        /// First wheel (index in the wrap order).
        a: usize,
        /// Second wheel.
        b: usize,
        /// Centre distance, m.
        distance: f64,
    },
    /// The track is too short to go round the wheels.
    #[error("{links} links are {short:.3} m too short to wrap the wheels; {fits}")]
    TrackTooShort {
        /// Number of links.
        links: usize,
        /// How much belt the joints leave uncovered, m.
        short: f64,
        /// The counts that would fit.
        fits: LinkCounts,
    },
    /// The track is longer than the wheels can take up.
    #[error("{links} links are {long:.3} m too long {limit}; {fits}")]
    TrackTooLong {
        /// Number of links.
        links: usize,
        /// How far the last joint overshoots the first, m of belt.
        long: f64,
        /// What ran out.
        limit: SlackLimit,
        /// The counts that would fit.
        fits: LinkCounts,
    },
    /// No sag (or tensioner setting) closes the loop, though the track is
    /// neither too short nor too long: the landing jumps past the first
    /// joint as the belt's supports change.
    #[error(
        "the wrap of {links} links does not close: the last joint lands {gap:.3} m from the first at best, as the belt moves from one set of wheels to another"
    )]
    Unclosed {
        /// Number of links.
        links: usize,
        /// The closest landing, m of belt.
        gap: f64,
    },
    /// The assembled start puts a shoe deeper than [`START_PENETRATION`]
    /// into a wheel, the sprocket or the ground.
    #[error(
        "the assembled track starts {:.1} mm inside {what} (link {link}); a start may be at most {:.0} mm deep: {}",
        depth * 1e3,
        START_PENETRATION * 1e3,
        what.hint()
    )]
    StartsInside {
        /// What the shoe is inside.
        what: Touching,
        /// The link, numbered from 1.
        link: usize,
        /// How deep, m.
        depth: f64,
    },
    /// The terrain to place the vehicle on is invalid (a NaN or infinite
    /// parameter, a bad table).
    #[error(transparent)]
    Terrain(#[from] crate::terrain::TerrainError),
    /// The track's links differ in length: its sprocket and pitch circles
    /// need one pitch.
    #[error(transparent)]
    Pitch(#[from] crate::multibody::PitchError),
}

/// What an assembled start puts a shoe inside.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Touching {
    /// The ground.
    Ground,
    /// A part pinned to the chassis.
    Part {
        /// What it is.
        kind: PartKind,
        /// Its declared name.
        name: &'static str,
    },
}

impl Touching {
    /// What most likely puts an assembled shoe inside this, and the keys
    /// of the declaration to change.
    pub fn hint(&self) -> &'static str {
        match self {
            Touching::Ground => {
                "the terrain rises into the track where it is assembled (chassis centroid at x = 0): \
                 start on level ground, or move the terrain's feature ahead"
            }
            Touching::Part {
                kind: PartKind::Sprocket,
                ..
            } => {
                "the sprocket's teeth strike the shoes' pins: move `pins` toward the joints, or set \
                 the sprocket's `gap_centre` and `gap_radius` so the gaps take them"
            }
            Touching::Part { .. } => {
                "the rim reaches past the shoes' inner faces: raise the shoe's `inner_offset` \
                 or reduce the part's `radius`"
            }
        }
    }
}

impl fmt::Display for Touching {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Touching::Ground => f.write_str("the ground"),
            Touching::Part { kind, name } => {
                let kind = match kind {
                    PartKind::Sprocket => "sprocket",
                    PartKind::Idler => "idler",
                    PartKind::RoadWheel => "road wheel",
                    PartKind::Roller => "roller",
                };
                write!(f, "{kind} `{name}`")
            }
        }
    }
}
