//! A vehicle: its chassis (formulation §3) as a tree of the frame and the parts
//! pinned to it, its track, what makes it run and its `tracks` block.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::chassis_type::{ChassisView, chassis_type};
use super::track::{default_docs, track_type};
use crate::ir::{Item, Vehicle};

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
    let doc = format!("The chassis of [`{name}`]: the frame (body 0) and its parts, pinned to it.");
    let chassis = chassis_type(vis, &doc, &chassis_name, &ChassisView::planar(vehicle));
    let arms = vehicle.parts.iter().filter(|p| p.arm.is_some()).count();
    let dofs = (
        vehicle.track.links.len() + 2,
        1 + vehicle.parts.len() + arms + 2,
    );
    let running = super::running::running(vis, name, &track_name, &chassis_name, vehicle, dofs);
    let spatial = vehicle
        .tracks
        .as_ref()
        .map(|tracks| super::spatial::spatial(vis, name, &track_name, vehicle, tracks));
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
        #spatial
    }
}
