//! Reading the reference data computed with Pinocchio
//! (`tests/data/pinocchio_*.json`; `tests/data/README.md`).

use serde_json::Value;

/// The cases of `tests/data/<file>`, checked to come from Pinocchio 4.1.0.
pub fn cases(file: &str) -> Vec<Value> {
    let path = format!("{}/tests/data/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("reference data");
    let data: Value = serde_json::from_str(&text).expect("valid JSON");
    assert_eq!(data["source"], "Pinocchio 4.1.0");
    data["cases"].as_array().unwrap().clone()
}

/// The case named `name` of `tests/data/<file>`.
pub fn case(file: &str, name: &str) -> Value {
    cases(file)
        .into_iter()
        .find(|c| c["name"] == name)
        .unwrap_or_else(|| panic!("no case {name} in {file}"))
}

/// A JSON array of numbers.
pub fn floats(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

/// A row-major JSON matrix as column-major values.
pub fn column_major(v: &Value) -> Vec<f64> {
    let rows: Vec<Vec<f64>> = v.as_array().unwrap().iter().map(floats).collect();
    let (r, c) = (rows.len(), rows[0].len());
    (0..c)
        .flat_map(|j| rows.iter().map(move |row| row[j]).take(r))
        .collect()
}
