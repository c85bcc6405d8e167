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

use crate::model::{Kind, Level, Local, Mode, Model, Origin};
use crate::plan::Plan;
use crate::value::{lit, Value};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use std::collections::BTreeMap;
use syn::Ident;

/// Emits the batch struct, its `BatchSplit` impl and `solve_batch`.
/// `inputs`: the driver inputs; `outputs`: the position outputs with their
/// types (`Point2<T>` for points, `T` otherwise; velocity and acceleration
/// outputs have the same names).
pub fn emit(
    model: &Model,
    plan: &Plan,
    inputs: &[Ident],
    outputs: &[(Ident, TokenStream)],
) -> TokenStream {
    let kept: Vec<(Ident, TokenStream)> = outputs
        .iter()
        .filter(|(o, _)| !given(model, o))
        .cloned()
        .collect();
    let outputs = &kept[..];
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
    // A point `P` gives the slices `pos_P_x` and `pos_P_y`, a link angle or
    // slide `s` the slice `pos_s`: a scalar output named `P_x` or `P_y`
    // beside a point output `P` would declare a field twice (rustc's errors
    // then point into the macro). Say which names meet instead.
    let mut errors = TokenStream::new();
    for (o, ty) in outputs {
        if ty.to_string().contains("Point2") {
            continue;
        }
        let s = o.to_string();
        let point = outputs.iter().find(|(p, t)| {
            t.to_string().contains("Point2") && [format!("{p}_x"), format!("{p}_y")].contains(&s)
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
    if !errors.is_empty() {
        return errors;
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
    let (lane_method, lane_call, lane_skip, has_lane) =
        match lane(model, plan, &all_in, outputs, levels.len()) {
            Some((m, c)) => (
                m,
                c,
                quote!(if b.status[k] == 0 {
                    continue;
                }),
                true,
            ),
            None => (
                TokenStream::new(),
                TokenStream::new(),
                TokenStream::new(),
                false,
            ),
        };
    let lane_block_skip = if has_lane {
        quote!(
            if b.status[start..end].iter().fold(0u8, |acc, s| acc | s) == 0 {
                start = end;
                continue;
            }
        )
    } else {
        TokenStream::new()
    };
    let method_doc = format!(
        "Evaluates every element of [`{batch_ty}`]: outputs into its slices (zero where an element failed), a status byte per element; returns the number of failed elements. No allocation, no early return, no panic."
    );
    let allow_lints = crate::emit::allow_literal_lints();
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

        #allow_lints
        impl<T: ::mechanism::Real> #name<T> {
            #[doc = #method_doc]
            #[inline]
            #[allow(non_snake_case, unused_variables)]
            pub fn solve_batch(&self, b: &mut #batch_ty<'_, T>) -> usize {
                let n = b.len();
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
                        #eval
                        let code = #status_expr;
                        #(#writes)*
                        b.status[k] = code;
                        failed += (code != 0) as usize;
                    }
                    start = end;
                }
                failed
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

/// `true` for an output the batch leaves out because the caller has it
/// already: a ground point (its position is in the definition, its
/// velocity and acceleration are zero) and the link of a crank (its angle is
/// the element's input, its rates the input's rates). Writing them for every
/// element would be memory traffic only.
fn given(model: &Model, output: &Ident) -> bool {
    model.stmts.iter().any(|s| match &s.kind {
        Kind::Ground { .. } => s.name == *output,
        Kind::Crank { .. } => s.links.first() == Some(output),
        _ => false,
    })
}

/// Per-statement names of the lane code: a point's position, velocity and
/// acceleration components.
fn pv(prefix: &str, name: &Ident) -> (Ident, Ident) {
    (
        format_ident!("{}_{}_x", prefix, name),
        format_ident!("{}_{}_y", prefix, name),
    )
}

/// A link in the lane code: unit axis, angle expression, angular velocity
/// and acceleration (expressions: a link that turns with a guide's body uses
/// that body's, a link that never turns `zero`).
struct LaneLink {
    axis: (TokenStream, TokenStream),
    angle: TokenStream,
    omega: TokenStream,
    alpha: TokenStream,
}

impl LaneLink {
    /// A link along the vector `(x, y)`, divided by `length` when given (a
    /// unit vector otherwise): its axis, its angle (`lane::angle` of the
    /// vector: a positive factor does not change it), its rates.
    fn along(
        ln: &TokenStream,
        (x, y): (TokenStream, TokenStream),
        length: Option<&TokenStream>,
        omega: TokenStream,
        alpha: TokenStream,
    ) -> LaneLink {
        let axis = match length {
            Some(l) => (quote!((#x / #l)), quote!((#y / #l))),
            None => (x.clone(), y.clone()),
        };
        LaneLink {
            axis,
            angle: quote!(#ln::angle(#y, #x)),
            omega,
            alpha,
        }
    }
}

/// A guide in the lane code: the `mechanism::lane::Line` local, the body's
/// motion as `Option<&LineVelocity>` / `Option<&LineAcceleration>`
/// expressions (`None` for a fixed guide, so its terms fold away), and the
/// body's angular velocity and acceleration (for the blocks sliding on it).
struct LaneGuide {
    line: Ident,
    gv: TokenStream,
    ga: TokenStream,
    omega: TokenStream,
    alpha: TokenStream,
}

/// A unit vector at `angle` as two expressions: literals when the angle is
/// literal, else a local computed once before the loop (named `id`) with the
/// scalar `geometry::unit`, as the scalar path does.
fn unit(angle: &Value, id: Ident, pre: &mut TokenStream) -> (TokenStream, TokenStream) {
    match angle.fold() {
        Some(a) => {
            let (s, c) = a.sin_cos();
            (lit(c), lit(s))
        }
        None => {
            let a = angle.emit();
            pre.extend(quote!(let #id = ::mechanism::geometry::unit(#a);));
            (quote!(#id.x), quote!(#id.y))
        }
    }
}

/// The sum of `terms` as a balanced tree of additions (`(a + b) + (c + d)`):
/// the same check as adding them one by one, with a dependency chain of
/// `log2(n)` additions instead of `n`, which a long loop body waits on.
fn tree_sum(terms: &[TokenStream]) -> Option<TokenStream> {
    match terms {
        [] => None,
        [t] => Some(t.clone()),
        _ => {
            let (lo, hi) = terms.split_at(terms.len() / 2);
            let (a, b) = (tree_sum(lo)?, tree_sum(hi)?);
            Some(quote!((#a + #b)))
        }
    }
}

fn sign(mode: &Mode) -> TokenStream {
    lit(match mode {
        Mode::Plus => 1.0,
        Mode::Minus => -1.0,
    })
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
/// `mechanism::lane`, writes its outputs and a status of 0 (ok) or 255 (to be
/// evaluated again by the scalar path, which writes zeros and the real
/// status). The checks of `mechanism::lane` are stricter than the scalar
/// ones, so an element the kernel accepts is one the scalar path accepts.
/// Values that do not depend on the element (a guide's direction given by a
/// run-time parameter) are computed once, before the loop, by the scalar
/// functions the scalar path uses.
fn lane(
    model: &Model,
    plan: &Plan,
    all_in: &[&Ident],
    outputs: &[(Ident, TokenStream)],
    levels: usize,
) -> Option<(TokenStream, TokenStream)> {
    let real = quote!(<T as ::mechanism::Real>);
    let ln = quote!(::mechanism::lane);
    let none = quote!(::core::option::Option::None);
    let mut pre = TokenStream::new();
    let mut body = TokenStream::new();
    let mut points: BTreeMap<String, ()> = BTreeMap::new();
    let mut links: BTreeMap<String, LaneLink> = BTreeMap::new();
    let mut guides: BTreeMap<String, LaneGuide> = BTreeMap::new();
    // Slide displacements by name: value at each level.
    let mut slides: BTreeMap<String, [TokenStream; 3]> = BTreeMap::new();
    let vel = levels > 1;
    let acc = levels > 2;
    let zero = quote!(zero);
    let still = || (quote!(zero), quote!(zero));
    // Only the statements the outputs need, as in the scalar path (a failing
    // statement nobody asked for must not send elements to the scalar path).
    for &i in &plan.solve {
        let stmt = &model.stmts[i];
        let name = &stmt.name;
        let (px, py) = pv("p", name);
        let (vx, vy) = pv("v", name);
        let (ax_, ay_) = pv("a", name);
        let g = format_ident!("g_{}", name);
        let known = |p: &Ident| points.contains_key(&p.to_string());
        // Point `p`'s position, velocity and acceleration locals.
        let point = |p: &Ident| (pv("p", p), pv("v", p), pv("a", p));
        let link_of = |k: usize| stmt.links.get(k).map(|l| l.to_string());
        let own_rates = |k: usize| -> Option<(Ident, Ident)> {
            let l = stmt.links.get(k)?;
            Some((format_ident!("w_{}", l), format_ident!("al_{}", l)))
        };
        // Slide locals of slot `k`: (position, velocity, acceleration).
        let slide_ids = |k: usize| {
            (
                format_ident!("s{}_{}", k, name),
                format_ident!("sd{}_{}", k, name),
                format_ident!("sdd{}_{}", k, name),
            )
        };
        let mut defines_point = true;
        let mut checked: Vec<TokenStream> = Vec::new();
        let mut new_links: Vec<(String, LaneLink)> = Vec::new();
        let mut new_slides: Vec<(usize, [TokenStream; 3])> = Vec::new();
        match &stmt.kind {
            Kind::Ground { x, y } => {
                let (x, y) = (x.emit(), y.emit());
                body.extend(quote! {
                    let #px = #x; let #py = #y;
                    let #vx = zero; let #vy = zero;
                    let #ax_ = zero; let #ay_ = zero;
                });
            }
            Kind::Guide {
                origin,
                angle,
                carrier,
            } => {
                defines_point = false;
                let line = format_ident!("ln_{}", name);
                let ((ox, oy), (ovx, ovy), (oax, oay)) = match origin {
                    Origin::Point(p) => {
                        if !known(p) {
                            return None;
                        }
                        let ((a, b), (c, d), (e, f)) = point(p);
                        (
                            (quote!(#a), quote!(#b)),
                            (quote!(#c), quote!(#d)),
                            (quote!(#e), quote!(#f)),
                        )
                    }
                    Origin::Coords(x, y) => ((x.emit(), y.emit()), still(), still()),
                };
                let guide = match carrier {
                    None => {
                        let (dx, dy) = unit(angle, format_ident!("u_{}", name), &mut pre);
                        body.extend(quote! {
                            let #line = #ln::Line { ox: #ox, oy: #oy, dx: #dx, dy: #dy };
                        });
                        LaneGuide {
                            line,
                            gv: none.clone(),
                            ga: none.clone(),
                            omega: zero.clone(),
                            alpha: zero.clone(),
                        }
                    }
                    Some(link) => {
                        let l = links.get(&link.to_string())?;
                        let (axx, axy) = &l.axis;
                        if angle.fold() == Some(0.0) {
                            body.extend(quote! {
                                let #line = #ln::Line { ox: #ox, oy: #oy, dx: #axx, dy: #axy };
                            });
                        } else {
                            let (lx, ly) = unit(angle, format_ident!("u_{}", name), &mut pre);
                            body.extend(quote! {
                                let #line = #ln::carried(#ox, #oy, (#axx, #axy), (#lx, #ly));
                            });
                        }
                        let (gv, ga) = (format_ident!("gv_{}", name), format_ident!("ga_{}", name));
                        let (omega, alpha) = (l.omega.clone(), l.alpha.clone());
                        if vel {
                            body.extend(quote! {
                                let #gv = #ln::LineVelocity { vx: #ovx, vy: #ovy, omega: #omega };
                            });
                        }
                        if acc {
                            body.extend(quote! {
                                let #ga = #ln::LineAcceleration { ax: #oax, ay: #oay, alpha: #alpha };
                            });
                        }
                        LaneGuide {
                            line,
                            gv: quote!(::core::option::Option::Some(&#gv)),
                            ga: quote!(::core::option::Option::Some(&#ga)),
                            omega,
                            alpha,
                        }
                    }
                };
                guides.insert(name.to_string(), guide);
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
                let ((ppx, ppy), (pvx, pvy), (pax, pay)) = point(pivot);
                let r = radius.emit();
                let th = format_ident!("in_{}", input);
                let (omega, alpha) = own_rates(0)?;
                body.extend(quote! {
                    let #g = #ln::crank(#ppx, #ppy, #r, #th[k]);
                    ok &= #g.ok;
                    let #px = #g.x; let #py = #g.y;
                });
                if vel {
                    let rate = format_ident!("rate_{}", input);
                    body.extend(quote! {
                        let #omega = #rate[k];
                        let (tx, ty) = #ln::rel_vel(#g.rx, #g.ry, #omega);
                        let #vx = #pvx + tx; let #vy = #pvy + ty;
                    });
                    checked.push(quote!(#omega));
                }
                if acc {
                    let accel = format_ident!("accel_{}", input);
                    body.extend(quote! {
                        let #alpha = #accel[k];
                        let (tx, ty) = #ln::rel_acc(#g.rx, #g.ry, #omega, #alpha);
                        let #ax_ = #pax + tx; let #ay_ = #pay + ty;
                    });
                    checked.push(quote!(#alpha));
                }
                new_links.push((
                    link_of(0)?,
                    LaneLink {
                        axis: (quote!(#g.ux), quote!(#g.uy)),
                        angle: quote!(#ln::wrap_angle(#th[k])),
                        omega: quote!(#omega),
                        alpha: quote!(#alpha),
                    },
                ));
            }
            Kind::Slider {
                guide,
                input,
                offset,
            } => {
                let gd = guides.get(&guide.to_string())?;
                let (line, gv, ga) = (&gd.line, &gd.gv, &gd.ga);
                let o = offset.emit();
                let s = format_ident!("in_{}", input);
                body.extend(quote! {
                    let (#px, #py) = #ln::slider(&#line, #o, #s[k]);
                });
                checked.push(quote!(#s[k]));
                if vel {
                    let rate = format_ident!("rate_{}", input);
                    body.extend(quote! {
                        let (#vx, #vy) = #ln::slider_velocity(&#line, #px, #py, #rate[k], #gv);
                    });
                    checked.push(quote!(#rate[k]));
                }
                if acc {
                    let (rate, accel) = (
                        format_ident!("rate_{}", input),
                        format_ident!("accel_{}", input),
                    );
                    body.extend(quote! {
                        let (#ax_, #ay_) = #ln::slider_acceleration(&#line, #px, #py, #rate[k], #accel[k], #gv, #ga);
                    });
                    checked.push(quote!(#accel[k]));
                }
                new_links.push((
                    link_of(0)?,
                    LaneLink::along(
                        &ln,
                        (quote!(#line.dx), quote!(#line.dy)),
                        None,
                        gd.omega.clone(),
                        gd.alpha.clone(),
                    ),
                ));
            }
            Kind::Rrr { a, l1, b, mode, .. }
            | Kind::Actuator {
                a, l: l1, b, mode, ..
            } => {
                if !known(a) || !known(b) || stmt.links.len() != 2 {
                    return None;
                }
                let actuator = match &stmt.kind {
                    Kind::Actuator { input, .. } => Some(input),
                    _ => None,
                };
                let ((apx, apy), (avx, avy), (aax, aay)) = point(a);
                let ((bpx, bpy), (bvx, bvy), (bax, bay)) = point(b);
                let l1 = l1.emit();
                let l2 = match (&stmt.kind, actuator) {
                    (Kind::Rrr { l2, .. }, _) => l2.emit(),
                    (_, Some(input)) => {
                        let s = format_ident!("in_{}", input);
                        checked.push(quote!(#s[k]));
                        quote!(#s[k])
                    }
                    _ => return None,
                };
                let sign = sign(mode);
                let (w1, al1) = own_rates(0)?;
                let (w2, al2) = own_rates(1)?;
                body.extend(quote! {
                    let #g = #ln::rrr(#apx, #apy, #l1, #bpx, #bpy, #l2, #sign);
                    ok &= #g.ok;
                    let #px = #g.x; let #py = #g.y;
                });
                if vel {
                    let rates = match actuator {
                        None => quote!(#ln::rrr_rates(&#g, #bvx - #avx, #bvy - #avy)),
                        Some(input) => {
                            let rate = format_ident!("rate_{}", input);
                            checked.push(quote!(#rate[k]));
                            quote!(#ln::actuator_rates(&#g, #bvx - #avx, #bvy - #avy, #l2, #rate[k]))
                        }
                    };
                    body.extend(quote! {
                        ok &= #g.ok_rate;
                        let (#w1, #w2) = #rates;
                        let (tx, ty) = #ln::rel_vel(#g.r1x, #g.r1y, #w1);
                        let #vx = #avx + tx; let #vy = #avy + ty;
                    });
                    checked.extend([quote!(#w1), quote!(#w2)]);
                }
                if acc {
                    let accels = match actuator {
                        None => quote!(#ln::rrr_accels(&#g, #bax - #aax, #bay - #aay, #w1, #w2)),
                        Some(input) => {
                            let (rate, accel) = (
                                format_ident!("rate_{}", input),
                                format_ident!("accel_{}", input),
                            );
                            checked.push(quote!(#accel[k]));
                            quote!(#ln::actuator_accels(&#g, #bax - #aax, #bay - #aay, #l2, #rate[k], #accel[k], #w1, #w2))
                        }
                    };
                    body.extend(quote! {
                        let (#al1, #al2) = #accels;
                        let (tx, ty) = #ln::rel_acc(#g.r1x, #g.r1y, #w1, #al1);
                        let #ax_ = #aax + tx; let #ay_ = #aay + ty;
                    });
                    checked.extend([quote!(#al1), quote!(#al2)]);
                }
                new_links.push((
                    link_of(0)?,
                    LaneLink::along(
                        &ln,
                        (quote!(#g.r1x), quote!(#g.r1y)),
                        Some(&quote!(#l1)),
                        quote!(#w1),
                        quote!(#al1),
                    ),
                ));
                new_links.push((
                    link_of(1)?,
                    LaneLink::along(
                        &ln,
                        (quote!(#g.r2x), quote!(#g.r2y)),
                        Some(&quote!(#l2)),
                        quote!(#w2),
                        quote!(#al2),
                    ),
                ));
            }
            Kind::Rrp {
                a,
                l,
                guide,
                mode,
                offset,
            } => {
                if !known(a) {
                    return None;
                }
                let gd = guides.get(&guide.to_string())?;
                let (line, gv, ga) = (&gd.line, &gd.gv, &gd.ga);
                let ((apx, apy), (avx, avy), (aax, aay)) = point(a);
                let (l, o, sign) = (l.emit(), offset.emit(), sign(mode));
                let (w1, al1) = own_rates(0)?;
                let (s, sd, sdd) = slide_ids(0);
                body.extend(quote! {
                    let #g = #ln::rrp(#apx, #apy, #l, &#line, #o, #sign);
                    ok &= #g.ok;
                    let #px = #g.x; let #py = #g.y;
                    let #s = #g.s;
                });
                checked.push(quote!(#s));
                if vel {
                    body.extend(quote! {
                        ok &= #g.ok_rate;
                        let (#w1, #sd, #vx, #vy) = #ln::rrp_rates(&#g, &#line, #avx, #avy, #gv);
                    });
                    checked.extend([quote!(#w1), quote!(#sd)]);
                }
                if acc {
                    body.extend(quote! {
                        let (#al1, #sdd, #ax_, #ay_) = #ln::rrp_accels(&#g, &#line, #aax, #aay, #w1, #sd, #gv, #ga);
                    });
                    checked.extend([quote!(#al1), quote!(#sdd)]);
                }
                new_slides.push((0, [quote!(#s), quote!(#sd), quote!(#sdd)]));
                new_links.push((
                    link_of(0)?,
                    LaneLink::along(
                        &ln,
                        (quote!(#g.r1x), quote!(#g.r1y)),
                        Some(&quote!(#l)),
                        quote!(#w1),
                        quote!(#al1),
                    ),
                ));
                new_links.push((
                    link_of(1)?,
                    LaneLink::along(
                        &ln,
                        (quote!(#line.dx), quote!(#line.dy)),
                        None,
                        gd.omega.clone(),
                        gd.alpha.clone(),
                    ),
                ));
            }
            Kind::Rpr { a, b, mode, offset } => {
                if !known(a) || !known(b) {
                    return None;
                }
                defines_point = false;
                let ((apx, apy), (avx, avy), (aax, aay)) = point(a);
                let ((bpx, bpy), (bvx, bvy), (bax, bay)) = point(b);
                let (o, sign) = (offset.emit(), sign(mode));
                let (w, al) = own_rates(0)?;
                let (s, sd, sdd) = slide_ids(0);
                body.extend(quote! {
                    let #g = #ln::rpr(#apx, #apy, #bpx, #bpy, #o, #sign);
                    ok &= #g.ok;
                    let #s = #g.s;
                });
                checked.extend([quote!(#s), quote!(#g.ux), quote!(#g.uy)]);
                if vel {
                    body.extend(quote! {
                        ok &= #g.ok_rate;
                        let (#w, #sd) = #ln::rpr_rates(&#g, #avx - #bvx, #avy - #bvy);
                    });
                    checked.extend([quote!(#w), quote!(#sd)]);
                }
                if acc {
                    body.extend(quote! {
                        let (#al, #sdd) = #ln::rpr_accels(&#g, #aax - #bax, #aay - #bay, #w, #sd);
                    });
                    checked.extend([quote!(#al), quote!(#sdd)]);
                }
                new_slides.push((0, [quote!(#s), quote!(#sd), quote!(#sdd)]));
                for k in 0..2 {
                    new_links.push((
                        link_of(k)?,
                        LaneLink::along(
                            &ln,
                            (quote!(#g.ux), quote!(#g.uy)),
                            None,
                            quote!(#w),
                            quote!(#al),
                        ),
                    ));
                }
            }
            Kind::Prp {
                g1,
                g2,
                offset1,
                offset2,
            } => {
                let (d1, d2) = (guides.get(&g1.to_string())?, guides.get(&g2.to_string())?);
                let (l1, gv1, ga1) = (&d1.line, &d1.gv, &d1.ga);
                let (l2, gv2, ga2) = (&d2.line, &d2.gv, &d2.ga);
                let (o1, o2) = (offset1.emit(), offset2.emit());
                let (s1, sd1, sdd1) = slide_ids(0);
                let (s2, sd2, sdd2) = slide_ids(1);
                body.extend(quote! {
                    let #g = #ln::prp(&#l1, #o1, &#l2, #o2);
                    ok &= #g.ok;
                    let #px = #g.x; let #py = #g.y;
                    let #s1 = #g.s1; let #s2 = #g.s2;
                });
                checked.extend([quote!(#s1), quote!(#s2)]);
                if vel {
                    body.extend(quote! {
                        let (#sd1, #sd2, #vx, #vy) = #ln::prp_rates(&#g, &#l1, &#l2, #gv1, #gv2);
                    });
                    checked.extend([quote!(#sd1), quote!(#sd2)]);
                }
                if acc {
                    body.extend(quote! {
                        let (#sdd1, #sdd2, #ax_, #ay_) = #ln::prp_accels(&#g, &#l1, &#l2, #sd1, #sd2, #gv1, #ga1, #gv2, #ga2);
                    });
                    checked.extend([quote!(#sdd1), quote!(#sdd2)]);
                }
                new_slides.push((0, [quote!(#s1), quote!(#sd1), quote!(#sdd1)]));
                new_slides.push((1, [quote!(#s2), quote!(#sd2), quote!(#sdd2)]));
                for (k, (d, l)) in [(d1, l1), (d2, l2)].into_iter().enumerate() {
                    new_links.push((
                        link_of(k)?,
                        LaneLink::along(
                            &ln,
                            (quote!(#l.dx), quote!(#l.dy)),
                            None,
                            d.omega.clone(),
                            d.alpha.clone(),
                        ),
                    ));
                }
            }
            Kind::Rpp {
                a,
                guide,
                slot,
                offset,
            } => {
                if !known(a) {
                    return None;
                }
                let gd = guides.get(&guide.to_string())?;
                let (line, gv, ga) = (&gd.line, &gd.gv, &gd.ga);
                let ((apx, apy), (avx, avy), (aax, aay)) = point(a);
                let (lx, ly) = unit(slot, format_ident!("u_{}", name), &mut pre);
                let o = offset.emit();
                let (s1, sd1, sdd1) = slide_ids(0);
                let (s2, sd2, sdd2) = slide_ids(1);
                body.extend(quote! {
                    let #g = #ln::rpp(#apx, #apy, &#line, #o, #lx, #ly);
                    ok &= #g.ok;
                    let #px = #g.x; let #py = #g.y;
                    let #s1 = #g.s1; let #s2 = #g.s2;
                });
                checked.extend([quote!(#s1), quote!(#s2)]);
                if vel {
                    body.extend(quote! {
                        let (#sd1, #sd2, #vx, #vy) = #ln::rpp_rates(&#g, &#line, #apx, #apy, #avx, #avy, #gv);
                    });
                    checked.extend([quote!(#sd1), quote!(#sd2)]);
                }
                if acc {
                    body.extend(quote! {
                        let (#sdd1, #sdd2, #ax_, #ay_) = #ln::rpp_accels(&#g, &#line, #apx, #apy, #aax, #aay, #sd1, #sd2, #gv, #ga);
                    });
                    checked.extend([quote!(#sdd1), quote!(#sdd2)]);
                }
                new_slides.push((0, [quote!(#s1), quote!(#sd1), quote!(#sdd1)]));
                new_slides.push((1, [quote!(#s2), quote!(#sd2), quote!(#sdd2)]));
                // Link 1 (the block) along the slot, link 2 (the yoke) along
                // the guide, as in the scalar path.
                new_links.push((
                    link_of(0)?,
                    LaneLink::along(
                        &ln,
                        (quote!(#g.wx), quote!(#g.wy)),
                        None,
                        gd.omega.clone(),
                        gd.alpha.clone(),
                    ),
                ));
                new_links.push((
                    link_of(1)?,
                    LaneLink::along(
                        &ln,
                        (quote!(#line.dx), quote!(#line.dy)),
                        None,
                        gd.omega.clone(),
                        gd.alpha.clone(),
                    ),
                ));
            }
            Kind::Point { link, from, local } => {
                let l = links.get(&link.to_string())?;
                if !known(from) {
                    return None;
                }
                let (lx, ly) = match local {
                    Local::Cartesian(x, y) => (x.emit(), y.emit()),
                    Local::Polar(d, a) => match (d.fold(), a.fold()) {
                        (Some(d), Some(a)) => {
                            let (s, c) = a.sin_cos();
                            (lit(d * c), lit(d * s))
                        }
                        _ => {
                            // Once, before the loop, as the scalar path does.
                            let (ux, uy) = unit(a, format_ident!("u_{}", name), &mut pre);
                            let d = d.emit();
                            let lp = format_ident!("lp_{}", name);
                            pre.extend(quote!(let #lp = (#ux * #d, #uy * #d);));
                            (quote!(#lp.0), quote!(#lp.1))
                        }
                    },
                };
                let (ux, uy) = &l.axis;
                let ((fpx, fpy), (fvx, fvy), (fax, fay)) = point(from);
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
                        let (tx, ty) = #ln::rel_vel(#ox, #oy, #omega);
                        let #vx = #fvx + tx; let #vy = #fvy + ty;
                    });
                }
                if acc {
                    body.extend(quote! {
                        let (tx, ty) = #ln::rel_acc(#ox, #oy, #omega, #alpha);
                        let #ax_ = #fax + tx; let #ay_ = #fay + ty;
                    });
                }
            }
        }
        // Every value the scalar path checks is checked here too (finite),
        // outputs or not, so that an element the kernel accepts is one the
        // scalar path accepts: summed (one add each), the sum is finite
        // unless one of them is not (or, harmlessly, the sum overflows:
        // the element then goes to the scalar path).
        if defines_point {
            checked.extend([quote!(#px), quote!(#py)]);
            if vel {
                checked.extend([quote!(#vx), quote!(#vy)]);
            }
            if acc {
                checked.extend([quote!(#ax_), quote!(#ay_)]);
            }
            points.insert(name.to_string(), ());
        }
        if let Some(sum) = tree_sum(&checked) {
            body.extend(quote!(chk += #sum;));
        }
        for (l, info) in new_links {
            links.insert(l, info);
        }
        for (slot, values) in new_slides {
            let slide = match (&stmt.kind, stmt.slides.get(slot)) {
                (_, Some(Some(s))) => Some(s.to_string()),
                (Kind::Rpr { .. }, _) => Some(name.to_string()),
                _ => None,
            };
            if let Some(s) = slide {
                slides.insert(s, values);
            }
        }
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
                let v = match (links.get(&o.to_string()), slides.get(&o.to_string())) {
                    (Some(l), _) => match li {
                        0 => l.angle.clone(),
                        1 => l.omega.clone(),
                        _ => l.alpha.clone(),
                    },
                    (None, Some(s)) => s[li].clone(),
                    (None, None) => return None,
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
            #pre
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

#[cfg(test)]
mod name_tests {
    /// A slide named `B_x` beside a point `B`: both would be the batch
    /// field `pos_B_x`. One clear error on the slide's name, not rustc's
    /// duplicate-field errors inside the macro.
    #[test]
    fn scalar_named_like_a_point_coordinate() {
        let out = crate::expand(quote::quote! {
            pub SlideNamedLikeCoord {
                let O = ground(0.0, 0.0);
                let line = guide(O, 0 deg);
                let A = crank(O, 0.1, theta) as link2;
                let B = rrp(A, 0.4, line, plus) as (link3, slider) slide B_x;
            }
        })
        .to_string();
        assert!(out.contains("compile_error"), "{out}");
        assert!(
            out.contains("`B_x` and the coordinates of point `B`"),
            "{out}"
        );
        assert_eq!(out.matches("compile_error").count(), 1, "{out}");
    }
}
