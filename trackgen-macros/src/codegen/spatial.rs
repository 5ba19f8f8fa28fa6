//! A vehicle's `tracks` block: the hull with both sides' running gear
//! (`NameHull`), the mirrored side's track when its link count differs
//! from the declared one's (`NameLeftTrack` or `NameRightTrack`), and the
//! `SpatialVehicle` impl that lays them out across the vehicle.

use proc_macro2::{Ident, TokenStream};
use quote::{format_ident, quote};

use super::chassis_type::{ChassisView, chassis_type};
use super::runtime_path::runtime;
use super::track::track_type;
use crate::ir::{Across, Tracks, Vehicle};

pub fn spatial(
    vis: &syn::Visibility,
    name: &Ident,
    right_track: &Ident,
    vehicle: &Vehicle,
    tracks: &Tracks,
) -> TokenStream {
    let rt = runtime();
    let hull_name = format_ident!("{}Hull", name);
    let doc = format!(
        "The hull of [`{name}`] in space: the frame (body 0, the whole hull) with the right \
         side's parts and arms, then the left side's, each side in its track's plane."
    );
    let view = ChassisView {
        bodies: &tracks.hull,
        gravity: &vehicle.gravity,
        parts: &tracks.parts,
        part_bodies: &tracks.part_bodies,
        seat: &vehicle.seat,
        hull: &vehicle.hull,
    };
    let hull = chassis_type(vis, &doc, &hull_name, &view);
    let (mirror_name, mirror_type) = mirror_track(vis, name, right_track, tracks);
    let (right_name, left_name) = match tracks.declared_left {
        true => (&mirror_name, right_track),
        false => (right_track, &mirror_name),
    };
    let hull_dof = tracks.hull.len() + 2;
    let right_dof = tracks.right_links.len() + 2;
    let left_dof = tracks.left_links.len() + 2;
    let declared = match tracks.declared_left {
        true => quote!(#rt::Side::Left),
        false => quote!(#rt::Side::Right),
    };
    let offsets = &tracks.offsets;
    let hull_across = tracks.hull_across.iter().map(across);
    let right_links = runs(&tracks.right_links);
    let left_links = runs(&tracks.left_links);
    let sides = tracks.left.iter().map(|&left| match left {
        true => quote!(#rt::Side::Left),
        false => quote!(#rt::Side::Right),
    });
    let Tracks {
        gauge,
        shoe_width,
        guide_play,
        ..
    } = tracks;
    quote! {
        impl #name {
            /// The hull with both sides' running gear.
            pub const HULL: #hull_name = #hull_name;
        }

        #hull
        #mirror_type

        impl #rt::SpatialVehicle for #name {
            const HULL_DOF: usize = #hull_dof;
            const RIGHT_TRACK_DOF: usize = #right_dof;
            const LEFT_TRACK_DOF: usize = #left_dof;
            type Hull = #hull_name;
            type RightTrack = #right_name;
            type LeftTrack = #left_name;

            fn layout() -> #rt::SpatialLayout {
                #rt::SpatialLayout {
                    declared: #declared,
                    gauge: #gauge,
                    shoe_width: #shoe_width,
                    guide_play: #guide_play,
                    hull_offsets: ::std::vec![#(#offsets),*],
                    hull_across: ::std::vec![#(#hull_across),*],
                    part_sides: ::std::vec![#(#sides),*],
                    right_links: #right_links,
                    left_links: #left_links,
                }
            }
        }

        impl #rt::SpatialVehicleSystem for #name {
            type Spatial = #rt::SpatialSystem<
                'static, #hull_name, #hull_dof, #right_name, #right_dof, #left_name, #left_dof,
            >;

            fn spatial(
                laws: #rt::SpatialLaws,
                field: #rt::HeightField,
            ) -> ::core::result::Result<Self::Spatial, #rt::SpatialError> {
                let geometry = <Self as #rt::Vehicle>::geometry();
                #rt::SpatialDynamics::new(
                    &#hull_name,
                    (&#right_name, &#left_name),
                    &<Self as #rt::SpatialVehicle>::layout(),
                    geometry.shoe,
                    geometry.sprocket,
                    laws,
                    field,
                )
                .map(#rt::SpatialSystem::new)
            }
        }
    }
}

/// The mirrored side's track type, `NameLeftTrack` or `NameRightTrack`,
/// where its link count differs from the declared side's (`NameTrack`
/// otherwise, no new type).
pub fn mirror_track(
    vis: &syn::Visibility,
    name: &Ident,
    declared: &Ident,
    tracks: &Tracks,
) -> (Ident, TokenStream) {
    let side = if tracks.declared_left {
        "Right"
    } else {
        "Left"
    };
    match &tracks.mirror_track {
        Some(track) => {
            let mirror = format_ident!("{}{}Track", name, side);
            let doc = format!(
                "The {} track of [`{name}`], where its link count differs from the declared side's.",
                side.to_lowercase()
            );
            let ty = track_type(&[], quote!(#[doc = #doc]), vis, &mirror, track);
            (mirror, ty)
        }
        None => (declared.clone(), TokenStream::new()),
    }
}

fn across(a: &Across) -> TokenStream {
    let rt = runtime();
    let Across { xx, zz, xz } = a;
    quote!(#rt::OutOfPlaneInertia { xx: #xx, zz: #zz, xz: #xz })
}

/// The links' inertias as a `Vec`: `vec![x; n]` where every link's is the
/// same (the usual track), else one per link.
fn runs(links: &[Across]) -> TokenStream {
    let same = |a: &Across, b: &Across| a.xx.same(&b.xx) && a.zz.same(&b.zz) && a.xz.same(&b.xz);
    match links.first() {
        Some(first) if links.iter().all(|l| same(l, first)) => {
            let (one, n) = (across(first), links.len());
            quote!(::std::vec![#one; #n])
        }
        _ => {
            let each = links.iter().map(across);
            quote!(::std::vec![#(#each),*])
        }
    }
}
