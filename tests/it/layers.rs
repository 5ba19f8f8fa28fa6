//! The layers: every crate of the workspace imports only along the edges
//! its graph allows, each item from the module that defines it, and no two
//! files need each other.
//!
//! Every source file of the runtime, the macro crate, the facade and the
//! application is parsed with `syn`. The module tree is read from the `mod`
//! declarations (inline and in files); every `use` (groups, renames,
//! `self`, globs) and every path in code (types, expressions, patterns,
//! trait bounds, and the tokens of macro calls) that starts with
//! `crate::`, `super::`, `self::` or a module's own child is resolved
//! through the tree to the module that *defines* the item, following
//! re-exports. Doc comments and other attributes are not read: a doc link
//! may point anywhere.
//!
//! Three rules, each failing with the file and line:
//! * **edges**: the top-level module of the importing file may import the
//!   top-level module of the defining file only if the crate's graph
//!   ([`RUNTIME`], [`MACROS`], [`APP`], [`FACADE`]) has the edge;
//! * **one path**: a path may pass through re-exports only inside the
//!   defining item's own top-level module (`crate::vehicle::VehicleSystem`,
//!   re-exported by `vehicle/mod.rs` from `vehicle/system.rs`, is its own
//!   module's face; `crate::DynamicsError` through the crate root, or
//!   `crate::simulate::Switch` re-exported from `closure`, is not);
//! * **no circles**: the graph of files (an edge for each private `use`
//!   and path in code; `mod` declarations and `pub use` re-exports are the
//!   module's face, not a need) has no cycle.
//!
//! The graphs themselves are checked to be acyclic, and to name every
//! top-level module (a new module must be placed in its crate's graph).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use proc_macro2::{TokenStream, TokenTree};
use syn::visit::Visit;

/// A crate's graph: each top-level module (`lib` or `main` for the crate
/// root) with the top-level modules it may import directly.
type Graph = &'static [(&'static str, &'static [&'static str])];

/// The runtime, by physical role (trackgen-runtime's crate docs give the
/// same list): core → laws → multibody → contact → solvers → time →
/// subsystems → vehicle → drivers. An edge is listed only where the code
/// needs it: contact does not import the solvers, the solvers do not
/// import contact, assembly does not import time.
pub const RUNTIME: Graph = &[
    // core
    ("planar", &[]),
    ("simd", &[]),
    ("ride", &[]),
    ("steering", &["ride"]),
    ("trig", &["simd"]),
    // physics: the laws, the bodies, contact
    ("laws", &["planar"]),
    ("multibody", &["planar", "laws"]),
    ("terrain", &["trig"]),
    (
        "contact",
        &["planar", "trig", "laws", "multibody", "terrain"],
    ),
    // solvers
    ("dynamics", &["planar", "simd", "laws", "multibody"]),
    ("closure", &["planar", "trig", "laws", "multibody"]),
    ("reference", &["planar", "multibody", "dynamics"]),
    ("spatial", &["trig", "laws", "multibody", "terrain"]),
    // time
    ("integrate", &["simd", "multibody", "closure"]),
    // subsystems
    (
        "system",
        &[
            "planar",
            "trig",
            "laws",
            "multibody",
            "dynamics",
            "closure",
            "integrate",
        ],
    ),
    (
        "assembly",
        &["planar", "multibody", "contact", "terrain", "spatial"],
    ),
    // the vehicle
    (
        "vehicle",
        &[
            "planar",
            "trig",
            "simd",
            "laws",
            "multibody",
            "terrain",
            "contact",
            "dynamics",
            "closure",
            "integrate",
            "system",
            "assembly",
        ],
    ),
    (
        "spatial_vehicle",
        &[
            "assembly",
            "laws",
            "multibody",
            "contact",
            "terrain",
            "spatial",
            "closure",
            "integrate",
            "vehicle",
        ],
    ),
    // drivers
    ("simulate", &["ride", "closure", "integrate", "system"]),
    (
        "analysis",
        &[
            "planar",
            "multibody",
            "contact",
            "dynamics",
            "integrate",
            "system",
            "vehicle",
            "simulate",
            "spatial_vehicle",
        ],
    ),
    (
        "scene",
        &[
            "planar",
            "multibody",
            "terrain",
            "contact",
            "vehicle",
            "simulate",
        ],
    ),
    (
        "scenario",
        &["terrain", "integrate", "system", "vehicle", "simulate"],
    ),
    (
        "mobility",
        &[
            "terrain",
            "contact",
            "integrate",
            "system",
            "vehicle",
            "simulate",
            "scene",
            "scenario",
            "spatial_vehicle",
        ],
    ),
    // `__private`: the paths generated code names (lib.rs).
    (
        "__private",
        &[
            "planar",
            "trig",
            "laws",
            "multibody",
            "terrain",
            "contact",
            "dynamics",
            "spatial",
            "spatial_vehicle",
            "vehicle",
        ],
    ),
    // The root declares the modules.
    ("lib", &[]),
];

