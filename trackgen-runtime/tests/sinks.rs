//! Streaming a run into sinks gives what the in-memory results hold.
//!
//! The system is a harmonic oscillator (`ẍ = −ω² x`, ω = 2π rad/s)
//! recording `x`, `v` and its energy, integrated by RK4 at a fixed 1 ms
//! step, so two runs with the same settings produce the same bits: the
//! comparisons are exact (CSV byte for byte). The Arrow sink's tests are
//! trackgen-arrow's.
//! A variant's derivative turns NaN after `fail_at`: RK4 stops at the
//! first stage past it (a stage time in `(fail_at, fail_at + 1 ms]`);
//! `fail_at` is between output times, so which rows precede the failure
//! does not hang on rounding.

// A failed stream carries its report and error by value, as the API returns it.
#![allow(clippy::result_large_err)]

use std::io;

use nalgebra::DVector;

use trackgen_runtime::integrate::{OdeSystem, SimulationError};
use trackgen_runtime::simulate::{
    Background, CsvSink, Output, Results, RunError, Select, Sink, SinkError, StreamFailure,
    Summary, Tee, Thinned, simulate,
};
use trackgen_runtime::system::Simulated;

#[path = "support/oscillator.rs"]
mod oscillator;
use oscillator::*;

#[test]
fn streamed_csv_is_the_in_memory_csv_byte_for_byte() {
    let reference = in_memory(2.0, None);
    assert_eq!(reference.len(), 201, "0, 0.01, …, 2 s");
    let mut csv = CsvSink::new(Vec::new());
    let mut kept = Results::default();
    let mut sinks = Tee::new().and(&mut csv).and(&mut kept);
    let report = stream(&mut sinks, 2.0, None).expect("the run finishes");
    drop(sinks);
    assert_eq!(report.rows, reference.len());
    assert_eq!(report.last_time, Some(2.0));
    assert_eq!(report.stats, reference.stats, "the same steps");
    let streamed = csv.into_inner().unwrap();
    assert_eq!(
        String::from_utf8(streamed).unwrap(),
        String::from_utf8(results_csv(&reference)).unwrap()
    );
    // The in-memory sink inside a tee keeps the same rows.
    assert_eq!(results_csv(&kept), results_csv(&reference));
}

#[test]
fn a_background_sink_writes_what_the_run_gives_it_and_finishes_a_failed_run() {
    // A finished run: the same CSV and rows as in memory.
    let reference = in_memory(2.0, None);
    let (mut csv, mut kept) = (CsvSink::new(Vec::new()), Results::default());
    let report = std::thread::scope(|scope| {
        let mut sink = Background::spawn(scope, || Tee::new().and(&mut csv).and(&mut kept));
        stream(&mut sink, 2.0, None)
    })
    .expect("the run finishes");
    assert_eq!(report.rows, reference.len());
    assert_eq!(csv.into_inner().unwrap(), results_csv(&reference));
    assert_eq!(results_csv(&kept), results_csv(&reference));

    // A run that fails: every row before the failure is written out.
    let fail_at = 0.5053;
    let reference = in_memory(2.0, Some(fail_at));
    let mut csv = CsvSink::new(Vec::new());
    let failure = std::thread::scope(|scope| {
        let mut sink = Background::spawn(scope, || &mut csv);
        stream(&mut sink, 2.0, Some(fail_at))
    })
    .expect_err("a NaN load stops the run");
    assert!(failure.finish.is_none(), "the file was finished");
    assert_eq!(failure.report.rows, 51);
    assert_eq!(csv.into_inner().unwrap(), results_csv(&reference));
}

