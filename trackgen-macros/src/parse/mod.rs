//! The syntax of a declaration, parsed with every span kept and nothing
//! checked beyond the shape of the tokens. Meaning is given by
//! [`crate::lower`].
//!
//! ```text
//! input    := item*
//! item     := attr* vis ("track" | "vehicle") Ident block
//! block    := "{" (entry ","?)* "}"
//! entry    := Ident ":" Expr                        // a field
//!           | Ident selector? Ident? count? block    // a section
//! count    := "[" Int "]"                           // repeated parts
//! selector := "[" range ("," range)* "]"
//! range    := Int (("..=" | "..") Int ("by" Int)?)?
//! ```

use proc_macro2::Span;
use syn::parse::{Parse, ParseStream};
use syn::punctuated::Punctuated;
use syn::{Attribute, Expr, Ident, LitInt, Token, Visibility, braced, bracketed};

mod kw {
    syn::custom_keyword!(by);
}

/// Everything inside `model! { … }`.
pub struct Input {
    pub items: Vec<ItemAst>,
}

/// `pub track Name { … }` or `pub vehicle Name { … }`.
pub struct ItemAst {
    pub attrs: Vec<Attribute>,
    pub vis: Visibility,
    pub kind: Ident,
    pub name: Ident,
    pub body: Block,
}

/// `{ entries }`.
pub struct Block {
    pub span: Span,
    pub entries: Vec<Entry>,
}

/// One entry of a block.
pub enum Entry {
    /// `key: value`.
    Field { key: Ident, value: Expr },
    /// `kind[selector] name[count] { … }`.
    Section {
        kind: Ident,
        selector: Option<Selector>,
        name: Option<Ident>,
        /// `[n]` after the name: `n` parts declared by one block.
        count: Option<LitInt>,
        body: Block,
    },
}

/// `[1, 3..=9 by 2]`: 1-based indices.
pub struct Selector {
    pub span: Span,
    pub ranges: Vec<IndexRange>,
}

/// `a`, `a..b`, `a..=b`, optionally `by step`.
pub struct IndexRange {
    pub start: LitInt,
    pub end: Option<(bool, LitInt)>,
    pub step: Option<LitInt>,
}

impl Parse for Input {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let mut items = Vec::new();
        while !input.is_empty() {
            items.push(input.parse()?);
        }
        Ok(Input { items })
    }
}

impl Parse for ItemAst {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let attrs = input.call(Attribute::parse_outer)?;
        let vis = input.parse()?;
        let kind: Ident = input.parse()?;
        if kind != "track" && kind != "vehicle" {
            return Err(syn::Error::new(
                kind.span(),
                "expected `track` or `vehicle`",
            ));
        }
        let name = input.parse()?;
        let body = input.parse()?;
        Ok(ItemAst {
            attrs,
            vis,
            kind,
            name,
            body,
        })
    }
}

impl Parse for Block {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let content;
        let brace = braced!(content in input);
        let mut entries = Vec::new();
        while !content.is_empty() {
            entries.push(content.parse()?);
            if !content.is_empty() {
                let is_section = matches!(entries.last(), Some(Entry::Section { .. }));
                if is_section {
                    let _: Option<Token![,]> = content.parse()?;
                } else {
                    content.parse::<Token![,]>()?;
                }
            }
        }
        Ok(Block {
            span: brace.span.join(),
            entries,
        })
    }
}

impl Parse for Entry {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let head: Ident = input.parse()?;
        if input.peek(Token![:]) && !input.peek(Token![::]) {
            input.parse::<Token![:]>()?;
            return Ok(Entry::Field {
                key: head,
                value: input.parse()?,
            });
        }
        let selector = if input.peek(syn::token::Bracket) {
            Some(input.parse()?)
        } else {
            None
        };
        let name = if input.peek(Ident) {
            Some(input.parse()?)
        } else {
            None
        };
        let count = if name.is_some() && input.peek(syn::token::Bracket) {
            let content;
            bracketed!(content in input);
            let count: LitInt = content.parse()?;
            if !content.is_empty() {
                return Err(content.error("expected one count of parts, e.g. `rw[5]`"));
            }
            Some(count)
        } else {
            None
        };
        if !input.peek(syn::token::Brace) {
            return Err(input.error(format!("expected `:` or `{{ … }}` after `{head}`")));
        }
        Ok(Entry::Section {
            kind: head,
            selector,
            name,
            count,
            body: input.parse()?,
        })
    }
}

impl Parse for Selector {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let content;
        let bracket = bracketed!(content in input);
        let ranges = Punctuated::<IndexRange, Token![,]>::parse_terminated(&content)?;
        if ranges.is_empty() {
            return Err(syn::Error::new(
                bracket.span.join(),
                "expected link numbers, e.g. `[3]` or `[2..=64 by 2]`",
            ));
        }
        Ok(Selector {
            span: bracket.span.join(),
            ranges: ranges.into_iter().collect(),
        })
    }
}

impl Parse for IndexRange {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let start = input.parse()?;
        let end = if input.peek(Token![..=]) {
            input.parse::<Token![..=]>()?;
            Some((true, input.parse()?))
        } else if input.peek(Token![..]) {
            input.parse::<Token![..]>()?;
            Some((false, input.parse()?))
        } else {
            None
        };
        let step = if end.is_some() && input.peek(kw::by) {
            input.parse::<kw::by>()?;
            Some(input.parse()?)
        } else {
            None
        };
        Ok(IndexRange { start, end, step })
    }
}
