//! Stage 5b, emit the force analysis: the known load of every link (inertia,
//! weight, external forces and couples), then the groups and drivers in the
//! reverse of the solve order, each through its fixed-size system in
//! `mechanism::force`, passing its outer reactions (negated) to the bodies it
//! is attached to; then the driving efforts and the power balance.
//!
//! Only the terms a definition has are generated: no gravity statement, no
//! weight terms; a link without mass, no inertia terms (its load starts with
//! the first reaction passed to it); no moment of inertia or a link that does
//! not turn, no inertia couple; a fixed centre of mass, no `m a` term.

use crate::emit::tag;
use crate::model::{ForceSpecValue, Kind, Model, Stmt};
use crate::plan::Plan;
use crate::value::{lit, Value};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use std::collections::BTreeSet;
use syn::Ident;

/// The generated force analysis: items (structs) and methods.
pub struct ForcesCode {
    /// `NameForces` and, with a `loads` block, `NameLoads`.
    pub items: TokenStream,
    /// `forces(...)`.
    pub methods: TokenStream,
    /// The extra parameter of `forces` and `solve` (`loads: &NameLoads<T>`),
    /// empty without a `loads` block.
    pub loads_param: TokenStream,
    /// The matching argument (`loads`), empty without a `loads` block.
    pub loads_arg: TokenStream,
}

/// A reaction field of the generated forces struct.
struct Reaction {
    name: Ident,
    ty: TokenStream,
    value: TokenStream,
    doc: String,
}

struct ForceEmitter<'a> {
    model: &'a Model,
    plan: &'a Plan,
    moving: &'a BTreeSet<String>,
    /// Links whose load local exists (the others carry no load yet).
    loaded: BTreeSet<String>,
    code: TokenStream,
    /// Power terms (expressions) for the balance.
    power: Vec<TokenStream>,
}

