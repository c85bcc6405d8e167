//! `actuator(A, l, B, INPUT, mode) as (ARM, CYLINDER)`: a linear actuator of
//! input length (length units) from `B` to the joint, an arm of length `l`
//! from `A` to it. The cylinder is a massless two-force member.
//!
//! `as (ARM, BARREL, ROD)`: a cylinder with mass, two bodies turning
//! together: the barrel pivoted at `B` (its points measured from `B`), the
//! rod pinned at the joint (its points measured from the joint), sliding in
//! each other along `B -> joint`, the axis of both.

use super::closure::{axis_between, f, Residuals};
use super::forces::{drive, prismatic, revolute, rx, ForceCx, Held};
use super::group::{links_text, mode_text, GroupKind, LinkShape, Role, Solve, Turn};
use super::lane::{Lane, Step};
use super::lane_shapes::{dyad, SecondSide};
use super::rates::{states, two_links, RateCx};
use super::reads::Reads;
use super::run::{Compile, ForceRunCx, InputSlot, Me, PointSlot, RunCx, RunPose};
use super::tokens::{arm, grp, local, mode_arg};
use crate::diag::show_num;
use crate::keys::LinkName;
use crate::kinds::pose::mode;
use crate::model::{Mode, Stmt};
use crate::names::Family;
use crate::value::Value;
use mechanism_core::{driver, sweep, Fault};
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

/// How `actuator` is written: its word, usage, arity and links.
pub(crate) const SPEC: super::word::Spec = super::word::Spec {
    word: super::word::KindWord::Actuator,
    text: "actuator",
    usage: "actuator(A, radius, B, INPUT, left|right) as (LINK, CYLINDER)",
    arity: super::word::Arity::Range(5, 5),
    links: "the link from A, and the cylinder from B",
    inputs: &[3],
    mode_at: Some(4),
    mode_words: super::word::SIDE_MODES,
    group: Some("actuator"),
};

/// An `actuator` statement.
pub(super) struct Actuator<'a> {
    pub stmt: &'a Stmt,
    pub a: &'a Ident,
    pub l: &'a Value,
    pub b: &'a Ident,
    pub input: &'a Ident,
    pub mode: Mode,
}

