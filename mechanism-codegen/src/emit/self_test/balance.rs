//! The generated `power_balance` test (with a force analysis).

use super::Context;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// The generated `power_balance` test: the force analysis's power residual
/// within its rounding (none without a force analysis).
pub(super) fn test(cx: &Context) -> TokenStream {
    let model = cx.model;
    if !model.has_forces() {
        return quote!();
    }
    let name = cx.name;
    let loads_arg = if model.kinetics.loads.is_empty() {
        quote!()
    } else {
        let loads_ty = format_ident!("{}Loads", name);
        quote!(, &#loads_ty::default())
    };
    quote! {
        /// The power balance of the generated force analysis (driving
        /// efforts + loads + weights + inertia = 0), relative to its
        /// largest term: rounding of the reactions is about
        /// `eps / condition` relative (the force systems' conditioning
        /// indicator), summed over a few terms: 256 eps / condition.
        #[test]
        fn power_balance() {
            let m = #name::<f64>::default();
            let mut checked = 0usize;
            for s in 0..samples() {
                let q = sample(s);
                let Ok(sol) = m.solve(&input(q), &input(W), &input(A) #loads_arg) else { continue };
                let f = sol.forces;
                let tol = 256.0 * f64::EPSILON / f.condition.max(f64::EPSILON);
                assert!(f.power_residual <= tol, "sample {q:?}: power residual {:e} (tolerance {tol:e}, condition {:e})", f.power_residual, f.condition);
                checked += 1;
            }
            assert!(checked > 0, "no sample could be checked");
        }
    }
}