/// The compiler: parse → lower (into the IR, every error collected) →
/// codegen, the IR and the numbers below all three.
pub const MACROS: Graph = &[
    ("num", &[]),
    ("ir", &["num"]),
    ("parse", &[]),
    ("lower", &["num", "ir", "parse"]),
    ("codegen", &["num", "ir"]),
    ("expand", &["parse", "lower", "codegen"]),
    ("lib", &["expand"]),
    (
        "tests",
        &["expand", "parse", "lower", "codegen", "ir", "num"],
    ),
    (
        "properties",
        &["expand", "parse", "lower", "codegen", "ir", "num"],
    ),
];

/// The facade: the vehicles it declares, and the root.
pub const FACADE: Graph = &[
    ("vehicles", &[]),
    ("__private", &[]),
    // The README's and the guide's doctests.
    ("guide", &[]),
    ("lib", &["vehicles"]),
];

/// The application (`trackgen-app`): the options, the console and what
/// the subcommands know of a vehicle at the bottom, the outputs and
/// reports over them (drawn by the crate `trackgen-draw`), a module per
/// subcommand, and `app` (the command line and the dispatch to a
/// vehicle's type) on top.
pub const APP: Graph = &[
    ("console", &[]),
    ("cli", &[]),
    ("offered", &[]),
    ("nearest", &[]),
    ("outputs", &["nearest"]),
    ("report", &["console", "cli"]),
    ("spatial_modes", &["console", "offered"]),
    ("modes", &["console", "cli", "offered", "spatial_modes"]),
    ("fmu", &["cli", "offered"]),
    ("mobility", &["cli", "offered"]),
    ("turn_runs", &["offered"]),
    (
        "steer",
        &["console", "cli", "offered", "modes", "turn_runs"],
    ),
    ("spatial_rows", &[]),
    ("spatial_frames", &[]),
    ("spatial_driveline", &[]),
    (
        "spatial",
        &[
            "console",
            "cli",
            "offered",
            "report",
            "spatial_rows",
            "spatial_frames",
            "spatial_driveline",
        ],
    ),
    (
        "run",
        &["console", "cli", "offered", "outputs", "report", "modes"],
    ),
    (
        "app",
        &[
            "cli",
            "offered",
            "run",
            "mobility",
            "modes",
            "steer",
            "spatial",
            "turn_runs",
            "spatial_modes",
            "fmu",
        ],
    ),
    ("lib", &["app"]),
];

/// A module of a crate: its file, what it defines, what it imports.
#[derive(Debug, Default)]
struct Module {
    /// The file its items are in.
    file: PathBuf,
    /// Child modules, by name.
    children: BTreeSet<String>,
    /// Names of the items it defines (types, functions, traits,
    /// constants, statics, macros).
    items: BTreeSet<String>,
    /// Its `use` declarations: the name each brings in (`None` for a
    /// glob), the path it names, whether it is a re-export (`pub` in any
    /// form), and the line.
    uses: Vec<UseEntry>,
    /// Paths in its code (not `use`) that may name a module of the crate,
    /// with their lines.
    paths: Vec<(Vec<String>, usize)>,
}

#[derive(Debug, Clone)]
struct UseEntry {
    name: Option<String>,
    path: Vec<String>,
    public: bool,
    line: usize,
}

/// A crate read from its sources: its modules by path from the root.
#[derive(Debug, Default)]
struct Crate {
    modules: BTreeMap<Vec<String>, Module>,
}

/// Where a path leads: the module defining its item (or the module it
/// names), and the modules whose re-exports it went through.
#[derive(Debug, PartialEq)]
struct Resolved {
    module: Vec<String>,
    via: Vec<Vec<String>>,
}

