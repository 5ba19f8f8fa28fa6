//! The whole expansion as a plain function on `proc_macro2` tokens.

use proc_macro2::TokenStream;

use crate::{codegen, lower, parse};

/// Expands the contents of `model! { … }`.
pub fn expand(input: TokenStream) -> TokenStream {
    let parsed: parse::Input = match syn::parse2(input) {
        Ok(parsed) => parsed,
        Err(e) => return e.to_compile_error(),
    };
    match lower::lower(parsed) {
        Ok(model) => codegen::generate(&model),
        Err((error, items)) => {
            let mut out = error.to_compile_error();
            out.extend(codegen::stubs(&items));
            out
        }
    }
}
