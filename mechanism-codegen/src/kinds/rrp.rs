//! `rrp(A, l, GUIDE, mode) as (LINK, BLOCK)`: the RRP dyad, a link of length
//! `l` from `A` pinned at the defined point to a block on a guide.

use super::closure::{axis_between, f, guide_axis, mode_sign, Residuals};
use super::forces::{inner, prismatic, revolute, rx, ForceCx};
use super::group::{links_text, mode_text, GroupKind, LinkShape, Role, Solve, Turn};
use super::lane::{Lane, LaneLink, PointLocals, Step};
use super::lane_shapes::{along_line, line_axis};
use super::rates::{states, vec_ty, Pieces, RateCx};
use super::reads::Reads;
use super::run::{Compile, ForceRunCx, GuideSlot, Me, PointSlot, RunCx, RunPose};
use super::tokens::{along, arm, grp, local, mode_arg};
use crate::diag::show_num;
use crate::keys::LinkName;
use crate::kinds::pose::mode;
use crate::model::{Mode, Stmt};
use crate::value::Value;
use mechanism_core::{dyad, sweep, Fault};
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

/// How `rrp` is written: its word, usage, arity and links.
pub(crate) const SPEC: super::word::Spec = super::word::Spec {
    word: super::word::KindWord::Rrp,
    text: "rrp",
    usage: "rrp(A, l, GUIDE, plus|minus[, offset]) as (LINK, BLOCK) slide S",
    arity: super::word::Arity::Range(4, 5),
    links: "the link from A, and the block on the guide",
    inputs: &[],
    mode_at: Some(3),
    mode_words: super::word::SIGN_MODES,
    group: Some("RRP"),
};

/// An `rrp` statement.
pub(super) struct Rrp<'a> {
    pub stmt: &'a Stmt,
    pub a: &'a Ident,
    pub l: &'a Value,
    pub guide: &'a Ident,
    pub mode: Mode,
    pub offset: &'a Value,
}

