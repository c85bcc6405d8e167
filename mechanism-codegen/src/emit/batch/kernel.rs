//! The vectorizable kernel of a batch: every statement the outputs need, in
//! solve order, through the lane code of its kind (`kinds::*::lane`), on the
//! state of `kinds::lane`.

use crate::kinds;
use crate::kinds::lane::{Lane, OutputShape, Step, Writes};
use crate::model::{Model, Stmt};
use crate::plan::Plan;
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

/// The vectorizable kernel and the call of it from `solve_batch`.
pub(super) struct Kernel {
    /// The `__lane_batch` method.
    pub method: TokenStream,
    /// `self.__lane_batch(...)` on the batch `b`.
    pub call: TokenStream,
}

/// The vectorizable kernel (`__lane_batch`) and the code that calls it, when
/// every statement the outputs need has a lane version (every kind of
/// statement has one: ground points, guides, cranks, sliders, actuators, the
/// five groups, points on links); `None` otherwise (the batch is then
/// evaluated by the scalar path alone).
///
/// The kernel takes every slice as its own argument (so the compiler knows
/// they do not overlap: no run-time alias checks that would stop the
/// vectorizer), evaluates every element branch-free with
/// `mechanism::__private::lane`, writes its outputs and a status of 0 (ok) or 255 (to be
/// evaluated again by the scalar path, which writes zeros and the real
/// status). The checks of `mechanism::__private::lane` are stricter than the scalar
/// ones, so an element the kernel accepts is one the scalar path accepts.
/// Values that do not depend on the element (a guide's direction given by a
/// run-time parameter) are computed once, before the loop, by the scalar
/// functions the scalar path uses.
pub(super) fn kernel(
    model: &Model,
    plan: &Plan,
    all_in: &[&Ident],
    outputs: &[(Ident, OutputShape)],
    levels: usize,
) -> Option<Kernel> {
    let mut lane = Lane::new(levels);
    // Only the statements the outputs need, as in the scalar path (a failing
    // statement nobody asked for must not send elements to the scalar path).
    for &i in &plan.solve {
        statement(&mut lane, &model.stmts[i])?;
    }
    let Writes { slices, code } = lane.writes(outputs, levels)?;
    let Lane { pre, body, .. } = lane;
    let ins = all_in;
    let real = quote!(<T as ::mechanism::Real>);
    let method = quote! {
        /// The vectorizable part of [`Self::solve_batch`] (see `mechanism::__private::lane`):
        /// every element branch-free; status 0, or 255 where the scalar path
        /// must evaluate the element again.
        #[doc(hidden)]
        #[inline]
        #[allow(non_snake_case, unused_variables, dead_code, clippy::too_many_arguments)]
        fn __lane_batch(&self, #(#ins: &[T],)* #(#slices: &mut [T],)* status: &mut [::core::primitive::u8]) {
            let mut n = status.len();
            #(n = ::core::cmp::min(n, #ins.len());)*
            #(n = ::core::cmp::min(n, #slices.len());)*
            #(let #ins = &#ins[..n];)*
            #(let #slices = &mut #slices[..n];)*
            let status = &mut status[..n];
            let zero = #real::lit(0.0);
            #pre
            for k in 0..n {
                let mut ok = true;
                let mut chk = zero;
                #body
                #code
                ok &= #real::finite(chk);
                status[k] = if ok { 0 } else { ::core::primitive::u8::MAX };
            }
        }
    };
    let call = quote! {
        self.__lane_batch(#(b.#ins,)* #(&mut *b.#slices,)* &mut *b.status);
    };
    Some(Kernel { method, call })
}

/// Adds the lane code of one statement (its kind's), `None` when it has no
/// lane version here (an argument the kernel does not know).
pub(super) fn statement(lane: &mut Lane, stmt: &Stmt) -> Option<()> {
    let kind = kinds::of(stmt);
    let mut s = Step::new(stmt, kind.names_slide());
    kind.lane(lane, &mut s)?;
    lane.commit(s);
    Some(())
}
