//! Validation: the syntax tree becomes the [IR](crate::ir), and every
//! problem is reported, each at the token that causes it, all at once.

use std::collections::BTreeMap;
use std::rc::Rc;
use std::str::FromStr;

use proc_macro2::Span;
use quote::{ToTokens, quote, quote_spanned};
use syn::spanned::Spanned;
use syn::{BinOp, Expr, Ident, Lit, LitInt, Member, UnOp};

mod vehicle;

use crate::ir::{Closure, ConstCheck, Item, ItemKind, Link, Model, Track};
use crate::num::{ConstPool, Num, Vec2};
use crate::parse::{Block, Entry, IndexRange, Input, ItemAst, Selector};

/// The most links a track may have: beyond this the unrolled code stops
/// being a good trade (see README, compile times).
pub const MAX_LINKS: usize = 1024;

#[derive(Clone, Copy, PartialEq, Eq)]
enum Bound {
    Positive,
    NonNegative,
}

/// Collects errors, like serde_derive's `Ctxt`.
#[derive(Default)]
pub struct Errors {
    first: Option<syn::Error>,
}

impl Errors {
    pub fn push(&mut self, error: syn::Error) {
        match &mut self.first {
            Some(first) => first.combine(error),
            None => self.first = Some(error),
        }
    }

    pub fn at(&mut self, span: Span, message: impl std::fmt::Display) {
        self.push(syn::Error::new(span, message));
    }

    /// An error covering all of `tokens` (first to last token).
    pub fn spanned(&mut self, tokens: impl ToTokens, message: impl std::fmt::Display) {
        self.push(syn::Error::new_spanned(tokens, message));
    }

    pub fn finish(self) -> Result<(), syn::Error> {
        self.first.map_or(Ok(()), Err)
    }
}

/// Lowers a parsed input. On error, also returns the names that did parse,
/// so stubs can be emitted for them.
pub fn lower(input: Input) -> Result<Model, (syn::Error, Vec<(syn::Visibility, Ident)>)> {
    let mut errors = Errors::default();
    let mut items = Vec::new();
    let mut names: BTreeMap<String, Ident> = BTreeMap::new();
    for ast in input.items {
        if let Some(prev) = names.insert(ast.name.to_string(), ast.name.clone()) {
            errors.at(ast.name.span(), format!("`{prev}` is declared twice"));
        }
        items.push(lower_item(ast, &mut errors));
    }
    match errors.finish() {
        Ok(()) => Ok(Model { items }),
        Err(e) => Err((e, items.into_iter().map(|i| (i.vis, i.name)).collect())),
    }
}

fn lower_item(ast: ItemAst, errors: &mut Errors) -> Item {
    let mut cx = Cx {
        errors,
        checks: Vec::new(),
        pool: ConstPool::new(&ast.name),
    };
    let kind = if ast.kind == "track" {
        ItemKind::Track(cx.track(&ast.body, true))
    } else {
        ItemKind::Vehicle(Box::new(cx.vehicle(&ast.body, &ast.name)))
    };
    Item {
        attrs: ast.attrs,
        vis: ast.vis,
        name: ast.name,
        kind,
        checks: cx.checks,
        consts: cx.pool,
    }
}

struct Cx<'e> {
    errors: &'e mut Errors,
    checks: Vec<ConstCheck>,
    /// The item's named constants.
    pool: Rc<ConstPool>,
}

/// The fields of one block by key, after unknown and duplicate keys were
/// reported.
struct Fields<'a> {
    what: &'static str,
    span: Span,
    map: BTreeMap<String, &'a Expr>,
}

const DEFAULT_GRAVITY: f64 = -9.81;

