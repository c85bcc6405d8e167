//! The batch form of the force analysis, for a definition with masses or
//! loads: `NAMEForcesBatch<'a, T>` and `NAME::solve_batch_forces`.
//!
//! For `pub Press` with a crank `theta`, a `loads { cut }` block and the
//! reactions `r_ground_crank` (a revolute), `r_ground_block` (a prismatic
//! pair) and the effort `drive_theta`, this emits
//!
//! - `PressForcesBatch<'a, T>`: `batch` (the kinematic `PressBatch`: inputs,
//!   kinematic outputs, `status`), `load_cut: &'a [T]` (one value per
//!   element: a press's process force may follow the ram), and one
//!   `&'a mut [T]` per scalar of the scalar `PressForces`:
//!   `r_ground_crank_x`, `r_ground_crank_y`; `r_ground_block_normal`,
//!   `r_ground_block_moment`, `r_ground_block_x`, `r_ground_block_y` (a
//!   `PrismaticReaction`'s normal force, couple and force vector);
//!   `drive_theta`; `condition`; `power_residual`;
//! - its `len`, `check` and `forces_at(k)` (element `k` as the scalar
//!   `PressForces`, `None` unless its status is 0), `impl
//!   ::mechanism::BatchSplit` (for `mechanism::par_solve`);
//! - `Press::solve_batch_forces`: per element the scalar `position`,
//!   `velocity`, `acceleration` and `forces`, the same calls in the same
//!   order as `solve`, so every column holds the scalar value bit for bit;
//!   status 4 where the force analysis failed (a singular force system,
//!   non-finite loads), its columns zero.
//!
//! The force systems are not vectorized: each group's reactions come from a
//! Gaussian elimination with partial pivoting (`mechanism::linsolve`), a
//! branch per pivot and a typed error per group, and the force analysis
//! reads every pose, rate and acceleration of the links, which the lane
//! kernel does not keep (it writes the requested outputs only). So the
//! kinematic lane kernel would have to be run again by the scalar path
//! anyway, and `solve_batch_forces` does not run it.

use super::{element, Fields};
use crate::emit::forces::ForceField;
use crate::emit::names::TypeNames;
use crate::model::Model;
use crate::names::Family;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::Ident;

/// One column of the forces batch: its field and the expression that
/// reads its value from the scalar forces `f`.
pub(super) struct ForceColumn {
    pub field: Ident,
    pub source: TokenStream,
}

