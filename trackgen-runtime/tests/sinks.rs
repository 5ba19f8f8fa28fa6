//! Streaming a run into sinks gives what the in-memory results hold.
//!
//! The system is a harmonic oscillator (`ẍ = −ω² x`, ω = 2π rad/s)
//! recording `x`, `v` and its energy, integrated by RK4 at a fixed 1 ms
//! step, so two runs with the same settings produce the same bits: the
//! comparisons are exact (CSV byte for byte, Arrow values by their bits).
//! A variant's derivative turns NaN after `fail_at`: RK4 stops at the
//! first stage past it (a stage time in `(fail_at, fail_at + 1 ms]`);
//! `fail_at` is between output times, so which rows precede the failure
//! does not hang on rounding.

// A failed stream carries its report and error by value, as the API returns it.
#![allow(clippy::result_large_err)]

use std::io::{self, Cursor};
use std::path::PathBuf;

use arrow_array::{Array, Float64Array};
use arrow_ipc::reader::FileReader;
use nalgebra::DVector;
use trackgen_runtime::integrate::{Integrator, OdeSystem, SimulationError};
use trackgen_runtime::simulate::{
    ArrowSink, Background, CsvSink, Output, Results, RunError, RunReport, Select, Sink, SinkError,
    StreamFailure, Summary, Tee, Thinned, simulate, simulate_into,
};
use trackgen_runtime::system::Simulated;

const OMEGA: f64 = 2.0 * std::f64::consts::PI;
const STEP: f64 = 1e-3;
const INTERVAL: f64 = 0.01;

struct Oscillator {
    fail_at: Option<f64>,
}

impl OdeSystem for Oscillator {
    fn dimension(&self) -> usize {
        2
    }

    fn derivative(&mut self, t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), SimulationError> {
        let load = match self.fail_at {
            Some(at) if t > at => f64::NAN,
            _ => 0.0,
        };
        dy[0] = y[1];
        dy[1] = -OMEGA * OMEGA * y[0] + load;
        Ok(())
    }
}

impl Simulated for Oscillator {
    fn initial_state(&self) -> DVector<f64> {
        DVector::from_column_slice(&[1.0, 0.0])
    }

    fn columns(&self) -> Vec<String> {
        ["x", "v", "energy"].map(String::from).to_vec()
    }

    fn observe(&mut self, _t: f64, y: &[f64], row: &mut Vec<f64>) -> Result<(), SimulationError> {
        let energy = 0.5 * (y[1] * y[1] + OMEGA * OMEGA * y[0] * y[0]);
        row.extend_from_slice(&[y[0], y[1], energy]);
        Ok(())
    }
}

fn rk4() -> Integrator {
    Integrator::Rk4 { step: STEP }
}

/// The reference: the same run, in memory.
fn in_memory(duration: f64, fail_at: Option<f64>) -> Results {
    let mut system = Oscillator { fail_at };
    match simulate(&mut system, rk4(), 0.0, duration, Output::Every(INTERVAL)) {
        Ok(r) => r,
        Err(f) => f.results,
    }
}

/// The oscillator (its derivative NaN after `fail_at`) streamed for
/// `duration` s into `sink`.
fn stream(
    sink: &mut dyn Sink,
    duration: f64,
    fail_at: Option<f64>,
) -> Result<RunReport, StreamFailure> {
    simulate_into(
        &mut Oscillator { fail_at },
        rk4(),
        0.0,
        duration,
        Output::Every(INTERVAL),
        sink,
        &mut |_| {},
    )
}

fn results_csv(results: &Results) -> Vec<u8> {
    let mut text = Vec::new();
    results.write_csv(&mut text).unwrap();
    text
}

