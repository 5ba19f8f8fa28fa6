//! Property tests of the whole expansion (parse → validate → codegen) on
//! `proc_macro2` tokens: whatever the input, the expander never panics,
//! and returns either code that parses as Rust items or `compile_error!`s.
//!
//! Three sources of input: declarations built from the grammar with random
//! keys (valid and wrong), numbers (NaN, infinities, negatives, huge,
//! suffixed, constant expressions), link counts (0 … 1100), selectors
//! (empty, reversed, out of range, huge), arms and parts (repeated ones
//! too), shoes, contact pairs and drives; such declarations
//! with tokens deleted, duplicated or replaced; and random token trees.
//! Errors on declarations from the grammar must point at a token of the
//! input, not at the macro call (`check_spanned`; spans carry locations
//! here through proc-macro2's `span-locations`, a dev-dependency feature).
//! The case counts keep the run to a few seconds.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::str::FromStr;

use proc_macro2::{Delimiter, Group, Ident, Literal, Punct, Spacing, Span, TokenStream, TokenTree};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

use crate::expand::expand;

/// Expands `input` and checks the outcome.
fn check(input: TokenStream) -> Result<(), TestCaseError> {
    let text = input.to_string();
    let out = catch_unwind(AssertUnwindSafe(|| expand(input)))
        .map_err(|_| TestCaseError::fail(format!("the expander panicked on: {text}")))?;
    let errors = compile_errors(&out);
    if errors.is_empty() {
        syn::parse2::<syn::File>(out).map_err(|e| {
            TestCaseError::fail(format!("the expansion is not Rust items ({e}) for: {text}"))
        })?;
    } else {
        for message in errors {
            prop_assert!(
                !message.is_empty(),
                "a compile_error! without a message for: {}",
                text
            );
        }
    }
    Ok(())
}

/// Expands `text`, lexed after a leading newline so that no token of it
/// starts where `Span::call_site()` reports (line 1, column 0), and checks
/// the outcome as [`check`] does, and also that every error points into
/// the input: a token span on line 2 or later, never the call site (which
/// the user would see as an error on the whole macro call).
fn check_spanned(text: &str) -> Result<(), TestCaseError> {
    let tokens = TokenStream::from_str(&format!("\n{text}")).expect("generated text lexes");
    let out = catch_unwind(AssertUnwindSafe(|| expand(tokens.clone())))
        .map_err(|_| TestCaseError::fail(format!("the expander panicked on: {text}")))?;
    for span in error_spans(&out) {
        prop_assert!(
            span.start().line >= 2 && !span.byte_range().is_empty(),
            "an error at the call site ({:?}) for: {}",
            span.start(),
            text
        );
    }
    check(tokens)
}

/// The span of every `compile_error` in `tokens` (where the compiler shows
/// the error), nested groups included.
fn error_spans(tokens: &TokenStream) -> Vec<Span> {
    let mut out = Vec::new();
    for t in tokens.clone() {
        match t {
            TokenTree::Ident(id) if id == "compile_error" => out.push(id.span()),
            TokenTree::Group(g) => out.extend(error_spans(&g.stream())),
            _ => {}
        }
    }
    out
}

/// The message of every `compile_error!` in `tokens`, nested groups
/// included.
fn compile_errors(tokens: &TokenStream) -> Vec<String> {
    let mut out = Vec::new();
    let tokens: Vec<TokenTree> = tokens.clone().into_iter().collect();
    for (i, t) in tokens.iter().enumerate() {
        match t {
            TokenTree::Ident(id) if id == "compile_error" => {
                let message = match tokens.get(i + 2) {
                    Some(TokenTree::Group(g)) => g.stream().to_string(),
                    _ => String::new(),
                };
                let message = message.trim_matches(|c| c == '"' || c == ' ').to_string();
                out.push(message);
            }
            TokenTree::Group(g) => out.extend(compile_errors(&g.stream())),
            _ => {}
        }
    }
    out
}

// ---------------------------------------------------------------------------
// Declarations from the grammar.

