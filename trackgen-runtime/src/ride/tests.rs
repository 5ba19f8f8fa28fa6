//! Tests of the ride criteria against their continuous closed forms
//! (Lee & Pradko's absorbed-power filter as Project Chrono publishes it,
//! ISO 2631-1:1997 Annex A, a 4-pole Butterworth; the guide's "The seat
//! and the ride" states each) and the values they give by hand. Run with
//! `--nocapture` to see the measured figures.

use std::f64::consts::PI;

use super::*;

/// The sample interval of the runs here, s.
const DT: f64 = 1e-3;

/// The continuous frequency the bilinear image of a section prewarped at
/// `fp` (0: none) responds with at the digital frequency `f`.
fn warped(f: f64, fp: f64, dt: f64) -> f64 {
    if fp > 0.0 {
        fp * (PI * f * dt).tan() / (PI * fp * dt).tan()
    } else {
        (PI * f * dt).tan() / (PI * dt)
    }
}

/// `d ln|H| / d ln f` of a continuous section, by central difference.
fn log_slope(s: &Section, f: f64) -> f64 {
    let h: f64 = 1e-4;
    (s.response(f * h.exp()).ln() - s.response(f * (-h).exp()).ln()) / (2.0 * h)
}

/// The bound on `|H_d/H − 1|` that the warp predicts: each stage's
/// magnitude moves by its log-slope times `ln(Ω/ω)`; to first order
/// `|ln(H_d/H)| ≤ Σ |slope_i| |ln(Ω_i/ω)|`. The factor 1.1 covers the
/// change of slope across `[ω, Ω]` (|ln(Ω/ω)| ≤ 0.033 here) and
/// `|e^x − 1| ≤ 1.1 |x|` for `|x| ≤ 0.1`.
fn warp_bound<const N: usize>(c: &Cascade<N>, f: f64) -> f64 {
    let sum: f64 = c
        .stages()
        .iter()
        .map(|b| {
            log_slope(b.section(), f).abs() * (warped(f, b.prewarp_hz(), b.dt()) / f).ln().abs()
        })
        .sum();
    1.1 * sum
}

/// Compares the discrete response with the continuous one on `[lo, hi]`
/// every 0.05 Hz; checks the exact warp identity and the warp bound;
/// returns the largest `|H_d/H − 1|`.
fn check_band<const N: usize>(name: &str, c: &Cascade<N>, lo: f64, hi: f64) -> f64 {
    let (mut worst, mut ratio): (f64, f64) = (0.0, 0.0);
    let steps = ((hi - lo) / 0.05).round() as usize;
    for i in 0..=steps {
        let f = lo + 0.05 * i as f64;
        let (hd, hc) = (c.response_discrete(f), c.response_continuous(f));
        // The bilinear transform is exact at the warped frequency: only
        // rounding separates the two. The 0.4 Hz high-pass's `1 + a1 z⁻¹ +
        // a2 z⁻²` nearly vanishes at low f (≈ θ², θ = 2πf·dt ≥ 3.1e-3),
        // so a few ε of rounding become ~4ε/θ² ≈ 1e-10 relative: 1e-9.
        let exact: f64 = c
            .stages()
            .iter()
            .map(|b| b.section().response(warped(f, b.prewarp_hz(), b.dt())))
            .product();
        assert!(
            (hd / exact - 1.0).abs() < 1e-9,
            "{name} {f} Hz: {hd} vs {exact}"
        );
        let err = (hd / hc - 1.0).abs();
        let bound = warp_bound(c, f) + 1e-9;
        assert!(
            err <= bound,
            "{name} {f} Hz: |Hd/H - 1| = {err:e} > {bound:e}"
        );
        worst = worst.max(err);
        ratio = ratio.max(err / bound);
    }
    println!(
        "{name}: max |Hd/H - 1| on [{lo}, {hi}] Hz at dt = {DT}: {worst:.3e}, max err/bound {ratio:.3}"
    );
    worst
}

/// Samples of `a sin(2π f t)` at `t = k·DT`, `k` from `k0`.
fn sine(a: f64, f: f64, k0: usize, n: usize) -> impl Iterator<Item = f64> {
    (k0..k0 + n).map(move |k| a * (2.0 * PI * f * k as f64 * DT).sin())
}

