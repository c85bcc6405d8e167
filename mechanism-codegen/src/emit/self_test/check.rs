//! The generated `check` test: `check()` with the default parameters finds
//! that every group assembles, and the singular positions the macro found at
//! expansion time (or, when it could not check, only allowed ones).

use super::Context;
use crate::check::Findings;
use crate::model::Allowed;
use proc_macro2::TokenStream;
use quote::quote;

/// Assertions on `report` that the singular positions are those of the
/// expansion-time check: the same count per group and the same first one
/// (to 1e-6 of the range, either way round a full turn).
fn as_at_expansion(findings: &Findings) -> TokenStream {
    let mut rows = Vec::new();
    for (g, list) in &findings.singular {
        let at: Vec<f64> = list.clone();
        let n = at.len() as u32;
        rows.push(quote! {
            assert_eq!(report.groups[#g].singular, #n, "group `{}`: singular positions found at run time {:?}, at expansion time {:?}", report.groups[#g].group, report.groups[#g], [#(#at),*]);
            let first = report.groups[#g].first_singular.map(|a| a[0]).unwrap_or(f64::NAN);
            let expected = [#(#at),*].iter().copied().fold(f64::INFINITY, f64::min);
            assert!(((first - expected).abs() <= 1e-6 * width) || ((first - expected).abs() - width).abs() <= 1e-6 * width, "group `{}`: first singular input {first} at run time, {expected} at expansion time", report.groups[#g].group);
        });
    }
    let found: Vec<usize> = findings.singular.iter().map(|(g, _)| *g).collect();
    quote! {
        let width = ranges_width();
        #(#rows)*
        for (g, r) in report.groups.iter().enumerate() {
            if ![#(#found),*].contains(&g) {
                assert_eq!(r.singular, 0, "group `{}`: singular at run time, not at expansion time: {:?}", r.group, r);
            }
        }
    }
}

/// Assertions on `report` that only the groups `allow singular` names pass
/// through a singular position (when the macro did not check).
fn only_allowed(cx: &Context) -> TokenStream {
    let model = cx.model;
    let allowed_names: Vec<String> = match &model.allowed {
        Allowed::Nothing => vec![],
        Allowed::Every => cx
            .checked
            .groups
            .iter()
            .map(|&i| model.stmts[i].name.to_string())
            .collect(),
        Allowed::Groups(l) => l.clone(),
    };
    quote! {
        for r in report.groups.iter() {
            assert!(r.singular == 0 || [#(#allowed_names),*].contains(&r.group), "group `{}` passes through a singular position (not allowed by `allow singular`): {:?}", r.group, r);
        }
    }
}

/// The generated `check` test.
pub(super) fn test(cx: &Context, findings: &Findings) -> TokenStream {
    let name = cx.name;
    let singular_check = if findings.ran {
        as_at_expansion(findings)
    } else {
        only_allowed(cx)
    };
    quote! {
        /// `check()` with the default parameters: every group assembles
        /// over the range, and the singular positions are those the macro
        /// found at expansion time (same sweep; to 1e-6 of the range: at a
        /// fold the determinant is exactly zero over a rounding band of
        /// about sqrt(4 eps) of the range, where the searches may stop).
        #[test]
        fn check() {
            let report = #name::<f64>::default().check();
            assert!(report.assembles(), "a group cannot be assembled: {report:?}");
            #singular_check
        }
    }
}
