//! Random roughness: the FFT against the direct sum of cosines, the
//! estimated PSD (Welch) against ISO 8608 in octave bands, the RMS against
//! its closed form, the detrended RMS against its target and its own
//! closed form, the run-in, determinism (the same seed gives the same
//! bits, here and on any machine: a recorded hash), and the errors.
//!
//! Tolerances, and why:
//! * FFT against the direct sum `Σ a_i cos(2π (ik mod N)/N + φ_i)`:
//!   `1e-12` of the largest |z|. Both are sums of ~N terms of size ≤ max a
//!   rounded at ~1e-16 each, the FFT in log₂N stages; their difference is
//!   ~1e-15 of the signal. A wrong twiddle, sign or bit reversal is off by
//!   O(1).
//! * Welch PSD in each octave band inside the band: within 20 % of
//!   ISO 8608's `∫ G_d dn` over the octave. The sum of cosines has
//!   deterministic amplitudes, so over a whole period its periodogram *is*
//!   the target line by line; the estimate's only scatter comes from
//!   cutting 10 km into 204.8 m Hann-windowed segments (lines of random
//!   phase leaking into each other's bins). With 96 half-overlapping
//!   segments and ≥ 12 bins in the lowest octave its relative standard
//!   deviation is a few per cent, so 20 % is over 5 σ on each of three
//!   seeds; a PSD off by a factor (wrong √2, wrong Δn, wrong exponent)
//!   misses by 40 % or more in some band.
//! * RMS of the fully rough part against `√(Σ G_d(n_i) Δn)`: 5 %. The
//!   closed form is exact over a whole period; 10 km of a 13.1 km period
//!   with wavelengths ≤ 20 m differs from it by cross terms of relative
//!   size ~ (longest wavelength / length) ≈ 0.2 %.
//! * Detrended RMS of a course by target: 5 % (the bound asked of a course); it is
//!   scaled to the target, so it meets it to rounding (~1e-16).
//! * Detrended RMS of a class course against the closed form
//!   `Σ G_d(n_i) Δn (1 − H(n_i))²`, `H` the moving average's response
//!   `sin(π n m Δx) / (m sin(π n Δx))`: 5 %, for the same reason as the
//!   RMS.
//! * A straight line detrended: `1e-12` m (rounding of sums of 61 values
//!   ≤ 15 m); a sine of 0.5 m wavelength: `1e-9` relative to its closed
//!   form (rounding of 1000 squares; the closed form is exact over whole
//!   periods).

use super::*;

use proptest::prelude::*;

/// `(max |a − b|, max |b|)` over two signals.
fn difference(a: &[f64], b: &[f64]) -> (f64, f64) {
    assert_eq!(a.len(), b.len());
    a.iter().zip(b).fold((0.0, 0.0), |(d, m), (&x, &y)| {
        (f64::max(d, (x - y).abs()), f64::max(m, y.abs()))
    })
}

/// The direct sum of the module docs, with the argument reduced exactly
/// in integers: `z_k = Σ a_i cos(2π ((i k) mod N) / N + φ_i)`.
fn direct_sum(lines: &[(usize, f64, f64)], period: usize, count: usize) -> Vec<f64> {
    (0..count)
        .map(|k| {
            lines
                .iter()
                .map(|&(i, a, phase)| {
                    let m = ((i as u64 * k as u64) % period as u64) as f64;
                    a * sin_cos(TAU * (m / period as f64) + phase).1
                })
                .sum()
        })
        .collect()
}

#[test]
fn the_fft_agrees_with_the_direct_sum() {
    let n = 1024;
    let mut rng = SplitMix64::new(11);
    let lines: Vec<(usize, f64, f64)> = (1..n / 2)
        .map(|i| (i, rng.next_f64(), TAU * rng.next_f64()))
        .collect();
    let mut c = vec![(0.0, 0.0); n];
    for &(i, a, phase) in &lines {
        let (s, cos) = sin_cos(phase);
        c[i] = (a * cos, a * s);
    }
    inverse_fft(&mut c);
    let fft: Vec<f64> = c.iter().map(|v| v.0).collect();
    let (d, m) = difference(&fft, &direct_sum(&lines, n, n));
    println!("FFT vs direct sum, N = {n}: {:e} of the largest |z|", d / m);
    assert!(d <= 1e-12 * m, "{d} vs {m}");
}

