//! The runtime's modules import only downward: every `crate::…` path in a
//! module's code (not its comments) names a module of the same layer or a
//! lower one. The layers, lowest first (trackgen-runtime's crate docs say
//! why):
//!
//! core (planar, trig, wide, error) → laws → model → dynamics → reference →
//! closure → integrate → system → contact → assembly → vehicle → simulate
//!
//! A path into a higher layer (a closure method that names the simulation
//! driver's types, a model trait that names the dynamics) fails here with
//! the file, the line and the two layers.

use std::path::{Path, PathBuf};

/// The layers, lowest first; modules in one entry are one layer.
const LAYERS: &[&[&str]] = &[
    &["planar", "trig", "wide", "error"],
    &["laws"],
    &["model"],
    &["dynamics"],
    &["reference"],
    &["closure"],
    &["integrate"],
    &["system"],
    &["contact"],
    &["assembly"],
    &["vehicle"],
    &["simulate"],
    &["analysis"],
];

/// Items the crate root re-exports, and the module each comes from.
const ROOT_ITEMS: &[(&str, &str)] = &[
    ("sin_cos", "trig"),
    ("sin_cos_each", "trig"),
    ("rotate", "planar"),
    ("rotate_derivative", "planar"),
    ("DynamicsError", "error"),
    ("SimulationError", "error"),
    ("SettingsError", "error"),
    ("BodyLoad", "model"),
    ("ChassisModel", "model"),
    ("RecursiveModel", "model"),
    ("TrackModel", "model"),
    ("TreeDescription", "model"),
    ("Accelerations", "dynamics"),
];

fn layer(module: &str) -> Option<usize> {
    let module = ROOT_ITEMS
        .iter()
        .find(|(item, _)| *item == module)
        .map_or(module, |(_, m)| m);
    LAYERS.iter().position(|l| l.contains(&module))
}

fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("the runtime's sources") {
        let path = entry.expect("a directory entry").path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// A line without its `//` comment (doc links may point anywhere).
fn code(line: &str) -> &str {
    line.find("//").map_or(line, |i| &line[..i])
}

/// The first module of every `crate::` path on a line, with the
/// identifiers of a `use crate::{a, b}` group.
fn targets(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = line;
    while let Some(i) = rest.find("crate::") {
        let after = &rest[i + "crate::".len()..];
        if let Some(group) = after.strip_prefix('{') {
            let inner = &group[..group.find('}').unwrap_or(group.len())];
            for name in inner.split(',') {
                let name = name.trim();
                let first = name.split("::").next().unwrap_or("");
                if !first.is_empty() {
                    out.push(first.to_string());
                }
            }
        } else {
            let name: String = after
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            out.push(name);
        }
        rest = &rest[i + "crate::".len()..];
    }
    out
}

#[test]
fn runtime_modules_import_only_downward() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("trackgen-runtime/src");
    let mut files = Vec::new();
    sources(&src, &mut files);
    files.sort();
    assert!(files.len() > 40, "the runtime's files: {}", files.len());
    let mut wrong = Vec::new();
    let mut checked = 0;
    for file in &files {
        let relative = file.strip_prefix(&src).expect("under src");
        let first = relative
            .iter()
            .next()
            .and_then(|c| c.to_str())
            .unwrap_or("");
        let module = first.trim_end_matches(".rs");
        if module == "lib" {
            // The crate root declares every module and re-exports across
            // the layers, for users.
            continue;
        }
        let own = layer(module).unwrap_or_else(|| {
            panic!(
                "{}: module `{module}` is in no layer: add it to LAYERS",
                relative.display()
            )
        });
        let text = std::fs::read_to_string(file).expect("a source file");
        for (n, line) in text.lines().enumerate() {
            for target in targets(code(line)) {
                checked += 1;
                let Some(theirs) = layer(&target) else {
                    wrong.push(format!(
                        "{}:{}: `crate::{target}` is in no layer (add it to LAYERS or ROOT_ITEMS)",
                        relative.display(),
                        n + 1
                    ));
                    continue;
                };
                if theirs > own {
                    wrong.push(format!(
                        "{}:{}: `{module}` (layer {own}) imports `{target}` (layer {theirs})",
                        relative.display(),
                        n + 1
                    ));
                }
            }
        }
    }
    assert!(checked > 100, "paths checked: {checked}");
    assert!(
        wrong.is_empty(),
        "imports that run upward:\n{}",
        wrong.join("\n")
    );
}

/// The test's own reading of paths, on lines that would fail it.
#[test]
fn the_reading_of_paths_finds_what_it_must() {
    assert_eq!(
        targets("use crate::simulate::{SimulationError, Switch};"),
        ["simulate"]
    );
    assert_eq!(
        targets("use crate::{ContactLaws, sin_cos};"),
        ["ContactLaws", "sin_cos"]
    );
    assert_eq!(
        targets("    let x = crate::sin_cos_each(a, b); // crate::vehicle"),
        ["sin_cos_each", "vehicle"]
    );
    assert_eq!(
        targets(code("    let x = 1; // crate::vehicle")),
        Vec::<String>::new()
    );
    assert!(layer("vehicle") > layer("contact"));
    assert_eq!(layer("sin_cos"), layer("trig"));
    assert_eq!(layer("nowhere"), None);
}
