//! What makes a declared vehicle run: its DOF constants and system type,
//! and with a declared shoe its `trackgen::Vehicle` impl (contact geometry,
//! declared configuration, speed drive). The build recipe is the
//! runtime's (`trackgen::vehicle::build`), not emitted here.

use proc_macro2::{Ident, TokenStream};
use quote::quote;

use super::runtime_path::runtime;
use crate::ir::{ContactPair, NormalLaw, Powertrain, Running, Vehicle};
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
    let geometry = geometry(run, sprocket, track, dt);
    let [ground, wheels, sprocket_pair] = &run.contact;
    let (ground, wheels, sprocket_pair) = (
        declared_pair(ground),
        declared_pair(wheels),
        declared_pair(sprocket_pair),
    );
    let Running {
        proportional,
        integral,
        max_torque,
        ..
    } = run;
    let bodies = VehicleBodies {
        geometry,
        config: quote! {
            let arms = <#chassis as #rt::ChassisModel<#dc>>::PARTS
                .iter()
                .filter_map(|part| part.arm)
                .collect();
            let fit = #rt::ContactFit::of(
                &<#track as #rt::RecursiveModel<#dt>>::description(&#track),
                &<#chassis as #rt::RecursiveModel<#dc>>::description(&#chassis),
                <#chassis as #rt::ChassisModel<#dc>>::PARTS,
                &<Self as #rt::Vehicle>::geometry(),
            );
            let laws = fit.laws(&#rt::DeclaredContact {
                ground: #ground,
                wheels: #wheels,
                sprocket: #sprocket_pair,
            });
            #rt::VehicleConfig::new(terrain, drive, arms, laws)
        },
        speed_drive: quote! {
            #rt::Drive::Speed {
                target: ::std::boxed::Box::new(target),
                proportional: #proportional,
                integral: #integral,
                max_torque: #max_torque,
            }
        },
        powertrain: run.powertrain.as_ref().map(powertrain),
    };
    let vehicle = vehicle_impl(name, (track, chassis), dofs, &bodies);
    quote! {
        #common
        #vehicle
    }
}

/// The bodies of a `Vehicle` impl's three methods.
pub struct VehicleBodies {
    pub geometry: TokenStream,
    pub config: TokenStream,
    pub speed_drive: TokenStream,
    /// The declared powertrain's value, if one is declared (the trait's
    /// default, none, otherwise).
    pub powertrain: Option<TokenStream>,
}

