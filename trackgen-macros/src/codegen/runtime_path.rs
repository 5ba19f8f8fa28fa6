//! The one path generated code reaches the runtime by: every kernel and
//! type it names is `::trackgen::__private::…` (the runtime's `__private`
//! holds exactly those).

use proc_macro2::TokenStream;
use quote::quote;

/// `::trackgen::__private`.
pub fn runtime() -> TokenStream {
    quote!(::trackgen::__private)
}
