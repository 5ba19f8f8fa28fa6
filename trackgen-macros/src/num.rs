//! Compile-time numbers: a declared value is either known to the macro (a
//! literal, or arithmetic on literals) or an arbitrary constant expression
//! (a named `const`, say) that only rustc can evaluate.
//!
//! Arithmetic on two known values is folded here, so the generated code
//! shows the number. Every constant expression the user wrote, and every
//! operation on one, is a named constant of the item's [`ConstPool`],
//! emitted once as `const __TRACKGEN_<k>: f64 = …;` in an inherent impl of
//! the item's type and referred to by name wherever it is used. A constant
//! expression is therefore type-checked and evaluated once, however many
//! places use it, and a derived value (a subtree mass `m₁ + … + mₙ`) is a
//! chain of one-operation constants, not an expression that grows with the
//! number of links: both the generated code and the error path stay linear
//! in the number of links.

use std::cell::RefCell;
use std::collections::HashMap;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};
use std::rc::Rc;

use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::{ToTokens, format_ident, quote, quote_spanned};

/// A compile-time `f64`.
#[derive(Clone, Debug)]
pub enum Num {
    /// Evaluated by the macro.
    Known(f64),
    /// A named constant for rustc to evaluate.
    Expr(Sym),
}

/// A named constant of a [`ConstPool`]: `Owner::__TRACKGEN_<id>`.
#[derive(Clone)]
pub struct Sym {
    pool: Rc<ConstPool>,
    id: usize,
}

impl fmt::Debug for Sym {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}::__TRACKGEN_{}", self.pool.owner, self.id)
    }
}

/// An operand of a memoised operation: a known value (by its bits) or a
/// constant (by pool and id).
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
enum Operand {
    Known(u64),
    Sym(usize, usize),
}

impl Operand {
    fn of(n: &Num) -> Operand {
        match n {
            Num::Known(v) => Operand::Known(v.to_bits()),
            Num::Expr(s) => Operand::Sym(Rc::as_ptr(&s.pool) as usize, s.id),
        }
    }
}

/// A constant's definition, and the constants of the same pool it uses.
struct Def {
    value: TokenStream,
    deps: Vec<usize>,
}

/// The named constants of one declared item, on the item's type `owner`.
pub struct ConstPool {
    owner: Ident,
    defs: RefCell<Vec<Def>>,
    /// Operations already named: `(op, a, b)` → id (`b` unused for the
    /// negation, `'n'`).
    memo: RefCell<HashMap<(char, Operand, Operand), usize>>,
    /// Whether generated code refers to the constant: only those, and
    /// what they use, are emitted.
    used: RefCell<Vec<bool>>,
}

impl ConstPool {
    /// An empty pool for the item whose type is `owner`.
    pub fn new(owner: &Ident) -> Rc<ConstPool> {
        Rc::new(ConstPool {
            owner: owner.clone(),
            defs: RefCell::new(Vec::new()),
            memo: RefCell::new(HashMap::new()),
            used: RefCell::new(Vec::new()),
        })
    }

    fn define(self: &Rc<Self>, value: TokenStream, deps: Vec<usize>) -> Sym {
        let mut defs = self.defs.borrow_mut();
        defs.push(Def { value, deps });
        self.used.borrow_mut().push(false);
        Sym {
            pool: Rc::clone(self),
            id: defs.len() - 1,
        }
    }

    /// A constant expression as the user wrote it (its tokens keep their
    /// spans, so rustc's errors point at them): one constant.
    pub fn user(self: &Rc<Self>, expr: TokenStream) -> Num {
        Num::Expr(self.define(expr, Vec::new()))
    }

