//! What makes a declared vehicle run: its DOF constants and system type,
//! and with a declared shoe its `trackgen::Vehicle` impl (contact geometry,
//! declared configuration, speed drive). The build recipe is the
//! runtime's (`trackgen::vehicle::build`), not emitted here.

use proc_macro2::{Ident, TokenStream};
use quote::quote;

use super::runtime;
use crate::ir::{ContactPair, NormalLaw, Running, Vehicle};
use crate::num::Vec2;

/// The vehicle's DOF constants and system type, and with a declared shoe
/// its `Vehicle` impl.
pub fn running(
    vis: &syn::Visibility,
    name: &Ident,
    track: &Ident,
    chassis: &Ident,
    vehicle: &Vehicle,
    dofs: (usize, usize),
) -> TokenStream {
    let rt = runtime();
    let common = common(vis, name, (track, chassis), dofs);
    let (Some(run), Some(sprocket)) = (&vehicle.running, sprocket_teeth(vehicle)) else {
        return common;
    };
    let (dt, dc) = dofs;
    let system = quote::format_ident!("{}System", name);
    let label = name.to_string();
    let geometry = geometry(run, sprocket, track, dt);
    let pairs = [quote!(ground), quote!(wheels), quote!(sprocket)]
        .iter()
        .zip(&run.contact)
        .map(|(field, pair)| contact_pair(field, pair))
        .collect::<TokenStream>();
    let Running {
        proportional,
        integral,
        max_torque,
        ..
    } = run;
    quote! {
        #common

        #[allow(clippy::approx_constant)]
        impl #rt::Vehicle for #name {
            const NAME: &'static str = #label;
            const TRACK_DOF: usize = #dt;
            const CHASSIS_DOF: usize = #dc;
            type Track = #track;
            type Chassis = #chassis;
            type System = #system;

            fn geometry() -> #rt::Geometry {
                #geometry
            }

            fn config(terrain: #rt::Terrain, drive: #rt::Drive) -> #rt::VehicleConfig {
                let arms = <#chassis as #rt::ChassisModel<#dc>>::PARTS
                    .iter()
                    .filter_map(|part| part.arm)
                    .collect();
                #[allow(unused_mut)]
                let mut config = #rt::VehicleConfig::new(terrain, drive, arms);
                #pairs
                config
            }

            fn speed_drive(
                target: impl ::core::ops::Fn(f64) -> f64 + ::core::marker::Send + 'static,
            ) -> #rt::Drive {
                #rt::Drive::Speed {
                    target: ::std::boxed::Box::new(target),
                    proportional: #proportional,
                    integral: #integral,
                    max_torque: #max_torque,
                }
            }
        }
    }
}

/// `TRACK_DOF`, `CHASSIS_DOF` and `NameSystem`: what every vehicle gets,
/// and its stub after an error.
pub fn common(
    vis: &syn::Visibility,
    name: &Ident,
    (track, chassis): (&Ident, &Ident),
    (dt, dc): (usize, usize),
) -> TokenStream {
    let rt = runtime();
    let system = quote::format_ident!("{}System", name);
    let system_doc = format!("[`{name}`] in motion: its track and chassis, coupled by contact.");
    quote! {
        impl #name {
            /// Number of track coordinates `q_i` (links + 2).
            pub const TRACK_DOF: usize = #dt;
            /// Number of chassis coordinates `q_i` (bodies + 2).
            pub const CHASSIS_DOF: usize = #dc;
        }

        #[doc = #system_doc]
        #vis type #system = #rt::VehicleSystem<#track, #dt, #chassis, #dc>;
    }
}

/// The `Geometry` literal: the declared shoe, the running face across the
/// track's pitch, the tooth profile (declared radii, the others
/// `ToothProfile::scaled` from the track's pitch and the teeth).
fn geometry(run: &Running, teeth: u32, track: &Ident, dt: usize) -> TokenStream {
    let rt = runtime();
    let v2 = |p: &Vec2| {
        let (x, y) = (&p.x, &p.y);
        quote!(#rt::nalgebra::Vector2::new(#x, #y))
    };
    let shoe = &run.shoe;
    let ground_points = shoe.ground_points.iter().map(v2);
    let pins = shoe.pins.iter().map(v2);
    let pin_radius = &shoe.pin_radius;
    let offset = &shoe.inner_offset;
    let width = match &shoe.width {
        Some(w) => quote!(::core::option::Option::Some(#w)),
        None => quote!(::core::option::Option::None),
    };
    let profile_fields = [
        (quote!(addendum), &run.tip_radius),
        (quote!(arc_radius), &run.gap_radius),
        (quote!(arc_centre_radius), &run.gap_centre),
    ]
    .into_iter()
    .filter_map(|(field, v)| v.as_ref().map(|v| quote!(profile.#field = #v;)));
    quote! {
        let description = <#track as #rt::RecursiveModel<#dt>>::description(&#track);
        // The running face spans the first link's joints along its x axis.
        let (u1, u2) = description.joints().map_or(
            (#rt::nalgebra::Vector2::zeros(), #rt::nalgebra::Vector2::zeros()),
            |joints| joints[0],
        );
        // Links of different lengths have no pitch: building the vehicle
        // refuses them, naming the lengths.
        let pitch = description.pitch().unwrap_or(f64::NAN);
        #[allow(unused_mut)]
        let mut profile = #rt::ToothProfile::scaled(#teeth, pitch);
        #(#profile_fields)*
        #rt::Geometry {
            shoe: #rt::ShoeGeometry {
                ground_points: ::std::vec![#(#ground_points),*],
                inner_face: [
                    #rt::nalgebra::Vector2::new(u1.x, #offset),
                    #rt::nalgebra::Vector2::new(u2.x, #offset),
                ],
                pins: ::std::vec![#(#pins),*],
                pin_radius: #pin_radius,
                width: #width,
            },
            sprocket: profile,
        }
    }
}

fn sprocket_teeth(vehicle: &Vehicle) -> Option<u32> {
    vehicle
        .parts
        .iter()
        .find(|p| p.kind == crate::ir::PartKind::Sprocket)
        .map(|p| p.teeth)
}

/// The statements setting one pair's declared law and friction.
fn contact_pair(field: &TokenStream, pair: &ContactPair) -> TokenStream {
    let rt = runtime();
    let law = pair.normal.as_ref().map(|law| {
        let law = match law {
            NormalLaw::HuntCrossley {
                stiffness,
                exponent,
                chi,
            } => quote! {
                #rt::NormalLaw::HuntCrossley {
                    stiffness: #stiffness, exponent: #exponent, chi: #chi,
                }
            },
            NormalLaw::KelvinVoigt { stiffness, damping } => quote! {
                #rt::NormalLaw::KelvinVoigt {
                    stiffness: #stiffness, damping: #damping,
                }
            },
        };
        quote!(config.#field.normal = #law;)
    });
    let mu = pair
        .mu
        .as_ref()
        .map(|v| quote!(config.#field.friction.mu = #v;));
    let slip = pair
        .slip
        .as_ref()
        .map(|v| quote!(config.#field.friction.slip = #v;));
    quote!(#law #mu #slip)
}