#[test]
fn a_background_sink_that_cannot_write_stops_the_run_soon_after() {
    // As `a_sink_that_cannot_write_stops_the_run_with_an_io_error`, the
    // failing writer now on another thread: the run hears of it at a later
    // row, at most the 256 rows in flight, the batch of 16 the worker was
    // writing and the batch being filled (288 rows, 2.88 s of output) after.
    let direct = {
        let mut sink = CsvSink::new(Full { room: 10_000 });
        stream(&mut sink, 100.0, None).expect_err("the disk is full")
    };
    let direct_t = stopped_by_a_full_disk(&direct);
    let failure = std::thread::scope(|scope| {
        let mut sink = Background::spawn(scope, || CsvSink::new(Full { room: 10_000 }));
        stream(&mut sink, 100.0, None)
    })
    .expect_err("the disk is full");
    let t = stopped_by_a_full_disk(&failure);
    assert!(
        t >= direct_t && t <= direct_t + 288.0 * INTERVAL + 1e-9,
        "heard of at t = {t}, the writer failed at row t = {direct_t}"
    );
}

/// The time of the row at which `failure` stopped its run, checking it was
/// a sink's I/O error of a full disk.
fn stopped_by_a_full_disk(failure: &StreamFailure) -> f64 {
    let RunError::Sink { t, source } = &failure.error else {
        panic!("a sink error, got {}", failure.error);
    };
    assert!(
        matches!(source, SinkError::Io { source, .. } if source.kind() == io::ErrorKind::StorageFull),
        "{source}"
    );
    *t
}

/// A writer that takes `room` bytes, then fails as a full disk does.
struct Full {
    room: usize,
}

impl io::Write for Full {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        if self.room == 0 {
            return Err(io::Error::new(io::ErrorKind::StorageFull, "no space left"));
        }
        let n = buf.len().min(self.room);
        self.room -= n;
        Ok(n)
    }

    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

#[test]
fn a_sink_that_cannot_write_stops_the_run_with_an_io_error() {
    // The CSV writer's 8 KiB buffer fills after ~150 rows of ~50 bytes;
    // 10 kB of room then runs out within the next ~200 rows.
    let mut kept = Results::default();
    let mut sinks = Tee::new()
        .and(&mut kept)
        .and(CsvSink::new(Full { room: 10_000 }));
    let failure = stream(&mut sinks, 100.0, None).expect_err("the disk is full");
    drop(sinks);
    let t = stopped_by_a_full_disk(&failure);
    assert!(t > 0.5 && t < 10.0, "stopped at t = {t}, long before 100 s");
    // The sink before the failing one kept the row it failed on.
    assert_eq!(kept.times().last().copied(), Some(t));
    assert_eq!(
        failure.report.rows + 1,
        kept.len(),
        "the failed row is not counted"
    );
}

#[test]
fn select_passes_on_named_columns_and_refuses_unknown_ones() {
    let reference = in_memory(0.5, None);
    let mut selected = Select::new(["energy", "x"], Results::default());
    stream(&mut selected, 0.5, None).unwrap();
    let got = selected.into_inner();
    assert_eq!(got.columns(), ["energy", "x"]);
    assert_eq!(got.times(), reference.times());
    assert_eq!(got.column("energy"), reference.column("energy"));
    assert_eq!(got.column("x"), reference.column("x"));

    let mut csv = CsvSink::new(Vec::new());
    let mut unknown = Select::new(["x", "speed"], &mut csv);
    let failure = stream(&mut unknown, 0.5, None).expect_err("no column `speed`");
    assert!(
        matches!(&failure.error, RunError::Sink { t: 0.0, source: SinkError::Columns(m) } if m.contains("`speed`")),
        "{}",
        failure.error
    );
    assert_eq!(failure.report.rows, 0, "refused before any row");
    assert_eq!(failure.report.stats.accepted, 0, "and before any step");
}

