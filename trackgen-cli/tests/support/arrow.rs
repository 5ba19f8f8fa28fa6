//! An Arrow IPC file read back: its columns and its rows, for the tests
//! of the files the binary writes.

use std::path::Path;

use arrow_array::{Array, Float64Array};

/// The column names and the rows of the Arrow IPC file at `path` (every
/// column `Float64`); a file that is missing or incomplete fails the
/// test, naming it.
pub fn read(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let file = std::fs::File::open(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let reader = arrow_ipc::reader::FileReader::try_new(file, None)
        .unwrap_or_else(|e| panic!("{}: not a complete Arrow file: {e}", path.display()));
    let names = reader
        .schema()
        .fields()
        .iter()
        .map(|f| f.name().clone())
        .collect();
    let mut rows = Vec::new();
    for batch in reader {
        let batch = batch.unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let columns: Vec<&Float64Array> = batch
            .columns()
            .iter()
            .map(|c| c.as_any().downcast_ref().expect("Float64 columns"))
            .collect();
        for r in 0..batch.num_rows() {
            rows.push(columns.iter().map(|c| c.value(r)).collect());
        }
    }
    (names, rows)
}
