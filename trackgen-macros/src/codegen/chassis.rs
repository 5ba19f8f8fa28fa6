//! A vehicle: its chassis (formulation §3) as a tree of the frame and the parts
//! pinned to it, and its track.

use proc_macro2::{Ident, TokenStream};
use quote::{format_ident, quote};

use super::runtime_path::runtime;
use super::track::{default_docs, track_type};
use super::tree::Tree;
use crate::ir::{Item, PartKind, Vehicle};
use crate::num::Num;

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

fn chassis_type(
    vis: &syn::Visibility,
    vehicle_name: &Ident,
    name: &Ident,
    vehicle: &Vehicle,
) -> TokenStream {
    let rt = runtime();
    let tree = Tree::new(vehicle.chassis.clone(), vehicle.gravity.clone(), None);
    let dof = tree.len() + 2;
    let n = tree.len();
    let statements = super::articulated::tree_dynamics(&tree);
    let loads = super::recursive::loads_or_zero(n, &rt);
    let tree_dynamics = super::scopes::shallow_scopes(quote! {
        ::core::assert_eq!(trig.len(), #n, "one (sin θ, cos θ) per body");
        #loads
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
    let (seat_x, seat_y) = (&vehicle.seat.x, &vehicle.seat.y);
    let hull = vehicle.hull.iter().map(|p| {
        let (x, y) = (&p.x, &p.y);
        quote!([#x, #y])
    });
    let indices = &vehicle.part_bodies;
    let parts = vehicle.parts.iter().zip(indices).map(|(p, &(body, arm_body))| {
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
                let (low, high) = (&a.travel.x, &a.travel.y);
                quote! {
                    ::core::option::Option::Some(#rt::ArmSpring {
                        body: #arm_body,
                        spring: #rt::TorsionSpring { stiffness: #k, damping: #c, preload: #t },
                        travel: (#low, #high),
                    })
                }
            }
            _ => quote!(::core::option::Option::None),
        };
        quote! {
            #rt::ChassisPart {
                name: #label, kind: #rt::PartKind::#kind, body: #body, radius: #radius, teeth: #teeth,
                arm: #arm,
            }
        }
    });
    let index_consts = vehicle
        .parts
        .iter()
        .zip(indices)
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

        // Folded numbers (a default travel of ±π/2) may be close to a
        // named constant: they are meant as written.
        #[allow(clippy::approx_constant)]
        impl #rt::ChassisModel<#dof> for #name {
            const PARTS: &'static [#rt::ChassisPart] = &[#(#parts),*];
            const SEAT: [f64; 2] = [#seat_x, #seat_y];
            const HULL: &'static [[f64; 2]] = &[#(#hull),*];
        }
    }
}
