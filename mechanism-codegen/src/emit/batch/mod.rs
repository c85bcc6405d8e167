//! Emission of the batch API: many evaluations at once over a structure of
//! arrays (one slice per input and per scalar output), into caller-provided
//! buffers, with a status byte per element instead of an early return.
//!
//! For `pub FourBar` at the acceleration level this emits
//!
//! - `FourBarBatch<'a, T>`: `in_<input>`, `rate_<input>`, `accel_<input>`
//!   (`&'a [T]`), `pos_<out>` / `vel_<out>` / `acc_<out>` (`&'a mut [T]`; a
//!   point gives `_x` and `_y` slices), and `status: &'a mut [u8]`;
//! - `FourBar::solve_batch(&self, &mut FourBarBatch) -> Result<usize,
//!   mechanism::BatchError>`: checks once that every slice has the length of
//!   the first input slice (the error names the first that does not,
//!   nothing evaluated), then evaluates every element, writes its outputs
//!   (zero for an element that failed: no NaN ever reaches the buffers) and
//!   its status (0 ok, 1 position, 2 velocity, 3 acceleration failed), and
//!   returns the number of failed elements;
//! - `impl ::mechanism::BatchSplit` (length, check, split in two), so that
//!   `mechanism::par_solve` (feature `rayon`) can spread a batch over cores;
//! - inside `::mechanism::__with_alloc!` (so only with the facade's feature
//!   `alloc`, whatever the features of the invoking crate): the owned form
//!   `FourBarColumns<T>` (the same fields as `Vec`s, `as_batch`),
//!   `FourBar::batch(n)` and `FourBar::solve_columns`.
//!
//! No early return inside the loop: the per-element work is straight-line
//! apart from the checks inside the primitives.
//!
//! `solve_batch` first runs the vectorizable kernel `__lane_batch` when the
//! definition has one (`kernel`; the state the statements share is
//! `kinds::lane`, each kind's lane code is its `GroupKind::lane`), then the
//! scalar path for the elements the kernel did not accept.

mod forces;
mod kernel;
#[cfg(test)]
mod tests;

use crate::emit::forces::ForceField;
use crate::keys::{LinkName, PointName};
use crate::kinds::{self, lane::OutputShape};
use crate::model::{Level, Model};
use crate::names::Family;
use crate::plan::Plan;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::Ident;

/// The slice prefixes of the levels: `pos`, `vel`, `acc`.
const PREFIXES: [Family; 3] = [Family::Pos, Family::Vel, Family::Acc];

/// One output slice of the batch: its field (`pos_B_x`), the expression
/// reading it from the scalar result of its level (`B.x` on `p`, `v` or
/// `a`) and that level (0 position, 1 velocity, 2 acceleration).
struct OutSlice {
    field: Ident,
    source: TokenStream,
    level: usize,
}

/// The batch's slice fields: the inputs by level (`in_*`, `rate_*`,
/// `accel_*`), the outputs by level.
struct Fields {
    inputs: Vec<Vec<Ident>>,
    outputs: Vec<OutSlice>,
}

impl Fields {
    /// The input fields' names, level after level.
    fn input_names(&self) -> Vec<&Ident> {
        self.inputs.iter().flatten().collect()
    }

    /// The output fields' names.
    fn output_names(&self) -> Vec<&Ident> {
        self.outputs.iter().map(|f| &f.field).collect()
    }
}