/// The course pipeline against the direct sum, re-deriving the lines and
/// phases from the module docs.
#[test]
fn a_course_is_the_direct_sum_of_its_lines() {
    let cases = [
        // spacing, length, band: N = 256 and N = 4096.
        (
            0.2,
            40.0,
            Band {
                n_min: 0.5,
                n_max: 2.5,
            },
        ),
        (0.05, 100.0, DEFAULT_BAND),
    ];
    for (spacing, length, band) in cases {
        let course = RoughCourse::new(Spectrum::Iso8608(Iso8608Class::D), length, spacing, 7)
            .with_band(band);
        let s = course.samples().unwrap();
        let (first, last) = s.lines;
        let mut rng = SplitMix64::new(7);
        let lines: Vec<(usize, f64, f64)> = (1..=last)
            .map(|i| (i, TAU * rng.next_f64()))
            .filter(|&(i, _)| i >= first)
            .map(|(i, phase)| {
                let n = i as f64 * s.dn;
                let a = (2.0 * Iso8608Class::D.gd_n0() * (N0 / n) * (N0 / n) * s.dn).sqrt();
                (i, a, phase)
            })
            .collect();
        let direct = direct_sum(&lines, s.period, s.heights.len());
        let (d, m) = difference(&s.heights, &direct);
        println!(
            "course N = {}, {} lines: FFT vs direct sum {:e} of the largest |z|",
            s.period,
            lines.len(),
            d / m
        );
        assert!(d <= 1e-12 * m, "{d} vs {m}");
        // The next line up is past n_max or at the Nyquist frequency.
        assert!(last < s.period / 2);
        assert!((last + 1) as f64 * s.dn > band.n_max || last + 1 == s.period / 2);
        assert!(first as f64 * s.dn >= band.n_min && (first - 1) as f64 * s.dn < band.n_min);
    }
}

/// Welch's method: Hann-windowed segments of `m` samples, half
/// overlapping, each's mean removed; the one-sided PSD
/// `P_j = 2 Δx |X_j|² / Σ w²` at `f_j = j / (m Δx)`, averaged.
fn welch(z: &[f64], dx: f64, m: usize) -> Vec<f64> {
    let window: Vec<f64> = (0..m)
        .map(|k| 0.5 - 0.5 * (TAU * k as f64 / m as f64).cos())
        .collect();
    let power: f64 = window.iter().map(|w| w * w).sum();
    let mut psd = vec![0.0; m / 2];
    let mut segments = 0;
    let mut start = 0;
    while start + m <= z.len() {
        let segment = &z[start..start + m];
        let mean = segment.iter().sum::<f64>() / m as f64;
        let mut c: Vec<(f64, f64)> = segment
            .iter()
            .zip(&window)
            .map(|(&v, &w)| ((v - mean) * w, 0.0))
            .collect();
        // |Σ x e^{+iθ}| = |Σ x e^{−iθ}| for real x.
        inverse_fft(&mut c);
        for (p, v) in psd.iter_mut().zip(&c) {
            *p += 2.0 * dx * (v.0 * v.0 + v.1 * v.1) / power;
        }
        segments += 1;
        start += m / 2;
    }
    for p in &mut psd {
        *p /= segments as f64;
    }
    psd
}

#[test]
fn the_welch_psd_is_within_20_percent_of_iso_8608_in_every_octave() {
    let (dx, m) = (0.05, 4096);
    let class = Iso8608Class::C;
    let df = 1.0 / (m as f64 * dx);
    let mut worst: f64 = 0.0;
    for seed in [1, 2, 3] {
        let s = RoughCourse::new(Spectrum::Iso8608(class), 10_000.0, dx, seed)
            .samples()
            .unwrap();
        let psd = welch(s.rough(), dx, m);
        let mut ratios = Vec::new();
        // Octaves [a, 2a) inside the band [0.05, 10): a = 1/16 … 4.
        for k in 0..7 {
            let a = 0.0625 * f64::powi(2.0, k);
            let estimate: f64 = (1..m / 2)
                .filter(|&j| (a..2.0 * a).contains(&(j as f64 * df)))
                .map(|j| psd[j] * df)
                .sum();
            let target = class.gd_n0() * N0 * N0 / (2.0 * a);
            let ratio = estimate / target;
            ratios.push(format!("{ratio:.3}"));
            worst = worst.max((ratio - 1.0).abs());
            assert!(
                (ratio - 1.0).abs() <= 0.2,
                "seed {seed}, octave [{a}, {}): {ratio}",
                2.0 * a
            );
        }
        println!("seed {seed}: Welch / ISO 8608 per octave from 1/16 cycles/m: {ratios:?}");
    }
    println!("worst octave: {:.1} % off (bound 20 %)", 100.0 * worst);
}

