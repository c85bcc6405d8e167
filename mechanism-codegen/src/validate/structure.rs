//! The rules on the mechanism as a whole: a driver, the declared mobility,
//! the outputs, an RPP's slot, and what `#[self_test]` needs.

use super::names::{is_named_link, link_hints, symbols, Category};
use crate::diag::{did_you_mean, Diagnostics};
use crate::kinds;
use crate::model::{Input, Model};
use proc_macro2::Span;

/// Rule: at least one driver, unless a statement's kind was already rejected
/// (it may have been meant as the driver: no cascade).
pub(super) fn has_driver(model: &Model, errors: &mut Diagnostics) {
    if model.unknown_kinds
        || !model.failed.is_empty()
        || model.stmts.iter().any(|s| s.kind.is_driver())
    {
        return;
    }
    errors.push(
        model.name.span(),
        format!(
            "`{}` has no driver, so nothing moves; add one, e.g. `let A = crank(O, radius, theta) as link2;`, a `slider(...)` or an `actuator(...)`",
            model.name
        ),
    );
}

/// Rule: a declared `dof N` matches Gruebler's count of the links and joints the
/// statements create (each driver adds one degree of freedom, each class II
/// group none), i.e. the number of inputs.
pub(super) fn dof_matches(model: &Model, errors: &mut Diagnostics) {
    let Some(declared) = &model.dof else { return };
    if !model.failed.is_empty() {
        return; // a rejected statement would make the count meaningless
    }
    let Ok(n) = declared.base10_parse::<i64>() else {
        errors.push(declared.span(), "`dof` takes a whole number");
        return;
    };
    let (mut links, mut joints, mut higher) = (1i64, 0i64, 0i64);
    let mut inputs = Vec::new();
    for stmt in &model.stmts {
        let (bodies, pairs, meshes) = kinds::of(stmt).bodies_and_pairs();
        links += bodies;
        joints += pairs;
        higher += meshes;
        inputs.extend(stmt.kind.inputs().iter().map(ToString::to_string));
    }
    let mobility = 3 * (links - 1) - 2 * joints - higher;
    let meshes = if higher > 0 {
        format!(" - {higher}")
    } else {
        String::new()
    };
    if mobility != n {
        errors.push(
            declared.span(),
            format!(
                "the mechanism has {} (Gruebler: 3*({links}-1) - 2*{joints}{meshes} = {mobility}) for {} [{}], but `dof {n}` is declared; add or remove a driver, or correct `dof`",
                crate::diag::counted(mobility, "degree of freedom", "degrees of freedom"),
                crate::diag::counted(inputs.len() as i64, "input", "inputs"),
                inputs.join(", ")
            ),
        );
    }
}

/// Rule: every requested output is a point, a named link or a slide.
pub(super) fn outputs_exist(model: &Model, errors: &mut Diagnostics) {
    let Some(outputs) = &model.outputs else {
        return;
    };
    let table = symbols(model);
    let mut listed: Vec<String> = Vec::new();
    for o in outputs {
        let name = o.to_string();
        if listed.contains(&name) {
            errors.push(
                o.span(),
                format!("`{name}` is listed twice in `outputs`; remove this one"),
            );
            continue;
        }
        listed.push(name.clone());
        match table.get(&name) {
            Some((Category::Point | Category::Link | Category::Slide, _)) => {}
            Some((cat, _)) => errors.push(
                o.span(),
                format!(
                    "this definition cannot give `{name}` as an output: it is {}; outputs are points, links (their angles and rates) and slide displacements",
                    cat.article()
                ),
            ),
            None => {
                let candidates = table
                    .iter()
                    .filter(|(n, (c, _))| match c {
                        Category::Point | Category::Slide => true,
                        Category::Link => is_named_link(model, n),
                        _ => false,
                    })
                    .map(|(n, _)| n.as_str());
                errors.push(
                    o.span(),
                    format!(
                        "this definition cannot give `{name}`: no point, link or slide has that name{}",
                        link_hints(model, did_you_mean(&name, candidates))
                    ),
                );
            }
        }
    }
}

/// Rule: each kind's own rules on its arguments (an RPP's slot crosses its
/// guide), as its `kinds` module states them.
pub(super) fn kind_rules(model: &Model, errors: &mut Diagnostics) {
    for stmt in &model.stmts {
        kinds::of(stmt).check(errors);
    }
}

/// Rule: each kind's own rules on the inputs it names (a triad's pose is
/// given at a value of one of the inputs).
pub(super) fn kind_input_rules(model: &Model, errors: &mut Diagnostics) {
    for stmt in &model.stmts {
        kinds::of(stmt).check_inputs(&model.inputs, errors);
    }
}

/// `#[self_test]` sweeps the input range: every input needs one, and there
/// are at most two inputs.
pub(super) fn self_test_sweepable(model: &Model, errors: &mut Diagnostics) {
    if let Some(span) = model.self_test {
        errors.extend(self_test_requirements(&model.inputs, span));
    }
}

/// The error when `#[self_test]` cannot run (an input without a range).
fn self_test_requirements(inputs: &[Input], span: Span) -> Option<syn::Error> {
    // A declared range that was rejected is reported already.
    let missing: Vec<String> = inputs
        .iter()
        .filter(|i| i.range.is_none() && !i.declared)
        .map(|i| format!("`{}`", i.name))
        .collect();
    if !missing.is_empty() {
        return Some(syn::Error::new(
            span,
            format!(
                "`#[self_test]` tests the mechanism over its input range, and {} has none: declare it, e.g. `range {} = (0.0, 0.1);` (sliders and actuators have no default range)",
                missing.join(", "),
                inputs.iter().find(|i| i.range.is_none() && !i.declared).map(|i| i.name.to_string()).unwrap_or_default()
            ),
        ));
    }
    if inputs.len() > 2 {
        return Some(syn::Error::new(
            span,
            "`#[self_test]` sweeps one or two inputs; this mechanism has more",
        ));
    }
    // Two inputs are swept (and `check()` generated) over a declared box
    // only: a crank's default full turn does not count (`check::emit_check`).
    if inputs.len() == 2 {
        if let Some(i) = inputs.iter().find(|i| !i.declared) {
            return Some(syn::Error::new(
                span,
                format!(
                    "`#[self_test]` sweeps the box of a two-input mechanism's declared ranges, and `{0}` has none (a crank's default full turn is used only when it is the only input): declare it, e.g. `range {0} = (0 deg, 360 deg);`",
                    i.name
                ),
            ));
        }
    }
    None
}