    /// `a op b` (or `-a`, `op == 'n'`, `b` absent) as a constant, the same
    /// constant each time it is asked for.
    fn operation(self: &Rc<Self>, op: char, a: &Num, b: Option<&Num>) -> Num {
        let (x, y) = (Operand::of(a), b.map_or(Operand::Known(0), Operand::of));
        // `a + b` and `b + a` are the same number (IEEE addition and
        // multiplication commute exactly): one constant.
        let key = if matches!(op, '+' | '*') && y < x {
            (op, y, x)
        } else {
            (op, x, y)
        };
        if let Some(&id) = self.memo.borrow().get(&key) {
            return Num::Expr(Sym {
                pool: Rc::clone(self),
                id,
            });
        }
        let deps = [Some(a), b]
            .into_iter()
            .flatten()
            .filter_map(|n| match n {
                Num::Expr(s) if Rc::ptr_eq(&s.pool, self) => Some(s.id),
                _ => None,
            })
            .collect();
        let (ta, tb) = (self.operand(a), b.map(|b| self.operand(b)));
        let value = match (tb, op) {
            (None, _) => quote!(-#ta),
            (Some(tb), '+') => quote!(#ta + #tb),
            (Some(tb), '-') => quote!(#ta - #tb),
            (Some(tb), '*') => quote!(#ta * #tb),
            (Some(tb), _) => quote!(#ta / #tb),
        };
        let sym = self.define(value, deps);
        let mut memo = self.memo.borrow_mut();
        memo.insert(key, sym.id);
        if let (None, Num::Expr(s)) = (b, a)
            && Rc::ptr_eq(&s.pool, self)
        {
            // `-(-a)` is `a`.
            let pool = Rc::as_ptr(self) as usize;
            memo.insert(('n', Operand::Sym(pool, sym.id), Operand::Known(0)), s.id);
        }
        Num::Expr(sym)
    }

    /// An operand inside another of this pool's definitions: naming it
    /// there does not make it used (the definition may never be).
    fn operand(&self, n: &Num) -> TokenStream {
        match n {
            Num::Expr(s) if std::ptr::eq(Rc::as_ptr(&s.pool), self) => s.path(),
            n => n.to_token_stream(),
        }
    }

    /// The used constants and what they use, in definition order (which
    /// is dependency order), as one inherent impl of the owner.
    pub fn definitions(&self) -> TokenStream {
        let defs = self.defs.borrow();
        let mut keep = self.used.borrow().clone();
        for id in (0..defs.len()).rev() {
            if keep[id] {
                for &d in &defs[id].deps {
                    keep[d] = true;
                }
            }
        }
        let consts: Vec<TokenStream> = defs
            .iter()
            .enumerate()
            .filter(|(id, _)| keep[*id])
            .map(|(id, def)| {
                let name = const_name(id);
                let value = &def.value;
                quote! { const #name: f64 = #value; }
            })
            .collect();
        if consts.is_empty() {
            return TokenStream::new();
        }
        let owner = &self.owner;
        quote! {
            #[doc(hidden)]
            #[allow(dead_code, clippy::all, clippy::pedantic)]
            impl #owner {
                #(#consts)*
            }
        }
    }
}

fn const_name(id: usize) -> Ident {
    format_ident!("__TRACKGEN_{}", id)
}

impl Sym {
    /// `Owner::__TRACKGEN_<id>`.
    fn path(&self) -> TokenStream {
        let (owner, name) = (&self.pool.owner, const_name(self.id));
        quote!(#owner::#name)
    }
}

/// Generated code that names the constant uses it: it is emitted.
impl ToTokens for Sym {
    fn to_tokens(&self, tokens: &mut TokenStream) {
        self.pool.used.borrow_mut()[self.id] = true;
        self.path().to_tokens(tokens);
    }
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

    /// Whether two numbers are the same constant: the same value, or the
    /// same named constant.
    pub fn same(&self, other: &Num) -> bool {
        Operand::of(self) == Operand::of(other)
    }

    fn combine(self, rhs: Num, fold: fn(f64, f64) -> f64, op: char) -> Num {
        match (&self, &rhs) {
            (Num::Known(a), Num::Known(b)) => Num::Known(fold(*a, *b)),
            (Num::Expr(s), _) | (_, Num::Expr(s)) => {
                let pool = Rc::clone(&s.pool);
                pool.operation(op, &self, Some(&rhs))
            }
        }
    }
}

/// An `f64` literal that reads back to exactly `v` (`f64::INFINITY` and
/// `f64::NAN` for the values no literal spells: a sum of huge masses can
/// overflow).
pub fn literal(v: f64) -> TokenStream {
    let span = Span::mixed_site();
    let magnitude = if v.is_nan() {
        return quote_spanned!(span=> f64::NAN);
    } else if v.is_infinite() {
        quote_spanned!(span=> f64::INFINITY)
    } else {
        Literal::f64_unsuffixed(v.abs()).into_token_stream()
    };
    if v.is_sign_negative() {
        quote!(-#magnitude)
    } else {
        magnitude
    }
}

impl ToTokens for Num {
    fn to_tokens(&self, tokens: &mut TokenStream) {
        match self {
            Num::Known(v) => literal(*v).to_tokens(tokens),
            Num::Expr(s) => s.to_tokens(tokens),
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
        self.combine(rhs, |a, b| a + b, '+')
    }
}

impl Sub for Num {
    type Output = Num;
    fn sub(self, rhs: Num) -> Num {
        if rhs.is_zero() {
            return self;
        }
        self.combine(rhs, |a, b| a - b, '-')
    }
}

impl Mul for Num {
    type Output = Num;
    fn mul(self, rhs: Num) -> Num {
        if self.is_zero() || rhs.is_zero() {
            return Num::ZERO;
        }
        // Exact in IEEE arithmetic: `1 x = x`, `−1 x = −x`.
        match (self.known(), rhs.known()) {
            (Some(1.0), _) => rhs,
            (_, Some(1.0)) => self,
            (Some(-1.0), _) => -rhs,
            (_, Some(-1.0)) => -self,
            _ => self.combine(rhs, |a, b| a * b, '*'),
        }
    }
}

impl Div for Num {
    type Output = Num;
    fn div(self, rhs: Num) -> Num {
        match rhs.known() {
            Some(1.0) => self,
            Some(-1.0) => -self,
            _ => self.combine(rhs, |a, b| a / b, '/'),
        }
    }
}

impl Neg for Num {
    type Output = Num;
    fn neg(self) -> Num {
        match &self {
            Num::Known(v) => Num::Known(-v),
            Num::Expr(s) => {
                let pool = Rc::clone(&s.pool);
                pool.operation('n', &self, None)
            }
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
