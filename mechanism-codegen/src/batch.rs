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

use crate::model::{Kind, Level, Local, Mode, Model};
use crate::value::lit;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use std::collections::BTreeMap;
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
    let (lane_method, lane_call, lane_skip) =
        match lane(model, &all_in, inputs, outputs, levels.len()) {
            Some((m, c)) => (
                m,
                c,
                quote!(if b.status[k] == 0 {
                    continue;
                }),
            ),
            None => (TokenStream::new(), TokenStream::new(), TokenStream::new()),
        };
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
                #lane_call
                for k in 0..n {
                    #lane_skip
                    #eval
                    let code = #status_expr;
                    #(#writes)*
                    b.status[k] = code;
                    failed += (code != 0) as usize;
                }
                failed
            }
            #lane_method
        }
    }
}

/// Per-statement names of the lane code: a point's position, velocity and
/// acceleration components.
fn pv(prefix: &str, name: &Ident) -> (Ident, Ident) {
    (
        format_ident!("{}_{}_x", prefix, name),
        format_ident!("{}_{}_y", prefix, name),
    )
}

/// A link in the lane code: unit axis, angle expression, rate and acceleration names.
struct LaneLink {
    axis: (TokenStream, TokenStream),
    angle: TokenStream,
    omega: Ident,
    alpha: Ident,
}

