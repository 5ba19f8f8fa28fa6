//! The README's and the guide's performance figures come from one dated
//! table: `docs/performance.md`'s "Figures the README quotes". Each row's
//! quoted text (the column "quoted as", one or more in backticks) must be
//! where the row says (the README's performance line, the guide's
//! Performance page), the README must give its rows' commands, and every
//! `×` figure in either must be one of the rows: a figure changed on one
//! side only, or quoted without its row, fails naming it.

use std::path::Path;

/// A row of the table.
struct Row {
    /// Where it is quoted: "README", "guide" or both.
    place: String,
    /// The texts quoted.
    quoted: Vec<String>,
    command: String,
}

/// The rows of the table.
fn quoted_rows(performance: &str) -> Vec<Row> {
    let Some(start) = performance.find("## Figures the README quotes") else {
        panic!("docs/performance.md has no section \"Figures the README quotes\"");
    };
    performance[start..]
        .lines()
        .skip_while(|l| !l.starts_with("| figure"))
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .map(|line| {
            let cells: Vec<&str> = line.split('|').map(str::trim).collect();
            // "", figure, where, quoted as, measured, command, date, ""
            let quoted = cells[3]
                .split('`')
                .skip(1)
                .step_by(2)
                .map(str::to_string)
                .collect();
            Row {
                place: cells[2].to_string(),
                quoted,
                command: cells[5].trim_matches('`').to_string(),
            }
        })
        .collect()
}

/// The README's performance bullet, as one line of text.
fn performance_bullet(readme: &str) -> String {
    let start = readme
        .find("- **Performance**")
        .expect("the README has a performance bullet");
    let rest = &readme[start..];
    let end = rest[1..].find("\n- ").map_or(rest.len(), |e| e + 1);
    rest[..end].split_whitespace().collect::<Vec<_>>().join(" ")
}

/// Every `N×` in `text`, as written.
fn times_figures(text: &str) -> Vec<String> {
    text.match_indices('×')
        .map(|(i, _)| {
            let digits: Vec<char> = text[..i]
                .chars()
                .rev()
                .take_while(|c| c.is_ascii_digit() || *c == '.')
                .collect();
            format!("{}×", digits.into_iter().rev().collect::<String>())
        })
        .collect()
}

#[test]
fn the_readme_and_the_guide_quote_the_dated_table() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let read = |p: &str| std::fs::read_to_string(root.join(p)).unwrap();
    let flat = |t: &str| t.split_whitespace().collect::<Vec<_>>().join(" ");
    let readme = performance_bullet(&read("README.md"));
    let guide = flat(&read("book/src/performance.md"));
    let rows = quoted_rows(&read("docs/performance.md"));
    assert!(rows.len() >= 2, "the table has {} rows", rows.len());
    for row in &rows {
        for (name, text) in [("README", &readme), ("guide", &guide)] {
            if !row.place.contains(name) {
                continue;
            }
            for quoted in &row.quoted {
                assert!(
                    text.contains(quoted.as_str()),
                    "the {name} does not say `{quoted}`"
                );
            }
            if name == "README" {
                assert!(
                    text.contains(row.command.as_str()),
                    "the README does not give the command `{}`",
                    row.command
                );
            }
        }
    }
    for (name, text) in [("README", &readme), ("guide", &guide)] {
        for figure in times_figures(text) {
            assert!(
                rows.iter().any(|r| r.place.contains(name)
                    && r.quoted.iter().any(|q| q.contains(figure.as_str()))),
                "the {name} quotes `{figure}` without a row in docs/performance.md's \"Figures the README quotes\""
            );
        }
    }
}