/// The sources a crate is read from: file path → text (so the tests
/// below can hand it a crate that exists only in memory).
trait Sources {
    fn read(&self, path: &Path) -> Option<String>;
}

struct Disk;

impl Sources for Disk {
    fn read(&self, path: &Path) -> Option<String> {
        std::fs::read_to_string(path).ok()
    }
}

impl Sources for BTreeMap<PathBuf, String> {
    fn read(&self, path: &Path) -> Option<String> {
        self.get(path).cloned()
    }
}

fn line_of(span: proc_macro2::Span) -> usize {
    span.start().line
}

/// Reads the crate whose root file is `root`, following `mod`
/// declarations. Errors: a file that does not parse, a declared module
/// without a file.
fn read_crate(root: &Path, sources: &dyn Sources) -> Result<Crate, String> {
    let mut krate = Crate::default();
    let dir = root
        .parent()
        .expect("a root file in a folder")
        .to_path_buf();
    read_file(&mut krate, sources, root, Vec::new(), dir)?;
    Ok(krate)
}

/// Reads one file as module `path`; `dir` is where its child modules'
/// files are.
fn read_file(
    krate: &mut Crate,
    sources: &dyn Sources,
    file: &Path,
    path: Vec<String>,
    dir: PathBuf,
) -> Result<(), String> {
    let text = sources
        .read(file)
        .ok_or_else(|| format!("{}: cannot be read", file.display()))?;
    let ast = syn::parse_file(&text).map_err(|e| {
        format!(
            "{}:{}: does not parse: {e}",
            file.display(),
            line_of(e.span())
        )
    })?;
    read_items(krate, sources, file, path, dir, &ast.items)
}

fn read_items(
    krate: &mut Crate,
    sources: &dyn Sources,
    file: &Path,
    path: Vec<String>,
    dir: PathBuf,
    items: &[syn::Item],
) -> Result<(), String> {
    let mut module = Module {
        file: file.to_path_buf(),
        ..Module::default()
    };
    let mut children = Vec::new();
    for item in items {
        let name = match item {
            syn::Item::Const(i) => Some(&i.ident),
            syn::Item::Enum(i) => Some(&i.ident),
            syn::Item::Fn(i) => Some(&i.sig.ident),
            syn::Item::Static(i) => Some(&i.ident),
            syn::Item::Struct(i) => Some(&i.ident),
            syn::Item::Trait(i) => Some(&i.ident),
            syn::Item::TraitAlias(i) => Some(&i.ident),
            syn::Item::Type(i) => Some(&i.ident),
            syn::Item::Union(i) => Some(&i.ident),
            syn::Item::Macro(i) => i.ident.as_ref(),
            _ => None,
        };
        if let Some(name) = name {
            module.items.insert(name.to_string());
        }
        match item {
            syn::Item::Mod(m) => {
                module.children.insert(m.ident.to_string());
                children.push(m);
            }
            syn::Item::Use(u) => {
                let public = !matches!(u.vis, syn::Visibility::Inherited);
                let mut entries = Vec::new();
                flatten_use(&u.tree, Vec::new(), &mut entries);
                for (name, path) in entries {
                    module.uses.push(UseEntry {
                        name,
                        path,
                        public,
                        line: line_of(u.use_token.span),
                    });
                }
            }
            _ => {
                let mut paths = PathCollector::default();
                paths.visit_item(item);
                module.paths.extend(paths.found);
            }
        }
    }
    krate.modules.insert(path.clone(), module);
    for m in children {
        let name = m.ident.to_string();
        let mut child = path.clone();
        child.push(name.clone());
        if let Some((_, items)) = &m.content {
            // An inline module: its files, if any, would be under
            // `dir/name/`.
            read_items(krate, sources, file, child, dir.join(&name), items)?;
        } else {
            let flat = dir.join(format!("{name}.rs"));
            let nested = dir.join(&name).join("mod.rs");
            let (found, child_dir) = if sources.read(&flat).is_some() {
                (flat, dir.join(&name))
            } else if sources.read(&nested).is_some() {
                (nested, dir.join(&name))
            } else {
                return Err(format!(
                    "{}:{}: module `{name}` has no file",
                    file.display(),
                    line_of(m.ident.span())
                ));
            };
            read_file(krate, sources, &found, child, child_dir)?;
        }
    }
    Ok(())
}

