//! A track: `RecursiveModel` of the chain (formulation §1) plus `TrackModel`, the
//! loop closure (formulation §2).

use proc_macro2::{Ident, TokenStream};
use quote::{format_ident, quote};
use syn::{Attribute, Visibility};

use super::lin::{LinVec, Trig};
use super::runtime_path::runtime;
use super::scopes::shallow_scopes;
use super::tree::{Penalty, Tree};
use crate::ir::{Closure, Item, Track};
use crate::num::Vec2;

/// The standalone track item.
pub fn track(item: &Item, track: &Track) -> TokenStream {
    let docs = default_docs(
        &item.attrs,
        &format!(
            "A {}-link track, compiled by `trackgen::model!`.",
            track.links.len()
        ),
    );
    track_type(&item.attrs, docs, &item.vis, &item.name, track)
}

/// Outer attributes, plus a doc line if the user gave none (generated
/// public items are documented).
pub fn default_docs(attrs: &[Attribute], doc: &str) -> TokenStream {
    if attrs.iter().any(|a| a.path().is_ident("doc")) {
        TokenStream::new()
    } else {
        quote!(#[doc = #doc])
    }
}

/// `d̄ʲ = ū2ʲ − ū1ʲ` for every link.
fn spans(track: &Track) -> Vec<Vec2> {
    track
        .links
        .iter()
        .map(|l| l.u2.clone() - l.u1.clone())
        .collect()
}

/// The chain's tree, with a penalty joint's spring if declared.
fn chain(track: &Track) -> Tree {
    let penalty = match &track.closure {
        Closure::Penalty { stiffness, damping } => Some(Penalty {
            stiffness: stiffness.clone(),
            damping: damping.clone(),
            spans: spans(track),
        }),
        _ => None,
    };
    Tree::new(track.bodies.clone(), track.gravity.clone(), penalty)
}

pub fn track_type(
    attrs: &[Attribute],
    docs: TokenStream,
    vis: &Visibility,
    name: &Ident,
    track: &Track,
) -> TokenStream {
    let rt = runtime();
    let tree = chain(track);
    let n = tree.len();
    let dof = n + 2;
    let closure = match &track.closure {
        Closure::Open => quote!(#rt::Closure::Open),
        Closure::Partitioned => quote!(#rt::Closure::Partitioned),
        Closure::Penalty { stiffness, damping } => {
            quote!(#rt::Closure::Penalty(#rt::PenaltyJoint { stiffness: #stiffness, damping: #damping }))
        }
    };
    let (first, last) = (&track.links[0].u1, &track.links[n - 1].u2);
    let (fx, fy, lx, ly) = (&first.x, &first.y, &last.x, &last.y);
    let loop_joint = quote! {
        ::core::option::Option::Some(#rt::LoopJoint {
            closure: #closure,
            first_u1: #rt::nalgebra::Vector2::new(#fx, #fy),
            last_u2: #rt::nalgebra::Vector2::new(#lx, #ly),
        })
    };
    let tree_dynamics = super::recovery::cut_dynamics(track);
    let recursive = super::recursive::recursive_impl(
        name,
        &tree,
        loop_joint,
        penalty_energy(track, &tree),
        tree_dynamics,
    );
    let closure_fns = closure_impl(&tree, track);
    let linear_time = super::linear_time::linear_time_dynamics(track);
    let recovery = super::recovery::recovery(track);
    let links_doc = format!("Number of links, `{n}`.");
    quote! {
        #(#attrs)*
        #docs
        #[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
        #vis struct #name;

        impl #name {
            #[doc = #links_doc]
            pub const LINKS: usize = #n;
        }

        #recursive

        #[allow(unused_variables, clippy::all, clippy::pedantic)]
        impl #rt::TrackModel<#dof> for #name {
            const CLOSURE: #rt::Closure = #closure;
            #closure_fns
            #linear_time
            #recovery
        }
    }
}

/// `½ k |C|²` for a penalty-closed track, with positions' trig bound.
fn penalty_energy(track: &Track, tree: &Tree) -> Option<TokenStream> {
    let Closure::Penalty { stiffness, damping } = &track.closure else {
        return None;
    };
    let rt = runtime();
    let gap = gap(tree, track);
    let (x, y) = (gap.x.tokens(), gap.y.tokens());
    Some(quote! {
        #rt::PenaltyJoint { stiffness: #stiffness, damping: #damping }
            .energy(#rt::nalgebra::Vector2::new(#x, #y))
    })
}

/// `C = Σ Aʲ d̄ʲ` (formulation §2).
fn gap(tree: &Tree, track: &Track) -> LinVec {
    spans(track)
        .iter()
        .enumerate()
        .fold(LinVec::zero(), |acc, (j, d)| {
            acc.plus(Trig::new(&tree.bodies[j].tag).rotate(d))
        })
}

fn closure_impl(tree: &Tree, track: &Track) -> TokenStream {
    let rt = runtime();
    let dof = tree.len() + 2;
    let trig = tree.trig_prelude();
    let gap = gap(tree, track);
    let (cx, cy) = (gap.x.tokens(), gap.y.tokens());
    let mut jacobian = TokenStream::new();
    let mut gamma = LinVec::zero();
    for (j, d) in spans(track).iter().enumerate() {
        let t = Trig::new(&tree.bodies[j].tag);
        let col = t.rotate_derivative(d);
        let (x, y) = (col.x.tokens(), col.y.tokens());
        let c = 2 + j;
        jacobian.extend(quote! { out[(0, #c)] = #x; out[(1, #c)] = #y; });
        let ww = format_ident!("ww_{}", tree.bodies[j].tag);
        gamma = gamma.plus(t.rotate(d).times(&quote!(#ww)));
    }
    let rates = tree.rate_prelude(true);
    let (gx, gy) = (gamma.x.tokens(), gamma.y.tokens());
    let closure = shallow_scopes(quote! { #trig #rt::nalgebra::Vector2::new(#cx, #cy) });
    let closure_jacobian = shallow_scopes(quote! {
        #trig
        let mut out = #rt::nalgebra::SMatrix::<f64, 2, #dof>::zeros();
        #jacobian
        out
    });
    let closure_gamma =
        shallow_scopes(quote! { #trig #rates #rt::nalgebra::Vector2::new(#gx, #gy) });
    quote! {
        #[inline]
        fn closure(&self, q: &#rt::nalgebra::SVector<f64, #dof>) -> #rt::nalgebra::Vector2<f64> {
            #closure
        }

        #[inline]
        fn closure_jacobian(&self, q: &#rt::nalgebra::SVector<f64, #dof>) -> #rt::nalgebra::SMatrix<f64, 2, #dof> {
            #closure_jacobian
        }

        #[inline]
        fn closure_gamma(
            &self,
            q: &#rt::nalgebra::SVector<f64, #dof>,
            qd: &#rt::nalgebra::SVector<f64, #dof>,
        ) -> #rt::nalgebra::Vector2<f64> {
            #closure_gamma
        }
    }
}