impl<'a> GroupKind<'a> for Actuator<'a> {
    fn references(&self) -> Vec<(&'a Ident, Role)> {
        vec![(self.a, Role::Point), (self.b, Role::Point)]
    }

    /// The arm `A`-joint; the cylinder `B`-joint, or with three names the
    /// barrel at `B` and the rod at the joint, turning with the barrel.
    fn link_shapes(&self) -> Vec<LinkShape> {
        let n = &self.stmt.name;
        let arm = LinkShape::new(&[self.a, n], Turn::Own, None);
        match self.barrel_and_rod() {
            None => vec![arm, LinkShape::new(&[self.b, n], Turn::Own, None)],
            Some((barrel, _)) => vec![
                arm,
                LinkShape::new(&[self.b], Turn::Own, None),
                LinkShape::new(&[n], Turn::With(LinkName::of(barrel)), None),
            ],
        }
    }

    fn point_owner(&self) -> Option<Option<LinkName>> {
        Some(Some(LinkName::of(&self.stmt.links[0])))
    }

    fn position_values(&self) -> Vec<Value> {
        vec![self.l.clone()]
    }

    fn position_type(&self) -> TokenStream {
        quote!(::mechanism::driver::actuator::ActuatorPosition<T>)
    }

    fn position(&self, _cos_sin: bool) -> Solve {
        let (l, m, input) = (self.l.emit(), mode_arg(self.stmt, self.mode), self.input);
        let (a, b) = (local(self.a), local(self.b));
        Solve::Group {
            call: quote!(::mechanism::driver::actuator::position(&#a, #l, &#b, input.#input, #m)),
            joint: Some("c"),
        }
    }

    fn link_direction(&self, index: usize) -> (TokenStream, TokenStream) {
        let input = self.input;
        match index {
            0 => arm(self.stmt, "r1", self.l.emit()),
            _ => arm(self.stmt, "r2", quote!(input.#input)),
        }
    }

    fn rates(&self, cx: &mut dyn RateCx) {
        let ((g, gv), input) = (states(self.stmt), self.input);
        let (ma, mb) = (cx.point_arg(self.a), cx.point_arg(self.b));
        let g = cx.reads().pos(&g);
        let call = if cx.accel() {
            let gv = cx.reads().vel(&gv);
            quote!(::mechanism::driver::actuator::acceleration(&#g, &#gv, #ma, #mb, rates.#input, accels.#input))
        } else {
            quote!(::mechanism::driver::actuator::velocity(&#g, #ma, #mb, rates.#input))
        };
        let gr = cx.group(self.stmt, call, quote!(driver::actuator), "Actuator");
        two_links(cx, self.stmt, &gr);
    }

    fn rate_system(&self) -> bool {
        true
    }

    /// `C` at `l` from `A`, at the input length from `B`, on its branch.
    fn residuals(&self, r: &mut Residuals<'_>, _link_axis: &dyn Fn(&Ident) -> TokenStream) {
        let (inputs, input) = (r.reads.pos_input(), self.input);
        r.at_length("|C - A| = l", self.a, f(self.l));
        r.at_length(
            "|C - B| = input length",
            self.b,
            quote!(<T as ::mechanism::Real>::as_f64(#inputs.#input)),
        );
        r.dyad_branch(self.a, self.b, self.mode);
    }

    fn closure_axis(&self, index: usize, reads: &Reads) -> TokenStream {
        let from = if index == 0 { self.a } else { self.b };
        axis_between(from, &self.stmt.name, reads)
    }

    fn link_lengths(&self) -> Vec<&'a Value> {
        vec![self.l]
    }

    fn explain_fault(&self, fault: &Fault, at: &str) -> Option<String> {
        let (a, b) = (self.a, self.b);
        let Fault::CannotAssemble { miss, reach } = fault else {
            return None;
        };
        Some(format!(
            "at {at}, `{a}` and `{b}` are {} outside the distances the link and the cylinder can span (bound {})",
            show_num(*miss),
            show_num(*reach)
        ))
    }

    fn singular_meaning(&self) -> Option<String> {
        let l = &self.stmt.links;
        Some(format!(
            "the cylinder `{}` is aligned with link `{}` (dead centre)",
            l[1], l[0]
        ))
    }

    fn primitive(&self) -> &'static str {
        "Actuator"
    }

    fn det_code(&self, reads: &Reads) -> TokenStream {
        let g = reads.pos(&grp(self.stmt));
        quote!(::mechanism::__private::det_rrr(&#g))
    }

    fn describe(&self) -> String {
        let (n, links, a, b, input) = (
            &self.stmt.name,
            links_text(self.stmt),
            self.a,
            self.b,
            self.input,
        );
        format!(
            "driver: linear actuator `{links}` from `{b}`, link pivoted at `{a}`, input `{input}`, joint `{n}`, {}{}",
            mode_text(self.stmt, self.mode),
            match self.barrel_and_rod() {
                Some((barrel, rod)) => format!(", cylinder with mass: barrel `{barrel}` pivoted at `{b}`, rod `{rod}` pinned at `{n}`"),
                None => String::new(),
            }
        )
    }

    fn link_kind(&self, index: usize) -> &'static str {
        if index >= 1 {
            "Cylinder"
        } else {
            "Bar"
        }
    }

    fn forces(&self, cx: &mut dyn ForceCx) {
        if self.barrel_and_rod().is_some() {
            return self.forces_with_cylinder(cx);
        }
        let (stmt, a, b, input) = (self.stmt, self.a, self.b, self.input);
        let (rx, links, name) = (rx(stmt), &stmt.links, &stmt.name);
        let load = cx.load_about(&links[0], a);
        let r = cx.reads();
        let (pa, pb, pn) = (r.pos(a), r.pos(b), r.pos(name));
        cx.solve(
            stmt,
            quote!(::mechanism::force::actuator::reactions(&#pa, &#pb, &#pn, &#load)),
        );
        let body_a = cx.pass_revolute(a, &rx, "a");
        if let Some(body) = cx.body_of_point(b) {
            let axis = Family::RxAxis.of(name);
            cx.code(quote!(let #axis = (#pn - #pb) / ::mechanism::geometry::length(&(#pn - #pb));));
            cx.force_on(&body, quote!(#axis * (-#rx.axial)), b);
        }
        cx.reaction(revolute(&rx, &body_a, &links[0], a, "a"));
        let rates = cx.reads().vel_rates();
        cx.power(quote!(#rx.axial * #rates.#input));
        cx.condition(quote!(#rx.min_pivot_ratio));
        let doc = format!("Axial force of the actuator `{}` (input `{input}`; force units, positive when it pushes its ends apart).", links[1]);
        cx.reaction(drive(&rx, input, "axial", Held::Push, doc));
    }

    /// Cylinder = barrel + rod: three bodies, four lower pairs.
    fn bodies_and_pairs(&self) -> (i64, i64, i64) {
        (3, 4, 0)
    }

    fn distinct_pair(&self) -> Option<(&'a Ident, &'a Ident, &'static str)> {
        Some((
            self.a,
            self.b,
            "points (the link's pivot and the cylinder's base)",
        ))
    }

    /// Its lane code in the batch kernel (`None`: an argument the kernel
    /// does not know; the batch then takes the scalar path).
    fn lane(&self, lane: &mut Lane, s: &mut Step<'_>) -> Option<()> {
        lane_steps(lane, s, self.a, self.l, self.b, self.input, &self.mode)
    }

    fn slide_field(&self, _slot: usize) -> TokenStream {
        quote!(s)
    }

    fn point_kind(&self) -> Option<&'static str> {
        Some("Joint")
    }

    fn point_moves(
        &self,
        _link_turns: &dyn Fn(&Ident) -> bool,
        _moves: &dyn Fn(&Ident) -> bool,
    ) -> bool {
        true
    }

    fn input_is_angle(&self) -> bool {
        false
    }
}

impl<'a> Actuator<'a> {
    /// The barrel and the rod of a cylinder with mass (three names).
    pub(super) fn barrel_and_rod(&self) -> Option<(&'a Ident, &'a Ident)> {
        match self.stmt.links.as_slice() {
            [_, barrel, rod] => Some((barrel, rod)),
            _ => None,
        }
    }

    /// The force analysis of a cylinder with mass
    /// (`force::actuator::reactions_with_cylinder`): the loads of the arm
    /// about `A`, of the rod about the joint and of the barrel about `B`;
    /// the pivot at `A` and the barrel's force at `B` passed to their
    /// bodies; fields for the four joints (`A`, the joint, `B`, the
    /// barrel-rod pair) and the drive.
    fn forces_with_cylinder(&self, cx: &mut dyn ForceCx) {
        let (stmt, a, b, input) = (self.stmt, self.a, self.b, self.input);
        let (rx, links, name) = (rx(stmt), &stmt.links, &stmt.name);
        let arm = cx.load_about(&links[0], a);
        let barrel = cx.load_about(&links[1], b);
        let rod = cx.load_about(&links[2], name);
        let r = cx.reads();
        let (pa, pb, pn) = (r.pos(a), r.pos(b), r.pos(name));
        cx.solve(
            stmt,
            quote!(::mechanism::force::actuator::reactions_with_cylinder(&#pa, &#pb, &#pn, &#arm, &#rod, &#barrel)),
        );
        let body_a = cx.pass_revolute(a, &rx, "a");
        let body_b = cx.pass_revolute(b, &rx, "b");
        cx.reaction(revolute(&rx, &body_a, &links[0], a, "a"));
        let arm_body = Some(LinkName::of(&links[0]));
        cx.reaction(revolute(&rx, &arm_body, &links[2], name, "c"));
        cx.reaction(revolute(&rx, &body_b, &links[1], b, "b"));
        let barrel_body = Some(LinkName::of(&links[1]));
        cx.reaction(prismatic(&rx, &barrel_body, &links[2], name, "pair"));
        let rates = cx.reads().vel_rates();
        cx.power(quote!(#rx.axial * #rates.#input));
        cx.condition(quote!(#rx.min_pivot_ratio));
        let doc = format!("Axial force of the actuator `{}`/`{}` (input `{input}`; force units): the pressure force between barrel and rod, positive when it pushes them apart.", links[1], links[2]);
        cx.reaction(drive(&rx, input, "axial", Held::Push, doc));
    }
}

/// A linear actuator between `a` and `b`: an RRR dyad (`lane::rrr`) whose
/// second side is the input length `in_INPUT[k]` (length unit), its rates
/// from `lane::actuator_rates` / `lane::actuator_accels` with the input's
/// rates. See [`groups::rrr`].
fn lane_steps(
    lane: &Lane,
    s: &mut Step,
    a: &Ident,
    l: &Value,
    b: &Ident,
    input: &Ident,
    mode: &Mode,
) -> Option<()> {
    dyad(lane, s, a, l, b, SecondSide::Input(input), mode)
}

impl super::run::RunKind for Actuator<'_> {
    fn compile(&self, cx: &Compile<'_>) -> Box<dyn super::run::Step> {
        Box::new(ActuatorRun {
            me: cx.me(self.stmt),
            a: cx.point(self.a),
            l: cx.num(self.l),
            b: cx.point(self.b),
            input: cx.input(self.input),
            input_name: super::run::intern(&self.input.to_string()),
            mode: mode(self.mode),
            cylinder: self.barrel_and_rod().is_some(),
        })
    }
}

/// An actuator, compiled: its arm's pivot `A` and length (L), the
/// cylinder's pivot `B`, its input, mode, and whether its cylinder is a
/// barrel and a rod of its own.
struct ActuatorRun {
    me: Me,
    a: PointSlot,
    l: f64,
    b: PointSlot,
    input: InputSlot,
    input_name: &'static str,
    mode: mechanism_core::Mode,
    cylinder: bool,
}

impl super::run::Step for ActuatorRun {
    fn group(&self) -> &'static str {
        self.me.group
    }

    fn walks(&self) -> super::run::Walks {
        super::run::Walks::ALL
    }

    fn position(&self, pose: &mut RunPose) -> Result<Option<f64>, mechanism_core::Error<f64>> {
        let len = pose.input(self.input);
        let (pa, pb) = (pose.point(self.a), pose.point(self.b));
        let p = driver::actuator::position(&pa, self.l, &pb, len, self.mode)?;
        let (arm, cylinder) = (p.r1 / self.l, p.r2 / len);
        pose.found(&self.me, p.c, &[arm, cylinder, cylinder]);
        pose.keep(&self.me, p);
        Ok(Some(sweep::det_rrr(&p)))
    }

    fn rates(&self, cx: &mut RunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let me = &self.me;
        let missing = || super::run::missing(mechanism_core::Primitive::Actuator);
        let g = cx
            .pose
            .kept::<driver::actuator::ActuatorPosition<f64>>(me)
            .ok_or_else(missing)?;
        let (ma, mb) = (cx.point_arg(self.a), cx.point_arg(self.b));
        let rate = cx.rate(self.input);
        if cx.accel() {
            let gv = cx
                .vel_group::<driver::actuator::ActuatorVelocity<f64>>(me)
                .ok_or_else(missing)?;
            let acc = cx.accel_of(self.input);
            let r = driver::actuator::acceleration(g, gv, ma.as_ref(), mb.as_ref(), rate, acc)?;
            cx.set_motion(me, r.ac);
            cx.set_own(me, 0, r.alpha1);
            cx.set_own(me, 1, r.alpha2);
        } else {
            let r = driver::actuator::velocity(g, ma.as_ref(), mb.as_ref(), rate)?;
            cx.set_motion(me, r.vc);
            cx.set_own(me, 0, r.omega1);
            cx.set_own(me, 1, r.omega2);
            cx.keep(me, r, Some(r.condition));
        }
        Ok(())
    }

    /// `force::actuator::reactions` (or `reactions_with_cylinder` for a
    /// barrel and rod) on the links' loads; the pin reactions passed to
    /// their bodies, the axial force along the actuator onto `B`'s body.
    fn forces(&self, cx: &mut ForceRunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        use mechanism_core::force::actuator;
        let (me, a, b) = (&self.me, self.a, self.b);
        let links = me.links;
        if self.cylinder {
            let arm = cx.load_about(links[0], a);
            let barrel = cx.load_about(links[1], b);
            let rod = cx.load_about(links[2], me.point);
            let (pa, pb, pc) = (cx.at(a), cx.at(b), cx.at(me.point));
            let rx = actuator::reactions_with_cylinder(&pa, &pb, &pc, &arm, &rod, &barrel)?;
            let body_a = cx.pass_revolute(a, rx.a);
            let body_b = cx.pass_revolute(b, rx.b);
            cx.revolute(body_a, links[0], rx.a);
            cx.revolute(Some(links[0]), links[2], rx.c);
            cx.revolute(body_b, links[1], rx.b);
            cx.prismatic(Some(links[1]), links[2], rx.pair);
            cx.power.push(rx.axial * cx.rate(self.input));
            cx.conditions.push(rx.min_pivot_ratio);
            cx.drive(self.input_name, Held::Push, rx.axial);
            return Ok(());
        }
        let load = cx.load_about(links[0], a);
        let (pa, pb, pc) = (cx.at(a), cx.at(b), cx.at(me.point));
        let rx = actuator::reactions(&pa, &pb, &pc, &load)?;
        let body_a = cx.pass_revolute(a, rx.a);
        if let Some(body) = cx.body_of_point(b) {
            let axis = (pc - pb) / mechanism_core::geometry::length(&(pc - pb));
            cx.force_on(body, axis * (-rx.axial), b);
        }
        cx.revolute(body_a, links[0], rx.a);
        cx.power.push(rx.axial * cx.rate(self.input));
        cx.conditions.push(rx.min_pivot_ratio);
        cx.drive(self.input_name, Held::Push, rx.axial);
        Ok(())
    }

    fn link_dir(&self, index: usize, pose: &RunPose) -> mechanism_core::Vector2<f64> {
        let nan = mechanism_core::Vector2::new(f64::NAN, f64::NAN);
        pose.kept::<driver::actuator::ActuatorPosition<f64>>(&self.me)
            .map_or(nan, |p| if index == 0 { p.r1 } else { p.r2 })
    }
}
