//! What a vehicle's declaration holds before it is lowered: the sections
//! that appear at most once, and the sprocket's declared profile, which
//! the chassis' lowering collects and the running gear's checks read.

use proc_macro2::Span;
use syn::Ident;
use trackgen_sprocket::Radii;

use crate::num::Num;

/// The vehicle-level sections that appear at most once, unnamed.
#[derive(Default)]
pub(super) struct VehicleSections<'a> {
    pub(super) chassis: Option<&'a crate::parse::Block>,
    pub(super) track: Option<&'a crate::parse::Block>,
    pub(super) shoe: Option<(&'a Ident, &'a crate::parse::Block)>,
    pub(super) contact: Option<&'a crate::parse::Block>,
    pub(super) drive: Option<&'a crate::parse::Block>,
    pub(super) powertrain: Option<&'a crate::parse::Block>,
    pub(super) tracks: Option<(&'a Ident, &'a crate::parse::Block)>,
}

/// The declared sprocket profile: tip radius, gap arc radius, gap arc
/// centre distance, each with the span of its value; and the teeth with
/// theirs.
#[derive(Default)]
pub(super) struct Profile {
    pub radii: [Option<Num>; 3],
    pub spans: [Option<Span>; 3],
    pub teeth: Option<(u32, Span)>,
}

impl Profile {
    /// The radii, the declared or `scaled` for a track of `pitch`, when
    /// the macro knows them all.
    pub(super) fn known_radii(&self, pitch: Option<f64>) -> Option<Radii> {
        let (teeth, _) = self.teeth?;
        let scaled = pitch.map(|p| trackgen_sprocket::scaled(teeth, p));
        let pick = |i: usize, default: Option<f64>| match &self.radii[i] {
            Some(v) => v.known(),
            None => default,
        };
        Some(Radii {
            addendum: pick(0, scaled.map(|r| r.addendum))?,
            arc_radius: pick(1, scaled.map(|r| r.arc_radius))?,
            arc_centre_radius: pick(2, scaled.map(|r| r.arc_centre_radius))?,
        })
    }

    /// Where the tip radius was declared, if it was.
    pub(super) fn tip_span(&self) -> Option<Span> {
        self.spans[0]
    }

    /// Where to point at a gap's problem: the declared gap radius, else
    /// the gap centre, else the teeth.
    pub(super) fn gap_span(&self) -> Option<Span> {
        self.spans[1]
            .or(self.spans[2])
            .or(self.spans[0])
            .or(self.teeth.map(|t| t.1))
    }
}
