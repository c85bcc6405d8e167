//! `rpr(A, B, mode) as (LINK1, LINK2)`: the RPR dyad, a block pinned at `A`
//! sliding on a link turning about `B`; the defined name is the slide.

use super::closure::{f, mode_sign, Residuals};
use super::forces::{inner, revolute, rx, ForceCx};
use super::group::{links_text, mode_text, GroupKind, LinkShape, Role, Solve, Turn};
use super::lane::{Lane, LaneLink, Step};
use super::lane_shapes::along_line;
use super::rates::{states, Pieces, RateCx};
use super::reads::Reads;
use super::run::{Compile, ForceRunCx, Me, PointSlot, RunCx, RunPose};
use super::tokens::{grp, local, mode_arg, unit_field};
use crate::diag::show_num;
use crate::keys::LinkName;
use crate::kinds::pose::mode;
use crate::model::{Mode, Stmt};
use crate::value::Value;
use mechanism_core::{dyad, sweep, Fault};
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

/// How `rpr` is written: its word, usage, arity and links.
pub(crate) const SPEC: super::word::Spec = super::word::Spec {
    word: super::word::KindWord::Rpr,
    text: "rpr",
    usage: "let S = rpr(A, B, plus|minus[, offset]) as (BLOCK, LINK)",
    arity: super::word::Arity::Range(3, 4),
    links: "the block pinned at A, and the link pivoted at B",
    inputs: &[],
    mode_at: Some(2),
    mode_words: super::word::SIGN_MODES,
    group: Some("RPR"),
};

/// An `rpr` statement.
pub(super) struct Rpr<'a> {
    pub stmt: &'a Stmt,
    pub a: &'a Ident,
    pub b: &'a Ident,
    pub mode: Mode,
    pub offset: &'a Value,
}

