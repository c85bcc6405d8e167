//! The velocity and acceleration analyses: each statement's rate code in
//! solve order (one function per statement family), the velocity and
//! acceleration structs and their methods.

use super::names::{
    debug_impl, lit_zero, marker, opt_point, output_docs, tag, Generated, TypeNames,
};
use super::reads::{Analysis, Reads};
use crate::model::{Kind, Model, Origin, Stmt};
use crate::plan::{Outputs, Plan};
use crate::value::lit;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use std::collections::BTreeSet;
use syn::Ident;

/// Which derivative a rate emitter writes.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(super) enum Rate {
    Velocity,
    Acceleration,
}

/// A hidden field of the velocity or acceleration struct.
pub(super) struct Field {
    pub name: Ident,
    pub ty: TokenStream,
}

/// An output field: its name, type and the value it is built from.
pub(super) struct Output {
    pub name: Ident,
    pub ty: TokenStream,
    pub value: TokenStream,
}

/// The velocity or acceleration code of a definition.
pub(super) struct RatesCode {
    /// Statements in solve order.
    pub code: TokenStream,
    /// The values the struct may keep, minus the outputs.
    pub hidden: Vec<Field>,
    /// Points, links and slides, as in the position struct.
    pub outputs: Vec<Output>,
}

/// The state of one rate emitter: the code so far, the values it may store
/// and the slides' rates by (statement, slot).
struct RateEmitter<'a> {
    model: &'a Model,
    plan: &'a Plan,
    moving: &'a BTreeSet<String>,
    accel: bool,
    /// `vel` or `acc`: prefix of point motions.
    pfx: &'static str,
    /// `omega` or `alpha`: prefix of link rates.
    wpfx: &'static str,
    code: TokenStream,
    fields: Vec<Field>,
    slide_values: Vec<(usize, usize, TokenStream)>,
}

fn vec_ty() -> TokenStream {
    quote!(::mechanism::Vector2<T>)
}

fn none() -> TokenStream {
    quote!(::core::option::Option::None)
}

