//! Shallow scopes for straight-line bodies.
//!
//! Every `let` opens a scope that lasts to the end of its block, so a body
//! of `k` successive `let`s nests `k` deep, and with debuginfo each scope
//! is a DWARF lexical block that LLVM builds recursively: at 512 links
//! (thousands of nested `let`s in `equations_of_motion`) rustc's
//! code-generation thread overflowed its stack and the build crashed.
//! [`shallow_scopes`] groups each run of up to 64 successive `let`s into one,
//!
//! ```text
//! let (a, b, …) = { let a = …; let b = …; …; (a, b, …) };
//! ```
//!
//! whose inner scopes close at the group's end: the nesting is at most 64
//! plus the number of groups, and the code means exactly what it meant
//! (the same statements in the same order, each name exported once). A
//! block of at most 256 `let`s (a track of up to about 30 links) is left as
//! it is, easier to read and as quick to build.

use std::collections::HashSet;

use proc_macro2::{Delimiter, Group, Ident, Spacing, TokenStream, TokenTree};
use quote::quote;

/// The most `let`s in one group.
const PER_GROUP: usize = 64;

/// Blocks with more `let`s than this are grouped.
const UNGROUPED: usize = 256;

/// Rewrites the statements of a block body, and of the statement-level
/// blocks in it, each on its own: runs of successive `let`s whose pattern
/// is a name or a tuple of names become groups (see the module docs). A
/// group ends before a `let` that would bind a name it binds already.
pub fn shallow_scopes(body: TokenStream) -> TokenStream {
    group(body, UNGROUPED)
}

/// [`shallow_scopes`], grouping blocks of more than `ungrouped` `let`s.
fn group(body: TokenStream, ungrouped: usize) -> TokenStream {
    let tokens: Vec<TokenTree> = body.into_iter().collect();
    let lets = tokens
        .iter()
        .filter(|t| matches!(t, TokenTree::Ident(kw) if kw == "let"))
        .count();
    let group_size = if lets > ungrouped { PER_GROUP } else { 1 };
    let mut out = TokenStream::new();
    let mut run = Run::default();
    let mut i = 0;
    while i < tokens.len() {
        match &tokens[i] {
            TokenTree::Group(g) if g.delimiter() == Delimiter::Brace => {
                run.flush(&mut out);
                let mut block = Group::new(Delimiter::Brace, group(g.stream(), ungrouped));
                block.set_span(g.span());
                out.extend([TokenTree::Group(block)]);
                i += 1;
            }
            TokenTree::Ident(kw) if kw == "let" => {
                let end = statement_end(&tokens, i);
                let statement = &tokens[i..=end];
                match simple_binding(&statement[1..]) {
                    Some(names) => {
                        let unique = {
                            let mut new = HashSet::new();
                            names.iter().all(|n| {
                                let n = n.to_string();
                                !run.bound.contains(&n) && new.insert(n)
                            })
                        };
                        if !unique || run.lets == group_size {
                            run.flush(&mut out);
                        }
                        run.push(statement, names);
                    }
                    None => {
                        run.flush(&mut out);
                        out.extend(statement.iter().cloned());
                    }
                }
                i = end + 1;
            }
            _ => {
                run.flush(&mut out);
                let end = statement_end(&tokens, i);
                out.extend(tokens[i..=end].iter().cloned());
                i = end + 1;
            }
        }
    }
    run.flush(&mut out);
    out
}

/// A run of `let`s being grouped.
#[derive(Default)]
struct Run {
    statements: TokenStream,
    names: Vec<Ident>,
    bound: HashSet<String>,
    lets: usize,
}

impl Run {
    fn push(&mut self, statement: &[TokenTree], names: Vec<Ident>) {
        self.statements.extend(statement.iter().cloned());
        self.bound.extend(names.iter().map(|n| n.to_string()));
        self.names.extend(names);
        self.lets += 1;
    }

