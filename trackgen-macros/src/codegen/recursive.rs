//! The `RecursiveModel` impl of a tree: the method shells around the
//! statements [`Tree`] generates.

use proc_macro2::{Ident, TokenStream};
use quote::quote;

use super::runtime_path::runtime;
use super::scopes::shallow_scopes;
use super::tree::Tree;

/// `impl RecursiveModel<DOF> for name`. `extra_potential` adds to the
/// gravity potential (the penalty spring's energy), with the trig bound.
pub fn recursive_impl(
    name: &Ident,
    tree: &Tree,
    loop_joint: TokenStream,
    extra_potential: Option<TokenStream>,
    tree_dynamics: TokenStream,
) -> TokenStream {
    let rt = runtime();
    let shell = Shell::new(tree, &rt);
    let dof = shell.dof;
    let n = tree.len();
    let description = tree.description(&rt, loop_joint);
    let kinematics = kinematics(tree, &shell);
    let dynamics = dynamics(tree, &shell, extra_potential, tree_dynamics);
    quote! {
        #[allow(unused_variables, clippy::all, clippy::pedantic)]
        impl #rt::RecursiveModel<#dof> for #name {
            const BODIES: usize = #n;

            fn description(&self) -> #rt::TreeDescription {
                #description
            }

            #kinematics
            #dynamics
        }
    }
}

/// What every method shell of a tree's impl shares: the runtime's path,
/// the coordinates' count, the arguments' types and the statements that
/// open most bodies.
struct Shell {
    rt: TokenStream,
    n: usize,
    dof: usize,
    /// `q: &SVector<f64, DOF>`.
    q: TokenStream,
    /// `qd: &SVector<f64, DOF>`.
    qd: TokenStream,
    /// `out: &mut [Vector2<f64>]`.
    vec_out: TokenStream,
    /// The sines and cosines of the tree's angles.
    trig: TokenStream,
    /// The joints' rates.
    rates: TokenStream,
    /// The bodies' positions.
    positions: TokenStream,
    /// The bodies' velocities.
    velocities: TokenStream,
}