/// The `(name, path)` pairs of a use tree: `use a::{b, c::d as e, f::*}`
/// gives `(b, a::b)`, `(e, a::c::d)`, `(None, a::f)`.
fn flatten_use(
    tree: &syn::UseTree,
    prefix: Vec<String>,
    out: &mut Vec<(Option<String>, Vec<String>)>,
) {
    match tree {
        syn::UseTree::Path(p) => {
            let mut next = prefix;
            next.push(p.ident.to_string());
            flatten_use(&p.tree, next, out);
        }
        syn::UseTree::Name(n) => {
            let name = n.ident.to_string();
            if name == "self" {
                let last = prefix.last().cloned();
                out.push((last, prefix));
            } else {
                let mut path = prefix;
                path.push(name.clone());
                out.push((Some(name), path));
            }
        }
        syn::UseTree::Rename(r) => {
            let mut path = prefix.clone();
            let from = r.ident.to_string();
            if from != "self" {
                path.push(from);
            }
            out.push((Some(r.rename.to_string()), path));
        }
        syn::UseTree::Glob(_) => out.push((None, prefix)),
        syn::UseTree::Group(g) => {
            for t in &g.items {
                flatten_use(t, prefix.clone(), out);
            }
        }
    }
}

/// Paths in code that may lead into the crate, with their lines: every
/// `syn::Path` outside attributes, and `crate`/`super`/`self` paths in
/// the tokens of macro calls (but not of `quote!`, whose tokens are the
/// code it generates).
#[derive(Default)]
struct PathCollector {
    found: Vec<(Vec<String>, usize)>,
}

impl<'ast> Visit<'ast> for PathCollector {
    fn visit_attribute(&mut self, _: &'ast syn::Attribute) {}

    fn visit_path(&mut self, path: &'ast syn::Path) {
        if path.leading_colon.is_none() && path.segments.len() > 1 {
            let segments = path.segments.iter().map(|s| s.ident.to_string()).collect();
            let line = line_of(path.segments[0].ident.span());
            self.found.push((segments, line));
        }
        syn::visit::visit_path(self, path);
    }

    fn visit_macro(&mut self, mac: &'ast syn::Macro) {
        self.visit_path(&mac.path);
        let name = mac.path.segments.last().map(|s| s.ident.to_string());
        if !matches!(
            name.as_deref(),
            Some("quote" | "quote_spanned" | "parse_quote")
        ) {
            token_paths(mac.tokens.clone(), &mut self.found);
        }
    }
}

/// `crate::a::b`, `super::a`, `self::a` paths in a token stream.
fn token_paths(tokens: TokenStream, out: &mut Vec<(Vec<String>, usize)>) {
    let tokens: Vec<TokenTree> = tokens.into_iter().collect();
    let mut i = 0;
    while i < tokens.len() {
        match &tokens[i] {
            TokenTree::Group(g) => token_paths(g.stream(), out),
            TokenTree::Ident(id)
                if matches!(id.to_string().as_str(), "crate" | "super" | "self") =>
            {
                let preceded_by_colons =
                    i >= 1 && matches!(&tokens[i - 1], TokenTree::Punct(p) if p.as_char() == ':');
                if !preceded_by_colons {
                    let mut path = vec![id.to_string()];
                    let mut j = i + 1;
                    while j + 2 < tokens.len() {
                        let colons = matches!(&tokens[j], TokenTree::Punct(p) if p.as_char() == ':')
                            && matches!(&tokens[j + 1], TokenTree::Punct(p) if p.as_char() == ':');
                        match (&colons, tokens.get(j + 2)) {
                            (true, Some(TokenTree::Ident(next))) => {
                                path.push(next.to_string());
                                j += 3;
                            }
                            _ => break,
                        }
                    }
                    if path.len() > 1 {
                        out.push((path, line_of(id.span())));
                    }
                    i = j.max(i + 1);
                    continue;
                }
            }
            _ => {}
        }
        i += 1;
    }
}

impl Crate {
    /// Resolves `path`, written in module `from`, to the module that
    /// defines what it names. `None` for a path outside the crate (an
    /// extern crate, a local variable's field, a generic).
    fn resolve(&self, from: &[String], path: &[String]) -> Option<Resolved> {
        let (start, rest) = self.anchor(from, path)?;
        let mut via = Vec::new();
        self.walk(from, start, rest, &mut via, 0)
            .map(|module| Resolved { module, via })
    }