impl<'a> GroupKind<'a> for Rpr<'a> {
    fn references(&self) -> Vec<(&'a Ident, Role)> {
        vec![(self.a, Role::Point), (self.b, Role::Point)]
    }

    fn link_shapes(&self) -> Vec<LinkShape> {
        vec![
            LinkShape::new(&[self.a], Turn::Own, None),
            LinkShape::new(&[self.b], Turn::Own, None),
        ]
    }

    fn point_owner(&self) -> Option<Option<LinkName>> {
        None
    }

    fn position_values(&self) -> Vec<Value> {
        vec![self.offset.clone()]
    }

    fn position_type(&self) -> TokenStream {
        quote!(::mechanism::dyad::rpr::RprPosition<T>)
    }

    fn position(&self, _cos_sin: bool) -> Solve {
        let (m, o) = (mode_arg(self.stmt, self.mode), self.offset.emit());
        let (a, b) = (local(self.a), local(self.b));
        Solve::Group {
            call: quote!(::mechanism::dyad::rpr::position(&#a, &#b, #o, #m)),
            joint: None,
        }
    }

    fn link_direction(&self, _index: usize) -> (TokenStream, TokenStream) {
        unit_field(self.stmt, "axis")
    }

    fn rates(&self, cx: &mut dyn RateCx) {
        let ((g, gv), a, b) = (states(self.stmt), self.a, self.b);
        let (ma, mb) = (cx.point_arg(a), cx.point_arg(b));
        let r = cx.reads();
        let (pg, pa, pb) = (r.pos(&g), r.pos(a), r.pos(b));
        let call = if cx.accel() {
            let gv = r.vel(&gv);
            quote!(::mechanism::dyad::rpr::acceleration(&#pg, &#pa, &#pb, &#gv, #ma, #mb))
        } else {
            quote!(::mechanism::dyad::rpr::velocity(&#pg, &#pa, &#pb, #ma, #mb))
        };
        let gr = cx.group(self.stmt, call, quote!(dyad::rpr), "Rpr");
        // Both links turn together: the group's one rate.
        let r = if cx.accel() {
            quote!(alpha)
        } else {
            quote!(omega)
        };
        let s = Pieces::of(cx.accel()).s;
        cx.named(cx.own(self.stmt, 0), quote!(#gr.#r), quote!(T));
        cx.named(cx.own(self.stmt, 1), quote!(#gr.#r), quote!(T));
        cx.slide(0, quote!(#gr.#s));
    }

    fn rate_system(&self) -> bool {
        true
    }

    /// Its slide line at its offset from `B`, the slide along it, a unit
    /// axis, and the branch (the sign of the slide).
    fn residuals(&self, r: &mut Residuals<'_>, _link_axis: &dyn Fn(&Ident) -> TokenStream) {
        let (g, a, b) = (r.pos(&grp(self.stmt)), r.pos(self.a), r.pos(self.b));
        let (m, o) = (mode_sign(self.mode), f(self.offset));
        r.push(
            "slide line at its offset from B",
            quote!(cross(vc(&#g.axis), sub(pt(&#a), pt(&#b))) - #o),
        );
        r.push(
            "slide = dot(A - B, u)",
            quote!(dot(vc(&#g.axis), sub(pt(&#a), pt(&#b))) - <T as ::mechanism::Real>::as_f64(#g.s)),
        );
        r.push(
            "unit axis (times |A - B|)",
            quote!((norm(vc(&#g.axis)) - 1.0) * norm(sub(pt(&#a), pt(&#b)))),
        );
        r.push(
            "assembly branch",
            quote!(wrong_side(#m * <T as ::mechanism::Real>::as_f64(#g.s))),
        );
    }

    fn closure_axis(&self, _index: usize, reads: &Reads) -> TokenStream {
        let g = reads.pos(&grp(self.stmt));
        quote!(unit_of(vc(&#g.axis)))
    }

    fn explain_fault(&self, fault: &Fault, at: &str) -> Option<String> {
        let (a, b) = (self.a, self.b);
        let Fault::CannotAssemble { miss, reach } = fault else {
            return None;
        };
        Some(format!(
            "at {at}, `{a}` is {} from `{b}`, {} inside the offset {} of the slide line",
            show_num(reach - miss),
            show_num(*miss),
            show_num(*reach)
        ))
    }

    fn singular_meaning(&self) -> Option<String> {
        let (a, b) = (self.a, self.b);
        Some(format!(
            "`{a}` is at the foot of the perpendicular from `{b}` on the slide line"
        ))
    }

    fn primitive(&self) -> &'static str {
        "Rpr"
    }

    fn det_code(&self, reads: &Reads) -> TokenStream {
        let (g, a, b) = (
            reads.pos(&grp(self.stmt)),
            reads.pos(self.a),
            reads.pos(self.b),
        );
        quote!(::mechanism::__private::det_rpr(&#g, &#a, &#b))
    }

    fn describe(&self) -> String {
        let (n, links, a, b) = (&self.stmt.name, links_text(self.stmt), self.a, self.b);
        format!(
            "RPR group `{links}`: block at `{a}` on link pivoted at `{b}`, slide `{n}`, {}",
            mode_text(self.stmt, self.mode)
        )
    }

    fn point_kind(&self) -> Option<&'static str> {
        None
    }

    fn point_moves(
        &self,
        _link_turns: &dyn Fn(&Ident) -> bool,
        _moves: &dyn Fn(&Ident) -> bool,
    ) -> bool {
        false
    }

    /// The first link is the block sliding along the second.
    fn link_kind(&self, index: usize) -> &'static str {
        if index == 0 {
            "Block"
        } else {
            "Bar"
        }
    }

    /// Its slide is its defined name.
    fn names_slide(&self) -> bool {
        true
    }

    fn forces(&self, cx: &mut dyn ForceCx) {
        let (stmt, a, b) = (self.stmt, self.a, self.b);
        let (rx, links, g) = (rx(stmt), &stmt.links, grp(stmt));
        let (l1, l2) = cx.loads_about(stmt, a);
        let r = cx.reads();
        let (pa, pb, pg) = (r.pos(a), r.pos(b), r.pos(&g));
        cx.solve(
            stmt,
            quote!(::mechanism::force::rpr::reactions(&#pa, &#pb, &#pg.axis, &#l1, &#l2)),
        );
        let ba = cx.pass_revolute(a, &rx, "a");
        let bb = cx.pass_revolute(b, &rx, "b");
        cx.reaction(revolute(&rx, &ba, &links[0], a, "a"));
        cx.reaction(revolute(&rx, &bb, &links[1], b, "b"));
        cx.reaction(inner(&rx, links, a, "slide", true));
        cx.condition(quote!(#rx.min_pivot_ratio));
    }

    fn bodies_and_pairs(&self) -> (i64, i64, i64) {
        (2, 3, 0)
    }

    fn distinct_pair(&self) -> Option<(&'a Ident, &'a Ident, &'static str)> {
        Some((
            self.a,
            self.b,
            "points (the block's pin and the link's pivot)",
        ))
    }

    /// Its lane code in the batch kernel (`None`: an argument the kernel
    /// does not know; the batch then takes the scalar path).
    fn lane(&self, lane: &mut Lane, s: &mut Step<'_>) -> Option<()> {
        lane_steps(lane, s, self.a, self.b, &self.mode, self.offset)
    }

    fn slide_field(&self, _slot: usize) -> TokenStream {
        quote!(s)
    }

    fn link_lengths(&self) -> Vec<&'a Value> {
        Vec::new()
    }

    fn input_is_angle(&self) -> bool {
        false
    }
}

/// An RPR group: a slide through `a` and `b` at `offset` (length unit)
/// from the line `a`-`b`, on the side `mode` (`lane::rpr`); defines no
/// point, only the slide (`s0_NAME`, named after the statement when the
/// definition gives none) and the rates of its two links, which share the
/// group's direction `u` (`lane::rpr_rates` / `lane::rpr_accels`). `None`
/// when `a` or `b` is not known yet.
fn lane_steps(
    lane: &Lane,
    s: &mut Step,
    a: &Ident,
    b: &Ident,
    mode: &Mode,
    offset: &Value,
) -> Option<()> {
    let (pa, pb) = (lane.point(a)?, lane.point(b)?);
    s.defines_no_point();
    let g = s.g.clone();
    let (o, sign) = (offset.emit(), s.sign(mode));
    let r = s.rates(0)?;
    let (w, al) = (&r.omega, &r.alpha);
    let slide = s.slide_locals(0);
    let (sl, sd, sdd) = (&slide.s, &slide.sd, &slide.sdd);
    let (apx, apy, bpx, bpy) = (&pa.px, &pa.py, &pb.px, &pb.py);
    s.emit(quote! {
        let #g = ::mechanism::__private::lane::rpr(#apx, #apy, #bpx, #bpy, #o, #sign);
        ok &= #g.ok;
        let #sl = #g.s;
    });
    s.check([quote!(#sl), quote!(#g.ux), quote!(#g.uy)]);
    if lane.vel {
        let (avx, avy, bvx, bvy) = (&pa.vx, &pa.vy, &pb.vx, &pb.vy);
        s.emit(quote! {
            ok &= #g.ok_rate;
            let (#w, #sd) = ::mechanism::__private::lane::rpr_rates(&#g, #avx - #bvx, #avy - #bvy);
        });
        s.check([quote!(#w), quote!(#sd)]);
    }
    if lane.acc {
        let (aax, aay, bax, bay) = (&pa.ax, &pa.ay, &pb.ax, &pb.ay);
        s.emit(quote! {
            let (#al, #sdd) = ::mechanism::__private::lane::rpr_accels(&#g, #aax - #bax, #aay - #bay, #w, #sd);
        });
        s.check([quote!(#al), quote!(#sdd)]);
    }
    s.defines_slide(0, &slide);
    for k in 0..2 {
        s.defines_link(
            k,
            LaneLink::along(along_line(&g, "u"), None, quote!(#w), quote!(#al)),
        )?;
    }
    Some(())
}

impl super::run::RunKind for Rpr<'_> {
    fn compile(&self, cx: &Compile<'_>) -> Box<dyn super::run::Step> {
        Box::new(RprRun {
            me: cx.me(self.stmt),
            a: cx.point(self.a),
            b: cx.point(self.b),
            mode: mode(self.mode),
            offset: cx.num(self.offset),
        })
    }
}

/// An RPR group, compiled: its known joints, mode and the slide's offset
/// from `B` (L).
struct RprRun {
    me: Me,
    a: PointSlot,
    b: PointSlot,
    mode: mechanism_core::Mode,
    offset: f64,
}

impl super::run::Step for RprRun {
    fn group(&self) -> &'static str {
        self.me.group
    }

    fn walks(&self) -> super::run::Walks {
        super::run::Walks::ALL
    }

    fn position(&self, pose: &mut RunPose) -> Result<Option<f64>, mechanism_core::Error<f64>> {
        let (pa, pb) = (pose.point(self.a), pose.point(self.b));
        let p = dyad::rpr::position(&pa, &pb, self.offset, self.mode)?;
        pose.found_axes(&self.me, &[p.axis, p.axis]);
        pose.keep(&self.me, p);
        Ok(Some(sweep::det_rpr(&p, &pa, &pb)))
    }

    fn rates(&self, cx: &mut RunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let me = &self.me;
        let missing = || super::run::missing(mechanism_core::Primitive::Rpr);
        let g = cx
            .pose
            .kept::<dyad::rpr::RprPosition<f64>>(me)
            .ok_or_else(missing)?;
        let (pa, pb) = (cx.pose.point(self.a), cx.pose.point(self.b));
        let (ma, mb) = (cx.point_arg(self.a), cx.point_arg(self.b));
        if cx.accel() {
            let gv = cx
                .vel_group::<dyad::rpr::RprVelocity<f64>>(me)
                .ok_or_else(missing)?;
            let r = dyad::rpr::acceleration(g, &pa, &pb, gv, ma.as_ref(), mb.as_ref())?;
            cx.set_own(me, 0, r.alpha);
            cx.set_own(me, 1, r.alpha);
            cx.set_slide(me, 0, r.s_ddot);
        } else {
            let r = dyad::rpr::velocity(g, &pa, &pb, ma.as_ref(), mb.as_ref())?;
            cx.set_own(me, 0, r.omega);
            cx.set_own(me, 1, r.omega);
            cx.set_slide(me, 0, r.s_dot);
            cx.keep(me, r, Some(r.condition));
        }
        Ok(())
    }

    /// `force::rpr::reactions` on the links' loads about `A`.
    fn forces(&self, cx: &mut ForceRunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let (me, a, b) = (&self.me, self.a, self.b);
        let axis = cx
            .pose
            .kept::<dyad::rpr::RprPosition<f64>>(me)
            .ok_or_else(|| super::run::missing(mechanism_core::Primitive::Rpr))?
            .axis;
        let (l1, l2) = cx.loads_about(me, a);
        let rx = mechanism_core::force::rpr::reactions(&cx.at(a), &cx.at(b), &axis, &l1, &l2)?;
        let ba = cx.pass_revolute(a, rx.a);
        let bb = cx.pass_revolute(b, rx.b);
        cx.revolute(ba, me.links[0], rx.a);
        cx.revolute(bb, me.links[1], rx.b);
        cx.inner(me, super::run::ForceValue::Prismatic(rx.slide));
        cx.conditions.push(rx.min_pivot_ratio);
        Ok(())
    }

    fn link_dir(&self, _index: usize, pose: &RunPose) -> mechanism_core::Vector2<f64> {
        let nan = mechanism_core::Vector2::new(f64::NAN, f64::NAN);
        pose.kept::<dyad::rpr::RprPosition<f64>>(&self.me)
            .map_or(nan, |p| p.axis)
    }

    fn slide(&self, _k: usize, pose: &RunPose) -> Option<f64> {
        pose.kept::<dyad::rpr::RprPosition<f64>>(&self.me)
            .map(|p| p.s)
    }
}
