//! Linear combinations `Σ cᵢ xᵢ` of run-time values `xᵢ` with compile-time
//! coefficients `cᵢ`: the shape of almost every generated statement. Zero
//! coefficients drop out, unit coefficients vanish, so the generated code
//! does exactly the arithmetic the constants leave.

use proc_macro2::{Ident, TokenStream};
use quote::{format_ident, quote};

use crate::num::{Num, Vec2};

/// `Σ coef · var`; an empty `var` stands for the constant 1.
#[derive(Clone, Default)]
pub struct Lin {
    terms: Vec<(Num, TokenStream)>,
}

impl Lin {
    pub fn zero() -> Lin {
        Lin::default()
    }

    /// A run-time value, with coefficient 1.
    pub fn var(var: TokenStream) -> Lin {
        Lin {
            terms: vec![(Num::Known(1.0), var)],
        }
    }

    /// A compile-time constant.
    pub fn constant(c: Num) -> Lin {
        Lin::term(c, TokenStream::new())
    }

    pub fn term(coef: Num, var: TokenStream) -> Lin {
        let mut lin = Lin::zero();
        lin.push(coef, var);
        lin
    }

    fn push(&mut self, coef: Num, var: TokenStream) {
        if !coef.is_zero() {
            self.terms.push((coef, var));
        }
    }

    pub fn plus(mut self, other: Lin) -> Lin {
        for (c, v) in other.terms {
            self.push(c, v);
        }
        self
    }

    pub fn minus(self, other: Lin) -> Lin {
        self.plus(other.scaled(&Num::Known(-1.0)))
    }

    pub fn scaled(self, k: &Num) -> Lin {
        let mut out = Lin::zero();
        for (c, v) in self.terms {
            out.push(c * k.clone(), v);
        }
        out
    }

    /// Every term multiplied by the run-time value `factor`.
    pub fn times(self, factor: &TokenStream) -> Lin {
        Lin {
            terms: self
                .terms
                .into_iter()
                .map(|(c, v)| {
                    if v.is_empty() {
                        (c, factor.clone())
                    } else {
                        (c, quote!(#v * #factor))
                    }
                })
                .collect(),
        }
    }

    pub fn tokens(&self) -> TokenStream {
        let mut out = TokenStream::new();
        for (i, (coef, var)) in self.terms.iter().enumerate() {
            let negative = coef.known().is_some_and(|c| c.is_sign_negative());
            let magnitude = if negative {
                -coef.clone()
            } else {
                coef.clone()
            };
            let body = match (magnitude.known(), var.is_empty()) {
                (_, true) => quote!(#magnitude),
                (Some(1.0), false) => var.clone(),
                _ => quote!(#magnitude * #var),
            };
            out.extend(match (i, negative) {
                (0, false) => body,
                (0, true) => quote!(-#body),
                (_, false) => quote!(+ #body),
                (_, true) => quote!(- #body),
            });
        }
        if out.is_empty() { quote!(0.0) } else { out }
    }
}

/// The planar vector `(x, y)` as two linear combinations.
#[derive(Clone, Default)]
pub struct LinVec {
    pub x: Lin,
    pub y: Lin,
}

impl LinVec {
    pub fn zero() -> LinVec {
        LinVec::default()
    }

    /// The run-time vector held in the locals `{prefix}x_{tag}`,
    /// `{prefix}y_{tag}`.
    pub fn vars(names: &(Ident, Ident)) -> LinVec {
        let (x, y) = names;
        LinVec {
            x: Lin::var(quote!(#x)),
            y: Lin::var(quote!(#y)),
        }
    }

    pub fn constant(v: &Vec2) -> LinVec {
        LinVec {
            x: Lin::constant(v.x.clone()),
            y: Lin::constant(v.y.clone()),
        }
    }

    pub fn plus(self, o: LinVec) -> LinVec {
        LinVec {
            x: self.x.plus(o.x),
            y: self.y.plus(o.y),
        }
    }

    pub fn minus(self, o: LinVec) -> LinVec {
        LinVec {
            x: self.x.minus(o.x),
            y: self.y.minus(o.y),
        }
    }

    pub fn scaled(self, k: &Num) -> LinVec {
        LinVec {
            x: self.x.scaled(k),
            y: self.y.scaled(k),
        }
    }

    pub fn times(self, factor: &TokenStream) -> LinVec {
        LinVec {
            x: self.x.times(factor),
            y: self.y.times(factor),
        }
    }

    /// `let px_tag = …; let py_tag = …;`
    pub fn bind(&self, names: &(Ident, Ident)) -> TokenStream {
        let (nx, ny) = names;
        let (x, y) = (self.x.tokens(), self.y.tokens());
        quote! { let #nx = #x; let #ny = #y; }
    }
}

/// The sine and cosine locals of a body's angle.
#[derive(Clone)]
pub struct Trig {
    pub s: Ident,
    pub c: Ident,
}

impl Trig {
    pub fn new(tag: &str) -> Trig {
        Trig {
            s: format_ident!("s_{}", tag),
            c: format_ident!("c_{}", tag),
        }
    }

    /// `A(θ) v` (formulation §0).
    pub fn rotate(&self, v: &Vec2) -> LinVec {
        let (s, c) = (&self.s, &self.c);
        LinVec {
            x: Lin::term(v.x.clone(), quote!(#c)).plus(Lin::term(-v.y.clone(), quote!(#s))),
            y: Lin::term(v.x.clone(), quote!(#s)).plus(Lin::term(v.y.clone(), quote!(#c))),
        }
    }

    /// `A_θ(θ) v = dA/dθ v` (formulation §0).
    pub fn rotate_derivative(&self, v: &Vec2) -> LinVec {
        let (s, c) = (&self.s, &self.c);
        LinVec {
            x: Lin::term(-v.x.clone(), quote!(#s)).plus(Lin::term(-v.y.clone(), quote!(#c))),
            y: Lin::term(v.x.clone(), quote!(#c)).plus(Lin::term(-v.y.clone(), quote!(#s))),
        }
    }
}

/// The pair of locals `{prefix}x_{tag}`, `{prefix}y_{tag}`.
pub fn pair(prefix: &str, tag: &str) -> (Ident, Ident) {
    (
        format_ident!("{}x_{}", prefix, tag),
        format_ident!("{}y_{}", prefix, tag),
    )
}
