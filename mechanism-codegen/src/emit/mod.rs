//! Stage 6, emit: straight-line Rust for one mechanism. Only what the scene asks
//! for is generated: no velocity code in a position-only scene, no `atan2`
//! unless a link angle is an output, and fixed points and guides pass `None`
//! so that their terms vanish at compile time.
//!
//! One file per generated item family: `solution` (the mechanism's struct,
//! its inputs, `solve`), `position`, `rates` (velocity and acceleration),
//! [`forces`], [`batch`], [`check_fn`] (`check()`), [`self_test`]; [`stub`] on
//! error. `names` holds the names and small helpers they share.
//!
//! The fields the position, velocity and acceleration structs keep beside
//! the outputs are those the other generated code reads: each emitter
//! records its reads as it writes them (`kinds::reads::Reads`), and the
//! structs are built last.

pub mod batch;
pub mod check_fn;
pub mod describe;
mod display;
pub mod dynamics;
pub mod forces;
mod interop;
pub mod krate;
mod names;
mod position;
mod rates;
pub mod self_test;
mod solution;
pub mod stub;
mod stub_fields;

use crate::check::Findings;
use crate::kinds::{self, Known};
use crate::model::{Level, Model};
use crate::plan::Plan;
use kinds::reads::Reads;
pub(crate) use names::{allow_literal_lints, tag};
use names::{Generated, TypeNames};
use proc_macro2::TokenStream;
use quote::quote;
use rates::Rate;

/// Expands a valid, planned and checked model: the mechanism's items, its
/// `check()`, the expansion-time check's warnings and, with `#[self_test]`,
/// its tests.
pub fn mechanism(model: &Model, plan: &Plan, findings: &Findings) -> TokenStream {
    // The position struct keeps, among others, the fields these read
    // (`pos.NAME`), recorded as they are emitted.
    let reads = Reads::default();
    let check = check_fn::emit_check(model, plan, &findings.summary, &reads);
    let self_tests = model
        .self_test
        .map(|_| self_test::emit(model, plan, findings, &reads));
    let readers: Vec<&TokenStream> = std::iter::once(&check.method)
        .chain(self_tests.as_ref())
        .collect();
    let mut out = items(model, plan, &findings.known, &reads, &readers);
    let name = &model.name;
    let allow_lints = allow_literal_lints();
    let (check_items, check) = (check.items, check.method);
    out.extend(quote! {
        #check_items
        #allow_lints
        impl<T: ::mechanism::Real> #name<T> { #check }
    });
    out.extend(describe::emit(model, plan));
    out.extend(findings.warnings.clone());
    out.extend(self_tests);
    out
}

/// The mechanism's structs and analyses. `reads`: the reads recorded by the
/// other generated code that reads position fields (the run-time `check()`
/// and the `#[self_test]` tests, whose code is `readers`); with the later
/// analyses' own reads they decide which fields the position, velocity and
/// acceleration structs keep ([`kinds::reads`]). `known`: what the check
/// found that the position code reads.
fn items(
    model: &Model,
    plan: &Plan,
    known: &Known,
    reads: &Reads,
    readers: &[&TokenStream],
) -> TokenStream {
    let em = position::Emitter::new(model, plan, known, false);
    let moving = plan.moving_points(model);
    let inputs = names::input_names(model);
    let position = em.code();
    // The later analyses, generated first: the hidden fields of the
    // position, velocity and acceleration structs are only those a later
    // analysis (or `check()`, or the self-tests) reads (`pos.NAME`,
    // `vel.NAME`, `acc.NAME`, recorded in `reads`); the rest are locals and
    // never stored.
    let level = model.level;
    let forces = (level >= Level::Forces).then(|| forces::emit(model, plan, &moving, reads));
    let dynamics = forces
        .as_ref()
        .filter(|_| level >= Level::Dynamics)
        .map(|f| dynamics::emit(model, plan, &moving, &f.loads_param, reads));
    let accel = (level >= Level::Acceleration)
        .then(|| rates::code(model, plan, &moving, Rate::Acceleration, reads));
    let vel = (level >= Level::Velocity)
        .then(|| rates::code(model, plan, &moving, Rate::Velocity, reads));
    let tracking = position::tracking_code(&em, reads);
    // Debug builds: every read in the readers' tokens was recorded, and
    // every recorded read is in them.
    if cfg!(debug_assertions) {
        let (unrecorded, unwritten) = reads.mismatch(
            readers
                .iter()
                .copied()
                .chain(vel.iter().chain(&accel).map(|r| &r.code))
                .chain(forces.iter().map(|f| &f.methods))
                .chain(dynamics.iter().map(|d| &d.methods))
                .chain(&tracking),
        );
        assert!(
            unrecorded.is_empty() && unwritten.is_empty(),
            "reads written into tokens without `kinds::reads::Reads`: {unrecorded:?}; recorded reads in no emitted code: {unwritten:?}"
        );
    }

    let mut out = solution::own_items(model, plan, &inputs);
    out.push(position::items(
        &em,
        &position,
        tracking.as_ref(),
        reads,
        &inputs,
    ));
    if let Some(vel) = vel {
        out.push(rates::velocity_items(model, plan, vel, reads));
    }
    if let Some(accel) = accel {
        if let Some(f) = &forces {
            out.push(Generated {
                items: f.items.clone(),
                methods: f.methods.clone(),
            });
        }
        if let Some(d) = dynamics {
            out.push(Generated {
                items: d.items,
                methods: d.methods,
            });
        }
        out.push(rates::acceleration_items(model, plan, accel, reads));
        out.push(solution::solve_items(model, forces.as_ref()));
    }
    // `Display` of the result structs, and what the definition's derives ask for.
    let force_fields = forces.as_ref().map(|f| f.fields.as_slice());
    out.items.extend(display::emit(model, plan, force_fields));
    out.items.extend(interop::emit(model, plan, force_fields));
    // Batch API (structure of arrays, issue 5): see `batch`.
    out.items.extend(batch::emit(
        model,
        plan,
        &inputs,
        &position.outputs,
        force_fields,
    ));
    let Generated { items, methods } = out;
    let name = TypeNames::of(model).name;
    let allow_lints = allow_literal_lints();
    quote! {
        #items
        #allow_lints
        impl<T: ::mechanism::Real> #name<T> {
            #methods
        }
    }
}

