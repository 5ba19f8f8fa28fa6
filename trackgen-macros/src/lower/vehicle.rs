//! Lowering a `vehicle`: chassis, parts (repeated parts expanded), arms;
//! what makes it run is [`super::running`]'s.

use std::collections::BTreeMap;

use proc_macro2::Span;
use quote::{format_ident, quote};
use syn::spanned::Spanned;
use syn::{Expr, Ident, Lit, LitInt};

use super::Lowering;
use super::keys::{Fields, strip};
use super::sections::{Profile, VehicleSections};
use crate::ir::{Arm, Closure, ConstCheck, Part, PartKind, Track, Vehicle};
use crate::num::{Num, Vec2};

/// The shortest arm, m: a pivot closer than this to its part's centre is
/// taken as a zero-length arm (the arm's angle would not move the part).
const MIN_ARM_LENGTH: f64 = 1e-9;

/// The most parts one repeated block declares.
const MAX_REPEAT: usize = 64;

impl Lowering<'_> {
    pub(super) fn vehicle(&mut self, block: &crate::parse::Block, name: &Ident) -> Vehicle {
        use crate::parse::Entry;
        let fields = self.fields("vehicle", block, &["gravity", "seat", "hull"]);
        let gravity = self.gravity(&fields);
        let seat = self.point(&fields, "seat", false);
        let hull = self.hull(&fields);
        let kinds = [
            "chassis",
            "track",
            "shoe",
            "contact",
            "drive",
            "powertrain",
            "sprocket",
            "idler",
            "road_wheel",
            "roller",
            "tracks",
        ];
        let sections = self.sections("vehicle", block, &kinds);
        let mut unique = VehicleSections::default();
        let mut parts = Vec::new();
        let mut part_names: BTreeMap<String, Ident> = BTreeMap::new();
        let mut sprocket: Option<&Ident> = None;
        let mut profile = Profile::default();
        let mut repeated: BTreeMap<String, Vec<usize>> = BTreeMap::new();
        let vehicle_name = name;
        for entry in sections {
            let Entry::Section {
                kind,
                selector,
                name,
                count,
                body,
            } = entry
            else {
                continue;
            };
            if let Some(sel) = selector {
                self.errors
                    .at(sel.span, format!("`{kind}` takes no link selector"));
            }
            let k = kind.to_string();
            let Some(kind_ir) = PartKind::from_keyword(&k) else {
                if let Some(name) = name {
                    self.errors.at(name.span(), format!("`{k}` takes no name"));
                }
                self.unique_section(&mut unique, kind, body);
                continue;
            };
            let Some(name) = name else {
                self.errors.at(
                    kind.span(),
                    format!("`{k}` needs a name, e.g. `{k} front {{ … }}`"),
                );
                continue;
            };
            let repeat = match count {
                Some(lit) => match self.repeat(lit, kind_ir) {
                    Some(n) => Some(n),
                    None => continue,
                },
                None => None,
            };
            let names: Vec<Ident> = match repeat {
                Some(n) => (1..=n)
                    .map(|i| format_ident!("{}{}", name, i, span = name.span()))
                    .collect(),
                None => vec![name.clone()],
            };
            self.claim_part_names(name, &names, &mut part_names);
            if kind_ir == PartKind::Sprocket {
                match sprocket {
                    // The runtime drives and meshes one sprocket.
                    Some(first) => self.errors.at(
                        kind.span(),
                        format!(
                            "one sprocket per vehicle: `{first}` is its sprocket; \
                             declare `{name}` as an `idler`"
                        ),
                    ),
                    None => sprocket = Some(name),
                }
            }
            let base = repeat.map(|_| name);
            let (declared, declared_profile) = self.part(kind_ir, &names, base, body);
            if base.is_some() {
                let first = parts.len();
                repeated.insert(name.to_string(), (first..first + declared.len()).collect());
            }
            parts.extend(declared);
            if let Some(p) = declared_profile {
                profile = p;
            }
        }
        let chassis = unique.chassis.map(|b| self.chassis(b));
        let track = unique.track.map(|b| self.track(b, false));
        self.required_sections(vehicle_name, chassis.is_some(), track.is_some());
        let (chassis_mass, chassis_inertia, centroid) =
            chassis.unwrap_or((Num::ZERO, Num::ZERO, Vec2::zero()));
        // The seat on the frame, from its centroid (the default: the
        // centroid itself).
        let seat = seat.map_or_else(Vec2::zero, |s| s - centroid.clone());
        let hull = hull.into_iter().map(|p| p - centroid.clone()).collect();
        for part in &mut parts {
            part.at = part.at.clone() - centroid.clone();
            if let Some(arm) = &mut part.arm {
                arm.pivot = arm.pivot.clone() - centroid.clone();
            }
        }
        let mut track = track.unwrap_or(Track {
            links: Vec::new(),
            closure: Closure::Open,
            gravity: Vec2::zero(),
            bodies: Vec::new(),
        });
        track.gravity = gravity.clone();
        let running = self.running(&unique, sprocket.is_some(), profile, &track);
        let tracks = unique.tracks.map(|(keyword, body)| {
            let sides = super::tracks::Sides {
                parts: &parts,
                repeated: &repeated,
                centroid: &centroid,
                track: &track,
                track_block: unique.track,
                shoe_width: running.as_ref().and_then(|r| r.shoe.width.clone()),
            };
            self.tracks(keyword, body, &sides)
        });
        let (chassis, part_bodies) = super::tree::chassis(&chassis_mass, &chassis_inertia, &parts);
        Vehicle {
            gravity,
            seat,
            hull,
            parts,
            track,
            chassis,
            part_bodies,
            running,
            tracks,
        }
    }

    /// A vehicle without its `chassis` or `track` section: an error at its
    /// name for each.
    fn required_sections(&mut self, vehicle: &Ident, chassis: bool, track: bool) {
        if !chassis {
            self.errors.at(
                vehicle.span(),
                format!("vehicle `{vehicle}` has no `chassis {{ mass: …, inertia: … }}` section"),
            );
        }
        if !track {
            self.errors.at(
                vehicle.span(),
                format!("vehicle `{vehicle}` has no `track {{ … }}` section"),
            );
        }
    }

    /// A section of which a vehicle has at most one (`chassis`, `track`,
    /// `shoe`, `contact`, `drive`, `powertrain`), kept in `unique`; a
    /// second is an error at its keyword.
    fn unique_section<'a>(
        &mut self,
        unique: &mut VehicleSections<'a>,
        kind: &'a Ident,
        body: &'a crate::parse::Block,
    ) {
        let k = kind.to_string();
        let slot = match k.as_str() {
            "chassis" => &mut unique.chassis,
            "track" => &mut unique.track,
            "contact" => &mut unique.contact,
            "drive" => &mut unique.drive,
            "powertrain" => &mut unique.powertrain,
            "tracks" => {
                if unique.tracks.is_some() {
                    self.errors
                        .at(kind.span(), "duplicate `tracks` section".to_string());
                } else {
                    unique.tracks = Some((kind, body));
                }
                return;
            }
            _ => {
                if unique.shoe.is_some() {
                    self.errors
                        .at(kind.span(), "duplicate `shoe` section".to_string());
                } else {
                    unique.shoe = Some((kind, body));
                }
                return;
            }
        };
        if slot.is_some() {
            self.errors
                .at(kind.span(), format!("duplicate `{k}` section"));
        } else {
            *slot = Some(body);
        }
    }

    /// Claims the part names `names` (declared as `name`, one or a
    /// repeated block's) in `taken`, by their upper case: part names
    /// become body-index constants (`RW1`) and local names beside the
    /// frame's (`chassis`), so a name taken twice, or the frame's, is an
    /// error at `name`.
    fn claim_part_names(
        &mut self,
        name: &Ident,
        names: &[Ident],
        taken: &mut BTreeMap<String, Ident>,
    ) {
        for part_name in names {
            let upper = part_name.to_string().to_uppercase();
            if upper == "FRAME" || upper == "CHASSIS" {
                self.errors.at(
                    name.span(),
                    format!(
                        "`{part_name}` is reserved for the chassis frame; choose another part name"
                    ),
                );
            } else if taken.insert(upper, part_name.clone()).is_some() {
                self.errors
                    .at(name.span(), format!("duplicate part name `{part_name}`"));
            }
        }
    }

    /// The count of a repeated part block, `rw[5]`.
    fn repeat(&mut self, lit: &LitInt, kind: PartKind) -> Option<usize> {
        if kind == PartKind::Sprocket {
            self.errors.at(
                lit.span(),
                "one sprocket per vehicle: a sprocket cannot be repeated",
            );
            return None;
        }
        match self.integer::<usize>(lit, "usize").ok()? {
            Some(n) if (1..=MAX_REPEAT).contains(&n) => Some(n),
            _ => {
                self.errors.at(
                    lit.span(),
                    format!(
                        "a repeated part declares 1 to {MAX_REPEAT} parts, found {}",
                        lit.base10_digits()
                    ),
                );
                None
            }
        }
    }

    fn chassis(&mut self, block: &crate::parse::Block) -> (Num, Num, Vec2) {
        let fields = self.fields("chassis", block, &["mass", "inertia", "centroid"]);
        self.sections("chassis", block, &[]);
        let mass = self.positive(&fields, "mass", true).unwrap_or(Num::ZERO);
        let inertia = self.positive(&fields, "inertia", true).unwrap_or(Num::ZERO);
        let centroid = self
            .point(&fields, "centroid", false)
            .unwrap_or(Vec2::zero());
        (mass, inertia, centroid)
    }

    /// One part, or one per name of a repeated block `base[n]` (whose `at`
    /// is then a list of positions), and a sprocket's declared profile.
    fn part(
        &mut self,
        kind: PartKind,
        names: &[Ident],
        repeated: Option<&Ident>,
        block: &crate::parse::Block,
    ) -> (Vec<Part>, Option<Profile>) {
        use crate::parse::Entry;
        let what = kind.keyword();
        let mut keys = vec!["at", "mass", "inertia", "radius"];
        if kind == PartKind::Sprocket {
            keys.extend(["teeth", "tip_radius", "gap_radius", "gap_centre"]);
        }
        let fields = self.fields(what, block, &keys);
        let takes_arm = matches!(kind, PartKind::RoadWheel | PartKind::Idler);
        let mut arm = None;
        for entry in &block.entries {
            let Entry::Section {
                kind: keyword,
                body,
                ..
            } = entry
            else {
                continue;
            };
            if keyword != "arm" {
                self.errors.at(
                    keyword.span(),
                    format!("unexpected section `{keyword}` in {what}"),
                );
            } else if !takes_arm {
                // Say why, rather than that the section is unknown.
                self.errors.at(
                    keyword.span(),
                    format!("a {what} takes no `arm`: only road wheels and idlers hang from arms"),
                );
            } else if arm.is_some() {
                self.errors
                    .at(keyword.span(), format!("duplicate `arm` in {what}"));
            } else {
                arm = Some(self.arm(body, repeated.is_some()));
            }
        }
        let n = names.len();
        let list = repeated.map(|base| format!("`{base}[{n}]` declares {n} parts"));
        let at = self.places(&fields, list.as_deref().map(|w| (n, w)));
        let mass = self.positive(&fields, "mass", true);
        let inertia = self.positive(&fields, "inertia", true);
        let radius = self.positive(&fields, "radius", true);
        let (teeth, profile) = if kind == PartKind::Sprocket {
            let keys = ["tip_radius", "gap_radius", "gap_centre"];
            let radii = keys.map(|key| self.positive(&fields, key, false));
            let spans = keys.map(|key| fields.map.get(key).map(|e| e.span()));
            let teeth = self.teeth(&fields);
            let teeth_span = fields.map.get("teeth").map(|e| e.span());
            let profile = Profile {
                radii,
                spans,
                teeth: teeth.zip(teeth_span),
            };
            (teeth, Some(profile))
        } else {
            (Some(0), None)
        };
        let (Some(at), Some(mass), Some(inertia), Some(radius), Some(teeth)) =
            (at, mass, inertia, radius, teeth)
        else {
            return (Vec::new(), profile);
        };
        let arm = match arm {
            Some(Some(arm)) => Some(arm),
            Some(None) => return (Vec::new(), profile),
            None => None,
        };
        let parts = names
            .iter()
            .zip(at)
            .map(|(name, at)| {
                let arm = arm.as_ref().map(|(arm, pivot, span)| {
                    let pivot = match pivot {
                        PivotAt::Absolute => arm.pivot.clone(),
                        PivotAt::FromPart => at.clone() + arm.pivot.clone(),
                    };
                    self.check_arm_length(&pivot, *span, &at, what);
                    Arm {
                        pivot,
                        ..arm.clone()
                    }
                });
                Part {
                    name: name.clone(),
                    kind,
                    at,
                    mass: mass.clone(),
                    inertia: inertia.clone(),
                    radius: radius.clone(),
                    teeth,
                    arm,
                }
            })
            .collect::<Vec<_>>();
        (parts, profile)
    }

    /// An arm carries its part at a distance: a pivot at the part's centre
    /// would make the arm's angle move nothing but the arm.
    fn check_arm_length(&mut self, pivot: &Vec2, pivot_span: Span, at: &Vec2, what: &str) {
        let what = what.replace('_', " ");
        let message = format!(
            "zero-length arm: its `pivot` is at the {what}'s centre `at`; \
             pivot and centre must be at least {MIN_ARM_LENGTH:e} m apart"
        );
        let d = pivot.clone() - at.clone();
        match (d.x.known(), d.y.known()) {
            (Some(x), Some(y)) => {
                if x.hypot(y) < MIN_ARM_LENGTH {
                    self.errors.at(pivot_span, message);
                }
            }
            _ => {
                let squared = d.norm_squared();
                let min = MIN_ARM_LENGTH * MIN_ARM_LENGTH;
                self.checks.push(ConstCheck {
                    span: pivot_span,
                    condition: quote!((#squared) >= #min),
                    message,
                });
            }
        }
    }

    /// `arm { pivot | pivot_offset, mass, inertia, stiffness, damping,
    /// preload, travel }`: the arm (its `pivot` as declared, absolute or from the
    /// part), how its pivot is given, and the pivot's span. In a repeated
    /// block only `pivot_offset` makes sense.
    fn arm(&mut self, block: &crate::parse::Block, repeated: bool) -> Option<(Arm, PivotAt, Span)> {
        let keys = [
            "pivot",
            "pivot_offset",
            "mass",
            "inertia",
            "stiffness",
            "damping",
            "preload",
            "travel",
        ];
        let fields = self.fields("arm", block, &keys);
        self.sections("arm", block, &[]);
        let pivot = match (fields.map.get("pivot"), fields.map.get("pivot_offset")) {
            (Some(p), Some(_)) => {
                self.errors.spanned(
                    p,
                    "give the arm's `pivot` or its `pivot_offset` from the part's centre, not both",
                );
                None
            }
            (Some(p), None) if repeated => {
                self.errors.spanned(
                    p,
                    "a repeated part's arms share one `pivot_offset` (m, from each part's centre), not a `pivot`",
                );
                None
            }
            (Some(p), None) => self
                .point(&fields, "pivot", true)
                .map(|v| (v, PivotAt::Absolute, p.span())),
            (None, Some(p)) => self
                .point(&fields, "pivot_offset", true)
                .map(|v| (v, PivotAt::FromPart, p.span())),
            (None, None) => {
                self.errors.at(
                    fields.span,
                    "missing key `pivot` (or `pivot_offset`) in arm",
                );
                None
            }
        };
        let mass = self.positive(&fields, "mass", true);
        let inertia = self.positive(&fields, "inertia", true);
        let stiffness = self.non_negative(&fields, "stiffness");
        let damping = self.non_negative(&fields, "damping");
        let preload = self.number(&fields, "preload", false).unwrap_or(Num::ZERO);
        let travel = self.travel(&fields);
        let (pivot, how, span) = pivot?;
        let arm = Arm {
            pivot,
            mass: mass?,
            inertia: inertia?,
            stiffness: stiffness?,
            damping: damping?,
            preload,
            travel: travel?,
        };
        Some((arm, how, span))
    }

    /// An arm's `travel: (low, high)`, rad from the design position, with
    /// `−π ≤ low ≤ 0 ≤ high ≤ π` and `low < high`; default a quarter turn
    /// each way.
    fn travel(&mut self, fields: &Fields) -> Option<Vec2> {
        let quarter = std::f64::consts::FRAC_PI_2;
        let Some(expr) = fields.map.get("travel").copied() else {
            return Some(Vec2 {
                x: Num::Known(-quarter),
                y: Num::Known(quarter),
            });
        };
        if !matches!(strip(expr), Expr::Tuple(t) if t.elems.len() == 2) {
            self.errors.spanned(
                expr,
                "`travel` must be a pair `(low, high)` of angles in rad",
            );
            return None;
        }
        let travel = self.point(fields, "travel", false)?;
        let message = "`travel` must be (low, high) in rad from the design position, with -π ≤ low ≤ 0 ≤ high ≤ π and low < high";
        match (travel.x.known(), travel.y.known()) {
            (Some(low), Some(high)) => {
                let pi = std::f64::consts::PI;
                if !(-pi <= low && low <= 0.0 && 0.0 <= high && high <= pi && low < high) {
                    self.errors
                        .spanned(expr, format!("{message}; found ({low}, {high})"));
                    return None;
                }
            }
            _ => {
                let (low, high) = (&travel.x, &travel.y);
                self.checks.push(ConstCheck {
                    span: expr.span(),
                    condition: quote!(
                        -::core::f64::consts::PI <= (#low) && (#low) <= 0.0
                            && 0.0 <= (#high) && (#high) <= ::core::f64::consts::PI
                            && (#low) < (#high)
                    ),
                    message: message.to_string(),
                });
            }
        }
        Some(travel)
    }

    fn teeth(&mut self, fields: &Fields) -> Option<u32> {
        let Some(expr) = fields.map.get("teeth") else {
            self.missing(fields, "teeth");
            return None;
        };
        match strip(expr) {
            Expr::Lit(syn::ExprLit {
                lit: Lit::Int(lit), ..
            }) => match self.integer::<u32>(lit, "u32").ok()? {
                Some(t) if t >= 3 => Some(t),
                Some(_) => {
                    self.errors
                        .at(lit.span(), "a sprocket needs at least 3 teeth");
                    None
                }
                None => {
                    self.errors.at(
                        lit.span(),
                        format!(
                            "`teeth` is a `u32`: at most {}, found {}",
                            u32::MAX,
                            lit.base10_digits()
                        ),
                    );
                    None
                }
            },
            other => {
                self.errors
                    .spanned(other, "`teeth` must be an integer literal");
                None
            }
        }
    }

    /// `hull: [(x, y), …]`: the hull's outline on the frame, m, a convex
    /// polygon of at least three corners in either winding, given in the
    /// vehicle's frame (the seat's); none when not declared. Its
    /// convexity is checked here when its numbers are literal, and when
    /// the vehicle is built otherwise.
    fn hull(&mut self, fields: &Fields) -> Vec<Vec2> {
        let Some(points) = self.points(fields, "hull", false) else {
            return Vec::new();
        };
        let expr = fields.map.get("hull").expect("points found it");
        if points.len() < 3 {
            self.errors.spanned(
                expr,
                format!(
                    "`hull` is an outline: at least 3 corners, found {}",
                    points.len()
                ),
            );
            return Vec::new();
        }
        let known: Option<Vec<(f64, f64)>> = points
            .iter()
            .map(|p| Some((p.x.known()?, p.y.known()?)))
            .collect();
        if let Some(corners) = known
            && let Err(why) = trackgen_sprocket::convex_outline(&corners)
        {
            self.errors.spanned(expr, format!("`hull`: {why}"));
            return Vec::new();
        }
        points
    }

    /// A non-empty list of points `[(x, y), …]`, m.
    /// `at`: one point, or for `n` parts (`what` says which, in the
    /// error) a list of `n` points.
    pub(super) fn places(
        &mut self,
        fields: &Fields,
        repeated: Option<(usize, &str)>,
    ) -> Option<Vec<Vec2>> {
        let Some((n, what)) = repeated else {
            return self.point(fields, "at", true).map(|p| vec![p]);
        };
        let at = self.points(fields, "at", true)?;
        if at.len() == n {
            return Some(at);
        }
        self.errors.spanned(
            fields.map["at"],
            format!("{what}: `at` needs {n} positions, found {}", at.len()),
        );
        None
    }

    pub(super) fn points(
        &mut self,
        fields: &Fields,
        key: &str,
        required: bool,
    ) -> Option<Vec<Vec2>> {
        let Some(expr) = fields.map.get(key) else {
            if required {
                self.missing(fields, key);
            }
            return None;
        };
        let Expr::Array(list) = strip(expr) else {
            self.errors.spanned(
                expr,
                format!("`{key}` must be a list of points `[(x, y), …]` in metres"),
            );
            return None;
        };
        if list.elems.is_empty() {
            self.errors
                .spanned(list, format!("`{key}` needs at least one point"));
            return None;
        }
        let points: Vec<Option<Vec2>> = list
            .elems
            .iter()
            .map(|e| self.eval_point(e, key).ok())
            .collect();
        points.into_iter().collect()
    }
}

/// How an arm's pivot is declared.
#[derive(Clone, Copy)]
enum PivotAt {
    /// `pivot`: in the vehicle's frame.
    Absolute,
    /// `pivot_offset`: from the part's centre.
    FromPart,
}