fn number() -> impl Strategy<Value = String> {
    let special = prop_oneof![
        Just("0.0"),
        Just("-0.0"),
        Just("1e308"),
        Just("-1e308"),
        Just("1e999"),
        Just("1e-320"),
        Just("f64::NAN"),
        Just("f64::INFINITY"),
        Just("-f64::INFINITY"),
        Just("f64::MAX * 2.0"),
        Just("1.0 / 0.0"),
        Just("0.0 / 0.0"),
        Just("SHOE_MASS"),
        Just("PITCH / 2.0"),
        Just("-PITCH / 2.0 + 0.01"),
        Just("np.float64(32.5)"),
        Just("const { 2.0 }"),
        Just("{ 1.0 }"),
        Just("(1.5)"),
        Just("1.0f32"),
        Just("2.5f64"),
        Just("3u8"),
        Just("7"),
        Just("99999999999999999999999999"),
        Just("\"heavy\""),
        Just("1.0 % 2.0"),
        Just("true"),
        Just("[1.0][0]"),
        Just("-(-1.0)"),
        Just("x as f64"),
        Just("(1.0, 2.0)"),
    ]
    .prop_map(str::to_string);
    prop_oneof![
        4 => (0.001f64..100.0).prop_map(|v| format!("{v:?}")),
        2 => (-1e3f64..1e3).prop_map(|v| format!("{v:?}")),
        3 => special,
    ]
}

fn point() -> impl Strategy<Value = String> {
    prop_oneof![
        6 => (number(), number()).prop_map(|(x, y)| format!("({x}, {y})")),
        3 => (-0.2f64..0.2, -0.2f64..0.2).prop_map(|(x, y)| format!("({x:?}, {y:?})")),
        1 => number(),
        1 => (number(), number(), number()).prop_map(|(x, y, z)| format!("({x}, {y}, {z})")),
        1 => Just("()".to_string()),
    ]
}

/// Lists of points: mostly lists, sometimes empty, a point or a number.
fn points() -> impl Strategy<Value = String> {
    prop_oneof![
        6 => prop::collection::vec(point(), 0..4).prop_map(|p| format!("[{}]", p.join(", "))),
        1 => point(),
        1 => Just("[1.0, 2.0]".to_string()),
    ]
}

/// A `shoe`, `contact` or `drive` section, valid or not.
fn running_section() -> impl Strategy<Value = String> {
    let shoe = fields(vec![
        ("ground_points", points().boxed()),
        ("inner_offset", number().boxed()),
        ("pins", points().boxed()),
        ("pin_radius", number().boxed()),
    ])
    .prop_map(|f| format!("shoe {}", block(f, true)));
    let pair = (
        prop_oneof![
            Just("ground"),
            Just("wheels"),
            Just("sprocket"),
            Just("tyres")
        ],
        fields(vec![
            ("stiffness", number().boxed()),
            ("exponent", number().boxed()),
            ("chi", number().boxed()),
            ("damping", number().boxed()),
            ("mu", number().boxed()),
            ("slip", number().boxed()),
        ]),
    )
        .prop_map(|(kind, f)| format!("{kind} {}", block(f, false)));
    let contact = prop::collection::vec(pair, 0..4)
        .prop_map(|pairs| format!("contact {}", block(pairs, true)));
    let drive = fields(vec![
        ("proportional", number().boxed()),
        ("integral", number().boxed()),
        ("max_torque", number().boxed()),
    ])
    .prop_map(|f| format!("drive {}", block(f, false)));
    prop_oneof![shoe, contact, drive]
}

/// Integers for counts, link numbers, teeth: mostly small.
fn integer() -> impl Strategy<Value = String> {
    prop_oneof![
        12 => (0usize..12).prop_map(|n| n.to_string()),
        1 => (1000usize..1100).prop_map(|n| n.to_string()),
        1 => prop_oneof![
            Just("99999999999999999999999"),
            Just("4294967296"),
            Just("18446744073709551615"),
            Just("8u8"),
            Just("8usize"),
            Just("10u32"),
            Just("4.5"),
            Just("-3"),
            Just("N"),
            Just("0x10"),
            Just("1_0"),
        ]
        .prop_map(str::to_string),
    ]
}