impl RateEmitter<'_> {
    /// Motion of a known point at this level.
    fn point_arg(&self, p: &Ident) -> TokenStream {
        opt_point(p, self.moving, self.pfx, &quote!())
    }

    /// Angular rate of a link at this level (None: it does not turn).
    fn link_rate(&self, link: &Ident) -> Option<Ident> {
        self.plan
            .turning_link(&link.to_string())
            .map(|l| format_ident!("{}_{}", self.wpfx, l))
    }

    fn link_omega_in_accel(&self, link: &Ident) -> Option<TokenStream> {
        self.plan.turning_link(&link.to_string()).map(|l| {
            let w = format_ident!("omega_{}", l);
            quote!(vel.#w)
        })
    }

    fn carried(&self, g: &Ident) -> bool {
        self.plan
            .guides
            .get(&g.to_string())
            .is_some_and(|i| i.carrier.is_some())
    }

    /// Guide velocity argument (in the velocity fn: local; in acceleration: from `vel`).
    fn guide_vel(&self, g: &Ident) -> TokenStream {
        if !self.carried(g) {
            return none();
        }
        let n = format_ident!("gvel_{}", g);
        if self.accel {
            quote!(::core::option::Option::Some(&vel.#n))
        } else {
            quote!(::core::option::Option::Some(&#n))
        }
    }

    fn guide_acc(&self, g: &Ident) -> TokenStream {
        if !self.carried(g) {
            return none();
        }
        let n = format_ident!("gacc_{}", g);
        quote!(::core::option::Option::Some(&#n))
    }

    /// `let LOCAL = VALUE;`, and LOCAL may be stored with type `ty`.
    fn named(&mut self, local: Ident, value: TokenStream, ty: TokenStream) {
        self.code.extend(quote!(let #local = #value;));
        self.fields.push(Field { name: local, ty });
    }

    /// The rate of link `k` of `stmt` (`omega_LINK` or `alpha_LINK`).
    fn own(&self, stmt: &Stmt, k: usize) -> Ident {
        format_ident!("{}_{}", self.wpfx, stmt.links[k])
    }

    /// The motion of point `stmt` (`vel_NAME` or `acc_NAME`).
    fn motion(&self, stmt: &Stmt) -> Ident {
        format_ident!("{}_{}", self.pfx, stmt.name)
    }

    fn statement(&mut self, i: usize) {
        let stmt = &self.model.stmts[i];
        match &stmt.kind {
            Kind::Ground { .. } | Kind::Guide { carrier: None, .. } => {}
            Kind::Guide {
                origin,
                carrier: Some(link),
                ..
            } => self.carried_guide(stmt, origin, link),
            Kind::Crank { pivot, input, .. } => self.crank(stmt, pivot, input),
            Kind::Slider { guide, input, .. } => self.slider(stmt, guide, input),
            Kind::Point { link, from, .. } => self.point(stmt, link, from),
            _ => self.group(i, stmt),
        }
    }

    /// A guide carried by a link: the motion of its line.
    fn carried_guide(&mut self, stmt: &Stmt, origin: &Origin, link: &Ident) {
        let gpfx = if self.accel { "gacc" } else { "gvel" };
        let n = format_ident!("{}_{}", gpfx, stmt.name);
        let origin_motion = match origin {
            Origin::Point(p) if self.moving.contains(&p.to_string()) => {
                let v = format_ident!("{}_{}", self.pfx, p);
                quote!(#v)
            }
            _ => quote!(::mechanism::Vector2::zeros()),
        };
        let w = self
            .link_rate(link)
            .map(|w| quote!(#w))
            .unwrap_or_else(lit_zero);
        let (body, ty) = if self.accel {
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
        self.code.extend(quote!(let #n = #body;));
        self.fields.push(Field { name: n, ty });
    }

    fn crank(&mut self, stmt: &Stmt, pivot: &Ident, input: &Ident) {
        let (g, pv, t) = (
            format_ident!("grp_{}", stmt.name),
            self.motion(stmt),
            tag(stmt),
        );
        let w = self.own(stmt, 0);
        let m = self.point_arg(pivot);
        self.code.extend(if self.accel {
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
        self.fields.push(Field {
            name: pv,
            ty: vec_ty(),
        });
        self.fields.push(Field {
            name: w,
            ty: quote!(T),
        });
    }

    fn slider(&mut self, stmt: &Stmt, guide: &Ident, input: &Ident) {
        let (g, pv, t) = (
            format_ident!("grp_{}", stmt.name),
            self.motion(stmt),
            tag(stmt),
        );
        let gvel = self.guide_vel(guide);
        self.code.extend(if self.accel {
            let gacc = self.guide_acc(guide);
            quote! {
                let #pv = ::mechanism::driver::slider::acceleration(&pos.#g, &pos.#guide, pos.input.#input, rates.#input, accels.#input, #gvel, #gacc) #t;
            }
        } else {
            quote! {
                let #pv = ::mechanism::driver::slider::velocity(&pos.#g, &pos.#guide, pos.input.#input, rates.#input, #gvel) #t;
            }
        });
        self.fields.push(Field {
            name: pv,
            ty: vec_ty(),
        });
    }

    /// A point on a link: its base point's motion plus its motion about it.
    fn point(&mut self, stmt: &Stmt, link: &Ident, from: &Ident) {
        let name = &stmt.name;
        if !self.moving.contains(&name.to_string()) {
            return;
        }
        let (pv, t) = (self.motion(stmt), tag(stmt));
        let base = if self.moving.contains(&from.to_string()) {
            let b = format_ident!("{}_{}", self.pfx, from);
            Some(quote!(#b))
        } else {
            None
        };
        let relative = match (self.link_rate(link), self.accel) {
            (None, _) => None,
            (Some(w), false) => {
                Some(quote!(::mechanism::link::point_velocity(&(pos.#name - pos.#from), #w) #t))
            }
            (Some(alpha), true) => {
                let w = self.link_omega_in_accel(link).unwrap_or_else(lit_zero);
                Some(
                    quote!(::mechanism::link::point_acceleration(&(pos.#name - pos.#from), #w, #alpha) #t),
                )
            }
        };
        let value = match (base, relative) {
            // Checked again: the sum of two finite vectors can overflow.
            (Some(b), Some(r)) => quote!(::mechanism::link::point_sum(&#b, #r) #t),
            (Some(b), None) => b,
            (None, Some(r)) => r,
            (None, None) => quote!(::mechanism::Vector2::zeros()),
        };
        self.code.extend(quote!(let #pv = #value;));
        self.fields.push(Field {
            name: pv,
            ty: vec_ty(),
        });
    }

    /// The five groups and the actuator share one shape: a call that returns
    /// a struct, then named pieces of it.
    fn group(&mut self, i: usize, stmt: &Stmt) {
        let Some(call) = self.group_call(stmt) else {
            return;
        };
        let gr = format_ident!(
            "{}_{}",
            if self.accel { "grp_a" } else { "grp_v" },
            stmt.name
        );
        let t = tag(stmt);
        self.code.extend(quote!(let #gr = #call #t;));
        self.fields.push(Field {
            name: gr.clone(),
            ty: group_type(&stmt.kind, self.accel),
        });
        self.group_pieces(i, stmt, &gr);
    }

    /// The core call of a group's (or the actuator's) rates.
    fn group_call(&self, stmt: &Stmt) -> Option<TokenStream> {
        let g = format_ident!("grp_{}", stmt.name);
        let gv = format_ident!("grp_v_{}", stmt.name);
        Some(match (&stmt.kind, self.accel) {
            (Kind::Actuator { a, b, input, .. }, false) => {
                let (ma, mb) = (self.point_arg(a), self.point_arg(b));
                quote!(::mechanism::driver::actuator::velocity(&pos.#g, #ma, #mb, rates.#input))
            }
            (Kind::Actuator { a, b, input, .. }, true) => {
                let (ma, mb) = (self.point_arg(a), self.point_arg(b));
                quote!(::mechanism::driver::actuator::acceleration(&pos.#g, &vel.#gv, #ma, #mb, rates.#input, accels.#input))
            }
            (Kind::Rrr { a, b, l1, l2, .. }, false) => {
                // The link lengths are the determinant's scale: no square root.
                let (ma, mb, l1, l2) = (self.point_arg(a), self.point_arg(b), l1.emit(), l2.emit());
                quote!(::mechanism::dyad::rrr::velocity_lengths(&pos.#g, #l1, #l2, #ma, #mb))
            }
            (Kind::Rrr { a, b, .. }, true) => {
                let (ma, mb) = (self.point_arg(a), self.point_arg(b));
                quote!(::mechanism::dyad::rrr::acceleration(&pos.#g, &vel.#gv, #ma, #mb))
            }
            (Kind::Rrp { a, guide, .. }, false) => {
                let (ma, gvel) = (self.point_arg(a), self.guide_vel(guide));
                quote!(::mechanism::dyad::rrp::velocity(&pos.#g, &pos.#guide, #ma, #gvel))
            }
            (Kind::Rrp { a, guide, .. }, true) => {
                let (ma, gvel, gacc) = (
                    self.point_arg(a),
                    self.guide_vel(guide),
                    self.guide_acc(guide),
                );
                quote!(::mechanism::dyad::rrp::acceleration(&pos.#g, &pos.#guide, &vel.#gv, #ma, #gvel, #gacc))
            }
            (Kind::Rpr { a, b, .. }, false) => {
                let (ma, mb) = (self.point_arg(a), self.point_arg(b));
                quote!(::mechanism::dyad::rpr::velocity(&pos.#g, &pos.#a, &pos.#b, #ma, #mb))
            }
            (Kind::Rpr { a, b, .. }, true) => {
                let (ma, mb) = (self.point_arg(a), self.point_arg(b));
                quote!(::mechanism::dyad::rpr::acceleration(&pos.#g, &pos.#a, &pos.#b, &vel.#gv, #ma, #mb))
            }
            (Kind::Prp { g1, g2, .. }, false) => {
                let (v1, v2) = (self.guide_vel(g1), self.guide_vel(g2));
                quote!(::mechanism::dyad::prp::velocity(&pos.#g, &pos.#g1, &pos.#g2, #v1, #v2))
            }
            (Kind::Prp { g1, g2, .. }, true) => {
                let (v1, v2) = (self.guide_vel(g1), self.guide_vel(g2));
                let (a1, a2) = (self.guide_acc(g1), self.guide_acc(g2));
                quote!(::mechanism::dyad::prp::acceleration(&pos.#g, &pos.#g1, &pos.#g2, &vel.#gv, #v1, #a1, #v2, #a2))
            }
            (Kind::Rpp { a, guide, .. }, false) => {
                let (ma, gvel) = (self.point_arg(a), self.guide_vel(guide));
                quote!(::mechanism::dyad::rpp::velocity(&pos.#g, &pos.#a, &pos.#guide, #ma, #gvel))
            }
            (Kind::Rpp { a, guide, .. }, true) => {
                let (ma, gvel, gacc) = (
                    self.point_arg(a),
                    self.guide_vel(guide),
                    self.guide_acc(guide),
                );
                quote!(::mechanism::dyad::rpp::acceleration(&pos.#g, &pos.#a, &pos.#guide, &vel.#gv, #ma, #gvel, #gacc))
            }
            _ => return None,
        })
    }

    /// The named pieces of a group's rates `gr`: its point's motion, its
    /// links' rates, its slides' rates.
    fn group_pieces(&mut self, i: usize, stmt: &Stmt, gr: &Ident) {
        let pv = self.motion(stmt);
        let (r1, r2) = if self.accel {
            (quote!(alpha1), quote!(alpha2))
        } else {
            (quote!(omega1), quote!(omega2))
        };
        let (pt, sd, sd1, sd2) = if self.accel {
            (quote!(ac), quote!(s_ddot), quote!(s1_ddot), quote!(s2_ddot))
        } else {
            (quote!(vc), quote!(s_dot), quote!(s1_dot), quote!(s2_dot))
        };
        match &stmt.kind {
            Kind::Actuator { .. } | Kind::Rrr { .. } => {
                self.named(pv, quote!(#gr.#pt), vec_ty());
                self.named(self.own(stmt, 0), quote!(#gr.#r1), quote!(T));
                self.named(self.own(stmt, 1), quote!(#gr.#r2), quote!(T));
            }
            Kind::Rrp { .. } => {
                self.named(pv, quote!(#gr.#pt), vec_ty());
                self.named(self.own(stmt, 0), quote!(#gr.#r1), quote!(T));
                self.slide_values.push((i, 0, quote!(#gr.#sd)));
            }
            Kind::Rpr { .. } => {
                let r = if self.accel {
                    quote!(alpha)
                } else {
                    quote!(omega)
                };
                self.named(self.own(stmt, 0), quote!(#gr.#r), quote!(T));
                self.named(self.own(stmt, 1), quote!(#gr.#r), quote!(T));
                self.slide_values.push((i, 0, quote!(#gr.#sd)));
            }
            Kind::Prp { .. } => {
                self.named(pv, quote!(#gr.#pt), vec_ty());
                self.slide_values.push((i, 0, quote!(#gr.#sd1)));
                self.slide_values.push((i, 1, quote!(#gr.#sd2)));
            }
            _ => {
                let q = if self.accel { quote!(aq) } else { quote!(vq) };
                self.named(pv, quote!(#gr.#q), vec_ty());
                self.slide_values.push((i, 0, quote!(#gr.#sd1)));
                self.slide_values.push((i, 1, quote!(#gr.#sd2)));
            }
        }
    }

    /// The output fields' values: points, links, slides.
    fn outputs(&self, out: &Outputs) -> Vec<Output> {
        let mut outs = Vec::new();
        for p in &out.points {
            let value = if self.moving.contains(&p.to_string()) {
                let v = format_ident!("{}_{}", self.pfx, p);
                quote!(#v)
            } else {
                quote!(::mechanism::Vector2::zeros())
            };
            outs.push(Output {
                name: p.clone(),
                ty: vec_ty(),
                value,
            });
        }
        for link in &out.links {
            let value = self
                .link_rate(link)
                .map(|w| quote!(#w))
                .unwrap_or_else(lit_zero);
            outs.push(Output {
                name: link.clone(),
                ty: quote!(T),
                value,
            });
        }
        for crate::plan::Slide {
            name: slide,
            stmt: i,
            slot,
        } in &out.slides
        {
            let value = self
                .slide_values
                .iter()
                .find(|(si, ss, _)| si == i && ss == slot)
                .map(|(_, _, v)| v.clone())
                .unwrap_or_else(lit_zero);
            outs.push(Output {
                name: slide.clone(),
                ty: quote!(T),
                value,
            });
        }
        outs
    }
}

/// The core type of a group's (or the actuator's) rates.
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

/// Velocity or acceleration statements of a planned model; `moving` holds
/// the points that move.
pub(super) fn code(model: &Model, plan: &Plan, moving: &BTreeSet<String>, rate: Rate) -> RatesCode {
    let accel = rate == Rate::Acceleration;
    let mut em = RateEmitter {
        model,
        plan,
        moving,
        accel,
        pfx: if accel { "acc" } else { "vel" },
        wpfx: if accel { "alpha" } else { "omega" },
        code: TokenStream::new(),
        fields: Vec::new(),
        slide_values: Vec::new(),
    };
    for &i in &plan.solve {
        em.statement(i);
    }
    let outputs = em.outputs(&plan.outputs);
    // Hidden fields that are also outputs are kept once (as outputs).
    let out_names: BTreeSet<String> = outputs.iter().map(|o| o.name.to_string()).collect();
    let mut hidden = em.fields;
    hidden.retain(|f| !out_names.contains(&f.name.to_string()));
    RatesCode {
        code: em.code,
        hidden,
        outputs,
    }
}

/// The columns of a rate struct: the outputs' names, types and values, and
/// the hidden fields some reader reads (names, types).
struct Columns {
    code: TokenStream,
    out_names: Vec<Ident>,
    out_types: Vec<TokenStream>,
    out_values: Vec<TokenStream>,
    hidden_names: Vec<Ident>,
    hidden_types: Vec<TokenStream>,
}

impl Columns {
    /// Keeps the hidden fields of `rates` that `reads` reads of `analysis`.
    fn new(rates: RatesCode, reads: &Reads, analysis: Analysis) -> Self {
        let mut c = Columns {
            code: rates.code,
            out_names: Vec::new(),
            out_types: Vec::new(),
            out_values: Vec::new(),
            hidden_names: Vec::new(),
            hidden_types: Vec::new(),
        };
        for o in rates.outputs {
            c.out_names.push(o.name);
            c.out_types.push(o.ty);
            c.out_values.push(o.value);
        }
        for f in rates.hidden {
            if reads.reads(analysis, &f.name) {
                c.hidden_names.push(f.name);
                c.hidden_types.push(f.ty);
            }
        }
        c
    }
}

/// `__condition`: the smallest of the groups' velocity indicators, one `let`
/// per group (a nested `min(min(..), ..)` would nest as deep as the chain is
/// long); 1 without groups.
fn condition(model: &Model, plan: &Plan) -> TokenStream {
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
    match conditions.split_first() {
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
    }
}

/// The velocity struct and the `velocity` method. `reads`: what later code
/// reads of the struct.
pub(super) fn velocity_items(
    model: &Model,
    plan: &Plan,
    rates: RatesCode,
    reads: &Reads,
) -> Generated {
    let names = TypeNames::of(model);
    let (name, vis) = (&names.name, &model.vis);
    let (position_ty, velocity_ty, input_ty) = (&names.position, &names.velocity, &names.input);
    let vel_docs = output_docs(&plan.outputs, 1);
    let condition = condition(model, plan);
    let vel_doc = format!("Velocity of [`{name}`]: point velocities in length units per second, link angular velocities in rad/s (counter-clockwise positive), slide rates in length units per second.");
    let c = Columns::new(rates, reads, Analysis::Velocity);
    let (code, on, ot, oc) = (&c.code, &c.out_names, &c.out_types, &c.out_values);
    let (hn, ht) = (&c.hidden_names, &c.hidden_types);
    let items = quote! {
        #[doc = #vel_doc]
        #[derive(Clone, Copy, PartialEq)]
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
    };
    let debug = debug_impl(velocity_ty, on, &["condition"]);
    let items = quote!(#items #debug);
    let methods = quote! {
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
    };
    Generated { items, methods }
}

/// The acceleration struct and the `acceleration` method. `reads`: what
/// later code reads of the struct.
pub(super) fn acceleration_items(
    model: &Model,
    plan: &Plan,
    rates: RatesCode,
    reads: &Reads,
) -> Generated {
    let names = TypeNames::of(model);
    let (name, vis) = (&names.name, &model.vis);
    let (position_ty, velocity_ty, acceleration_ty, input_ty) = (
        &names.position,
        &names.velocity,
        &names.acceleration,
        &names.input,
    );
    let acc_docs = output_docs(&plan.outputs, 2);
    let acc_doc = format!("Acceleration of [`{name}`]: point accelerations in length units per s^2, link angular accelerations in rad/s^2, slide accelerations in length units per s^2.");
    let c = Columns::new(rates, reads, Analysis::Acceleration);
    let (code, on, ot, oc) = (&c.code, &c.out_names, &c.out_types, &c.out_values);
    let (hn, ht) = (&c.hidden_names, &c.hidden_types);
    let (acc_marker, acc_marker_init) = marker(on.is_empty() && hn.is_empty());
    let items = quote! {
        #[doc = #acc_doc]
        #[derive(Clone, Copy, PartialEq)]
        #[allow(non_snake_case)]
        #vis struct #acceleration_ty<T: ::mechanism::Real = ::core::primitive::f64> {
            #(#[doc = #acc_docs] pub #on: #ot,)*
            #(#[doc(hidden)] pub #hn: #ht,)*
            #acc_marker
        }
    };
    let debug = debug_impl(acceleration_ty, on, &[]);
    let items = quote!(#items #debug);
    let methods = quote! {
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
    };
    Generated { items, methods }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::emit::moving_points;
    use crate::emit::test_support::{flat, four_bar, planned};

    fn rates(src: &str, rate: Rate) -> RatesCode {
        let (model, plan) = planned(src);
        let moving = moving_points(&model, &plan);
        code(&model, &plan, &moving, rate)
    }

    fn output(rates: &RatesCode, name: &str) -> String {
        let o = rates.outputs.iter().find(|o| o.name == name).unwrap();
        flat(&o.value)
    }

    // Proves a crank's link rate is its input's rate (velocity) or
    // acceleration (acceleration), and a ground point's motion is zero with
    // no code of its own.
    #[test]
    fn crank_rates_are_the_inputs_and_ground_points_do_not_move() {
        let src = four_bar("outputs { O2, A, link2 }");
        let vel = rates(&src, Rate::Velocity);
        let code = flat(&vel.code);
        assert!(code.contains("letomega_link2=rates.theta2;"), "{code}");
        assert!(!code.contains("vel_O2"), "{code}");
        assert_eq!(output(&vel, "link2"), "omega_link2");
        assert_eq!(output(&vel, "A"), "vel_A");
        assert_eq!(output(&vel, "O2"), "::mechanism::Vector2::zeros()");
        let acc = rates(&src, Rate::Acceleration);
        assert!(flat(&acc.code).contains("letalpha_link2=accels.theta2;"));
        assert_eq!(output(&acc, "link2"), "alpha_link2");
    }

    // Proves the RRR's velocity passes its link lengths (the determinant's
    // scale, no square root) and a moving / fixed pivot as Some / None, and
    // its acceleration reads the velocity's group state `vel.grp_v_B`.
    #[test]
    fn rrr_velocity_by_lengths_and_acceleration_from_the_velocity_state() {
        let src = four_bar("");
        let vel = flat(&rates(&src, Rate::Velocity).code);
        assert!(vel.contains("letgrp_v_B=::mechanism::dyad::rrr::velocity_lengths(&pos.grp_B,self.coupler,self.rocker,::core::option::Option::Some(&vel_A),::core::option::Option::None)"), "{vel}");
        let acc = flat(&rates(&src, Rate::Acceleration).code);
        assert!(
            acc.contains("rrr::acceleration(&pos.grp_B,&vel.grp_v_B,"),
            "{acc}"
        );
        assert!(acc.contains("letacc_B=grp_a_B.ac;"), "{acc}");
    }

    // Proves the velocity's `__condition` is 1 without groups, the one group's
    // indicator with one, and one `min` per further group (no nesting).
    #[test]
    fn condition_is_one_let_per_group() {
        let crank_only = "pub Crank {
            let O = ground(0.0, 0.0);
            let A = crank(O, 1.0, t) as link;
        }";
        let (model, plan) = planned(crank_only);
        assert_eq!(
            flat(&condition(&model, &plan)),
            "let__condition=<Tas::mechanism::Real>::lit(1f64);"
        );
        let (model, plan) = planned(&four_bar(""));
        assert_eq!(
            flat(&condition(&model, &plan)),
            "let__condition=grp_v_B.condition;"
        );
        let six_bar = four_bar("let D = rrr(P, 200.0, O4, 300.0, right) as (link5, link6);");
        let (model, plan) = planned(&six_bar);
        assert_eq!(
            flat(&condition(&model, &plan)),
            "let__condition=grp_v_B.condition;let__condition=::mechanism::geometry::min(__condition,grp_v_D.condition);"
        );
    }
}