/// The finite-averaging bound on `|mean(y²)/(A²/2) − 1|` for a sampled
/// sine of any phase over `n` samples: `Σ sin² = n/2 − ½ Σ cos(2θk + φ)`
/// and `|Σ cos(2θk + φ)| ≤ 1/|sin θ|`, `θ = 2π f DT`.
fn averaging_bound(f: f64, n: usize) -> f64 {
    1.0 / (n as f64 * (2.0 * PI * f * DT).sin().abs())
}

#[test]
fn absorbed_power_closed_form() {
    // The closed form's values `|H(j2πf)|²`, W/(ft/s²)², computed apart to
    // 4 significant digits: tolerance half a unit in the last digit, plus
    // 1e-12 for rounding.
    let ap = AbsorbedPower::new(DT);
    // Chrono's 1 m = 3.280839895 ft (the exact 1/0.3048), to its 10 digits.
    assert!((FT_PER_M - 3.280839895).abs() < 5e-10);
    let cases = [
        (1.0, 0.007754, 5e-7),
        (2.0, 0.03815, 5e-6),
        (4.4, 0.2081, 5e-5),
        (5.0, 0.1959, 5e-5),
        (10.0, 0.04935, 5e-6),
        (20.0, 0.01266, 5e-6),
    ];
    for (f, want, tol) in cases {
        let got = ap.response_continuous(f).powi(2);
        println!("AP |H({f} Hz)|^2 = {got:.7} (closed form {want})");
        assert!((got - want).abs() <= tol + 1e-12, "{f} Hz: {got} vs {want}");
    }
}

#[test]
fn iso_weightings_closed_form() {
    // ISO 2631-1:1997's tabulated weighting factors (its Table 3, in
    // thousandths): tolerance half a unit in the last digit (5e-4), except
    // W_k at 16 Hz: the formula gives 0.76870 (0.76895 without band
    // limiting), 0.769 when rounded; the table's 0.768 is 0.7 of a unit
    // below, and is held to one unit (1e-3).
    let wk = IsoWeighting::wk(DT);
    for (f, want, tol) in [
        (1.0, 0.482, 5e-4),
        (4.0, 0.967, 5e-4),
        (8.0, 1.036, 5e-4),
        (16.0, 0.768, 1e-3),
    ] {
        let got = wk.response_continuous(f);
        println!("|W_k({f} Hz)| = {got:.6} (table {want})");
        assert!((got - want).abs() <= tol, "W_k {f} Hz: {got} vs {want}");
    }
    assert!((wk.response_continuous(16.0) - 0.769).abs() < 5e-4);
    let wd = IsoWeighting::wd(DT);
    for (f, want) in [
        (0.5, 0.853),
        (1.0, 1.011),
        (2.0, 0.890),
        (4.0, 0.512),
        (8.0, 0.253),
        (16.0, 0.125),
    ] {
        let got = wd.response_continuous(f);
        println!("|W_d({f} Hz)| = {got:.6} (table {want})");
        assert!((got - want).abs() <= 5e-4, "W_d {f} Hz: {got} vs {want}");
    }
    // The table's values include the band limiting: without it (stages 3
    // and 4 only) |W_d(0.5 Hz)| = 1.0125 and |W_k(1 Hz)| = 0.4886, both
    // off by more than 5e-3.
    let unlimited = |w: &IsoWeighting, f: f64| -> f64 {
        w.filter().stages()[2..]
            .iter()
            .map(|b| b.response_continuous(f))
            .product()
    };
    assert!((unlimited(&wd, 0.5) - 0.853).abs() > 5e-3);
    assert!((unlimited(&wk, 1.0) - 0.482).abs() > 5e-3);
}

