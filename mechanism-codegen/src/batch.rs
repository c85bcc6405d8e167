//! Emission of the batch API: many evaluations at once over a structure of
//! arrays (one slice per input and per scalar output), into caller-provided
//! buffers, with a status byte per element instead of an early return.
//!
//! For `pub FourBar` at the acceleration level this emits
//!
//! - `FourBarBatch<'a, T>`: `in_<input>`, `rate_<input>`, `accel_<input>`
//!   (`&'a [T]`), `pos_<out>` / `vel_<out>` / `acc_<out>` (`&'a mut [T]`; a
//!   point gives `_x` and `_y` slices), and `status: &'a mut [u8]`;
//! - `FourBar::solve_batch(&self, &mut FourBarBatch) -> usize`: evaluates
//!   every element (the shortest slice's length), writes its outputs (zero
//!   for an element that failed: no NaN ever reaches the buffers) and its
//!   status (0 ok, 1 position, 2 velocity, 3 acceleration failed), and returns
//!   the number of failed elements;
//! - `impl ::mechanism::BatchSplit` (length, split in two), so that
//!   `mechanism::par_solve` (feature `rayon`) can spread a batch over cores.
//!
//! No early return inside the loop: the per-element work is straight-line
//! apart from the checks inside the primitives.

use crate::model::{Level, Model};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::Ident;

