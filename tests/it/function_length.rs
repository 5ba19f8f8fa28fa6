//! No function in the crates' sources (tests aside) is over
//! [`LONGEST`] lines, and no file over [`LONGEST_FILE`]: a longer one has
//! more than one job. Code inside `quote!` is the generated code's, not a
//! function of ours, and `syn` reads it as a macro's tokens, so it is not
//! counted. Modules under `#[cfg(test)]` and `#[test]` functions are
//! tests, and so are the files such modules declare.

use std::path::{Path, PathBuf};

use syn::visit::Visit;

/// The most lines a function may span, its signature and doc comments
/// included.
const LONGEST: usize = 150;

/// The most lines a source file may have (its tests' files aside).
const LONGEST_FILE: usize = 800;

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

/// What a crate's walk found: its long functions, its long files, and
/// how many files it read.
#[derive(Default)]
struct Survey {
    long: Vec<String>,
    long_files: Vec<String>,
    files: usize,
}

/// The walk of the crate whose root is `root`.
fn survey(root: &Path) -> Survey {
    let mut pending = vec![(root.to_path_buf(), true)];
    let mut found = Survey::default();
    while let Some((file, owns_folder)) = pending.pop() {
        let text =
            std::fs::read_to_string(&file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        let lines = text.lines().count();
        if lines > LONGEST_FILE {
            found
                .long_files
                .push(format!("{}: {lines} lines", file.display()));
        }
        let ast = syn::parse_file(&text).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        let mut walk = Walk {
            file: file.clone(),
            long: Vec::new(),
            children: Vec::new(),
        };
        walk.visit_file(&ast);
        found.files += 1;
        found.long.append(&mut walk.long);
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
    found
}

/// Every crate's walk, the paths relative to the workspace.
fn survey_all() -> Survey {
    let base = Path::new(env!("CARGO_MANIFEST_DIR"));
    let relative = |l: String| l.replacen(&format!("{}/", base.display()), "", 1);
    let mut all = Survey::default();
    for root in ROOTS {
        let found = survey(&base.join(root));
        all.long.extend(found.long.into_iter().map(relative));
        all.long_files
            .extend(found.long_files.into_iter().map(relative));
        all.files += found.files;
    }
    // The walk follows every module: the runtime alone has some 90 files.
    assert!(all.files >= 150, "only {} files read", all.files);
    all
}

#[test]
fn no_function_of_ours_is_over_150_lines() {
    let long = survey_all().long;
    assert!(
        long.is_empty(),
        "over {LONGEST} lines:\n{}",
        long.join("\n")
    );
}

#[test]
fn no_file_of_ours_is_over_800_lines() {
    let long = survey_all().long_files;
    assert!(
        long.is_empty(),
        "over {LONGEST_FILE} lines:\n{}",
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
