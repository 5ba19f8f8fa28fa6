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
    }
}

fn chassis_tree(vehicle: &Vehicle) -> Tree {
    let frame = Body {
        tag: FRAME.to_string(),
        mass: vehicle.chassis_mass.clone(),
        inertia: vehicle.chassis_inertia.clone(),
        parent: None,
        at_parent: Vec2::zero(),
        at_self: Vec2::zero(),
    };
    let parts = vehicle.parts.iter().map(|p| Body {
        tag: p.name.to_string(),
        mass: p.mass.clone(),
        inertia: p.inertia.clone(),
        parent: Some(0),
        at_parent: p.at.clone(),
        at_self: Vec2::zero(),
    });
    Tree::new(
        std::iter::once(frame).chain(parts).collect(),
        vehicle.gravity.clone(),
        None,
    )
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
    let recursive =
        super::recursive::recursive_impl(name, &tree, quote!(::core::option::Option::None), None);
    let doc = format!(
        "The chassis of [`{vehicle_name}`]: the frame (body 0) and its parts, pinned to it."
    );
    let parts = vehicle.parts.iter().enumerate().map(|(i, p)| {
        let label = p.name.to_string();
        let kind = match p.kind {
            PartKind::Sprocket => quote!(Sprocket),
            PartKind::Idler => quote!(Idler),
            PartKind::RoadWheel => quote!(RoadWheel),
            PartKind::Roller => quote!(Roller),
        };
        let radius: &Num = &p.radius;
        let teeth = p.teeth;
        let body = i + 1;
        quote! {
            #rt::runtime::ChassisPart {
                name: #label, kind: #rt::runtime::PartKind::#kind, body: #body, radius: #radius, teeth: #teeth,
            }
        }
    });
    let indices = vehicle.parts.iter().enumerate().map(|(i, p)| {
        let konst = format_ident!("{}", p.name.to_string().to_uppercase());
        let doc = format!(
            "Body index of the {} `{}`.",
            p.kind.keyword().replace('_', " "),
            p.name
        );
        let body = i + 1;
        quote! { #[doc = #doc] pub const #konst: usize = #body; }
    });
    quote! {
        #[doc = #doc]
        #[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
        #vis struct #name;

        impl #name {
            /// Body index of the chassis frame.
            pub const FRAME: usize = 0;
            #(#indices)*
        }

        #recursive

        impl #rt::runtime::ChassisModel<#dof> for #name {
            const PARTS: &'static [#rt::runtime::ChassisPart] = &[#(#parts),*];
        }
    }
}
