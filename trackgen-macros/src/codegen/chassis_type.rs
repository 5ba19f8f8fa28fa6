//! A chassis type from a tree of the frame and the parts pinned to it: the
//! planar vehicle's chassis, or the spatial hull with both sides' parts.

use proc_macro2::{Ident, TokenStream};
use quote::{format_ident, quote};

use super::runtime_path::runtime;
use super::tree::Tree;
use crate::ir::{Part, PartKind, TreeBody, Vehicle};
use crate::num::{Num, Vec2};

/// What a chassis type is generated from: the planar chassis, or the
/// spatial hull with both sides' parts.
pub struct ChassisView<'a> {
    pub bodies: &'a [TreeBody],
    pub gravity: &'a Vec2,
    pub parts: &'a [Part],
    pub part_bodies: &'a [(usize, Option<usize>)],
    pub seat: &'a Vec2,
    pub hull: &'a [Vec2],
}

impl<'a> ChassisView<'a> {
    pub fn planar(vehicle: &'a Vehicle) -> ChassisView<'a> {
        ChassisView {
            bodies: &vehicle.chassis,
            gravity: &vehicle.gravity,
            parts: &vehicle.parts,
            part_bodies: &vehicle.part_bodies,
            seat: &vehicle.seat,
            hull: &vehicle.hull,
        }
    }
}

/// A chassis type `name`: its `RecursiveModel` and `ChassisModel`, and its
/// body-index constants.
pub fn chassis_type(
    vis: &syn::Visibility,
    doc: &str,
    name: &Ident,
    view: &ChassisView,
) -> TokenStream {
    let rt = runtime();
    let tree = Tree::new(view.bodies.to_vec(), view.gravity.clone(), None);
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
    let (seat_x, seat_y) = (&view.seat.x, &view.seat.y);
    let hull = view.hull.iter().map(|p| {
        let (x, y) = (&p.x, &p.y);
        quote!([#x, #y])
    });
    let indices = view.part_bodies;
    let parts = view.parts.iter().zip(indices).map(|(p, &(body, arm_body))| {
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
    let index_consts = view
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