/// The columns of the forces batch in the forces struct's field order, then
/// `condition` and `power_residual`.
pub(super) fn columns(fields: &[(Ident, ForceField)]) -> Vec<ForceColumn> {
    let mut out = Vec::new();
    let mut push = |field: Ident, source: TokenStream| out.push(ForceColumn { field, source });
    for (name, held) in fields {
        match held {
            ForceField::Force => {
                push(format_ident!("{}_x", name), quote!(#name.x));
                push(format_ident!("{}_y", name), quote!(#name.y));
            }
            ForceField::Prismatic => {
                push(format_ident!("{}_normal", name), quote!(#name.normal));
                push(format_ident!("{}_moment", name), quote!(#name.moment));
                push(format_ident!("{}_x", name), quote!(#name.force.x));
                push(format_ident!("{}_y", name), quote!(#name.force.y));
            }
            ForceField::Torque | ForceField::Push => push(name.clone(), quote!(#name)),
        }
    }
    for extra in ["condition", "power_residual"] {
        let f = format_ident!("{}", extra);
        push(f.clone(), quote!(#f));
    }
    out
}

/// The `load_NAME` fields, one per entry of the `loads` block.
pub(super) fn load_fields(model: &Model) -> Vec<(Ident, Ident)> {
    model
        .kinetics
        .loads
        .iter()
        .map(|(n, _)| (Family::Load.of(n), n.clone()))
        .collect()
}

/// The expression of the scalar forces struct of element `k` rebuilt from
/// the columns `cols` (a `NAMEForcesBatch` or a `NAMEColumns`).
fn rebuild(names: &TypeNames, fields: &[(Ident, ForceField)], cols: &TokenStream) -> TokenStream {
    let values = fields.iter().map(|(name, held)| {
        let c = |suffix: &str| {
            let f = format_ident!("{}{}", name, suffix);
            quote!(#cols.#f[k])
        };
        let value = match held {
            ForceField::Force => {
                let (x, y) = (c("_x"), c("_y"));
                quote!(::mechanism::Vector2::new(#x, #y))
            }
            ForceField::Prismatic => {
                let (n, m, x, y) = (c("_normal"), c("_moment"), c("_x"), c("_y"));
                quote!(::mechanism::force::PrismaticReaction { normal: #n, moment: #m, force: ::mechanism::Vector2::new(#x, #y) })
            }
            ForceField::Torque | ForceField::Push => c(""),
        };
        quote!(#name: #value)
    });
    let forces_ty = &names.forces;
    quote!(#forces_ty { #(#values,)* condition: #cols.condition[k], power_residual: #cols.power_residual[k] })
}

/// The forces batch struct, its methods and `BatchSplit` impl, and
/// `solve_batch_forces`.
pub(super) fn emit(
    model: &Model,
    inputs: &[Ident],
    fields: &Fields,
    force_fields: &[(Ident, ForceField)],
) -> TokenStream {
    let names = TypeNames::of(model);
    let (name, vis) = (&names.name, &model.vis);
    let batch_ty = format_ident!("{}Batch", name);
    let fb_ty = format_ident!("{}ForcesBatch", name);
    let forces_ty = &names.forces;
    let cols = columns(force_fields);
    let outs: Vec<&Ident> = cols.iter().map(|c| &c.field).collect();
    let loads = load_fields(model);
    let load_f: Vec<&Ident> = loads.iter().map(|(f, _)| f).collect();
    let own: Vec<&Ident> = load_f.iter().copied().chain(outs.iter().copied()).collect();
    let own_names = own.iter().map(|f| f.to_string());
    let first_in = fields
        .inputs
        .first()
        .and_then(|l| l.first())
        .map_or_else(|| "status".to_string(), ToString::to_string);
    let doc = format!(
        "Structure-of-arrays buffers for [`{name}::solve_batch_forces`]: the kinematic batch `batch` ([`{batch_ty}`]: inputs, outputs, `status`), {}and one column per scalar of [`{forces_ty}`] (a joint force as `_x`, `_y`; a prismatic pair's reaction as `_normal`, `_moment`, `_x`, `_y`; a driving effort, `condition` and `power_residual` as themselves). Units as in the scalar API. Every slice must have the length of `batch.{first_in}`.",
        if loads.is_empty() { String::new() } else { "the run-time loads per element (`load_*`, the fields of the scalar loads struct) ".to_string() }
    );
    let rebuilt = rebuild(&names, force_fields, &quote!(self));
    let split_out = outs.iter().map(|f| {
        let (l, h) = (format_ident!("{}_lo", f), format_ident!("{}_hi", f));
        quote!(let (#l, #h) = self.#f.split_at_mut(mid);)
    });
    let lo = outs.iter().map(|f| format_ident!("{}_lo", f));
    let hi = outs.iter().map(|f| format_ident!("{}_hi", f));
    let split_in = load_f
        .iter()
        .map(|f| quote!(let #f = self.#f.split_at(mid);));
    let (in_lo, in_hi): (Vec<_>, Vec<_>) = load_f
        .iter()
        .map(|f| (quote!(#f: #f.0), quote!(#f: #f.1)))
        .unzip();
    let shortest = quote!({
        let mut n = ::mechanism::BatchSplit::len(&self.batch);
        #(n = ::core::cmp::min(n, self.#own.len());)*
        n
    });
    let solve = solve_method(model, inputs, fields, &cols, &loads);
    quote! {
        #[doc = #doc]
        #[allow(non_snake_case, missing_docs)]
        #[derive(::core::fmt::Debug)]
        #vis struct #fb_ty<'a, T = ::core::primitive::f64> {
            pub batch: #batch_ty<'a, T>,
            #(pub #load_f: &'a [T],)*
            #(pub #outs: &'a mut [T],)*
        }

        impl<'a, T: ::mechanism::Real> #fb_ty<'a, T> {
            /// Number of elements: the kinematic batch's.
            #[inline]
            pub fn len(&self) -> usize {
                self.batch.len()
            }
            /// `true` when there is no element.
            #[inline]
            pub fn is_empty(&self) -> bool {
                self.len() == 0
            }
            /// The number of elements when every slice has the same length;
            /// otherwise the error naming the first slice (the kinematic
            /// batch's first, then this struct's in field order) whose
            /// length differs.
            #[inline]
            pub fn check(&self) -> ::core::result::Result<usize, ::mechanism::BatchError> {
                let n = self.batch.check()?;
                #(
                    if self.#own.len() != n {
                        return ::core::result::Result::Err(::mechanism::BatchError::length_mismatch(
                            #own_names, self.#own.len(), #first_in, n,
                        ));
                    }
                )*
                ::core::result::Result::Ok(n)
            }
            /// Element `k`'s force analysis as the scalar struct (the
            /// columns' values, bit for bit what `forces` gave), `None`
            /// when `k` is out of range or the element's status is not 0.
            #[inline]
            pub fn forces_at(&self, k: usize) -> ::core::option::Option<#forces_ty<T>> {
                if k >= self.len() || self.batch.status[k] != 0 || self.check().is_err() {
                    return ::core::option::Option::None;
                }
                ::core::option::Option::Some(#rebuilt)
            }
        }

        impl<'a, T: ::mechanism::Real + ::core::marker::Send + ::core::marker::Sync> ::mechanism::BatchSplit for #fb_ty<'a, T> {
            #[inline]
            fn len(&self) -> usize {
                #fb_ty::len(self)
            }
            #[inline]
            fn check(&self) -> ::core::result::Result<usize, ::mechanism::BatchError> {
                #fb_ty::check(self)
            }
            #[inline]
            #[allow(non_snake_case)]
            fn split_at(self, mid: usize) -> (Self, Self) {
                let mid = ::core::cmp::min(mid, #shortest);
                #(#split_in)*
                #(#split_out)*
                let (batch_lo, batch_hi) = ::mechanism::BatchSplit::split_at(self.batch, mid);
                (
                    #fb_ty { batch: batch_lo, #(#in_lo,)* #(#outs: #lo,)* },
                    #fb_ty { batch: batch_hi, #(#in_hi,)* #(#outs: #hi,)* },
                )
            }
        }

        #solve
    }
}

/// `impl NAME<T> { solve_batch_forces }`: the scalar path per element (the
/// kinematic element code of `solve_batch` on `b.batch`, then `forces`).
fn solve_method(
    model: &Model,
    inputs: &[Ident],
    fields: &Fields,
    cols: &[ForceColumn],
    loads: &[(Ident, Ident)],
) -> TokenStream {
    let names = TypeNames::of(model);
    let (name, loads_ty) = (&names.name, &names.loads);
    let fb_ty = format_ident!("{}ForcesBatch", name);
    let element = element(model, inputs, fields, 3, &quote!(b.batch));
    let loads_arg = if loads.is_empty() {
        TokenStream::new()
    } else {
        let (f, l): (Vec<&Ident>, Vec<&Ident>) = loads.iter().map(|(f, l)| (f, l)).unzip();
        quote!(, &#loads_ty { #(#l: b.#f[k],)* })
    };
    let writes = cols.iter().map(|c| {
        let (f, src) = (&c.field, &c.source);
        quote!(b.#f[k] = match &fo { ::core::option::Option::Some(r) => r.#src, ::core::option::Option::None => zero };)
    });
    let doc = format!(
        "Evaluates every element of [`{fb_ty}`]: the kinematic outputs and the force analysis (what `solve` gives), each element through the scalar `position`, `velocity`, `acceleration` and `forces` (the same calls as `solve`: bit for bit its values); zeros where an element failed, and its status: 0 ok, 1 position, 2 velocity, 3 acceleration, 4 forces failed. Returns the number of failed elements. No allocation, no panic.\n\n# Errors\n\n`mechanism::BatchError` when the slices differ in length (checked once, before any element is evaluated or written)."
    );
    let allow_lints = crate::emit::allow_literal_lints();
    quote! {
        #allow_lints
        impl<T: ::mechanism::Real> #name<T> {
            #[doc = #doc]
            #[inline]
            #[allow(non_snake_case, unused_variables)]
            #[must_use = "the number of failed elements; an error means no element was evaluated"]
            pub fn solve_batch_forces(&self, b: &mut #fb_ty<'_, T>) -> ::core::result::Result<usize, ::mechanism::BatchError> {
                let n = b.check()?;
                let zero = <T as ::mechanism::Real>::lit(0.0);
                let mut failed = 0usize;
                for k in 0..n {
                    #element
                    let fo = match (&p, &v, &a) {
                        (::core::option::Option::Some(p), ::core::option::Option::Some(v), ::core::option::Option::Some(a)) => self.forces(p, v, a #loads_arg).ok(),
                        _ => ::core::option::Option::None,
                    };
                    let code = if code == 0 && fo.is_none() { 4u8 } else { code };
                    #(#writes)*
                    b.batch.status[k] = code;
                    failed += (code != 0) as usize;
                }
                ::core::result::Result::Ok(failed)
            }
        }
    }
}

/// What the owned form adds for the force analysis: the fields of
/// `NAMEColumns` (the loads, then the force columns), the `zeros` values of
/// the load columns (the definition's values), the `as_forces_batch` and
/// `forces_at` methods, and `solve_columns`' body.
pub(super) struct Owned {
    pub loads: Vec<Ident>,
    pub load_defaults: Vec<TokenStream>,
    pub outs: Vec<Ident>,
    pub methods: TokenStream,
    pub solve: TokenStream,
}

/// The owned form's force parts (see [`Owned`]).
/// `kinematic`: the kinematic batch borrowed from the columns' fields
/// (`NAMEBatch { in_theta: &self.in_theta, .. }`; borrowed field by field,
/// so that the force columns can be borrowed beside it).
pub(super) fn owned(
    model: &Model,
    force_fields: &[(Ident, ForceField)],
    kinematic: &TokenStream,
) -> Owned {
    let names = TypeNames::of(model);
    let fb_ty = format_ident!("{}ForcesBatch", names.name);
    let forces_ty = &names.forces;
    let loads: Vec<Ident> = load_fields(model).into_iter().map(|(f, _)| f).collect();
    let load_defaults = model
        .kinetics
        .loads
        .iter()
        .map(|(_, v)| crate::value::lit(*v))
        .collect();
    let outs: Vec<Ident> = columns(force_fields).into_iter().map(|c| c.field).collect();
    let rebuilt = rebuild(&names, force_fields, &quote!(self));
    let methods = quote! {
        /// The columns as the borrowed batch of `solve_batch_forces`
        /// (kinematics and force analysis).
        #[inline]
        pub fn as_forces_batch(&mut self) -> #fb_ty<'_, T> {
            #fb_ty {
                batch: #kinematic,
                #(#loads: &self.#loads,)*
                #(#outs: &mut self.#outs,)*
            }
        }
        /// Element `k`'s force analysis as the scalar struct, `None` when
        /// `k` is out of range, a column is shorter, or the element's
        /// status is not 0.
        #[inline]
        pub fn forces_at(&self, k: usize) -> ::core::option::Option<#forces_ty<T>>
        where
            T: ::mechanism::Real,
        {
            if self.status.get(k) != ::core::option::Option::Some(&0) #(|| self.#outs.len() <= k)* {
                return ::core::option::Option::None;
            }
            ::core::option::Option::Some(#rebuilt)
        }
    };
    Owned {
        loads,
        load_defaults,
        outs,
        methods,
        solve: quote!(self.solve_batch_forces(&mut columns.as_forces_batch())),
    }
}