    /// Where a path starts: the module its first segment names, and the
    /// segments after it.
    fn anchor<'p>(
        &self,
        from: &[String],
        path: &'p [String],
    ) -> Option<(Vec<String>, &'p [String])> {
        let mut at: Vec<String> = from.to_vec();
        let mut rest = path;
        match rest.first()?.as_str() {
            "crate" => {
                at.clear();
                rest = &rest[1..];
            }
            "self" => rest = &rest[1..],
            "super" => {
                while rest.first().map(String::as_str) == Some("super") {
                    at.pop()?;
                    rest = &rest[1..];
                }
            }
            first => {
                // A path from a name in scope: a child module, an item
                // defined here, or a name a `use` brought in.
                let module = self.modules.get(&at)?;
                if !module.children.contains(first)
                    && !module.items.contains(first)
                    && !module.uses.iter().any(|u| u.name.as_deref() == Some(first))
                {
                    return None;
                }
            }
        }
        Some((at, rest))
    }

    fn walk(
        &self,
        from: &[String],
        mut at: Vec<String>,
        rest: &[String],
        via: &mut Vec<Vec<String>>,
        depth: usize,
    ) -> Option<Vec<String>> {
        if depth > 32 {
            return None;
        }
        for (k, segment) in rest.iter().enumerate() {
            let module = self.modules.get(&at)?;
            if module.children.contains(segment) {
                at.push(segment.clone());
                continue;
            }
            if module.items.contains(segment) {
                return Some(at);
            }
            // Brought in by a `use`: follow it.
            if let Some(entry) = module
                .uses
                .iter()
                .find(|u| u.name.as_deref() == Some(segment.as_str()))
            {
                // The importing module's own `use` is the import itself;
                // any other module's is a re-export.
                if at != from {
                    via.push(at.clone());
                }
                let (start, tail) = self.anchor(&at, &entry.path)?;
                let mut target: Vec<String> = tail.to_vec();
                target.extend(rest[k + 1..].iter().cloned());
                return self.walk(from, start, &target, via, depth + 1);
            }
            // A glob: the first that leads somewhere.
            for entry in module.uses.iter().filter(|u| u.name.is_none()) {
                if let Some((start, tail)) = self.anchor(&at, &entry.path) {
                    let mut target: Vec<String> = tail.to_vec();
                    target.extend(rest[k..].iter().cloned());
                    let mut through = via.clone();
                    if at != from {
                        through.push(at.clone());
                    }
                    if let Some(found) = self.walk(from, start, &target, &mut through, depth + 1) {
                        *via = through;
                        return Some(found);
                    }
                }
            }
            return None;
        }
        Some(at)
    }
}

/// One import that breaks a rule, for the failure message.
fn top(module: &[String], root: &str) -> String {
    module.first().cloned().unwrap_or_else(|| root.to_string())
}

