//! Compile-time numbers: a declared value is either known to the macro (a
//! literal, or arithmetic on literals) or an arbitrary constant expression
//! (a named `const`, say) that only rustc can evaluate.
//!
//! Arithmetic on two known values is folded here, so the generated code
//! shows the number; anything involving an unknown value is emitted inside
//! an inline `const { … }` block, so rustc folds it at compile time all the
//! same.

use std::ops::{Add, Mul, Neg, Sub};

use proc_macro2::{Literal, Span, TokenStream};
use quote::{ToTokens, quote, quote_spanned};

/// A compile-time `f64`.
#[derive(Clone, Debug)]
pub enum Num {
    /// Evaluated by the macro.
    Known(f64),
    /// A constant expression for rustc to evaluate (raw tokens, no `const`
    /// block yet).
    Expr(TokenStream),
}

impl Num {
    pub const ZERO: Num = Num::Known(0.0);

    pub fn known(&self) -> Option<f64> {
        match self {
            Num::Known(v) => Some(*v),
            Num::Expr(_) => None,
        }
    }

    pub fn is_zero(&self) -> bool {
        self.known() == Some(0.0)
    }

    /// The expression as it can stand inside another constant expression.
    fn raw(&self) -> TokenStream {
        match self {
            Num::Known(v) => literal(*v),
            Num::Expr(t) => quote!((#t)),
        }
    }

    fn combine(self, rhs: Num, fold: fn(f64, f64) -> f64, op: TokenStream) -> Num {
        match (&self, &rhs) {
            (Num::Known(a), Num::Known(b)) => Num::Known(fold(*a, *b)),
            _ => {
                let (a, b) = (self.raw(), rhs.raw());
                Num::Expr(quote!(#a #op #b))
            }
        }
    }
}

/// An `f64` literal that reads back to exactly `v`.
pub fn literal(v: f64) -> TokenStream {
    let lit = Literal::f64_unsuffixed(v.abs());
    if v.is_sign_negative() {
        quote!(-#lit)
    } else {
        quote!(#lit)
    }
}

impl ToTokens for Num {
    fn to_tokens(&self, tokens: &mut TokenStream) {
        match self {
            Num::Known(v) => literal(*v).to_tokens(tokens),
            // Parenthesised: a bare `const { … }` would start a statement.
            Num::Expr(t) => quote_spanned!(Span::mixed_site()=> (const { #t })).to_tokens(tokens),
        }
    }
}

impl Add for Num {
    type Output = Num;
    fn add(self, rhs: Num) -> Num {
        if self.is_zero() {
            return rhs;
        }
        if rhs.is_zero() {
            return self;
        }
        self.combine(rhs, |a, b| a + b, quote!(+))
    }
}

impl Sub for Num {
    type Output = Num;
    fn sub(self, rhs: Num) -> Num {
        if rhs.is_zero() {
            return self;
        }
        self.combine(rhs, |a, b| a - b, quote!(-))
    }
}

impl Mul for Num {
    type Output = Num;
    fn mul(self, rhs: Num) -> Num {
        if self.is_zero() || rhs.is_zero() {
            return Num::ZERO;
        }
        self.combine(rhs, |a, b| a * b, quote!(*))
    }
}

impl Neg for Num {
    type Output = Num;
    fn neg(self) -> Num {
        match self {
            Num::Known(v) => Num::Known(-v),
            Num::Expr(t) => Num::Expr(quote!(-(#t))),
        }
    }
}

/// A constant planar vector.
#[derive(Clone, Debug)]
pub struct Vec2 {
    pub x: Num,
    pub y: Num,
}

impl Vec2 {
    pub fn zero() -> Vec2 {
        Vec2 {
            x: Num::ZERO,
            y: Num::ZERO,
        }
    }

    pub fn is_zero(&self) -> bool {
        self.x.is_zero() && self.y.is_zero()
    }

    pub fn scale(&self, k: &Num) -> Vec2 {
        Vec2 {
            x: self.x.clone() * k.clone(),
            y: self.y.clone() * k.clone(),
        }
    }

    pub fn dot(&self, other: &Vec2) -> Num {
        self.x.clone() * other.x.clone() + self.y.clone() * other.y.clone()
    }

    pub fn norm_squared(&self) -> Num {
        self.dot(self)
    }
}

impl Add for Vec2 {
    type Output = Vec2;
    fn add(self, rhs: Vec2) -> Vec2 {
        Vec2 {
            x: self.x + rhs.x,
            y: self.y + rhs.y,
        }
    }
}

impl Sub for Vec2 {
    type Output = Vec2;
    fn sub(self, rhs: Vec2) -> Vec2 {
        Vec2 {
            x: self.x - rhs.x,
            y: self.y - rhs.y,
        }
    }
}

impl Neg for Vec2 {
    type Output = Vec2;
    fn neg(self) -> Vec2 {
        Vec2 {
            x: -self.x,
            y: -self.y,
        }
    }
}

impl std::ops::Div for Num {
    type Output = Num;
    fn div(self, rhs: Num) -> Num {
        self.combine(rhs, |a, b| a / b, quote!(/))
    }
}