/// A declared powertrain as the runtime's `Powertrain::Converter`.
fn powertrain(p: &Powertrain) -> TokenStream {
    let rt = runtime();
    let table = |points: &[(crate::num::Num, crate::num::Num)]| {
        let (x, y): (Vec<_>, Vec<_>) = points.iter().map(|(x, y)| (x, y)).unzip();
        quote!(::std::vec![#((#x, #y)),*])
    };
    let (engine, capacity, torque_ratio) =
        (table(&p.engine), table(&p.capacity), table(&p.torque_ratio));
    let ranges = &p.ranges;
    let lockup = &p.lockup;
    let steer_ratios = &p.steer_ratios;
    let Powertrain {
        lockup_speed_ratio,
        final_drive,
        gearbox_efficiency,
        final_drive_efficiency,
        share,
        ..
    } = p;
    let shift = match &p.shift {
        Some((up, down, time)) => quote! {
            ::std::option::Option::Some(#rt::Shift {
                up: ::std::vec![#(#up),*],
                down: ::std::vec![#(#down),*],
                time: #time,
            })
        },
        None => quote!(::std::option::Option::None),
    };
    let reverse = match &p.reverse {
        Some(ratio) => quote!(::std::option::Option::Some(#ratio)),
        None => quote!(::std::option::Option::None),
    };
    let dynamics = match &p.dynamics {
        Some(d) => {
            let inertia = &d.inertia;
            let drag = table(&d.drag);
            let or = |value: &Option<crate::num::Num>, default: TokenStream| match value {
                Some(v) => quote!(#v),
                None => default,
            };
            let governor_time = or(&d.governor_time, quote!(#rt::EngineDynamics::GOVERNOR_TIME));
            let peak = p.engine.iter().map(|(_, t)| t);
            let lockup_capacity = or(
                &d.lockup_capacity,
                quote!(#rt::EngineDynamics::LOCKUP_MARGIN * [#(#peak),*].into_iter().fold(0.0, f64::max)),
            );
            let lockup_stiffness = or(
                &d.lockup_stiffness,
                quote!(#rt::EngineDynamics::lockup_stiffness_for(__engine_inertia)),
            );
            let lockup_damping = or(
                &d.lockup_damping,
                quote!(#rt::EngineDynamics::lockup_damping_for(
                    __engine_inertia,
                    __lockup_stiffness
                )),
            );
            quote! {
                ::std::option::Option::Some({
                    // The defaults of the driveline's compliance follow the
                    // declared inertia (named apart from the user's names).
                    let __engine_inertia: f64 = #inertia;
                    let __lockup_stiffness: f64 = #lockup_stiffness;
                    #rt::EngineDynamics {
                        inertia: __engine_inertia,
                        drag: #drag,
                        governor_time: #governor_time,
                        lockup_capacity: #lockup_capacity,
                        lockup_stiffness: __lockup_stiffness,
                        lockup_damping: #lockup_damping,
                    }
                })
            }
        }
        None => quote!(::std::option::Option::None),
    };
    quote! {
        #rt::Powertrain::Converter(::std::boxed::Box::new(#rt::Driveline {
            engine: #engine,
            capacity: #capacity,
            torque_ratio: #torque_ratio,
            ranges: ::std::vec![#(#ranges),*],
            lockup_ranges: ::std::vec![#(#lockup),*],
            lockup_speed_ratio: #lockup_speed_ratio,
            final_drive: #final_drive,
            gearbox_efficiency: #gearbox_efficiency,
            final_drive_efficiency: #final_drive_efficiency,
            share: #share,
            reverse: #reverse,
            shift: #shift,
            dynamics: #dynamics,
            steer_ratios: ::std::vec![#(#steer_ratios),*],
        }))
    }
}

/// The `Vehicle` impl of `name` with these method bodies (the real ones,
/// or a stub's after an error).
pub fn vehicle_impl(
    name: &Ident,
    (track, chassis): (&Ident, &Ident),
    (dt, dc): (usize, usize),
    bodies: &VehicleBodies,
) -> TokenStream {
    let rt = runtime();
    let system = quote::format_ident!("{}System", name);
    let label = name.to_string();
    let VehicleBodies {
        geometry,
        config,
        speed_drive,
        powertrain,
    } = bodies;
    let powertrain = powertrain.as_ref().map(|value| {
        quote! {
            fn powertrain() -> ::core::option::Option<#rt::Powertrain> {
                ::core::option::Option::Some(#value)
            }
        }
    });
    quote! {
        // Folded numbers (a default travel of ±π/2) may be close to a
        // named constant: they are meant as written.
        #[allow(clippy::approx_constant, unused_variables)]
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

            fn declared_config(terrain: #rt::Terrain, drive: #rt::Drive) -> #rt::VehicleConfig {
                #config
            }

            fn speed_drive(
                target: impl ::core::ops::Fn(f64) -> f64 + ::core::marker::Send + 'static,
            ) -> #rt::Drive {
                #speed_drive
            }

            #powertrain
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

/// A `DeclaredPair` literal: what the declaration gives, `None` for the
/// rest.
fn declared_pair(pair: &ContactPair) -> TokenStream {
    let rt = runtime();
    let option = |v: Option<TokenStream>| match v {
        Some(v) => quote!(::core::option::Option::Some(#v)),
        None => quote!(::core::option::Option::None),
    };
    let normal = option(pair.normal.as_ref().map(|law| match law {
        NormalLaw::HuntCrossley {
            stiffness,
            exponent,
            chi,
        } => quote! {
            #rt::NormalLaw::HuntCrossley { stiffness: #stiffness, exponent: #exponent, chi: #chi }
        },
        NormalLaw::KelvinVoigt { stiffness, damping } => quote! {
            #rt::NormalLaw::KelvinVoigt { stiffness: #stiffness, damping: #damping }
        },
    }));
    let number = |v: &Option<crate::num::Num>| option(v.as_ref().map(|v| quote!(#v)));
    let (mu, slip) = (number(&pair.mu), number(&pair.slip));
    let (stiffness, damping) = (
        number(&pair.tangential_stiffness),
        number(&pair.tangential_damping),
    );
    quote! {
        #rt::DeclaredPair {
            normal: #normal,
            mu: #mu,
            slip: #slip,
            tangential_stiffness: #stiffness,
            tangential_damping: #damping,
        }
    }
}
