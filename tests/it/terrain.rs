//! Terrain profiles (`trackgen::terrain::Terrain`): heights and slopes of
//! every variant by hand, slopes against a central finite difference of the
//! height, the culling bound `max_height` against dense sampling, and the
//! errors of `Terrain::table` with their messages.
//!
//! Tolerances, and why:
//! * Hand values: `1e-15` absolute for sums and products of a few terms of
//!   size ≤ 1 (a handful of roundings of 1.1e-16 each); values that are
//!   copied through untouched (a flat height, a table's end value, the
//!   zero outside a bump) are compared exactly.
//! * Slope against the central difference `(h(x+e) − h(x−e)) / 2e` with
//!   `e = 1e-6` m: the truncation error is `e² |h'''| / 6`, at most
//!   `1e-12 · 0.05 · (2π/0.8)³ / 6 ≈ 4e-12` for the steepest profile here
//!   (a 0.1 m bump 0.8 m wide), and the rounding error is
//!   `2.2e-16 · |h| / e ≤ 1e-10`; `1e-8` absolute leaves two orders of
//!   margin, while a wrong slope (wrong sign, missing factor k, slope of
//!   the neighbouring segment) is off by ≥ 1e-2. Points within 2e of a
//!   kink (table knots, the ramp's start, a bump's edges) are skipped: the
//!   slope is one-sided there by design.
//! * `max_height ≥ h(x)` at every sampled point, allowing `1e-12` m: a
//!   table's interpolation `a + s (x − x_a)` may exceed the higher knot by
//!   an ulp or two (5e-17 m at these heights), which no contact can feel;
//!   a culling that skips a real peak is off by ≥ 1e-3 m here.

use crate::support;

use support::{Lcg, max_of};
use trackgen::terrain::{Terrain, TerrainError};

use std::f64::consts::PI;

/// `(h(x), h'(x))` against expected values within `tol`.
fn check(terrain: &Terrain, x: f64, height: f64, slope: f64, tol: f64) {
    let (h, s) = terrain.height_and_slope(x);
    assert!(
        (h - height).abs() <= tol && (s - slope).abs() <= tol,
        "{terrain:?} at x = {x}: got ({h}, {s}), want ({height}, {slope})"
    );
    // `height` is the first half of `height_and_slope`.
    assert_eq!(terrain.height(x).to_bits(), h.to_bits(), "height at {x}");
}

fn table() -> Terrain {
    Terrain::table(vec![(0.0, 0.0), (1.0, 0.2), (2.0, -0.1), (4.0, 0.3)]).unwrap()
}

/// A piecewise-linear table by hand: interior points of each segment,
/// the knots, the ends and beyond (flat, zero slope).
#[test]
fn table_height_and_slope_by_hand() {
    let t = table();
    // Interior of each segment: a + s (x − x_a).
    check(&t, 0.5, 0.1, 0.2, 1e-15);
    check(&t, 1.5, 0.2 - 0.3 * 0.5, -0.3, 1e-15);
    check(&t, 3.0, -0.1 + 0.2 * 1.0, 0.2, 1e-15);
    check(&t, 3.75, -0.1 + 0.2 * 1.75, 0.2, 1e-15);
    // At and beyond the ends: the end value, flat.
    check(&t, 0.0, 0.0, 0.0, 0.0);
    check(&t, -7.0, 0.0, 0.0, 0.0);
    check(&t, 4.0, 0.3, 0.0, 0.0);
    check(&t, 1e6, 0.3, 0.0, 0.0);
    // At an interior knot the height is the knot's (continuous); the
    // slope is that of one of the two segments meeting there.
    for (x, y, slopes) in [(1.0, 0.2, [0.2, -0.3]), (2.0, -0.1, [-0.3, 0.2])] {
        let (h, s) = t.height_and_slope(x);
        assert!((h - y).abs() <= 1e-15, "knot {x}: {h}");
        assert!(
            slopes.iter().any(|w| (s - w).abs() <= 1e-15),
            "knot {x}: slope {s} is neither of {slopes:?}"
        );
    }
    // Just either side of a knot: continuous, the segments' slopes.
    let e = 1e-9;
    check(&t, 1.0 - e, 0.2 - 0.2 * e, 0.2, 1e-15);
    check(&t, 1.0 + e, 0.2 - 0.3 * e, -0.3, 1e-15);
    // A table built directly may be empty or have one point (the variant
    // is public); it is then flat (0, or the one point's height).
    check(&Terrain::Table(vec![]), 3.0, 0.0, 0.0, 0.0);
    check(&Terrain::Table(vec![(1.0, 0.5)]), -3.0, 0.5, 0.0, 0.0);
    check(&Terrain::Table(vec![(1.0, 0.5)]), 3.0, 0.5, 0.0, 0.0);
    assert_eq!(Terrain::Table(vec![]).max_height(-1.0, 1.0), 0.0);
}