/// Emits the batch struct, its `BatchSplit` impl and `solve_batch`, and
/// with `force_fields` (the forces struct's reactions and efforts, for a
/// definition with the force analysis) the forces batch (`forces`).
/// `inputs`: the driver inputs; `outputs`: the position outputs with their
/// types (`Point2<T>` for points, `T` otherwise; velocity and acceleration
/// outputs have the same names).
pub fn emit(
    model: &Model,
    plan: &Plan,
    inputs: &[Ident],
    outputs: &[(Ident, OutputShape)],
    force_fields: Option<&[(Ident, ForceField)]>,
) -> TokenStream {
    let kept: Vec<(Ident, OutputShape)> = outputs
        .iter()
        .filter(|(o, shape)| !given(model, o) && !constant(model, plan, o, *shape))
        .cloned()
        .collect();
    let outputs = &kept[..];
    let levels = match model.level {
        Level::Position => 1,
        Level::Velocity => 2,
        _ => 3,
    };
    let errors = clashes(model, outputs);
    if !errors.is_empty() {
        return errors;
    }
    let fields = Fields {
        inputs: Family::BATCH_INPUTS[..levels]
            .iter()
            .map(|f| inputs.iter().map(|i| f.of(i)).collect())
            .collect(),
        outputs: out_slices(outputs, levels),
    };
    let kernel = kernel::kernel(model, plan, &fields.input_names(), outputs, levels);
    let mut items = batch_struct(model, &fields);
    items.extend(solve_batch(model, inputs, &fields, levels, kernel));
    if let Some(ff) = force_fields {
        items.extend(forces::emit(model, inputs, &fields, ff));
    }
    items.extend(owned(model, &fields, force_fields));
    items
}

