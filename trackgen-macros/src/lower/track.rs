//! A track: its keys, closure, link count and links (a template and
//! overrides by index range), each link's joints distinct.

use std::collections::BTreeMap;

use proc_macro2::Span;
use quote::{ToTokens, quote};
use syn::spanned::Spanned;
use syn::{Expr, Lit, LitInt, Member};

use super::keys::{Fields, strip};
use super::{Lowering, MAX_LINKS, tree};
use crate::ir::{Closure, ConstCheck, Link, Track};
use crate::num::{Num, Vec2};
use crate::parse::{Block, Entry, IndexRange, Selector};

const DEFAULT_GRAVITY: f64 = -9.81;

impl Lowering<'_> {
    pub(super) fn gravity(&mut self, fields: &Fields) -> Vec2 {
        self.point(fields, "gravity", false).unwrap_or(Vec2 {
            x: Num::ZERO,
            y: Num::Known(DEFAULT_GRAVITY),
        })
    }

    pub(super) fn track(&mut self, block: &Block, standalone: bool) -> Track {
        let allowed: &[&str] = if standalone {
            &["links", "closure", "gravity"]
        } else {
            &["links", "closure"]
        };
        let fields = self.fields("track", block, allowed);
        let closure = self.closure(&fields);
        let count = self.link_count(&fields, &closure);
        let gravity = if standalone {
            self.gravity(&fields)
        } else {
            Vec2::zero()
        };
        let sections = self.sections("track", block, &["link"]);
        let links = self.links(&sections, count, block.span);
        let bodies = tree::chain(&links);
        Track {
            links,
            closure,
            gravity,
            bodies,
        }
    }

    pub(super) fn link_count(&mut self, fields: &Fields, closure: &Closure) -> Option<usize> {
        let Some(expr) = fields.map.get("links") else {
            self.missing(fields, "links");
            return None;
        };
        let Expr::Lit(syn::ExprLit {
            lit: Lit::Int(lit), ..
        }) = strip(expr)
        else {
            self.errors.spanned(
                expr,
                "`links` must be an integer literal: it fixes the shape of the generated code",
            );
            return None;
        };
        let n = self.integer::<usize>(lit, "usize").ok()?;
        let Some(n) = n.filter(|&n| n <= MAX_LINKS) else {
            self.errors.at(
                lit.span(),
                format!(
                    "at most {MAX_LINKS} links are supported, found {}",
                    lit.base10_digits()
                ),
            );
            return None;
        };
        let closed = !matches!(closure, Closure::Open);
        if n == 0 {
            self.errors
                .at(lit.span(), "a track needs at least one link");
            None
        } else if closed && n < 3 {
            self.errors.at(
                lit.span(),
                format!("a closed track needs at least 3 links, found {n}"),
            );
            None
        } else {
            Some(n)
        }
    }

    pub(super) fn closure(&mut self, fields: &Fields) -> Closure {
        const EXPECTED: &str =
            "expected `open`, `partitioned` or `penalty { stiffness: …, damping: … }`";
        let Some(expr) = fields.map.get("closure") else {
            return Closure::Partitioned;
        };
        match strip(expr) {
            Expr::Path(p) if p.path.is_ident("open") => Closure::Open,
            Expr::Path(p) if p.path.is_ident("partitioned") => Closure::Partitioned,
            Expr::Struct(s) if s.path.is_ident("penalty") => {
                let mut map = BTreeMap::new();
                for f in &s.fields {
                    let Member::Named(key) = &f.member else {
                        self.errors
                            .at(f.member.span(), "expected `stiffness` or `damping`");
                        continue;
                    };
                    let name = key.to_string();
                    if name != "stiffness" && name != "damping" {
                        self.errors.at(key.span(), format!("unknown key `{name}` in penalty; expected one of: stiffness, damping"));
                    } else if map.insert(name.clone(), &f.expr).is_some() {
                        self.errors
                            .at(key.span(), format!("duplicate key `{name}` in penalty"));
                    }
                }
                let pf = Fields {
                    what: "penalty",
                    span: s.brace_token.span.join(),
                    map,
                };
                let stiffness = self.positive(&pf, "stiffness", true);
                let damping = self.non_negative(&pf, "damping");
                Closure::Penalty {
                    stiffness: stiffness.unwrap_or(Num::ZERO),
                    damping: damping.unwrap_or(Num::ZERO),
                }
            }
            other => {
                self.errors.spanned(other, EXPECTED);
                Closure::Partitioned
            }
        }
    }

    /// The template `link { … }` filled in by the overrides `link[…] { … }`,
    /// in order.
    pub(super) fn links(
        &mut self,
        sections: &[&Entry],
        count: Option<usize>,
        span: Span,
    ) -> Vec<Link> {
        let mut template: Option<Link> = None;
        let mut overrides = Vec::new();
        for entry in sections {
            let Entry::Section {
                kind,
                selector,
                name,
                body,
                ..
            } = entry
            else {
                continue;
            };
            if let Some(name) = name {
                self.errors.at(name.span(), "a link section takes no name");
            }
            const KEYS: &[&str] = &["mass", "inertia", "u1", "u2"];
            let fields = self.fields("link", body, KEYS);
            self.sections("link", body, &[]);
            match selector {
                None => {
                    if template.is_some() {
                        self.errors.at(
                            kind.span(),
                            "duplicate `link` template; use `link[i] { … }` to change some links",
                        );
                    }
                    let mass = self.positive(&fields, "mass", true);
                    let inertia = self.positive(&fields, "inertia", true);
                    let u1 = self.point(&fields, "u1", true);
                    let u2 = self.point(&fields, "u2", true);
                    if let (Some(mass), Some(inertia), Some(u1), Some(u2)) = (mass, inertia, u1, u2)
                    {
                        let link = Link {
                            mass,
                            inertia,
                            u1,
                            u2,
                        };
                        self.check_distinct_joints(&link, "the link template", body.span);
                        template.get_or_insert(link);
                    }
                }
                Some(sel) => {
                    let indices = count.map(|n| self.select(sel, n)).unwrap_or_default();
                    let mass = self.positive(&fields, "mass", false);
                    let inertia = self.positive(&fields, "inertia", false);
                    let u1 = self.point(&fields, "u1", false);
                    let u2 = self.point(&fields, "u2", false);
                    overrides.push((indices, mass, inertia, u1, u2, body.span));
                }
            }
        }
        let (Some(template), Some(n)) = (template, count) else {
            if count.is_some()
                && !sections
                    .iter()
                    .any(|e| matches!(e, Entry::Section { selector: None, .. }))
            {
                self.errors.at(
                    span,
                    "missing `link { mass: …, inertia: …, u1: (…), u2: (…) }` template in track",
                );
            }
            return Vec::new();
        };
        let mut links = vec![template; n];
        // Links an override changed: the template was checked already.
        let mut touched = vec![None; n];
        for (indices, mass, inertia, u1, u2, body_span) in overrides {
            for i in indices {
                let link = &mut links[i];
                if let Some(v) = &mass {
                    link.mass = v.clone();
                }
                if let Some(v) = &inertia {
                    link.inertia = v.clone();
                }
                if let Some(v) = &u1 {
                    link.u1 = v.clone();
                }
                if let Some(v) = &u2 {
                    link.u2 = v.clone();
                }
                touched[i] = Some(body_span);
            }
        }
        for (i, link) in links.iter().enumerate() {
            if let Some(span) = touched[i] {
                self.check_distinct_joints(link, &format!("link {}", i + 1), span);
            }
        }
        links
    }

    pub(super) fn check_distinct_joints(&mut self, link: &Link, which: &str, span: Span) {
        let d = link.u2.clone() - link.u1.clone();
        match (d.x.known(), d.y.known()) {
            (Some(x), Some(y)) => {
                if x == 0.0 && y == 0.0 {
                    self.errors.at(
                        span,
                        format!("{which}: its joint points `u1` and `u2` coincide"),
                    );
                }
            }
            _ => {
                let (x, y) = (d.x.to_token_stream(), d.y.to_token_stream());
                self.checks.push(ConstCheck {
                    span,
                    condition: quote!(!((#x) == 0.0 && (#y) == 0.0)),
                    message: format!("{which}: its joint points `u1` and `u2` coincide"),
                });
            }
        }
    }

    /// The 0-based link indices a selector names (it names 1-based links).
    /// Each range that selects nothing, or a link the track does not have,
    /// is an error at its tokens.
    pub(super) fn select(&mut self, sel: &Selector, n: usize) -> Vec<usize> {
        let mut out = Vec::new();
        for range in &sel.ranges {
            // A link number too large for a `usize` names no link either.
            let mut number = |lit: &LitInt| {
                self.integer::<usize>(lit, "usize")
                    .map(|v| v.unwrap_or(usize::MAX))
            };
            let start = number(&range.start);
            let end = range.end.as_ref().map(|(_, lit)| number(lit)).transpose();
            let step = range.step.as_ref().map(&mut number).transpose();
            let (Ok(start), Ok(end), Ok(step)) = (start, end, step) else {
                continue;
            };
            if start == 0 {
                self.errors
                    .at(range.start.span(), "links are numbered from 1");
                continue;
            }
            // The last link selected, 1-based.
            let last = match (&range.end, end) {
                (Some((true, _)), Some(end)) => end,
                (Some((false, _)), Some(end)) => end.saturating_sub(1),
                _ => start,
            };
            if last < start {
                let equal = matches!(&range.end, Some((false, _))) && end == Some(start);
                self.empty_range(range, equal);
                continue;
            }
            if last > n {
                let lit = range.end.as_ref().map_or(&range.start, |(_, l)| l);
                // The literal itself, unless it is an exclusive end that
                // fits in a `usize` (then the link before it).
                let last = match &range.end {
                    Some((false, _)) if end != Some(usize::MAX) => last.to_string(),
                    _ => lit.base10_digits().to_string(),
                };
                self.errors.at(
                    lit.span(),
                    format!("the track has {n} links; link {last} does not exist"),
                );
                continue;
            }
            let step = step.unwrap_or(1);
            if step == 0 {
                self.errors.at(
                    range.step.as_ref().map_or(sel.span, |s| s.span()),
                    "the step must be at least 1",
                );
                continue;
            }
            out.extend((start..=last).step_by(step).map(|i| i - 1));
        }
        out
    }

    /// `a..=b` with `b < a`, or `a..b` with `b ≤ a`: most likely a typo,
    /// which would otherwise change nothing without a word.
    pub(super) fn empty_range(&mut self, range: &IndexRange, equal: bool) {
        let Some((inclusive, end)) = &range.end else {
            return;
        };
        let start = &range.start;
        let (a, b) = (start.base10_digits(), end.base10_digits());
        let (dots, text) = if *inclusive {
            (quote!(..=), format!("{a}..={b}"))
        } else {
            (quote!(..), format!("{a}..{b}"))
        };
        let message = if equal {
            format!(
                "empty range `{text}`: it stops before link {b}, so it selects no link; \
                 `[{a}]` selects link {a}"
            )
        } else {
            format!("empty range `{text}`: it selects no link; write the lower link first")
        };
        self.errors.spanned(quote!(#start #dots #end), message);
    }
}
