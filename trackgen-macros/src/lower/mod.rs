//! Validation: the syntax tree becomes the [IR](crate::ir), and every
//! problem is reported, each at the token that causes it, all at once.
//!
//! By concern: [`keys`] reads a block's keys and numbers (shared), [`track`]
//! a track and its links, [`vehicle`] a vehicle's chassis, parts and what
//! makes it run, and [`tree`] lowers both to the trees the generator works
//! on.

use std::collections::BTreeMap;
use std::rc::Rc;

use proc_macro2::Span;
use quote::ToTokens;
use syn::Ident;

mod engine;
mod keys;
mod powertrain;
mod running;
mod sections;
mod track;
mod tracks;
mod tree;
mod vehicle;

use crate::ir::{ConstCheck, Item, ItemKind, Model};
use crate::num::ConstPool;
use crate::parse::{Input, ItemAst};

/// The most links a track may have: beyond this the unrolled code stops
/// being a good trade (docs/performance.md, compile times).
pub const MAX_LINKS: usize = 1024;

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

/// Lowers a parsed input. On error, also returns the items as far as they
/// lowered, so stubs can be emitted for everything they would generate.
pub fn lower(input: Input) -> Result<Model, (syn::Error, Vec<Item>)> {
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
        Err(e) => Err((e, items)),
    }
}

fn lower_item(ast: ItemAst, errors: &mut Errors) -> Item {
    let mut cx = Lowering {
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

/// The lowering of one item: where its errors go, the compile-time checks
/// of the constant expressions it could not evaluate, and its named
/// constants.
pub(crate) struct Lowering<'e> {
    pub(crate) errors: &'e mut Errors,
    pub(crate) checks: Vec<ConstCheck>,
    /// The item's named constants.
    pub(crate) pool: Rc<ConstPool>,
}
