//! The whole ride chain against a closed form: a rigid hull on two
//! spring-damper axles (bounce and pitch, linear) driven over a
//! sinusoidal road at speed `v`, integrated, its seat's acceleration
//! streamed into a `RideSink` at 1 ms; the absorbed power and the `W_k`
//! RMS it reports against the steady state of the same linear system in
//! the frequency domain: `P = |H(jω)|² |a(jω)|² / 2` (the filter's
//! continuous gain per ft/s², the seat's acceleration amplitude in ft/s²)
//! and `W_k RMS = |W_k(jω)| |a(jω)| / √2`.
//!
//! The steady state is solved as phasors: with the road `z(s) = A sin(2π s
//! / λ)` the axles at `x_i` see `Z_i = A e^{j ω x_i / v}`, `ω = 2π v / λ`,
//! and `(K + jωC − ω² M) q = Σ (k_i + jω c_i) Z_i [1, x_i]` for `q = (h,
//! θ)`; the seat at `x_s` accelerates `−ω² (h + x_s θ)`. Measured over 20
//! road periods after 10 s (the slowest mode decays as `e^{−ζω_n t}`,
//! ζω_n ≈ 2 /s: e^{−20} by then). Tolerance 2 % (the issue's): the
//! filters' discretisation at 1 ms is 1e-3 (`ride`'s docs), the
//! integration at 1e-10 far below, so the bound is loose by an order and
//! still catches a factor lost in units (ft against m: ×10.8), a filter
//! at the wrong frequency or a measurement window that is not whole
//! periods. Measured at 1, 2, 4.4 and 8 Hz: the absorbed power within
//! 0.07, 0.06, 0.04 and 0.09 %, `W_k` within 0.02 %.

use trackgen::integrate::{Integrator, OdeSystem, SimulationError};
use trackgen::nalgebra::{Complex, DVector, Matrix2, Vector2};
use trackgen::ride::{AbsorbedPower, FT_PER_M, IsoWeighting};
use trackgen::simulate::{Output, RideSink, Sink, simulate_into};
use trackgen::system::Simulated;

/// The hull: mass, pitch inertia, the axles' positions (m, from the
/// centroid), stiffnesses (N/m) and dampings (N s/m), the seat's x, the
/// road's amplitude (m) and wavelength (m), the speed (m/s).
#[derive(Clone, Copy)]
struct Hull {
    mass: f64,
    inertia: f64,
    axles: [(f64, f64, f64); 2],
    seat: f64,
    amplitude: f64,
    wavelength: f64,
    speed: f64,
}

impl Hull {
    fn road(&self, t: f64, x: f64) -> (f64, f64) {
        let k = 2.0 * std::f64::consts::PI / self.wavelength;
        let s = self.speed * t + x;
        (
            self.amplitude * (k * s).sin(),
            self.amplitude * k * self.speed * (k * s).cos(),
        )
    }

    /// `(ḧ, θ̈)` at the state `(h, θ, ḣ, θ̇)`.
    fn accelerations(&self, t: f64, y: &[f64]) -> (f64, f64) {
        let (mut force, mut moment) = (0.0, 0.0);
        for &(x, k, c) in &self.axles {
            let (z, zd) = self.road(t, x);
            let f = k * (z - (y[0] + x * y[1])) + c * (zd - (y[2] + x * y[3]));
            force += f;
            moment += x * f;
        }
        (force / self.mass, moment / self.inertia)
    }

    /// The seat's steady acceleration amplitude, m/s², from the phasors.
    fn steady_seat_amplitude(&self) -> f64 {
        let w = 2.0 * std::f64::consts::PI * self.speed / self.wavelength;
        let j = Complex::new(0.0, 1.0);
        let mut a = Matrix2::from_diagonal(&Vector2::new(
            Complex::from(-w * w * self.mass),
            Complex::from(-w * w * self.inertia),
        ));
        let mut b = Vector2::<Complex<f64>>::zeros();
        for &(x, k, c) in &self.axles {
            let stiffness = Complex::from(k) + j * (w * c);
            a[(0, 0)] += stiffness;
            a[(0, 1)] += stiffness * x;
            a[(1, 0)] += stiffness * x;
            a[(1, 1)] += stiffness * (x * x);
            let z = (j * (w * x / self.speed)).exp() * self.amplitude;
            b[0] += stiffness * z;
            b[1] += stiffness * z * x;
        }
        let q = a.lu().solve(&b).expect("the hull is supported");
        (w * w * (q[0] + q[1] * self.seat)).norm()
    }
}

impl OdeSystem for Hull {
    fn dimension(&self) -> usize {
        4
    }