/// Checks a crate against its graph: every import along an allowed edge
/// and from its own module, and no circle between files. Returns the
/// breaches, each with file and line, and the number of imports checked.
fn check(krate: &Crate, root_name: &str, graph: Graph, base: &Path) -> (Vec<String>, usize) {
    let mut wrong = Vec::new();
    let allowed: BTreeMap<&str, &[&str]> = graph.iter().copied().collect();
    let show = |file: &Path| {
        file.strip_prefix(base)
            .unwrap_or(file)
            .display()
            .to_string()
    };
    // Every top-level module is in the graph.
    for (path, module) in &krate.modules {
        let name = top(path, root_name);
        if !allowed.contains_key(name.as_str()) {
            wrong.push(format!(
                "{}: module `{name}` is in no layer of the graph: place it",
                show(&module.file)
            ));
        }
    }
    let mut files: BTreeMap<PathBuf, BTreeMap<PathBuf, usize>> = BTreeMap::new();
    let mut checked = 0;
    for (path, module) in &krate.modules {
        let own = top(path, root_name);
        let imports = module
            .uses
            .iter()
            // A glob's path names a module; a named import, an item.
            .map(|u| (u.path.clone(), u.line, u.public))
            .chain(module.paths.iter().map(|(p, l)| (p.clone(), *l, false)));
        for (target, line, public) in imports {
            let Some(resolved) = krate.resolve(path, &target) else {
                continue;
            };
            checked += 1;
            let theirs = top(&resolved.module, root_name);
            let written = target.join("::");
            if theirs != own
                && !allowed
                    .get(own.as_str())
                    .is_some_and(|a| a.contains(&theirs.as_str()))
            {
                wrong.push(format!(
                    "{}:{line}: `{own}` imports `{written}` from `{theirs}`: not an edge of the graph",
                    show(&module.file)
                ));
            }
            for through in &resolved.via {
                if top(through, root_name) != theirs {
                    wrong.push(format!(
                        "{}:{line}: `{written}` goes through a re-export in `{}`: import it from `{}`, which defines it",
                        show(&module.file),
                        if through.is_empty() { "the crate root".to_string() } else { through.join("::") },
                        resolved.module.join("::"),
                    ));
                    break;
                }
            }
            let defining = &krate.modules[&resolved.module].file;
            if !public && defining != &module.file {
                files
                    .entry(module.file.clone())
                    .or_default()
                    .entry(defining.clone())
                    .or_insert(line);
            }
        }
    }
    for cycle in cycles(&files) {
        let closed: Vec<&PathBuf> = cycle.iter().chain(cycle.first()).collect();
        let shown: Vec<String> = closed
            .windows(2)
            .map(|w| format!("{} (line {})", show(w[0]), files[w[0]][w[1]]))
            .collect();
        wrong.push(format!(
            "a circle between files: {} -> {}",
            shown.join(" -> "),
            show(&cycle[0])
        ));
    }
    (wrong, checked)
}

/// The cycles of a directed graph, one per strongly connected component
/// of more than one node (Tarjan's algorithm), each as a closed walk.
fn cycles<N: Ord + Clone>(graph: &BTreeMap<N, BTreeMap<N, usize>>) -> Vec<Vec<N>> {
    let nodes: BTreeSet<N> = graph
        .iter()
        .flat_map(|(a, out)| std::iter::once(a.clone()).chain(out.keys().cloned()))
        .collect();
    let index_of: BTreeMap<N, usize> = nodes
        .iter()
        .cloned()
        .enumerate()
        .map(|(i, n)| (n, i))
        .collect();
    let names: Vec<N> = nodes.into_iter().collect();
    let edges: Vec<Vec<usize>> = names
        .iter()
        .map(|n| {
            graph
                .get(n)
                .map(|out| out.keys().map(|m| index_of[m]).collect())
                .unwrap_or_default()
        })
        .collect();
    let components = strongly_connected(&edges);
    components
        .into_iter()
        .filter(|c| c.len() > 1)
        .map(|c| {
            // The shortest closed walk inside the component through its
            // first node (breadth first).
            let inside: BTreeSet<usize> = c.iter().copied().collect();
            let start = c[0];
            let mut came_from: BTreeMap<usize, usize> = BTreeMap::new();
            let mut queue = std::collections::VecDeque::from([start]);
            'search: while let Some(at) = queue.pop_front() {
                for &next in &edges[at] {
                    if !inside.contains(&next) || came_from.contains_key(&next) {
                        continue;
                    }
                    came_from.insert(next, at);
                    if next == start {
                        break 'search;
                    }
                    queue.push_back(next);
                }
            }
            let mut walk = Vec::new();
            let mut at = came_from[&start];
            while at != start {
                walk.push(at);
                at = came_from[&at];
            }
            walk.push(start);
            walk.reverse();
            walk.into_iter().map(|i| names[i].clone()).collect()
        })
        .collect()
}

