//! Lowering a vehicle's `tracks` block: the spatial vehicle's two sides.
//!
//! ```text
//! tracks {
//!     side: right,                   // the side declared (default right)
//!     gauge: 2.159,                  // m, centre plane to centre plane
//!     guide_play: 0.02,              // m each way (default 0)
//!     hull { mass: …, inertia: (roll, pitch, yaw) },
//!     across { link: (xx, zz), rw: (xx, zz, xz), … },   // optional
//!     left { links: 63, rw { at: [(x, y), …] } },       // optional: the other side
//! }
//! ```
//!
//! The declared side is the planar declaration. The other is its mirror:
//! the same parts at the same places in its own plane, the same track,
//! except where its section says otherwise (a link count, a part's place;
//! a moved part's arm moves with it). A body's inertia across the plane is the
//! declared one, or `I/2 + m w²/12` about both in-plane axes (the runtime's
//! `OutOfPlaneInertia::extruded`; `w` the shoe's width for links, 0 for
//! the hull's parts).

use std::collections::{BTreeMap, BTreeSet};

use quote::format_ident;
use syn::spanned::Spanned;
use syn::{Expr, Ident};

use super::keys::{Bound, Fields, strip};
use super::{Errors, Lowering};
use crate::ir::{Across, Link, Part, Track, Tracks};
use crate::num::{Num, Vec2};
use crate::parse::{Block, Entry};

/// What the `tracks` block is lowered against: the vehicle as the rest of
/// its declaration made it.
pub(super) struct Sides<'a> {
    /// The right side's parts, places from the chassis centroid.
    pub parts: &'a [Part],
    /// The repeated blocks' names (`rw`) and the indices of their parts.
    pub repeated: &'a BTreeMap<String, Vec<usize>>,
    /// The chassis centroid, in the declaration's frame.
    pub centroid: &'a Vec2,
    /// The right track, and its block (the left's links are lowered from
    /// it again when their count differs).
    pub track: &'a Track,
    pub track_block: Option<&'a Block>,
    /// The shoe's declared width, if any.
    pub shoe_width: Option<Num>,
}