#[test]
fn the_rms_is_within_5_percent_of_the_closed_form() {
    for (class, seed) in [
        (Iso8608Class::A, 4),
        (Iso8608Class::E, 5),
        (Iso8608Class::H, 6),
    ] {
        let s = RoughCourse::new(Spectrum::Iso8608(class), 10_000.0, 0.05, seed)
            .with_run_in(20.0, 10.0)
            .samples()
            .unwrap();
        let rough = s.rough();
        let rms = (rough.iter().map(|z| z * z).sum::<f64>() / rough.len() as f64).sqrt();
        let e = rms / s.rms - 1.0;
        println!(
            "class {}: RMS {rms:.6e} m vs closed form {:.6e} m: {:+.3} %",
            class.letter(),
            s.rms,
            100.0 * e
        );
        assert!(e.abs() <= 0.05);
    }
}

/// The moving average's response at `n` cycles/m.
fn moving_average_response(n: f64, dx: f64, m: usize) -> f64 {
    let a = std::f64::consts::PI * n * dx;
    (a * m as f64).sin() / (m as f64 * a.sin())
}

#[test]
fn detrended_rms_matches_its_closed_form() {
    let (dx, base) = (0.05, DETRENDING_BASE_LENGTH);
    let s = RoughCourse::new(Spectrum::Iso8608(Iso8608Class::D), 10_000.0, dx, 8)
        .samples()
        .unwrap();
    let m = 2 * (base / (2.0 * dx)).round() as usize + 1;
    let expected: f64 = (s.lines.0..=s.lines.1)
        .map(|i| {
            let n = i as f64 * s.dn;
            let r = 1.0 - moving_average_response(n, dx, m);
            iso8608_psd(s.gd_n0, n) * s.dn * r * r
        })
        .sum::<f64>()
        .sqrt();
    let got = detrended_rms(s.rough(), dx, base).unwrap();
    let e = got / expected - 1.0;
    println!(
        "class D detrended RMS {got:.6e} m vs closed form {expected:.6e} m: {:+.3} % (plain RMS {:.4e} m)",
        100.0 * e,
        s.rms
    );
    assert!(e.abs() <= 0.05);
}

#[test]
fn a_course_by_target_rms_meets_it_after_detrending() {
    let inch = 0.0254;
    for (rms_in, length) in [(1.0, 304.8), (1.5, 304.8), (2.0, 1000.0), (4.0, 10_000.0)] {
        let target = rms_in * inch;
        let spectrum = Spectrum::DetrendedRms {
            rms: target,
            base_length: DETRENDING_BASE_LENGTH,
        };
        let s = RoughCourse::new(spectrum, length, 0.05, 9)
            .with_run_in(100.0, 10.0)
            .samples()
            .unwrap();
        let got = detrended_rms(s.rough(), 0.05, DETRENDING_BASE_LENGTH).unwrap();
        let e = got / target - 1.0;
        println!(
            "{rms_in} in over {length} m: detrended RMS {got:.6e} m, {e:+.1e} relative; plain RMS {:.4} in",
            s.rms / inch
        );
        assert!(e.abs() <= 0.05);
    }
}

#[test]
fn detrending_removes_a_line_and_keeps_short_waves() {
    let (dx, base) = (0.05, DETRENDING_BASE_LENGTH);
    let ramp: Vec<f64> = (0..1000).map(|k| 0.3 * (k as f64 * dx) - 2.0).collect();
    let r = detrended_rms(&ramp, dx, base).unwrap();
    assert!(r <= 1e-12, "{r}");
    // A sine of 0.5 m (10 samples) over 1000 residuals, 100 periods:
    // residual (1 − H) sin, mean square (1 − H)² A² / 2.
    let (h, amplitude) = (30, 0.07);
    let sine: Vec<f64> = (0..1000 + 2 * h)
        .map(|k| amplitude * (TAU * k as f64 / 10.0).sin())
        .collect();
    let expected = (1.0 - moving_average_response(2.0, dx, 2 * h + 1)) * amplitude / 2f64.sqrt();
    let got = detrended_rms(&sine, dx, base).unwrap();
    assert!((got / expected - 1.0).abs() <= 1e-9, "{got} vs {expected}");
    assert_eq!(
        detrended_rms(&sine[..60], dx, base),
        Err(RoughnessError::TooShort {
            samples: 60,
            window: 61,
            base_length: base,
            spacing: dx
        })
    );
}

