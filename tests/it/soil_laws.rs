//! The terramechanics laws of soft soil (`trackgen::terrain::soil`) against
//! the closed forms of Wong's *Theory of Ground Vehicles* (the guide's
//! "Soft soil"), worked numbers computed from them by hand, and
//! against independent quadrature.
//!
//! Tolerances, and why:
//! - Worked numbers (dry sand, b = 0.4 m,
//!   l = 4 m, W = 1.4e5 N, K = 2.5 cm): to the half unit of their last
//!   printed digit (z₀ = 0.07414 m ± 5e-6, R_c = 1235.7 N ± 0.05, F ± 0.5 N).
//! - Wong's tractive effort against Simpson quadrature of the
//!   Janosi–Hanamoto stress along the track (2000 panels; the integrand's
//!   fourth derivative is bounded by τ_max/K⁴, so the rule's error is below
//!   1e-9 of F at these slips): 1e-8 relative.
//! - The inverse of the static sinkage, and the memory's continuity at its
//!   yield point: 1e-12 relative (a handful of roundings).

use trackgen::terrain::{soil::Soil, soil::SoilError, soil::SoilMemory, soil::SoilPreset};

fn close(label: &str, got: f64, want: f64, abs: f64) {
    assert!(
        (got - want).abs() <= abs && got.is_finite(),
        "{label}: got {got}, want {want} ± {abs}"
    );
}

/// Wong's dry sand (Table 2.3), in SI, with K = 0.025 m.
fn dry_sand() -> Soil {
    let soil = SoilPreset::DrySand.soil();
    assert_eq!(
        (
            soil.n,
            soil.k_c,
            soil.k_phi,
            soil.cohesion,
            soil.friction_angle_deg,
            soil.shear_modulus
        ),
        (1.1, 990.0, 1.52843e6, 1040.0, 28.0, 0.025)
    );
    soil
}

const WIDTH: f64 = 0.4;
const LENGTH: f64 = 4.0;
const LOAD: f64 = 1.4e5;

#[test]
fn static_sinkage_and_compaction_resistance_match_the_worked_numbers() {
    let soil = dry_sand();
    close("p", LOAD / (WIDTH * LENGTH), 87_500.0, 1e-9);
    let z0 = soil.static_sinkage(LOAD, WIDTH, LENGTH);
    close("z₀", z0, 0.07414, 5e-6);
    // Bekker's pressure at that sinkage is the applied pressure.
    let p = soil.bekker_pressure(z0, WIDTH);
    close("p(z₀)", p, 87_500.0, 1e-12 * 87_500.0);
    close(
        "R_c",
        soil.compaction_resistance(LOAD, WIDTH, LENGTH),
        1235.7,
        0.05,
    );
    // Other rows, same plate (LETE sand with Chrono's n = 0.793).
    let lete = Soil {
        n: 0.793,
        ..SoilPreset::LeteSand.soil()
    };
    for (soil, want, abs) in [
        (SoilPreset::Clay.soil(), 0.0146, 5e-5),
        (lete, 0.0053, 5e-5),
        (SoilPreset::Snow.soil(), 0.583, 5e-4),
    ] {
        close(
            "z₀ of another row",
            soil.static_sinkage(LOAD, WIDTH, LENGTH),
            want,
            abs,
        );
    }
}

#[test]
fn tractive_effort_matches_the_worked_numbers_and_quadrature() {
    let soil = dry_sand();
    for (slip, want) in [
        (0.01, 38_142.0),
        (0.05, 66_594.0),
        (0.1, 71_347.0),
        (0.2, 73_725.0),
        (0.5, 75_152.0),
    ] {
        let f = soil.tractive_effort(LOAD, WIDTH, LENGTH, slip);
        close(&format!("F at slip {slip}"), f, want, 0.5);
        // Independently: b ∫₀ˡ τ(p, i x) dx by Simpson's rule.
        let p = LOAD / (WIDTH * LENGTH);
        let panels = 2000;
        let h = LENGTH / panels as f64;
        let sum: f64 = (0..=panels)
            .map(|k| {
                let weight = if k == 0 || k == panels {
                    1.0
                } else if k % 2 == 1 {
                    4.0
                } else {
                    2.0
                };
                weight * soil.shear_stress(p, slip * k as f64 * h)
            })
            .sum();
        let quadrature = WIDTH * sum * h / 3.0;
        close(
            &format!("quadrature at slip {slip}"),
            f,
            quadrature,
            1e-8 * f,
        );
    }
    let limit = WIDTH * LENGTH * soil.cohesion + LOAD * soil.tan_phi();
    close("A c + W tan φ", limit, 76_103.0, 0.5);
    // Small slips against the series of the mobilised fraction,
    // 1 − (1 − e^{−x})/x = x/2 − x²/6 + x³/24 − …, x = i l / K, to 1e-9 of
    // F (the omitted terms are below 1e-10 of it at these x), on both
    // sides of the implementation's switch to its own series at x = 1e-4;
    // large slip, F → limit.
    for small in [1e-7, 2e-6, 1e-5] {
        let x = small * LENGTH / soil.shear_modulus;
        let series = x / 2.0 - x * x / 6.0 + x * x * x / 24.0;
        close(
            &format!("F at slip {small:e}"),
            soil.tractive_effort(LOAD, WIDTH, LENGTH, small),
            limit * series,
            1e-9 * limit * series,
        );
    }
    close(
        "F at full slip",
        soil.tractive_effort(LOAD, WIDTH, LENGTH, 1e3),
        limit,
        1e-4 * limit,
    );
}