/// `key: value` entries, each key present with some probability, plus
/// now and then a wrong or repeated key.
fn fields(keys: Vec<(&'static str, BoxedStrategy<String>)>) -> BoxedStrategy<Vec<String>> {
    let present: Vec<BoxedStrategy<Option<String>>> = keys
        .into_iter()
        .map(|(key, value)| {
            proptest::option::weighted(0.85, value.prop_map(move |v| format!("{key}: {v}"))).boxed()
        })
        .collect();
    let extra = proptest::option::weighted(
        0.15,
        (
            prop_oneof![
                Just("mass"),
                Just("colour"),
                Just("links"),
                Just("teeth"),
                Just("u3")
            ],
            number(),
        )
            .prop_map(|(k, v)| format!("{k}: {v}")),
    );
    (present, extra)
        .prop_map(|(present, extra)| present.into_iter().flatten().chain(extra).collect())
        .boxed()
}

fn block(entries: Vec<String>, trailing: bool) -> String {
    let mut body = entries.join(", ");
    if trailing && !body.is_empty() {
        body.push(',');
    }
    format!("{{ {body} }}")
}

fn range() -> impl Strategy<Value = String> {
    prop_oneof![
        3 => integer(),
        2 => (integer(), integer()).prop_map(|(a, b)| format!("{a}..{b}")),
        2 => (integer(), integer()).prop_map(|(a, b)| format!("{a}..={b}")),
        2 => (integer(), integer(), integer()).prop_map(|(a, b, k)| format!("{a}..={b} by {k}")),
        1 => (integer(), integer(), integer()).prop_map(|(a, b, k)| format!("{a}..{b} by {k}")),
    ]
}

fn link_section() -> impl Strategy<Value = String> {
    let selector = prop_oneof![
        3 => Just(String::new()),
        4 => prop::collection::vec(range(), 1..3).prop_map(|r| format!("[{}]", r.join(", "))),
        1 => Just("[]".to_string()),
    ];
    let body = fields(vec![
        ("mass", number().boxed()),
        ("inertia", number().boxed()),
        ("u1", point().boxed()),
        ("u2", point().boxed()),
    ]);
    (selector, body, any::<bool>())
        .prop_map(|(sel, body, trailing)| format!("link{sel} {}", block(body, trailing)))
}

fn closure() -> impl Strategy<Value = String> {
    prop_oneof![
        Just("open".to_string()),
        Just("partitioned".to_string()),
        (number(), number())
            .prop_map(|(k, c)| format!("penalty {{ stiffness: {k}, damping: {c} }}")),
        number().prop_map(|k| format!("penalty {{ stiffness: {k}, spring: 1.0 }}")),
        Just("closed".to_string()),
    ]
}

/// The body of a `track` (standalone or in a vehicle).
fn track_body() -> impl Strategy<Value = String> {
    (
        fields(vec![
            ("links", integer().boxed()),
            ("closure", closure().boxed()),
            ("gravity", point().boxed()),
        ]),
        prop::collection::vec(link_section(), 0..4),
        // The template first, usually.
        proptest::option::weighted(
            0.8,
            (-0.2f64..-0.01, 0.01f64..0.2, 1.0f64..30.0).prop_map(|(a, b, m)| {
                format!("link {{ mass: {m:?}, inertia: 0.04, u1: ({a:?}, 0.0), u2: ({b:?}, 0.0) }}")
            }),
        ),
        any::<bool>(),
    )
        .prop_map(|(fields, links, template, trailing)| {
            let entries: Vec<String> = fields.into_iter().chain(template).chain(links).collect();
            block(entries, trailing)
        })
}

fn arm() -> impl Strategy<Value = String> {
    let body = fields(vec![
        ("pivot", point().boxed()),
        ("pivot_offset", point().boxed()),
        ("mass", number().boxed()),
        ("inertia", number().boxed()),
        ("stiffness", number().boxed()),
        ("damping", number().boxed()),
        ("preload", number().boxed()),
        ("travel", point().boxed()),
    ]);
    (body, any::<bool>()).prop_map(|(b, t)| format!("arm {}", block(b, t)))
}

fn part() -> impl Strategy<Value = String> {
    let kind = prop_oneof![
        Just("sprocket"),
        Just("idler"),
        Just("road_wheel"),
        Just("roller"),
        Just("wheel"),
    ];
    let name = prop_oneof![
        Just("drive"),
        Just("rw1"),
        Just("rw2"),
        Just("rear"),
        Just("chassis"),
        Just("FRAME"),
        Just(""),
    ];
    let body = fields(vec![
        ("at", point().boxed()),
        ("mass", number().boxed()),
        ("inertia", number().boxed()),
        ("radius", number().boxed()),
        ("teeth", integer().boxed()),
        ("tip_radius", number().boxed()),
        ("gap_radius", number().boxed()),
        ("gap_centre", number().boxed()),
    ]);
    // `name[count]` with `at` a list.
    let repeat = proptest::option::weighted(0.3, (integer(), points()));
    (
        kind,
        name,
        (body, repeat).prop_map(|(mut body, repeat)| match repeat {
            Some((n, at)) => {
                body.retain(|f| !f.starts_with("at:"));
                body.push(format!("at: {at}"));
                (format!("[{n}]"), body)
            }
            None => (String::new(), body),
        }),
        prop::collection::vec(arm(), 0..3),
        // An arm whose pivot is the part's centre.
        proptest::option::weighted(0.1, Just(())),
    )
        .prop_map(|(kind, name, (count, mut body), arms, centred)| {
            if centred.is_some() {
                body.retain(|f| !f.starts_with("at:"));
                body.push("at: (-1.0, -0.2)".to_string());
                body.push(
                    "arm { pivot: (-1.0, -0.2), mass: 5.0, inertia: 0.1, stiffness: 1.0, damping: 0.0 }"
                        .to_string(),
                );
            }
            body.extend(arms);
            format!("{kind} {name}{count} {}", block(body, false))
        })
}

fn vehicle_body() -> impl Strategy<Value = String> {
    (
        proptest::option::weighted(0.2, point().prop_map(|g| format!("gravity: {g}"))),
        proptest::option::weighted(
            0.85,
            fields(vec![
                ("mass", number().boxed()),
                ("inertia", number().boxed()),
                ("centroid", point().boxed()),
            ])
            .prop_map(|f| format!("chassis {}", block(f, false))),
        ),
        prop::collection::vec(part(), 0..5),
        proptest::option::weighted(0.85, track_body().prop_map(|t| format!("track {t}"))),
        proptest::option::weighted(0.05, Just("track { links: 3 }".to_string())),
        prop::collection::vec(running_section(), 0..4),
    )
        .prop_map(|(gravity, chassis, parts, track, extra, running)| {
            let entries: Vec<String> = gravity
                .into_iter()
                .chain(chassis)
                .chain(parts)
                .chain(track)
                .chain(extra)
                .chain(running)
                .collect();
            block(entries, true)
        })
}

fn item() -> impl Strategy<Value = String> {
    let head = (
        prop_oneof![Just(""), Just("/// Docs.\n"), Just("#[derive(Debug)]\n")],
        prop_oneof![Just("pub "), Just(""), Just("pub(crate) ")],
        prop_oneof![Just("Chain"), Just("Tank"), Just("Other")],
    );
    (
        head,
        prop_oneof![
            5 => track_body().prop_map(|b| ("track", b)),
            4 => vehicle_body().prop_map(|b| ("vehicle", b)),
            1 => track_body().prop_map(|b| ("tank", b)),
        ],
    )
        .prop_map(|((doc, vis, name), (kind, body))| format!("{doc}{vis}{kind} {name} {body}"))
}

fn declaration() -> impl Strategy<Value = String> {
    prop::collection::vec(item(), 1..3).prop_map(|items| items.join("\n"))
}

// ---------------------------------------------------------------------------
// Valid declarations: every value in range, named constants among them.

fn tame_number() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => (0.01f64..100.0).prop_map(|v| format!("{v:?}")),
        1 => prop_oneof![
            Just("SHOE_MASS"),
            Just("2.0 * SHOE_MASS"),
            Just("const { 2.0 }"),
            Just("shoe::HEAVY / 3.0"),
            Just("1.5f64"),
            Just("7"),
            // Valid, but sums of them overflow to infinity (the generated
            // code spells it `f64::INFINITY`) or products underflow.
            Just("1e308"),
            Just("1e-300"),
        ]
        .prop_map(str::to_string),
    ]
}