/// Emits the batch struct, its `BatchSplit` impl and `solve_batch`.
/// `inputs`: the driver inputs; `outputs`: the position outputs with their
/// types (`Point2<T>` for points, `T` otherwise; velocity and acceleration
/// outputs have the same names).
pub fn emit(model: &Model, inputs: &[Ident], outputs: &[(Ident, TokenStream)]) -> TokenStream {
    let name = &model.name;
    let vis = &model.vis;
    let batch_ty = format_ident!("{}Batch", name);
    let input_ty = format_ident!("{}Input", name);
    let level = model.level;
    let levels: Vec<(&str, &str)> = [
        ("pos", "position"),
        ("vel", "velocity"),
        ("acc", "acceleration"),
    ]
    .into_iter()
    .take(match level {
        Level::Position => 1,
        Level::Velocity => 2,
        _ => 3,
    })
    .collect();
    let in_names: Vec<Vec<Ident>> = ["in", "rate", "accel"]
        .iter()
        .take(levels.len())
        .map(|p| {
            inputs
                .iter()
                .map(|i| format_ident!("{}_{}", p, i))
                .collect()
        })
        .collect();
    // Output slices: (slice field, source expression suffix, level index).
    let mut out_fields: Vec<(Ident, TokenStream, usize)> = Vec::new();
    for (li, (prefix, _)) in levels.iter().enumerate() {
        for (o, ty) in outputs {
            let point = ty.to_string().contains("Point2");
            if point {
                out_fields.push((format_ident!("{}_{}_x", prefix, o), quote!(#o.x), li));
                out_fields.push((format_ident!("{}_{}_y", prefix, o), quote!(#o.y), li));
            } else {
                out_fields.push((format_ident!("{}_{}", prefix, o), quote!(#o), li));
            }
        }
    }
    let all_in: Vec<&Ident> = in_names.iter().flatten().collect();
    let out_names: Vec<&Ident> = out_fields.iter().map(|f| &f.0).collect();
    let doc = format!(
        "Structure-of-arrays buffers for [`{name}::solve_batch`]: `in_*` (and `rate_*`, `accel_*`) are the driver inputs per element, `pos_*`, `vel_*`, `acc_*` the outputs (points as `_x`, `_y`), `status` one byte per element (0 ok, 1 position, 2 velocity, 3 acceleration failed). Units as in the scalar API. Every slice should have the same length; the shortest one sets how many elements are evaluated."
    );
    let n_expr = quote!(
        {
            let mut n = self.status.len();
            #(n = ::core::cmp::min(n, self.#all_in.len());)*
            #(n = ::core::cmp::min(n, self.#out_names.len());)*
            n
        }
    );
    // Per element: evaluate level by level, each as an Option.
    let an = [quote!(p), quote!(v), quote!(a)];
    let ins: Vec<TokenStream> = in_names
        .iter()
        .map(|names| quote!(#input_ty { #(#inputs: b.#names[k],)* }))
        .collect();
    let mut eval = TokenStream::new();
    let p_in = &ins[0];
    eval.extend(quote!(let p = self.position(&#p_in).ok();));
    if levels.len() > 1 {
        let v_in = &ins[1];
        eval.extend(quote!(let v = match &p { ::core::option::Option::Some(p) => self.velocity(p, &#v_in).ok(), ::core::option::Option::None => ::core::option::Option::None };));
    }
    if levels.len() > 2 {
        let a_in = &ins[2];
        eval.extend(quote!(let a = match (&p, &v) { (::core::option::Option::Some(p), ::core::option::Option::Some(v)) => self.acceleration(p, v, &#a_in).ok(), _ => ::core::option::Option::None };));
    }
    let status_expr = match levels.len() {
        1 => quote!(if p.is_none() { 1u8 } else { 0u8 }),
        2 => quote!(if p.is_none() {
            1u8
        } else if v.is_none() {
            2u8
        } else {
            0u8
        }),
        _ => quote!(if p.is_none() {
            1u8
        } else if v.is_none() {
            2u8
        } else if a.is_none() {
            3u8
        } else {
            0u8
        }),
    };
    let writes: Vec<TokenStream> = out_fields
        .iter()
        .map(|(f, src, li)| {
            let r = &an[*li];
            quote!(b.#f[k] = match &#r { ::core::option::Option::Some(r) => r.#src, ::core::option::Option::None => zero };)
        })
        .collect();
    // Fields split at `mid`: immutable inputs with split_at, outputs with split_at_mut.
    let in_pairs: Vec<Ident> = all_in.iter().map(|f| format_ident!("{}", f)).collect();
    let split_out: Vec<TokenStream> = out_names
        .iter()
        .map(|f| {
            let l = format_ident!("{}_lo", f);
            let h = format_ident!("{}_hi", f);
            quote!(let (#l, #h) = self.#f.split_at_mut(mid);)
        })
        .collect();
    let lo: Vec<Ident> = out_names
        .iter()
        .map(|f| format_ident!("{}_lo", f))
        .collect();
    let hi: Vec<Ident> = out_names
        .iter()
        .map(|f| format_ident!("{}_hi", f))
        .collect();
    let in_lo: Vec<TokenStream> = in_pairs.iter().map(|f| quote!(#f: #f.0)).collect();
    let in_hi: Vec<TokenStream> = in_pairs.iter().map(|f| quote!(#f: #f.1)).collect();
    let split_in: Vec<TokenStream> = in_pairs
        .iter()
        .map(|f| quote!(let #f = self.#f.split_at(mid);))
        .collect();
    let method_doc = format!(
        "Evaluates every element of [`{batch_ty}`]: outputs into its slices (zero where an element failed), a status byte per element; returns the number of failed elements. No allocation, no early return, no panic."
    );
    quote! {
        #[doc = #doc]
        #[allow(non_snake_case, missing_docs)]
        #vis struct #batch_ty<'a, T = ::core::primitive::f64> {
            #(pub #all_in: &'a [T],)*
            #(pub #out_names: &'a mut [T],)*
            pub status: &'a mut [::core::primitive::u8],
        }

        impl<'a, T> #batch_ty<'a, T> {
            /// Number of elements evaluated: the shortest slice's length.
            #[inline]
            pub fn len(&self) -> usize #n_expr
            /// `true` when no element would be evaluated.
            #[inline]
            pub fn is_empty(&self) -> bool {
                self.len() == 0
            }
        }

        impl<'a, T: ::core::marker::Send + ::core::marker::Sync> ::mechanism::BatchSplit for #batch_ty<'a, T> {
            #[inline]
            fn len(&self) -> usize {
                #batch_ty::len(self)
            }
            #[inline]
            #[allow(non_snake_case)]
            fn split_at(self, mid: usize) -> (Self, Self) {
                let mid = ::core::cmp::min(mid, #batch_ty::len(&self));
                #(#split_in)*
                #(#split_out)*
                let (status_lo, status_hi) = self.status.split_at_mut(mid);
                (
                    #batch_ty { #(#in_lo,)* #(#out_names: #lo,)* status: status_lo },
                    #batch_ty { #(#in_hi,)* #(#out_names: #hi,)* status: status_hi },
                )
            }
        }

        impl<T: ::mechanism::Real> #name<T> {
            #[doc = #method_doc]
            #[inline]
            #[allow(non_snake_case, unused_variables)]
            pub fn solve_batch(&self, b: &mut #batch_ty<'_, T>) -> usize {
                let n = b.len();
                let zero = <T as ::mechanism::Real>::lit(0.0);
                let mut failed = 0usize;
                for k in 0..n {
                    #eval
                    let code = #status_expr;
                    #(#writes)*
                    b.status[k] = code;
                    failed += (code != 0) as usize;
                }
                failed
            }
        }
    }
}
