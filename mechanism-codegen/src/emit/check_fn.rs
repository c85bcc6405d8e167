//! The generated `check()`: the expansion-time sweep of the position analysis
//! over the input ranges (`crate::check`), run at run time through the
//! generated `position()`, so that it holds for any parameters.

use crate::check::joints_at_infinity;
use crate::kinds;
use crate::kinds::reads::Reads;
use crate::model::{Model, StmtId};
use crate::plan::{checked, Plan};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::Ident;

/// The scaled determinant of a checked group, from the generated position
/// struct `pos` (code; `reads` records its reads).
pub(crate) fn det_code(model: &Model, stmt_index: StmtId, reads: &Reads) -> TokenStream {
    kinds::of(&model.stmts[stmt_index]).det_code(reads)
}

/// The generated `check()` method: the items to put beside the mechanism's
/// (empty, or the trait of [`uncallable`]) and the method.
pub struct CheckFn {
    pub items: TokenStream,
    pub method: TokenStream,
}

/// The generated `check()`. It sweeps the ranges the definition gives
/// (declared by `range`, or a crank's full turn for a one-input
/// mechanism). Where the definition gives none for an input (a slider, a
/// cylinder, a target's coordinate, either of two inputs not both declared),
/// or the inputs are more than two, `check()` still exists, and a call is a
/// compile error saying which `range` statements to add ([`uncallable`]).
/// `reads` records its reads of the position struct.
pub fn emit_check(model: &Model, plan: &Plan, summary: &str, reads: &Reads) -> CheckFn {
    let inputs = &model.inputs;
    let checked = checked(model, plan);
    if inputs.is_empty() || inputs.len() > 2 {
        let why = format!(
            "`{}::check()` sweeps one or two inputs, and this mechanism has {}; check the run-time cases with `position()`",
            model.name,
            inputs.len()
        );
        return uncallable(model, &why);
    }
    let missing: Vec<&Ident> = inputs
        .iter()
        .filter(|i| i.range.is_none() || (inputs.len() == 2 && !i.declared))
        .map(|i| &i.name)
        .collect();
    if !missing.is_empty() {
        let declare: Vec<String> = missing
            .iter()
            .map(|i| format!("`range {i} = (lo, hi);`"))
            .collect();
        let quoted: Vec<String> = missing.iter().map(|i| format!("`{i}`")).collect();
        let why = format!(
            "`{}::check()` sweeps the input ranges the definition gives, and it gives none for {}{}: add {} to the definition",
            model.name,
            quoted.join(" and "),
            if inputs.len() == 2 { " (a two-input sweep takes both ranges declared)" } else { "" },
            declare.join(" and "),
        );
        return uncallable(model, &why);
    }
    let name = &model.name;
    let input_ty = format_ident!("{}Input", name);
    let g = checked.groups.len();
    let d = inputs.len();
    let group_names: Vec<String> = checked
        .groups
        .iter()
        .map(|&i| model.stmts[i].name.to_string())
        .collect();
    let indices: Vec<usize> = (0..g).collect();
    let dets: Vec<TokenStream> = checked
        .groups
        .iter()
        .map(|&i| det_code(model, i, reads))
        .collect();
    let input_names: Vec<&Ident> = inputs.iter().map(|i| &i.name).collect();
    let input_strs: Vec<String> = input_names.iter().map(|i| i.to_string()).collect();
    let ks: Vec<usize> = (0..d).collect();
    let ranges: Vec<TokenStream> = inputs
        .iter()
        .map(|i| {
            let r = i.range.expect("checked above");
            let (lo, hi, p) = (r.lo, r.hi, r.periodic);
            quote!(::mechanism::sweep::Range { lo: #lo, hi: #hi, periodic: #p })
        })
        .collect();
    // A PRP's or an RPP's joint at infinity is a failure, as at expansion
    // time; the call only where the mechanism has one.
    let at_infinity = joints_at_infinity(model, &checked);
    let mark_infinity = if at_infinity.contains(&true) {
        quote!(.with_joints_at_infinity([#(#at_infinity),*]))
    } else {
        TokenStream::new()
    };
    let sweep_call = if d == 1 {
        quote!(::mechanism::sweep::sweep_1d(&ranges[0], ::mechanism::sweep::SAMPLES_1D, &tol, eval, |e| report.record(&e));)
    } else {
        quote!(let _ = tol; ::mechanism::sweep::sweep_2d(&ranges, ::mechanism::sweep::SAMPLES_2D, eval, |e| report.record(&e));)
    };
    let doc = format!(
        "Sweeps the input range with these parameters, through [`{name}::position`]: per group (in solve order: {}), where it cannot be assembled and where its rate system is singular. The sweep is the one the macro runs at expansion time (`mechanism::sweep`), in the scalar `T` (edges bisected to `max(1e-10, eps)` of the range, singular below `sqrt(eps)`; an edge lies where `position()` in `T` stops assembling, which can be the group's rounding band beyond the exact limit: in `f32` a few 1e-6 rad at an RRR's limit); about {} position solves. No heap.\n\n{summary}",
        group_names.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", "),
        if d == 1 { "4000" } else { "15000" }
    );
    let method = quote! {
        #[doc = #doc]
        #[allow(clippy::all)]
        pub fn check(&self) -> ::mechanism::sweep::Report<#g, #d> {
            let ranges = [#(#ranges),*];
            let mut report = ::mechanism::sweep::Report::new([#(#input_strs),*], ranges, [#(#group_names),*])#mark_infinity;
            let tol = ::mechanism::sweep::Tolerances::for_eps(<T as ::mechanism::Real>::as_f64(<T as ::mechanism::Real>::eps()));
            let eval = |q: &[::core::primitive::f64; #d]| -> ::mechanism::sweep::Outcome<#g> {
                let input = #input_ty { #(#input_names: <T as ::mechanism::Real>::lit(q[#ks]),)* };
                match self.position(&input) {
                    ::core::result::Result::Ok(pos) => ::core::result::Result::Ok([#(#dets),*]),
                    ::core::result::Result::Err(e) => ::core::result::Result::Err((
                        match e.group { #(#group_names => #indices,)* _ => 0 },
                        e.fault.to_f64(),
                    )),
                }
            };
            #sweep_call
            report
        }
    };
    CheckFn {
        items: TokenStream::new(),
        method,
    }
}

/// `check()` for a definition that gives it nothing to sweep: it exists, so
/// that a call finds it (rather than no method, or an unrelated trait's),
/// and its bound is a trait of the definition's own that nothing implements,
/// whose `on_unimplemented` message, `why`, is the compile error at the call.
/// It returns `()`: it can never run.
fn uncallable(model: &Model, why: &str) -> CheckFn {
    let name = &model.name;
    let vis = &model.vis;
    let bound = format_ident!("{}CheckNeedsRanges", name);
    let doc = format!("Not available for this definition: {why}.");
    let label = "`check()` has no range to sweep";
    CheckFn {
        items: quote! {
            #[doc(hidden)]
            #[diagnostic::on_unimplemented(message = #why, label = #label)]
            #vis trait #bound {
                /// Never called: nothing implements the trait.
                fn never(&self);
            }
        },
        method: quote! {
            #[doc = #doc]
            pub fn check(&self) where Self: #bound {
                <Self as #bound>::never(self)
            }
        },
    }
}
