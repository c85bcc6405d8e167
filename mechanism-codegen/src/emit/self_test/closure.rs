//! The loop-closure tests: every constraint of every group the position
//! analysis solves, written here from the definition (not from the generated
//! position code) as a residual recomputed from the solved points.

use super::Context;
use crate::keys::LinkName;
use crate::kinds;
use crate::kinds::closure::{Residual, Residuals};
use crate::kinds::reads::Reads;
use crate::model::{Model, Stmt};
use crate::plan::Plan;
use crate::value::Value;
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

/// A value with run-time parameters at their defaults (`None` for a load).
fn with_defaults(model: &Model, v: &Value) -> Option<f64> {
    v.eval_with(&|p| model.params.iter().find(|(n, _)| n == p).map(|(_, x)| *x))
}

/// Residuals of one statement's constraints (lengths in the definition's
/// unit), as its kind writes them; a link's axis comes from the kind that
/// creates the link.
/// `reads` records their reads of the position struct.
fn residuals(model: &Model, plan: &Plan, stmt: &Stmt, reads: &Reads) -> Vec<Residual> {
    let mut r = Residuals::new(&stmt.name, reads);
    let link_axis = |link: &Ident| {
        let info = &plan.links[&LinkName::of(link)];
        kinds::of(&model.stmts[info.stmt]).closure_axis(info.index, reads)
    };
    kinds::of(stmt).residuals(&mut r, &link_axis);
    r.list
}

/// Every constraint of every solved statement, in solve order, as the
/// generated module uses them.
pub(super) struct Constraints {
    /// Failure-message labels (`LABELS`).
    pub labels: Vec<String>,
    /// Residual codes (`self_test_residuals`).
    pub codes: Vec<TokenStream>,
    /// Tolerance scales (code, in `loop_closure`).
    pub scales: Vec<TokenStream>,
}

impl Constraints {
    /// The constraints of the statements `position()` solves.
    pub fn new(cx: &Context) -> Self {
        let mut c = Constraints {
            labels: Vec::new(),
            codes: Vec::new(),
            scales: Vec::new(),
        };
        for &i in &cx.checked.order {
            for r in residuals(cx.model, cx.plan, &cx.model.stmts[i], cx.reads) {
                c.labels.push(r.label);
                c.codes.push(r.code);
                c.scales.push(r.scale.emit());
            }
        }
        c
    }

    /// How many constraints (residuals) there are.
    pub fn len(&self) -> usize {
        self.codes.len()
    }
}

/// The shortest link length with the default parameters (positive lengths
/// only; 1 when there is none), for the rounding of link angles.
pub(super) fn shortest_link(cx: &Context) -> f64 {
    let model = cx.model;
    let mut lengths: Vec<f64> = Vec::new();
    for &i in &cx.checked.order {
        for l in kinds::of(&model.stmts[i]).link_lengths() {
            lengths.extend(with_defaults(model, l));
        }
    }
    let l_min = lengths
        .iter()
        .copied()
        .filter(|x| *x > 0.0)
        .fold(f64::INFINITY, f64::min);
    if l_min.is_finite() {
        l_min
    } else {
        1.0
    }
}

/// The generated `loop_closure` tests (f64 and f32).
pub(super) fn tests(cx: &Context, constraints: &Constraints) -> TokenStream {
    let name = cx.name;
    let nres = constraints.len();
    let scales = &constraints.scales;
    quote! {
        /// Every constraint of every group, recomputed from the solved
        /// points, within 64 eps times its scale: the mechanism's size
        /// for a length (each is a few roundings of numbers of that
        /// size), 1 for a guide direction from an angle (a difference of
        /// unit vectors), the size over the shortest link for a direction
        /// turned from a link's axis (recomputed from two solved points).
        /// A group's constraints hold to rounding whatever its
        /// conditioning; errors of its inputs do not enter, its residuals
        /// are measured from them.
        fn loop_closure<T: ::mechanism::Real>() {
            let m = #name::<T>::default();
            let eps = T::eps().as_f64();
            let mut checked = 0usize;
            for s in 0..samples() {
                let q = sample(s);
                let Ok(pos) = m.position(&input(q)) else { continue };
                let r = m.self_test_residuals(&pos);
                let size = size_of(&pos);
                let scale: [f64; #nres] = [#(#scales),*];
                for (j, x) in r.iter().enumerate() {
                    let tol = 64.0 * eps * scale[j];
                    assert!(x.abs() <= tol, "sample {q:?}: {} off by {x:e} (tolerance {tol:e})", LABELS[j]);
                }
                checked += 1;
            }
            assert!(checked > 0, "no sample assembles");
        }
        #[test]
        fn loop_closure_f64() { loop_closure::<f64>(); }
        #[test]
        fn loop_closure_f32() { loop_closure::<f32>(); }
    }
}
