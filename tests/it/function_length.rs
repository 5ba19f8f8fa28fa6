//! No function in the crates' sources (tests aside) is over
//! [`LONGEST`] lines: a longer one has more than one job. Code inside
//! `quote!` is the generated code's, not a function of ours, and `syn`
//! reads it as a macro's tokens, so it is not counted. Modules under
//! `#[cfg(test)]` and `#[test]` functions are tests.

use std::path::{Path, PathBuf};

use syn::visit::Visit;

/// The most lines a function may span, its signature and doc comments
/// included.
const LONGEST: usize = 150;

/// Every crate's root file, relative to the workspace.
const ROOTS: [&str; 9] = [
    "src/lib.rs",
    "trackgen-runtime/src/lib.rs",
    "trackgen-macros/src/lib.rs",
    "trackgen-fmu/src/lib.rs",
    "trackgen-app/src/lib.rs",
    "trackgen-cli/src/main.rs",
    "trackgen-draw/src/lib.rs",
    "trackgen-arrow/src/lib.rs",
    "trackgen-sprocket/src/lib.rs",
];

fn is_test(attrs: &[syn::Attribute]) -> bool {
    attrs.iter().any(|a| {
        a.path().is_ident("test")
            || (a.path().is_ident("cfg")
                && a.parse_args::<syn::Meta>()
                    .is_ok_and(|m| m.path().is_ident("test")))
    })
}

/// Walks one file: its long functions, and the files of the modules it
/// declares (`mod name;`) outside tests.
struct Walk {
    file: PathBuf,
    long: Vec<String>,
    children: Vec<String>,
}

impl Walk {
    fn measure(&mut self, name: &syn::Ident, attrs: &[syn::Attribute], span: proc_macro2::Span) {
        if is_test(attrs) {
            return;
        }
        let lines = span.end().line - span.start().line + 1;
        if lines > LONGEST {
            self.long.push(format!(
                "{}:{}: `{name}` spans {lines} lines",
                self.file.display(),
                span.start().line
            ));
        }
    }
}

impl<'ast> Visit<'ast> for Walk {
    fn visit_item_mod(&mut self, item: &'ast syn::ItemMod) {
        if is_test(&item.attrs) {
            return;
        }
        if item.content.is_none() {
            self.children.push(item.ident.to_string());
        }
        syn::visit::visit_item_mod(self, item);
    }

    fn visit_item_fn(&mut self, item: &'ast syn::ItemFn) {
        use syn::spanned::Spanned;
        self.measure(&item.sig.ident, &item.attrs, item.span());
        syn::visit::visit_item_fn(self, item);
    }

    fn visit_impl_item_fn(&mut self, item: &'ast syn::ImplItemFn) {
        use syn::spanned::Spanned;
        self.measure(&item.sig.ident, &item.attrs, item.span());
        syn::visit::visit_impl_item_fn(self, item);
    }

    fn visit_trait_item_fn(&mut self, item: &'ast syn::TraitItemFn) {
        use syn::spanned::Spanned;
        self.measure(&item.sig.ident, &item.attrs, item.span());
        syn::visit::visit_trait_item_fn(self, item);
    }
}

/// The long functions of the crate whose root is `root`, and how many
/// files were read.
fn long_functions(root: &Path) -> (Vec<String>, usize) {
    let mut pending = vec![(root.to_path_buf(), true)];
    let (mut long, mut files) = (Vec::new(), 0);
    while let Some((file, owns_folder)) = pending.pop() {
        let text =
            std::fs::read_to_string(&file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        let ast = syn::parse_file(&text).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        let mut walk = Walk {
            file: file.clone(),
            long: Vec::new(),
            children: Vec::new(),
        };
        walk.visit_file(&ast);
        files += 1;
        long.append(&mut walk.long);
        // `lib.rs`, `main.rs` and `mod.rs` own their folder; `a.rs` owns
        // `a/`.
        let folder = if owns_folder {
            file.parent().expect("a file in a folder").to_path_buf()
        } else {
            file.with_extension("")
        };
        for child in walk.children {
            let flat = folder.join(format!("{child}.rs"));
            if flat.exists() {
                pending.push((flat, false));
            } else {
                pending.push((folder.join(&child).join("mod.rs"), true));
            }
        }
    }
    (long, files)
}

#[test]
fn no_function_of_ours_is_over_150_lines() {
    let base = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut long = Vec::new();
    let mut files = 0;
    for root in ROOTS {
        let (found, read) = long_functions(&base.join(root));
        long.extend(
            found
                .into_iter()
                .map(|l| l.replacen(&format!("{}/", base.display()), "", 1)),
        );
        files += read;
    }
    // The walk follows every module: the runtime alone has some 90 files.
    assert!(files >= 150, "only {files} files read");
    assert!(
        long.is_empty(),
        "over {LONGEST} lines:\n{}",
        long.join("\n")
    );
}

#[test]
fn a_long_function_is_found() {
    // The walk's measure, on a function of 151 lines and one of 150.
    let body = |n: usize| "    let _ = 0;\n".repeat(n - 2);
    let text = format!(
        "fn long() {{\n{}}}\nfn short() {{\n{}}}\n#[cfg(test)]\nmod t {{ fn long_test() {{\n{}}} }}\n",
        body(151),
        body(150),
        body(200)
    );
    let ast = syn::parse_file(&text).expect("parses");
    let mut walk = Walk {
        file: PathBuf::from("toy.rs"),
        long: Vec::new(),
        children: Vec::new(),
    };
    walk.visit_file(&ast);
    assert_eq!(
        walk.long,
        vec!["toy.rs:1: `long` spans 151 lines".to_string()]
    );
}