/// A cosine bump and a cosine dip: crest, half-way, edge, outside.
#[test]
fn bump_and_dip_by_hand() {
    for height in [0.1, -0.1] {
        let b = Terrain::Bump {
            centre: 2.0,
            width: 1.0,
            height,
        };
        let k = 2.0 * PI / 1.0;
        // Crest (or bottom): the full height, flat.
        check(&b, 2.0, height, 0.0, 1e-15);
        // A quarter width from the centre: half the height, steepest,
        // h' = −H/2 k sin(k u) with k u = ±π/2.
        check(&b, 2.25, height / 2.0, -height / 2.0 * k, 1e-15);
        check(&b, 1.75, height / 2.0, height / 2.0 * k, 1e-15);
        // At the edges and outside: flat at 0.
        for x in [1.5, 2.5, 1.0, 3.0, -10.0, 10.0] {
            check(&b, x, 0.0, 0.0, 0.0);
        }
        // An eighth of the width: H/2 (1 + cos π/4).
        check(
            &b,
            2.125,
            height / 2.0 * (1.0 + 0.5f64.sqrt()),
            -height / 2.0 * k * 0.5f64.sqrt(),
            1e-15,
        );
    }
    // A bump of no width is no bump.
    let flat = Terrain::Bump {
        centre: 0.0,
        width: 0.0,
        height: 1.0,
    };
    check(&flat, 0.0, 0.0, 0.0, 0.0);
}

/// A sine (both signs of amplitude), and the degenerate zero wavelength.
#[test]
fn sine_by_hand() {
    for amplitude in [0.05, -0.05] {
        let s = Terrain::Sine {
            amplitude,
            wavelength: 2.0,
        };
        // k = π: h = A sin(π x), h' = A π cos(π x).
        check(&s, 0.0, 0.0, amplitude * PI, 1e-15);
        check(&s, 0.5, amplitude, 0.0, 1e-15);
        check(&s, 1.5, -amplitude, 0.0, 1e-15);
        check(
            &s,
            1.0 / 6.0,
            amplitude * 0.5,
            amplitude * PI * 0.75f64.sqrt(),
            1e-15,
        );
        check(
            &s,
            -0.25,
            -amplitude * 0.5f64.sqrt(),
            amplitude * PI * 0.5f64.sqrt(),
            1e-15,
        );
    }
    // Zero wavelength: flat at 0, not NaN (sin(x · ∞)).
    let z = Terrain::Sine {
        amplitude: 0.3,
        wavelength: 0.0,
    };
    for x in [0.0, 0.3, -2.0] {
        check(&z, x, 0.0, 0.0, 0.0);
    }
}

/// Ramps up and down from a flat, and flat ground.
#[test]
fn ramp_and_flat_by_hand() {
    let up = Terrain::Ramp {
        height: 0.1,
        start: 1.0,
        slope: 0.25,
    };
    check(&up, 0.0, 0.1, 0.0, 0.0);
    check(&up, 1.0, 0.1, 0.0, 0.0);
    check(&up, 3.0, 0.1 + 0.5, 0.25, 1e-15);
    check(&up, 1.5, 0.1 + 0.125, 0.25, 1e-15);
    let down = Terrain::Ramp {
        height: 0.0,
        start: -1.0,
        slope: -0.2,
    };
    check(&down, -3.0, 0.0, 0.0, 0.0);
    check(&down, 1.0, -0.4, -0.2, 1e-15);
    let flat = Terrain::Flat { height: -0.35 };
    for x in [-1e3, 0.0, 7.5] {
        check(&flat, x, -0.35, 0.0, 0.0);
    }
    // The culling bound: the higher end for a ramp, the height for flat.
    assert!((up.max_height(0.0, 3.0) - 0.6).abs() <= 1e-15);
    assert_eq!(up.max_height(-2.0, 0.5), 0.1);
    assert_eq!(down.max_height(-3.0, 1.0), 0.0);
    assert!((down.max_height(0.0, 1.0) - -0.2).abs() <= 1e-15);
    assert_eq!(flat.max_height(-1.0, 1.0), -0.35);
}