/// Definitions planned as `expand` plans them, for the emitters' unit tests.
#[cfg(test)]
mod test_support {
    use crate::diag::Diagnostics;
    use crate::model::Model;
    use crate::plan::Plan;
    use proc_macro2::TokenStream;

    /// The four-bar of seed 002 (mm) with a coupler point `P`, and `scene`
    /// (analysis, outputs, masses...) appended.
    pub fn four_bar(scene: &str) -> String {
        format!(
            "pub FourBar {{
                params {{ ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }}
                let O2 = ground(0.0, 0.0);
                let O4 = ground(ground, 0.0);
                let A = crank(O2, crank, theta2) as link2;
                let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
                let P = point(link3, from A, 120.0, 30 deg);
                {scene}
            }}"
        )
    }

    /// The model and plan of a valid definition `src`.
    pub fn planned(src: &str) -> (Model, Plan) {
        let definition: crate::parse::Definition = syn::parse_str(src).expect("parses");
        let mut diag = Diagnostics::new();
        let model = crate::model::lower(definition, &mut diag);
        crate::validate::model(&model, &mut diag);
        let plan = crate::plan::plan(&model, &mut diag);
        let errors: Vec<String> = diag.finish().iter().map(|e| e.to_string()).collect();
        assert!(errors.is_empty(), "{errors:?}");
        (model, plan.expect("a plan"))
    }

    /// `code` as text without whitespace, for searching.
    pub fn flat(code: &TokenStream) -> String {
        code.to_string().split_whitespace().collect()
    }
}

#[cfg(test)]
mod tests {
    use super::test_support::{flat, four_bar};
    use proc_macro2::TokenStream;
    use std::str::FromStr;

    /// The expansion of a valid definition, without whitespace.
    fn expand(src: &str) -> String {
        let code = flat(&crate::expand(TokenStream::from_str(src).unwrap()));
        assert!(!code.contains("compile_error"), "{code}");
        code
    }

    // Proves a scene gets only the item families it asks for: a position-only
    // definition has no velocity, acceleration, solution or forces items, a
    // velocity one stops before accelerations, and only a mass asks for forces.
    #[test]
    fn each_analysis_level_emits_only_its_own_items() {
        let position = expand(&four_bar("analysis position;"));
        assert!(position.contains("structFourBarPosition") && position.contains("fnposition("));
        for absent in [
            "FourBarVelocity",
            "fnvelocity(",
            "FourBarAcceleration",
            "fnsolve(",
        ] {
            assert!(
                !position.contains(absent),
                "{absent} in a position-only expansion"
            );
        }
        let velocity = expand(&four_bar("analysis velocity;"));
        assert!(velocity.contains("structFourBarVelocity") && velocity.contains("fnvelocity("));
        assert!(!velocity.contains("FourBarAcceleration") && !velocity.contains("fnsolve("));
        let full = expand(&four_bar(""));
        assert!(full.contains("structFourBarSolution") && full.contains("fnsolve("));
        assert!(!full.contains("FourBarForces"));
        let forces = expand(&four_bar("mass link3 { m = 2.0, at = P };"));
        assert!(
            forces.contains("structFourBarForces") && forces.contains("forces:FourBarForces<T>")
        );
    }

    // Proves the mechanism's methods come in the order position, velocity,
    // forces, acceleration, solve (the order the snapshots fix), all in one impl.
    #[test]
    fn methods_in_one_impl_in_analysis_order() {
        let code = expand(&four_bar("mass link3 { m = 2.0, at = P };"));
        let at = |s: &str| code.find(s).unwrap_or_else(|| panic!("{s} missing"));
        let order = [
            "pubfnposition(",
            "pubfnvelocity(",
            "pubfnforces(",
            "pubfnacceleration(",
            "pubfnsolve(",
        ];
        for pair in order.windows(2) {
            assert!(at(pair[0]) < at(pair[1]), "{} after {}", pair[0], pair[1]);
        }
    }
}
