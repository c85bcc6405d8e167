//! The `mechanism!` procedural macro. All the work is in `mechanism-codegen`,
//! a plain library that can be unit- and snapshot-tested.
use proc_macro::TokenStream;

/// Generates specialized position, velocity, acceleration and force analysis
/// for one planar mechanism. See `docs/dsl.md` for the language.
#[proc_macro]
pub fn mechanism(input: TokenStream) -> TokenStream {
    mechanism_codegen::expand(input.into()).into()
}