/// Every profile the tests use, dips and interior peaks included.
fn profiles() -> Vec<Terrain> {
    vec![
        Terrain::Flat { height: 0.2 },
        Terrain::Ramp {
            height: 0.1,
            start: 1.0,
            slope: 0.25,
        },
        Terrain::Ramp {
            height: 0.0,
            start: -1.0,
            slope: -0.3,
        },
        Terrain::Bump {
            centre: 2.0,
            width: 0.8,
            height: 0.1,
        },
        Terrain::Bump {
            centre: 2.0,
            width: 0.8,
            height: -0.1,
        },
        Terrain::Sine {
            amplitude: 0.05,
            wavelength: 1.3,
        },
        Terrain::Sine {
            amplitude: -0.05,
            wavelength: 0.7,
        },
        table(),
        // A table with a narrow peak and a narrow pit between flat parts.
        Terrain::table(vec![
            (-1.0, 0.0),
            (0.0, 0.0),
            (0.02, 0.15),
            (0.04, 0.0),
            (1.0, 0.0),
            (1.01, -0.2),
            (1.02, 0.0),
            (3.0, 0.05),
        ])
        .unwrap(),
    ]
}

/// Kinks of a profile, where its slope is one-sided.
fn kinks(terrain: &Terrain) -> Vec<f64> {
    match terrain {
        Terrain::Ramp { start, .. } => vec![*start],
        Terrain::Bump { centre, width, .. } => vec![centre - width / 2.0, centre + width / 2.0],
        Terrain::Table(points) => points.iter().map(|p| p.0).collect(),
        _ => vec![],
    }
}

/// The slope is the derivative of the height wherever the profile is
/// smooth: a central difference at 2001 points over [−2, 5] m.
#[test]
fn slope_is_the_derivative_of_height() {
    let e = 1e-6;
    for terrain in profiles() {
        let kinks = kinks(&terrain);
        let mut checked = 0;
        for i in 0..=2000 {
            let x = -2.0 + 7.0 * i as f64 / 2000.0 + 1.234e-4;
            if kinks.iter().any(|k| (x - k).abs() < 2.0 * e) {
                continue;
            }
            let fd = (terrain.height(x + e) - terrain.height(x - e)) / (2.0 * e);
            let (_, slope) = terrain.height_and_slope(x);
            assert!(
                (slope - fd).abs() <= 1e-8,
                "{terrain:?} at x = {x}: slope {slope}, difference {fd}"
            );
            checked += 1;
        }
        assert!(checked > 1900, "{terrain:?}: only {checked} points checked");
    }
}

/// `max_height(x0, x1)` bounds the height at every point of the interval
/// (sampled at 401 points, the ends included), for every profile: random
/// intervals from 1 mm to 3 m long, plus intervals chosen to hold only a
/// peak's flank, a pit, the inside of a dip, or a bump's crest.
#[test]
fn max_height_bounds_every_sampled_point() {
    let mut rng = Lcg::new(7);
    let mut intervals: Vec<(f64, f64)> = (0..300)
        .map(|_| {
            let x0 = rng.uniform(-2.0, 5.0);
            let len = 10f64.powf(rng.uniform(-3.0, 0.5));
            (x0, x0 + len)
        })
        .collect();
    intervals.extend([
        (0.005, 0.035), // the narrow table peak, strictly inside
        (0.019, 0.021), // its tip
        (1.005, 1.015), // the narrow pit
        (1.8, 2.2),     // inside a bump or dip, around its centre
        (1.9, 1.95),    // inside, one flank only
        (1.0, 3.0),     // a whole bump or dip and the flat around it
        (0.5, 1.5),     // the first table's interior peak at x = 1
        (1.2, 1.8),     // between its knots, falling
        (-3.0, -2.5),   // before everything
    ]);
    for terrain in profiles() {
        for &(x0, x1) in &intervals {
            let bound = terrain.max_height(x0, x1);
            let highest = max_of((0..=400).map(|i| {
                let x = if i == 400 {
                    x1
                } else {
                    x0 + (x1 - x0) * i as f64 / 400.0
                };
                terrain.height(x)
            }));
            assert!(
                bound >= highest - 1e-12,
                "{terrain:?} over [{x0}, {x1}]: max_height {bound} below the sampled {highest}"
            );
        }
    }
}

