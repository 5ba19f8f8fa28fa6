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
        /// Sprocket, one road wheel, idler; a 3-link track; a hull.
        pub vehicle Small {
            hull: [(0.3, -0.1), (0.3, 0.6), (-2.3, 0.6), (-2.3, -0.1)],
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

#[test]
fn runnable_vehicle_with_repeated_wheels() {
    insta::assert_snapshot!(pretty(expand(quote! {
        /// Two road wheels from one block, a shoe, a partly declared
        /// profile, one contact pair and the drive gains.
        pub vehicle Runner {
            chassis { mass: 1000.0, inertia: 500.0, centroid: (-1.0, 0.3) },
            sprocket drive { at: (0.0, 0.0), mass: 20.0, inertia: 0.5, radius: 0.2, teeth: 9,
                tip_radius: TIP },
            road_wheel rw[2] { at: [(-0.5, -0.2), (-1.0, -0.2)], mass: 30.0, inertia: 1.5, radius: 0.25,
                arm { pivot_offset: (0.25, 0.1), mass: 40.0, inertia: 0.5,
                      stiffness: 2e4, damping: 400.0 } },
            idler rear { at: (-1.6, 0.0), mass: 20.0, inertia: 1.0, radius: 0.2 },
            track {
                links: 3,
                link { mass: 10.0, inertia: 0.02, u1: (-0.06, 0.0), u2: (0.06, 0.0) },
            },
            shoe { ground_points: [(-0.05, -0.025), (0.05, -0.025)], inner_offset: 0.025,
                   pins: [(0.0, 0.0)], pin_radius: 0.012 },
            contact { ground { stiffness: 1e6, chi: 1.0, mu: 0.7 }, sprocket { stiffness: 5e6, damping: 1e3 } },
            drive { max_torque: 5e3 },
        }
    })));
}

/// A declared powertrain becomes the `Vehicle::powertrain` the runtime's
/// `Driveline` is built from: the tables as pairs, the lock-up ranges
/// 0-based, the side's share defaulting to a half, a named constant kept
/// for rustc (and checked by it), and a shift schedule.
#[test]
fn vehicle_with_a_powertrain() {
    insta::assert_snapshot!(pretty(expand(quote! {
        pub vehicle Driven {
            chassis { mass: 1000.0, inertia: 500.0, centroid: (-1.0, 0.3) },
            sprocket drive { at: (0.0, 0.0), mass: 20.0, inertia: 0.5, radius: 0.2, teeth: 9 },
            road_wheel rw[2] { at: [(-0.5, -0.2), (-1.0, -0.2)], mass: 30.0, inertia: 1.5, radius: 0.25,
                arm { pivot_offset: (0.25, 0.1), mass: 40.0, inertia: 0.5,
                      stiffness: 2e4, damping: 400.0 } },
            idler rear { at: (-1.6, 0.0), mass: 20.0, inertia: 1.0, radius: 0.2 },
            track {
                links: 3,
                link { mass: 10.0, inertia: 0.02, u1: (-0.06, 0.0), u2: (0.06, 0.0) },
            },
            shoe { ground_points: [(-0.05, -0.025), (0.05, -0.025)], inner_offset: 0.025,
                   pins: [(0.055, 0.0)], pin_radius: 0.012 },
            powertrain {
                engine: [(100.0, 500.0), (200.0, 600.0), (300.0, 0.0)],
                capacity: [(0.0, 9.0), (1.0, 18.0)],
                torque_ratio: [(0.0, 2.5), (0.8, 1.0), (1.0, 1.0)],
                ranges: [3.0, 1.5],
                reverse: 4.0,
                lockup: [2],
                lockup_speed_ratio: 0.9,
                final_drive: FINAL,
                gearbox_efficiency: 0.95,
                final_drive_efficiency: 0.97,
                upshift: [250.0, 0.0],
                downshift: [0.0, 100.0],
                shift_time: 0.4,
                engine_inertia: 0.8,
                engine_drag: [(0.0, 0.0), (300.0, -40.0)],
                governor_time: 0.05,
                steer_ratios: [2.0, 1.5],
            },
        }
    })));
}

/// Each user expression is emitted once, as a named constant, however many
/// links or generated places use it (issue 12: a bad expression copied into
/// every generated place made a 64-link error path take minutes). Each of
/// the 32 links gets its own expression `np(k)`, and the shared ones are
/// `PITCH`-based: the ident `np` appears exactly once per expression, and
/// `PITCH` once per distinct joint expression.
#[test]
fn each_user_expression_is_emitted_once() {
    let mut overrides = TokenStream::new();
    for k in 1..=32usize {
        let value = k as f64 + 0.5;
        overrides.extend(quote! { link[#k] { mass: np(#value), inertia: np(0.04 * #value) }, });
    }
    let out = expand(quote! {
        pub track Pasted {
            links: 32,
            link { mass: 1.0, inertia: 0.1, u1: (-PITCH / 2.0, 0.0), u2: (PITCH / 2.0, 0.0) },
            #overrides
            closure: partitioned,
        }
    });
    fn count(tokens: TokenStream, name: &str) -> usize {
        tokens
            .into_iter()
            .map(|t| match t {
                proc_macro2::TokenTree::Ident(i) => usize::from(i == name),
                proc_macro2::TokenTree::Group(g) => count(g.stream(), name),
                _ => 0,
            })
            .sum()
    }
    assert_eq!(
        count(out.clone(), "np"),
        64,
        "each of the 64 expressions once"
    );
    assert_eq!(
        count(out, "PITCH"),
        2,
        "each of the two joint expressions once"
    );
}

/// A `tracks` block: the hull with both sides' parts (the left's road
/// wheels moved, their arms with them), a left track one link shorter
/// (its link override still in range), the links' declared inertia across
/// the plane and the parts' by the default rule, and the layout.
#[test]
fn vehicle_with_two_tracks() {
    insta::assert_snapshot!(pretty(expand(quote! {
        pub vehicle Twin {
            chassis { mass: 1000.0, inertia: 500.0, centroid: (-1.0, 0.3) },
            sprocket drive { at: (0.0, 0.0), mass: 20.0, inertia: 0.5, radius: 0.2, teeth: 9 },
            road_wheel rw[2] { at: [(-0.5, -0.2), (-1.0, -0.2)], mass: 30.0, inertia: 1.5, radius: 0.25,
                arm { pivot_offset: (0.25, 0.1), mass: 40.0, inertia: 0.5,
                      stiffness: 2e4, damping: 400.0 } },
            idler rear { at: (-1.6, 0.0), mass: 20.0, inertia: 1.0, radius: 0.2 },
            track {
                links: 4,
                link { mass: 10.0, inertia: 0.02, u1: (-0.06, 0.0), u2: (0.06, 0.0) },
                link[2] { mass: 11.0 },
            },
            shoe { ground_points: [(-0.05, -0.025), (0.05, -0.025)], inner_offset: 0.025,
                   pins: [(0.055, 0.0)], pin_radius: 0.012, width: 0.3 },
            tracks {
                gauge: GAUGE,
                guide_play: 0.01,
                hull { mass: 2000.0, inertia: (600.0, 1000.0, 1200.0) },
                across { rw_arm: (0.3, 0.4, 0.1) },
                left { links: 3, rw { at: [(-0.45, -0.2), (-0.95, -0.2)] } },
            },
        }
    })));
}

/// After an error in a `tracks` block, the stubs still hold `NameHull`
/// with its parts' constants, `NameLeftTrack` and the `SpatialVehicle`
/// impl: code naming them reports only the real error.
#[test]
fn tracks_errors_expand_to_stubs() {
    let out = expand(quote! {
        pub vehicle Twin {
            chassis { mass: 1000.0, inertia: 500.0 },
            road_wheel rw1 { at: (-1.0, -0.2), mass: 35.56, inertia: 2.16, radius: 0.305 },
            track {
                links: 4,
                link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
            },
            shoe { ground_points: [(-0.05, -0.025)], inner_offset: 0.025,
                   pins: [(0.0, 0.0)], pin_radius: 0.012, width: 0.4 },
            tracks {
                gauge: 0.3,
                hull { mass: 2000.0, inertia: (600.0, 1000.0, 1200.0) },
                left { links: 3 },
            },
        }
    })
    .to_string();
    assert!(out.contains("compile_error"), "{out}");
    assert!(out.contains("must exceed the track's width"), "{out}");
    for stub in [
        "struct TwinHull",
        "struct TwinLeftTrack",
        "SpatialVehicle for Twin",
        "RIGHT_RW1",
        "LEFT_RW1",
    ] {
        assert!(out.contains(stub), "no `{stub}` among the stubs: {out}");
    }
}