/// The vectorizable kernel (`__lane_batch`) and the code that calls it, when
/// every statement of the definition has a lane version (ground points,
/// cranks, RRR groups, points on their links with literal polar or any
/// Cartesian coordinates); `None` otherwise (the batch is then evaluated by
/// the scalar path alone).
///
/// The kernel takes every slice as its own argument (so the compiler knows
/// they do not overlap: no run-time alias checks that would stop the
/// vectorizer), evaluates every element branch-free with
/// `mechanism::lane`, writes its outputs and a status of 0 (ok) or 255 (to be
/// evaluated again by the scalar path, which writes zeros and the real
/// status). The checks of `mechanism::lane` are stricter than the scalar
/// ones, so an element the kernel accepts is one the scalar path accepts.
fn lane(
    model: &Model,
    all_in: &[&Ident],
    inputs: &[Ident],
    outputs: &[(Ident, TokenStream)],
    levels: usize,
) -> Option<(TokenStream, TokenStream)> {
    let plan = crate::plan::plan(model).ok()?;
    let real = quote!(<T as ::mechanism::Real>);
    let mut body = TokenStream::new();
    let mut points: BTreeMap<String, ()> = BTreeMap::new();
    let mut links: BTreeMap<String, LaneLink> = BTreeMap::new();
    let vel = levels > 1;
    let acc = levels > 2;
    for &i in &plan.order {
        let stmt = &model.stmts[i];
        let name = &stmt.name;
        let (px, py) = pv("p", name);
        let (vx, vy) = pv("v", name);
        let (ax_, ay_) = pv("a", name);
        let g = format_ident!("g_{}", name);
        let known = |p: &Ident| points.contains_key(&p.to_string());
        match &stmt.kind {
            Kind::Ground { x, y } => {
                let (x, y) = (x.emit(), y.emit());
                body.extend(quote! {
                    let #px = #x; let #py = #y;
                    let #vx = zero; let #vy = zero;
                    let #ax_ = zero; let #ay_ = zero;
                });
            }
            Kind::Crank {
                pivot,
                radius,
                input,
                ..
            } => {
                if !known(pivot) {
                    return None;
                }
                let (ppx, ppy) = pv("p", pivot);
                let (pvx, pvy) = pv("v", pivot);
                let (pax, pay) = pv("a", pivot);
                let r = radius.emit();
                let th = format_ident!("in_{}", input);
                let link = stmt.links.first()?;
                let omega = format_ident!("w_{}", link);
                let alpha = format_ident!("al_{}", link);
                body.extend(quote! {
                    let #g = ::mechanism::lane::crank(#ppx, #ppy, #r, #th[k]);
                    ok &= #g.ok;
                    let #px = #g.x; let #py = #g.y;
                });
                if vel {
                    let rate = format_ident!("rate_{}", input);
                    body.extend(quote! {
                        let #omega = #rate[k];
                        let (tx, ty) = ::mechanism::lane::rel_vel(#g.rx, #g.ry, #omega);
                        let #vx = #pvx + tx; let #vy = #pvy + ty;
                    });
                }
                if acc {
                    let accel = format_ident!("accel_{}", input);
                    body.extend(quote! {
                        let #alpha = #accel[k];
                        let (tx, ty) = ::mechanism::lane::rel_acc(#g.rx, #g.ry, #omega, #alpha);
                        let #ax_ = #pax + tx; let #ay_ = #pay + ty;
                    });
                }
                links.insert(
                    link.to_string(),
                    LaneLink {
                        axis: (quote!(#g.ux), quote!(#g.uy)),
                        angle: quote!(::mechanism::lane::wrap_angle(#th[k])),
                        omega,
                        alpha,
                    },
                );
            }
            Kind::Rrr { a, l1, b, l2, mode } => {
                if !known(a) || !known(b) || stmt.links.len() != 2 {
                    return None;
                }
                let (apx, apy) = pv("p", a);
                let (bpx, bpy) = pv("p", b);
                let (avx, avy) = pv("v", a);
                let (bvx, bvy) = pv("v", b);
                let (aax, aay) = pv("a", a);
                let (bax, bay) = pv("a", b);
                let (l1, l2) = (l1.emit(), l2.emit());
                let sign = lit(match mode {
                    Mode::Plus => 1.0,
                    Mode::Minus => -1.0,
                });
                let (w1, w2) = (
                    format_ident!("w_{}", stmt.links[0]),
                    format_ident!("w_{}", stmt.links[1]),
                );
                let (al1, al2) = (
                    format_ident!("al_{}", stmt.links[0]),
                    format_ident!("al_{}", stmt.links[1]),
                );
                body.extend(quote! {
                    let #g = ::mechanism::lane::rrr(#apx, #apy, #l1, #bpx, #bpy, #l2, #sign);
                    ok &= #g.ok;
                    let #px = #g.x; let #py = #g.y;
                });
                if vel {
                    body.extend(quote! {
                        ok &= #g.ok_rate;
                        let (#w1, #w2) = ::mechanism::lane::rrr_rates(&#g, #bvx - #avx, #bvy - #avy);
                        let (tx, ty) = ::mechanism::lane::rel_vel(#g.r1x, #g.r1y, #w1);
                        let #vx = #avx + tx; let #vy = #avy + ty;
                    });
                }
                if acc {
                    body.extend(quote! {
                        let (#al1, #al2) = ::mechanism::lane::rrr_accels(&#g, #bax - #aax, #bay - #aay, #w1, #w2);
                        let (tx, ty) = ::mechanism::lane::rel_acc(#g.r1x, #g.r1y, #w1, #al1);
                        let #ax_ = #aax + tx; let #ay_ = #aay + ty;
                    });
                }
                links.insert(
                    stmt.links[0].to_string(),
                    LaneLink {
                        axis: (quote!((#g.r1x / #l1)), quote!((#g.r1y / #l1))),
                        angle: quote!(::mechanism::lane::atan2(#g.r1y, #g.r1x)),
                        omega: w1,
                        alpha: al1,
                    },
                );
                links.insert(
                    stmt.links[1].to_string(),
                    LaneLink {
                        axis: (quote!((#g.r2x / #l2)), quote!((#g.r2y / #l2))),
                        angle: quote!(::mechanism::lane::atan2(#g.r2y, #g.r2x)),
                        omega: w2,
                        alpha: al2,
                    },
                );
            }
            Kind::Point { link, from, local } => {
                let l = links.get(&link.to_string())?;
                if !known(from) {
                    return None;
                }
                let (lx, ly) = match local {
                    Local::Cartesian(x, y) => (x.emit(), y.emit()),
                    Local::Polar(d, a) => {
                        let (d, a) = (d.fold()?, a.fold()?);
                        let (s, c) = a.sin_cos();
                        (lit(d * c), lit(d * s))
                    }
                };
                let (ux, uy) = &l.axis;
                let (fpx, fpy) = pv("p", from);
                let (fvx, fvy) = pv("v", from);
                let (fax, fay) = pv("a", from);
                let (ox, oy) = pv("o", name);
                body.extend(quote! {
                    let (lx, ly) = (#lx, #ly);
                    let #ox = #ux * lx - #uy * ly;
                    let #oy = #uy * lx + #ux * ly;
                    let #px = #fpx + #ox; let #py = #fpy + #oy;
                });
                let (omega, alpha) = (&l.omega, &l.alpha);
                if vel {
                    body.extend(quote! {
                        let (tx, ty) = ::mechanism::lane::rel_vel(#ox, #oy, #omega);
                        let #vx = #fvx + tx; let #vy = #fvy + ty;
                    });
                }
                if acc {
                    body.extend(quote! {
                        let (tx, ty) = ::mechanism::lane::rel_acc(#ox, #oy, #omega, #alpha);
                        let #ax_ = #fax + tx; let #ay_ = #fay + ty;
                    });
                }
            }
            _ => return None,
        }
        // Every value the scalar path checks is checked here too (finite),
        // outputs or not, so that an element the kernel accepts is one the
        // scalar path accepts: summed (one add each), the sum is finite
        // unless one of them is not (or, harmlessly, the sum overflows:
        // the element then goes to the scalar path).
        let mut checked = vec![px, py];
        if vel {
            checked.extend([vx, vy]);
        }
        if acc {
            checked.extend([ax_, ay_]);
        }
        for link in &stmt.links {
            if let Some(l) = links.get(&link.to_string()) {
                if vel {
                    checked.push(l.omega.clone());
                }
                if acc {
                    checked.push(l.alpha.clone());
                }
            }
        }
        body.extend(quote!(#(chk += #checked;)*));
        points.insert(name.to_string(), ());
    }
    // Outputs: (slice, value) per level.
    let mut params_out: Vec<Ident> = Vec::new();
    let mut writes = TokenStream::new();
    let prefixes = ["pos", "vel", "acc"];
    let lanes = ["p", "v", "a"];
    for li in 0..levels {
        for (o, ty) in outputs {
            let point = ty.to_string().contains("Point2");
            let pairs: Vec<(Ident, TokenStream)> = if point {
                if !points.contains_key(&o.to_string()) {
                    return None;
                }
                let (x, y) = pv(lanes[li], o);
                vec![
                    (format_ident!("{}_{}_x", prefixes[li], o), quote!(#x)),
                    (format_ident!("{}_{}_y", prefixes[li], o), quote!(#y)),
                ]
            } else {
                let l = links.get(&o.to_string())?;
                let v = match li {
                    0 => l.angle.clone(),
                    1 => {
                        let w = &l.omega;
                        quote!(#w)
                    }
                    _ => {
                        let a = &l.alpha;
                        quote!(#a)
                    }
                };
                vec![(format_ident!("{}_{}", prefixes[li], o), v)]
            };
            for (f, v) in pairs {
                // Angles are finite where their arguments are (checked above).
                writes.extend(quote! {
                    #f[k] = #v;
                });
                params_out.push(f);
            }
        }
    }
    let _ = inputs;
    let ins: Vec<&Ident> = all_in.to_vec();
    let method = quote! {
        /// The vectorizable part of [`Self::solve_batch`] (see `mechanism::lane`):
        /// every element branch-free; status 0, or 255 where the scalar path
        /// must evaluate the element again.
        #[doc(hidden)]
        #[inline]
        #[allow(non_snake_case, unused_variables, dead_code, clippy::too_many_arguments)]
        fn __lane_batch(&self, #(#ins: &[T],)* #(#params_out: &mut [T],)* status: &mut [::core::primitive::u8]) {
            let mut n = status.len();
            #(n = ::core::cmp::min(n, #ins.len());)*
            #(n = ::core::cmp::min(n, #params_out.len());)*
            #(let #ins = &#ins[..n];)*
            #(let #params_out = &mut #params_out[..n];)*
            let status = &mut status[..n];
            let zero = #real::lit(0.0);
            for k in 0..n {
                let mut ok = true;
                let mut chk = zero;
                #body
                #writes
                ok &= #real::finite(chk);
                status[k] = if ok { 0 } else { ::core::primitive::u8::MAX };
            }
        }
    };
    let call = quote! {
        self.__lane_batch(#(b.#ins,)* #(&mut *b.#params_out,)* &mut *b.status);
    };
    Some((method, call))
}