impl Shell {
    fn new(tree: &Tree, rt: &TokenStream) -> Shell {
        let n = tree.len();
        let dof = n + 2;
        Shell {
            rt: rt.clone(),
            n,
            dof,
            q: quote!(q: &#rt::nalgebra::SVector<f64, #dof>),
            qd: quote!(qd: &#rt::nalgebra::SVector<f64, #dof>),
            vec_out: quote!(out: &mut [#rt::nalgebra::Vector2<f64>]),
            trig: tree.trig_prelude(),
            rates: tree.rate_prelude(false),
            positions: tree.positions(),
            velocities: tree.velocities(),
        }
    }
}

/// The kinematic methods: the bodies' positions, velocities (with or
/// without the trig given) and velocity terms `γ`.
fn kinematics(tree: &Tree, shell: &Shell) -> TokenStream {
    let Shell {
        rt,
        n,
        q,
        qd,
        vec_out,
        trig,
        rates,
        positions,
        velocities,
        ..
    } = shell;
    let trig_given = tree.trig_from_slice();
    let terms = tree.velocity_terms();
    let rates_squared = tree.rate_prelude(true);
    let store_r = tree.store("r", rt);
    let store_v = tree.store("v", rt);
    let store_g = tree.store("g", rt);
    let check_out = quote!(::core::assert_eq!(out.len(), #n, "one entry per body"););
    // Straight-line bodies, thousands of `let`s long for a large track:
    // flat scopes (see `flatten`).
    let body_positions = shallow_scopes(quote! { #check_out #trig #positions #store_r });
    let body_velocities = shallow_scopes(quote! { #check_out #trig #rates #velocities #store_v });
    let body_states_with_trig = shallow_scopes(quote! {
        ::core::assert_eq!(trig.len(), #n, "one entry per body");
        ::core::assert_eq!(positions.len(), #n, "one entry per body");
        ::core::assert_eq!(velocities.len(), #n, "one entry per body");
        #trig_given
        #rates
        #positions
        #velocities
        {
            let out = positions;
            #store_r
        }
        {
            let out = velocities;
            #store_v
        }
    });
    let velocity_terms = shallow_scopes(quote! { #check_out #trig #rates_squared #terms #store_g });
    quote! {
        #[inline]
        fn body_positions(&self, #q, #vec_out) {
            #body_positions
        }

        #[inline]
        fn body_velocities(&self, #q, #qd, #vec_out) {
            #body_velocities
        }

        #[inline]
        fn body_states(
            &self,
            #q,
            #qd,
            positions: &mut [#rt::nalgebra::Vector2<f64>],
            velocities: &mut [#rt::nalgebra::Vector2<f64>],
        ) {
            let mut trig = [(0.0f64, 1.0f64); #n];
            #rt::sin_cos_each(&q.as_slice()[2..], &mut trig);
            self.body_states_with_trig(&trig, q, qd, positions, velocities);
        }

        #[inline]
        fn body_states_with_trig(
            &self,
            trig: &[(f64, f64)],
            #q,
            #qd,
            positions: &mut [#rt::nalgebra::Vector2<f64>],
            velocities: &mut [#rt::nalgebra::Vector2<f64>],
        ) {
            #body_states_with_trig
        }

        #[inline]
        fn velocity_terms(&self, #q, #qd, #vec_out) {
            #velocity_terms
        }
    }
}

/// The dynamic methods: the mass matrix, the generalized forces, both
/// together, the tree's O(n) dynamics (`tree_dynamics`, given) and the
/// energies (`extra_potential` added to gravity's).
fn dynamics(
    tree: &Tree,
    shell: &Shell,
    extra_potential: Option<TokenStream>,
    tree_dynamics: TokenStream,
) -> TokenStream {
    let Shell {
        rt,
        n,
        dof,
        q,
        qd,
        trig,
        rates,
        positions,
        velocities,
        ..
    } = shell;
    let mass = tree.mass_matrix();
    let forces = tree.generalized_forces();
    let kinetic = tree.kinetic_energy();
    let potential = tree.gravity_potential();
    let extra_potential = extra_potential.map(|e| quote!(+ #e));
    let loads = loads_or_zero(*n, rt);
    let mass_matrix = shallow_scopes(quote! { #trig #mass });
    let generalized_forces = shallow_scopes(quote! { #loads #trig #forces });
    let equations_of_motion = shallow_scopes(quote! {
        #loads
        #trig
        {
            let out = mass;
            #mass
        }
        {
            let out = forces;
            #forces
        }
    });
    let kinetic_energy = shallow_scopes(quote! { #trig #rates #velocities #kinetic });
    let potential_energy = shallow_scopes(quote! { #trig #positions #potential #extra_potential });
    quote! {
        #[inline]
        fn mass_matrix(&self, #q, out: &mut #rt::nalgebra::SMatrix<f64, #dof, #dof>) {
            #mass_matrix
        }

        #[inline]
        fn generalized_forces(
            &self,
            #q,
            #qd,
            loads: &[#rt::BodyLoad],
            out: &mut #rt::nalgebra::SVector<f64, #dof>,
        ) {
            #generalized_forces
        }

        #[inline]
        fn equations_of_motion(
            &self,
            #q,
            #qd,
            loads: &[#rt::BodyLoad],
            mass: &mut #rt::nalgebra::SMatrix<f64, #dof, #dof>,
            forces: &mut #rt::nalgebra::SVector<f64, #dof>,
        ) {
            #equations_of_motion
        }

        fn tree_dynamics(
            &self,
            trig: &[(f64, f64)],
            #qd,
            loads: &[#rt::BodyLoad],
            qdd: &mut #rt::nalgebra::SVector<f64, #dof>,
        ) -> ::core::result::Result<(), #rt::DynamicsError> {
            #tree_dynamics
        }

        fn kinetic_energy(&self, #q, #qd) -> f64 {
            #kinetic_energy
        }

        fn potential_energy(&self, #q) -> f64 {
            #potential_energy
        }
    }
}

/// `loads` rebound as `n` bodies' loads: missing loads are zero loads; a
/// slice of another length is a bug.
pub(super) fn loads_or_zero(n: usize, rt: &TokenStream) -> TokenStream {
    quote! {
        let no_loads = [#rt::BodyLoad::ZERO; #n];
        let loads: &[#rt::BodyLoad] = if loads.is_empty() {
            &no_loads
        } else {
            ::core::assert_eq!(loads.len(), #n, "one load per body, or none");
            loads
        };
    }
}