/// A link's joints, never coincident: `u1` behind, `u2` ahead.
fn tame_joints() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => (-0.2f64..-0.01, -0.05f64..0.05, 0.01f64..0.2, -0.05f64..0.05)
            .prop_map(|(a, b, c, d)| format!("u1: ({a:?}, {b:?}), u2: ({c:?}, {d:?})")),
        1 => Just("u1: (-PITCH / 2.0, 0.0), u2: (PITCH / 2.0, 0.0)".to_string()),
    ]
}

/// A track of 3 … 12 links, closed or not, with overrides inside it (the
/// largest size is [`the_largest_declaration_expands_to_code`]'s).
fn tame_track() -> impl Strategy<Value = String> {
    let links = 3usize..=12;
    let closure = prop_oneof![
        Just("open".to_string()),
        Just("partitioned".to_string()),
        (tame_number(), tame_number())
            .prop_map(|(k, c)| format!("penalty {{ stiffness: {k}, damping: {c} }}")),
    ];
    let link_override = (
        0usize..3,
        tame_number(),
        tame_number(),
        tame_joints(),
        1usize..4,
        any::<bool>(),
    );
    (
        links,
        closure,
        tame_number(),
        tame_number(),
        tame_joints(),
        prop::collection::vec(link_override, 0..3),
    )
        .prop_map(|(n, closure, mass, inertia, joints, overrides)| {
            let mut entries = vec![
                format!("links: {n}"),
                format!("closure: {closure}"),
                format!("link {{ mass: {mass}, inertia: {inertia}, {joints} }}"),
            ];
            for (kind, m, j, uv, k, inclusive) in overrides {
                let selector = match (kind, inclusive) {
                    (0, _) => format!("{}", 1 + k % n),
                    (1, true) => format!("1..={n} by {k}"),
                    (1, false) => format!("2..{n}"),
                    _ => format!("{}, {n}", 1 + k % n),
                };
                entries.push(format!(
                    "link[{selector}] {{ mass: {m}, inertia: {j}, {uv} }}"
                ));
            }
            block(entries, true)
        })
}