impl Cx<'_> {
    fn fields<'a>(&mut self, what: &'static str, block: &'a Block, allowed: &[&str]) -> Fields<'a> {
        let mut map = BTreeMap::new();
        for entry in &block.entries {
            if let Entry::Field { key, value } = entry {
                let name = key.to_string();
                if !allowed.contains(&name.as_str()) {
                    self.errors.at(
                        key.span(),
                        format!(
                            "unknown key `{name}` in {what}; expected one of: {}",
                            allowed.join(", ")
                        ),
                    );
                } else if map.insert(name.clone(), value).is_some() {
                    self.errors
                        .at(key.span(), format!("duplicate key `{name}` in {what}"));
                }
            }
        }
        Fields {
            what,
            span: block.span,
            map,
        }
    }

    fn sections<'a>(
        &mut self,
        what: &'static str,
        block: &'a Block,
        allowed: &[&str],
    ) -> Vec<&'a Entry> {
        let mut out = Vec::new();
        for entry in &block.entries {
            if let Entry::Section { kind, .. } = entry {
                if allowed.contains(&kind.to_string().as_str()) {
                    out.push(entry);
                } else if allowed.is_empty() {
                    self.errors.at(
                        kind.span(),
                        format!("unexpected section `{kind}` in {what}"),
                    );
                } else {
                    self.errors.at(
                        kind.span(),
                        format!(
                            "unknown section `{kind}` in {what}; expected one of: {}",
                            allowed.join(", ")
                        ),
                    );
                }
            }
        }
        out
    }

    fn missing(&mut self, fields: &Fields, key: &str) {
        self.errors.at(
            fields.span,
            format!("missing key `{key}` in {}", fields.what),
        );
    }

    /// A required or optional number.
    fn number(&mut self, fields: &Fields, key: &str, required: bool) -> Option<Num> {
        match fields.map.get(key) {
            Some(expr) => self.eval(expr, key).ok(),
            None => {
                if required {
                    self.missing(fields, key);
                }
                None
            }
        }
    }

    /// A strictly positive, finite number (mass, inertia, radius, stiffness).
    fn positive(&mut self, fields: &Fields, key: &str, required: bool) -> Option<Num> {
        self.bounded(fields, key, required, Bound::Positive)
    }

    /// A non-negative, finite number (damping).
    fn non_negative(&mut self, fields: &Fields, key: &str) -> Option<Num> {
        self.bounded(fields, key, true, Bound::NonNegative)
    }

    /// A number with a lower bound, checked here when the macro can
    /// evaluate it and by a compile-time assertion otherwise.
    fn bounded(&mut self, fields: &Fields, key: &str, required: bool, bound: Bound) -> Option<Num> {
        let expr = fields.map.get(key).copied();
        let value = self.number(fields, key, required)?;
        let (what, holds) = match bound {
            Bound::Positive => ("positive", quote!(> 0.0)),
            Bound::NonNegative => ("non-negative", quote!(>= 0.0)),
        };
        match &value {
            Num::Known(v) => {
                let ok = v.is_finite()
                    && if bound == Bound::Positive {
                        *v > 0.0
                    } else {
                        *v >= 0.0
                    };
                if !ok {
                    self.errors.spanned(
                        expr?,
                        format!("`{key}` must be {what} and finite, found {v}"),
                    );
                }
            }
            Num::Expr(_) => self.checks.push(ConstCheck {
                span: expr?.span(),
                condition: quote!((#value) #holds && (#value) <= f64::MAX),
                message: format!("`{key}` must be {what} and finite"),
            }),
        }
        Some(value)
    }

    fn point(&mut self, fields: &Fields, key: &str, required: bool) -> Option<Vec2> {
        match fields.map.get(key) {
            Some(expr) => self.eval_point(expr, key).ok(),
            None => {
                if required {
                    self.missing(fields, key);
                }
                None
            }
        }
    }

    /// Evaluates a number: literals and arithmetic on them are folded here,
    /// anything else that can be a constant expression is left to rustc.
    fn eval(&mut self, expr: &Expr, key: &str) -> Result<Num, ()> {
        let result = eval_number(expr, &self.pool);
        match result {
            Ok(Num::Known(v)) if !v.is_finite() => {
                self.errors
                    .spanned(expr, format!("`{key}` must be finite, found {v}"));
                Err(())
            }
            Ok(n) => Ok(n),
            Err(e) => {
                self.errors.push(e);
                Err(())
            }
        }
    }

    fn eval_point(&mut self, expr: &Expr, key: &str) -> Result<Vec2, ()> {
        match strip(expr) {
            Expr::Tuple(t) if t.elems.len() == 2 => {
                let x = self.eval(&t.elems[0], key);
                let y = self.eval(&t.elems[1], key);
                Ok(Vec2 { x: x?, y: y? })
            }
            other => {
                self.errors
                    .spanned(other, format!("`{key}` must be a point `(x, y)` in metres"));
                Err(())
            }
        }
    }

    fn gravity(&mut self, fields: &Fields) -> Vec2 {
        self.point(fields, "gravity", false).unwrap_or(Vec2 {
            x: Num::ZERO,
            y: Num::Known(DEFAULT_GRAVITY),
        })
    }

    fn track(&mut self, block: &Block, standalone: bool) -> Track {
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
        Track {
            links,
            closure,
            gravity,
        }
    }

    fn link_count(&mut self, fields: &Fields, closure: &Closure) -> Option<usize> {
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

    fn closure(&mut self, fields: &Fields) -> Closure {
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
    fn links(&mut self, sections: &[&Entry], count: Option<usize>, span: Span) -> Vec<Link> {
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

    fn check_distinct_joints(&mut self, link: &Link, which: &str, span: Span) {
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
    fn select(&mut self, sel: &Selector, n: usize) -> Vec<usize> {
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
    fn empty_range(&mut self, range: &IndexRange, equal: bool) {
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

    /// The value of an integer literal for a field of type `ty`: `Ok(None)`
    /// if it does not fit (the caller reports that against the field's own
    /// bound), `Err(())` after reporting a suffix other than `ty`'s (as
    /// `f64` fields refuse theirs).
    fn integer<T: FromStr>(&mut self, lit: &LitInt, ty: &str) -> Result<Option<T>, ()> {
        let suffix = lit.suffix();
        if !suffix.is_empty() && suffix != ty {
            self.errors
                .at(lit.span(), format!("expected a `{ty}`; remove the suffix"));
            return Err(());
        }
        // `base10_digits` is the literal's value in decimal digits (no sign,
        // no underscores, hex converted): parsing fails only on overflow.
        Ok(lit.base10_digits().parse::<T>().ok())
    }
}

fn strip(expr: &Expr) -> &Expr {
    match expr {
        Expr::Paren(p) => strip(&p.expr),
        Expr::Group(g) => strip(&g.expr),
        e => e,
    }
}

/// A number: folded when built from literals, otherwise a constant
/// expression for rustc. Rejects what cannot be an `f64` at all.
fn eval_number(expr: &Expr, pool: &Rc<ConstPool>) -> syn::Result<Num> {
    match strip(expr) {
        Expr::Lit(l) => match &l.lit {
            Lit::Float(f) if matches!(f.suffix(), "" | "f64") => {
                f.base10_parse::<f64>().map(Num::Known)
            }
            Lit::Int(i) if matches!(i.suffix(), "" | "f64") => i
                .base10_digits()
                .parse::<f64>()
                .map(Num::Known)
                .map_err(|e| syn::Error::new(i.span(), e)),
            Lit::Float(_) | Lit::Int(_) => Err(syn::Error::new(
                l.span(),
                "expected an `f64`; remove the suffix",
            )),
            _ => Err(syn::Error::new(l.span(), "expected a number")),
        },
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => Ok(-eval_number(&u.expr, pool)?),
        Expr::Binary(b) => {
            let (l, r) = (eval_number(&b.left, pool), eval_number(&b.right, pool));
            let (l, r) = match (l, r) {
                (Ok(l), Ok(r)) => (l, r),
                (Err(mut a), Err(b)) => {
                    a.combine(b);
                    return Err(a);
                }
                (Err(e), _) | (_, Err(e)) => return Err(e),
            };
            match b.op {
                BinOp::Add(_) => Ok(l + r),
                BinOp::Sub(_) => Ok(l - r),
                BinOp::Mul(_) => Ok(l * r),
                BinOp::Div(_) => Ok(l / r),
                _ => Err(syn::Error::new(
                    b.op.span(),
                    "only `+ - * /` may combine numbers",
                )),
            }
        }
        e @ (Expr::Path(_)
        | Expr::Call(_)
        | Expr::MethodCall(_)
        | Expr::Field(_)
        | Expr::Index(_)
        | Expr::Const(_)
        | Expr::Block(_)) => {
            let tokens = e.to_token_stream();
            let span = e.span();
            Ok(pool.user(quote_spanned!(span=> #tokens)))
        }
        e => Err(syn::Error::new(
            e.span(),
            "expected a number (a literal or a constant expression)",
        )),
    }
}
