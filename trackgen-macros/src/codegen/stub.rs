//! After an error: a unit struct for every name that parsed, so code that
//! mentions the type reports nothing more than the real error.

use proc_macro2::TokenStream;
use quote::quote;
use syn::{Ident, Visibility};

pub fn stubs(names: &[(Visibility, Ident)]) -> TokenStream {
    names
        .iter()
        .map(|(vis, name)| {
            quote! {
                #[allow(dead_code)]
                #vis struct #name;
            }
        })
        .collect()
}