/// Tarjan's strongly connected components.
fn strongly_connected(edges: &[Vec<usize>]) -> Vec<Vec<usize>> {
    struct State<'a> {
        edges: &'a [Vec<usize>],
        index: Vec<Option<usize>>,
        low: Vec<usize>,
        on_stack: Vec<bool>,
        stack: Vec<usize>,
        next: usize,
        out: Vec<Vec<usize>>,
    }
    fn visit(s: &mut State<'_>, v: usize) {
        s.index[v] = Some(s.next);
        s.low[v] = s.next;
        s.next += 1;
        s.stack.push(v);
        s.on_stack[v] = true;
        for &w in &s.edges[v] {
            match s.index[w] {
                None => {
                    visit(s, w);
                    s.low[v] = s.low[v].min(s.low[w]);
                }
                Some(i) if s.on_stack[w] => s.low[v] = s.low[v].min(i),
                _ => {}
            }
        }
        if Some(s.low[v]) == s.index[v] {
            let mut component = Vec::new();
            while let Some(w) = s.stack.pop() {
                s.on_stack[w] = false;
                component.push(w);
                if w == v {
                    break;
                }
            }
            component.reverse();
            s.out.push(component);
        }
    }
    let n = edges.len();
    let mut s = State {
        edges,
        index: vec![None; n],
        low: vec![0; n],
        on_stack: vec![false; n],
        stack: Vec::new(),
        next: 0,
        out: Vec::new(),
    };
    for v in 0..n {
        if s.index[v].is_none() {
            visit(&mut s, v);
        }
    }
    s.out
}

/// A graph of allowed edges is a graph of layers only if it has no cycle.
fn graph_cycles(graph: Graph) -> Vec<Vec<&'static str>> {
    let map: BTreeMap<&'static str, BTreeMap<&'static str, usize>> = graph
        .iter()
        .map(|(m, to)| (*m, to.iter().map(|t| (*t, 0)).collect()))
        .collect();
    cycles(&map)
}

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).to_path_buf()
}

fn assert_layered(root: &str, root_name: &str, graph: Graph, min_files: usize, min_imports: usize) {
    let base = workspace();
    assert!(
        graph_cycles(graph).is_empty(),
        "{root}: the graph has a cycle: {:?}",
        graph_cycles(graph)
    );
    let krate = read_crate(&base.join(root), &Disk).unwrap_or_else(|e| panic!("{e}"));
    let files: BTreeSet<&PathBuf> = krate.modules.values().map(|m| &m.file).collect();
    assert!(
        files.len() >= min_files,
        "{root}: read {} files, expected at least {min_files}",
        files.len()
    );
    let (wrong, checked) = check(&krate, root_name, graph, &base);
    assert!(
        checked >= min_imports,
        "{root}: only {checked} imports resolved"
    );
    assert!(wrong.is_empty(), "{root}:\n{}", wrong.join("\n"));
}

#[test]
fn the_runtime_is_layered() {
    assert_layered("trackgen-runtime/src/lib.rs", "lib", RUNTIME, 90, 500);
}

#[test]
fn the_macro_crate_is_layered() {
    assert_layered("trackgen-macros/src/lib.rs", "lib", MACROS, 25, 200);
}

#[test]
fn the_facade_is_layered() {
    assert_layered("src/lib.rs", "lib", FACADE, 3, 0);
}

#[test]
fn the_application_is_layered() {
    assert_layered("trackgen-app/src/lib.rs", "lib", APP, 15, 40);
}

/// The runtime's layers are one list: every module of the graph is named
/// in the runtime's crate docs and in the guide's architecture chapter,
/// whose table of edges is the graph's.
#[test]
fn the_layers_are_one_list() {
    let base = workspace();
    let docs: String = std::fs::read_to_string(base.join("trackgen-runtime/src/lib.rs"))
        .expect("the runtime's lib.rs")
        .lines()
        .filter_map(|l| l.trim_start().strip_prefix("//!"))
        .collect::<Vec<_>>()
        .join("\n");
    let guide = std::fs::read_to_string(base.join("book/src/architecture.md"))
        .expect("the guide's architecture chapter");
    for (module, edges) in RUNTIME {
        if matches!(*module, "lib" | "__private") {
            continue;
        }
        assert!(
            docs.contains(&format!("`{module}`")),
            "the runtime's crate docs do not name `{module}`"
        );
        // Its row of the guide's table: `| `module` … | edges |`.
        let row = guide
            .lines()
            .find(|l| {
                l.starts_with('|')
                    && l.split('|')
                        .nth(1)
                        .is_some_and(|c| c.contains(&format!("`{module}`")))
            })
            .unwrap_or_else(|| panic!("the guide's table has no row for `{module}`"));
        let listed = row.split('|').nth(2).unwrap_or("");
        if listed.contains("all of the above") {
            continue;
        }
        for edge in *edges {
            assert!(
                listed.contains(&format!("`{edge}`")),
                "the guide's row for `{module}` lacks `{edge}`: {row}"
            );
        }
    }
}

