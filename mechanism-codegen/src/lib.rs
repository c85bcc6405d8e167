//! Code generation for `mechanism!`: parse -> model -> validate -> plan -> emit.
use proc_macro2::TokenStream;

/// Expands a mechanism definition.
pub fn expand(input: TokenStream) -> TokenStream {
    let _ = input;
    TokenStream::new()
}