/// The output slices, level by level: a point `P` gives `pos_P_x` and
/// `pos_P_y`, a link angle or slide `s` gives `pos_s`.
fn out_slices(outputs: &[(Ident, OutputShape)], levels: usize) -> Vec<OutSlice> {
    let mut out = Vec::new();
    for (level, prefix) in PREFIXES.iter().take(levels).enumerate() {
        for (o, shape) in outputs {
            let mut push = |field: Ident, source: TokenStream| {
                out.push(OutSlice {
                    field,
                    source,
                    level,
                })
            };
            if *shape == OutputShape::Point {
                push(prefix.coord(o, "x"), quote!(#o.x));
                push(prefix.coord(o, "y"), quote!(#o.y));
            } else {
                push(prefix.of(o), quote!(#o));
            }
        }
    }
    out
}

/// A point `P` gives the slices `pos_P_x` and `pos_P_y`, a link angle or
/// slide `s` the slice `pos_s`: a scalar output named `P_x` or `P_y`
/// beside a point output `P` would declare a field twice (rustc's errors
/// then point into the macro). Says which names meet instead: one
/// `compile_error!` per clash, on the scalar's name (empty when none).
fn clashes(model: &Model, outputs: &[(Ident, OutputShape)]) -> TokenStream {
    let name = &model.name;
    let mut errors = TokenStream::new();
    for (o, shape) in outputs {
        if *shape == OutputShape::Point {
            continue;
        }
        let s = o.to_string();
        let point = outputs.iter().find(|(p, t)| {
            *t == OutputShape::Point && [format!("{p}_x"), format!("{p}_y")].contains(&s)
        });
        if let Some((p, _)) = point {
            errors.extend(
                syn::Error::new(
                    o.span(),
                    format!(
                        "`{s}` and the coordinates of point `{p}` get the same field `pos_{s}` in the batch API (`{name}Batch`: a point's slices are `pos_{p}_x` and `pos_{p}_y`): rename `{s}`, e.g. `{s}_s`"
                    ),
                )
                .to_compile_error(),
            );
        }
    }
    errors
}

/// The batch struct `NAMEBatch<'a, T>` (one `&'a [T]` per input field, one
/// `&'a mut [T]` per output field, the `status` bytes), its `len`,
/// `is_empty` and `check` (every slice as long as the first input slice, or
/// the `BatchError` naming the first that is not), and
/// `impl ::mechanism::BatchSplit` (every slice split at the same index,
/// inputs with `split_at`, outputs with `split_at_mut`).
fn batch_struct(model: &Model, fields: &Fields) -> TokenStream {
    let name = &model.name;
    let vis = &model.vis;
    let batch_ty = format_ident!("{}Batch", name);
    let all_in = fields.input_names();
    let out_names = fields.output_names();
    let status = format_ident!("status");
    let reference = all_in.first().copied().unwrap_or(&status);
    let doc = format!(
        "Structure-of-arrays buffers for [`{name}::solve_batch`]: `in_*` (and `rate_*`, `accel_*`) are the driver inputs per element, `pos_*`, `vel_*`, `acc_*` the outputs (points as `_x`, `_y`), `status` one byte per element (0 ok, 1 position, 2 velocity, 3 acceleration failed). Units as in the scalar API. Every slice must have the length of `{reference}` (`solve_batch` returns a `mechanism::BatchError` otherwise)."
    );
    let len_doc = format!("Number of elements: the length of `{reference}`.");
    let checked: Vec<&Ident> = all_in
        .iter()
        .copied()
        .chain(out_names.iter().copied())
        .chain(core::iter::once(&status))
        .filter(|f| *f != reference)
        .collect();
    let checked_names = checked.iter().map(|f| f.to_string());
    let reference_name = reference.to_string();
    let shortest = quote!(
        {
            let mut n = self.status.len();
            #(n = ::core::cmp::min(n, self.#all_in.len());)*
            #(n = ::core::cmp::min(n, self.#out_names.len());)*
            n
        }
    );
    let split_out = out_names.iter().map(|f| {
        let (l, h) = (format_ident!("{}_lo", f), format_ident!("{}_hi", f));
        quote!(let (#l, #h) = self.#f.split_at_mut(mid);)
    });
    let lo = out_names.iter().map(|f| format_ident!("{}_lo", f));
    let hi = out_names.iter().map(|f| format_ident!("{}_hi", f));
    let in_lo = all_in.iter().map(|f| quote!(#f: #f.0));
    let in_hi = all_in.iter().map(|f| quote!(#f: #f.1));
    let split_in = all_in
        .iter()
        .map(|f| quote!(let #f = self.#f.split_at(mid);));
    quote! {
        #[doc = #doc]
        #[allow(non_snake_case, missing_docs)]
        #[derive(::core::fmt::Debug)]
        #vis struct #batch_ty<'a, T = ::core::primitive::f64> {
            #(pub #all_in: &'a [T],)*
            #(pub #out_names: &'a mut [T],)*
            pub status: &'a mut [::core::primitive::u8],
        }

        impl<'a, T> #batch_ty<'a, T> {
            #[doc = #len_doc]
            #[inline]
            pub fn len(&self) -> usize {
                self.#reference.len()
            }
            /// `true` when there is no element.
            #[inline]
            pub fn is_empty(&self) -> bool {
                self.len() == 0
            }
            /// The number of elements when every slice has the same length;
            /// otherwise the error naming the first slice (in field order)
            /// whose length differs.
            #[inline]
            pub fn check(&self) -> ::core::result::Result<usize, ::mechanism::BatchError> {
                let n = self.len();
                #(
                    if self.#checked.len() != n {
                        return ::core::result::Result::Err(::mechanism::BatchError::length_mismatch(
                            #checked_names, self.#checked.len(), #reference_name, n,
                        ));
                    }
                )*
                ::core::result::Result::Ok(n)
            }
        }

        impl<'a, T: ::core::marker::Send + ::core::marker::Sync> ::mechanism::BatchSplit for #batch_ty<'a, T> {
            #[inline]
            fn len(&self) -> usize {
                #batch_ty::len(self)
            }
            #[inline]
            fn check(&self) -> ::core::result::Result<usize, ::mechanism::BatchError> {
                #batch_ty::check(self)
            }
            #[inline]
            #[allow(non_snake_case)]
            fn split_at(self, mid: usize) -> (Self, Self) {
                let mid = ::core::cmp::min(mid, #shortest);
                #(#split_in)*
                #(#split_out)*
                let (status_lo, status_hi) = self.status.split_at_mut(mid);
                (
                    #batch_ty { #(#in_lo,)* #(#out_names: #lo,)* status: status_lo },
                    #batch_ty { #(#in_hi,)* #(#out_names: #hi,)* status: status_hi },
                )
            }
        }
    }
}

/// The owned form, inside `::mechanism::__with_alloc!` (emitted only when
/// the facade's feature `alloc` is on): `NAMEColumns<T>` (the batch's fields
/// as `Vec`s, and with `force_fields` the forces batch's), its `zeros`,
/// `len`, `is_empty` and `as_batch` (and `as_forces_batch`, `forces_at`),
/// and `NAME::batch(n)` and `NAME::solve_columns`.
fn owned(
    model: &Model,
    fields: &Fields,
    force_fields: Option<&[(Ident, ForceField)]>,
) -> TokenStream {
    let name = &model.name;
    let vis = &model.vis;
    let batch_ty = format_ident!("{}Batch", name);
    let cols_ty = format_ident!("{}Columns", name);
    let all_in = fields.input_names();
    let out_names = fields.output_names();
    let kinematic = quote!(#batch_ty {
        #(#all_in: &self.#all_in,)*
        #(#out_names: &mut self.#out_names,)*
        status: &mut self.status,
    });
    let force = force_fields.map(|ff| forces::owned(model, ff, &kinematic));
    let (loads, load_defaults, force_outs, force_methods) = match &force {
        Some(f) => (
            &f.loads[..],
            &f.load_defaults[..],
            &f.outs[..],
            f.methods.clone(),
        ),
        None => (&[][..], &[][..], &[][..], TokenStream::new()),
    };
    let zeroed: Vec<&Ident> = all_in
        .iter()
        .chain(out_names.iter())
        .copied()
        .chain(force_outs.iter())
        .collect();
    let all: Vec<&Ident> = zeroed.iter().copied().chain(loads.iter()).collect();
    let reference = match all_in.first() {
        Some(r) => quote!(#r),
        None => quote!(status),
    };
    let doc = format!(
        "The owned form of [`{batch_ty}`] (feature `alloc` of `mechanism`): the same fields as `Vec`s{}. [`{name}::batch`] makes one of `n` zeroed elements; fill the `in_*` (`rate_*`, `accel_*`) columns, then [`{name}::solve_columns`] (or [`Self::as_batch`] for `solve_batch` and `mechanism::par_solve`).",
        if force.is_some() { format!(", and those of [`{name}ForcesBatch`] (the force analysis: [`Self::as_forces_batch`], [`Self::forces_at`])") } else { String::new() }
    );
    let vec = quote!(::mechanism::__alloc::Vec);
    // Without loads, every column is zero; with them, the `load_*` columns
    // start at the definition's values.
    let zeros = if loads.is_empty() {
        quote! {
            /// `n` elements, every column and `status` zero.
            pub fn zeros(n: usize) -> Self {
                let column = || {
                    let mut v = #vec::new();
                    v.resize(n, <T as ::mechanism::Real>::lit(0.0));
                    v
                };
                let mut status = #vec::new();
                status.resize(n, 0u8);
                #cols_ty { #(#zeroed: column(),)* status }
            }
        }
    } else {
        quote! {
            /// `n` elements, every column and `status` zero but the
            /// `load_*` columns, which hold the definition's values (those
            /// of the loads struct's `Default`).
            pub fn zeros(n: usize) -> Self {
                let column = |x: T| {
                    let mut v = #vec::new();
                    v.resize(n, x);
                    v
                };
                let zero = <T as ::mechanism::Real>::lit(0.0);
                let mut status = #vec::new();
                status.resize(n, 0u8);
                #cols_ty { #(#zeroed: column(zero),)* #(#loads: column(#load_defaults),)* status }
            }
        }
    };
    let batch_doc = format!(
        "A [`{cols_ty}`] of `n` elements, every column and `status` zero{}: `{name}::<f64>::batch(n)`.",
        if loads.is_empty() { "" } else { " (the `load_*` columns at the definition's values)" }
    );
    let (solve_doc, solve_body) = match &force {
        Some(f) => (
            format!("[`Self::solve_batch_forces`] on the columns (`columns.as_forces_batch()`): kinematics and force analysis of every element; the number of failed elements, or the `mechanism::BatchError` naming the first column whose length differs from `{reference}`'s (nothing evaluated). For the kinematics alone (the vectorized kernel), `solve_batch(&mut columns.as_batch())`."),
            f.solve.clone(),
        ),
        None => (
            format!("[`Self::solve_batch`] on the columns (`columns.as_batch()`): the number of failed elements, or the `mechanism::BatchError` naming the first column whose length differs from `{reference}`'s (nothing evaluated)."),
            quote!(self.solve_batch(&mut columns.as_batch())),
        ),
    };
    quote! {
        ::mechanism::__with_alloc! {
            #[doc = #doc]
            #[allow(non_snake_case, missing_docs)]
            #[derive(::core::fmt::Debug, ::core::clone::Clone, ::core::cmp::PartialEq)]
            #vis struct #cols_ty<T = ::core::primitive::f64> {
                #(pub #all: #vec<T>,)*
                pub status: #vec<::core::primitive::u8>,
            }

            impl<T: ::mechanism::Real> #cols_ty<T> {
                #zeros
                #force_methods
            }

            impl<T> #cols_ty<T> {
                /// Number of elements: the length of the reference column
                /// (the first input's).
                #[inline]
                pub fn len(&self) -> usize {
                    self.#reference.len()
                }
                /// `true` when there is no element.
                #[inline]
                pub fn is_empty(&self) -> bool {
                    self.len() == 0
                }
                /// The columns as the borrowed batch of `solve_batch`.
                #[inline]
                pub fn as_batch(&mut self) -> #batch_ty<'_, T> {
                    #kinematic
                }
            }

            impl<T: ::mechanism::Real> #name<T> {
                #[doc = #batch_doc]
                pub fn batch(n: usize) -> #cols_ty<T> {
                    #cols_ty::zeros(n)
                }
                #[doc = #solve_doc]
                #[must_use = "the number of failed elements; an error means no element was evaluated"]
                #[inline]
                pub fn solve_columns(&self, columns: &mut #cols_ty<T>) -> ::core::result::Result<usize, ::mechanism::BatchError> {
                    #solve_body
                }
            }
        }
    }
}

/// The scalar evaluation of element `k`, level by level, each an `Option`
/// (`p`, `v`, `a`: `None` once a level failed), the status byte from them
/// (0 ok, 1 position, 2 velocity, 3 acceleration failed), and the writes of
/// the outputs (zero where the element failed: no NaN reaches the buffers).
/// `b`: the kinematic batch (`b`, or `b.batch` inside the forces batch).
fn element(
    model: &Model,
    inputs: &[Ident],
    fields: &Fields,
    levels: usize,
    b: &TokenStream,
) -> TokenStream {
    let input_ty = format_ident!("{}Input", model.name);
    let ins: Vec<TokenStream> = fields
        .inputs
        .iter()
        .map(|names| quote!(#input_ty { #(#inputs: #b.#names[k],)* }))
        .collect();
    let mut eval = TokenStream::new();
    let p_in = &ins[0];
    eval.extend(quote!(let p = self.position(&#p_in).ok();));
    if levels > 1 {
        let v_in = &ins[1];
        eval.extend(quote!(let v = match &p { ::core::option::Option::Some(p) => self.velocity(p, &#v_in).ok(), ::core::option::Option::None => ::core::option::Option::None };));
    }
    if levels > 2 {
        let a_in = &ins[2];
        eval.extend(quote!(let a = match (&p, &v) { (::core::option::Option::Some(p), ::core::option::Option::Some(v)) => self.acceleration(p, v, &#a_in).ok(), _ => ::core::option::Option::None };));
    }
    let status = match levels {
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
    let an = [quote!(p), quote!(v), quote!(a)];
    let writes = fields.outputs.iter().map(|o| {
        let (f, src, r) = (&o.field, &o.source, &an[o.level]);
        quote!(#b.#f[k] = match &#r { ::core::option::Option::Some(r) => r.#src, ::core::option::Option::None => zero };)
    });
    quote! {
        #eval
        let code = #status;
        #(#writes)*
    }
}

/// `impl NAME<T> { solve_batch, __solve_batch_lane_only, __lane_batch }`:
/// the kernel (when the definition has one) first, then the scalar path
/// over the elements it did not accept, in blocks of 64.
fn solve_batch(
    model: &Model,
    inputs: &[Ident],
    fields: &Fields,
    levels: usize,
    kernel: Option<kernel::Kernel>,
) -> TokenStream {
    let name = &model.name;
    let batch_ty = format_ident!("{}Batch", name);
    let element = element(model, inputs, fields, levels, &quote!(b));
    let has_lane = kernel.is_some();
    let (lane_method, lane_call) = match kernel {
        Some(k) => (k.method, k.call),
        None => (TokenStream::new(), TokenStream::new()),
    };
    let (lane_skip, lane_block_skip) = if has_lane {
        (
            quote!(if b.status[k] == 0 {
                continue;
            }),
            quote!(
                if b.status[start..end].iter().fold(0u8, |acc, s| acc | s) == 0 {
                    start = end;
                    continue;
                }
            ),
        )
    } else {
        (TokenStream::new(), TokenStream::new())
    };
    let method_doc = format!(
        "Evaluates every element of [`{batch_ty}`]: outputs into its slices (zero where an element failed), a status byte per element; returns the number of failed elements. No allocation, no panic.\n\n# Errors\n\n`mechanism::BatchError` when the slices differ in length (checked once, before any element is evaluated or written)."
    );
    let allow_lints = crate::emit::allow_literal_lints();
    quote! {
        #allow_lints
        impl<T: ::mechanism::Real> #name<T> {
            #[doc = #method_doc]
            #[inline]
            #[allow(non_snake_case, unused_variables)]
            #[must_use = "the number of failed elements; an error means no element was evaluated"]
            pub fn solve_batch(&self, b: &mut #batch_ty<'_, T>) -> ::core::result::Result<usize, ::mechanism::BatchError> {
                let n = b.check()?;
                let zero = <T as ::mechanism::Real>::lit(0.0);
                let mut failed = 0usize;
                #lane_call
                // The elements the kernel did not accept (or all, without a
                // kernel), through the scalar path; blocks of 64 the kernel
                // accepted whole are skipped with one OR of their statuses.
                let mut start = 0usize;
                while start < n {
                    let end = ::core::cmp::min(start + 64, n);
                    #lane_block_skip
                    for k in start..end {
                        #lane_skip
                        #element
                        b.status[k] = code;
                        failed += (code != 0) as usize;
                    }
                    start = end;
                }
                ::core::result::Result::Ok(failed)
            }

            /// The vectorized kernel of [`Self::solve_batch`] alone (for
            /// tests): writes the outputs of the elements it accepts with
            /// status 0 and status 255 for the others (their outputs are
            /// meaningless); returns `false`, touching nothing, when the
            /// definition has no lane version.
            #[doc(hidden)]
            #[allow(non_snake_case, unused_variables)]
            pub fn __solve_batch_lane_only(&self, b: &mut #batch_ty<'_, T>) -> bool {
                #lane_call
                #has_lane
            }
            #lane_method
        }
    }
}

/// `true` for an output that never changes, so that the batch leaves it
/// out: the angle of a link that does not turn (a block on a fixed guide,
/// whose angle is the guide's and whose rates are zero) and a point that
/// does not move (on such a link, from a still point). Its value is the
/// scalar `position`'s at any element (and its rates zero); a column would
/// repeat it per element.
/// `ty`: the output's type (`Point2<T>` for a point).
fn constant(model: &Model, plan: &Plan, output: &Ident, shape: OutputShape) -> bool {
    if shape == OutputShape::Point {
        return !plan.moving_points(model).contains(&PointName::of(output));
    }
    let o = LinkName::of(output);
    plan.links.contains_key(&o) && plan.turning_link(&o).is_none()
}

/// `true` for an output the batch leaves out because the caller has it
/// already: a ground point (its position is in the definition, its
/// velocity and acceleration are zero) and the link of a crank (its angle is
/// the element's input, its rates the input's rates). Writing them for every
/// element would be memory traffic only.
fn given(model: &Model, output: &Ident) -> bool {
    model
        .stmts
        .iter()
        .any(|s| kinds::of(s).given_by_caller(output))
}
