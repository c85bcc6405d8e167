//! Code generation for `mechanism!`, as a plain library so it can be unit- and
//! snapshot-tested. The pipeline, in stage order (each stage reads only the
//! ones before it):
//!
//! [`parse`] (tokens to syntax) -> [`model`] (typed statements, inputs and
//! their ranges) -> `kinds` (what each statement kind means, one module per
//! kind, read by every later stage) -> [`validate`] (one rule per function)
//! -> [`plan`] (solve order, owners, what each analysis needs) -> `slots`
//! (the plan's names laid out in flat storage, for the compiled position
//! walk) -> [`check`] (the mechanism assembled over its input range at
//! expansion time, walking the compiled steps) ->
//! [`emit`] (the generated items, one file per family).
//!
//! Errors from every stage go to one [`diag::Diagnostics`] and are reported
//! together, sorted by position, each on the user's token; on error, stub
//! items with the real names keep the user's own code free of follow-on
//! errors.

pub mod check;
pub mod diag;
pub mod emit;
pub mod keys;
pub(crate) mod kinds;
pub mod model;
pub mod names;
pub mod parse;
pub mod plan;
pub mod runtime;
pub(crate) mod slots;
pub mod validate;
pub mod value;

use proc_macro2::TokenStream;

/// Expands a mechanism definition into Rust items.
pub fn expand(input: TokenStream) -> TokenStream {
    let definition = match parse::definition(input) {
        Ok(d) => d,
        Err(e) => return e.to_compile_error(),
    };
    let krate = definition.krate.clone();
    let code = expand_definition(definition);
    match &krate {
        Some(path) => emit::krate::rename(code, path),
        None => code,
    }
}

/// The pipeline on a parsed definition, every path to the facade written
/// `::mechanism`.
fn expand_definition(definition: parse::Definition) -> TokenStream {
    let mut diag = diag::Diagnostics::new();
    let model = model::lower(definition, &mut diag);
    validate::model(&model, &mut diag);
    let plan = plan::plan(&model, &mut diag);
    if let Some(plan) = &plan {
        validate::planned(&model, plan, &mut diag);
    }
    let plan = match plan {
        Some(plan) if diag.is_empty() => plan,
        _ => return emit::stub::emit(&model, diag.finish()),
    };
    let findings = check::expansion_check(&model, &plan, &mut diag);
    check::modes::other_modes(&model, &plan, &mut diag);
    if !diag.is_empty() {
        return emit::stub::emit(&model, diag.finish());
    }
    diag.finish();
    emit::mechanism(&model, &plan, &findings)
}
