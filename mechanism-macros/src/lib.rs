//! The `mechanism!` procedural macro of the `planar-mechanism` package. All the
//! work is in `mechanism-codegen`, a plain library that can be unit- and
//! snapshot-tested.
//!
//! The generated code refers to `::mechanism::` (the library of
//! `planar-mechanism`): depend on that package and write
//! `use mechanism::mechanism;`. The language reference is on the page of
//! [`mechanism!`].
use proc_macro::TokenStream;

/// Generates specialized position, velocity, acceleration and force analysis
/// for one planar mechanism (the language reference follows; the files it
/// names, such as `checks.md` or `tests/ui/`, are in the repository's `docs/`
/// folder or at its root).
///
#[doc = include_str!(concat!(env!("OUT_DIR"), "/dsl.md"))]
#[proc_macro]
pub fn mechanism(input: TokenStream) -> TokenStream {
    mechanism_codegen::expand(input.into()).into()
}
