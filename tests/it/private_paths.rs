//! `__private` holds exactly what generated code names: the insta
//! snapshots of the macro's expansions (every kind of item it generates: a
//! free track open, closed and penalty-closed, vehicles with and without
//! running gear, arms and repeated wheels, and the stubs after an error)
//! reach the runtime only by `::trackgen::__private::…` paths, and every
//! item the runtime's `__private` re-exports is named by one of them.
//!
//! Both sides are read with `syn`: the snapshots' code (every path, every
//! `use` tree, and the tokens of macro calls), and the `pub use` trees of
//! `trackgen-runtime/src/lib.rs`'s `mod __private`.

use std::collections::BTreeSet;
use std::path::Path;

use proc_macro2::{TokenStream, TokenTree};
use syn::visit::Visit;

/// The names under `::trackgen::__private` a path or use tree reaches,
/// as `name` or `module::name` (one level of nesting: `elimination`), and
/// every `::trackgen::` path that does not go through `__private`.
#[derive(Default)]
struct Named {
    private: BTreeSet<String>,
    elsewhere: BTreeSet<String>,
}

impl Named {
    fn path(&mut self, segments: &[String]) {
        match segments {
            [krate, private, rest @ ..] if krate == "trackgen" && private == "__private" => {
                match rest {
                    [] => {}
                    [module, item, ..] if module == "elimination" => {
                        self.private.insert(format!("{module}::{item}"));
                    }
                    [item, ..] => {
                        self.private.insert(item.clone());
                    }
                }
            }
            [krate, ..] if krate == "trackgen" => {
                self.elsewhere.insert(segments.join("::"));
            }
            _ => {}
        }
    }

    fn use_tree(&mut self, tree: &syn::UseTree, prefix: Vec<String>) {
        match tree {
            syn::UseTree::Path(p) => {
                let mut next = prefix;
                next.push(p.ident.to_string());
                self.use_tree(&p.tree, next);
            }
            syn::UseTree::Name(n) => {
                let mut path = prefix;
                if n.ident != "self" {
                    path.push(n.ident.to_string());
                }
                self.path(&path);
            }
            syn::UseTree::Rename(r) => {
                let mut path = prefix;
                path.push(r.ident.to_string());
                self.path(&path);
            }
            syn::UseTree::Glob(_) => self.path(&prefix),
            syn::UseTree::Group(g) => {
                for t in &g.items {
                    self.use_tree(t, prefix.clone());
                }
            }
        }
    }

    /// `:: trackgen :: a :: b` sequences in macro tokens.
    fn tokens(&mut self, tokens: TokenStream) {
        let tokens: Vec<TokenTree> = tokens.into_iter().collect();
        for (i, token) in tokens.iter().enumerate() {
            match token {
                TokenTree::Group(g) => self.tokens(g.stream()),
                TokenTree::Ident(id) if id == "trackgen" => {
                    let mut path = vec![id.to_string()];
                    let mut j = i + 1;
                    while let (
                        Some(TokenTree::Punct(a)),
                        Some(TokenTree::Punct(b)),
                        Some(TokenTree::Ident(next)),
                    ) = (tokens.get(j), tokens.get(j + 1), tokens.get(j + 2))
                    {
                        if a.as_char() != ':' || b.as_char() != ':' {
                            break;
                        }
                        path.push(next.to_string());
                        j += 3;
                    }
                    self.path(&path);
                }
                _ => {}
            }
        }
    }
}

impl<'ast> Visit<'ast> for Named {
    fn visit_path(&mut self, path: &'ast syn::Path) {
        if path.leading_colon.is_some() {
            let segments: Vec<String> = path.segments.iter().map(|s| s.ident.to_string()).collect();
            self.path(&segments);
        }
        syn::visit::visit_path(self, path);
    }

    fn visit_item_use(&mut self, item: &'ast syn::ItemUse) {
        if item.leading_colon.is_some() {
            self.use_tree(&item.tree, Vec::new());
        }
    }