impl<'a> GroupKind<'a> for Rrp<'a> {
    fn references(&self) -> Vec<(&'a Ident, Role)> {
        vec![(self.a, Role::Point), (self.guide, Role::Guide)]
    }

    fn link_shapes(&self) -> Vec<LinkShape> {
        let n = &self.stmt.name;
        vec![
            LinkShape::new(&[self.a, n], Turn::Own, None),
            LinkShape::new(&[n], Turn::None, Some(self.guide)),
        ]
    }

    fn point_owner(&self) -> Option<Option<LinkName>> {
        Some(Some(LinkName::of(&self.stmt.links[0])))
    }

    fn position_values(&self) -> Vec<Value> {
        vec![self.l.clone(), self.offset.clone()]
    }

    fn position_type(&self) -> TokenStream {
        quote!(::mechanism::dyad::rrp::RrpPosition<T>)
    }

    fn position(&self, _cos_sin: bool) -> Solve {
        let (l, m, o) = (
            self.l.emit(),
            mode_arg(self.stmt, self.mode),
            self.offset.emit(),
        );
        let (a, guide) = (local(self.a), local(self.guide));
        Solve::Group {
            call: quote!(::mechanism::dyad::rrp::position(&#a, #l, &#guide, #o, #m)),
            joint: Some("c"),
        }
    }

    fn link_direction(&self, index: usize) -> (TokenStream, TokenStream) {
        match index {
            0 => arm(self.stmt, "r1", self.l.emit()),
            _ => along(self.guide),
        }
    }

    fn rates(&self, cx: &mut dyn RateCx) {
        let ((g, gv), guide) = (states(self.stmt), self.guide);
        let (ma, gvel) = (cx.point_arg(self.a), cx.guide_vel(guide));
        let r = cx.reads();
        let (pg, pl) = (r.pos(&g), r.pos(guide));
        let call = if cx.accel() {
            let (gacc, gv) = (cx.guide_acc(guide), r.vel(&gv));
            quote!(::mechanism::dyad::rrp::acceleration(&#pg, &#pl, &#gv, #ma, #gvel, #gacc))
        } else {
            quote!(::mechanism::dyad::rrp::velocity(&#pg, &#pl, #ma, #gvel))
        };
        let gr = cx.group(self.stmt, call, quote!(dyad::rrp), "Rrp");
        let Pieces { point, r1, s, .. } = Pieces::of(cx.accel());
        cx.named(cx.motion(self.stmt), quote!(#gr.#point), vec_ty());
        cx.named(cx.own(self.stmt, 0), quote!(#gr.#r1), quote!(T));
        cx.slide(0, quote!(#gr.#s));
    }

    fn rate_system(&self) -> bool {
        true
    }

    /// `C` at `l` from `A`, on the guide's offset line, on its branch
    /// (along the guide from `A`).
    fn residuals(&self, r: &mut Residuals<'_>, _link_axis: &dyn Fn(&Ident) -> TokenStream) {
        r.at_length("|C - A| = l", self.a, f(self.l));
        r.on_offset_line("C on the offset line", self.guide, self.offset);
        let (n, a, guide) = (r.pos(r.n), r.pos(self.a), r.pos(self.guide));
        let m = mode_sign(self.mode);
        r.push(
            "assembly branch",
            quote!(wrong_side(#m * dot(sub(pt(&#n), pt(&#a)), vc(&#guide.dir)))),
        );
    }

    fn closure_axis(&self, index: usize, reads: &Reads) -> TokenStream {
        match index {
            0 => axis_between(self.a, &self.stmt.name, reads),
            _ => guide_axis(self.guide, reads),
        }
    }

    fn link_lengths(&self) -> Vec<&'a Value> {
        vec![self.l]
    }

    fn explain_fault(&self, fault: &Fault, at: &str) -> Option<String> {
        let (a, guide) = (self.a, self.guide);
        let Fault::CannotAssemble { miss, reach } = fault else {
            return None;
        };
        Some(format!(
            "at {at}, `{a}` is {} from the line of guide `{guide}`, {} more than the link's length {} reaches",
            show_num(reach + miss),
            show_num(*miss),
            show_num(*reach)
        ))
    }

    fn singular_meaning(&self) -> Option<String> {
        let (l, guide) = (&self.stmt.links, self.guide);
        Some(format!(
            "link `{}` is perpendicular to guide `{guide}` (the block cannot be pushed along it)",
            l[0]
        ))
    }

    fn primitive(&self) -> &'static str {
        "Rrp"
    }

    fn det_code(&self, reads: &Reads) -> TokenStream {
        let (g, guide) = (reads.pos(&grp(self.stmt)), reads.pos(self.guide));
        quote!(::mechanism::__private::det_rrp(&#g, &#guide))
    }

    fn describe(&self) -> String {
        let (n, links, a, guide) = (&self.stmt.name, links_text(self.stmt), self.a, self.guide);
        format!(
            "RRP group `{links}`: `{a}` and guide `{guide}` -> `{n}`, {}",
            mode_text(self.stmt, self.mode)
        )
    }

    fn forces(&self, cx: &mut dyn ForceCx) {
        let (stmt, a, guide) = (self.stmt, self.a, self.guide);
        let (rx, links, name) = (rx(stmt), &stmt.links, &stmt.name);
        let (l1, l2) = cx.loads_about(stmt, name);
        let r = cx.reads();
        let (pa, pn, pl) = (r.pos(a), r.pos(name), r.pos(guide));
        cx.solve(
            stmt,
            quote!(::mechanism::force::rrp::reactions(&#pa, &#pn, &#pl.dir, &#l1, &#l2)),
        );
        let ba = cx.pass_revolute(a, &rx, "a");
        let bg = cx.body_of_guide(guide);
        cx.prismatic_on(bg.clone(), quote!(#rx.guide), name);
        cx.reaction(revolute(&rx, &ba, &links[0], a, "a"));
        cx.reaction(inner(&rx, links, name, "c", false));
        cx.reaction(prismatic(&rx, &bg, &links[1], name, "guide"));
        cx.condition(quote!(#rx.min_pivot_ratio));
    }

    fn bodies_and_pairs(&self) -> (i64, i64, i64) {
        (2, 3, 0)
    }

    /// Its lane code in the batch kernel (`None`: an argument the kernel
    /// does not know; the batch then takes the scalar path).
    fn lane(&self, lane: &mut Lane, s: &mut Step<'_>) -> Option<()> {
        lane_steps(lane, s, self.a, self.l, self.guide, &self.mode, self.offset)
    }

    fn slide_field(&self, _slot: usize) -> TokenStream {
        quote!(s)
    }

    moving_joint_facets!();
}

/// An RRP group: the joint at distance `l` (length unit) from `a` and at
/// `offset` across `guide`, on the side `mode` (`lane::rrp`), its slide
/// along the guide (`s0_NAME`), rates with `lane::rrp_rates` /
/// `lane::rrp_accels`. Link 1 lies along `r1`, link 2 (the block) turns
/// with the guide. `None` when `a` or the guide is not known yet.
fn lane_steps(
    lane: &Lane,
    s: &mut Step,
    a: &Ident,
    l: &Value,
    guide: &Ident,
    mode: &Mode,
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
    let (l, o, sign) = (l.emit(), offset.emit(), s.sign(mode));
    let r1 = s.rates(0)?;
    let (w1, al1) = (&r1.omega, &r1.alpha);
    let slide = s.slide_locals(0);
    let (sl, sd, sdd) = (&slide.s, &slide.sd, &slide.sdd);
    let (apx, apy) = (&pa.px, &pa.py);
    s.emit(quote! {
        let #g = ::mechanism::__private::lane::rrp(#apx, #apy, #l, &#line, #o, #sign);
        ok &= #g.ok;
        let #px = #g.x; let #py = #g.y;
        let #sl = #g.s;
    });
    s.check([quote!(#sl)]);
    if lane.vel {
        let (avx, avy) = (&pa.vx, &pa.vy);
        s.emit(quote! {
            ok &= #g.ok_rate;
            let (#w1, #sd, #vx, #vy) = ::mechanism::__private::lane::rrp_rates(&#g, &#line, #avx, #avy, #gv);
        });
        s.check([quote!(#w1), quote!(#sd)]);
    }
    if lane.acc {
        let (aax, aay) = (&pa.ax, &pa.ay);
        s.emit(quote! {
            let (#al1, #sdd, #ax, #ay) = ::mechanism::__private::lane::rrp_accels(&#g, &#line, #aax, #aay, #w1, #sd, #gv, #ga);
        });
        s.check([quote!(#al1), quote!(#sdd)]);
    }
    s.defines_slide(0, &slide);
    let (w1, al1) = (quote!(#w1), quote!(#al1));
    s.defines_link(0, LaneLink::along(along_line(&g, "r1"), Some(&l), w1, al1))?;
    let block = LaneLink::along(line_axis(line), None, gd.omega.clone(), gd.alpha.clone());
    s.defines_link(1, block)
}

impl super::run::RunKind for Rrp<'_> {
    fn compile(&self, cx: &Compile<'_>) -> Box<dyn super::run::Step> {
        Box::new(RrpRun {
            me: cx.me(self.stmt),
            a: cx.point(self.a),
            l: cx.num(self.l),
            guide: cx.guide(self.guide),
            mode: mode(self.mode),
            offset: cx.num(self.offset),
        })
    }
}

/// An RRP group, compiled: its known joint, link length (L), guide, mode
/// and the block's offset from the guide (L).
struct RrpRun {
    me: Me,
    a: PointSlot,
    l: f64,
    guide: GuideSlot,
    mode: mechanism_core::Mode,
    offset: f64,
}

impl super::run::Step for RrpRun {
    fn group(&self) -> &'static str {
        self.me.group
    }

    fn walks(&self) -> super::run::Walks {
        super::run::Walks::ALL
    }

    fn position(&self, pose: &mut RunPose) -> Result<Option<f64>, mechanism_core::Error<f64>> {
        let (pa, gl, l) = (pose.point(self.a), pose.line(self.guide), self.l);
        let p = dyad::rrp::position(&pa, l, &gl, self.offset, self.mode)?;
        pose.found(&self.me, p.c, &[p.r1 / l, gl.dir]);
        pose.keep(&self.me, p);
        Ok(Some(sweep::det_rrp(&p, &gl)))
    }

    fn rates(&self, cx: &mut RunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let me = &self.me;
        let missing = || super::run::missing(mechanism_core::Primitive::Rrp);
        let g = cx
            .pose
            .kept::<dyad::rrp::RrpPosition<f64>>(me)
            .ok_or_else(missing)?;
        let line = cx.pose.line(self.guide);
        let (ma, gvel) = (cx.point_arg(self.a), cx.guide_vel(self.guide));
        if cx.accel() {
            let gv = cx
                .vel_group::<dyad::rrp::RrpVelocity<f64>>(me)
                .ok_or_else(missing)?;
            let gacc = cx.guide_acc(self.guide);
            let r =
                dyad::rrp::acceleration(g, &line, gv, ma.as_ref(), gvel.as_ref(), gacc.as_ref())?;
            cx.set_motion(me, r.ac);
            cx.set_own(me, 0, r.alpha1);
            cx.set_slide(me, 0, r.s_ddot);
        } else {
            let r = dyad::rrp::velocity(g, &line, ma.as_ref(), gvel.as_ref())?;
            cx.set_motion(me, r.vc);
            cx.set_own(me, 0, r.omega1);
            cx.set_slide(me, 0, r.s_dot);
            cx.keep(me, r, Some(r.condition));
        }
        Ok(())
    }

    /// `force::rrp::reactions` on the links' loads about the joint.
    fn forces(&self, cx: &mut ForceRunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let (me, a, guide) = (&self.me, self.a, self.guide);
        let (l1, l2) = cx.loads_about(me, me.point);
        let dir = cx.pose.line(guide).dir;
        let rx =
            mechanism_core::force::rrp::reactions(&cx.at(a), &cx.at(me.point), &dir, &l1, &l2)?;
        let ba = cx.pass_revolute(a, rx.a);
        let bg = cx.body_of_guide(guide);
        cx.prismatic_on(bg, &rx.guide, me.point);
        cx.revolute(ba, me.links[0], rx.a);
        cx.inner(me, super::run::ForceValue::Force(rx.c));
        cx.prismatic(bg, me.links[1], rx.guide);
        cx.conditions.push(rx.min_pivot_ratio);
        Ok(())
    }

    fn link_dir(&self, index: usize, pose: &RunPose) -> mechanism_core::Vector2<f64> {
        let nan = mechanism_core::Vector2::new(f64::NAN, f64::NAN);
        match index {
            0 => pose
                .kept::<dyad::rrp::RrpPosition<f64>>(&self.me)
                .map_or(nan, |p| p.r1),
            _ => pose.line(self.guide).dir,
        }
    }

    fn slide(&self, _k: usize, pose: &RunPose) -> Option<f64> {
        pose.kept::<dyad::rrp::RrpPosition<f64>>(&self.me)
            .map(|p| p.s)
    }
}