#[test]
fn the_run_in_is_flat_then_fades_in() {
    let class = Spectrum::Iso8608(Iso8608Class::F);
    let blended = RoughCourse::new(class, 50.0, 0.05, 3)
        .starting_at(-7.0)
        .with_run_in(10.0, 5.0)
        .samples()
        .unwrap();
    // The same period and phases without the run-in.
    let raw = RoughCourse::new(class, 65.0, 0.05, 3).samples().unwrap();
    assert_eq!(blended.heights.len(), raw.heights.len());
    assert_eq!(blended.rough_from, 300);
    for (k, (&b, &r)) in blended.heights.iter().zip(&raw.heights).enumerate() {
        let s = k as f64 * 0.05;
        let expected = if s < 10.0 {
            0.0
        } else if s < 15.0 {
            r * (0.5 - 0.5 * sin_cos(PI * ((s - 10.0) / 5.0)).1)
        } else {
            r
        };
        assert_eq!(b.to_bits(), expected.to_bits(), "k = {k}");
    }
    let p = blended.profile().unwrap();
    assert_eq!(p.point(0), (-7.0, 0.0));
    assert_eq!(p.point_count(), 1301);
    assert_eq!(p.x_range().1, -7.0 + 1300.0 * 0.05);
}

/// FNV-1a over the samples' bits.
fn fnv1a(values: &[f64]) -> u64 {
    values
        .iter()
        .flat_map(|v| v.to_bits().to_le_bytes())
        .fold(0xCBF2_9CE4_8422_2325, |h, b| {
            (h ^ b as u64).wrapping_mul(0x0000_0100_0000_01B3)
        })
}

/// The same seed gives the same bits: twice in a run, and as recorded
/// (the hash below was computed once on x86-64; a machine whose
/// arithmetic differed would change it).
#[test]
fn the_same_seed_gives_the_same_bits() {
    let iso = RoughCourse::new(Spectrum::Iso8608(Iso8608Class::D), 500.0, 0.05, 42)
        .with_run_in(10.0, 5.0);
    let rms = RoughCourse::new(
        Spectrum::DetrendedRms {
            rms: 0.0508,
            base_length: DETRENDING_BASE_LENGTH,
        },
        304.8,
        0.05,
        2016,
    )
    .with_run_in(100.0, 10.0);
    let mut hashes = Vec::new();
    for course in [iso, rms] {
        let (a, b) = (course.samples().unwrap(), course.samples().unwrap());
        assert_eq!(a, b);
        assert!(
            a.heights
                .iter()
                .zip(&b.heights)
                .all(|(x, y)| x.to_bits() == y.to_bits())
        );
        let hash = fnv1a(&a.heights);
        println!("{} samples, FNV-1a {hash:#018x}", a.heights.len());
        hashes.push(hash);
    }
    assert_eq!(
        hashes,
        [0x4be6_3a42_df7c_73a6, 0x2b1a_6824_e2ca_b119],
        "the courses' bits changed"
    );
}

#[test]
fn different_seeds_give_different_courses() {
    let course = |seed| {
        RoughCourse::new(Spectrum::Iso8608(Iso8608Class::C), 1000.0, 0.05, seed)
            .samples()
            .unwrap()
    };
    let (a, b) = (course(1), course(2));
    let differ = a
        .heights
        .iter()
        .zip(&b.heights)
        .filter(|(x, y)| x != y)
        .count();
    let fraction = differ as f64 / a.heights.len() as f64;
    println!("seeds 1 and 2: {:.4} % of samples differ", 100.0 * fraction);
    assert!(fraction > 0.99);
    // Uncorrelated: |correlation| well below 1.
    let dot = |x: &[f64], y: &[f64]| x.iter().zip(y).map(|(p, q)| p * q).sum::<f64>();
    let r = dot(&a.heights, &b.heights)
        / (dot(&a.heights, &a.heights) * dot(&b.heights, &b.heights)).sqrt();
    assert!(r.abs() < 0.5, "correlation {r}");
}

#[test]
fn splitmix64_matches_its_reference() {
    // Rosetta Code, "Pseudo-random numbers/Splitmix64": seed 1234567.
    let mut rng = SplitMix64::new(1_234_567);
    let first: Vec<u64> = (0..5).map(|_| rng.next_u64()).collect();
    assert_eq!(
        first,
        [
            6457827717110365317,
            3203168211198807973,
            9817491932198370423,
            4593380528125082431,
            16408922859458223821
        ]
    );
    let u = SplitMix64::new(0).next_f64();
    assert_eq!(
        u,
        (0xE220_A839_7B1D_CDAF_u64 >> 11) as f64 / (1u64 << 53) as f64
    );
}