#[test]
fn summary_holds_each_columns_first_last_and_extremes() {
    let reference = in_memory(2.0, None);
    let mut summary = Summary::new();
    reference.write_to(&mut summary).unwrap();
    assert_eq!(summary.rows(), reference.len());
    let time = summary.time().unwrap();
    assert_eq!((time.first, time.last), (0.0, 2.0));
    for name in ["x", "v", "energy"] {
        let column = reference.column(name).unwrap();
        let s = summary.get(name).unwrap();
        assert_eq!(s.first, column[0], "{name}");
        assert_eq!(s.last, *column.last().unwrap(), "{name}");
        assert_eq!(
            s.min,
            column.iter().copied().fold(f64::INFINITY, f64::min),
            "{name}"
        );
        assert_eq!(
            s.max,
            column.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            "{name}"
        );
    }
    // Two periods of x = cos(2π t): from 1 through −1 and back.
    let x = summary.get("x").unwrap();
    assert!((x.max_abs() - 1.0).abs() < 1e-9 && (x.min + 1.0).abs() < 1e-9);
    assert!(summary.get("nope").is_none());

    // A NaN is not dropped.
    let mut summary = Summary::new();
    summary.begin(&["a".to_string()]).unwrap();
    for v in [1.0, f64::NAN, 3.0] {
        summary.row(0.0, &[v]).unwrap();
    }
    let a = summary.get("a").unwrap();
    assert!(a.max.is_nan() && a.min.is_nan() && a.max_abs().is_nan());
    assert_eq!(a.last, 3.0);
    assert!(
        summary.row(0.0, &[1.0, 2.0]).is_err(),
        "a row of the wrong length"
    );
}

#[test]
fn thinned_keeps_a_bounded_evenly_spaced_selection_ending_at_the_last_row() {
    for (rows, capacity) in [(10, 64), (1001, 64), (1000, 63), (64, 64), (65, 64), (7, 2)] {
        let mut thinned = Thinned::new(capacity);
        thinned.begin(&["i".to_string()]).unwrap();
        for i in 0..rows {
            thinned.row(i as f64, &[i as f64]).unwrap();
        }
        thinned.finish().unwrap();
        let kept = thinned.results().times().to_vec();
        let case = format!("{rows} rows into {capacity}: kept {kept:?}");
        assert!(kept.len() <= capacity, "{case}");
        assert!(rows <= capacity || kept.len() > capacity / 4, "{case}");
        assert_eq!(kept[0], 0.0, "{case}");
        assert_eq!(*kept.last().unwrap(), (rows - 1) as f64, "{case}");
        // Every `stride`-th row, then the last.
        let stride = thinned.stride() as f64;
        let body = &kept[..kept.len() - 1];
        for (k, &t) in body.iter().enumerate() {
            assert_eq!(t, k as f64 * stride, "{case}");
        }
        assert!(
            kept[kept.len() - 1] - body.last().copied().unwrap_or(-1.0) <= stride,
            "{case}"
        );
        assert_eq!(thinned.results().column("i").unwrap(), kept, "{case}");
    }
}

/// The oscillator, recording a NaN energy after `t = 0.5` s from its finite
/// state.
struct NanRecord(Oscillator);

impl OdeSystem for NanRecord {
    fn dimension(&self) -> usize {
        self.0.dimension()
    }

    fn derivative(&mut self, t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), SimulationError> {
        self.0.derivative(t, y, dy)
    }
}

impl Simulated for NanRecord {
    fn initial_state(&self) -> DVector<f64> {
        self.0.initial_state()
    }

    fn columns(&self) -> Vec<String> {
        self.0.columns()
    }

    fn observe(&mut self, t: f64, y: &[f64], row: &mut Vec<f64>) -> Result<(), SimulationError> {
        self.0.observe(t, y, row)?;
        if t > 0.5 {
            *row.last_mut().unwrap() = f64::NAN;
        }
        Ok(())
    }
}

/// Regression: a recorded NaN from a finite state was written into the
/// results of every system but the vehicle (which checked its own rows).
/// The driver checks every row: the run stops with the column's name and
/// keeps the rows before it.
#[test]
fn a_recorded_nan_stops_any_system_naming_its_column() {
    let mut system = NanRecord(Oscillator { fail_at: None });
    let failure = simulate(&mut system, rk4(), 0.0, 1.0, Output::Every(INTERVAL)).unwrap_err();
    match &failure.error {
        SimulationError::NonFiniteRecord { t, column } => {
            assert!(*t > 0.5 && *t <= 0.5 + INTERVAL + 1e-12, "t = {t}");
            assert_eq!(column, "energy");
        }
        other => panic!("{other}"),
    }
    assert_eq!(failure.results.len(), 51);
    assert!(
        failure
            .results
            .iter()
            .all(|s| s.values.iter().all(|v| v.is_finite()))
    );
}