impl ForceEmitter<'_> {
    /// The reference point a link's load is accumulated about: its first point.
    fn reference(&self, link: &str) -> Ident {
        format_ident!("{}", self.plan.links[link].points[0])
    }

    /// Adds a wrench (given as code about the link's reference point) to a link's load.
    fn add(&mut self, link: &str, wrench: TokenStream) {
        let local = format_ident!("load_{}", link);
        if self.loaded.insert(link.to_string()) {
            self.code.extend(quote!(let #local = #wrench;));
        } else {
            self.code.extend(quote!(let #local = #local + #wrench;));
        }
    }

    /// A force `force` (code) acting on `link` at point `at`, as a wrench about
    /// the link's reference point.
    fn force_on(&mut self, link: &str, force: TokenStream, at: &Ident) {
        let r = self.reference(link);
        let wrench = if *at == r {
            quote!(::mechanism::force::Wrench::new(#force, <T as ::mechanism::Real>::lit(0.0)))
        } else {
            quote!(::mechanism::force::Wrench::force_at(&(#force), &pos.#at, &pos.#r))
        };
        self.add(link, wrench);
    }

    /// A prismatic reaction `rx` (about point `about`) negated onto `body`.
    fn prismatic_on(&mut self, body: Option<String>, rx: TokenStream, about: &Ident) {
        if let Some(body) = body {
            let r = self.reference(&body);
            let wrench = if *about == r {
                quote!(-(#rx).wrench())
            } else {
                quote!(-(#rx).wrench_about(&pos.#about, &pos.#r))
            };
            self.add(&body, wrench);
        }
    }

    /// An outer revolute joint at `point` whose reaction on the group is
    /// `rx.field`: passes the reaction, negated, to the body that owns the
    /// point (nothing for the ground) and returns that body.
    fn pass_revolute(&mut self, point: &Ident, rx: &Ident, field: &str) -> Option<String> {
        let body = self.plan.body_of_point(&point.to_string());
        if let Some(b) = &body {
            let field = format_ident!("{}", field);
            self.force_on(b, quote!(-#rx.#field), point);
        }
        body
    }

    /// The load of `link` as a wrench about `point`.
    fn load_about(&self, link: &Ident, point: &Ident) -> TokenStream {
        let l = link.to_string();
        if !self.loaded.contains(&l) {
            return quote!(::mechanism::force::Wrench::zero());
        }
        let local = format_ident!("load_{}", l);
        let r = self.reference(&l);
        if *point == r {
            quote!(#local)
        } else {
            quote!(#local.moved(&pos.#r, &pos.#point))
        }
    }

    /// Velocity of a point (code), `None` when it never moves.
    fn velocity(&self, point: &Ident) -> Option<TokenStream> {
        self.moving.contains(&point.to_string()).then(|| {
            let v = format_ident!("vel_{}", point);
            quote!(vel.#v)
        })
    }

    /// Angular velocity and acceleration of a link (code), `None` when it
    /// does not turn.
    fn rates_of(&self, link: &Ident) -> Option<(TokenStream, TokenStream)> {
        self.plan.turning_link(&link.to_string()).map(|l| {
            let (w, a) = (format_ident!("omega_{}", l), format_ident!("alpha_{}", l));
            (quote!(vel.#w), quote!(acc.#a))
        })
    }

    /// The name of the body on the far side of a joint, for field names.
    fn body_name(body: &Option<String>) -> String {
        body.clone().unwrap_or_else(|| "ground".into())
    }

    /// Known loads: inertia and weight of every link with mass, external
    /// forces and couples.
    fn known_loads(&mut self) {
        let model = self.model;
        let k = &model.kinetics;
        if let Some((_, gx, gy)) = &k.gravity {
            let (gx, gy) = (gx.emit(), gy.emit());
            self.code
                .extend(quote!(let gravity = ::mechanism::Vector2::new(#gx, #gy);));
        }
        for m in &k.masses {
            let link = m.link.to_string();
            let at = &m.at;
            let mass = self.checked(&m.mass, &link, Quantity::Mass);
            let inertia_force = format_ident!("pw_inertia_force_{}", link);
            let weight = format_ident!("pw_weight_{}", link);
            let v_g = self.velocity(at);
            let mut force_terms = Vec::new();
            if v_g.is_some() {
                let a = format_ident!("acc_{}", at);
                self.code
                    .extend(quote!(let #inertia_force = acc.#a * (-#mass);));
                force_terms.push(quote!(#inertia_force));
            }
            if k.gravity.is_some() {
                self.code.extend(quote!(let #weight = gravity * #mass;));
                force_terms.push(quote!(#weight));
            }
            let couple = match (&m.inertia, self.rates_of(&m.link)) {
                (Some(j), Some((w, alpha))) if j.fold() != Some(0.0) => {
                    let j = self.checked(j, &link, Quantity::Inertia);
                    let c = format_ident!("pw_inertia_couple_{}", link);
                    self.code.extend(quote!(let #c = -(#j * #alpha);));
                    self.power.push(quote!(#c * #w));
                    Some(quote!(#c))
                }
                _ => None,
            };
            if let Some(v) = &v_g {
                self.power
                    .push(quote!(::mechanism::geometry::dot(&#inertia_force, &#v)));
                if k.gravity.is_some() {
                    self.power
                        .push(quote!(::mechanism::geometry::dot(&#weight, &#v)));
                }
            }
            if !force_terms.is_empty() {
                let total = force_terms
                    .iter()
                    .skip(1)
                    .fold(force_terms[0].clone(), |acc, t| quote!(#acc + #t));
                self.force_on(&link, total, at);
            }
            if let Some(c) = couple {
                self.add(&link, quote!(::mechanism::force::Wrench::couple(#c)));
            }
        }
        for (n, f) in k.forces.iter().enumerate() {
            let link = match &f.on {
                Some(l) => l.to_string(),
                None => self.plan.links_with_point(&f.at.to_string())[0].clone(),
            };
            let local = format_ident!("pw_force_{}", n);
            let value = match &f.value {
                ForceSpecValue::Components(x, y) => {
                    let (x, y) = (x.emit(), y.emit());
                    quote!(::mechanism::Vector2::new(#x, #y))
                }
                ForceSpecValue::Along(guide, v) => {
                    let v = v.emit();
                    quote!(pos.#guide.dir * #v)
                }
            };
            self.code.extend(quote!(let #local = #value;));
            if let Some(v) = self.velocity(&f.at) {
                self.power
                    .push(quote!(::mechanism::geometry::dot(&#local, &#v)));
            }
            self.force_on(&link, quote!(#local), &f.at);
        }
        for (n, t) in k.torques.iter().enumerate() {
            let local = format_ident!("pw_torque_{}", n);
            let value = t.value.emit();
            self.code.extend(quote!(let #local = #value;));
            if let Some((w, _)) = self.rates_of(&t.on) {
                self.power.push(quote!(#local * #w));
            }
            self.add(
                &t.on.to_string(),
                quote!(::mechanism::force::Wrench::couple(#local)),
            );
        }
    }

    /// A mass or moment of inertia of `link` as the force analysis uses it. A
    /// literal one was checked at expansion (`model`); one that depends on
    /// `params` or `loads` is checked here, at run time, into a local: a mass
    /// must be finite and positive, a moment of inertia finite and not
    /// negative, else a typed error naming the group that creates the link
    /// (a negative mass would give finite, consistent and wrong reactions).
    fn checked(&mut self, value: &Value, link: &str, quantity: Quantity) -> TokenStream {
        if value.fold().is_some() {
            return value.emit();
        }
        let Some(stmt) = self
            .model
            .stmts
            .iter()
            .find(|s| s.links.iter().any(|l| l == link))
        else {
            return value.emit();
        };
        let v = value.emit();
        let primitive = primitive(&stmt.kind);
        let t = tag(stmt);
        let (local, check, what) = match quantity {
            Quantity::Mass => (
                format_ident!("pw_m_{}", link),
                quote!(positive),
                format!("mass of `{link}`"),
            ),
            Quantity::Inertia => (
                format_ident!("pw_j_{}", link),
                quote!(non_negative),
                format!("moment of inertia of `{link}`"),
            ),
        };
        self.code.extend(quote!(
            let #local = ::mechanism::geometry::#check(#v, #primitive, #what) #t;
        ));
        quote!(#local)
    }

    /// One group or driver: its reactions, passed on to the outside bodies.
    fn group(
        &mut self,
        stmt: &Stmt,
        reactions: &mut Vec<Reaction>,
        conditions: &mut Vec<TokenStream>,
    ) {
        let name = &stmt.name;
        let rx = format_ident!("rx_{}", name);
        let g = format_ident!("grp_{}", name);
        let t = tag(stmt);
        let links = &stmt.links;
        let owner = |p: &Ident| self.plan.body_of_point(&p.to_string());
        let carrier = |guide: &Ident| self.plan.body_of_guide(&guide.to_string());
        let vec_ty = quote!(::mechanism::Vector2<T>);
        let pr_ty = quote!(::mechanism::force::PrismaticReaction<T>);
        let revolute =
            |from: &Option<String>, to: &Ident, at: &Ident, field: TokenStream| Reaction {
                name: format_ident!("r_{}_{}", Self::body_name(from), to),
                ty: vec_ty.clone(),
                value: quote!(#rx.#field),
                doc: format!(
                    "Force of `{}` on `{to}` at `{at}` (force units, global frame).",
                    Self::body_name(from)
                ),
            };
        let prismatic = |from: &Option<String>, to: &Ident, about: &Ident, field: TokenStream| {
            Reaction {
            name: format_ident!("r_{}_{}", Self::body_name(from), to),
            ty: pr_ty.clone(),
            value: quote!(#rx.#field),
            doc: format!(
                "Reaction of the prismatic pair of `{}` on `{to}`: normal force (signed, along the left normal of the sliding direction) and couple about `{about}` (counter-clockwise positive).",
                Self::body_name(from)
            ),
        }
        };
        let drive = |input: &Ident, what: &str| Reaction {
            name: format_ident!("drive_{}", input),
            ty: quote!(T),
            value: quote!(#rx.#input),
            doc: what.to_string(),
        };
        match &stmt.kind {
            Kind::Crank { pivot, input, .. } => {
                let load = self.load_about(&links[0], pivot);
                self.code
                    .extend(quote!(let #rx = ::mechanism::force::crank::reactions(&#load) #t;));
                let body = owner(pivot);
                if let Some(b) = &body {
                    let r = self.reference(b);
                    let w = quote!(::mechanism::force::Wrench::force_at(&(-#rx.pivot), &pos.#pivot, &pos.#r).with_couple(-#rx.torque));
                    self.add(b, w);
                }
                reactions.push(revolute(&body, &links[0], pivot, quote!(pivot)));
                let mut d = drive(input, &format!("Driving torque on `{}` (input `{input}`; force x length units, counter-clockwise positive): the balancing moment.", links[0]));
                d.value = quote!(#rx.torque);
                self.power.push(quote!(#rx.torque * vel.rates.#input));
                reactions.push(d);
            }
            Kind::Slider { guide, input, .. } => {
                let load = self.load_about(&links[0], name);
                self.code.extend(quote!(let #rx = ::mechanism::force::slider::reactions(&pos.#guide.dir, &#load) #t;));
                let body = carrier(guide);
                if let Some(b) = &body {
                    let r = self.reference(b);
                    let w = quote!(::mechanism::force::Wrench::force_at(&(-(#rx.guide.force + pos.#guide.dir * #rx.drive)), &pos.#name, &pos.#r).with_couple(-#rx.guide.moment));
                    self.add(b, w);
                }
                reactions.push(prismatic(&body, &links[0], name, quote!(guide)));
                let mut d = drive(input, &format!("Driving force on `{}` along its guide (input `{input}`; force units, positive along the guide's direction).", links[0]));
                d.value = quote!(#rx.drive);
                self.power.push(quote!(#rx.drive * vel.rates.#input));
                reactions.push(d);
            }
            Kind::Actuator { a, b, input, .. } => {
                let load = self.load_about(&links[0], a);
                self.code.extend(quote!(let #rx = ::mechanism::force::actuator::reactions(&pos.#a, &pos.#b, &pos.#name, &#load) #t;));
                let body_a = self.pass_revolute(a, &rx, "a");
                if let Some(body) = owner(b) {
                    let axis = format_ident!("rx_axis_{}", name);
                    self.code.extend(quote!(let #axis = (pos.#name - pos.#b) / ::mechanism::geometry::length(&(pos.#name - pos.#b));));
                    self.force_on(&body, quote!(#axis * (-#rx.axial)), b);
                }
                reactions.push(revolute(&body_a, &links[0], a, quote!(a)));
                let mut d = drive(input, &format!("Axial force of the actuator `{}` (input `{input}`; force units, positive when it pushes its ends apart).", links[1]));
                d.value = quote!(#rx.axial);
                self.power.push(quote!(#rx.axial * vel.rates.#input));
                conditions.push(quote!(#rx.min_pivot_ratio));
                reactions.push(d);
            }
            Kind::Rrr { a, b, .. } => {
                let (l1, l2) = (
                    self.load_about(&links[0], name),
                    self.load_about(&links[1], name),
                );
                self.code.extend(quote!(let #rx = ::mechanism::force::rrr::reactions(&pos.#a, &pos.#b, &pos.#name, &#l1, &#l2) #t;));
                let ba = self.pass_revolute(a, &rx, "a");
                let bb = self.pass_revolute(b, &rx, "b");
                reactions.push(revolute(&ba, &links[0], a, quote!(a)));
                reactions.push(revolute(&bb, &links[1], b, quote!(b)));
                reactions.push(revolute(
                    &Some(links[0].to_string()),
                    &links[1],
                    name,
                    quote!(c),
                ));
                conditions.push(quote!(#rx.min_pivot_ratio));
            }
            Kind::Rrp { a, guide, .. } => {
                let (l1, l2) = (
                    self.load_about(&links[0], name),
                    self.load_about(&links[1], name),
                );
                self.code.extend(quote!(let #rx = ::mechanism::force::rrp::reactions(&pos.#a, &pos.#name, &pos.#guide.dir, &#l1, &#l2) #t;));
                let ba = self.pass_revolute(a, &rx, "a");
                let bg = carrier(guide);
                self.prismatic_on(bg.clone(), quote!(#rx.guide), name);
                reactions.push(revolute(&ba, &links[0], a, quote!(a)));
                reactions.push(revolute(
                    &Some(links[0].to_string()),
                    &links[1],
                    name,
                    quote!(c),
                ));
                reactions.push(prismatic(&bg, &links[1], name, quote!(guide)));
                conditions.push(quote!(#rx.min_pivot_ratio));
            }
            Kind::Rpr { a, b, .. } => {
                let (l1, l2) = (self.load_about(&links[0], a), self.load_about(&links[1], a));
                self.code.extend(quote!(let #rx = ::mechanism::force::rpr::reactions(&pos.#a, &pos.#b, &pos.#g.axis, &#l1, &#l2) #t;));
                let ba = self.pass_revolute(a, &rx, "a");
                let bb = self.pass_revolute(b, &rx, "b");
                reactions.push(revolute(&ba, &links[0], a, quote!(a)));
                reactions.push(revolute(&bb, &links[1], b, quote!(b)));
                reactions.push(prismatic(
                    &Some(links[0].to_string()),
                    &links[1],
                    a,
                    quote!(slide),
                ));
                conditions.push(quote!(#rx.min_pivot_ratio));
            }
            Kind::Prp { g1, g2, .. } => {
                let (l1, l2) = (
                    self.load_about(&links[0], name),
                    self.load_about(&links[1], name),
                );
                self.code.extend(quote!(let #rx = ::mechanism::force::prp::reactions(&pos.#name, &pos.#g1.dir, &pos.#g2.dir, &#l1, &#l2) #t;));
                let (c1, c2) = (carrier(g1), carrier(g2));
                self.prismatic_on(c1.clone(), quote!(#rx.guide1), name);
                self.prismatic_on(c2.clone(), quote!(#rx.guide2), name);
                reactions.push(prismatic(&c1, &links[0], name, quote!(guide1)));
                reactions.push(prismatic(&c2, &links[1], name, quote!(guide2)));
                reactions.push(revolute(
                    &Some(links[0].to_string()),
                    &links[1],
                    name,
                    quote!(c),
                ));
                conditions.push(quote!(#rx.min_pivot_ratio));
            }
            Kind::Rpp { a, guide, .. } => {
                let (l1, l2) = (self.load_about(&links[0], a), self.load_about(&links[1], a));
                self.code.extend(quote!(let #rx = ::mechanism::force::rpp::reactions(&pos.#a, &pos.#g.slot, &pos.#guide.dir, &#l1, &#l2) #t;));
                let ba = self.pass_revolute(a, &rx, "a");
                let bg = carrier(guide);
                self.prismatic_on(bg.clone(), quote!(#rx.guide), a);
                reactions.push(revolute(&ba, &links[0], a, quote!(a)));
                reactions.push(prismatic(
                    &Some(links[0].to_string()),
                    &links[1],
                    a,
                    quote!(slot),
                ));
                reactions.push(prismatic(&bg, &links[1], a, quote!(guide)));
                conditions.push(quote!(#rx.min_pivot_ratio));
            }
            Kind::Ground { .. } | Kind::Guide { .. } | Kind::Point { .. } => {}
        }
    }
}

/// What [`ForceEmitter::checked`] checks.
#[derive(Clone, Copy)]
enum Quantity {
    /// A link's mass: finite and positive.
    Mass,
    /// A link's moment of inertia about its centre of mass: finite, `>= 0`.
    Inertia,
}

/// The core's tag of the primitive a statement calls (for run-time errors).
fn primitive(kind: &Kind) -> TokenStream {
    let name = match kind {
        Kind::Crank { .. } => quote!(Crank),
        Kind::Slider { .. } => quote!(Slider),
        Kind::Actuator { .. } => quote!(Actuator),
        Kind::Rrr { .. } => quote!(Rrr),
        Kind::Rrp { .. } => quote!(Rrp),
        Kind::Rpr { .. } => quote!(Rpr),
        Kind::Prp { .. } => quote!(Prp),
        Kind::Rpp { .. } => quote!(Rpp),
        Kind::Ground { .. } | Kind::Guide { .. } | Kind::Point { .. } => quote!(LinkPoint),
    };
    quote!(::mechanism::Primitive::#name)
}

/// Emits the force analysis of a valid, planned model whose definition asks
/// for it. `moving` holds the points that move.
pub fn emit(model: &Model, plan: &Plan, moving: &BTreeSet<String>) -> ForcesCode {
    let name = &model.name;
    let vis = &model.vis;
    let forces_ty = format_ident!("{}Forces", name);
    let loads_ty = format_ident!("{}Loads", name);
    let position_ty = format_ident!("{}Position", name);
    let velocity_ty = format_ident!("{}Velocity", name);
    let acceleration_ty = format_ident!("{}Acceleration", name);
    let mut em = ForceEmitter {
        model,
        plan,
        moving,
        loaded: BTreeSet::new(),
        code: TokenStream::new(),
        power: Vec::new(),
    };
    em.known_loads();
    let mut reactions = Vec::new();
    let mut conditions = Vec::new();
    for &i in plan.solve.iter().rev() {
        em.group(&model.stmts[i], &mut reactions, &mut conditions);
    }
    // Field names must be unique: a second joint between the same two bodies
    // gets the joint's point appended.
    let mut seen = BTreeSet::new();
    for r in &mut reactions {
        let mut candidate = r.name.to_string();
        let mut k = 2;
        while !seen.insert(candidate.clone()) {
            candidate = format!("{}_{k}", r.name);
            k += 1;
        }
        r.name = format_ident!("{}", candidate);
    }
    // The velocity's indicator first: a group's force system is the
    // transpose of its rate system (virtual work), so it is singular at the
    // same poses, and the scaled determinants see that in any frame. The
    // force solves' relative pivots are row-equilibrated and can miss it: a
    // PRP with its guides along the x axis has a row (the x balance) whose
    // entries all vanish together, and the scaling lifts it back to 1.
    let condition = conditions.iter().fold(
        quote!(vel.condition),
        |acc, c| quote!(::mechanism::geometry::min(#acc, #c)),
    );
    let terms: Vec<Ident> = (0..em.power.len())
        .map(|k| format_ident!("pw_{}", k))
        .collect();
    let power_terms = &em.power;
    let power = if terms.is_empty() {
        lit(0.0)
    } else {
        let sum = terms.iter().skip(1).fold(
            {
                let t = &terms[0];
                quote!(#t)
            },
            |acc, t| quote!(#acc + #t),
        );
        // The largest |term| by comparisons (`RealField::max` would call
        // libm's `fmaxf`, about 20 instructions a call on a Cortex-M4F); a
        // NaN term is skipped, as `max` skips it, and shows in the sum.
        let residual = quote! {{
            let pw_scale = [#(::mechanism::geometry::abs(#terms)),*]
                .into_iter()
                .fold(<T as ::mechanism::Real>::lit(0.0), |m, a| if a > m { a } else { m });
            let pw_sum = #sum;
            if !(pw_scale.finite() && pw_sum.finite()) {
                ::core::option::Option::None
            } else if pw_scale > <T as ::mechanism::Real>::lit(0.0) {
                ::core::option::Option::Some(::mechanism::geometry::abs(pw_sum) / pw_scale)
            } else {
                ::core::option::Option::Some(<T as ::mechanism::Real>::lit(0.0))
            }
        }};
        // Reactions, loads and rates are finite here (every group checks
        // them), so only a product that overflows `T` (an `f32` force of
        // 1e38 N at 10 m/s) makes a term infinite: then no balance can be
        // shown, and 1 is reported rather than a NaN (a rescaled second
        // evaluation of every term would double this code for that case).
        quote! {{
            #(let #terms = #power_terms;)*
            match #residual {
                ::core::option::Option::Some(r) => r,
                ::core::option::Option::None => <T as ::mechanism::Real>::lit(1.0),
            }
        }}
    };
    let code = em.code;
    let field_names: Vec<&Ident> = reactions.iter().map(|r| &r.name).collect();
    let field_types: Vec<&TokenStream> = reactions.iter().map(|r| &r.ty).collect();
    let field_values: Vec<&TokenStream> = reactions.iter().map(|r| &r.value).collect();
    let field_docs: Vec<&String> = reactions.iter().map(|r| &r.doc).collect();
    let forces_doc = format!("Joint reactions and driving efforts of [`{name}`] (force units: mass x length / s^2 in the definition's units; N with kg, m, s). Each reaction is the force of one body on another in the global frame, as its field says.");
    let loads = &model.kinetics.loads;
    let (loads_item, loads_param, loads_arg) = if loads.is_empty() {
        (quote!(), quote!(), quote!())
    } else {
        let names: Vec<&Ident> = loads.iter().map(|(n, _)| n).collect();
        let defaults: Vec<TokenStream> = loads.iter().map(|(_, v)| lit(*v)).collect();
        let doc = format!("Load values of [`{name}`] supplied per evaluation (declared in `loads {{ }}`); `Default` gives the definition's values.");
        (
            quote! {
                #[doc = #doc]
                #[derive(Clone, Copy, Debug, PartialEq)]
                #[allow(non_snake_case)]
                #vis struct #loads_ty<T = ::core::primitive::f64> {
                    #(#[doc = "Load value (force, couple or factor, as the definition uses it)."] pub #names: T,)*
                }
                impl<T: ::mechanism::Real> ::core::default::Default for #loads_ty<T> {
                    #[inline]
                    fn default() -> Self {
                        #loads_ty { #(#names: #defaults,)* }
                    }
                }
            },
            quote!(, loads: &#loads_ty<T>),
            quote!(, loads),
        )
    };
    let items = quote! {
        #[doc = #forces_doc]
        #[derive(Clone, Copy, Debug, PartialEq)]
        #[allow(non_snake_case)]
        #vis struct #forces_ty<T: ::mechanism::Real = ::core::primitive::f64> {
            #(#[doc = #field_docs] pub #field_names: #field_types,)*
            /// Conditioning indicator: the smaller of the velocity's
            /// `condition` (the groups' scaled determinants, singular at the
            /// same poses as their force systems) and the smallest relative
            /// pivot over the groups' force systems; 1 for a well-conditioned
            /// pose, tending to 0 towards a singular one (toggle, dead centre,
            /// parallel guides).
            pub condition: T,
            /// Power balance residual: |driver power + power of the external
            /// loads, weights, inertia forces and couples| divided by the largest
            /// of those powers (0 when all vanish). A few eps when consistent.
            pub power_residual: T,
        }
        #loads_item
    };
    let methods = quote! {
        /// Force analysis at a solved pose: joint reactions, driving efforts,
        /// the conditioning indicator and the power-balance residual.
        /// Groups are solved in the reverse of the solve order.
        ///
        /// Errors name the group whose force system is singular or whose
        /// loads are not finite.
        #[inline(always)]
        #[allow(non_snake_case, unused_variables, clippy::too_many_arguments)]
        pub fn forces(&self, pos: &#position_ty<T>, vel: &#velocity_ty<T>, acc: &#acceleration_ty<T> #loads_param) -> ::core::result::Result<#forces_ty<T>, ::mechanism::Error<T>> {
            #code
            let condition = #condition;
            let power_residual = #power;
            ::core::result::Result::Ok(#forces_ty { #(#field_names: #field_values,)* condition, power_residual })
        }
    };
    ForcesCode {
        items,
        methods,
        loads_param,
        loads_arg,
    }
}

#[cfg(test)]
mod tests {
    use proc_macro2::TokenStream;
    use std::str::FromStr;

    /// The messages of the `compile_error!`s in the expansion of `src`.
    fn errors(src: &str) -> Vec<String> {
        let out = crate::expand(TokenStream::from_str(src).unwrap()).to_string();
        out.split("compile_error !")
            .skip(1)
            .map(|rest| rest.split(';').next().unwrap_or("").to_string())
            .collect()
    }

    /// A boom lifted by a cylinder, and an RRR group pinned at `PIN`.
    fn arm(pin: &str) -> String {
        format!(
            "pub Arm {{
                let A = ground(0.0, 0.0);
                let B = ground(0.6, -0.3);
                let O6 = ground(1.2, 0.2);
                let C = actuator(A, 1.0, B, len, left) as (boom, cyl);
                let M = point(cyl, from B, 0.3, 0 deg);
                let N = point(boom, from A, 0.5, 0 deg);
                let K = rrr({pin}, 0.8, O6, 0.7, right) as (link5, link6);
                mass link6 {{ m = 10.0, at = K }};
                range len = (0.9, 1.3);
            }}"
        )
    }

    #[test]
    fn a_group_pinned_to_an_actuators_cylinder_is_an_error() {
        let on_cylinder = errors(&arm("M"));
        assert_eq!(on_cylinder.len(), 1, "{on_cylinder:?}");
        assert!(
            on_cylinder[0].contains("cylinder `cyl`")
                && on_cylinder[0].contains("two-force member"),
            "{on_cylinder:?}"
        );
        // Pinned to the boom instead: no error.
        assert!(errors(&arm("N")).is_empty());
        // Without a force analysis the cylinder's point is fine.
        let kinematic = arm("M").replace("mass link6 { m = 10.0, at = K };", "");
        assert!(errors(&kinematic).is_empty());
    }
}
