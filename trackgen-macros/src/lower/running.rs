//! Lowering what makes a vehicle run: its `shoe`, the sprocket's profile,
//! `contact` laws and `drive` gains.

use proc_macro2::Span;
use syn::spanned::Spanned;
use trackgen_sprocket::{Engagement, ProfileProblem};

use super::Lowering;
use super::keys::Bound;
use super::sections::{Profile, VehicleSections};
use crate::ir::{ContactPair, NormalLaw, Running, Shoe, Track};
use crate::num::Num;

/// A link's two joint points `(ū1, ū2)`, m, link frame.
type LinkJoints = ((f64, f64), (f64, f64));

/// Default speed drive: proportional gain, N m s/rad.
const DEFAULT_PROPORTIONAL: f64 = 3000.0;
/// Default speed drive: integral gain, N m/rad.
const DEFAULT_INTEGRAL: f64 = 6000.0;
/// Default speed drive: torque limit, N m.
const DEFAULT_MAX_TORQUE: f64 = 2e4;

/// The contact pairs of a `contact { … }` section, in [`Running::contact`]'s
/// order.
const PAIRS: [&str; 3] = ["ground", "wheels", "sprocket"];

/// The spans of the shoe's keys the sprocket's checks point at.
struct ShoeSpans {
    pins: Span,
    pin_radius: Span,
}

