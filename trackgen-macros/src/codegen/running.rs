//! What makes a declared vehicle run: its shoe, sprocket profile, contact
//! and drive as a `VehicleConfig`, and the one-call constructors.

use proc_macro2::{Ident, TokenStream};
use quote::quote;

use super::runtime;
use crate::ir::{ContactPair, NormalLaw, Running, Vehicle};
use crate::num::Vec2;

/// The vehicle's DOF constants and system type, and with a declared shoe
/// its `shoe`, `tooth_profile`, `config`, `speed_drive`, `system` and
/// `system_with`.
pub fn running(
    vis: &syn::Visibility,
    name: &Ident,
    track: &Ident,
    chassis: &Ident,
    vehicle: &Vehicle,
    dofs: (usize, usize),
) -> TokenStream {
    let rt = runtime();
    let (dt, dc) = dofs;
    let system = quote::format_ident!("{}System", name);
    let system_doc = format!("[`{name}`] in motion: its track and chassis, coupled by contact.");
    let common = quote! {
        impl #name {
            /// Number of track coordinates `q_i` (links + 2).
            pub const TRACK_DOF: usize = #dt;
            /// Number of chassis coordinates `q_i` (bodies + 2).
            pub const CHASSIS_DOF: usize = #dc;
        }

        #[doc = #system_doc]
        #vis type #system = #rt::runtime::vehicle::VehicleSystem<#track, #dt, #chassis, #dc>;
    };
    let (Some(run), Some(sprocket)) = (&vehicle.running, sprocket_teeth(vehicle)) else {
        return common;
    };
    let v2 = |p: &Vec2| {
        let (x, y) = (&p.x, &p.y);
        quote!(#rt::nalgebra::Vector2::new(#x, #y))
    };
    let shoe = &run.shoe;
    let ground_points = shoe.ground_points.iter().map(v2);
    let pins = shoe.pins.iter().map(v2);
    let pin_radius = &shoe.pin_radius;
    let offset = &shoe.inner_offset;
    // The running face spans the first link's joints along its x axis.
    let first = vehicle.track.links.first();
    let (x1, x2, pitch) = match first {
        Some(l) => {
            let d = l.u2.clone() - l.u1.clone();
            let (dx, dy) = (&d.x, &d.y);
            (l.u1.x.clone(), l.u2.x.clone(), quote!(f64::hypot(#dx, #dy)))
        }
        None => (crate::num::Num::ZERO, crate::num::Num::ZERO, quote!(0.0)),
    };
    let profile_fields = [
        (quote!(addendum), &run.tip_radius),
        (quote!(arc_radius), &run.gap_radius),
        (quote!(arc_centre_radius), &run.gap_centre),
    ]
    .into_iter()
    .filter_map(|(field, v)| v.as_ref().map(|v| quote!(profile.#field = #v;)));
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
    let error = quote!(#rt::runtime::vehicle::BuildError);
    quote! {
        #common

        impl #name {
            /// The shoe's contact features as declared (link frame, m).
            pub fn shoe() -> #rt::runtime::contact::ShoeGeometry {
                #rt::runtime::contact::ShoeGeometry {
                    ground_points: ::std::vec![#(#ground_points),*],
                    inner_face: [
                        #rt::nalgebra::Vector2::new(#x1, #offset),
                        #rt::nalgebra::Vector2::new(#x2, #offset),
                    ],
                    pins: ::std::vec![#(#pins),*],
                    pin_radius: #pin_radius,
                }
            }

            /// The sprocket's tooth profile: the declared radii, the others
            /// `ToothProfile::scaled` from the pitch and teeth.
            pub fn tooth_profile() -> #rt::runtime::contact::sprocket::ToothProfile {
                #[allow(unused_mut)]
                let mut profile =
                    #rt::runtime::contact::sprocket::ToothProfile::scaled(#sprocket, #pitch);
                #(#profile_fields)*
                profile
            }

            /// The declared contact, arm springs and shoe on `terrain`,
            /// driven by `drive`. Every field is public: change contact
            /// laws, friction, arm rates (`arms`) or the terrain before
            /// [`system_with`](Self::system_with), no rebuild needed.
            pub fn config(
                terrain: #rt::runtime::contact::Terrain,
                drive: #rt::runtime::vehicle::Drive,
            ) -> #rt::runtime::vehicle::VehicleConfig {
                let mut config = #rt::runtime::vehicle::VehicleConfig::new(
                    Self::shoe(),
                    Self::tooth_profile(),
                    terrain,
                    drive,
                );
                #pairs
                config.arms = ::core::option::Option::Some(
                    #rt::runtime::suspension::declared_arms::<#chassis, #dc>()
                        .copied()
                        .collect(),
                );
                config
            }

            /// A PI speed drive with the declared gains and torque limit:
            /// `target` is the forward speed wanted, m/s, against time, s.
            pub fn speed_drive(
                target: impl ::core::ops::Fn(f64) -> f64 + ::core::marker::Send + 'static,
            ) -> #rt::runtime::vehicle::Drive {
                #rt::runtime::vehicle::Drive::Speed {
                    target: ::std::boxed::Box::new(target),
                    proportional: #proportional,
                    integral: #integral,
                    max_torque: #max_torque,
                }
            }

            /// The vehicle assembled on `terrain` with its declared
            /// [`config`](Self::config) and `drive`: see
            /// [`system_with`](Self::system_with).
            pub fn system(
                terrain: #rt::runtime::contact::Terrain,
                drive: #rt::runtime::vehicle::Drive,
            ) -> ::core::result::Result<#system, #error> {
                Self::system_with(Self::config(terrain, drive))
            }

            /// The vehicle assembled on `config`'s terrain (chassis centroid
            /// at x = 0, shoes 1 mm above the ground), its tensioner set
            /// with the spring's rest angle where it takes up the slack
            /// (`VehicleConfig::adjust_tensioner`), its loop closed by
            /// partitioning, ready for `simulate`. `BuildError::Assembly`
            /// when no start fits, `BuildError::Setup` for a configuration
            /// that makes no vehicle.
            pub fn system_with(
                mut config: #rt::runtime::vehicle::VehicleConfig,
            ) -> ::core::result::Result<#system, #error> {
                let assembled = #rt::runtime::vehicle::assemble(
                    &#track,
                    &#chassis,
                    &config.shoe,
                    &config.sprocket.profile,
                    &config.ground.terrain,
                    0.0,
                    0.001,
                )?;
                config.adjust_tensioner::<#chassis, #dc, #dt>(&assembled);
                ::core::result::Result::Ok(#rt::runtime::vehicle::VehicleSystem::new(
                    #track,
                    #chassis,
                    assembled.track,
                    assembled.chassis,
                    #rt::runtime::closure::ClosureMethod::Declared,
                    config,
                )?)
            }
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
                #rt::runtime::contact::NormalLaw::HuntCrossley {
                    stiffness: #stiffness, exponent: #exponent, chi: #chi,
                }
            },
            NormalLaw::KelvinVoigt { stiffness, damping } => quote! {
                #rt::runtime::contact::NormalLaw::KelvinVoigt {
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
