//! Code generation: thin, from the validated [IR](crate::ir).
//!
//! Generated code names runtime items only through
//! `::trackgen::__private`, never a bare `nalgebra::`, so a user needs
//! nothing but the `trackgen` dependency.

mod articulated;
mod chassis;
mod chassis_type;
mod lin;
mod linear_time;
mod per_link;
mod recovery;
mod recursive;
mod running;
mod runtime_path;
mod scopes;
mod spatial;
mod stub;
mod track;
mod tree;

use proc_macro2::TokenStream;
use quote::quote;

use crate::ir::{Item, ItemKind, Model};

pub use stub::stubs;

/// All items one invocation generates.
pub fn generate(model: &Model) -> TokenStream {
    model.items.iter().map(item).collect()
}

fn item(item: &Item) -> TokenStream {
    let checks = item.checks.iter().map(|c| {
        let (cond, msg) = (&c.condition, &c.message);
        quote::quote_spanned! {c.span=> const _: () = ::core::assert!(#cond, #msg); }
    });
    let checks: TokenStream = checks.collect();
    let body = match &item.kind {
        ItemKind::Track(t) => track::track(item, t),
        ItemKind::Vehicle(v) => chassis::vehicle(item, v),
    };
    // After the body and the checks: it holds the constants they use.
    let consts = item.consts.definitions();
    quote! { #consts #checks #body }
}