fn tame_part(index: usize) -> impl Strategy<Value = String> {
    let kind = prop_oneof![Just("idler"), Just("road_wheel"), Just("roller")];
    (
        kind,
        (-4.0f64..0.0, -0.5f64..0.5),
        (tame_number(), tame_number(), tame_number()),
        proptest::option::weighted(
            0.5,
            (0.05f64..0.5, tame_number(), tame_number(), tame_number(), tame_number()),
        ),
    )
        .prop_map(move |(kind, (x, y), (m, j, r), arm)| {
            let arm = match (kind, arm) {
                ("roller", _) | (_, None) => String::new(),
                (_, Some((l, am, aj, k, c))) => format!(
                    ", arm {{ pivot: ({:?}, {:?}), mass: {am}, inertia: {aj}, stiffness: {k}, damping: {c}, preload: -{k} }}",
                    x + l,
                    y + 0.1
                ),
            };
            format!("{kind} p{index} {{ at: ({x:?}, {y:?}), mass: {m}, inertia: {j}, radius: {r}{arm} }}")
        })
}

fn tame_vehicle() -> impl Strategy<Value = String> {
    (
        (tame_number(), tame_number()),
        proptest::option::weighted(0.8, (3u32..40, tame_number())),
        (0usize..4).prop_flat_map(|k| (0..k).map(tame_part).collect::<Vec<_>>()),
        tame_track(),
        proptest::option::weighted(0.6, tame_running()),
    )
        .prop_map(|((m, j), sprocket, parts, track, running)| {
            let mut entries = vec![format!("chassis {{ mass: {m}, inertia: {j}, centroid: (-1.0, 0.4) }}")];
            let has_sprocket = sprocket.is_some();
            if let Some((teeth, r)) = sprocket {
                entries.push(format!(
                    "sprocket drive {{ at: (0.0, 0.0), mass: 27.0, inertia: 0.9, radius: {r}, teeth: {teeth} }}"
                ));
            }
            entries.extend(parts);
            entries.push(format!("track {track}"));
            // What makes it run needs a sprocket to drive.
            if let Some(running) = running.filter(|_| has_sprocket) {
                entries.push(running);
            }
            block(entries, false)
        })
}

