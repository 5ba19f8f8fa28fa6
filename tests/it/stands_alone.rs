//! The repository stands on its own: no source, test, guide page or
//! document cites the specification folder that sits beside the
//! repository during development (its spec, paper and reference data),
//! which a user who clones the project does not have. The mathematics is
//! the guide's "The formulation" (cited as "formulation §n"), the
//! reference values are `tests/data/` (with their README), and every
//! figure cites its published source.
//!
//! Every text file under the workspace (Rust, Markdown, TOML, shell,
//! Python, YAML; `target/` and `.git/` skipped) is read; a citation fails
//! the test with its file and line.

use std::path::{Path, PathBuf};

/// What a citation of the folder looks like. Built from pieces so that
/// this file does not cite it itself.
fn needles() -> Vec<String> {
    let folder = "shared";
    let mut needles: Vec<String> = ["spec", "reference", "paper"]
        .iter()
        .map(|sub| format!("{folder}/{sub}"))
        .collect();
    needles.push(format!("../{folder}"));
    needles.push(format!("{} §", "spec"));
    needles
}

fn text_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        let name = entry.file_name();
        let name = name.to_string_lossy();
        if path.is_dir() {
            if name != "target" && !name.starts_with('.') || name == ".ci" {
                text_files(&path, out);
            }
        } else if ["rs", "md", "toml", "sh", "py", "yml", "yaml"]
            .iter()
            .any(|ext| path.extension().is_some_and(|e| e == *ext))
            || name == "run"
        {
            out.push(path);
        }
    }
}

#[test]
fn nothing_cites_the_development_folder() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    text_files(root, &mut files);
    assert!(
        files.len() > 100,
        "read {} files: the walk found too few",
        files.len()
    );
    let needles = needles();
    let mut found = Vec::new();
    for file in &files {
        let Ok(text) = std::fs::read_to_string(file) else {
            continue;
        };
        for (i, line) in text.lines().enumerate() {
            if let Some(needle) = needles.iter().find(|n| line.contains(n.as_str())) {
                found.push(format!(
                    "{}:{}: cites `{needle}`",
                    file.strip_prefix(root).unwrap_or(file).display(),
                    i + 1
                ));
            }
        }
    }
    assert!(found.is_empty(), "{}", found.join("\n"));
}
