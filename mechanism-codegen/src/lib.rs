//! Code generation for `mechanism!`, as a plain library so it can be unit- and
//! snapshot-tested: [`parse`] -> [`model`] -> [`validate`] -> [`plan`] ->
//! [`check`] (the mechanism assembled over its input range at expansion time)
//! -> [`emit`] (with [`self_test`], the generated tests of `#[self_test]`).
//!
//! Errors are accumulated across stages and reported together, each on the
//! user's token; on error, stub items with the real names keep the user's own
//! code free of follow-on errors.

pub mod batch;
pub mod check;
pub mod emit;
pub mod kinetostatics;
pub mod model;
pub mod parse;
pub mod plan;
pub mod self_test;
pub mod validate;
pub mod value;

use proc_macro2::TokenStream;

/// Expands a mechanism definition into Rust items.
pub fn expand(input: TokenStream) -> TokenStream {
    let definition = match parse::definition(input) {
        Ok(d) => d,
        Err(e) => return e.to_compile_error(),
    };
    let kinds_failed = definition.items.iter().any(|item| match item {
        parse::Item::Let(l) => !model::KINDS.contains(&l.kind.to_string().as_str()),
        _ => false,
    });
    let (model, mut errors) = model::lower(definition);
    validate::unique_names(&model, &mut errors);
    validate::reserved_names(&model, &mut errors);
    validate::references_resolve(&model, &mut errors);
    validate::has_driver(&model, kinds_failed, &mut errors);
    validate::dof_matches(&model, &mut errors);
    validate::outputs_exist(&model, &mut errors);
    validate::rpp_slot_crosses_guide(&model, &mut errors);
    let inputs = check::inputs(&model, &mut errors);
    let allowed = check::allowances(&model, &mut errors);
    if !errors.0.is_empty() {
        return emit::emit_stub(&model, errors.0);
    }
    let plan = match plan::plan(&model) {
        Ok(p) => p,
        Err(e) => return emit::emit_stub(&model, e),
    };
    validate::geometry_consistent(&model, &plan, &mut errors);
    validate::kinetics_consistent(&model, &plan, &mut errors);
    if !errors.0.is_empty() {
        return emit::emit_stub(&model, errors.0);
    }
    let mut findings = check::expansion_check(&model, &plan, &inputs, &allowed);
    let mut errors = std::mem::take(&mut findings.errors);
    if let Some(span) = model.checks.self_test {
        if let Some(e) = self_test::requirements(&model, &inputs, span) {
            errors.push(e);
        }
    }
    if !errors.is_empty() {
        return emit::emit_stub(&model, errors);
    }
    let check = check::emit_check(&model, &plan, &inputs, &findings.summary);
    let self_tests = model
        .checks
        .self_test
        .map(|_| self_test::emit(&model, &plan, &inputs, &allowed, &findings));
    // The position struct keeps the fields these read (`pos.NAME`).
    let readers = format!(
        "{} {}",
        check,
        self_tests
            .as_ref()
            .map(|t| t.to_string())
            .unwrap_or_default()
    );
    let mut out = emit::emit(&model, &plan, &readers);
    let name = &model.name;
    let allow_lints = emit::allow_literal_lints();
    out.extend(quote::quote! {
        #allow_lints
        impl<T: ::mechanism::Real> #name<T> { #check }
    });
    out.extend(findings.warnings.clone());
    out.extend(self_tests);
    out
}
