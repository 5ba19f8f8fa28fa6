//! What the FMU's test binaries share.

use trackgen_fmu::variables::{Causality, Variable};
use trackgen_fmu::{Plant, description};

/// A model's table holds together: names unique, value references in
/// order, one independent variable, every unit defined in its FMI 3.0
/// description, and the token in it.
pub fn assert_table_is_consistent<P: Plant>(table: &[Variable]) {
    let mut names: Vec<&str> = table.iter().map(|v| v.name.as_str()).collect();
    names.sort_unstable();
    let n = names.len();
    names.dedup();
    assert_eq!(names.len(), n, "names are unique");
    for (i, v) in table.iter().enumerate() {
        assert_eq!(v.value_reference as usize, i);
    }
    assert_eq!(
        table
            .iter()
            .filter(|v| v.causality == Causality::Independent)
            .count(),
        1
    );
    let xml = description::fmi3::<P>(table);
    for v in table {
        if !v.unit.is_empty() && v.unit != "1" {
            assert!(
                xml.contains(&format!("<Unit name=\"{}\">", v.unit)),
                "{}'s unit {} is defined",
                v.name,
                v.unit
            );
        }
    }
    assert!(xml.contains(&description::token::<P>(table)));
}
