//! The Arrow sink: a streamed run's file reads back with the columns and
//! the values of the in-memory results, bit for bit, and a failing run
//! leaves a complete file with every row before the failure. The system
//! is trackgen-runtime's tests' oscillator (RK4 at a fixed step, so two
//! runs give the same bits).

// A failed stream carries its report and error by value, as the API returns it.
#![allow(clippy::result_large_err)]

use std::io::Cursor;

use arrow_array::{Array, Float64Array};
use arrow_ipc::reader::FileReader;
use trackgen_arrow::ArrowSink;
use trackgen_runtime::integrate::SimulationError;
use trackgen_runtime::simulate::{CsvSink, RunError, Tee};

#[path = "../../trackgen-runtime/tests/support/oscillator.rs"]
mod oscillator;
use oscillator::*;

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