#[test]
fn peak_filter_closed_form() {
    // A 4-pole Butterworth: |H|² = 1/(1 + (f/30)⁸) exactly (rounding only).
    let p = PeakVertical::new(DT);
    for f in [1.0, 10.0, 30.0, 60.0, 100.0] {
        let want = 1.0 / (1.0 + (f / 30.0f64).powi(8)).sqrt();
        assert!((p.response_continuous(f) / want - 1.0).abs() < 1e-12);
    }
    // Prewarped at 30 Hz: the digital -3 dB point is 30 Hz.
    assert!((p.response_discrete(30.0) - std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-12);
}

#[test]
fn discrete_matches_continuous_in_band() {
    // Each bound is the warp prediction of `warp_bound`, checked point by
    // point; the maxima are also held to the figures in the module docs.
    let ap = check_band("absorbed power", AbsorbedPower::new(DT).filter(), 0.5, 20.0);
    let wk = check_band("W_k", IsoWeighting::wk(DT).filter(), 0.5, 20.0);
    let wd = check_band("W_d", IsoWeighting::wd(DT).filter(), 0.5, 20.0);
    let pk = check_band("peak 30 Hz", PeakVertical::new(DT).filter(), 0.5, 30.0);
    assert!(ap < 1.3e-3 && wk < 0.65e-3 && wd < 1.3e-3 && pk < 0.72e-3);
    // Within 1 % up to 40 Hz (0.08 of Nyquist) for all.
    for f in (1..=40).map(f64::from) {
        let errs = [
            rel_err(AbsorbedPower::new(DT).filter(), f),
            rel_err(IsoWeighting::wk(DT).filter(), f),
            rel_err(IsoWeighting::wd(DT).filter(), f),
            rel_err(PeakVertical::new(DT).filter(), f),
        ];
        assert!(errs.iter().all(|e| *e < 0.01), "{f} Hz: {errs:?}");
    }
}

fn rel_err<const N: usize>(c: &Cascade<N>, f: f64) -> f64 {
    (c.response_discrete(f) / c.response_continuous(f) - 1.0).abs()
}

#[test]
fn absorbed_power_prewarp_vs_plain_bilinear() {
    // Chrono discretises the whole H with the plain bilinear transform
    // (K = 2/dt); the bilinear image of a product is the product of the
    // images at the same K, so prewarp 0 on both stages is Chrono's
    // filter. Prewarping a stage at f_p rescales its frequency axis by the
    // constant tan(πf_p dt)/(πf_p dt) (3.3e-4 at 10.03 Hz, 6.3e-5 at
    // 4.36 Hz), so the two differ by the stages' log-slopes times those
    // (× 1.1 as in `warp_bound`).
    let ours = *AbsorbedPower::new(DT).filter();
    let plain = Cascade::new(
        ours.stages()
            .map(|b| Biquad::bilinear(*b.section(), DT, 0.0)),
    );
    let mut worst: f64 = 0.0;
    for i in 0..=390 {
        let f = 0.5 + 0.05 * f64::from(i);
        let err = (ours.response_discrete(f) / plain.response_discrete(f) - 1.0).abs();
        let bound: f64 = ours
            .stages()
            .iter()
            .map(|b| {
                let x = PI * b.prewarp_hz() * DT;
                1.1 * log_slope(b.section(), f).abs() * (x.tan() / x).ln()
            })
            .sum();
        assert!(err <= bound + 1e-12, "{f} Hz: {err:e} > {bound:e}");
        worst = worst.max(err);
    }
    println!("absorbed power, prewarped vs plain bilinear, 0.5-20 Hz: {worst:.2e}");
    assert!(worst < 4e-4);
}

#[test]
fn absorbed_power_steady_state() {
    // 2 s run-in: the slowest pole decays as e^{-12 t} (s² + 24 s + 750),
    // e^{-24} ≈ 4e-11 left. 200 s measured. Tolerance: finite averaging
    // (`averaging_bound`) + the squared discretisation error
    // (2.1 × warp_bound) + 1e-9 for the transient and rounding.
    let n = 200_000;
    for f in [1.0, 4.4, 10.0] {
        let a = 1.0; // m/s²
        let mut ap = AbsorbedPower::new(DT);
        sine(a, f, 0, 2000).for_each(|x| {
            ap.push(x);
        });
        ap.start_measuring();
        sine(a, f, 2000, n).for_each(|x| {
            ap.push(x);
        });
        assert_eq!(ap.samples(), n as u64);
        let a_ft = a * FT_PER_M;
        let want = ap.response_continuous(f).powi(2) * a_ft * a_ft / 2.0;
        let err = (ap.power() / want - 1.0).abs();
        let tol = averaging_bound(f, n) + 2.1 * warp_bound(ap.filter(), f) + 1e-9;
        println!(
            "AP {f} Hz: {:.6} W, want {want:.6} W, rel err {err:.2e} <= {tol:.2e}",
            ap.power()
        );
        assert!(err <= tol);
        // Against the discrete response only averaging is left.
        let want_d = ap.response_discrete(f).powi(2) * a_ft * a_ft / 2.0;
        let err_d = (ap.power() / want_d - 1.0).abs();
        assert!(err_d <= averaging_bound(f, n) + 1e-9, "{err_d}");
    }
}

#[test]
fn iso_weighted_rms_steady_state() {
    // 20 s run-in: the slowest pole (0.4 Hz high-pass, Q = 1/√2) decays
    // as e^{-1.78 t}, e^{-35} left. 200 s measured. The r.m.s. is the
    // square root of the mean, so its relative error is half the mean's:
    // averaging_bound/2 + 1.01 × warp_bound + 1e-9.
    let n = 200_000;
    let cases = [
        ("W_k", IsoWeighting::wk(DT), [1.0, 4.0, 8.0, 16.0]),
        ("W_d", IsoWeighting::wd(DT), [0.5, 1.0, 4.0, 16.0]),
    ];
    for (name, w0, freqs) in cases {
        for f in freqs {
            let a = 2.0; // m/s²
            let mut w = w0;
            sine(a, f, 0, 20_000).for_each(|x| {
                w.push(x);
            });
            w.start_measuring();
            sine(a, f, 20_000, n).for_each(|x| {
                w.push(x);
            });
            let want = w.response_continuous(f) * a / 2f64.sqrt();
            let err = (w.rms() / want - 1.0).abs();
            let tol = averaging_bound(f, n) / 2.0 + 1.01 * warp_bound(w.filter(), f) + 1e-9;
            println!(
                "{name} {f} Hz: a_w = {:.6}, want {want:.6}, rel err {err:.2e} <= {tol:.2e}",
                w.rms()
            );
            assert!(err <= tol);
        }
    }
}

#[test]
fn peak_vertical_sines() {
    // 5 Hz, 1 g: |H| = 1 − 9e-7 and the largest 1 ms sample of a 5 Hz
    // sine is within 1 − cos(π·5·DT) = 1.2e-4 of its amplitude, so 1 %
    // (the brief's tolerance) leaves room for the start-up overshoot too.
    let mut p = PeakVertical::new(DT);
    sine(G, 5.0, 0, 1000).for_each(|x| {
        p.push(x);
    });
    let with_transient = p.peak_g();
    p.start_measuring();
    sine(G, 5.0, 1000, 1000).for_each(|x| {
        p.push(x);
    });
    println!(
        "peak at 5 Hz, 1 g: {with_transient:.5} g from t = 0, {:.6} g after 1 s",
        p.peak_g()
    );
    assert!((with_transient - 1.0).abs() < 0.01);
    assert!((p.peak_g() - 1.0).abs() < 0.01);
    assert!((p.max_g() + p.min_g()).abs() < 1e-3, "a sine is symmetric");

    // 100 Hz, 1 g, after 0.5 s: the output is a sine of amplitude
    // |H_d(100 Hz)|, sampled 10 times a period, so its largest sample is
    // between cos(π/10) and 1 times that. |H_d| is within a factor 2 of
    // the Butterworth's asymptote (30/100)⁴ = 8.1e-3.
    let mut p = PeakVertical::new(DT);
    sine(G, 100.0, 0, 500).for_each(|x| {
        p.push(x);
    });
    p.start_measuring();
    sine(G, 100.0, 500, 1000).for_each(|x| {
        p.push(x);
    });
    let hd = p.response_discrete(100.0);
    let asymptote = (30.0f64 / 100.0).powi(4);
    println!(
        "peak at 100 Hz, 1 g: {:.5} g; |H_d| = {hd:.5}, |H| = {:.5}, (30/100)^4 = {asymptote:.5}",
        p.peak_g(),
        p.response_continuous(100.0)
    );
    assert!(hd > 0.5 * asymptote && hd < 2.0 * asymptote);
    assert!(p.peak_g() <= hd * (1.0 + 1e-9) && p.peak_g() >= hd * (PI / 10.0).cos() * (1.0 - 1e-9));
}

#[test]
fn reset_and_start_measuring() {
    let mut ap = AbsorbedPower::new(DT);
    let mut w = IsoWeighting::wk(DT);
    let mut p = PeakVertical::new(DT);
    assert_eq!((ap.power(), w.rms(), p.peak_g()), (0.0, 0.0, 0.0));
    for x in sine(3.0, 2.0, 0, 777) {
        ap.push(x);
        w.push(x);
        p.push(x);
    }
    ap.start_measuring();
    w.start_measuring();
    assert_eq!((ap.samples(), w.samples(), ap.power()), (0, 0, 0.0));
    ap.reset();
    w.reset();
    p.reset();
    assert_eq!(ap, AbsorbedPower::new(DT));
    assert_eq!(w, IsoWeighting::wk(DT));
    assert_eq!(p, PeakVertical::new(DT));
}

#[test]
#[should_panic(expected = "Nyquist")]
fn prewarp_above_nyquist_panics() {
    // 100 Hz band limit at dt = 5 ms is at Nyquist.
    IsoWeighting::wd(5e-3);
}

#[test]
fn constant_memory() {
    // By construction: every type is Copy (so it owns no heap: a Copy type
    // cannot have a Drop, hence no Vec or Box) and of fixed size; pushing
    // 10⁶ samples changes neither.
    fn copy_and_small<T: Copy>() {
        assert!(
            std::mem::size_of::<T>() <= 512,
            "{}",
            std::mem::size_of::<T>()
        );
    }
    copy_and_small::<AbsorbedPower>();
    copy_and_small::<IsoWeighting>();
    copy_and_small::<PeakVertical>();
    let (mut ap, mut wk, mut wd, mut p) = (
        AbsorbedPower::new(DT),
        IsoWeighting::wk(DT),
        IsoWeighting::wd(DT),
        PeakVertical::new(DT),
    );
    // A deterministic pseudo-random input (64-bit LCG, Knuth's MMIX).
    let mut state: u64 = 1;
    for _ in 0..1_000_000 {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        let x = (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
        ap.push(x);
        wk.push(x);
        wd.push(x);
        p.push(x);
    }
    assert_eq!(
        (ap.samples(), wk.samples(), wd.samples()),
        (1_000_000, 1_000_000, 1_000_000)
    );
    assert!(ap.power().is_finite() && wk.rms().is_finite() && wd.rms().is_finite());
    assert!(p.peak_g().is_finite() && p.peak_g() > 0.0);
}

/// A deterministic pseudo-random phase in `[0, 2π)` (SplitMix64).
fn phase(i: u64) -> f64 {
    let mut z = i
        .wrapping_add(0x9E37_79B9_7F4A_7C15)
        .wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^= z >> 31;
    2.0 * PI * (z >> 11) as f64 / (1u64 << 53) as f64
}

/// A tone on a bin's frequency puts its mean square, `A²/2`, into that
/// bin and one each side (the Hann window's main lobe), exactly: Welch's
/// density is scaled so that `Σ S Δf` is the mean square.
#[test]
fn a_tone_on_a_bin_carries_its_mean_square() {
    let segment = 4096;
    let mut welch = Welch::new(DT, segment).unwrap();
    let df = 1.0 / (segment as f64 * DT);
    let (amplitude, bin) = (1.7, 123);
    let f = bin as f64 * df;
    for i in 0..(segment * 6) {
        welch.push(amplitude * (2.0 * PI * f * i as f64 * DT + 0.3).sin());
    }
    let s = welch.spectrum().unwrap();
    assert_eq!(s.segments, 11);
    let expected = amplitude * amplitude / 2.0;
    let total = s.mean_square();
    let lobe: f64 = s.psd[bin - 1..=bin + 1].iter().sum::<f64>() * s.df;
    println!("tone: mean square {total:.12}, main lobe {lobe:.12}, A²/2 {expected}");
    // Rounding only: the window's cross terms vanish on a bin.
    assert!((total / expected - 1.0).abs() < 1e-9);
    assert!((lobe / expected - 1.0).abs() < 1e-9);
    let lines = s.lines(&s.psd.iter().map(|p| p * s.df).collect::<Vec<_>>(), 3, 1);
    assert_eq!(lines[0].frequency, f);
    assert!((lines[0].carried / expected - 1.0).abs() < 1e-9);
}

/// A tone between bins leaks: the Hann window's first sidelobes are
/// −31 dB, so two bins either side hold all but a part in a thousand of
/// it, and the total is still its mean square (to the window's ripple
/// over a non-integer number of cycles, 1e-3).
#[test]
fn a_tone_between_bins_stays_within_two_bins() {
    let segment = 2048;
    let mut welch = Welch::new(DT, segment).unwrap();
    let df = 1.0 / (segment as f64 * DT);
    let f = 40.5 * df;
    for i in 0..(segment * 20) {
        welch.push((2.0 * PI * f * i as f64 * DT).cos());
    }
    let s = welch.spectrum().unwrap();
    let total = s.mean_square();
    let near: f64 = s.psd[38..=43].iter().sum::<f64>() * s.df;
    println!("off-bin tone: mean square {total:.6}, within two bins {near:.6}");
    assert!((total / 0.5 - 1.0).abs() < 1e-3);
    assert!(near / total > 0.999);
}

/// The absorbed power summed over the spectrum equals the time-domain
/// filter's mean square over the same samples: a course-like signal (200
/// tones from 0.5 to 60 Hz with random phases, 400 s at 1 ms). The two
/// routes differ by the bilinear filter's discretisation (1.3e-3 in `|H|`
/// below 20 Hz, `ride`'s docs: 2.6e-3 in `|H|²`), the Hann window's
/// leakage, and the filter's start and the segments' edges over a finite
/// record: 3e-3 against the filter; against the tones' closed form
/// `Σ |H|² A²/2`, leakage and the record alone, 1e-3.
#[test]
fn the_spectrum_sums_to_the_absorbed_power() {
    let segment = Welch::segment_for(DT, 8.0);
    assert_eq!(segment, 8192);
    let mut welch = Welch::new(DT, segment).unwrap();
    let mut filter = AbsorbedPower::new(DT);
    let tones: Vec<(f64, f64, f64)> = (0..200u64)
        .map(|i| {
            let f = 0.5 + 59.5 * (i as f64 + 0.5) / 200.0;
            (f, 2.0 / (1.0 + f / 5.0), phase(i))
        })
        .collect();
    let n = 400_000;
    for i in 0..n {
        let t = i as f64 * DT;
        let a: f64 = tones
            .iter()
            .map(|(f, amp, ph)| amp * (2.0 * PI * f * t + ph).sin())
            .sum();
        if i == 10_000 {
            filter.start_measuring();
        }
        filter.push(a);
        welch.push(a);
    }
    let s = welch.spectrum().unwrap();
    let spectral: f64 = s.absorbed().iter().sum();
    let direct = filter.power();
    let closed: f64 = tones
        .iter()
        .map(|(f, amp, _)| {
            let h = filter.response_continuous(*f);
            h * h * (amp * FT_PER_M).powi(2) / 2.0
        })
        .sum();
    println!(
        "absorbed power: spectrum {spectral:.5} W, filter {direct:.5} W, closed form {closed:.5} W"
    );
    assert!((spectral / direct - 1.0).abs() < 3e-3);
    assert!((spectral / closed - 1.0).abs() < 1e-3);
}

/// Lines on the shoe passage's harmonics are named so; others are not,
/// unless a mode is near.
#[test]
fn lines_are_named_by_the_shoe_passage() {
    let (speed, pitch) = (5.0, 0.154);
    let passage = speed / pitch;
    let line = |f| Line {
        frequency: f,
        carried: 1.0,
    };
    assert_eq!(
        line(2.0 * passage + 0.05).shoe_harmonic(speed, pitch, 0.1),
        Some(2.0)
    );
    assert_eq!(
        line(0.5 * passage).shoe_harmonic(speed, pitch, 0.1),
        Some(0.5)
    );
    assert_eq!(line(0.7 * passage).shoe_harmonic(speed, pitch, 0.1), None);
    let modes = [(3.2, "hull bounce".to_string())];
    assert_eq!(
        line(3.25).name(speed, pitch, &modes, (0.1, 0.1)).as_deref(),
        Some("hull bounce (3.20 Hz at rest)")
    );
    assert_eq!(line(4.0).name(speed, pitch, &modes, (0.1, 0.1)), None);
}

#[test]
fn a_bad_segment_or_interval_is_refused() {
    assert_eq!(
        Welch::new(DT, 1000).unwrap_err(),
        SpectrumError::Segment(1000)
    );
    assert_eq!(Welch::new(DT, 8).unwrap_err(), SpectrumError::Segment(8));
    assert!(matches!(
        Welch::new(0.0, 1024),
        Err(SpectrumError::Interval(_))
    ));
    assert!(Welch::new(DT, 1024).unwrap().spectrum().is_none());
}