/// A repeated, sprung road-wheel block, a shoe, contact pairs (either
/// law) and drive gains, all in range.
fn tame_running() -> impl Strategy<Value = String> {
    (
        1usize..4,
        (tame_number(), tame_number(), tame_number()),
        (0.01f64..0.05, tame_number()),
        prop::collection::vec((any::<bool>(), tame_number(), tame_number()), 0..3),
        proptest::option::of((tame_number(), tame_number(), tame_number())),
    )
        .prop_map(|(n, (m, j, r), (offset, _pin), laws, drive)| {
            let at: Vec<String> = (0..n).map(|i| format!("({:?}, -0.3)", -0.5 * (i + 1) as f64)).collect();
            let mut entries = vec![
                format!(
                    "road_wheel w[{n}] {{ at: [{}], mass: {m}, inertia: {j}, radius: {r}, \
                     arm {{ pivot_offset: (0.2, 0.1), mass: {m}, inertia: {j}, stiffness: {r}, damping: 1.0 }} }}",
                    at.join(", ")
                ),
                // The pins by named constants: whether they seat in the
                // random sprocket's gaps is the runtime's check there (a
                // pin of known position and size is checked at compile
                // time, `tests/ui/profile_*.rs`).
                format!(
                    "shoe {{ ground_points: [(-0.05, -{offset:?}), (0.05, -{offset:?})], inner_offset: {offset:?}, \
                     pins: [(PIN_X, 0.0)], pin_radius: PIN_RADIUS }}"
                ),
            ];
            let pairs: Vec<String> = laws
                .into_iter()
                .zip(["ground", "wheels", "sprocket"])
                .map(|((hunt, k, c), pair)| {
                    let law = if hunt { format!("chi: {c}, exponent: 1.5") } else { format!("damping: {c}") };
                    format!("{pair} {{ stiffness: {k}, {law}, mu: 0.5, slip: {c} }}")
                })
                .collect();
            entries.push(format!("contact {}", block(pairs, true)));
            if let Some((p, i, t)) = drive {
                entries.push(format!("drive {{ proportional: {p}, integral: {i}, max_torque: {t} }}"));
            }
            entries.join(", ")
        })
}

fn tame_declaration() -> impl Strategy<Value = String> {
    prop::collection::vec(
        prop_oneof![
            tame_track().prop_map(|b| format!("pub track Chain {b}")),
            tame_vehicle().prop_map(|b| format!("/// A vehicle.\npub vehicle Tank {b}")),
        ],
        1..2,
    )
    .prop_map(|items| items.join("\n"))
}

// ---------------------------------------------------------------------------
// Random tokens.