    fn visit_macro(&mut self, mac: &'ast syn::Macro) {
        self.visit_path(&mac.path);
        self.tokens(mac.tokens.clone());
    }
}

/// What the snapshots of generated code name.
fn named_by_snapshots() -> (Named, usize) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("trackgen-macros/src/snapshots");
    let mut named = Named::default();
    let mut read = 0;
    for entry in std::fs::read_dir(&dir).expect("the snapshots") {
        let path = entry.expect("a snapshot").path();
        if path.extension().is_none_or(|e| e != "snap") {
            continue;
        }
        let text = std::fs::read_to_string(&path).expect("a snapshot's text");
        // insta's header is between the first two `---` lines.
        let code = text
            .strip_prefix("---\n")
            .and_then(|t| t.split_once("\n---\n"))
            .map(|(_, body)| body)
            .unwrap_or_else(|| panic!("{}: no insta header", path.display()));
        let file = syn::parse_file(code)
            .unwrap_or_else(|e| panic!("{}: not Rust items: {e}", path.display()));
        named.visit_file(&file);
        read += 1;
    }
    (named, read)
}

/// What the runtime's `__private` re-exports.
fn exported_by_runtime() -> BTreeSet<String> {
    let lib = Path::new(env!("CARGO_MANIFEST_DIR")).join("trackgen-runtime/src/lib.rs");
    let file = syn::parse_file(&std::fs::read_to_string(&lib).expect("the runtime's lib.rs"))
        .expect("lib.rs parses");
    let private = file
        .items
        .iter()
        .find_map(|item| match item {
            syn::Item::Mod(m) if m.ident == "__private" => m.content.as_ref(),
            _ => None,
        })
        .expect("a `mod __private { … }` in the runtime's lib.rs");
    let mut out = BTreeSet::new();
    let mut add = |tree: &syn::UseTree, module: Option<&str>| {
        let mut names = Vec::new();
        last_names(tree, &mut names);
        for name in names {
            out.insert(module.map_or(name.clone(), |m| format!("{m}::{name}")));
        }
    };
    for item in &private.1 {
        match item {
            syn::Item::Use(u) => add(&u.tree, None),
            syn::Item::Mod(m) => {
                let module = m.ident.to_string();
                for inner in &m.content.as_ref().expect("an inline module").1 {
                    if let syn::Item::Use(u) = inner {
                        add(&u.tree, Some(&module));
                    }
                }
            }
            other => panic!("__private holds only re-exports, found {other:?}"),
        }
    }
    out
}

/// The names a use tree brings in.
fn last_names(tree: &syn::UseTree, out: &mut Vec<String>) {
    match tree {
        syn::UseTree::Path(p) => last_names(&p.tree, out),
        syn::UseTree::Name(n) => out.push(n.ident.to_string()),
        syn::UseTree::Rename(r) => out.push(r.rename.to_string()),
        syn::UseTree::Glob(_) => panic!("a glob in __private: list what generated code needs"),
        syn::UseTree::Group(g) => g.items.iter().for_each(|t| last_names(t, out)),
    }
}

#[test]
fn private_holds_exactly_what_generated_code_names() {
    let (named, snapshots) = named_by_snapshots();
    assert!(snapshots >= 7, "snapshots read: {snapshots}");
    assert!(
        named.elsewhere.is_empty(),
        "generated code names the facade outside `__private`: {:?}",
        named.elsewhere
    );
    let exported = exported_by_runtime();
    let unused: Vec<_> = exported.difference(&named.private).collect();
    let missing: Vec<_> = named.private.difference(&exported).collect();
    assert!(
        unused.is_empty() && missing.is_empty(),
        "__private re-exports what no snapshot names: {unused:?}; snapshots name what it lacks: {missing:?}"
    );
    // The reading finds the kernels: a run of the generated linear-time
    // solve names its tables, a vehicle its `VehicleSystem`.
    for name in ["elimination::with_tables", "VehicleSystem", "sin_cos_each"] {
        assert!(
            named.private.contains(name),
            "{name} not found in the snapshots"
        );
    }
}