/// Reads an Arrow IPC file: column names, the values column by column,
/// and the number of record batches.
fn read_arrow(bytes: Vec<u8>) -> (Vec<String>, Vec<Vec<f64>>, usize) {
    let reader = FileReader::try_new(Cursor::new(bytes), None).expect("a complete Arrow file");
    let names: Vec<String> = reader
        .schema()
        .fields()
        .iter()
        .map(|f| f.name().clone())
        .collect();
    let mut columns = vec![Vec::new(); names.len()];
    let mut batches = 0;
    for batch in reader {
        let batch = batch.expect("a readable batch");
        batches += 1;
        for (k, column) in batch.columns().iter().enumerate() {
            let values = column
                .as_any()
                .downcast_ref::<Float64Array>()
                .expect("Float64 columns");
            assert_eq!(values.null_count(), 0, "no nulls");
            columns[k].extend(values.values().iter().copied());
        }
    }
    (names, columns, batches)
}

/// `results` as columns: `t`, then each recorded quantity.
fn columns_of(results: &Results) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut names = vec!["t".to_string()];
    names.extend(results.columns().iter().cloned());
    let mut columns = vec![results.times().to_vec()];
    for c in results.columns() {
        columns.push(results.column(c).unwrap());
    }
    (names, columns)
}

fn bits(columns: &[Vec<f64>]) -> Vec<Vec<u64>> {
    columns
        .iter()
        .map(|c| c.iter().map(|v| v.to_bits()).collect())
        .collect()
}

fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("sinks");
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

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
fn arrow_file_reads_back_with_the_same_columns_and_values() {
    let reference = in_memory(2.0, None);
    // 201 rows in batches of 64: three full ones and a partial one.
    let mut arrow = ArrowSink::new(Vec::new()).with_batch_rows(64);
    stream(&mut arrow, 2.0, None).expect("the run finishes");
    let (names, columns, batches) = read_arrow(arrow.into_inner().unwrap());
    let (want_names, want) = columns_of(&reference);
    assert_eq!(names, want_names);
    assert_eq!(batches, 4, "⌈201 / 64⌉ record batches");
    assert_eq!(bits(&columns), bits(&want), "the same values, bit for bit");
    // Results held in memory write the same file through `write_to`.
    let mut again = ArrowSink::new(Vec::new()).with_batch_rows(64);
    reference.write_to(&mut again).unwrap();
    let (names2, columns2, _) = read_arrow(again.into_inner().unwrap());
    assert_eq!((names2, bits(&columns2)), (want_names, bits(&want)));
}

#[test]
fn a_failing_run_leaves_flushed_files_with_every_row_before_the_failure() {
    let fail_at = 0.5053;
    let reference = in_memory(2.0, Some(fail_at));
    let csv_path = scratch("failing.csv");
    let arrow_path = scratch("failing.arrow");
    let mut csv = CsvSink::create(&csv_path).unwrap();
    let mut arrow = ArrowSink::create(&arrow_path).unwrap().with_batch_rows(16);
    let mut sinks = Tee::new().and(&mut csv).and(&mut arrow);
    let failure = stream(&mut sinks, 2.0, Some(fail_at)).expect_err("a NaN load stops the run");
    drop(sinks);
    let RunError::Simulation(SimulationError::NonFinite { t, .. }) = failure.error else {
        panic!("a non-finite failure, got {}", failure.error);
    };
    assert!(t > fail_at && t <= fail_at + STEP, "failed at t = {t}");
    assert!(failure.finish.is_none(), "the files were finished");
    // Every output time up to the failure: 0, 0.01, …, 0.5.
    assert_eq!(reference.len(), 51, "the reference stops at the same time");
    assert_eq!(failure.report.rows, reference.len());
    assert_eq!(failure.report.last_time, reference.times().last().copied());
    let written = std::fs::read(&csv_path).unwrap();
    assert_eq!(written, results_csv(&reference), "the CSV is complete");
    let (names, columns, _) = read_arrow(std::fs::read(&arrow_path).unwrap());
    let (want_names, want) = columns_of(&reference);
    assert_eq!((names, bits(&columns)), (want_names, bits(&want)));
    let message = failure.to_string();
    assert!(message.contains("51 rows written"), "{message}");
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
