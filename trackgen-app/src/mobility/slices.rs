//! Slices of a set: each task's rows, trials included, one JSON object a
//! line; read back exactly (floats in their shortest round-trip form).

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};

use serde_json::{Value, json};
use trackgen::mobility::search::{Confirmation, Limit, Search, Trial};

use super::tasks::Row;

fn number(v: f64) -> Value {
    serde_json::Number::from_f64(v).map_or(Value::Null, Value::Number)
}

fn limit_json(limit: Limit) -> Value {
    match limit {
        Limit::Found {
            value,
            passed,
            failed,
        } => json!({"found": [number(value), number(passed), number(failed)]}),
        Limit::Beyond { end } => json!({"beyond": number(end)}),
        Limit::Before { start } => json!({"before": number(start)}),
    }
}

fn limit_of(limit: &Value) -> Result<Limit, String> {
    if let Some(f) = limit.get("found") {
        Ok(Limit::Found {
            value: float(&f[0]),
            passed: float(&f[1]),
            failed: float(&f[2]),
        })
    } else if let Some(end) = limit.get("beyond") {
        Ok(Limit::Beyond { end: float(end) })
    } else if let Some(start) = limit.get("before") {
        Ok(Limit::Before {
            start: float(start),
        })
    } else {
        Err("a search without its limit".into())
    }
}

fn row_json(r: &Row) -> Value {
    let search = r.search.as_ref().map(|s| {
        let trials: Vec<Value> = s
            .trials
            .iter()
            .map(|t| json!([number(t.parameter), number(t.figure), t.passed]))
            .collect();
        let confirmation = s.confirmation.map(|c| {
            json!({
                "tolerance": number(c.tolerance),
                "first_trial": c.first_trial,
                "moved_from": c.moved_from.map(limit_json),
            })
        });
        json!({
            "limit": limit_json(s.limit),
            "trials": trials,
            "confirmation": confirmation,
            "picture": r.picture,
        })
    });
    json!({
        "event": r.event,
        "parameter": r.parameter.map(|(n, v, u)| json!([n, number(v), u])),
        "quantity": r.quantity,
        "value": number(r.value),
        "relation": r.relation,
        "unit": r.unit,
        "runs": r.runs,
        "wall": number(r.wall),
        "search": search,
        "failure": r.failure,
    })
}

/// Writes a slice: a line per task, `{"task": i, "wall": s, "rows": […]}`.
pub fn write(path: &Path, done: &[(usize, Vec<Row>)], wall: f64) -> std::io::Result<()> {
    if let Some(dir) = path.parent() {
        fs::create_dir_all(dir)?;
    }
    let mut text = String::new();
    for (i, rows) in done {
        let line = json!({
            "task": i,
            "slice_wall": number(wall),
            "rows": rows.iter().map(row_json).collect::<Vec<_>>(),
        });
        text.push_str(&line.to_string());
        text.push('\n');
    }
    fs::write(path, text)
}

/// The rows' strings live as long as the merge (a short command).
fn text(v: &Value, what: &str) -> Result<&'static str, String> {
    v.as_str()
        .map(|s| &*Box::leak(s.to_string().into_boxed_str()))
        .ok_or_else(|| format!("`{what}` is not a string"))
}

fn float(v: &Value) -> f64 {
    v.as_f64().unwrap_or(f64::NAN)
}

fn row_of(v: &Value) -> Result<Row, String> {
    let search = match &v["search"] {
        Value::Null => None,
        s => {
            let limit = limit_of(&s["limit"])?;
            let confirmation = match &s["confirmation"] {
                Value::Null => None,
                c => Some(Confirmation {
                    tolerance: float(&c["tolerance"]),
                    first_trial: c["first_trial"]
                        .as_u64()
                        .ok_or("a confirmation without its first trial")?
                        as usize,
                    moved_from: match &c["moved_from"] {
                        Value::Null => None,
                        m => Some(limit_of(m)?),
                    },
                }),
            };
            let trials = s["trials"]
                .as_array()
                .ok_or("a search without its trials")?
                .iter()
                .map(|t| Trial {
                    parameter: float(&t[0]),
                    figure: float(&t[1]),
                    passed: t[2].as_bool().unwrap_or(false),
                })
                .collect();
            // The picture travels drawn (the row's), not as its geometry.
            Some(Search {
                limit,
                trials,
                picture: None,
                confirmation,
            })
        }
    };
    let parameter = match &v["parameter"] {
        Value::Null => None,
        p => Some((
            text(&p[0], "parameter")?,
            float(&p[1]),
            text(&p[2], "unit")?,
        )),
    };
    Ok(Row {
        event: text(&v["event"], "event")?,
        parameter,
        quantity: text(&v["quantity"], "quantity")?,
        value: float(&v["value"]),
        relation: text(&v["relation"], "relation")?,
        unit: text(&v["unit"], "unit")?,
        runs: v["runs"].as_u64().unwrap_or(0) as usize,
        wall: float(&v["wall"]),
        picture: v["search"]["picture"].as_str().map(str::to_owned),
        search,
        failure: v["failure"].as_str().map(str::to_string),
    })
}

