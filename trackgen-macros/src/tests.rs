//! Snapshots of what the compiler emits, formatted with prettyplease, so a
//! change in generated code is a reviewed diff. Update with
//! `INSTA_UPDATE=always cargo test -p trackgen-macros`, then read the diff.

use proc_macro2::TokenStream;
use quote::quote;

use crate::expand::expand;

fn pretty(tokens: TokenStream) -> String {
    let file: syn::File = syn::parse2(tokens).expect("the expansion parses as Rust items");
    prettyplease::unparse(&file)
}

#[test]
fn open_chain_3_links() {
    insta::assert_snapshot!(pretty(expand(quote! {
        /// Three links, open.
        pub track Open3 {
            links: 3,
            link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
            link[2] { mass: 20.0, u1: (-0.0535, 0.01) },
            closure: open,
        }
    })));
}

#[test]
fn closed_chain_4_links() {
    insta::assert_snapshot!(pretty(expand(quote! {
        /// Four identical links, closed by partitioning.
        pub track Closed4 {
            links: 4,
            link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
            closure: partitioned,
        }
    })));
}

#[test]
fn penalty_chain_with_named_constants() {
    insta::assert_snapshot!(pretty(expand(quote! {
        pub track Penalty3 {
            links: 3,
            link { mass: SHOE_MASS, inertia: 0.04, u1: (-PITCH / 2.0, 0.0), u2: (PITCH / 2.0, 0.0) },
            closure: penalty { stiffness: 1e6, damping: 50.0 },
        }
    })));
}

#[test]
fn small_vehicle() {
    insta::assert_snapshot!(pretty(expand(quote! {
        /// Sprocket, one road wheel, idler; a 3-link track.
        pub vehicle Small {
            chassis { mass: 1000.0, inertia: 500.0, centroid: (-1.0, 0.4) },
            sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 10 },
            road_wheel rw1 { at: (-1.0, -0.2), mass: 35.56, inertia: 2.16, radius: 0.305 },
            idler rear { at: (-2.0, 0.0), mass: 25.76, inertia: 1.12, radius: 0.255 },
            track {
                links: 3,
                link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
                closure: open,
            },
        }
    })));
}

#[test]
fn vehicle_with_a_sprung_road_wheel() {
    insta::assert_snapshot!(pretty(expand(quote! {
        /// A road wheel on a trailing arm: a two-level chassis tree.
        pub vehicle Sprung {
            chassis { mass: 1000.0, inertia: 500.0 },
            road_wheel rw1 { at: (-1.0, -0.2), mass: 35.56, inertia: 2.16, radius: 0.305,
                arm { pivot: (-0.712, -0.066), mass: 75.26, inertia: 0.77,
                      stiffness: 2.5e4, damping: 500.0, preload: 1e4 } },
            track {
                links: 3,
                link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
                closure: open,
            },
        }
    })));
}

#[test]
fn errors_expand_to_compile_errors_and_stubs() {
    let out = expand(quote! {
        pub track Broken {
            links: 4,
            link { mass: -1.0, inertia: 0.04, u1: (0.0, 0.0), u2: (0.0, 0.0) },
        }
    });
    insta::assert_snapshot!(out.to_string());
}