#[test]
fn iso_classes_are_the_geometric_means() {
    let expected = [
        16e-6, 64e-6, 256e-6, 1024e-6, 4096e-6, 16384e-6, 65536e-6, 262144e-6,
    ];
    for (class, g) in Iso8608Class::ALL.into_iter().zip(expected) {
        assert_eq!(class.gd_n0(), g, "{class:?}");
        assert_eq!(Iso8608Class::from_letter(class.letter()), Some(class));
        assert_eq!(
            Iso8608Class::from_letter(class.letter().to_ascii_lowercase()),
            Some(class)
        );
    }
    assert_eq!(Iso8608Class::from_letter('I'), None);
    assert_eq!(Iso8608Class::from_letter('@'), None);
    assert_eq!(iso8608_psd(16e-6, N0), 16e-6);
    assert_eq!(iso8608_psd(16e-6, 2.0 * N0), 4e-6);
}

#[test]
fn parameters_out_of_range_are_errors() {
    let base = RoughCourse::new(Spectrum::Iso8608(Iso8608Class::A), 100.0, 0.05, 0);
    let parameter = |course: RoughCourse| match course.samples() {
        Err(RoughnessError::Parameter { parameter, .. }) => parameter,
        other => panic!("{other:?}"),
    };
    assert_eq!(
        parameter(RoughCourse {
            length: 0.0,
            ..base
        }),
        "length"
    );
    assert_eq!(
        parameter(RoughCourse {
            spacing: f64::NAN,
            ..base
        }),
        "spacing"
    );
    assert_eq!(
        parameter(RoughCourse {
            spacing: 11.0,
            ..base
        }),
        "spacing"
    );
    assert_eq!(parameter(base.starting_at(2e6)), "start");
    assert_eq!(parameter(base.with_run_in(-1.0, 0.0)), "run_in");
    assert_eq!(parameter(base.with_run_in(0.0, f64::INFINITY)), "taper");
    let band = |n_min, n_max| base.with_band(Band { n_min, n_max });
    assert_eq!(parameter(band(0.0, 1.0)), "n_min");
    assert_eq!(parameter(band(1.0, 1.0)), "n_max");
    let rms = |rms, base_length| RoughCourse {
        spectrum: Spectrum::DetrendedRms { rms, base_length },
        ..base
    };
    assert_eq!(parameter(rms(0.0, 3.0)), "rms");
    assert_eq!(parameter(rms(0.05, 0.01)), "base_length");
    // Above the Nyquist frequency of 5 cm: no line.
    assert!(matches!(
        band(20.0, 30.0).samples(),
        Err(RoughnessError::EmptyBand { nyquist, .. }) if nyquist == 10.0
    ));
    assert!(matches!(
        RoughCourse {
            length: 1e6,
            spacing: 0.001,
            ..base
        }
        .samples(),
        Err(RoughnessError::TooManySamples { .. })
    ));
    // A target RMS on a course shorter than one detrending window.
    assert!(matches!(
        rms(0.05, 3.048)
            .with_band(DEFAULT_BAND)
            .samples()
            .map(|_| ()),
        Ok(())
    ));
    assert!(matches!(
        RoughCourse {
            length: 2.0,
            ..rms(0.05, 3.048)
        }
        .samples(),
        Err(RoughnessError::TooShort { .. })
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// No parameters panic the generator: in range or not, it returns
    /// samples or an error.
    #[test]
    fn no_parameters_panic(
        length in prop_oneof![Just(f64::NAN), -1.0..300.0f64],
        spacing in prop_oneof![Just(0.0), 0.0005..2.0f64],
        run_in in -1.0..20.0f64,
        taper in -1.0..20.0f64,
        n_min in prop_oneof![Just(0.0), 1e-3..5.0f64],
        n_max in 0.0..50.0f64,
        rms in -0.1..0.2f64,
        base_length in 0.0..10.0f64,
        seed in any::<u64>(),
        by_class in any::<bool>(),
    ) {
        let spectrum = if by_class {
            Spectrum::Iso8608(Iso8608Class::B)
        } else {
            Spectrum::DetrendedRms { rms, base_length }
        };
        let course = RoughCourse::new(spectrum, length, spacing, seed)
            .with_run_in(run_in, taper)
            .with_band(Band { n_min, n_max });
        if let Ok(s) = course.samples() {
            prop_assert!(s.heights.iter().all(|z| z.is_finite()));
            prop_assert!(s.profile().is_ok());
        }
    }
}
