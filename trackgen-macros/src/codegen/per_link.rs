//! Constants of every link of a track, folded into generated code: one
//! shared by every link is a number (and a zero drops its terms), one that
//! differs between links a table the generated loop reads.

use proc_macro2::{Ident, TokenStream};
use quote::{format_ident, quote};

use super::lin::Lin;
use crate::num::Num;

/// A constant of every link: one value, folded into the code, or a table
/// indexed at run time.
pub enum PerLink {
    Uniform(Num),
    Table { name: Ident, values: Vec<Num> },
}

impl PerLink {
    pub fn new(name: &str, values: Vec<Num>) -> PerLink {
        if values.iter().all(|v| v.same(&values[0])) {
            PerLink::Uniform(values[0].clone())
        } else {
            PerLink::Table {
                name: format_ident!("{}", name),
                values,
            }
        }
    }

    /// The value for the link at `index` (an expression of type `usize`).
    pub fn at(&self, index: TokenStream) -> Lin {
        match self {
            PerLink::Uniform(v) => Lin::constant(v.clone()),
            PerLink::Table { name, .. } => Lin::var(quote!(#name[#index])),
        }
    }

    /// `const NAME: [f64; n] = [...];` for a table.
    pub fn declaration(&self) -> TokenStream {
        match self {
            PerLink::Uniform(_) => TokenStream::new(),
            PerLink::Table { name, values } => {
                let n = values.len();
                quote! { const #name: [f64; #n] = [#(#values),*]; }
            }
        }
    }
}

/// A linear combination as a parenthesised expression.
pub fn expr(lin: Lin) -> TokenStream {
    let t = lin.tokens();
    quote!((#t))
}
