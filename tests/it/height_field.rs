//! The ground in space (`terrain::field`): a plane at a heading is its
//! closed form; each side keeps its own profile, blended linearly across
//! the band between; a grid is bilinear (it reproduces a plane and any
//! `a + b x + c y + d x y` to rounding) with its slopes the central
//! differences of its heights, flat beyond its edges; a tilt adds a
//! plane; a hole, a bad grid, profile, divide, band or tilt is refused,
//! naming it. The highest point over a box bounds every height in it and
//! is reached where the field's shape says it is.

use trackgen::nalgebra::Vector2;
use trackgen::terrain::Terrain;
use trackgen::terrain::field::{FieldError, FieldShape, Grid, HeightField};

fn points() -> Vec<(f64, f64)> {
    (0..40)
        .map(|k| {
            let t = k as f64;
            (7.3 * (0.37 * t).sin() + 0.5 * t, 2.1 * (1.3 * t).cos())
        })
        .collect()
}

#[test]
fn a_plane_at_a_heading_is_its_closed_form() {
    // A 30 % grade at 40° from the path: z = 0.3 (x cos 40° + y sin 40°),
    // its gradient 0.3 along the heading (to rounding).
    let heading = 40f64.to_radians();
    let field = HeightField::plane(0.3, heading);
    for (x, y) in points() {
        let (h, g) = field.height_and_gradient(x, y);
        let closed = 0.3 * (x * heading.cos() + y * heading.sin());
        assert!((h - closed).abs() < 1e-14 * (1.0 + closed.abs()));
        assert!((g.norm() - 0.3).abs() < 1e-15);
        assert!((g.y.atan2(g.x) - heading).abs() < 1e-15);
    }
}

#[test]
fn each_side_keeps_its_own_profile_and_the_band_blends_them() {
    let left = Terrain::table(vec![(-10.0, 0.0), (2.0, 0.0), (3.0, 0.2), (30.0, 0.2)]).unwrap();
    let right = Terrain::Flat { height: -0.05 };
    let field = HeightField {
        base: FieldShape::Sides {
            left: left.clone(),
            right: right.clone(),
            divide: 0.1,
            band: 0.4,
        },
        tilt: Vector2::zeros(),
    };
    field.check().unwrap();
    for (x, _) in points() {
        assert_eq!(
            field.height(x, 0.3),
            left.height(x),
            "the left side from the band's edge"
        );
        assert_eq!(field.height(x, 1.5), left.height(x));
        assert_eq!(
            field.height(x, -0.1),
            right.height(x),
            "the right side from its edge"
        );
        let middle = field.height(x, 0.1);
        assert!((middle - 0.5 * (left.height(x) + right.height(x))).abs() < 1e-15);
        // Linear across the band: the slope across is the difference over
        // the band's width.
        let (_, g) = field.height_and_gradient(x, 0.2);
        assert!((g.y - (left.height(x) - right.height(x)) / 0.4).abs() < 1e-12);
    }
}

#[test]
fn a_grid_is_bilinear_and_flat_beyond_its_edges() {
    let (a, b, c, d) = (0.3, 0.05, -0.02, 0.004);
    let f = |x: f64, y: f64| a + b * x + c * y + d * x * y;
    let (nx, ny, dx, dy, x0, y0) = (12, 7, 0.5, 0.4, -2.0, -1.2);
    let heights: Vec<f64> = (0..ny)
        .flat_map(|j| (0..nx).map(move |i| (x0 + i as f64 * dx, y0 + j as f64 * dy)))
        .map(|(x, y)| f(x, y))
        .collect();
    let field = HeightField {
        base: FieldShape::Grid(Grid::new((x0, y0), (dx, dy), (nx, ny), heights).unwrap()),
        tilt: Vector2::zeros(),
    };
    let (x1, y1) = (x0 + (nx - 1) as f64 * dx, y0 + (ny - 1) as f64 * dy);
    for (x, y) in points() {
        let (x, y) = (
            x0 + (x + 3.0).rem_euclid(x1 - x0),
            y0 + (y + 2.1).rem_euclid(y1 - y0),
        );
        let (h, g) = field.height_and_gradient(x, y);
        assert!(
            (h - f(x, y)).abs() < 1e-14,
            "({x}, {y}): {h} against {}",
            f(x, y)
        );
        assert!((g - Vector2::new(b + d * y, c + d * x)).amax() < 1e-13);
        let e = 1e-6;
        let by_x = (field.height(x + e, y) - field.height(x - e, y)) / (2.0 * e);
        assert!((by_x - g.x).abs() < 1e-8);
    }
    // Beyond the grid: the nearest edge's height, no slope across it.
    let (h, g) = field.height_and_gradient(x1 + 5.0, y0 + 1.0);
    assert!((h - f(x1, y0 + 1.0)).abs() < 1e-14);
    assert_eq!(g.x, 0.0);
}

#[test]
fn a_tilt_adds_a_plane() {
    let base = HeightField {
        base: FieldShape::Profile(Terrain::Sine {
            amplitude: 0.1,
            wavelength: 3.0,
        }),
        tilt: Vector2::zeros(),
    };
    let side = base.clone().tilted(Vector2::new(0.0, 0.3));
    for (x, y) in points() {
        let ((h0, g0), (h1, g1)) = (
            base.height_and_gradient(x, y),
            side.height_and_gradient(x, y),
        );
        assert!((h1 - h0 - 0.3 * y).abs() < 1e-14);
        assert!((g1 - g0 - Vector2::new(0.0, 0.3)).amax() < 1e-15);
    }
}

