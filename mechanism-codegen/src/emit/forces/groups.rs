//! The force code of each driver and group, one function per kind: its
//! reactions from the loads of its links, passed (negated) to the bodies it
//! is attached to, its fields in the forces struct, its conditioning and its
//! driving power.

use super::{ForceEmitter, Held, Reaction};
use crate::emit::tag;
use crate::model::{Kind, Stmt};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::Ident;

/// `rx_NAME`: the local holding a statement's reactions.
fn rx(stmt: &Stmt) -> Ident {
    format_ident!("rx_{}", stmt.name)
}

/// The reaction of a revolute joint: the force of `from` (a body, or the
/// ground) on `to` at `at`, field `field` of `rx`.
fn revolute(rx: &Ident, from: &Option<String>, to: &Ident, at: &Ident, field: &str) -> Reaction {
    let from = ForceEmitter::body_name(from);
    let field = format_ident!("{}", field);
    Reaction {
        name: format_ident!("r_{}_{}", from, to),
        ty: quote!(::mechanism::Vector2<T>),
        value: quote!(#rx.#field),
        doc: format!("Force of `{from}` on `{to}` at `{at}` (force units, global frame)."),
        held: Held::Force,
    }
}

/// The reaction of a prismatic pair of `from` on `to`, its couple taken
/// about `about`, field `field` of `rx`.
fn prismatic(
    rx: &Ident,
    from: &Option<String>,
    to: &Ident,
    about: &Ident,
    field: &str,
) -> Reaction {
    let from = ForceEmitter::body_name(from);
    let field = format_ident!("{}", field);
    Reaction {
        name: format_ident!("r_{}_{}", from, to),
        ty: quote!(::mechanism::force::PrismaticReaction<T>),
        value: quote!(#rx.#field),
        doc: format!(
            "Reaction of the prismatic pair of `{from}` on `{to}`: normal force (signed, along the left normal of the sliding direction) and couple about `{about}` (counter-clockwise positive)."
        ),
        held: Held::Prismatic,
    }
}

/// The driving effort of `input`, field `field` of `rx` (a torque or a push
/// along the driver's line, as `held` says), documented by `doc`.
fn drive(rx: &Ident, input: &Ident, field: &str, held: Held, doc: String) -> Reaction {
    let field = format_ident!("{}", field);
    Reaction {
        name: format_ident!("drive_{}", input),
        ty: quote!(T),
        value: quote!(#rx.#field),
        doc,
        held,
    }
}

/// The joint between the two links of a group, at `at`.
fn inner(rx: &Ident, links: &[Ident], at: &Ident, field: &str, prismatic_pair: bool) -> Reaction {
    let from = Some(links[0].to_string());
    if prismatic_pair {
        prismatic(rx, &from, &links[1], at, field)
    } else {
        revolute(rx, &from, &links[1], at, field)
    }
}

impl ForceEmitter<'_> {
    /// One group or driver: its reactions, passed on to the outside bodies.
    pub(super) fn group(&mut self, stmt: &Stmt) {
        match &stmt.kind {
            Kind::Crank { pivot, input, .. } => self.crank(stmt, pivot, input),
            Kind::Slider { guide, input, .. } => self.slider(stmt, guide, input),
            Kind::Actuator { a, b, input, .. } => self.actuator(stmt, a, b, input),
            Kind::Rrr { a, b, .. } => self.rrr(stmt, a, b),
            Kind::Rrp { a, guide, .. } => self.rrp(stmt, a, guide),
            Kind::Rpr { a, b, .. } => self.rpr(stmt, a, b),
            Kind::Prp { g1, g2, .. } => self.prp(stmt, g1, g2),
            Kind::Rpp { a, guide, .. } => self.rpp(stmt, a, guide),
            Kind::Ground { .. } | Kind::Guide { .. } | Kind::Point { .. } => {}
        }
    }

    /// `let rx_NAME = CALL.map_err(..)?;`
    fn solve(&mut self, stmt: &Stmt, call: TokenStream) {
        let (rx, t) = (rx(stmt), tag(stmt));
        self.code.extend(quote!(let #rx = #call #t;));
    }

    /// The loads of the two links of a group about `point`.
    fn loads_about(&self, stmt: &Stmt, point: &Ident) -> (TokenStream, TokenStream) {
        (
            self.load_about(&stmt.links[0], point),
            self.load_about(&stmt.links[1], point),
        )
    }

    fn crank(&mut self, stmt: &Stmt, pivot: &Ident, input: &Ident) {
        let (rx, link) = (rx(stmt), &stmt.links[0]);
        let load = self.load_about(link, pivot);
        self.solve(stmt, quote!(::mechanism::force::crank::reactions(&#load)));
        let body = self.plan.body_of_point(&pivot.to_string());
        if let Some(b) = &body {
            let r = self.reference(b);
            let w = quote!(::mechanism::force::Wrench::force_at(&(-#rx.pivot), &pos.#pivot, &pos.#r).with_couple(-#rx.torque));
            self.add(b, w);
        }
        self.reactions
            .push(revolute(&rx, &body, link, pivot, "pivot"));
        self.power.push(quote!(#rx.torque * vel.rates.#input));
        let doc = format!("Driving torque on `{link}` (input `{input}`; force x length units, counter-clockwise positive): the balancing moment.");
        self.reactions
            .push(drive(&rx, input, "torque", Held::Torque, doc));
    }

    fn slider(&mut self, stmt: &Stmt, guide: &Ident, input: &Ident) {
        let (rx, link, name) = (rx(stmt), &stmt.links[0], &stmt.name);
        let load = self.load_about(link, name);
        self.solve(
            stmt,
            quote!(::mechanism::force::slider::reactions(&pos.#guide.dir, &#load)),
        );
        let body = self.plan.body_of_guide(&guide.to_string());
        if let Some(b) = &body {
            let r = self.reference(b);
            let w = quote!(::mechanism::force::Wrench::force_at(&(-(#rx.guide.force + pos.#guide.dir * #rx.drive)), &pos.#name, &pos.#r).with_couple(-#rx.guide.moment));
            self.add(b, w);
        }
        self.reactions
            .push(prismatic(&rx, &body, link, name, "guide"));
        self.power.push(quote!(#rx.drive * vel.rates.#input));
        let doc = format!("Driving force on `{link}` along its guide (input `{input}`; force units, positive along the guide's direction).");
        self.reactions
            .push(drive(&rx, input, "drive", Held::Push, doc));
    }

    fn actuator(&mut self, stmt: &Stmt, a: &Ident, b: &Ident, input: &Ident) {
        let (rx, links, name) = (rx(stmt), &stmt.links, &stmt.name);
        let load = self.load_about(&links[0], a);
        self.solve(
            stmt,
            quote!(::mechanism::force::actuator::reactions(&pos.#a, &pos.#b, &pos.#name, &#load)),
        );
        let body_a = self.pass_revolute(a, &rx, "a");
        if let Some(body) = self.plan.body_of_point(&b.to_string()) {
            let axis = format_ident!("rx_axis_{}", name);
            self.code.extend(quote!(let #axis = (pos.#name - pos.#b) / ::mechanism::geometry::length(&(pos.#name - pos.#b));));
            self.force_on(&body, quote!(#axis * (-#rx.axial)), b);
        }
        self.reactions
            .push(revolute(&rx, &body_a, &links[0], a, "a"));
        self.power.push(quote!(#rx.axial * vel.rates.#input));
        self.conditions.push(quote!(#rx.min_pivot_ratio));
        let doc = format!("Axial force of the actuator `{}` (input `{input}`; force units, positive when it pushes its ends apart).", links[1]);
        self.reactions
            .push(drive(&rx, input, "axial", Held::Push, doc));
    }

    fn rrr(&mut self, stmt: &Stmt, a: &Ident, b: &Ident) {
        let (rx, links, name) = (rx(stmt), &stmt.links, &stmt.name);
        let (l1, l2) = self.loads_about(stmt, name);
        self.solve(
            stmt,
            quote!(::mechanism::force::rrr::reactions(&pos.#a, &pos.#b, &pos.#name, &#l1, &#l2)),
        );
        let ba = self.pass_revolute(a, &rx, "a");
        let bb = self.pass_revolute(b, &rx, "b");
        self.reactions.push(revolute(&rx, &ba, &links[0], a, "a"));
        self.reactions.push(revolute(&rx, &bb, &links[1], b, "b"));
        self.reactions.push(inner(&rx, links, name, "c", false));
        self.conditions.push(quote!(#rx.min_pivot_ratio));
    }

    fn rrp(&mut self, stmt: &Stmt, a: &Ident, guide: &Ident) {
        let (rx, links, name) = (rx(stmt), &stmt.links, &stmt.name);
        let (l1, l2) = self.loads_about(stmt, name);
        self.solve(
            stmt,
            quote!(::mechanism::force::rrp::reactions(&pos.#a, &pos.#name, &pos.#guide.dir, &#l1, &#l2)),
        );
        let ba = self.pass_revolute(a, &rx, "a");
        let bg = self.plan.body_of_guide(&guide.to_string());
        self.prismatic_on(bg.clone(), quote!(#rx.guide), name);
        self.reactions.push(revolute(&rx, &ba, &links[0], a, "a"));
        self.reactions.push(inner(&rx, links, name, "c", false));
        self.reactions
            .push(prismatic(&rx, &bg, &links[1], name, "guide"));
        self.conditions.push(quote!(#rx.min_pivot_ratio));
    }

    fn rpr(&mut self, stmt: &Stmt, a: &Ident, b: &Ident) {
        let (rx, links, g) = (rx(stmt), &stmt.links, format_ident!("grp_{}", stmt.name));
        let (l1, l2) = self.loads_about(stmt, a);
        self.solve(
            stmt,
            quote!(::mechanism::force::rpr::reactions(&pos.#a, &pos.#b, &pos.#g.axis, &#l1, &#l2)),
        );
        let ba = self.pass_revolute(a, &rx, "a");
        let bb = self.pass_revolute(b, &rx, "b");
        self.reactions.push(revolute(&rx, &ba, &links[0], a, "a"));
        self.reactions.push(revolute(&rx, &bb, &links[1], b, "b"));
        self.reactions.push(inner(&rx, links, a, "slide", true));
        self.conditions.push(quote!(#rx.min_pivot_ratio));
    }

    fn prp(&mut self, stmt: &Stmt, g1: &Ident, g2: &Ident) {
        let (rx, links, name) = (rx(stmt), &stmt.links, &stmt.name);
        let (l1, l2) = self.loads_about(stmt, name);
        self.solve(
            stmt,
            quote!(::mechanism::force::prp::reactions(&pos.#name, &pos.#g1.dir, &pos.#g2.dir, &#l1, &#l2)),
        );
        let c1 = self.plan.body_of_guide(&g1.to_string());
        let c2 = self.plan.body_of_guide(&g2.to_string());
        self.prismatic_on(c1.clone(), quote!(#rx.guide1), name);
        self.prismatic_on(c2.clone(), quote!(#rx.guide2), name);
        self.reactions
            .push(prismatic(&rx, &c1, &links[0], name, "guide1"));
        self.reactions
            .push(prismatic(&rx, &c2, &links[1], name, "guide2"));
        self.reactions.push(inner(&rx, links, name, "c", false));
        self.conditions.push(quote!(#rx.min_pivot_ratio));
    }

    fn rpp(&mut self, stmt: &Stmt, a: &Ident, guide: &Ident) {
        let (rx, links, g) = (rx(stmt), &stmt.links, format_ident!("grp_{}", stmt.name));
        let (l1, l2) = self.loads_about(stmt, a);
        self.solve(
            stmt,
            quote!(::mechanism::force::rpp::reactions(&pos.#a, &pos.#g.slot, &pos.#guide.dir, &#l1, &#l2)),
        );
        let ba = self.pass_revolute(a, &rx, "a");
        let bg = self.plan.body_of_guide(&guide.to_string());
        self.prismatic_on(bg.clone(), quote!(#rx.guide), a);
        self.reactions.push(revolute(&rx, &ba, &links[0], a, "a"));
        self.reactions.push(inner(&rx, links, a, "slot", true));
        self.reactions
            .push(prismatic(&rx, &bg, &links[1], a, "guide"));
        self.conditions.push(quote!(#rx.min_pivot_ratio));
    }
}

#[cfg(test)]
mod tests {
    use crate::emit::test_support::{flat, four_bar, planned};

    /// The forces struct's fields of `src` as `name:value` pairs, and the
    /// `forces` method's code, without whitespace.
    fn reactions(src: &str) -> (Vec<String>, String) {
        let (model, plan) = planned(src);
        let moving = crate::emit::moving_points(&model, &plan);
        let code = super::super::emit(&model, &plan, &moving);
        let methods = flat(&code.methods);
        let value = methods.split("Ok(").last().unwrap();
        let fields = value
            .split(['{', '}', ','])
            .filter(|f| f.contains(':'))
            .map(str::to_string)
            .collect();
        (fields, methods)
    }

    // Proves a four-bar's reactions, groups taken in the reverse of the solve
    // order: the RRR's three joints named after the bodies on each side (its
    // pin at A on the crank, at O4 on the ground, the inner one at B), then
    // the crank's pivot and driving torque; and the RRR's reaction at A is
    // passed, negated, onto the crank's load.
    #[test]
    fn four_bar_reactions_by_body_and_passed_on() {
        let (fields, code) = reactions(&four_bar("mass link3 { m = 2.0, at = P };"));
        assert_eq!(
            fields,
            [
                "r_link2_link3:rx_B.a",
                "r_ground_link4:rx_B.b",
                "r_link3_link4:rx_B.c",
                "r_ground_link2:rx_A.pivot",
                "drive_theta2:rx_A.torque",
            ]
        );
        assert!(
            code.contains(
                "letload_link2=::mechanism::force::Wrench::force_at(&(-rx_B.a),&pos.A,&pos.O2);"
            ),
            "{code}"
        );
    }

    // Proves an RRP on a fixed guide reports its guide's reaction as a
    // prismatic one of the ground on the block, passes nothing to the ground,
    // and takes the block's load about its point B.
    #[test]
    fn rrp_on_a_fixed_guide_reacts_on_the_ground() {
        let src = "pub SliderCrank {
            params { crank = 0.1, rod = 0.4, offset = 0.02 }
            let O = ground(0.0, 0.0);
            let line = guide((0.0, offset), 0 deg);
            let A = crank(O, crank, theta) as link2;
            let B = rrp(A, rod, line, plus) as (link3, slider) slide x;
            mass slider { m = 1.5, at = B };
        }";
        let (fields, code) = reactions(src);
        assert_eq!(
            fields,
            [
                "r_link2_link3:rx_B.a",
                "r_link3_slider:rx_B.c",
                "r_ground_slider:rx_B.guide",
                "r_ground_link2:rx_A.pivot",
                "drive_theta:rx_A.torque",
            ]
        );
        assert!(
            code.contains("rrp::reactions(&pos.A,&pos.B,&pos.line.dir,&::mechanism::force::Wrench::zero(),&load_slider)"),
            "{code}"
        );
        assert!(!code.contains("load_ground"), "{code}");
    }
}
