//! Reading a block's keys: unknown, duplicate and missing keys, numbers
//! (folded or named constants), bounds, points and integers. Shared by
//! tracks and vehicles.

use std::collections::BTreeMap;
use std::rc::Rc;
use std::str::FromStr;

use proc_macro2::Span;
use quote::{ToTokens, quote, quote_spanned};
use syn::spanned::Spanned;
use syn::{BinOp, Expr, Lit, LitInt, UnOp};

use super::Lowering;
use crate::ir::ConstCheck;
use crate::num::{ConstPool, Num, Vec2};
use crate::parse::{Block, Entry};

#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Bound {
    Positive,
    NonNegative,
}

/// The fields of one block by key, after unknown and duplicate keys were
/// reported.
pub(super) struct Fields<'a> {
    pub(super) what: &'static str,
    pub(super) span: Span,
    pub(super) map: BTreeMap<String, &'a Expr>,
}

impl Lowering<'_> {
    pub(super) fn fields<'a>(
        &mut self,
        what: &'static str,
        block: &'a Block,
        allowed: &[&str],
    ) -> Fields<'a> {
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

    pub(super) fn sections<'a>(
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

    pub(super) fn missing(&mut self, fields: &Fields, key: &str) {
        self.errors.at(
            fields.span,
            format!("missing key `{key}` in {}", fields.what),
        );
    }

    /// A required or optional number.
    pub(super) fn number(&mut self, fields: &Fields, key: &str, required: bool) -> Option<Num> {
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
    pub(super) fn positive(&mut self, fields: &Fields, key: &str, required: bool) -> Option<Num> {
        self.bounded(fields, key, required, Bound::Positive)
    }

    /// A non-negative, finite number (damping).
    pub(super) fn non_negative(&mut self, fields: &Fields, key: &str) -> Option<Num> {
        self.bounded(fields, key, true, Bound::NonNegative)
    }

    /// A number with a lower bound, checked here when the macro can
    /// evaluate it and by a compile-time assertion otherwise.
    pub(super) fn bounded(
        &mut self,
        fields: &Fields,
        key: &str,
        required: bool,
        bound: Bound,
    ) -> Option<Num> {
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

    pub(super) fn point(&mut self, fields: &Fields, key: &str, required: bool) -> Option<Vec2> {
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
    pub(super) fn eval(&mut self, expr: &Expr, key: &str) -> Result<Num, ()> {
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

    pub(super) fn eval_point(&mut self, expr: &Expr, key: &str) -> Result<Vec2, ()> {
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

    /// The value of an integer literal for a field of type `ty`: `Ok(None)`
    /// if it does not fit (the caller reports that against the field's own
    /// bound), `Err(())` after reporting a suffix other than `ty`'s (as
    /// `f64` fields refuse theirs).
    pub(super) fn integer<T: FromStr>(&mut self, lit: &LitInt, ty: &str) -> Result<Option<T>, ()> {
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

pub(super) fn strip(expr: &Expr) -> &Expr {
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