/// Every shape, tilted: a bump on one side, a grid with a peak inside
/// and heights beyond its edges, a sine, a step profile.
fn shapes() -> Vec<HeightField> {
    let bump = Terrain::Bump {
        centre: 1.0,
        height: 0.25,
        width: 0.8,
    };
    let (nx, ny) = (9, 6);
    let heights: Vec<f64> = (0..nx * ny)
        .map(|k| 0.1 * ((k * 7919) % 13) as f64 - 0.4)
        .collect();
    let grid = Grid::new((-1.5, -1.0), (0.5, 0.4), (nx, ny), heights).unwrap();
    [
        FieldShape::Level,
        FieldShape::Profile(Terrain::Sine {
            amplitude: 0.1,
            wavelength: 3.0,
        }),
        FieldShape::Profile(
            Terrain::table(vec![(-10.0, 0.0), (0.5, 0.0), (0.5001, 0.3), (30.0, 0.3)]).unwrap(),
        ),
        FieldShape::Sides {
            left: bump,
            right: Terrain::Flat { height: -0.05 },
            divide: 0.1,
            band: 0.4,
        },
        FieldShape::Grid(grid),
    ]
    .into_iter()
    .flat_map(|base| {
        [Vector2::zeros(), Vector2::new(0.2, -0.3)].map(|tilt| HeightField {
            base: base.clone(),
            tilt,
        })
    })
    .collect()
}

#[test]
fn the_highest_point_over_a_box_bounds_every_height_in_it() {
    // Boxes over, across and beyond the shapes' features, sampled on a
    // 41 × 41 lattice: no height above the bound (a rounding's worth
    // allowed: the bound adds the tilt at a corner, the height at the
    // point), and on a level field tilted the bound is the corner's
    // height itself.
    let boxes = [
        ((-0.2, 1.7), (-0.6, 0.9)),
        ((0.9, 1.1), (0.3, 0.5)),
        ((-4.0, -2.0), (-3.0, -1.5)),
        ((2.0, 6.0), (0.5, 2.5)),
        ((-1.6, 3.0), (-1.2, 1.2)),
    ];
    for field in shapes() {
        for ((x0, x1), (y0, y1)) in boxes {
            let top = field.max_height((x0, x1), (y0, y1));
            let mut highest = f64::NEG_INFINITY;
            for i in 0..=40 {
                for j in 0..=40 {
                    let x = x0 + (x1 - x0) * i as f64 / 40.0;
                    let y = y0 + (y1 - y0) * j as f64 / 40.0;
                    highest = highest.max(field.height(x, y));
                }
            }
            assert!(
                highest <= top + 1e-14,
                "{:?} over ({x0}, {x1}) × ({y0}, {y1}): {highest} above the bound {top}",
                field.base
            );
            if field.base == FieldShape::Level {
                assert!(
                    (top - highest).abs() < 1e-15,
                    "a plane's bound is its corner"
                );
            }
        }
    }
    let nan = HeightField::level().max_height((f64::NAN, 1.0), (0.0, 1.0));
    assert_eq!(
        nan,
        f64::INFINITY,
        "a box that is not a number culls nothing"
    );
}

#[test]
fn holes_and_bad_figures_are_refused_naming_them() {
    let mut heights = vec![0.0; 6 * 4];
    heights[2 * 6 + 3] = f64::NAN;
    let hole = Grid::new((1.0, -1.0), (0.5, 0.25), (6, 4), heights.clone());
    match hole {
        Err(FieldError::Hole {
            i: 3, j: 2, x, y, ..
        }) => {
            assert_eq!((x, y), (2.5, -0.5));
        }
        other => panic!("{other:?}"),
    }
    let message = Grid::new((1.0, -1.0), (0.5, 0.25), (6, 4), heights)
        .unwrap_err()
        .to_string();
    assert!(
        message.contains("(3, 2)") && message.contains("hole"),
        "{message}"
    );
    assert!(matches!(
        Grid::new((0.0, 0.0), (0.0, 1.0), (2, 2), vec![0.0; 4]),
        Err(FieldError::Grid { .. })
    ));
    assert!(matches!(
        Grid::new((0.0, 0.0), (1.0, 1.0), (3, 2), vec![0.0; 5]),
        Err(FieldError::Size {
            nx: 3,
            ny: 2,
            got: 5
        })
    ));
    let sides = |divide: f64, band: f64| HeightField {
        base: FieldShape::Sides {
            left: Terrain::Flat { height: 0.0 },
            right: Terrain::Flat { height: 0.0 },
            divide,
            band,
        },
        tilt: Vector2::zeros(),
    };
    assert!(matches!(
        sides(0.0, -1.0).check(),
        Err(FieldError::Sides { .. })
    ));
    assert!(matches!(
        sides(f64::NAN, 0.0).check(),
        Err(FieldError::Sides { .. })
    ));
    let bad = Terrain::Sine {
        amplitude: 0.1,
        wavelength: f64::NAN,
    };
    assert!(matches!(
        HeightField {
            base: FieldShape::Profile(bad.clone()),
            tilt: Vector2::zeros(),
        }
        .check(),
        Err(FieldError::Profile(_))
    ));
    assert!(matches!(
        HeightField {
            base: FieldShape::Sides {
                left: Terrain::Flat { height: 0.0 },
                right: bad,
                divide: 0.0,
                band: 0.1,
            },
            tilt: Vector2::zeros(),
        }
        .check(),
        Err(FieldError::Profile(_))
    ));
    let tilted = HeightField::level().tilted(Vector2::new(f64::INFINITY, 0.0));
    assert!(matches!(tilted.check(), Err(FieldError::Tilt { .. })));
}
