//! The set's rows as text: the summary table, each published figure
//! beside its answer, a row as JSON.

use trackgen::mobility::Published;

use super::tasks::Row;

pub(super) fn parameter_text(row: &Row) -> String {
    match row.parameter {
        Some((what, value, unit)) => format!("{what} {value:.4} {unit}"),
        None => String::new(),
    }
}

/// The value with its relation: `5.416`, `> 20.000`, `< 1.000`, `0.000
/// (stalls)`, or the word for no answer (`stalled`, `failed`, …).
pub(super) fn value_text(r: &Row) -> String {
    match r.relation {
        "=" => format!("{:.3}", r.value),
        ">" | "<" => format!("{} {:.3}", r.relation, r.value),
        word if r.value.is_finite() => format!("{:.3} ({word})", r.value),
        word => word.to_string(),
    }
}

pub(super) fn print_summary(name: &str, rows: &[Row], wall: f64) {
    let runs: usize = rows.iter().map(|r| r.runs).sum();
    eprintln!(
        "{name}: {} results from {runs} runs in {wall:.1} s of wall time",
        rows.len()
    );
    println!(
        "{:<11} {:<28} {:<26} {:>12}  {:<14} {:>5} {:>8}  confirmed",
        "event", "parameter", "quantity", "value", "unit", "runs", "wall s"
    );
    for r in rows {
        println!(
            "{:<11} {:<28} {:<26} {:>12}  {:<14} {:>5} {:>8.1}  {}",
            r.event,
            parameter_text(r),
            r.quantity,
            value_text(r),
            r.unit,
            r.runs,
            r.wall,
            confirmation_text(r)
        );
    }
}

/// How the row's answer stood at the confirming tolerance: `held at
/// 1e-4`, or `at 1e-4 (from = 14.969)` where it moved (the first answer
/// with its relation), or empty where it was not confirmed (a curve's
/// later points, a quantity that is no search's).
pub(super) fn confirmation_text(r: &Row) -> String {
    match r.search.as_ref().and_then(|s| s.confirmation) {
        Some(c) => match c.moved_from {
            None => format!("held at {:.0e}", c.tolerance),
            Some(from) => format!(
                "at {:.0e} (from {} {:.3})",
                c.tolerance,
                from.relation(),
                from.value()
            ),
        },
        None => String::new(),
    }
}

/// A published figure beside the set's answer to it.
pub(super) struct Against<'a> {
    pub(super) figure: &'a Published,
    /// The answer as the table prints it, or `not run`.
    pub(super) answer: String,
    /// The answer over the published value (NaN if none).
    pub(super) ratio: f64,
    /// Agrees, misses (by how much; the guide's "Against the real
    /// vehicle" gives the cause measured), or not run.
    pub(super) verdict: String,
}

/// Each published figure with the set's answer to it: the row of that
/// quantity with no parameter.
pub(super) fn against<'a>(published: &'a [Published], rows: &[Row]) -> Vec<Against<'a>> {
    published
        .iter()
        .map(|figure| {
            let row = rows
                .iter()
                .find(|r| r.quantity == figure.quantity && r.parameter.is_none());
            let Some(r) = row else {
                return Against {
                    figure,
                    answer: "not run".into(),
                    ratio: f64::NAN,
                    verdict: "not run".into(),
                };
            };
            let c = figure.compare(r.value);
            let verdict = if c.agrees {
                format!(
                    "agrees within {:.0} %",
                    100.0 * trackgen::mobility::AGREEMENT
                )
            } else if c.ratio.is_finite() {
                format!(
                    "misses by {:+.0} % (the guide, Mobility events, \"Against the real \
                     vehicle\", gives the cause)",
                    100.0 * (c.ratio - 1.0)
                )
            } else {
                format!("no answer ({})", r.relation)
            };
            Against {
                figure,
                answer: value_text(r),
                ratio: c.ratio,
                verdict,
            }
        })
        .collect()
}

/// The published figures beside the answers, on standard output after
/// the table.
pub(super) fn print_against(published: &[Published], rows: &[Row]) {
    let against = against(published, rows);
    if against.is_empty() {
        return;
    }
    println!("\nagainst the real vehicle:");
    for Against {
        figure,
        answer,
        ratio,
        verdict,
    } in against
    {
        println!(
            "{:<26} {:>12} against {:>8.3} {:<14} ratio {ratio:.2}: {verdict}\n{:<26} source: {}",
            figure.quantity, answer, figure.value, figure.unit, "", figure.source
        );
    }
}

pub(super) fn json(row: &Row) -> String {
    let number = |v: f64| v.is_finite().then_some(v);
    serde_json::json!({
        "event": row.event,
        "parameter": row.parameter.map(|(name, value, unit)| {
            serde_json::json!({"name": name, "value": number(value), "unit": unit})
        }),
        "quantity": row.quantity,
        "value": number(row.value),
        "relation": row.relation,
        "unit": row.unit,
        "runs": row.runs,
        "confirmed_at": row.search.as_ref().and_then(|s| s.confirmation).map(|c| c.tolerance),
        "moved_from": row
            .search
            .as_ref()
            .and_then(|s| s.confirmation?.moved_from)
            .map(|l| l.value()),
        "failure": row.failure,
    })
    .to_string()
}
