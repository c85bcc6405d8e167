//! `rpp(A, GUIDE, slot angle) as (YOKE, BLOCK)`: the RPP dyad, a yoke pinned
//! at `A` whose slot (at the given angle to the guide) carries a block that
//! slides on the guide; the defined point is the yoke's reference point.

use super::closure::{f, guide_axis, Residuals};
use super::forces::{inner, prismatic, revolute, rx, ForceCx};
use super::group::{links_text, GroupKind, LinkShape, Role, Solve, Turn};
use super::lane::{Lane, LaneLink, PointLocals, Step, Vector};
use super::lane_shapes::{along_line, line_axis};
use super::rates::{states, vec_ty, Pieces, RateCx};
use super::reads::Reads;
use super::run::{Compile, ForceRunCx, GuideSlot, Me, PointSlot, RunCx, RunPose};
use super::tokens::{along, grp, local, unit_field, unit_vector};
use crate::diag::Diagnostics;
use crate::keys::LinkName;
use crate::model::Stmt;
use crate::value::Value;
use mechanism_core::{dyad, geometry, sweep, Fault};
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

/// How `rpp` is written: its word, usage, arity and links.
pub(crate) const SPEC: super::word::Spec = super::word::Spec {
    word: super::word::KindWord::Rpp,
    text: "rpp",
    usage: "rpp(A, GUIDE, slot_angle[, offset]) as (BLOCK, LINK) slide (S1, S2)",
    arity: super::word::Arity::Range(3, 4),
    links: "the block pinned at A, and the slotted link sliding on the guide",
    inputs: &[],
    mode_at: None,
    mode_words: &[],
    group: Some("RPP"),
};

/// An `rpp` statement.
pub(super) struct Rpp<'a> {
    pub stmt: &'a Stmt,
    pub a: &'a Ident,
    pub guide: &'a Ident,
    pub slot: &'a Value,
    pub offset: &'a Value,
}