impl Lowering<'_> {
    /// What makes the vehicle run, from its `shoe`, `contact` and `drive`
    /// sections and the sprocket's profile; `None` without a shoe.
    pub(super) fn running(
        &mut self,
        unique: &VehicleSections,
        has_sprocket: bool,
        profile: Profile,
        track: &Track,
    ) -> Option<Running> {
        let Some((shoe_kw, shoe_block)) = unique.shoe else {
            self.check_engagement(&profile, None, track);
            for (section, block) in [
                ("contact", unique.contact),
                ("drive", unique.drive),
                ("powertrain", unique.powertrain),
            ] {
                if let Some(block) = block {
                    self.errors.at(
                        block.span,
                        format!(
                            "`{section}` is used by the vehicle's `config` and `system`, which need a \
                             `shoe {{ ground_points: […], inner_offset: …, pins: […], pin_radius: … }}` section"
                        ),
                    );
                }
            }
            return None;
        };
        if !has_sprocket {
            self.errors.at(
                shoe_kw.span(),
                "a vehicle with a `shoe` runs: it needs a `sprocket` to drive it",
            );
        }
        let shoe = self.shoe(shoe_block);
        self.check_engagement(&profile, shoe.as_ref().map(|(s, spans)| (s, spans)), track);
        let contact = match unique.contact {
            Some(block) => self.contact(block),
            None => Default::default(),
        };
        let drive = unique
            .drive
            .map(|block| self.fields("drive", block, &["proportional", "integral", "max_torque"]));
        if let Some(block) = unique.drive {
            self.sections("drive", block, &[]);
        }
        let mut gain = |key: &str, bound: Bound, default: f64| {
            drive
                .as_ref()
                .and_then(|f| self.bounded(f, key, false, bound))
                .unwrap_or(Num::Known(default))
        };
        let proportional = gain("proportional", Bound::NonNegative, DEFAULT_PROPORTIONAL);
        let integral = gain("integral", Bound::NonNegative, DEFAULT_INTEGRAL);
        let max_torque = gain("max_torque", Bound::Positive, DEFAULT_MAX_TORQUE);
        // A declared powertrain with errors has been reported: no running.
        let powertrain = match unique.powertrain {
            Some(block) => Some(self.powertrain(block)?),
            None => None,
        };
        let (shoe, _) = shoe?;
        let [tip_radius, gap_radius, gap_centre] = profile.radii;
        Some(Running {
            shoe,
            tip_radius,
            gap_radius,
            gap_centre,
            contact,
            proportional,
            integral,
            max_torque,
            powertrain,
        })
    }

    /// The sprocket's checks (`trackgen_sprocket`, the rules the runtime
    /// applies too) on what the macro can evaluate: gaps that do not
    /// overlap, stay inside the sprocket and cut into the tip circle; pins
    /// narrower than the gaps; every pin of a seated link in a gap; teeth
    /// that reach the pins. Each
    /// problem at the key to change, with the range that would work.
    fn check_engagement(
        &mut self,
        profile: &Profile,
        shoe: Option<(&Shoe, &ShoeSpans)>,
        track: &Track,
    ) {
        let Some((teeth, teeth_span)) = profile.teeth else {
            return;
        };
        // The pitch and joints of the links, when every link's are known
        // and alike (the runtime refuses links of different lengths).
        let joints: Option<Vec<LinkJoints>> = track
            .links
            .iter()
            .map(|l| {
                Some((
                    (l.u1.x.known()?, l.u1.y.known()?),
                    (l.u2.x.known()?, l.u2.y.known()?),
                ))
            })
            .collect();
        let span = |(a, b): &LinkJoints| (b.0 - a.0).hypot(b.1 - a.1);
        let first = joints
            .filter(|j| {
                j.first().is_some_and(|first| {
                    j.iter()
                        .all(|l| (span(l) - span(first)).abs() <= 1e-9 * span(first))
                })
            })
            .and_then(|j| j.first().copied());
        let Some(radii) = profile.known_radii(first.as_ref().map(span)) else {
            return;
        };
        let mut fine = true;
        if let Err(problem) = radii.check(teeth) {
            self.errors
                .at(profile.gap_span().unwrap_or(teeth_span), problem);
            fine = false;
        }
        let Some((shoe, spans)) = shoe else {
            return;
        };
        let Some(pin_radius) = shoe.pin_radius.known() else {
            return;
        };
        if let Err(problem) = trackgen_sprocket::check_pin_radius(pin_radius, radii.arc_radius) {
            self.errors.at(spans.pin_radius, problem);
            fine = false;
        }
        let pins: Option<Vec<(f64, f64)>> = shoe
            .pins
            .iter()
            .map(|p| Some((p.x.known()?, p.y.known()?)))
            .collect();
        let (true, Some(pins), Some((u1, u2))) = (fine, pins, first) else {
            return;
        };
        let engagement = Engagement {
            teeth,
            radii,
            joints: [u1, u2],
            pins: &pins,
            pin_radius,
        };
        if let Err(problem) = engagement.check() {
            // Teeth too short are the tip circle's to change, where declared.
            let span = match problem {
                ProfileProblem::TeethMissPins { .. } => profile.tip_span().unwrap_or(spans.pins),
                _ => spans.pins,
            };
            self.errors.at(span, problem);
        }
    }

    /// `shoe { ground_points, inner_offset, pins, pin_radius, width? }`.
    fn shoe(&mut self, block: &crate::parse::Block) -> Option<(Shoe, ShoeSpans)> {
        let keys = [
            "ground_points",
            "inner_offset",
            "pins",
            "pin_radius",
            "width",
        ];
        let fields = self.fields("shoe", block, &keys);
        self.sections("shoe", block, &[]);
        let ground_points = self.points(&fields, "ground_points", true);
        let inner_offset = self.positive(&fields, "inner_offset", true);
        let pins = self.points(&fields, "pins", true);
        let pin_radius = self.positive(&fields, "pin_radius", true);
        let width = self.positive(&fields, "width", false);
        let spans = ShoeSpans {
            pins: fields.map.get("pins").map_or(block.span, |e| e.span()),
            pin_radius: fields
                .map
                .get("pin_radius")
                .map_or(block.span, |e| e.span()),
        };
        Some((
            Shoe {
                ground_points: ground_points?,
                inner_offset: inner_offset?,
                pins: pins?,
                pin_radius: pin_radius?,
                width,
            },
            spans,
        ))
    }

    /// `contact { ground { … }, wheels { … }, sprocket { … } }`.
    fn contact(&mut self, block: &crate::parse::Block) -> [ContactPair; 3] {
        use crate::parse::Entry;
        self.fields("contact", block, &[]);
        let mut out: [ContactPair; 3] = Default::default();
        let mut seen = [false; 3];
        for entry in self.sections("contact", block, &PAIRS) {
            let Entry::Section {
                kind, name, body, ..
            } = entry
            else {
                continue;
            };
            if let Some(name) = name {
                self.errors
                    .at(name.span(), format!("`{kind}` takes no name"));
            }
            let i = PAIRS
                .iter()
                .position(|p| kind == p)
                .expect("filtered by sections()");
            if std::mem::replace(&mut seen[i], true) {
                self.errors
                    .at(kind.span(), format!("duplicate `{kind}` in contact"));
                continue;
            }
            out[i] = self.pair(body, i == 0);
        }
        out
    }

    /// One contact pair: a normal law (`stiffness` with `chi` and optional
    /// `exponent` for Hunt-Crossley, or with `damping` for Kelvin-Voigt)
    /// and friction (`mu`, `slip`), each part optional. On the `ground`,
    /// friction is stiction unless `slip` asks for regularised Coulomb
    /// friction: its `tangential_stiffness` and `tangential_damping` are
    /// optional too (and an error with `slip`, or on another pair).
    fn pair(&mut self, block: &crate::parse::Block, ground: bool) -> ContactPair {
        let keys = [
            "stiffness",
            "exponent",
            "chi",
            "damping",
            "mu",
            "slip",
            "tangential_stiffness",
            "tangential_damping",
        ];
        let fields = self.fields("contact pair", block, &keys);
        for key in ["tangential_stiffness", "tangential_damping"] {
            let Some(expr) = fields.map.get(key) else {
                continue;
            };
            if !ground {
                self.errors.spanned(
                    expr,
                    format!(
                        "`{key}` is stiction's, which only the `ground` pair has: rims and teeth take regularised friction (`mu`, `slip`)"
                    ),
                );
            } else if fields.map.contains_key("slip") {
                self.errors.spanned(
                    expr,
                    format!(
                        "`{key}` belongs to friction with stiction and `slip` to regularised friction: give one"
                    ),
                );
            }
        }
        self.sections("contact pair", block, &[]);
        let has = |k: &str| fields.map.contains_key(k);
        let normal = if !(has("stiffness") || has("chi") || has("damping") || has("exponent")) {
            None
        } else if has("damping") && (has("chi") || has("exponent")) {
            let key = if has("chi") { "chi" } else { "exponent" };
            self.errors.spanned(
                fields.map[key],
                format!(
                    "`{key}` belongs to the Hunt-Crossley law and `damping` to the Kelvin-Voigt law: give one law"
                ),
            );
            None
        } else if has("damping") {
            let stiffness = self.positive(&fields, "stiffness", true);
            let damping = self.bounded(&fields, "damping", true, Bound::NonNegative);
            Some(NormalLaw::KelvinVoigt {
                stiffness: stiffness.unwrap_or(Num::ZERO),
                damping: damping.unwrap_or(Num::ZERO),
            })
        } else {
            let stiffness = self.positive(&fields, "stiffness", true);
            let exponent = self
                .positive(&fields, "exponent", false)
                .unwrap_or(Num::Known(1.0));
            if !has("chi") {
                self.errors.at(
                    fields.span,
                    "missing key `chi` (Hunt-Crossley, s/m) or `damping` (Kelvin-Voigt, N s/m) in contact pair",
                );
            }
            let chi = self.bounded(&fields, "chi", false, Bound::NonNegative);
            Some(NormalLaw::HuntCrossley {
                stiffness: stiffness.unwrap_or(Num::ZERO),
                exponent,
                chi: chi.unwrap_or(Num::ZERO),
            })
        };
        ContactPair {
            normal,
            mu: self.bounded(&fields, "mu", false, Bound::NonNegative),
            slip: self.bounded(&fields, "slip", false, Bound::NonNegative),
            tangential_stiffness: self.positive(&fields, "tangential_stiffness", false),
            tangential_damping: self.positive(&fields, "tangential_damping", false),
        }
    }
}