/// `max_height` is exact where it can be, so culling is not needlessly
/// loose: a table's interior peak, a bump's crest, a dip's rim, the ends.
#[test]
fn max_height_by_hand() {
    let t = table();
    assert_eq!(t.max_height(0.5, 1.5), 0.2);
    assert!((t.max_height(1.2, 1.8) - (0.2 - 0.3 * 0.2)).abs() <= 1e-15);
    assert!((t.max_height(2.5, 3.5) - 0.2).abs() <= 1e-15);
    assert_eq!(t.max_height(-1.0, 5.0), 0.3);
    let bump = Terrain::Bump {
        centre: 2.0,
        width: 1.0,
        height: 0.1,
    };
    assert_eq!(bump.max_height(1.0, 2.1), 0.1);
    assert!((bump.max_height(2.25, 2.4) - 0.05).abs() <= 1e-15);
    assert_eq!(bump.max_height(3.0, 4.0), 0.0);
    let dip = Terrain::Bump {
        centre: 2.0,
        width: 1.0,
        height: -0.1,
    };
    // Inside the dip: the higher end, −H/2 (1 + cos(2π · 0.25)) = −0.05.
    assert!((dip.max_height(1.75, 2.1) - -0.05).abs() <= 1e-15);
    // Reaching out of it: the flat at 0.
    assert_eq!(dip.max_height(1.0, 2.0), 0.0);
    let sine = Terrain::Sine {
        amplitude: -0.07,
        wavelength: 1.0,
    };
    assert_eq!(sine.max_height(0.0, 0.01), 0.07);
}

/// `Terrain::table` rejects what it cannot interpolate, naming the point.
#[test]
fn table_errors_name_the_problem() {
    for n in [0, 1] {
        let points = vec![(0.0, 0.0); n];
        let e = Terrain::table(points).unwrap_err();
        assert_eq!(e, TerrainError::TooFewPoints(n));
        assert_eq!(
            e.to_string(),
            format!("a terrain table needs at least 2 points, got {n}")
        );
    }
    // Equal x is out of order too (x must increase strictly).
    let e = Terrain::table(vec![(0.0, 0.0), (1.0, 0.0), (1.0, 0.5)]).unwrap_err();
    assert_eq!(
        e,
        TerrainError::OutOfOrder {
            index: 2,
            x: 1.0,
            previous: 1.0
        }
    );
    assert_eq!(
        e.to_string(),
        "terrain table out of order: point 2 has x = 1 m, not after the previous x = 1 m"
    );
    let e = Terrain::table(vec![(0.0, 0.0), (-0.5, 0.0), (1.0, 0.0)]).unwrap_err();
    assert_eq!(
        e,
        TerrainError::OutOfOrder {
            index: 1,
            x: -0.5,
            previous: 0.0
        }
    );
    assert_eq!(
        e.to_string(),
        "terrain table out of order: point 1 has x = -0.5 m, not after the previous x = 0 m"
    );
    for (points, index) in [
        (vec![(f64::NAN, 0.0), (1.0, 0.0)], 0),
        (vec![(0.0, 0.0), (1.0, f64::INFINITY)], 1),
        (vec![(0.0, 0.0), (1.0, 0.0), (f64::NEG_INFINITY, 0.0)], 2),
        // A non-finite x is reported as such, not as out of order.
        (vec![(0.0, 0.0), (f64::NAN, 0.0)], 1),
    ] {
        let e = Terrain::table(points).unwrap_err();
        assert_eq!(e, TerrainError::NonFinite(index));
        assert_eq!(
            e.to_string(),
            format!("terrain: non-finite value at point {index}")
        );
    }
    // A valid table is kept as given.
    let points = vec![(0.0, 1.0), (0.5, -1.0)];
    assert_eq!(Terrain::table(points.clone()), Ok(Terrain::Table(points)));
}

/// Regression: a table evaluated at x = NaN panicked (index underflow in
/// the segment search); every profile gives a NaN height there, so the
/// integrator's finiteness check reports it.
#[test]
fn every_profile_is_nan_at_nan() {
    let table = Terrain::table(vec![(0.0, 0.0), (1.0, 0.5), (2.0, 0.0)]).unwrap();
    for terrain in [
        table,
        Terrain::Ramp {
            height: 0.0,
            start: 1.0,
            slope: 0.2,
        },
        Terrain::Bump {
            centre: 1.0,
            width: 1.0,
            height: 0.1,
        },
        Terrain::Sine {
            amplitude: 0.1,
            wavelength: 2.0,
        },
    ] {
        let (h, _) = terrain.height_and_slope(f64::NAN);
        assert!(h.is_nan(), "{terrain:?}: h(NaN) = {h}");
    }
}
