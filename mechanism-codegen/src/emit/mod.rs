//! Stage 5, emit: straight-line Rust for one mechanism. Only what the scene asks
//! for is generated: no velocity code in a position-only scene, no `atan2`
//! unless a link angle is an output, and fixed points and guides pass `None`
//! so that their terms vanish at compile time.

pub mod batch;
pub mod check_fn;
pub mod describe;
pub mod forces;
pub mod reads;
pub mod self_test;
pub mod stub;

use crate::check::Findings;
use crate::model::{Kind, Level, Local, Mode, Model, Origin, Stmt};
use crate::plan::{Outputs, Plan};
use crate::value::{lit, Value};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use reads::{Analysis, Reads};
use std::collections::BTreeSet;
use syn::Ident;

/// Doc comments of the output fields, in the order points, links, slides.
/// The lints the generated impls allow: folded constants (the cosine of 45
/// deg, say) are long literals that clippy's `approx_constant` (deny by
/// default), `excessive_precision` and `unreadable_literal` would flag in the
/// user's crate (`tests/hygiene.rs`, `lint_clean`).
pub(crate) fn allow_literal_lints() -> TokenStream {
    quote!(#[allow(clippy::approx_constant, clippy::excessive_precision, clippy::unreadable_literal)])
}

fn output_docs(out: &Outputs, level: usize) -> Vec<String> {
    let (p, l, s) = match level {
        0 => (
            "Point `{}` (length units).",
            "Angle of link `{}` from +x (rad, in (-pi, pi], counter-clockwise).",
            "Slide displacement `{}` (length units).",
        ),
        1 => (
            "Velocity of point `{}` (length units/s).",
            "Angular velocity of link `{}` (rad/s, counter-clockwise positive).",
            "Rate of slide displacement `{}` (length units/s).",
        ),
        _ => (
            "Acceleration of point `{}` (length units/s^2).",
            "Angular acceleration of link `{}` (rad/s^2).",
            "Second derivative of slide displacement `{}` (length units/s^2).",
        ),
    };
    let fill = |t: &str, n: &Ident| t.replace("{}", &n.to_string());
    out.points
        .iter()
        .map(|n| fill(p, n))
        .chain(out.links.iter().map(|n| fill(l, n)))
        .chain(out.slides.iter().map(|(n, _, _)| fill(s, n)))
        .collect()
}

fn mode_tokens(mode: Mode) -> TokenStream {
    match mode {
        Mode::Plus => quote!(::mechanism::Mode::Plus),
        Mode::Minus => quote!(::mechanism::Mode::Minus),
    }
}

/// A unit vector at a given angle: folded at expansion time when literal.
fn unit_vector(angle: &Value) -> TokenStream {
    match angle.fold() {
        Some(a) => {
            let (s, c) = a.sin_cos();
            let (c, s) = (lit(c), lit(s));
            quote!(::mechanism::Vector2::new(#c, #s))
        }
        None => {
            let a = angle.emit();
            quote!(::mechanism::geometry::unit(#a))
        }
    }
}

/// The local variable of the position code that holds the user's name
/// `name` (a point, a guide, a link angle or a slide): `pos_NAME`. A bare
/// `let NAME = ..` would be a pattern, not a binding, wherever a constant,
/// static or unit struct of that name is in scope (`const G: f64 = 9.81;`
/// beside a point `G`), and would not compile. The velocity and acceleration
/// code already use `vel_NAME` and `acc_NAME`.
fn local(name: &Ident) -> Ident {
    format_ident!("pos_{}", name)
}

/// `.map_err(|e| e.in_group(NAME))?`: tags a core error with the statement's name.
pub(crate) fn tag(stmt: &Stmt) -> TokenStream {
    let name = stmt.name.to_string();
    quote!(.map_err(|e| e.in_group(#name))?)
}

/// A value of the position code the position struct may keep: its field
/// name, the local that holds it, and its type.
#[derive(Clone)]
struct Stored {
    field: Ident,
    local: Ident,
    ty: TokenStream,
}

impl Stored {
    fn new(field: &Ident, local: &Ident, ty: TokenStream) -> Self {
        Stored {
            field: field.clone(),
            local: local.clone(),
            ty,
        }
    }
}

/// The core type of a statement's solved position state (`grp_NAME`).
fn group_position_type(kind: &Kind) -> TokenStream {
    match kind {
        Kind::Crank { .. } => quote!(::mechanism::driver::crank::CrankPosition<T>),
        Kind::Slider { .. } => quote!(::mechanism::driver::slider::SliderPosition<T>),
        Kind::Actuator { .. } => quote!(::mechanism::driver::actuator::ActuatorPosition<T>),
        Kind::Rrr { .. } => quote!(::mechanism::dyad::rrr::RrrPosition<T>),
        Kind::Rrp { .. } => quote!(::mechanism::dyad::rrp::RrpPosition<T>),
        Kind::Rpr { .. } => quote!(::mechanism::dyad::rpr::RprPosition<T>),
        Kind::Prp { .. } => quote!(::mechanism::dyad::prp::PrpPosition<T>),
        Kind::Rpp { .. } => quote!(::mechanism::dyad::rpp::RppPosition<T>),
        Kind::Ground { .. } | Kind::Guide { .. } | Kind::Point { .. } => quote!(()),
    }
}

struct Emitter<'a> {
    model: &'a Model,
    plan: &'a Plan,
    /// Links whose unit axis is needed in position (points on them, carried guides).
    axes: BTreeSet<String>,
    /// Emitting `position_cos_sin`: cranks marked `as cos_sin` read
    /// `input_cs.NAME.cos` and `.sin`.
    cos_sin: bool,
}

impl Emitter<'_> {
    fn grp(&self, stmt: &Stmt) -> Ident {
        format_ident!("grp_{}", stmt.name)
    }

    /// Unit axis and raw direction of link `index` of `stmt`, in position
    /// scope (guides by their locals, [`local`]).
    fn link_direction(&self, stmt: &Stmt, index: usize) -> (TokenStream, TokenStream) {
        let g = self.grp(stmt);
        match (&stmt.kind, index) {
            (Kind::Crank { .. }, _) | (Kind::Rpr { .. }, _) => (quote!(#g.axis), quote!(#g.axis)),
            (Kind::Slider { guide, .. }, _)
            | (Kind::Rrp { guide, .. }, 1)
            | (Kind::Rpp { guide, .. }, 1) => {
                let guide = local(guide);
                (quote!(#guide.dir), quote!(#guide.dir))
            }
            (Kind::Actuator { l, .. }, 0)
            | (Kind::Rrp { l, .. }, 0)
            | (Kind::Rrr { l1: l, .. }, 0) => {
                let l = l.emit();
                (quote!(#g.r1 / #l), quote!(#g.r1))
            }
            (Kind::Rrr { l2, .. }, _) => {
                let l2 = l2.emit();
                (quote!(#g.r2 / #l2), quote!(#g.r2))
            }
            (Kind::Actuator { input, .. }, _) => (quote!(#g.r2 / input.#input), quote!(#g.r2)),
            (Kind::Prp { g1: guide, .. }, 0) | (Kind::Prp { g2: guide, .. }, _) => {
                let guide = local(guide);
                (quote!(#guide.dir), quote!(#guide.dir))
            }
            (Kind::Rpp { .. }, _) => (quote!(#g.slot), quote!(#g.slot)),
            _ => (
                quote!(::mechanism::Vector2::x()),
                quote!(::mechanism::Vector2::x()),
            ),
        }
    }

    /// Position statements for one statement; returns the code and the values
    /// the position struct may keep (those a later reader reads).
    fn position(&self, stmt: &Stmt) -> (TokenStream, Vec<Stored>) {
        let name = &local(&stmt.name);
        let own_ty = match stmt.kind {
            Kind::Guide { .. } => quote!(::mechanism::guide::Line<T>),
            _ => quote!(::mechanism::Point2<T>),
        };
        let own = Stored::new(&stmt.name, name, own_ty);
        let g = self.grp(stmt);
        let group = Stored::new(&g, &g, group_position_type(&stmt.kind));
        let t = tag(stmt);
        let mut fields = vec![];
        let code = match &stmt.kind {
            Kind::Ground { x, y } => {
                let (x, y) = (x.emit(), y.emit());
                fields.push(own);
                quote!(let #name = ::mechanism::Point2::new(#x, #y);)
            }
            Kind::Guide {
                origin,
                angle,
                carrier,
            } => {
                let origin = match origin {
                    Origin::Point(p) => {
                        let p = local(p);
                        quote!(#p)
                    }
                    Origin::Coords(x, y) => {
                        let (x, y) = (x.emit(), y.emit());
                        quote!(::mechanism::Point2::new(#x, #y))
                    }
                };
                let dir = match carrier {
                    None => unit_vector(angle),
                    Some(link) => {
                        let axis = format_ident!("axis_{}", link);
                        if angle.fold() == Some(0.0) {
                            quote!(#axis)
                        } else {
                            let u = unit_vector(angle);
                            quote!(::mechanism::link::local_offset(&#axis, &#u))
                        }
                    }
                };
                fields.push(own);
                quote!(let #name = ::mechanism::guide::Line { origin: #origin, dir: #dir };)
            }
            Kind::Crank {
                pivot,
                radius,
                input,
                cos_sin,
            } => {
                let (r, pivot_l) = (radius.emit(), local(pivot));
                fields.extend([group.clone(), own]);
                if *cos_sin && self.cos_sin {
                    quote! {
                        let #g = ::mechanism::driver::crank::position_cos_sin(&#pivot_l, #r, input_cs.#input.cos, input_cs.#input.sin) #t;
                        let #name = #g.tip;
                    }
                } else {
                    quote! {
                        let #g = ::mechanism::driver::crank::position(&#pivot_l, #r, input.#input) #t;
                        let #name = #g.tip;
                    }
                }
            }
            Kind::Slider {
                guide,
                input,
                offset,
            } => {
                let (o, guide_l) = (offset.emit(), local(guide));
                fields.extend([group.clone(), own]);
                quote! {
                    let #g = ::mechanism::driver::slider::position(&#guide_l, #o, input.#input) #t;
                    let #name = #g.p;
                }
            }
            Kind::Actuator {
                a,
                l,
                b,
                input,
                mode,
            } => {
                let (l, m) = (l.emit(), mode_tokens(*mode));
                let (a_l, b_l) = (local(a), local(b));
                fields.extend([group.clone(), own]);
                quote! {
                    let #g = ::mechanism::driver::actuator::position(&#a_l, #l, &#b_l, input.#input, #m) #t;
                    let #name = #g.c;
                }
            }
            Kind::Rrr { a, l1, b, l2, mode } => {
                let (l1, l2, m) = (l1.emit(), l2.emit(), mode_tokens(*mode));
                let (a_l, b_l) = (local(a), local(b));
                fields.extend([group.clone(), own]);
                quote! {
                    let #g = ::mechanism::dyad::rrr::position(&#a_l, #l1, &#b_l, #l2, #m) #t;
                    let #name = #g.c;
                }
            }
            Kind::Rrp {
                a,
                l,
                guide,
                mode,
                offset,
            } => {
                let (l, m, o) = (l.emit(), mode_tokens(*mode), offset.emit());
                let (a_l, guide_l) = (local(a), local(guide));
                fields.extend([group.clone(), own]);
                quote! {
                    let #g = ::mechanism::dyad::rrp::position(&#a_l, #l, &#guide_l, #o, #m) #t;
                    let #name = #g.c;
                }
            }
            Kind::Rpr { a, b, mode, offset } => {
                let (m, o) = (mode_tokens(*mode), offset.emit());
                let (a_l, b_l) = (local(a), local(b));
                fields.push(group.clone());
                quote! {
                    let #g = ::mechanism::dyad::rpr::position(&#a_l, &#b_l, #o, #m) #t;
                }
            }
            Kind::Prp {
                g1,
                g2,
                offset1,
                offset2,
            } => {
                let (o1, o2) = (offset1.emit(), offset2.emit());
                let (g1_l, g2_l) = (local(g1), local(g2));
                fields.extend([group.clone(), own]);
                quote! {
                    let #g = ::mechanism::dyad::prp::position(&#g1_l, #o1, &#g2_l, #o2) #t;
                    let #name = #g.c;
                }
            }
            Kind::Rpp {
                a,
                guide,
                slot,
                offset,
            } => {
                let (u, o) = (unit_vector(slot), offset.emit());
                let (a_l, guide_l) = (local(a), local(guide));
                fields.extend([group.clone(), own]);
                quote! {
                    let #g = ::mechanism::dyad::rpp::position(&#a_l, &#guide_l, #o, &#u) #t;
                    let #name = #g.q;
                }
            }
            Kind::Point {
                link,
                from,
                local: offset,
            } => {
                let axis = format_ident!("axis_{}", link);
                let from_l = local(from);
                let offset = match offset {
                    Local::Cartesian(x, y) => {
                        let (x, y) = (x.emit(), y.emit());
                        quote!(::mechanism::Vector2::new(#x, #y))
                    }
                    Local::Polar(d, a) => match (d.fold(), a.fold()) {
                        (Some(d), Some(a)) => {
                            let (s, c) = a.sin_cos();
                            let (x, y) = (lit(d * c), lit(d * s));
                            quote!(::mechanism::Vector2::new(#x, #y))
                        }
                        _ => {
                            let (d, u) = (d.emit(), unit_vector(a));
                            quote!((#u * #d))
                        }
                    },
                };
                fields.push(own);
                quote! {
                    let #name = ::mechanism::link::point_position(&#from_l, &#axis, &#offset) #t;
                }
            }
        };
        // Unit axes of the links this statement creates, where needed.
        let mut axes = TokenStream::new();
        for (j, link) in stmt.links.iter().enumerate() {
            if self.axes.contains(&link.to_string()) {
                let axis = format_ident!("axis_{}", link);
                let (unit, _) = self.link_direction(stmt, j);
                axes.extend(quote!(let #axis = #unit;));
                fields.push(Stored::new(&axis, &axis, quote!(::mechanism::Vector2<T>)));
            }
        }
        (quote!(#code #axes), fields)
    }
}

fn opt_point(
    point: &Ident,
    moving: &BTreeSet<String>,
    prefix: &str,
    scope: &TokenStream,
) -> TokenStream {
    if moving.contains(&point.to_string()) {
        let v = format_ident!("{}_{}", prefix, point);
        quote!(::core::option::Option::Some(&#scope #v))
    } else {
        quote!(::core::option::Option::None)
    }
}

/// Expands a valid, planned and checked model: the mechanism's items, its
/// `check()`, the expansion-time check's warnings and, with `#[self_test]`,
/// its tests.
pub fn mechanism(model: &Model, plan: &Plan, findings: &Findings) -> TokenStream {
    let check = check_fn::emit_check(model, plan, &findings.summary);
    let self_tests = model
        .self_test
        .map(|_| self_test::emit(model, plan, findings));
    // The position struct keeps the fields these read (`pos.NAME`).
    let mut readers = Reads::default();
    readers.scan(&check);
    if let Some(tests) = &self_tests {
        readers.scan(tests);
    }
    let mut out = items(model, plan, readers);
    let name = &model.name;
    let allow_lints = allow_literal_lints();
    out.extend(quote! {
        #allow_lints
        impl<T: ::mechanism::Real> #name<T> { #check }
    });
    out.extend(describe::emit(model, plan));
    out.extend(findings.warnings.clone());
    out.extend(self_tests);
    out
}

/// The mechanism's structs and analyses. `readers`: the reads of the other
/// generated code that reads position fields (the run-time `check()` and the
/// `#[self_test]` tests); with the later analyses' own reads they decide
/// which fields the position, velocity and acceleration structs keep
/// ([`reads`]).
fn items(model: &Model, plan: &Plan, readers: Reads) -> TokenStream {
    let name = &model.name;
    let vis = &model.vis;
    let docs = &model.docs;
    let position_ty = format_ident!("{}Position", name);
    let velocity_ty = format_ident!("{}Velocity", name);
    let acceleration_ty = format_ident!("{}Acceleration", name);
    let input_ty = format_ident!("{}Input", name);
    let solution_ty = format_ident!("{}Solution", name);
    let out = &plan.outputs;

    // Which link axes are needed in position.
    let mut axes = BTreeSet::new();
    for stmt in plan.solve.iter().map(|&i| &model.stmts[i]) {
        match &stmt.kind {
            Kind::Point { link, .. } => {
                axes.insert(link.to_string());
            }
            Kind::Guide {
                carrier: Some(link),
                ..
            } => {
                axes.insert(link.to_string());
            }
            _ => {}
        }
    }
    let em = Emitter {
        model,
        plan,
        axes,
        cos_sin: false,
    };

    // Points that move (everything but ground points and points on still links
    // measured from still points).
    let mut moving: BTreeSet<String> = BTreeSet::new();
    for &i in &plan.solve {
        let stmt = &model.stmts[i];
        match &stmt.kind {
            Kind::Ground { .. } | Kind::Guide { .. } | Kind::Rpr { .. } => {}
            Kind::Point { link, from, .. } => {
                if plan.turning_link(&link.to_string()).is_some()
                    || moving.contains(&from.to_string())
                {
                    moving.insert(stmt.name.to_string());
                }
            }
            _ => {
                moving.insert(stmt.name.to_string());
            }
        }
    }

    // ---------------- inputs and parameters ----------------
    let inputs: Vec<Ident> = model
        .stmts
        .iter()
        .filter_map(|s| s.kind.input().cloned())
        .collect();
    let param_names: Vec<&Ident> = model.params.iter().map(|(n, _)| n).collect();
    let param_defaults: Vec<TokenStream> = model.params.iter().map(|(_, v)| lit(*v)).collect();

    // ---------------- position ----------------
    let mut pos_code = TokenStream::new();
    let mut pos_fields: Vec<Stored> = Vec::new();
    for &i in &plan.solve {
        let (code, fields) = em.position(&model.stmts[i]);
        pos_code.extend(code);
        pos_fields.extend(fields);
    }
    // Output locals: link angles and slides. `cos_sin`: the code for
    // `position_cos_sin`, where a marked crank's angle is its axis' angle.
    let out_code = |cos_sin: bool| {
        let mut code = TokenStream::new();
        for link in &out.links {
            let info = &plan.links[&link.to_string()];
            let (_, dir) = em.link_direction(&model.stmts[info.stmt], info.index);
            // A crank's angle is its input: reduced to (-pi, pi], no atan2.
            let value = match &model.stmts[info.stmt].kind {
                Kind::Crank {
                    input,
                    cos_sin: marked,
                    ..
                } if !(cos_sin && *marked) => {
                    quote!(::mechanism::geometry::wrap_angle(input.#input))
                }
                _ => quote!(::mechanism::geometry::angle(&#dir)),
            };
            let l = local(link);
            code.extend(quote!(let #l = #value;));
        }
        for (slide, i, slot) in &out.slides {
            let g = em.grp(&model.stmts[*i]);
            let field = match (&model.stmts[*i].kind, slot) {
                (Kind::Prp { .. }, 0) | (Kind::Rpp { .. }, 0) => quote!(s1),
                (Kind::Prp { .. }, _) | (Kind::Rpp { .. }, _) => quote!(s2),
                _ => quote!(s),
            };
            let l = local(slide);
            code.extend(quote!(let #l = #g.#field;));
        }
        code
    };
    let pos_out_code = out_code(false);
    let mut pos_out_fields: Vec<(Ident, TokenStream)> = Vec::new();
    for p in &out.points {
        pos_out_fields.push((p.clone(), quote!(::mechanism::Point2<T>)));
    }
    for link in &out.links {
        pos_out_fields.push((link.clone(), quote!(T)));
    }
    for (slide, _, _) in &out.slides {
        pos_out_fields.push((slide.clone(), quote!(T)));
    }
    // The later analyses, generated first: the hidden fields of the
    // position, velocity and acceleration structs are only those a later
    // analysis (or `check()`, or the self-tests) reads (`pos.NAME`,
    // `vel.NAME`, `acc.NAME`); the rest are locals and never stored.
    let level = model.level;
    let forces = (level >= Level::Forces).then(|| forces::emit(model, plan, &moving));
    let accel_rates = (level >= Level::Acceleration).then(|| emit_rates(&em, &moving, out, true));
    let vel_rates = (level >= Level::Velocity).then(|| emit_rates(&em, &moving, out, false));
    let mut reads = readers;
    if let Some((code, _, _)) = &vel_rates {
        reads.scan(code);
    }
    if let Some((code, _, _)) = &accel_rates {
        reads.scan(code);
    }
    if let Some(f) = &forces {
        reads.scan(&f.methods);
    }
    let out_names: BTreeSet<String> = pos_out_fields.iter().map(|(n, _)| n.to_string()).collect();
    let hidden: Vec<&Stored> = pos_fields
        .iter()
        .filter(|f| {
            !out_names.contains(&f.field.to_string()) && reads.reads(Analysis::Position, &f.field)
        })
        .collect();
    let hidden_pos: Vec<&Ident> = hidden.iter().map(|f| &f.field).collect();
    let hidden_pos_locals: Vec<&Ident> = hidden.iter().map(|f| &f.local).collect();
    let hidden_pos_types: Vec<&TokenStream> = hidden.iter().map(|f| &f.ty).collect();
    // The inputs, kept when a later analysis reads them (a slider's position).
    let keep_input = reads.reads(Analysis::Position, &format_ident!("input"));
    let (input_field, input_init) = if keep_input {
        (
            quote!(#[doc(hidden)] pub input: #input_ty<T>,),
            quote!(input,),
        )
    } else {
        (TokenStream::new(), TokenStream::new())
    };
    let (pos_out_names, pos_out_types): (Vec<Ident>, Vec<TokenStream>) =
        pos_out_fields.iter().cloned().unzip();
    // A struct none of whose fields has the type `T` (`outputs { }`, or only
    // what no later code reads) needs a marker, or rustc rejects the unused
    // parameter.
    let marker = |empty: bool| {
        if empty {
            (
                quote!(#[doc(hidden)] pub _scalar: ::core::marker::PhantomData<T>,),
                quote!(_scalar: ::core::marker::PhantomData,),
            )
        } else {
            (TokenStream::new(), TokenStream::new())
        }
    };
    let (pos_marker, pos_marker_init) =
        marker(pos_out_names.is_empty() && hidden_pos.is_empty() && !keep_input);
    // The mechanism's own struct: with `params` it can be written out in
    // full (`FourBar { ground: 0.3, crank: 0.1, .. }`, no hidden field).
    let (params_marker, params_marker_init) = marker(param_names.is_empty());

    let pos_docs = output_docs(out, 0);
    let vel_docs = output_docs(out, 1);
    let acc_docs = output_docs(out, 2);
    let mut items = TokenStream::new();
    let mut methods = TokenStream::new();

    // ---------------- structure doc ----------------
    let mut structure = String::from("Structure found by `mechanism!` (solve order):\n\n");
    for (k, &i) in plan.solve.iter().enumerate() {
        structure.push_str(&format!("{}. {}\n", k + 1, describe(&model.stmts[i])));
    }
    structure.push_str(&format!(
        "\nAnalyses generated: {}.",
        match level {
            Level::Position => "position",
            Level::Velocity => "position, velocity",
            Level::Acceleration => "position, velocity, acceleration",
            Level::Forces =>
                "position, velocity, acceleration, forces (joint reactions and driving efforts)",
        }
    ));

    let input_doc = format!("Inputs of [`{name}`], one per driver: angles in rad, lengths in the definition's unit. The same struct carries their rates and accelerations.");
    let pos_doc = format!("Position of [`{name}`]: points in the definition's length unit, link angles in rad in (-pi, pi] from +x, counter-clockwise; slide displacements in length units.");
    let allow_lints = allow_literal_lints();
    items.extend(quote! {
        #(#docs)*
        #[doc = ""]
        #[doc = #structure]
        #[derive(Clone, Copy, Debug, PartialEq)]
        #vis struct #name<T = ::core::primitive::f64> {
            #(#[doc = "Run-time parameter (default from the definition)."] pub #param_names: T,)*
            #params_marker
        }

        #allow_lints
        impl<T: ::mechanism::Real> ::core::default::Default for #name<T> {
            #[inline]
            fn default() -> Self {
                #name { #(#param_names: #param_defaults,)* #params_marker_init }
            }
        }

        #[doc = #input_doc]
        #[derive(Clone, Copy, Debug, PartialEq)]
        #[allow(non_snake_case)]
        #vis struct #input_ty<T = ::core::primitive::f64> {
            #(#[doc = "Driver input (or its rate / acceleration)."] pub #inputs: T,)*
        }

        #[doc = #pos_doc]
        #[derive(Clone, Copy, Debug, PartialEq)]
        #[allow(non_snake_case)]
        #vis struct #position_ty<T: ::mechanism::Real = ::core::primitive::f64> {
            #(#[doc = #pos_docs] pub #pos_out_names: #pos_out_types,)*
            #(#[doc(hidden)] pub #hidden_pos: #hidden_pos_types,)*
            #input_field
            #pos_marker
        }
    });
    // Field names and the position code's locals that hold them.
    let pos_all: Vec<&Ident> = pos_out_names
        .iter()
        .chain(hidden_pos.iter().copied())
        .collect();
    let pos_out_locals: Vec<Ident> = pos_out_names.iter().map(local).collect();
    let pos_init: Vec<TokenStream> = pos_all
        .iter()
        .zip(
            pos_out_locals
                .iter()
                .chain(hidden_pos_locals.iter().copied()),
        )
        .map(|(field, value)| {
            if field == &value {
                quote!(#field)
            } else {
                quote!(#field: #value)
            }
        })
        .collect();
    methods.extend(quote! {
        /// Solves the position analysis for the driver inputs (rad or length units).
        ///
        /// Errors name the group that cannot be assembled or is singular.
        #[inline(always)]
        #[allow(non_snake_case, unused_variables)]
        pub fn position(&self, input: &#input_ty<T>) -> ::core::result::Result<#position_ty<T>, ::mechanism::Error<T>> {
            let input = *input;
            #pos_code
            #pos_out_code
            ::core::result::Result::Ok(#position_ty { #(#pos_init,)* #input_init #pos_marker_init })
        }
    });
    let marked: Vec<&Ident> = model
        .stmts
        .iter()
        .filter_map(|s| match &s.kind {
            Kind::Crank {
                input,
                cos_sin: true,
                ..
            } => Some(input),
            _ => None,
        })
        .collect();
    if !marked.is_empty() {
        let em_cs = Emitter {
            cos_sin: true,
            axes: em.axes.clone(),
            ..em
        };
        let mut cs_code = TokenStream::new();
        for &i in &plan.solve {
            cs_code.extend(em_cs.position(&model.stmts[i]).0);
        }
        let cs_out = out_code(true);
        let cs_ty = format_ident!("{}CosSin", name);
        let field_ty: Vec<TokenStream> = inputs
            .iter()
            .map(|i| {
                if marked.contains(&i) {
                    quote!(::mechanism::driver::crank::CosSin<T>)
                } else {
                    quote!(T)
                }
            })
            .collect();
        let copied: Vec<TokenStream> = inputs
            .iter()
            .map(|i| {
                if marked.contains(&i) {
                    quote!(#i: <T as ::mechanism::Real>::lit(0.0))
                } else {
                    quote!(#i: input_cs.#i)
                }
            })
            .collect();
        let cs_input = if keep_input {
            quote!(let input = #input_ty { #(#copied,)* };)
        } else {
            TokenStream::new()
        };
        let cs_doc = format!("Driver inputs of [`{name}`] for `position_cos_sin`: the cranks written `INPUT as cos_sin` take their angle as `(cos, sin)` (need not be unit: it is normalized), the other inputs as in [`{input_ty}`].");
        items.extend(quote! {
            #[doc = #cs_doc]
            #[derive(Clone, Copy, Debug, PartialEq)]
            #[allow(non_snake_case)]
            #vis struct #cs_ty<T = ::core::primitive::f64> {
                #(#[doc = "Driver input."] pub #inputs: #field_ty,)*
            }
        });
        methods.extend(quote! {
            /// Solves the position analysis with the marked cranks' angles
            /// given as `(cos, sin)` (no sine or cosine is evaluated for
            /// them; their link angle, if an output, is one `atan2`). Where
            /// the position records the inputs (for a slider driver's rates),
            /// the marked cranks' entries are 0: nothing reads them.
            #[inline(always)]
            #[allow(non_snake_case, unused_variables)]
            pub fn position_cos_sin(&self, input: &#cs_ty<T>) -> ::core::result::Result<#position_ty<T>, ::mechanism::Error<T>> {
                let input_cs = *input;
                #cs_input
                #cs_code
                #cs_out
                ::core::result::Result::Ok(#position_ty { #(#pos_init,)* #input_init #pos_marker_init })
            }
        });
    }

    if let Some((code, fields, outs)) = vel_rates {
        let fields: Vec<(Ident, TokenStream)> = fields
            .into_iter()
            .filter(|(n, _)| reads.reads(Analysis::Velocity, n))
            .collect();
        let conditions: Vec<Ident> = plan
            .solve
            .iter()
            .map(|&i| &model.stmts[i])
            .filter(|s| {
                matches!(
                    s.kind,
                    Kind::Actuator { .. }
                        | Kind::Rrr { .. }
                        | Kind::Rrp { .. }
                        | Kind::Rpr { .. }
                        | Kind::Prp { .. }
                        | Kind::Rpp { .. }
                )
            })
            .map(|s| format_ident!("grp_v_{}", s.name))
            .collect();
        // The smallest of the groups' indicators, one `let` per group (a
        // nested `min(min(..), ..)` would nest as deep as the chain is long).
        let condition = match conditions.split_first() {
            None => {
                let one = lit(1.0);
                quote!(let __condition = #one;)
            }
            Some((first, rest)) => {
                let steps = rest.iter().map(
                    |g| quote!(let __condition = ::mechanism::geometry::min(__condition, #g.condition);),
                );
                quote!(let __condition = #first.condition; #(#steps)*)
            }
        };
        let vel_doc = format!("Velocity of [`{name}`]: point velocities in length units per second, link angular velocities in rad/s (counter-clockwise positive), slide rates in length units per second.");
        let (on, ot, oc): (Vec<Ident>, Vec<TokenStream>, Vec<TokenStream>) = unzip3(outs);
        let (hn, ht): (Vec<Ident>, Vec<TokenStream>) = fields.into_iter().unzip();
        items.extend(quote! {
            #[doc = #vel_doc]
            #[derive(Clone, Copy, Debug, PartialEq)]
            #[allow(non_snake_case)]
            #vis struct #velocity_ty<T: ::mechanism::Real = ::core::primitive::f64> {
                #(#[doc = #vel_docs] pub #on: #ot,)*
                #(#[doc(hidden)] pub #hn: #ht,)*
                /// Conditioning indicator: the smallest scaled determinant
                /// `|det| / scale` of the groups' rate systems, in (0, 1]
                /// (1 for a mechanism without groups). It tends to 0 towards a
                /// toggle or dead-centre position, where the rates grow as
                /// 1 / condition; below 16 eps the velocity analysis returns
                /// `Singular` instead. End to end (from positions rounded to
                /// eps of their coordinates `L`) the rates are accurate to
                /// about `eps (L / l) / condition^2` of the largest of them,
                /// `l` the group's shortest link (`docs/stability.md`, "End
                /// to end").
                pub condition: T,
                #[doc(hidden)]
                pub rates: #input_ty<T>,
            }
        });
        methods.extend(quote! {
            /// Solves the velocity analysis at `pos` for the input rates
            /// (rad/s or length units per second).
            #[inline(always)]
            #[allow(non_snake_case, unused_variables)]
            pub fn velocity(&self, pos: &#position_ty<T>, rates: &#input_ty<T>) -> ::core::result::Result<#velocity_ty<T>, ::mechanism::Error<T>> {
                let rates = *rates;
                #code
                #condition
                ::core::result::Result::Ok(#velocity_ty { #(#on: #oc,)* #(#hn,)* condition: __condition, rates })
            }
        });
    }
    if let Some((code, fields, outs)) = accel_rates {
        let forces_ty = format_ident!("{}Forces", name);
        let (forces_field, forces_call, forces_value, loads_param) = match &forces {
            Some(f) => {
                items.extend(f.items.clone());
                methods.extend(f.methods.clone());
                let arg = &f.loads_arg;
                (
                    quote! {
                        /// Force analysis.
                        pub forces: #forces_ty<T>,
                    },
                    quote!(let forces = self.forces(&position, &velocity, &acceleration #arg)?;),
                    quote!(forces,),
                    f.loads_param.clone(),
                )
            }
            None => (quote!(), quote!(), quote!(), quote!()),
        };
        let solution_doc = if forces.is_some() {
            " Position, velocity, acceleration and forces together."
        } else {
            " Position, velocity and acceleration together."
        };
        let solution_item = quote! {
            #[doc = #solution_doc]
            #[derive(Clone, Copy, Debug, PartialEq)]
            #vis struct #solution_ty<T: ::mechanism::Real = ::core::primitive::f64> {
                /// Position analysis.
                pub position: #position_ty<T>,
                /// Velocity analysis.
                pub velocity: #velocity_ty<T>,
                /// Acceleration analysis.
                pub acceleration: #acceleration_ty<T>,
                #forces_field
            }
        };
        let fields: Vec<(Ident, TokenStream)> = fields
            .into_iter()
            .filter(|(n, _)| reads.reads(Analysis::Acceleration, n))
            .collect();
        let acc_doc = format!("Acceleration of [`{name}`]: point accelerations in length units per s^2, link angular accelerations in rad/s^2, slide accelerations in length units per s^2.");
        let (on, ot, oc): (Vec<Ident>, Vec<TokenStream>, Vec<TokenStream>) = unzip3(outs);
        let (hn, ht): (Vec<Ident>, Vec<TokenStream>) = fields.into_iter().unzip();
        let (acc_marker, acc_marker_init) = marker(on.is_empty() && hn.is_empty());
        items.extend(quote! {
            #[doc = #acc_doc]
            #[derive(Clone, Copy, Debug, PartialEq)]
            #[allow(non_snake_case)]
            #vis struct #acceleration_ty<T: ::mechanism::Real = ::core::primitive::f64> {
                #(#[doc = #acc_docs] pub #on: #ot,)*
                #(#[doc(hidden)] pub #hn: #ht,)*
                #acc_marker
            }

            #solution_item
        });
        methods.extend(quote! {
            /// Solves the acceleration analysis at `pos`, `vel` for the input
            /// accelerations (rad/s^2 or length units per s^2).
            #[inline(always)]
            #[allow(non_snake_case, unused_variables)]
            pub fn acceleration(&self, pos: &#position_ty<T>, vel: &#velocity_ty<T>, accels: &#input_ty<T>) -> ::core::result::Result<#acceleration_ty<T>, ::mechanism::Error<T>> {
                let accels = *accels;
                let rates = vel.rates;
                #code
                ::core::result::Result::Ok(#acceleration_ty { #(#on: #oc,)* #(#hn,)* #acc_marker_init })
            }

            /// Every analysis the definition asks for, at once.
            // Always inlined, as the analyses and the primitives are: their
            // results are large structs, returned through memory when a call
            // stays a call (in the report's program the compiler kept them
            // calls, and the six-bar and shaper took 1.6 times as long;
            // docs/performance.md).
            #[inline(always)]
            pub fn solve(&self, input: &#input_ty<T>, rates: &#input_ty<T>, accels: &#input_ty<T> #loads_param) -> ::core::result::Result<#solution_ty<T>, ::mechanism::Error<T>> {
                let position = self.position(input)?;
                let velocity = self.velocity(&position, rates)?;
                let acceleration = self.acceleration(&position, &velocity, accels)?;
                #forces_call
                ::core::result::Result::Ok(#solution_ty { position, velocity, acceleration, #forces_value })
            }
        });
    }

    // Batch API (structure of arrays, issue 5): see batch.rs.
    items.extend(batch::emit(model, plan, &inputs, &pos_out_fields));
    let allow_lints = allow_literal_lints();
    quote! {
        #items
        #allow_lints
        impl<T: ::mechanism::Real> #name<T> {
            #methods
        }
    }
}

fn unzip3<A, B, C>(v: Vec<(A, B, C)>) -> (Vec<A>, Vec<B>, Vec<C>) {
    let mut a = Vec::new();
    let mut b = Vec::new();
    let mut c = Vec::new();
    for (x, y, z) in v {
        a.push(x);
        b.push(y);
        c.push(z);
    }
    (a, b, c)
}

fn group_type(kind: &Kind, accel: bool) -> TokenStream {
    let (module, ty) = match kind {
        Kind::Actuator { .. } => (quote!(driver::actuator), "Actuator"),
        Kind::Rrr { .. } => (quote!(dyad::rrr), "Rrr"),
        Kind::Rrp { .. } => (quote!(dyad::rrp), "Rrp"),
        Kind::Rpr { .. } => (quote!(dyad::rpr), "Rpr"),
        Kind::Prp { .. } => (quote!(dyad::prp), "Prp"),
        _ => (quote!(dyad::rpp), "Rpp"),
    };
    let ty = format_ident!("{}{}", ty, if accel { "Acceleration" } else { "Velocity" });
    quote!(::mechanism::#module::#ty<T>)
}

/// Velocity (`accel == false`) or acceleration statements. Returns the code,
/// the hidden fields (name, type) and the outputs (name, type, value).
#[allow(clippy::type_complexity)]
fn emit_rates(
    em: &Emitter<'_>,
    moving: &BTreeSet<String>,
    out: &Outputs,
    accel: bool,
) -> (
    TokenStream,
    Vec<(Ident, TokenStream)>,
    Vec<(Ident, TokenStream, TokenStream)>,
) {
    let model = em.model;
    let plan = em.plan;
    let vec_ty = quote!(::mechanism::Vector2<T>);
    let (pfx, wpfx, gpfx, rpfx) = if accel {
        ("acc", "alpha", "gacc", "grp_a")
    } else {
        ("vel", "omega", "gvel", "grp_v")
    };
    let none = quote!(::core::option::Option::None);
    // Motion of a known point at this level.
    let point_arg = |p: &Ident| opt_point(p, moving, pfx, &quote!());
    // Angular rate of a link at this level (None: it does not turn).
    let link_rate = |link: &Ident| {
        plan.turning_link(&link.to_string())
            .map(|l| format_ident!("{}_{}", wpfx, l))
    };
    let link_omega_in_accel = |link: &Ident| {
        plan.turning_link(&link.to_string()).map(|l| {
            let w = format_ident!("omega_{}", l);
            quote!(vel.#w)
        })
    };
    let carried = |g: &Ident| {
        plan.guides
            .get(&g.to_string())
            .is_some_and(|i| i.carrier.is_some())
    };
    // Guide velocity argument (in the velocity fn: local; in acceleration: from `vel`).
    let guide_vel = |g: &Ident| {
        if !carried(g) {
            return none.clone();
        }
        let n = format_ident!("gvel_{}", g);
        if accel {
            quote!(::core::option::Option::Some(&vel.#n))
        } else {
            quote!(::core::option::Option::Some(&#n))
        }
    };
    let guide_acc = |g: &Ident| {
        if !carried(g) {
            return none.clone();
        }
        let n = format_ident!("gacc_{}", g);
        quote!(::core::option::Option::Some(&#n))
    };
    let mut code = TokenStream::new();
    let mut fields: Vec<(Ident, TokenStream)> = Vec::new();
    // Slide rate expressions by (stmt, slot).
    let mut slide_values: Vec<(usize, usize, TokenStream)> = Vec::new();
    for &i in &plan.solve {
        let stmt = &model.stmts[i];
        let name = &stmt.name;
        let g = format_ident!("grp_{}", name);
        let gv = format_ident!("grp_v_{}", name);
        let gr = format_ident!("{}_{}", rpfx, name);
        let pv = format_ident!("{}_{}", pfx, name);
        let t = tag(stmt);
        let own = |k: usize| format_ident!("{}_{}", wpfx, stmt.links[k]);
        let (r1, r2) = if accel {
            (quote!(alpha1), quote!(alpha2))
        } else {
            (quote!(omega1), quote!(omega2))
        };
        let (pt, sd, sd1, sd2) = if accel {
            (quote!(ac), quote!(s_ddot), quote!(s1_ddot), quote!(s2_ddot))
        } else {
            (quote!(vc), quote!(s_dot), quote!(s1_dot), quote!(s2_dot))
        };
        match &stmt.kind {
            Kind::Ground { .. } | Kind::Guide { carrier: None, .. } => {}
            Kind::Guide {
                origin,
                carrier: Some(link),
                ..
            } => {
                let n = format_ident!("{}_{}", gpfx, name);
                let origin_motion = match origin {
                    Origin::Point(p) if moving.contains(&p.to_string()) => {
                        let v = format_ident!("{}_{}", pfx, p);
                        quote!(#v)
                    }
                    _ => quote!(::mechanism::Vector2::zeros()),
                };
                let w = link_rate(link)
                    .map(|w| quote!(#w))
                    .unwrap_or_else(|| lit(0.0));
                let (body, ty) = if accel {
                    (
                        quote!(::mechanism::guide::LineAcceleration { a_origin: #origin_motion, alpha: #w }),
                        quote!(::mechanism::guide::LineAcceleration<T>),
                    )
                } else {
                    (
                        quote!(::mechanism::guide::LineVelocity { v_origin: #origin_motion, omega: #w }),
                        quote!(::mechanism::guide::LineVelocity<T>),
                    )
                };
                code.extend(quote!(let #n = #body;));
                fields.push((n, ty));
            }
            Kind::Crank { pivot, input, .. } => {
                let w = own(0);
                let m = point_arg(pivot);
                code.extend(if accel {
                    quote! {
                        let #pv = ::mechanism::driver::crank::acceleration(&pos.#g, #m, rates.#input, accels.#input) #t;
                        let #w = accels.#input;
                    }
                } else {
                    quote! {
                        let #pv = ::mechanism::driver::crank::velocity(&pos.#g, #m, rates.#input) #t;
                        let #w = rates.#input;
                    }
                });
                fields.push((pv, vec_ty.clone()));
                fields.push((w, quote!(T)));
            }
            Kind::Slider { guide, input, .. } => {
                let gvel = guide_vel(guide);
                code.extend(if accel {
                    let gacc = guide_acc(guide);
                    quote! {
                        let #pv = ::mechanism::driver::slider::acceleration(&pos.#g, &pos.#guide, pos.input.#input, rates.#input, accels.#input, #gvel, #gacc) #t;
                    }
                } else {
                    quote! {
                        let #pv = ::mechanism::driver::slider::velocity(&pos.#g, &pos.#guide, pos.input.#input, rates.#input, #gvel) #t;
                    }
                });
                fields.push((pv, vec_ty.clone()));
            }
            Kind::Point { link, from, .. } => {
                if !moving.contains(&name.to_string()) {
                    continue;
                }
                let base = if moving.contains(&from.to_string()) {
                    let b = format_ident!("{}_{}", pfx, from);
                    Some(quote!(#b))
                } else {
                    None
                };
                let relative = match (link_rate(link), accel) {
                    (None, _) => None,
                    (Some(w), false) => Some(
                        quote!(::mechanism::link::point_velocity(&(pos.#name - pos.#from), #w) #t),
                    ),
                    (Some(alpha), true) => {
                        let w = link_omega_in_accel(link).unwrap_or_else(|| lit(0.0));
                        Some(
                            quote!(::mechanism::link::point_acceleration(&(pos.#name - pos.#from), #w, #alpha) #t),
                        )
                    }
                };
                let value = match (base, relative) {
                    (Some(b), Some(r)) => quote!(#b + #r),
                    (Some(b), None) => b,
                    (None, Some(r)) => r,
                    (None, None) => quote!(::mechanism::Vector2::zeros()),
                };
                code.extend(quote!(let #pv = #value;));
                fields.push((pv, vec_ty.clone()));
            }
            kind => {
                // The five groups and the actuator share one shape: a call that
                // returns a struct, then named pieces of it.
                let call = match (kind, accel) {
                    (Kind::Actuator { a, b, input, .. }, false) => {
                        let (ma, mb) = (point_arg(a), point_arg(b));
                        quote!(::mechanism::driver::actuator::velocity(&pos.#g, #ma, #mb, rates.#input))
                    }
                    (Kind::Actuator { a, b, input, .. }, true) => {
                        let (ma, mb) = (point_arg(a), point_arg(b));
                        quote!(::mechanism::driver::actuator::acceleration(&pos.#g, &vel.#gv, #ma, #mb, rates.#input, accels.#input))
                    }
                    (Kind::Rrr { a, b, l1, l2, .. }, false) => {
                        // The link lengths are the determinant's scale: no square root.
                        let (ma, mb, l1, l2) = (point_arg(a), point_arg(b), l1.emit(), l2.emit());
                        quote!(::mechanism::dyad::rrr::velocity_lengths(&pos.#g, #l1, #l2, #ma, #mb))
                    }
                    (Kind::Rrr { a, b, .. }, true) => {
                        let (ma, mb) = (point_arg(a), point_arg(b));
                        quote!(::mechanism::dyad::rrr::acceleration(&pos.#g, &vel.#gv, #ma, #mb))
                    }
                    (Kind::Rrp { a, guide, .. }, false) => {
                        let (ma, gvel) = (point_arg(a), guide_vel(guide));
                        quote!(::mechanism::dyad::rrp::velocity(&pos.#g, &pos.#guide, #ma, #gvel))
                    }
                    (Kind::Rrp { a, guide, .. }, true) => {
                        let (ma, gvel, gacc) = (point_arg(a), guide_vel(guide), guide_acc(guide));
                        quote!(::mechanism::dyad::rrp::acceleration(&pos.#g, &pos.#guide, &vel.#gv, #ma, #gvel, #gacc))
                    }
                    (Kind::Rpr { a, b, .. }, false) => {
                        let (ma, mb) = (point_arg(a), point_arg(b));
                        quote!(::mechanism::dyad::rpr::velocity(&pos.#g, &pos.#a, &pos.#b, #ma, #mb))
                    }
                    (Kind::Rpr { a, b, .. }, true) => {
                        let (ma, mb) = (point_arg(a), point_arg(b));
                        quote!(::mechanism::dyad::rpr::acceleration(&pos.#g, &pos.#a, &pos.#b, &vel.#gv, #ma, #mb))
                    }
                    (Kind::Prp { g1, g2, .. }, false) => {
                        let (v1, v2) = (guide_vel(g1), guide_vel(g2));
                        quote!(::mechanism::dyad::prp::velocity(&pos.#g, &pos.#g1, &pos.#g2, #v1, #v2))
                    }
                    (Kind::Prp { g1, g2, .. }, true) => {
                        let (v1, v2) = (guide_vel(g1), guide_vel(g2));
                        let (a1, a2) = (guide_acc(g1), guide_acc(g2));
                        quote!(::mechanism::dyad::prp::acceleration(&pos.#g, &pos.#g1, &pos.#g2, &vel.#gv, #v1, #a1, #v2, #a2))
                    }
                    (Kind::Rpp { a, guide, .. }, false) => {
                        let (ma, gvel) = (point_arg(a), guide_vel(guide));
                        quote!(::mechanism::dyad::rpp::velocity(&pos.#g, &pos.#a, &pos.#guide, #ma, #gvel))
                    }
                    (Kind::Rpp { a, guide, .. }, true) => {
                        let (ma, gvel, gacc) = (point_arg(a), guide_vel(guide), guide_acc(guide));
                        quote!(::mechanism::dyad::rpp::acceleration(&pos.#g, &pos.#a, &pos.#guide, &vel.#gv, #ma, #gvel, #gacc))
                    }
                    _ => continue,
                };
                code.extend(quote!(let #gr = #call #t;));
                fields.push((gr.clone(), group_type(kind, accel)));
                let mut named = |local: Ident, value: TokenStream, ty: TokenStream| {
                    code.extend(quote!(let #local = #value;));
                    fields.push((local, ty));
                };
                match kind {
                    Kind::Actuator { .. } | Kind::Rrr { .. } => {
                        named(pv.clone(), quote!(#gr.#pt), vec_ty.clone());
                        named(own(0), quote!(#gr.#r1), quote!(T));
                        named(own(1), quote!(#gr.#r2), quote!(T));
                    }
                    Kind::Rrp { .. } => {
                        named(pv.clone(), quote!(#gr.#pt), vec_ty.clone());
                        named(own(0), quote!(#gr.#r1), quote!(T));
                        slide_values.push((i, 0, quote!(#gr.#sd)));
                    }
                    Kind::Rpr { .. } => {
                        let r = if accel { quote!(alpha) } else { quote!(omega) };
                        named(own(0), quote!(#gr.#r), quote!(T));
                        named(own(1), quote!(#gr.#r), quote!(T));
                        slide_values.push((i, 0, quote!(#gr.#sd)));
                    }
                    Kind::Prp { .. } => {
                        named(pv.clone(), quote!(#gr.#pt), vec_ty.clone());
                        slide_values.push((i, 0, quote!(#gr.#sd1)));
                        slide_values.push((i, 1, quote!(#gr.#sd2)));
                    }
                    _ => {
                        let q = if accel { quote!(aq) } else { quote!(vq) };
                        named(pv.clone(), quote!(#gr.#q), vec_ty.clone());
                        slide_values.push((i, 0, quote!(#gr.#sd1)));
                        slide_values.push((i, 1, quote!(#gr.#sd2)));
                    }
                }
            }
        }
    }
    // Outputs.
    let mut outs = Vec::new();
    for p in &out.points {
        let value = if moving.contains(&p.to_string()) {
            let v = format_ident!("{}_{}", pfx, p);
            quote!(#v)
        } else {
            quote!(::mechanism::Vector2::zeros())
        };
        outs.push((p.clone(), vec_ty.clone(), value));
    }
    for link in &out.links {
        let value = link_rate(link)
            .map(|w| quote!(#w))
            .unwrap_or_else(|| lit(0.0));
        outs.push((link.clone(), quote!(T), value));
    }
    for (slide, i, slot) in &out.slides {
        let value = slide_values
            .iter()
            .find(|(si, ss, _)| si == i && ss == slot)
            .map(|(_, _, v)| v.clone())
            .unwrap_or_else(|| lit(0.0));
        outs.push((slide.clone(), quote!(T), value));
    }
    // Hidden fields that are also outputs are kept once (as outputs).
    let out_names: BTreeSet<String> = outs.iter().map(|(n, _, _)| n.to_string()).collect();
    fields.retain(|(n, _)| !out_names.contains(&n.to_string()));
    (code, fields, outs)
}

/// One line of the structure listing in the generated type's doc comment.
fn describe(stmt: &Stmt) -> String {
    let links = stmt
        .links
        .iter()
        .map(Ident::to_string)
        .collect::<Vec<_>>()
        .join(", ");
    let mode = |m: &Mode| match m {
        Mode::Plus => "mode plus (m = +1)",
        Mode::Minus => "mode minus (m = -1)",
    };
    let n = &stmt.name;
    match &stmt.kind {
        Kind::Ground { .. } => format!("ground point `{n}`"),
        Kind::Guide { carrier: None, .. } => format!("fixed guide `{n}`"),
        Kind::Guide { carrier: Some(l), .. } => format!("guide `{n}` carried by `{l}`"),
        Kind::Crank { pivot, input, .. } => {
            format!("driver: crank `{links}` about `{pivot}`, input `{input}`, tip `{n}`")
        }
        Kind::Slider { guide, input, .. } => {
            format!("driver: slider `{links}` on `{guide}`, input `{input}`, pin `{n}`")
        }
        Kind::Actuator { a, b, input, mode: m, .. } => format!(
            "driver: linear actuator `{links}` from `{b}`, link pivoted at `{a}`, input `{input}`, joint `{n}`, {}",
            mode(m)
        ),
        Kind::Rrr { a, b, mode: m, .. } => {
            format!("RRR group `{links}`: `{a}`, `{b}` -> `{n}`, {}", mode(m))
        }
        Kind::Rrp { a, guide, mode: m, .. } => {
            format!("RRP group `{links}`: `{a}` and guide `{guide}` -> `{n}`, {}", mode(m))
        }
        Kind::Rpr { a, b, mode: m, .. } => {
            format!("RPR group `{links}`: block at `{a}` on link pivoted at `{b}`, slide `{n}`, {}", mode(m))
        }
        Kind::Prp { g1, g2, .. } => format!("PRP group `{links}`: guides `{g1}`, `{g2}` -> `{n}`"),
        Kind::Rpp { a, guide, .. } => {
            format!("RPP group `{links}`: block at `{a}`, link on guide `{guide}`, reference point `{n}`")
        }
        Kind::Point { link, from, .. } => format!("point `{n}` on `{link}` (from `{from}`)"),
    }
}