    /// Emits the run: as it is if it is a single `let`, else as a group.
    fn flush(&mut self, out: &mut TokenStream) {
        let run = std::mem::take(self);
        match run.lets {
            0 => {}
            1 => out.extend(run.statements),
            _ => {
                let (statements, names) = (run.statements, run.names);
                out.extend(quote! {
                    let (#(#names),*) = { #statements (#(#names),*) };
                });
            }
        }
    }
}

/// The index of the `;` that ends the statement starting at `start` (or
/// the last index, for a tail expression).
fn statement_end(tokens: &[TokenTree], start: usize) -> usize {
    tokens[start..]
        .iter()
        .position(|t| matches!(t, TokenTree::Punct(p) if p.as_char() == ';'))
        .map_or(tokens.len() - 1, |p| start + p)
}

/// The names a `let` statement (after `let`, up to `;`) binds, if its
/// pattern is `name` or `(name, name, …)` followed by a lone `=`.
fn simple_binding(statement: &[TokenTree]) -> Option<Vec<Ident>> {
    let is_assign = |t: Option<&TokenTree>| matches!(t, Some(TokenTree::Punct(p)) if p.as_char() == '=' && p.spacing() == Spacing::Alone);
    if !is_assign(statement.get(1)) {
        return None;
    }
    match &statement[0] {
        TokenTree::Ident(name) if !is_keyword(name) => Some(vec![name.clone()]),
        TokenTree::Group(g) if g.delimiter() == Delimiter::Parenthesis => {
            let mut names = Vec::new();
            for (k, t) in g.stream().into_iter().enumerate() {
                match t {
                    TokenTree::Ident(name) if k % 2 == 0 && !is_keyword(&name) => names.push(name),
                    TokenTree::Punct(p) if k % 2 == 1 && p.as_char() == ',' => {}
                    _ => return None,
                }
            }
            (!names.is_empty()).then_some(names)
        }
        _ => None,
    }
}

fn is_keyword(name: &Ident) -> bool {
    matches!(name.to_string().as_str(), "mut" | "ref" | "_")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Grouping every block, however short.
    fn flat(body: TokenStream) -> String {
        group(body, 0).to_string()
    }

    fn lets(n: usize) -> TokenStream {
        let lets = (0..n).map(|k| {
            let name = quote::format_ident!("v_{}", k);
            quote!(let #name = #k;)
        });
        quote!(#(#lets)*)
    }

    /// `let`s outside any group or block.
    fn outer_lets(body: TokenStream) -> usize {
        body.into_iter()
            .filter(|t| matches!(t, TokenTree::Ident(i) if i == "let"))
            .count()
    }

    #[test]
    fn only_long_blocks_are_grouped() {
        assert_eq!(shallow_scopes(lets(256)).to_string(), lets(256).to_string());
        assert_eq!(outer_lets(shallow_scopes(lets(257))), 5);
    }

    #[test]
    fn successive_lets_are_grouped() {
        let got = flat(quote! {
            let (s_1, c_1) = q[2].sin_cos();
            let rx_1 = q[0];
            let rx_2 = rx_1 + 0.5 * c_1;
            out[0] = rx_2;
        });
        let want = quote! {
            let (s_1, c_1, rx_1, rx_2) = {
                let (s_1, c_1) = q[2].sin_cos();
                let rx_1 = q[0];
                let rx_2 = rx_1 + 0.5 * c_1;
                (s_1, c_1, rx_1, rx_2)
            };
            out[0] = rx_2;
        };
        assert_eq!(got, want.to_string());
    }

    #[test]
    fn typed_mutable_and_rebinding_lets_end_a_group() {
        let got = flat(quote! {
            let loads: &[f64] = if loads.is_empty() { &none } else { loads };
            let mut out = 0.0;
            let x = 1.0;
            let x = x + 1.0;
            let y = y * 2.0;
            let _ = x;
        });
        let want = quote! {
            let loads: &[f64] = if loads.is_empty() { &none } else { loads };
            let mut out = 0.0;
            let x = 1.0;
            let (x, y) = { let x = x + 1.0; let y = y * 2.0; (x, y) };
            let _ = x;
        };
        assert_eq!(got, want.to_string());
    }

    #[test]
    fn blocks_are_flattened_on_their_own_and_tails_kept() {
        let got = flat(quote! {
            let a = 1.0;
            let b = 2.0;
            { let out = mass; let c = a; out[0] = c; }
            a + b
        });
        let want = quote! {
            let (a, b) = { let a = 1.0; let b = 2.0; (a, b) };
            { let (out, c) = { let out = mass; let c = a; (out, c) }; out[0] = c; }
            a + b
        };
        assert_eq!(got, want.to_string());
    }

    #[test]
    fn groups_hold_64_lets() {
        assert_eq!(outer_lets(group(lets(130), 0)), 3);
    }
}
