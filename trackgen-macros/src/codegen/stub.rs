//! After an error: every item a declaration would generate, as a stub, so
//! that code using any of them reports nothing more than the real error
//! (thiserror-impl's way). The stubs' methods are never run: the crate
//! does not compile.
//!
//! A track becomes its unit struct with `LINKS` and the model traits for
//! any coordinate count; a vehicle also `NameTrack`, `NameChassis` (with
//! the body-index constants of the parts that parsed), `TRACK_DOF`,
//! `CHASSIS_DOF`, `TRACK`, `CHASSIS`, `NameSystem`, if it has a shoe its
//! `Vehicle` impl, and with a `tracks` block `NameHull`, `HULL`, the
//! mirrored side's track it declares and its `SpatialVehicle` impl.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::{Ident, Visibility};

use super::runtime_path::runtime;
use crate::ir::{Item, ItemKind, Part};

pub fn stubs(items: &[Item]) -> TokenStream {
    items.iter().map(stub).collect()
}

fn stub(item: &Item) -> TokenStream {
    let (vis, name) = (&item.vis, &item.name);
    match &item.kind {
        ItemKind::Track(track) => {
            let links = track.links.len();
            let mut out = unit(vis, name);
            out.extend(quote! {
                impl #name {
                    #[allow(dead_code)]
                    pub const LINKS: usize = #links;
                }
            });
            out.extend(models(name, false));
            out
        }
        ItemKind::Vehicle(vehicle) => {
            let track = format_ident!("{}Track", name);
            let chassis = format_ident!("{}Chassis", name);
            let links = vehicle.track.links.len();
            let dofs = (links + 2, vehicle.chassis.len() + 2);
            let mut out = unit(vis, name);
            out.extend(unit(vis, &track));
            out.extend(unit(vis, &chassis));
            let parts = part_constants(&vehicle.parts, &vehicle.part_bodies);
            out.extend(quote! {
                #[allow(dead_code)]
                impl #name {
                    pub const TRACK: #track = #track;
                    pub const CHASSIS: #chassis = #chassis;
                }
                #[allow(dead_code)]
                impl #track {
                    pub const LINKS: usize = #links;
                }
                #[allow(dead_code)]
                impl #chassis {
                    pub const FRAME: usize = 0;
                    #(#parts)*
                }
            });
            out.extend(models(&track, false));
            out.extend(models(&chassis, true));
            out.extend(super::running::common(vis, name, (&track, &chassis), dofs));
            if vehicle.running.is_some() {
                out.extend(vehicle_impl(name, (&track, &chassis), dofs));
            }
            if let Some(tracks) = &vehicle.tracks {
                out.extend(spatial(
                    vis,
                    name,
                    &track,
                    tracks,
                    vehicle.running.is_some(),
                ));
            }
            out
        }
    }
}