    fn derivative(&mut self, t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), SimulationError> {
        let (hdd, thdd) = self.accelerations(t, y);
        dy.copy_from_slice(&[y[2], y[3], hdd, thdd]);
        Ok(())
    }
}

impl Simulated for Hull {
    fn initial_state(&self) -> DVector<f64> {
        DVector::zeros(4)
    }

    fn columns(&self) -> Vec<String> {
        vec!["x".into(), "seat_ax".into(), "seat_az".into()]
    }

    fn observe(&mut self, t: f64, y: &[f64], row: &mut Vec<f64>) -> Result<(), SimulationError> {
        let (hdd, thdd) = self.accelerations(t, y);
        row.extend([self.speed * t, 0.0, hdd + self.seat * thdd]);
        Ok(())
    }
}

#[test]
fn the_ride_chain_matches_the_steady_state_in_closed_form() {
    let dt = 1e-3;
    // Road frequencies 1, 2, 4.4 (the absorbed power's peak) and 8 Hz.
    for (speed, wavelength) in [(5.0, 5.0), (4.0, 2.0), (8.8, 2.0), (12.0, 1.5)] {
        let mut hull = Hull {
            mass: 1e4,
            inertia: 3e4,
            axles: [(2.0, 4e5, 2e4), (-2.0, 4e5, 2e4)],
            seat: 1.0,
            amplitude: 0.01,
            wavelength,
            speed,
        };
        let f = speed / wavelength;
        let settle = 10.0;
        let end = settle + 20.0 / f;
        let mut ride = RideSink::new(dt, settle).unwrap();
        simulate_into(
            &mut hull,
            Integrator::Dopri5 {
                rtol: 1e-10,
                atol: 1e-12,
                max_step: dt,
            },
            0.0,
            end,
            Output::Every(dt),
            &mut ride as &mut dyn Sink,
            &mut |_| {},
        )
        .expect("the run finishes");
        let figures = ride.figures();
        let amplitude = hull.steady_seat_amplitude();
        let power = AbsorbedPower::new(dt).response_continuous(f).powi(2)
            * (amplitude * FT_PER_M).powi(2)
            / 2.0;
        let wk = IsoWeighting::wk(dt).response_continuous(f) * amplitude / 2f64.sqrt();
        eprintln!(
            "{f:.1} Hz: absorbed {:.5} W (closed form {power:.5}), W_k {:.5} ({wk:.5}) m/s²",
            figures.absorbed_power, figures.wk_rms
        );
        assert!(
            (figures.absorbed_power - power).abs() < 0.02 * power,
            "{f} Hz: {} W against {power} W",
            figures.absorbed_power
        );
        assert!(
            (figures.wk_rms - wk).abs() < 0.02 * wk,
            "{f} Hz: W_k {} against {wk}",
            figures.wk_rms
        );
        // The same rows' spectrum: its mean square is the seat's (the
        // same 2 %: a Hann window over 4 or more road periods leaks under
        // 1e-3 of a tone); the absorbed power it splits by frequency sums
        // to the closed form within that and its resolution bias (the
        // window spreads a tone over a bin each side, where `|H|²`, rising
        // as `f²` below its peak, is larger on average by `(Δf/f)²/3`: 2 %
        // at 1 Hz with 0.244 Hz bins), in one line at the
        // road's frequency (within its bin); the speed from the rows' `x`.
        // Runs measured for less than one segment (the 8 Hz road's 2.5 s)
        // have none.
        let measured = end - settle;
        match ride.spectrum() {
            None => assert!(measured < RideSink::SPECTRUM_SEGMENT, "{f} Hz: no spectrum"),
            Some(spectrum) => {
                let absorbed = spectrum.absorbed();
                let total: f64 = absorbed.iter().sum();
                let line = spectrum.lines(&absorbed, 1, 1)[0];
                eprintln!(
                    "{f:.1} Hz: the spectrum's {total:.5} W, its line at {:.3} Hz carrying {:.5} W",
                    line.frequency, line.carried
                );
                let mean_square = amplitude * amplitude / 2.0;
                assert!(
                    (spectrum.mean_square() - mean_square).abs() < 0.02 * mean_square,
                    "{f} Hz: mean square {}",
                    spectrum.mean_square()
                );
                let bias = (spectrum.df / f).powi(2) / 3.0;
                assert!(
                    (total - power).abs() < (0.02 + bias) * power,
                    "{f} Hz: spectrum {total} W"
                );
                assert!(
                    (line.frequency - f).abs() <= spectrum.df,
                    "{f} Hz: line at {}",
                    line.frequency
                );
                assert!(line.carried > 0.99 * total);
                let speed = ride.mean_speed().expect("the rows have x");
                assert!((speed / hull.speed - 1.0).abs() < 1e-9, "speed {speed}");
            }
        }
    }
}