impl<'a> GroupKind<'a> for Rpp<'a> {
    fn references(&self) -> Vec<(&'a Ident, Role)> {
        vec![(self.a, Role::Point), (self.guide, Role::Guide)]
    }

    fn link_shapes(&self) -> Vec<LinkShape> {
        vec![
            LinkShape::new(&[self.a], Turn::None, Some(self.guide)),
            LinkShape::new(&[&self.stmt.name], Turn::None, Some(self.guide)),
        ]
    }

    /// The reference point belongs to the yoke, the second link.
    fn point_owner(&self) -> Option<Option<LinkName>> {
        Some(Some(LinkName::of(&self.stmt.links[1])))
    }

    fn position_values(&self) -> Vec<Value> {
        vec![self.slot.clone(), self.offset.clone()]
    }

    fn position_type(&self) -> TokenStream {
        quote!(::mechanism::dyad::rpp::RppPosition<T>)
    }

    fn position(&self, _cos_sin: bool) -> Solve {
        let (u, o) = (unit_vector(self.slot), self.offset.emit());
        let (a, guide) = (local(self.a), local(self.guide));
        Solve::Group {
            call: quote!(::mechanism::dyad::rpp::position(&#a, &#guide, #o, &#u)),
            joint: Some("q"),
        }
    }

    fn link_direction(&self, index: usize) -> (TokenStream, TokenStream) {
        match index {
            1 => along(self.guide),
            _ => unit_field(self.stmt, "slot"),
        }
    }

    fn slide_field(&self, slot: usize) -> TokenStream {
        match slot {
            0 => quote!(s1),
            _ => quote!(s2),
        }
    }

    fn rates(&self, cx: &mut dyn RateCx) {
        let ((g, gv), a, guide) = (states(self.stmt), self.a, self.guide);
        let (ma, gvel) = (cx.point_arg(a), cx.guide_vel(guide));
        let r = cx.reads();
        let (pg, pa, pl) = (r.pos(&g), r.pos(a), r.pos(guide));
        let call = if cx.accel() {
            let (gacc, gv) = (cx.guide_acc(guide), r.vel(&gv));
            quote!(::mechanism::dyad::rpp::acceleration(&#pg, &#pa, &#pl, &#gv, #ma, #gvel, #gacc))
        } else {
            quote!(::mechanism::dyad::rpp::velocity(&#pg, &#pa, &#pl, #ma, #gvel))
        };
        let gr = cx.group(self.stmt, call, quote!(dyad::rpp), "Rpp");
        // The reference point's motion is `vq`/`aq`.
        let q = if cx.accel() { quote!(aq) } else { quote!(vq) };
        let Pieces { s1, s2, .. } = Pieces::of(cx.accel());
        cx.named(cx.motion(self.stmt), quote!(#gr.#q), vec_ty());
        cx.slide(0, quote!(#gr.#s1));
        cx.slide(1, quote!(#gr.#s2));
    }

    fn rate_system(&self) -> bool {
        true
    }

    /// `Q` on the guide's offset line, `A` in the slot through `Q`.
    fn residuals(&self, r: &mut Residuals<'_>, _link_axis: &dyn Fn(&Ident) -> TokenStream) {
        r.on_offset_line("Q on the offset line", self.guide, self.offset);
        let (n, a, guide, s) = (r.pos(r.n), r.pos(self.a), r.pos(self.guide), f(self.slot));
        r.push(
            "A in the slot through Q",
            quote!(cross(turn(unit_of(vc(&#guide.dir)), #s), sub(pt(&#a), pt(&#n)))),
        );
    }

    fn closure_axis(&self, index: usize, reads: &Reads) -> TokenStream {
        match index {
            1 => guide_axis(self.guide, reads),
            _ => {
                let (guide, s) = (reads.pos(self.guide), f(self.slot));
                quote!(turn(unit_of(vc(&#guide.dir)), #s))
            }
        }
    }

    fn explain_fault(&self, fault: &Fault, at: &str) -> Option<String> {
        let guide = self.guide;
        matches!(fault, Fault::Singular { .. }).then(|| {
            format!("at {at}, the slot is parallel to guide `{guide}`: the joint is at infinity")
        })
    }

    fn singular_meaning(&self) -> Option<String> {
        let guide = self.guide;
        Some(format!("the slot is parallel to guide `{guide}`"))
    }

    fn primitive(&self) -> &'static str {
        "Rpp"
    }

    fn det_code(&self, reads: &Reads) -> TokenStream {
        let (g, guide) = (reads.pos(&grp(self.stmt)), reads.pos(self.guide));
        quote!(::mechanism::__private::det_rpp(&#g, &#guide))
    }

    fn describe(&self) -> String {
        let (n, links, a, guide) = (&self.stmt.name, links_text(self.stmt), self.a, self.guide);
        format!(
            "RPP group `{links}`: block at `{a}`, link on guide `{guide}`, reference point `{n}`"
        )
    }

    fn forces(&self, cx: &mut dyn ForceCx) {
        let (stmt, a, guide) = (self.stmt, self.a, self.guide);
        let (rx, links, g) = (rx(stmt), &stmt.links, grp(stmt));
        let (l1, l2) = cx.loads_about(stmt, a);
        let r = cx.reads();
        let (pa, pg, pl) = (r.pos(a), r.pos(&g), r.pos(guide));
        cx.solve(
            stmt,
            quote!(::mechanism::force::rpp::reactions(&#pa, &#pg.slot, &#pl.dir, &#l1, &#l2)),
        );
        let ba = cx.pass_revolute(a, &rx, "a");
        let bg = cx.body_of_guide(guide);
        cx.prismatic_on(bg.clone(), quote!(#rx.guide), a);
        cx.reaction(revolute(&rx, &ba, &links[0], a, "a"));
        cx.reaction(inner(&rx, links, a, "slot", true));
        cx.reaction(prismatic(&rx, &bg, &links[1], a, "guide"));
        cx.condition(quote!(#rx.min_pivot_ratio));
    }

    fn bodies_and_pairs(&self) -> (i64, i64, i64) {
        (2, 3, 0)
    }

    fn joint_at_infinity(&self) -> bool {
        true
    }

    /// The slot crosses the guide. The slotted link translates along the
    /// guide without turning relative to it (a carried guide turns the slot
    /// with it), so the slot keeps its angle to the guide at every pose: a
    /// slot parallel to the guide is parallel at every input, and the joint
    /// is at infinity everywhere. Known at compile time for a slot angle that
    /// folds to a number; "parallel" is the test the run-time solve applies
    /// (`mechanism_core::dyad::rpp`: `|sin(slot)| <= 16 eps`, in f64 here).
    fn check(&self, errors: &mut Diagnostics) {
        let (guide, slot) = (self.guide, self.slot);
        let Some(angle) = slot.fold() else {
            return;
        };
        if angle.sin().abs() <= 16.0 * f64::EPSILON {
            // Rounded to 1e-9 deg, so that `180 deg` (rounded once to
            // radians and back) shows as 180.
            let deg = (angle.to_degrees() * 1e9).round() / 1e9;
            errors.push(
                slot.span,
                format!(
                    "the slot of `{}` is at {deg} deg to guide `{guide}`, parallel to it; the slotted link slides along `{guide}` without turning, so the slot stays parallel at every pose and the block's pin is at infinity for every input: give the slot an angle across the guide (e.g. `90 deg`, a slot perpendicular to it)",
                    self.stmt.name
                ),
            );
        }
    }

    /// Its lane code in the batch kernel (`None`: an argument the kernel
    /// does not know; the batch then takes the scalar path).
    fn lane(&self, lane: &mut Lane, s: &mut Step<'_>) -> Option<()> {
        lane_steps(lane, s, self.a, self.guide, self.slot, self.offset)
    }

    fn link_lengths(&self) -> Vec<&'a Value> {
        Vec::new()
    }

    moving_joint_facets!();
}

/// An RPP group: a block sliding on `guide` (at `offset`, length unit)
/// carrying a slot at `slot` (radians from the guide) through which the
/// point `a` slides (`lane::rpp`), its two slides (`s0_NAME` along the
/// guide, `s1_NAME` along the slot) and their rates (`lane::rpp_rates` /
/// `lane::rpp_accels`). Both links turn with the guide's body: link 1 (the
/// block) along the slot `w`, link 2 (the yoke) along the guide, as in the
/// scalar path. `None` when `a` or the guide is not known yet.
fn lane_steps(
    lane: &Lane,
    s: &mut Step,
    a: &Ident,
    guide: &Ident,
    slot: &Value,
    offset: &Value,
) -> Option<()> {
    let pa = lane.point(a)?;
    let gd = lane.guide(guide)?;
    let PointLocals {
        px,
        py,
        vx,
        vy,
        ax,
        ay,
    } = s.own.clone();
    let g = s.g.clone();
    let (line, gv, ga) = (&gd.line, &gd.gv, &gd.ga);
    let Vector { x: lx, y: ly } = s.unit(slot);
    let o = offset.emit();
    let (slide1, slide2) = (s.slide_locals(0), s.slide_locals(1));
    let (s1, sd1, sdd1) = (&slide1.s, &slide1.sd, &slide1.sdd);
    let (s2, sd2, sdd2) = (&slide2.s, &slide2.sd, &slide2.sdd);
    let (apx, apy) = (&pa.px, &pa.py);
    s.emit(quote! {
        let #g = ::mechanism::__private::lane::rpp(#apx, #apy, &#line, #o, #lx, #ly);
        ok &= #g.ok;
        let #px = #g.x; let #py = #g.y;
        let #s1 = #g.s1; let #s2 = #g.s2;
    });
    s.check([quote!(#s1), quote!(#s2)]);
    if lane.vel {
        let (avx, avy) = (&pa.vx, &pa.vy);
        s.emit(quote! {
            let (#sd1, #sd2, #vx, #vy) = ::mechanism::__private::lane::rpp_rates(&#g, &#line, #apx, #apy, #avx, #avy, #gv);
        });
        s.check([quote!(#sd1), quote!(#sd2)]);
    }
    if lane.acc {
        let (aax, aay) = (&pa.ax, &pa.ay);
        s.emit(quote! {
            let (#sdd1, #sdd2, #ax, #ay) = ::mechanism::__private::lane::rpp_accels(&#g, &#line, #apx, #apy, #aax, #aay, #sd1, #sd2, #gv, #ga);
        });
        s.check([quote!(#sdd1), quote!(#sdd2)]);
    }
    s.defines_slide(0, &slide1);
    s.defines_slide(1, &slide2);
    let turning = |v: Vector| LaneLink::along(v, None, gd.omega.clone(), gd.alpha.clone());
    s.defines_link(0, turning(along_line(&g, "w")))?;
    s.defines_link(1, turning(line_axis(line)))
}

impl super::run::RunKind for Rpp<'_> {
    fn compile(&self, cx: &Compile<'_>) -> Box<dyn super::run::Step> {
        Box::new(RppRun {
            me: cx.me(self.stmt),
            a: cx.point(self.a),
            guide: cx.guide(self.guide),
            slot: geometry::unit(cx.num(self.slot)),
            offset: cx.num(self.offset),
        })
    }
}

/// An RPP group, compiled: its known joint, its guide, the slot's unit
/// direction in the yoke's frame and the block's offset (L).
struct RppRun {
    me: Me,
    a: PointSlot,
    guide: GuideSlot,
    slot: mechanism_core::Vector2<f64>,
    offset: f64,
}

impl super::run::Step for RppRun {
    fn group(&self) -> &'static str {
        self.me.group
    }

    fn walks(&self) -> super::run::Walks {
        super::run::Walks::ALL
    }

    fn position(&self, pose: &mut RunPose) -> Result<Option<f64>, mechanism_core::Error<f64>> {
        let (pa, gl) = (pose.point(self.a), pose.line(self.guide));
        let p = dyad::rpp::position(&pa, &gl, self.offset, &self.slot)?;
        pose.found(&self.me, p.q, &[p.slot, gl.dir]);
        pose.keep(&self.me, p);
        Ok(Some(sweep::det_rpp(&p, &gl)))
    }

    fn rates(&self, cx: &mut RunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let me = &self.me;
        let missing = || super::run::missing(mechanism_core::Primitive::Rpp);
        let g = cx
            .pose
            .kept::<dyad::rpp::RppPosition<f64>>(me)
            .ok_or_else(missing)?;
        let (pa, line) = (cx.pose.point(self.a), cx.pose.line(self.guide));
        let (ma, gvel) = (cx.point_arg(self.a), cx.guide_vel(self.guide));
        if cx.accel() {
            let gv = cx
                .vel_group::<dyad::rpp::RppVelocity<f64>>(me)
                .ok_or_else(missing)?;
            let gacc = cx.guide_acc(self.guide);
            let r = dyad::rpp::acceleration(
                g,
                &pa,
                &line,
                gv,
                ma.as_ref(),
                gvel.as_ref(),
                gacc.as_ref(),
            )?;
            cx.set_motion(me, r.aq);
            cx.set_slide(me, 0, r.s1_ddot);
            cx.set_slide(me, 1, r.s2_ddot);
        } else {
            let r = dyad::rpp::velocity(g, &pa, &line, ma.as_ref(), gvel.as_ref())?;
            cx.set_motion(me, r.vq);
            cx.set_slide(me, 0, r.s1_dot);
            cx.set_slide(me, 1, r.s2_dot);
            cx.keep(me, r, Some(r.condition));
        }
        Ok(())
    }

    /// `force::rpp::reactions` on the links' loads about `A`.
    fn forces(&self, cx: &mut ForceRunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let (me, a, guide) = (&self.me, self.a, self.guide);
        let slot = cx
            .pose
            .kept::<dyad::rpp::RppPosition<f64>>(me)
            .ok_or_else(|| super::run::missing(mechanism_core::Primitive::Rpp))?
            .slot;
        let (l1, l2) = cx.loads_about(me, a);
        let dir = cx.pose.line(guide).dir;
        let rx = mechanism_core::force::rpp::reactions(&cx.at(a), &slot, &dir, &l1, &l2)?;
        let ba = cx.pass_revolute(a, rx.a);
        let bg = cx.body_of_guide(guide);
        cx.prismatic_on(bg, &rx.guide, a);
        cx.revolute(ba, me.links[0], rx.a);
        cx.inner(me, super::run::ForceValue::Prismatic(rx.slot));
        cx.prismatic(bg, me.links[1], rx.guide);
        cx.conditions.push(rx.min_pivot_ratio);
        Ok(())
    }

    fn link_dir(&self, index: usize, pose: &RunPose) -> mechanism_core::Vector2<f64> {
        let nan = mechanism_core::Vector2::new(f64::NAN, f64::NAN);
        match index {
            1 => pose.line(self.guide).dir,
            _ => pose
                .kept::<dyad::rpp::RppPosition<f64>>(&self.me)
                .map_or(nan, |p| p.slot),
        }
    }

    fn slide(&self, k: usize, pose: &RunPose) -> Option<f64> {
        pose.kept::<dyad::rpp::RppPosition<f64>>(&self.me)
            .map(|p| if k == 0 { p.s1 } else { p.s2 })
    }
}