/// The body-index constants of `parts` (and of their arms), each once: a
/// part named twice is one of the errors.
fn part_constants(parts: &[Part], bodies: &[(usize, Option<usize>)]) -> Vec<TokenStream> {
    let mut seen = std::collections::BTreeSet::new();
    parts
        .iter()
        .zip(bodies)
        .filter(|(p, _)| seen.insert(p.name.to_string()))
        .map(|(p, &(body, arm))| {
            let konst = format_ident!("{}", p.name.to_string().to_uppercase());
            let arm = arm.map(|arm| {
                let konst = format_ident!("{}_ARM", p.name.to_string().to_uppercase());
                quote!(pub const #konst: usize = #arm;)
            });
            quote!(pub const #konst: usize = #body; #arm)
        })
        .collect()
}

fn unit(vis: &Visibility, name: &Ident) -> TokenStream {
    quote! {
        #[allow(dead_code)]
        #[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
        #vis struct #name;
    }
}

/// `RecursiveModel` and `TrackModel` (or `ChassisModel`) for any
/// coordinate count.
fn models(name: &Ident, chassis: bool) -> TokenStream {
    let rt = runtime();
    let never = quote!(::core::unreachable!("the declaration did not compile"));
    let v = quote!(#rt::nalgebra::SVector<f64, D>);
    let last = if chassis {
        quote! {
            impl<const D: usize> #rt::ChassisModel<D> for #name {
                const PARTS: &'static [#rt::ChassisPart] = &[];
                const SEAT: [f64; 2] = [0.0, 0.0];
                const HULL: &'static [[f64; 2]] = &[];
            }
        }
    } else {
        quote! {
            #[allow(unused_variables)]
            impl<const D: usize> #rt::TrackModel<D> for #name {
                const CLOSURE: #rt::Closure = #rt::Closure::Open;
                fn closure(&self, q: &#v) -> #rt::nalgebra::Vector2<f64> { #never }
                fn closure_jacobian(&self, q: &#v) -> #rt::nalgebra::SMatrix<f64, 2, D> { #never }
                fn closure_gamma(&self, q: &#v, qd: &#v) -> #rt::nalgebra::Vector2<f64> { #never }
                fn recover_closure(
                    &self, q: &mut #v, qd: &mut #v, pair: [usize; 2], tolerance: f64,
                    max_iterations: usize, trig: &mut [(f64, f64)],
                ) -> ::core::result::Result<usize, (usize, f64)> { #never }
                fn closure_columns(&self, trig: &[(f64, f64)], out: &mut [#rt::nalgebra::Vector2<f64>]) { #never }
                fn linear_time_dynamics(
                    &self, trig: &[(f64, f64)], qd: &#v, loads: &[#rt::BodyLoad],
                    closing: #rt::ClosingJoint, qdd: &mut #v,
                    joint_forces: &mut [#rt::nalgebra::Vector2<f64>],
                ) -> ::core::result::Result<(), #rt::DynamicsError> { #never }
            }
        }
    };
    quote! {
        #[allow(unused_variables)]
        impl<const D: usize> #rt::RecursiveModel<D> for #name {
            const BODIES: usize = 0;
            fn description(&self) -> #rt::TreeDescription { #never }
            fn body_positions(&self, q: &#v, out: &mut [#rt::nalgebra::Vector2<f64>]) { #never }
            fn body_velocities(&self, q: &#v, qd: &#v, out: &mut [#rt::nalgebra::Vector2<f64>]) { #never }
            fn velocity_terms(&self, q: &#v, qd: &#v, out: &mut [#rt::nalgebra::Vector2<f64>]) { #never }
            fn mass_matrix(&self, q: &#v, out: &mut #rt::nalgebra::SMatrix<f64, D, D>) { #never }
            fn generalized_forces(&self, q: &#v, qd: &#v, loads: &[#rt::BodyLoad], out: &mut #v) { #never }
            fn tree_dynamics(
                &self, trig: &[(f64, f64)], qd: &#v, loads: &[#rt::BodyLoad], qdd: &mut #v,
            ) -> ::core::result::Result<(), #rt::DynamicsError> { #never }
            fn kinetic_energy(&self, q: &#v, qd: &#v) -> f64 { #never }
            fn potential_energy(&self, q: &#v) -> f64 { #never }
        }
        #last
    }
}

/// A `tracks` block's items: `NameHull` with the constants of its parts,
/// the mirrored side's track where declared, the `SpatialVehicle` impl,
/// and the `SpatialVehicleSystem` impl where `vehicle` (the stubs
/// implement `Vehicle`).
fn spatial(
    vis: &Visibility,
    name: &Ident,
    declared: &Ident,
    tracks: &crate::ir::Tracks,
    vehicle: bool,
) -> TokenStream {
    let rt = runtime();
    let hull = format_ident!("{}Hull", name);
    let mut out = unit(vis, &hull);
    let parts = part_constants(&tracks.parts, &tracks.part_bodies);
    let mirror = match &tracks.mirror_track {
        Some(_) => {
            let side = if tracks.declared_left {
                "Right"
            } else {
                "Left"
            };
            let mirror = format_ident!("{}{}Track", name, side);
            out.extend(unit(vis, &mirror));
            out.extend(models(&mirror, false));
            mirror
        }
        None => declared.clone(),
    };
    let (right, left) = match tracks.declared_left {
        true => (&mirror, declared),
        false => (declared, &mirror),
    };
    let (dh, dr, dl) = (
        tracks.hull.len() + 2,
        tracks.right_links.len() + 2,
        tracks.left_links.len() + 2,
    );
    out.extend(quote! {
        #[allow(dead_code)]
        impl #name {
            pub const HULL: #hull = #hull;
        }
        #[allow(dead_code)]
        impl #hull {
            pub const FRAME: usize = 0;
            #(#parts)*
        }
        impl #rt::SpatialVehicle for #name {
            const HULL_DOF: usize = #dh;
            const RIGHT_TRACK_DOF: usize = #dr;
            const LEFT_TRACK_DOF: usize = #dl;
            type Hull = #hull;
            type RightTrack = #right;
            type LeftTrack = #left;
            fn layout() -> #rt::SpatialLayout {
                ::core::unreachable!("the declaration did not compile")
            }
        }
    });
    // Only where the stubs implement `Vehicle`, which it requires.
    if vehicle {
        out.extend(quote! {
            #[allow(unused_variables)]
            impl #rt::SpatialVehicleSystem for #name {
                type Spatial = #rt::SpatialSystem<'static, #hull, #dh, #right, #dr, #left, #dl>;
                fn spatial(
                    laws: #rt::SpatialLaws,
                    field: #rt::HeightField,
                ) -> ::core::result::Result<Self::Spatial, #rt::SpatialError> {
                    ::core::unreachable!("the declaration did not compile")
                }
            }
        });
    }
    out.extend(models(&hull, true));
    out
}

/// The `Vehicle` impl of a vehicle with a shoe.
fn vehicle_impl(name: &Ident, parts: (&Ident, &Ident), dofs: (usize, usize)) -> TokenStream {
    let never = quote!(::core::unreachable!("the declaration did not compile"));
    let bodies = super::running::VehicleBodies {
        geometry: never.clone(),
        config: never.clone(),
        speed_drive: never,
        powertrain: None,
    };
    super::running::vehicle_impl(name, parts, dofs, &bodies)
}