/// The ride sink runs the named columns through the ride criteria: the
/// oscillator's `x = cos 2πt` (read as a vertical acceleration, m/s²) and
/// `v` (longitudinal), sampled every 1 ms, measured from 2 s (the filters'
/// transients gone) to 22 s. A steady 1 Hz sine of amplitude 1 m/s² gives
/// an absorbed power `|H(j2π)|² A²/2` with `A` in ft/s², a `W_k` RMS
/// `|W_k(1 Hz)|/√2` and a peak of `|H_30(1 Hz)|` m/s² (the 4-pole 30 Hz
/// Butterworth passes 1 Hz unchanged to 1e-11), each from the criteria's
/// own discrete responses: within 1e-3 (20 whole periods averaged, and
/// RK4's 1 ms step keeps the sine to 1e-9). A ride sink is refused at
/// rows 5 ms apart, and rows off its spacing stop the run with the time.
#[test]
fn a_ride_sink_measures_the_named_columns_from_its_start() {
    use trackgen_runtime::ride::{AbsorbedPower, FT_PER_M, G, IsoWeighting, PeakVertical};
    use trackgen_runtime::simulate::{RideIntervalError, RideSink, simulate_into};

    let dt = 1e-3;
    let mut ride = RideSink::of_columns("x", "v", dt, 2.0).unwrap();
    let mut rows = Results::default();
    let mut both = Tee::new().and(&mut ride).and(&mut rows);
    simulate_into(
        &mut Oscillator { fail_at: None },
        rk4(),
        0.0,
        22.0,
        Output::Every(dt),
        &mut both,
        &mut |_| {},
    )
    .expect("the run finishes");
    drop(both);
    let figures = ride.figures();
    let measured = rows.times().iter().filter(|&&t| t >= 2.0).count();
    assert!(measured > 19_990, "{measured} rows measured");
    assert_eq!(figures.samples, measured as u64, "the rows from 2 s on");
    let f = 1.0;
    let absorbed = AbsorbedPower::new(dt).response_discrete(f).powi(2) * FT_PER_M.powi(2) / 2.0;
    let wk = IsoWeighting::wk(dt).response_discrete(f) / 2f64.sqrt();
    let wd = IsoWeighting::wd(dt).response_discrete(f) * OMEGA / 2f64.sqrt();
    let peak = PeakVertical::new(dt).response_discrete(f) / G;
    let close = |got: f64, want: f64, what: &str| {
        assert!(
            ((got - want) / want).abs() < 1e-3,
            "{what}: {got} against {want}"
        );
    };
    close(figures.absorbed_power, absorbed, "absorbed power, W");
    close(figures.wk_rms, wk, "W_k RMS, m/s²");
    close(figures.wd_rms, wd, "W_d RMS of v = -2π sin 2πt, m/s²");
    close(figures.peak_g, peak, "peak, g");

    assert_eq!(
        RideSink::new(5e-3, 0.0).unwrap_err(),
        RideIntervalError {
            dt: 5e-3,
            max: 2e-3
        }
    );
    let mut coarse = RideSink::of_columns("x", "v", dt, 0.0).unwrap();
    let failure = stream(&mut coarse, 1.0, None).expect_err("rows 10 ms apart");
    let RunError::Sink { t, source } = failure.error else {
        panic!("a sink error, got {}", failure.error);
    };
    assert!(
        (t - INTERVAL).abs() < 1e-12,
        "refused at the second row, t = {t}"
    );
    assert!(source.to_string().contains("not every 0.001 s"), "{source}");
}
