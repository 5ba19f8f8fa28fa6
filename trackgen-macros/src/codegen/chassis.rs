//! A vehicle: its chassis (spec §3) as a tree of the frame and the parts
//! pinned to it, and its track.

use proc_macro2::{Ident, TokenStream};
use quote::{format_ident, quote};

use super::runtime;
use super::track::{default_docs, track_type};
use super::tree::{Body, Tree};
use crate::ir::{Item, PartKind, Vehicle};
use crate::num::{Num, Vec2};

/// The frame's local tag (the paper's superscript `c`).
const FRAME: &str = "chassis";

pub fn vehicle(item: &Item, vehicle: &Vehicle) -> TokenStream {
    let name = &item.name;
    let vis = &item.vis;
    let attrs = &item.attrs;
    let track_name = format_ident!("{}Track", name);
    let chassis_name = format_ident!("{}Chassis", name);
    let docs = default_docs(
        attrs,
        &format!("The vehicle `{name}`, compiled by `trackgen::model!`."),
    );
    let track_doc = format!("The track of [`{name}`].");
    let track = track_type(
        &[],
        quote!(#[doc = #track_doc]),
        vis,
        &track_name,
        &vehicle.track,
    );
    let chassis = chassis_type(vis, name, &chassis_name, vehicle);
    let arms = vehicle.parts.iter().filter(|p| p.arm.is_some()).count();
    let dofs = (
        vehicle.track.links.len() + 2,
        1 + vehicle.parts.len() + arms + 2,
    );
    let running = super::running::running(vis, name, &track_name, &chassis_name, vehicle, dofs);
    quote! {
        #(#attrs)*
        #docs
        #[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
        #vis struct #name;

        impl #name {
            /// The track subsystem.
            pub const TRACK: #track_name = #track_name;
            /// The chassis subsystem.
            pub const CHASSIS: #chassis_name = #chassis_name;
        }

        #track
        #chassis
        #running
    }
}

/// The frame (body 0), then each part, preceded by its arm if it has one:
/// a two-level tree. An arm's centroid is midway between its pivot and the
/// part, and its frame is aligned with the chassis at the design position.
fn chassis_tree(vehicle: &Vehicle) -> Tree {
    let mut bodies = vec![Body {
        tag: FRAME.to_string(),
        mass: vehicle.chassis_mass.clone(),
        inertia: vehicle.chassis_inertia.clone(),
        parent: None,
        at_parent: Vec2::zero(),
        at_self: Vec2::zero(),
    }];
    for part in &vehicle.parts {
        let (parent, at_parent) = match &part.arm {
            Some(arm) => {
                let half = Num::Known(0.5);
                // From the arm's centroid (midway) to the pivot and the part.
                let to_pivot = (arm.pivot.clone() - part.at.clone()).scale(&half);
                bodies.push(Body {
                    tag: format!("{}_arm", part.name),
                    mass: arm.mass.clone(),
                    inertia: arm.inertia.clone(),
                    parent: Some(0),
                    at_parent: arm.pivot.clone(),
                    at_self: to_pivot.clone(),
                });
                (bodies.len() - 1, -to_pivot)
            }
            None => (0, part.at.clone()),
        };
        bodies.push(Body {
            tag: part.name.to_string(),
            mass: part.mass.clone(),
            inertia: part.inertia.clone(),
            parent: Some(parent),
            at_parent,
            at_self: Vec2::zero(),
        });
    }
    Tree::new(bodies, vehicle.gravity.clone(), None)
}

/// Body indices of each part and its arm, in [`chassis_tree`]'s order.
fn body_indices(vehicle: &Vehicle) -> Vec<(usize, Option<usize>)> {
    let mut next = 1;
    vehicle
        .parts
        .iter()
        .map(|p| {
            let arm = p.arm.as_ref().map(|_| {
                next += 1;
                next - 1
            });
            next += 1;
            (next - 1, arm)
        })
        .collect()
}

fn chassis_type(
    vis: &syn::Visibility,
    vehicle_name: &Ident,
    name: &Ident,
    vehicle: &Vehicle,
) -> TokenStream {
    let rt = runtime();
    let tree = chassis_tree(vehicle);
    let dof = tree.len() + 2;
    let n = tree.len();
    let statements = super::articulated::tree_dynamics(&tree);
    let tree_dynamics = super::flat::flatten(quote! {
        ::core::assert_eq!(trig.len(), #n, "one (sin θ, cos θ) per body");
        let no_loads = [#rt::runtime::BodyLoad::ZERO; #n];
        let loads: &[#rt::runtime::BodyLoad] = if loads.is_empty() {
            &no_loads
        } else {
            ::core::assert_eq!(loads.len(), #n, "one load per body, or none");
            loads
        };
        #statements
        ::core::result::Result::Ok(())
    });
    let recursive = super::recursive::recursive_impl(
        name,
        &tree,
        quote!(::core::option::Option::None),
        None,
        tree_dynamics,
    );
    let doc = format!(
        "The chassis of [`{vehicle_name}`]: the frame (body 0) and its parts, pinned to it."
    );
    let indices = body_indices(vehicle);
    let parts = vehicle.parts.iter().zip(&indices).map(|(p, &(body, arm_body))| {
        let label = p.name.to_string();
        let kind = match p.kind {
            PartKind::Sprocket => quote!(Sprocket),
            PartKind::Idler => quote!(Idler),
            PartKind::RoadWheel => quote!(RoadWheel),
            PartKind::Roller => quote!(Roller),
        };
        let radius: &Num = &p.radius;
        let teeth = p.teeth;
        let arm = match (&p.arm, arm_body) {
            (Some(a), Some(arm_body)) => {
                let (k, c, t) = (&a.stiffness, &a.damping, &a.preload);
                quote! {
                    ::core::option::Option::Some(#rt::runtime::ArmSpring {
                        body: #arm_body, stiffness: #k, damping: #c, preload: #t,
                    })
                }
            }
            _ => quote!(::core::option::Option::None),
        };
        quote! {
            #rt::runtime::ChassisPart {
                name: #label, kind: #rt::runtime::PartKind::#kind, body: #body, radius: #radius, teeth: #teeth,
                arm: #arm,
            }
        }
    });
    let index_consts = vehicle
        .parts
        .iter()
        .zip(&indices)
        .map(|(p, &(body, arm_body))| {
            let konst = format_ident!("{}", p.name.to_string().to_uppercase());
            let doc = format!(
                "Body index of the {} `{}`.",
                p.kind.keyword().replace('_', " "),
                p.name
            );
            let arm = arm_body.map(|arm| {
                let konst = format_ident!("{}_ARM", p.name.to_string().to_uppercase());
                let doc = format!("Body index of the arm carrying `{}`.", p.name);
                quote! { #[doc = #doc] pub const #konst: usize = #arm; }
            });
            quote! { #[doc = #doc] pub const #konst: usize = #body; #arm }
        });
    quote! {
        #[doc = #doc]
        #[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
        #vis struct #name;

        impl #name {
            /// Body index of the chassis frame.
            pub const FRAME: usize = 0;
            #(#index_consts)*
        }

        #recursive

        impl #rt::runtime::ChassisModel<#dof> for #name {
            const PARTS: &'static [#rt::runtime::ChassisPart] = &[#(#parts),*];
        }
    }
}