/// One token tree, before it is built (proptest needs `Clone + Debug`).
#[derive(Clone, Debug)]
enum Tok {
    Ident(&'static str),
    Punct(char, bool),
    Literal(String),
    Group(u8, Vec<Tok>),
}

const IDENTS: &[&str] = &[
    "track",
    "vehicle",
    "pub",
    "link",
    "links",
    "mass",
    "inertia",
    "u1",
    "u2",
    "closure",
    "penalty",
    "stiffness",
    "damping",
    "open",
    "partitioned",
    "gravity",
    "chassis",
    "sprocket",
    "idler",
    "road_wheel",
    "roller",
    "arm",
    "pivot",
    "preload",
    "travel",
    "at",
    "radius",
    "teeth",
    "by",
    "centroid",
    "shoe",
    "ground_points",
    "inner_offset",
    "pins",
    "pin_radius",
    "contact",
    "chi",
    "mu",
    "pivot_offset",
    "tip_radius",
    "Chain",
    "Tank",
    "drive",
    "f64",
    "NAN",
    "const",
    "crate",
    "self",
    "_",
    "r#type",
];

const PUNCT: &[char] = &[
    ':', ',', ';', '.', '=', '-', '+', '*', '/', '#', '!', '<', '>', '&', '%',
];

fn literal() -> impl Strategy<Value = String> {
    prop_oneof![
        (0u64..2000).prop_map(|n| n.to_string()),
        (-1e6f64..1e6).prop_map(|v| format!("{:?}", v.abs())),
        Just("1e999".to_string()),
        Just("99999999999999999999999".to_string()),
        Just("4294967296".to_string()),
        Just("3u8".to_string()),
        Just("2.5f32".to_string()),
        Just("\"text\"".to_string()),
        Just("'c'".to_string()),
        Just("b'x'".to_string()),
        Just("0x1F".to_string()),
        Just("1e-400".to_string()),
    ]
}

fn tok() -> impl Strategy<Value = Tok> {
    let leaf = prop_oneof![
        4 => prop::sample::select(IDENTS).prop_map(Tok::Ident),
        3 => (prop::sample::select(PUNCT), any::<bool>()).prop_map(|(c, j)| Tok::Punct(c, j)),
        2 => literal().prop_map(Tok::Literal),
    ];
    leaf.prop_recursive(3, 48, 8, |inner| {
        (0u8..4, prop::collection::vec(inner, 0..8)).prop_map(|(d, ts)| Tok::Group(d, ts))
    })
}

fn build(toks: &[Tok]) -> TokenStream {
    toks.iter()
        .map(|t| -> TokenTree {
            match t {
                Tok::Ident(name) => match name.strip_prefix("r#") {
                    Some(raw) => Ident::new_raw(raw, Span::call_site()).into(),
                    None => Ident::new(name, Span::call_site()).into(),
                },
                Tok::Punct(c, joint) => {
                    let spacing = if *joint {
                        Spacing::Joint
                    } else {
                        Spacing::Alone
                    };
                    Punct::new(*c, spacing).into()
                }
                Tok::Literal(text) => Literal::from_str(text).expect("a valid literal").into(),
                Tok::Group(d, inner) => {
                    let delimiter = match d {
                        0 => Delimiter::Brace,
                        1 => Delimiter::Bracket,
                        2 => Delimiter::Parenthesis,
                        _ => Delimiter::None,
                    };
                    Group::new(delimiter, build(inner)).into()
                }
            }
        })
        .collect()
}

// ---------------------------------------------------------------------------
// Mutations of declarations: leaves deleted, duplicated or replaced, the
// groups kept balanced.

enum Event {
    Leaf(TokenTree),
    Open(Delimiter),
    Close,
}

fn events(tokens: TokenStream, out: &mut Vec<Event>) {
    for t in tokens {
        match t {
            TokenTree::Group(g) => {
                out.push(Event::Open(g.delimiter()));
                events(g.stream(), out);
                out.push(Event::Close);
            }
            leaf => out.push(Event::Leaf(leaf)),
        }
    }
}

fn rebuild(events: &mut std::iter::Peekable<std::vec::IntoIter<Event>>) -> TokenStream {
    let mut out = TokenStream::new();
    while let Some(e) = events.next() {
        match e {
            Event::Leaf(t) => out.extend([t]),
            Event::Open(d) => out.extend([TokenTree::Group(Group::new(d, rebuild(events)))]),
            Event::Close => break,
        }
    }
    out
}

/// Applies `(position, operation, replacement)` edits to the leaves.
fn mutate(tokens: TokenStream, edits: &[(usize, u8, Tok)]) -> TokenStream {
    let mut list = Vec::new();
    events(tokens, &mut list);
    for (position, op, replacement) in edits {
        let leaves: Vec<usize> = (0..list.len())
            .filter(|&i| matches!(list[i], Event::Leaf(_)))
            .collect();
        if leaves.is_empty() {
            break;
        }
        let at = leaves[position % leaves.len()];
        let new = || {
            let mut built = Vec::new();
            events(build(std::slice::from_ref(replacement)), &mut built);
            built
        };
        match op % 3 {
            0 => {
                list.remove(at);
            }
            1 => {
                if let Event::Leaf(t) = &list[at] {
                    let copy = Event::Leaf(t.clone());
                    list.insert(at, copy);
                }
            }
            _ => {
                list.splice(at..=at, new());
            }
        }
    }
    rebuild(&mut list.into_iter().peekable())
}

// ---------------------------------------------------------------------------

/// Small tracks, so the cases stay quick: a 1024-link expansion takes a
/// good part of a second in a test build.
fn config(cases: u32) -> ProptestConfig {
    ProptestConfig {
        cases,
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

proptest! {
    #![proptest_config(config(96))]

    #[test]
    fn declarations_expand_to_code_or_errors(text in declaration()) {
        check_spanned(&text)?;
    }

    #[test]
    fn valid_declarations_expand_to_code(text in tame_declaration()) {
        let tokens = TokenStream::from_str(&text).expect("generated text lexes");
        let out = catch_unwind(AssertUnwindSafe(|| expand(tokens)))
            .map_err(|_| TestCaseError::fail(format!("the expander panicked on: {text}")))?;
        let errors = compile_errors(&out);
        prop_assert!(errors.is_empty(), "{:?} for: {}", errors, text);
        syn::parse2::<syn::File>(out)
            .map_err(|e| TestCaseError::fail(format!("not Rust items ({e}) for: {text}")))?;
    }

    #[test]
    fn mutated_declarations_expand_to_code_or_errors(
        text in prop_oneof![tame_declaration(), declaration()],
        edits in prop::collection::vec((any::<usize>(), any::<u8>(), tok()), 1..5),
    ) {
        let tokens = TokenStream::from_str(&text).expect("generated text lexes");
        check(mutate(tokens, &edits))?;
    }
}

proptest! {
    #![proptest_config(config(256))]

    #[test]
    fn random_tokens_expand_to_code_or_errors(toks in prop::collection::vec(tok(), 0..24)) {
        check(build(&toks))?;
    }
}

/// The generators reach both outcomes, and a valid declaration expands to
/// code (a check that the properties above are not vacuous).
#[test]
fn both_outcomes_are_reached() {
    let good = TokenStream::from_str(
        "pub track Chain { links: 4, link { mass: 1.0, inertia: 0.1, u1: (-0.1, 0.0), u2: (0.1, 0.0) } }",
    )
    .unwrap();
    let out = expand(good);
    assert!(compile_errors(&out).is_empty());
    syn::parse2::<syn::File>(out).unwrap();
    let bad = TokenStream::from_str("pub track Chain { links: 0 }").unwrap();
    let errors = compile_errors(&expand(bad));
    assert!(!errors.is_empty(), "{errors:?}");
    assert!(errors.iter().all(|m| !m.is_empty()));
}

/// The most links the macro accepts, every number a named constant and
/// some links overridden: code, no error.
#[test]
fn the_largest_declaration_expands_to_code() {
    let text = "pub vehicle Tank {
        chassis { mass: CHASSIS / 2.0, inertia: 500.0 },
        sprocket drive { at: (0.0, 0.0), mass: 27.0, inertia: 0.9, radius: 0.25, teeth: 10 },
        road_wheel rw1 { at: (-1.0, -0.2), mass: 35.0, inertia: 2.0, radius: 0.3,
            arm { pivot: (-1.0 + ARM, -0.1), mass: 5.0, inertia: 0.1, stiffness: 1e4, damping: 10.0 } },
        track {
            links: 1024,
            link { mass: SHOE_MASS, inertia: SHOE_INERTIA, u1: (-PITCH / 2.0, 0.0), u2: (PITCH / 2.0, 0.0) },
            link[1..=1024 by 7] { mass: 2.0 * SHOE_MASS },
            link[1024] { u2: (PITCH / 2.0, 0.001) },
        },
    }";
    let out = expand(TokenStream::from_str(text).unwrap());
    assert!(compile_errors(&out).is_empty());
    syn::parse2::<syn::File>(out).unwrap();
}