#[test]
fn janosi_hanamoto_by_hand() {
    let soil = dry_sand();
    let p = 5e4;
    let strength = 1040.0 + p * 28f64.to_radians().tan();
    close("τ_max", soil.shear_strength(p), strength, 1e-9);
    close("τ at j = 0", soil.shear_stress(p, 0.0), 0.0, 0.0);
    close(
        "τ at j = K",
        soil.shear_stress(p, 0.025),
        strength * (1.0 - (-1f64).exp()),
        1e-9 * strength,
    );
    // The stress opposes slip whichever way it went: magnitude only.
    assert_eq!(soil.shear_stress(p, -0.01), soil.shear_stress(p, 0.01));
}

/// Loading follows Bekker; unloading and reloading below the deepest
/// sinkage are elastic with slope K_e; pressing deeper yields again; the
/// pressure is continuous at the yield point; a second pass to the same
/// depth leaves the plastic sinkage unchanged.
#[test]
fn memory_loads_by_bekker_and_unloads_elastically() {
    let soil = dry_sand();
    let fresh = SoilMemory::default();
    for z in [0.001, 0.01, 0.05] {
        assert_eq!(
            fresh.pressure(&soil, z, WIDTH),
            soil.bekker_pressure(z, WIDTH)
        );
    }
    assert_eq!(fresh.pressure(&soil, -0.01, WIDTH), 0.0);
    let z1 = 0.05;
    let pressed = fresh.pressed_to(&soil, z1, WIDTH);
    let p1 = soil.bekker_pressure(z1, WIDTH);
    close("yield pressure", pressed.yield_pressure, p1, 0.0);
    close(
        "plastic sinkage",
        pressed.plastic,
        z1 - p1 / soil.unloading_stiffness,
        1e-15,
    );
    close("deepest", pressed.deepest(&soil), z1, 1e-12 * z1);
    // Continuous at the yield point, from both sides.
    let below = pressed.pressure(&soil, z1 * (1.0 - 1e-12), WIDTH);
    let above = pressed.pressure(&soil, z1 * (1.0 + 1e-12), WIDTH);
    close("continuity", below, above, 1e-9 * p1);
    // Unloading: slope K_e, down to zero at the plastic sinkage.
    let dz = 1e-4;
    let slope = (pressed.pressure(&soil, z1 - dz, WIDTH)
        - pressed.pressure(&soil, z1 - 2.0 * dz, WIDTH))
        / dz;
    close(
        "unloading slope",
        slope,
        soil.unloading_stiffness,
        1e-6 * slope,
    );
    assert_eq!(pressed.pressure(&soil, pressed.plastic, WIDTH), 0.0);
    assert_eq!(pressed.pressure(&soil, pressed.plastic - 0.01, WIDTH), 0.0);
    // A second pass to the same depth changes nothing; deeper yields.
    assert_eq!(pressed.pressed_to(&soil, z1, WIDTH), pressed);
    assert_eq!(pressed.pressed_to(&soil, 0.03, WIDTH), pressed);
    let deeper = pressed.pressed_to(&soil, 0.06, WIDTH);
    assert!(deeper.plastic > pressed.plastic && deeper.yield_pressure > p1);
    // The same load sinks less the second time: the elastic reload
    // carries it above the sinkage of the first pass.
    let load = 0.5 * p1;
    let first = soil.static_sinkage(load * WIDTH * LENGTH, WIDTH, LENGTH);
    let second = pressed.plastic + load / soil.unloading_stiffness;
    assert!(second < z1 && second > pressed.plastic, "{second}");
    assert!(first < z1, "{first}");
}

#[test]
fn presets_are_valid_and_named() {
    for preset in SoilPreset::ALL {
        preset
            .soil()
            .check()
            .unwrap_or_else(|e| panic!("{preset}: {e}"));
        assert_eq!(preset.name().parse::<SoilPreset>(), Ok(preset));
    }
    let unknown = "quicksand".parse::<SoilPreset>().unwrap_err();
    assert_eq!(unknown, SoilError::UnknownPreset("quicksand".into()));
    let message = unknown.to_string();
    assert!(
        message.contains("quicksand") && message.contains("dry-sand, sandy-loam"),
        "{message}"
    );
}

#[test]
fn bad_parameters_are_clear_errors() {
    let good = dry_sand();
    let cases: [(Soil, &str); 9] = [
        (Soil { n: 0.0, ..good }, "n"),
        (Soil { k_c: -1.0, ..good }, "k_c"),
        (
            Soil {
                k_phi: f64::NAN,
                ..good
            },
            "k_phi",
        ),
        (
            Soil {
                cohesion: -5.0,
                ..good
            },
            "cohesion",
        ),
        (
            Soil {
                friction_angle_deg: 90.0,
                ..good
            },
            "friction_angle_deg",
        ),
        (
            Soil {
                shear_modulus: 0.0,
                ..good
            },
            "shear_modulus",
        ),
        (
            Soil {
                unloading_stiffness: f64::INFINITY,
                ..good
            },
            "unloading_stiffness",
        ),
        (
            Soil {
                damping: -1.0,
                ..good
            },
            "damping",
        ),
        (
            Soil {
                friction_angle_deg: -1.0,
                ..good
            },
            "friction_angle_deg",
        ),
    ];
    for (soil, field) in cases {
        match soil.check() {
            Err(SoilError::OutOfRange { name, .. }) => assert_eq!(name, field),
            other => panic!("{field}: {other:?}"),
        }
        let message = soil.check().unwrap_err().to_string();
        assert!(
            message.contains(field) && message.contains("must be"),
            "{message}"
        );
    }
    assert_eq!(
        Soil {
            k_c: 0.0,
            k_phi: 0.0,
            ..good
        }
        .check(),
        Err(SoilError::NoBearing)
    );
    assert!(matches!(
        Soil {
            unloading_stiffness: 1e6,
            ..good
        }
        .check(),
        Err(SoilError::SoftUnloading { .. })
    ));
}