/// A crate in memory, from `(file, text)` pairs under `/c/`.
fn in_memory(files: &[(&str, &str)]) -> Crate {
    let sources: BTreeMap<PathBuf, String> = files
        .iter()
        .map(|(f, t)| (Path::new("/c").join(f), t.to_string()))
        .collect();
    read_crate(Path::new("/c/lib.rs"), &sources).unwrap_or_else(|e| panic!("{e}: {files:?}"))
}

const TOY: Graph = &[("low", &[]), ("high", &["low"]), ("lib", &["low", "high"])];

fn toy_breaches(files: &[(&str, &str)]) -> Vec<String> {
    check(&in_memory(files), "lib", TOY, Path::new("/c")).0
}

/// The reading finds what it must: an upward import written every way
/// (a grouped `use` wrapped over lines, `super::`, a path in code, a path
/// inside a macro call), a path through the crate root's re-export, and a
/// circle between two files.
#[test]
fn the_check_finds_what_it_must() {
    // Clean: downward imports, written in each form.
    let clean = toy_breaches(&[
        ("lib.rs", "pub mod low; pub mod high;"),
        ("low.rs", "pub struct A; pub fn f() {}"),
        (
            "high/mod.rs",
            "mod inner; pub use inner::B;\nuse crate::{\n    low::A,\n};\nfn g() { crate::low::f(); let _ = A; }",
        ),
        (
            "high/inner.rs",
            "pub struct B; fn h() { super::super::low::f(); }",
        ),
    ]);
    assert!(clean.is_empty(), "{clean:?}");

    // Upward, in a wrapped group.
    let up = toy_breaches(&[
        ("lib.rs", "pub mod low; pub mod high;"),
        ("low.rs", "use crate::{\n    high::B,\n};"),
        ("high.rs", "pub struct B;"),
    ]);
    assert!(
        up.iter()
            .any(|e| e.contains("low.rs:1") && e.contains("not an edge")),
        "{up:?}"
    );

    // Upward by `super::` and in code and in a macro's tokens.
    let up = toy_breaches(&[
        ("lib.rs", "pub mod low; pub mod high;"),
        ("low/mod.rs", "mod leaf;"),
        (
            "low/leaf.rs",
            "fn f() {\n let _ = super::super::high::B;\n let _ = vec![crate::high::g()];\n}",
        ),
        ("high.rs", "pub struct B; pub fn g() -> u8 { 0 }"),
    ]);
    assert_eq!(
        up.iter().filter(|e| e.contains("not an edge")).count(),
        2,
        "{up:?}"
    );
    assert!(up.iter().any(|e| e.contains("low/leaf.rs:2")), "{up:?}");
    assert!(up.iter().any(|e| e.contains("low/leaf.rs:3")), "{up:?}");

    // Through the root's re-export.
    let root = toy_breaches(&[
        ("lib.rs", "pub mod low; pub mod high; pub use low::A;"),
        ("low.rs", "pub struct A;"),
        ("high.rs", "use crate::A;"),
    ]);
    assert!(
        root.iter().any(|e| e.contains("the crate root")),
        "{root:?}"
    );

    // A circle between two files of one module.
    let circle = toy_breaches(&[
        ("lib.rs", "pub mod low; pub mod high;"),
        ("low/mod.rs", "mod a; mod b;"),
        ("low/a.rs", "use super::b::B; pub struct A;"),
        ("low/b.rs", "use super::a::A; pub struct B;"),
        ("high.rs", ""),
    ]);
    assert!(
        circle.iter().any(|e| e.contains("a circle between files")),
        "{circle:?}"
    );

    // A module in no layer.
    let stray = toy_breaches(&[
        ("lib.rs", "pub mod low; mod stray;"),
        ("low.rs", ""),
        ("stray.rs", ""),
    ]);
    assert!(
        stray.iter().any(|e| e.contains("`stray` is in no layer")),
        "{stray:?}"
    );

    // A graph with a cycle is refused.
    assert!(!graph_cycles(&[("a", &["b"]), ("b", &["a"])]).is_empty());
    for graph in [RUNTIME, MACROS, FACADE, APP] {
        assert!(graph_cycles(graph).is_empty());
    }
}