/// The set's rows in task order from its slices, and the longest
/// slice's wall time; an error names the file and line, or the tasks
/// missing or given twice.
pub fn merge(files: &[PathBuf], tasks: usize) -> Result<(Vec<Row>, f64), String> {
    let mut found: BTreeMap<usize, (Vec<Row>, String)> = BTreeMap::new();
    let mut wall: f64 = 0.0;
    for file in files {
        let content = fs::read_to_string(file).map_err(|e| format!("{}: {e}", file.display()))?;
        for (n, line) in content.lines().enumerate() {
            let at = format!("{}:{}", file.display(), n + 1);
            let v: Value = serde_json::from_str(line).map_err(|e| format!("{at}: {e}"))?;
            let task = v["task"]
                .as_u64()
                .ok_or_else(|| format!("{at}: no task index"))? as usize;
            if task >= tasks {
                return Err(format!(
                    "{at}: task {task}, but this set has {tasks} (give the merge the slices' --events and --quick)"
                ));
            }
            wall = wall.max(float(&v["slice_wall"]));
            let rows = v["rows"]
                .as_array()
                .ok_or_else(|| format!("{at}: no rows"))?
                .iter()
                .map(row_of)
                .collect::<Result<Vec<_>, _>>()
                .map_err(|e| format!("{at}: {e}"))?;
            if let Some((_, first)) = found.insert(task, (rows, at.clone())) {
                return Err(format!("task {task} is in two slices: {first} and {at}"));
            }
        }
    }
    let missing: Vec<String> = (0..tasks)
        .filter(|i| !found.contains_key(i))
        .map(|i| i.to_string())
        .collect();
    if !missing.is_empty() {
        return Err(format!(
            "tasks missing from the slices: {} (of {tasks})",
            missing.join(", ")
        ));
    }
    Ok((
        found.into_values().flat_map(|(rows, _)| rows).collect(),
        wall,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A confirmed search's row travels through a slice's line unchanged:
    /// its limit, trials and confirmation (the first answer kept where it
    /// moved), the floats exactly.
    #[test]
    fn a_confirmed_search_round_trips_through_a_slice() {
        let trial = |parameter, passed| Trial {
            parameter,
            figure: parameter - 0.1,
            passed,
        };
        for moved_from in [None, Some(Limit::Beyond { end: 1.5 })] {
            let search = Search {
                limit: Limit::Found {
                    value: 0.987_304_687_5,
                    passed: 0.984_375,
                    failed: 0.990_234_375,
                },
                trials: vec![trial(0.05, true), trial(1.5, false), trial(0.1 + 0.2, true)],
                picture: None,
                confirmation: Some(Confirmation {
                    tolerance: 1e-4,
                    first_trial: 2,
                    moved_from,
                }),
            };
            let row = Row {
                event: "step",
                parameter: None,
                quantity: "highest step",
                value: search.limit.value(),
                relation: "=",
                unit: "m",
                runs: search.runs(),
                wall: 1.25,
                search: Some(search.clone()),
                picture: None,
                failure: None,
            };
            let back = row_of(&row_json(&row)).unwrap();
            assert_eq!(back.search, Some(search));
        }
        // A confirmation without its first trial is refused, not guessed.
        let mut line = row_json(&Row {
            event: "step",
            parameter: None,
            quantity: "highest step",
            value: 1.0,
            relation: "=",
            unit: "m",
            runs: 0,
            wall: 0.0,
            search: Some(Search {
                limit: Limit::Beyond { end: 1.5 },
                trials: vec![],
                picture: None,
                confirmation: Some(Confirmation {
                    tolerance: 1e-4,
                    first_trial: 0,
                    moved_from: None,
                }),
            }),
            picture: None,
            failure: None,
        });
        line["search"]["confirmation"]["first_trial"] = Value::Null;
        assert!(row_of(&line).is_err());
    }
}
