//! The velocity and acceleration analyses: each statement's rate code in
//! solve order (one function per statement family), the velocity and
//! acceleration structs and their methods.

use super::names::{debug_impl, lit_zero, marker, opt_point, output_docs, Generated, TypeNames};
use crate::keys::{GuideName, LinkName, PointName};
use crate::kinds;
use crate::kinds::rates::{vec_ty, RateCx};
use crate::kinds::reads::{Analysis, Reads};
use crate::model::{Model, StmtId};
use crate::names::Family;
use crate::plan::{Outputs, Plan};
use crate::value::lit;
use proc_macro2::TokenStream;
use quote::quote;
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
    plan: &'a Plan,
    moving: &'a BTreeSet<PointName>,
    accel: bool,
    /// `vel_` or `acc_`: the family of point motions.
    pfx: Family,
    /// `omega_` or `alpha_`: the family of link rates.
    wpfx: Family,
    /// The statement being emitted (its slides' rates are keyed by it).
    current: StmtId,
    code: TokenStream,
    fields: Vec<Field>,
    slide_values: Vec<(StmtId, usize, TokenStream)>,
    /// The recorder of the code's reads of `pos` and `vel`.
    reads: &'a Reads,
}

fn none() -> TokenStream {
    quote!(::core::option::Option::None)
}

impl RateCx for RateEmitter<'_> {
    fn accel(&self) -> bool {
        self.accel
    }

    fn moves(&self, p: &Ident) -> bool {
        self.moving.contains(&PointName::of(p))
    }

    fn point_arg(&self, p: &Ident) -> TokenStream {
        opt_point(p, self.moving, self.pfx, &quote!())
    }

    /// Guide velocity argument (in the velocity fn: local; in acceleration: from `vel`).
    fn guide_vel(&self, g: &Ident) -> TokenStream {
        if !self.carried(g) {
            return none();
        }
        let n = Family::Gvel.of(g);
        if self.accel {
            let n = self.reads.vel(&n);
            quote!(::core::option::Option::Some(&#n))
        } else {
            quote!(::core::option::Option::Some(&#n))
        }
    }

    fn guide_acc(&self, g: &Ident) -> TokenStream {
        if !self.carried(g) {
            return none();
        }
        let n = Family::Gacc.of(g);
        quote!(::core::option::Option::Some(&#n))
    }

    fn link_rate(&self, link: &Ident) -> Option<Ident> {
        self.plan
            .turning_link(&LinkName::of(link))
            .map(|l| self.wpfx.of(l))
    }

    fn link_omega_in_accel(&self, link: &Ident) -> Option<TokenStream> {
        self.plan
            .turning_link(&LinkName::of(link))
            .map(|l| self.reads.vel(&Family::Omega.of(&l)))
    }

    fn code(&mut self, code: TokenStream) {
        self.code.extend(code);
    }

    fn field(&mut self, name: Ident, ty: TokenStream) {
        self.fields.push(Field { name, ty });
    }

    fn slide(&mut self, slot: usize, value: TokenStream) {
        self.slide_values.push((self.current, slot, value));
    }

    fn reads(&self) -> &Reads {
        self.reads
    }
}

impl RateEmitter<'_> {
    fn carried(&self, g: &Ident) -> bool {
        self.plan
            .guides
            .get(&GuideName::of(g))
            .is_some_and(|i| i.carrier.is_some())
    }

    /// The output fields' values: points, links, slides.
    fn outputs(&self, out: &Outputs) -> Vec<Output> {
        let mut outs = Vec::new();
        for p in &out.points {
            let value = if self.moving.contains(&PointName::of(p)) {
                let v = self.pfx.of(p);
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

/// Velocity or acceleration statements of a planned model; `moving` holds
/// the points that move; `reads` records the code's reads of `pos` and `vel`.
pub(super) fn code(
    model: &Model,
    plan: &Plan,
    moving: &BTreeSet<PointName>,
    rate: Rate,
    reads: &Reads,
) -> RatesCode {
    let accel = rate == Rate::Acceleration;
    let mut em = RateEmitter {
        plan,
        moving,
        accel,
        pfx: Family::motion(accel),
        wpfx: Family::link_rate(accel),
        current: StmtId(0),
        code: TokenStream::new(),
        fields: Vec::new(),
        slide_values: Vec::new(),
        reads,
    };
    for &i in &plan.solve {
        em.current = i;
        kinds::of(&model.stmts[i]).rates(&mut em);
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
        .filter(|s| kinds::of(s).rate_system())
        .map(|s| Family::GrpVel.of(&s.name))
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
    // `vel.rates` is a field every velocity struct has, read by the
    // velocity's own family: not a reader that decides the struct's fields.
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
    use crate::emit::test_support::{flat, four_bar, planned};

    fn rates(src: &str, rate: Rate) -> RatesCode {
        let (model, plan) = planned(src);
        let moving = plan.moving_points(&model);
        code(&model, &plan, &moving, rate, &Reads::default())
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