impl Lowering<'_> {
    pub(super) fn tracks(&mut self, keyword: &Ident, block: &Block, sides: &Sides) -> Tracks {
        let fields = self.fields("tracks", block, &["side", "gauge", "guide_play"]);
        let declared_left = self.declared_side(&fields);
        let (declared, other) = match declared_left {
            true => ("left", "right"),
            false => ("right", "left"),
        };
        let gauge = self.positive(&fields, "gauge", true).unwrap_or(Num::ZERO);
        let guide_play = match fields.map.contains_key("guide_play") {
            true => self
                .bounded(&fields, "guide_play", true, Bound::NonNegative)
                .unwrap_or(Num::ZERO),
            false => Num::ZERO,
        };
        let shoe_width = sides.shoe_width.clone().unwrap_or_else(|| {
            self.errors.at(
                keyword.span(),
                "`tracks` needs the track's width: declare `width` in the `shoe` section",
            );
            Num::ZERO
        });
        self.gauge_against_width(&fields, &gauge, &shoe_width);
        let mut hull = None;
        let mut across = None;
        let mut mirror = None;
        let kinds = ["hull", "across", "left", "right"];
        for entry in self.sections("tracks", block, &kinds) {
            let Entry::Section { kind, body, .. } = entry else {
                continue;
            };
            let slot = match kind.to_string().as_str() {
                "hull" => &mut hull,
                "across" => &mut across,
                k if k == declared => {
                    self.errors.at(
                        kind.span(),
                        format!(
                            "the {declared} side is the declaration itself; \
                             what differs on the {other} goes in `{other} {{ … }}`"
                        ),
                    );
                    continue;
                }
                _ => &mut mirror,
            };
            if slot.is_some() {
                self.errors
                    .at(kind.span(), format!("duplicate `{kind}` in tracks"));
            } else {
                *slot = Some(body);
            }
        }
        let (hull_mass, hull_inertia) = match hull {
            Some(body) => self.hull_body(body),
            None => {
                self.errors.at(
                    block.span,
                    "missing section `hull { mass: …, inertia: (roll, pitch, yaw) }` in tracks",
                );
                (Num::ZERO, [Num::ZERO, Num::ZERO, Num::ZERO])
            }
        };
        let (mirror_parts, mirror_track) = match mirror {
            Some(body) => self.mirror_side(body, other, sides),
            None => (sides.parts.to_vec(), None),
        };
        // The hull lists the right side's bodies first, whichever is
        // declared.
        let (right_parts, left_parts) = match declared_left {
            true => (mirror_parts.as_slice(), sides.parts),
            false => (sides.parts, mirror_parts.as_slice()),
        };
        let declared = across.map(|b| self.across(b, sides)).unwrap_or_default();
        let named = |part: &Part, side: &str| {
            let mut p = part.clone();
            p.name = format_ident!("{}_{}", side, part.name, span = part.name.span());
            p
        };
        let mut parts: Vec<Part> = right_parts.iter().map(|p| named(p, "right")).collect();
        parts.extend(left_parts.iter().map(|p| named(p, "left")));
        let left_flags: Vec<bool> = (0..parts.len()).map(|i| i >= right_parts.len()).collect();
        let [roll, pitch, yaw] = hull_inertia;
        let (tree, part_bodies) = super::tree::chassis(&hull_mass, &pitch, &parts);
        // Each hull body's side and declared name (a part's or its arm's).
        let half = gauge.clone() / Num::Known(2.0);
        let mut offsets = vec![Num::ZERO; tree.len()];
        let mut hull_across = vec![
            Across {
                xx: roll,
                zz: yaw,
                xz: Num::ZERO,
            };
            tree.len()
        ];
        let all = right_parts.iter().chain(left_parts);
        for ((part, &(body, arm)), &is_left) in all.zip(&part_bodies).zip(&left_flags) {
            let offset = if is_left { half.clone() } else { -half.clone() };
            let name = part.name.to_string();
            offsets[body] = offset.clone();
            hull_across[body] = declared
                .get(&name)
                .cloned()
                .unwrap_or_else(|| extruded(&tree[body].mass, &tree[body].inertia, &Num::ZERO));
            if let Some(arm) = arm {
                offsets[arm] = offset;
                hull_across[arm] = declared
                    .get(&format!("{name}_arm"))
                    .cloned()
                    .unwrap_or_else(|| extruded(&tree[arm].mass, &tree[arm].inertia, &Num::ZERO));
            }
        }
        let link_across = |links: &[Link]| -> Vec<Across> {
            links
                .iter()
                .map(|l| {
                    declared
                        .get("link")
                        .cloned()
                        .unwrap_or_else(|| extruded(&l.mass, &l.inertia, &shoe_width))
                })
                .collect()
        };
        let declared_links = link_across(&sides.track.links);
        let mirror_links = link_across(
            mirror_track
                .as_ref()
                .map_or(&sides.track.links, |t: &Track| &t.links),
        );
        let (right_links, left_links) = match declared_left {
            true => (mirror_links, declared_links),
            false => (declared_links, mirror_links),
        };
        Tracks {
            gauge,
            shoe_width,
            guide_play,
            hull: tree,
            parts,
            part_bodies,
            left: left_flags,
            offsets,
            hull_across,
            right_links,
            left_links,
            declared_left,
            mirror_track,
        }
    }

    /// `side: right` or `side: left`: the side the planar declaration
    /// describes (right when not given); whether it is the left.
    fn declared_side(&mut self, fields: &Fields) -> bool {
        let Some(expr) = fields.map.get("side").copied() else {
            return false;
        };
        match strip(expr) {
            Expr::Path(p) if p.path.is_ident("left") => true,
            Expr::Path(p) if p.path.is_ident("right") => false,
            other => {
                self.errors.spanned(
                    other,
                    "expected `right` or `left`: the side the declaration describes",
                );
                false
            }
        }
    }

    /// A gauge no wider than the track: the two tracks would overlap.
    fn gauge_against_width(&mut self, fields: &Fields, gauge: &Num, width: &Num) {
        let Some(expr) = fields.map.get("gauge").copied() else {
            return;
        };
        match (gauge.known(), width.known()) {
            (Some(g), Some(w)) => {
                if g > 0.0 && w > 0.0 && g <= w {
                    self.errors.spanned(
                        expr,
                        format!(
                            "the gauge ({g} m) must exceed the track's width ({w} m): \
                             the two tracks would overlap"
                        ),
                    );
                }
            }
            _ => self.checks.push(crate::ir::ConstCheck {
                span: expr.span(),
                condition: quote::quote!((#gauge) > (#width)),
                message: "the gauge must exceed the track's width: the two tracks would overlap"
                    .to_string(),
            }),
        }
    }

    /// `hull { mass, inertia: (roll, pitch, yaw) }`: the whole hull's mass
    /// and principal inertias about its centroid (forward, lateral and
    /// vertical axes), kg and kg m².
    fn hull_body(&mut self, block: &Block) -> (Num, [Num; 3]) {
        let fields = self.fields("hull", block, &["mass", "inertia"]);
        self.sections("hull", block, &[]);
        let mass = self.positive(&fields, "mass", true).unwrap_or(Num::ZERO);
        let zero = [Num::ZERO, Num::ZERO, Num::ZERO];
        let Some(expr) = fields.map.get("inertia").copied() else {
            self.missing(&fields, "inertia");
            return (mass, zero);
        };
        let Some([roll, pitch, yaw]) = self.positive_tuple::<3>(expr, "inertia") else {
            return (mass, zero);
        };
        if let (Some(a), Some(b), Some(c)) = (roll.known(), pitch.known(), yaw.known()) {
            // A rigid body's principal moments: each at most the sum of
            // the other two.
            if a > b + c || b > a + c || c > a + b {
                self.errors.spanned(
                    expr,
                    format!(
                        "the hull's inertias ({a}, {b}, {c}) kg m² are no rigid body's: \
                         each principal moment must be at most the sum of the other two"
                    ),
                );
            }
        }
        (mass, [roll, pitch, yaw])
    }

    /// `(a, b, …)`: `N` positive numbers, each finite.
    fn positive_tuple<const N: usize>(&mut self, expr: &Expr, key: &str) -> Option<[Num; N]> {
        let elems = match strip(expr) {
            Expr::Tuple(t) if t.elems.len() == N => t.elems.iter().collect::<Vec<_>>(),
            _ => {
                self.errors
                    .spanned(expr, format!("`{key}` must be a tuple of {N} numbers"));
                return None;
            }
        };
        let values: Vec<Option<Num>> = elems
            .into_iter()
            .map(|e| self.positive_expr(e, key))
            .collect();
        values
            .into_iter()
            .collect::<Option<Vec<_>>>()?
            .try_into()
            .ok()
    }

    /// One positive, finite number.
    fn positive_expr(&mut self, expr: &Expr, key: &str) -> Option<Num> {
        let fields = Fields {
            what: "tracks",
            span: expr.span(),
            map: BTreeMap::from([(key.to_string(), expr)]),
        };
        self.positive(&fields, key, true)
    }

    /// `across { name: (xx, zz) or (xx, zz, xz), … }`: declared inertias
    /// across the plane, by the name of a part (a repeated block's name
    /// gives all its parts), `name_arm` for its arm, `link` for every
    /// link.
    fn across(&mut self, block: &Block, sides: &Sides) -> BTreeMap<String, Across> {
        self.sections("across", block, &[]);
        let mut names: Vec<String> = vec!["link".to_string()];
        let mut expand: BTreeMap<String, Vec<String>> = BTreeMap::new();
        for part in sides.parts {
            let n = part.name.to_string();
            expand.insert(n.clone(), vec![n.clone()]);
            if part.arm.is_some() {
                expand.insert(format!("{n}_arm"), vec![format!("{n}_arm")]);
            }
            names.push(n);
        }
        for (base, indices) in sides.repeated {
            let members = indices.iter().map(|&i| sides.parts[i].name.to_string());
            expand.insert(base.clone(), members.clone().collect());
            if sides.parts[indices[0]].arm.is_some() {
                expand.insert(
                    format!("{base}_arm"),
                    members.map(|m| format!("{m}_arm")).collect(),
                );
            }
        }
        expand.insert("link".to_string(), vec!["link".to_string()]);
        let mut out = BTreeMap::new();
        for entry in &block.entries {
            let Entry::Field { key, value } = entry else {
                continue;
            };
            let name = key.to_string();
            let Some(targets) = expand.get(&name) else {
                let known: Vec<&str> = expand.keys().map(String::as_str).collect();
                self.errors.at(
                    key.span(),
                    format!(
                        "`{name}` names no part, arm or `link`; expected one of: {}",
                        known.join(", ")
                    ),
                );
                continue;
            };
            let Some(inertia) = self.across_value(value, &name) else {
                continue;
            };
            for target in targets {
                if out.insert(target.clone(), inertia.clone()).is_some() {
                    self.errors.at(
                        key.span(),
                        format!("`{target}`'s inertia across the plane is declared twice"),
                    );
                }
            }
        }
        out
    }

    /// `(xx, zz)` or `(xx, zz, xz)`, positive definite where known.
    fn across_value(&mut self, value: &Expr, key: &str) -> Option<Across> {
        let elems: Vec<&Expr> = match strip(value) {
            Expr::Tuple(t) if matches!(t.elems.len(), 2 | 3) => t.elems.iter().collect(),
            _ => {
                self.errors.spanned(
                    value,
                    format!("`{key}` must be `(xx, zz)` or `(xx, zz, xz)` in kg m²"),
                );
                return None;
            }
        };
        let xx = self.positive_expr(elems[0], key);
        let zz = self.positive_expr(elems[1], key);
        let xz = match elems.get(2) {
            Some(e) => self.eval(e, key).ok(),
            None => Some(Num::ZERO),
        };
        let across = Across {
            xx: xx?,
            zz: zz?,
            xz: xz?,
        };
        if let (Some(xx), Some(zz), Some(xz)) =
            (across.xx.known(), across.zz.known(), across.xz.known())
            && xx * zz <= xz * xz
        {
            self.errors.spanned(
                value,
                format!(
                    "`{key}`'s inertia ({xx}, {zz}, {xz}) kg m² is not positive definite: \
                     xx zz must exceed xz²"
                ),
            );
        }
        Some(across)
    }

    /// `left { links: n, part { at: … }, … }` (or `right`): the mirrored
    /// side's parts (the declared side's, moved where said) and its track
    /// when `links` differs.
    fn mirror_side(
        &mut self,
        block: &Block,
        side: &'static str,
        sides: &Sides,
    ) -> (Vec<Part>, Option<Track>) {
        let fields = self.fields(side, block, &["links"]);
        let mut parts = sides.parts.to_vec();
        let by_name: BTreeMap<String, Vec<usize>> = sides
            .parts
            .iter()
            .enumerate()
            .map(|(i, p)| (p.name.to_string(), vec![i]))
            .chain(sides.repeated.iter().map(|(k, v)| (k.clone(), v.clone())))
            .collect();
        let mut moved = BTreeSet::new();
        for entry in &block.entries {
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
            if selector.is_some() || name.is_some() || count.is_some() {
                self.errors.at(
                    kind.span(),
                    format!("expected `{kind} {{ at: … }}`: the {side} side moves parts by name"),
                );
                continue;
            }
            let part = kind.to_string();
            let Some(indices) = by_name.get(&part) else {
                let known: Vec<&str> = by_name.keys().map(String::as_str).collect();
                self.errors.at(
                    kind.span(),
                    format!(
                        "the declared side has no part `{part}` to mirror; expected one of: {}",
                        known.join(", ")
                    ),
                );
                continue;
            };
            let place = self.fields("a mirrored part", body, &["at"]);
            self.sections("a mirrored part", body, &[]);
            let n = indices.len();
            let what = sides
                .repeated
                .contains_key(&part)
                .then(|| format!("`{part}` is {n} parts"));
            let points = self.places(&place, what.as_deref().map(|w| (n, w)));
            for (&i, at) in indices.iter().zip(points.into_iter().flatten()) {
                if !moved.insert(i) {
                    self.errors.at(
                        kind.span(),
                        format!("`{}` is moved twice on the {side}", sides.parts[i].name),
                    );
                }
                // From the chassis centroid, as the right side's places.
                let at = at - sides.centroid.clone();
                let shift = at.clone() - parts[i].at.clone();
                parts[i].at = at;
                if let Some(arm) = &mut parts[i].arm {
                    arm.pivot = arm.pivot.clone() + shift;
                }
            }
        }
        let track = fields
            .map
            .contains_key("links")
            .then(|| self.mirror_track(&fields, side, sides))
            .flatten();
        (parts, track)
    }

    /// The mirrored side's track, from the declared one's block with its
    /// own link count (`None` when the counts agree); an error in it (a
    /// link override beyond the shorter track) is reported as that side's.
    fn mirror_track(&mut self, fields: &Fields, side: &str, sides: &Sides) -> Option<Track> {
        let right = sides.track;
        let n = self.link_count(fields, &right.closure)?;
        let block = sides.track_block?;
        if n == right.links.len() {
            return None;
        }
        let mut scratch = Errors::default();
        let mut sub = Lowering {
            errors: &mut scratch,
            checks: Vec::new(),
            pool: self.pool.clone(),
        };
        let sections = sub.sections("track", block, &["link"]);
        let links = sub.links(&sections, Some(n), block.span);
        // The right's lowering made the same constant checks.
        drop(sub.checks);
        if let Err(errors) = scratch.finish() {
            for e in errors {
                self.errors
                    .at(e.span(), format!("on the {side} side ({n} links): {e}"));
            }
            return None;
        }
        let bodies = super::tree::chain(&links);
        Some(Track {
            links,
            closure: right.closure.clone(),
            gravity: right.gravity.clone(),
            bodies,
        })
    }
}

/// The default inertia across the plane: `I/2 + m w²/12` about both
/// in-plane axes (`OutOfPlaneInertia::extruded`).
fn extruded(mass: &Num, inertia: &Num, width: &Num) -> Across {
    let across = inertia.clone() / Num::Known(2.0)
        + mass.clone() * width.clone() * width.clone() / Num::Known(12.0);
    Across {
        xx: across.clone(),
        zz: across,
        xz: Num::ZERO,
    }
}
