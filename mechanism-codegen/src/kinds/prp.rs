//! `prp(GUIDE1, GUIDE2) as (BLOCK1, BLOCK2)`: the PRP dyad, two blocks on two
//! guides pinned together at the defined point.

use super::closure::{guide_axis, Residuals};
use super::forces::{inner, prismatic, rx, ForceCx};
use super::group::{links_text, GroupKind, LinkShape, Role, Solve, Turn};
use super::lane::{Lane, LaneLink, PointLocals, Step};
use super::lane_shapes::line_axis;
use super::rates::{states, vec_ty, Pieces, RateCx};
use super::reads::Reads;
use super::run::{Compile, ForceRunCx, GuideSlot, Me, RunCx, RunPose};
use super::tokens::{along, local};
use crate::keys::LinkName;
use crate::model::Stmt;
use crate::value::Value;
use mechanism_core::{dyad, sweep, Fault};
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

/// How `prp` is written: its word, usage, arity and links.
pub(crate) const SPEC: super::word::Spec = super::word::Spec {
    word: super::word::KindWord::Prp,
    text: "prp",
    usage: "prp(GUIDE1, GUIDE2[, offset1, offset2]) as (LINK1, LINK2) slide (S1, S2)",
    arity: super::word::Arity::Range(2, 4),
    links: "the block on the first guide, and the block on the second",
    inputs: &[],
    mode_at: None,
    mode_words: &[],
    group: Some("PRP"),
};

/// A `prp` statement.
pub(super) struct Prp<'a> {
    pub stmt: &'a Stmt,
    pub g1: &'a Ident,
    pub g2: &'a Ident,
    pub offset1: &'a Value,
    pub offset2: &'a Value,
}

impl<'a> GroupKind<'a> for Prp<'a> {
    fn references(&self) -> Vec<(&'a Ident, Role)> {
        vec![(self.g1, Role::Guide), (self.g2, Role::Guide)]
    }

    fn link_shapes(&self) -> Vec<LinkShape> {
        let n = &self.stmt.name;
        vec![
            LinkShape::new(&[n], Turn::None, Some(self.g1)),
            LinkShape::new(&[n], Turn::None, Some(self.g2)),
        ]
    }

    fn point_owner(&self) -> Option<Option<LinkName>> {
        Some(Some(LinkName::of(&self.stmt.links[0])))
    }

    fn position_values(&self) -> Vec<Value> {
        vec![self.offset1.clone(), self.offset2.clone()]
    }

    fn position_type(&self) -> TokenStream {
        quote!(::mechanism::dyad::prp::PrpPosition<T>)
    }

    fn position(&self, _cos_sin: bool) -> Solve {
        let (o1, o2) = (self.offset1.emit(), self.offset2.emit());
        let (g1, g2) = (local(self.g1), local(self.g2));
        Solve::Group {
            call: quote!(::mechanism::dyad::prp::position(&#g1, #o1, &#g2, #o2)),
            joint: Some("c"),
        }
    }

    fn link_direction(&self, index: usize) -> (TokenStream, TokenStream) {
        match index {
            0 => along(self.g1),
            _ => along(self.g2),
        }
    }

    fn slide_field(&self, slot: usize) -> TokenStream {
        match slot {
            0 => quote!(s1),
            _ => quote!(s2),
        }
    }

    fn rates(&self, cx: &mut dyn RateCx) {
        let ((g, gv), g1, g2) = (states(self.stmt), self.g1, self.g2);
        let (v1, v2) = (cx.guide_vel(g1), cx.guide_vel(g2));
        let r = cx.reads();
        let (pg, p1, p2) = (r.pos(&g), r.pos(g1), r.pos(g2));
        let call = if cx.accel() {
            let (a1, a2, gv) = (cx.guide_acc(g1), cx.guide_acc(g2), r.vel(&gv));
            quote!(::mechanism::dyad::prp::acceleration(&#pg, &#p1, &#p2, &#gv, #v1, #a1, #v2, #a2))
        } else {
            quote!(::mechanism::dyad::prp::velocity(&#pg, &#p1, &#p2, #v1, #v2))
        };
        let gr = cx.group(self.stmt, call, quote!(dyad::prp), "Prp");
        let Pieces { point, s1, s2, .. } = Pieces::of(cx.accel());
        cx.named(cx.motion(self.stmt), quote!(#gr.#point), vec_ty());
        cx.slide(0, quote!(#gr.#s1));
        cx.slide(1, quote!(#gr.#s2));
    }

    fn rate_system(&self) -> bool {
        true
    }

    /// `C` on both guides' offset lines.
    fn residuals(&self, r: &mut Residuals<'_>, _link_axis: &dyn Fn(&Ident) -> TokenStream) {
        r.on_offset_line("C on offset line 1", self.g1, self.offset1);
        r.on_offset_line("C on offset line 2", self.g2, self.offset2);
    }

    fn closure_axis(&self, index: usize, reads: &Reads) -> TokenStream {
        guide_axis(if index == 0 { self.g1 } else { self.g2 }, reads)
    }

    fn explain_fault(&self, fault: &Fault, at: &str) -> Option<String> {
        let (g1, g2) = (self.g1, self.g2);
        matches!(fault, Fault::Singular { .. }).then(|| {
            format!("at {at}, guides `{g1}` and `{g2}` are parallel: the joint is at infinity")
        })
    }

    fn singular_meaning(&self) -> Option<String> {
        let (g1, g2) = (self.g1, self.g2);
        Some(format!("guides `{g1}` and `{g2}` are parallel"))
    }

    fn primitive(&self) -> &'static str {
        "Prp"
    }

    fn det_code(&self, reads: &Reads) -> TokenStream {
        let (g1, g2) = (reads.pos(self.g1), reads.pos(self.g2));
        quote!(::mechanism::__private::det_prp(&#g1, &#g2))
    }

    fn describe(&self) -> String {
        let (n, links, g1, g2) = (&self.stmt.name, links_text(self.stmt), self.g1, self.g2);
        format!("PRP group `{links}`: guides `{g1}`, `{g2}` -> `{n}`")
    }

    fn forces(&self, cx: &mut dyn ForceCx) {
        let (stmt, g1, g2) = (self.stmt, self.g1, self.g2);
        let (rx, links, name) = (rx(stmt), &stmt.links, &stmt.name);
        let (l1, l2) = cx.loads_about(stmt, name);
        let r = cx.reads();
        let (pn, p1, p2) = (r.pos(name), r.pos(g1), r.pos(g2));
        cx.solve(
            stmt,
            quote!(::mechanism::force::prp::reactions(&#pn, &#p1.dir, &#p2.dir, &#l1, &#l2)),
        );
        let c1 = cx.body_of_guide(g1);
        let c2 = cx.body_of_guide(g2);
        cx.prismatic_on(c1.clone(), quote!(#rx.guide1), name);
        cx.prismatic_on(c2.clone(), quote!(#rx.guide2), name);
        cx.reaction(prismatic(&rx, &c1, &links[0], name, "guide1"));
        cx.reaction(prismatic(&rx, &c2, &links[1], name, "guide2"));
        cx.reaction(inner(&rx, links, name, "c", false));
        cx.condition(quote!(#rx.min_pivot_ratio));
    }

    fn bodies_and_pairs(&self) -> (i64, i64, i64) {
        (2, 3, 0)
    }

    fn distinct_pair(&self) -> Option<(&'a Ident, &'a Ident, &'static str)> {
        Some((self.g1, self.g2, "guides"))
    }

    fn joint_at_infinity(&self) -> bool {
        true
    }

    /// Guides parallel at every pose checked (guides that turn together,
    /// or keep their directions): said directly.
    fn singular_everywhere(&self, over: &str) -> Option<String> {
        let (g1, g2) = (self.g1, self.g2);
        Some(format!(
            "group `{}` (PRP) cannot assemble: guides `{g1}` and `{g2}` are parallel at every pose checked ({over}), so the joint is at infinity for every input\n  = help: make the guides cross: change the angle of one of them",
            self.stmt.name
        ))
    }

    /// Its lane code in the batch kernel (`None`: an argument the kernel
    /// does not know; the batch then takes the scalar path).
    fn lane(&self, lane: &mut Lane, s: &mut Step<'_>) -> Option<()> {
        lane_steps(lane, s, self.g1, self.g2, self.offset1, self.offset2)
    }

    fn link_lengths(&self) -> Vec<&'a Value> {
        Vec::new()
    }

    moving_joint_facets!();
}

/// A PRP group: the joint of two blocks, on `g1` at `offset1` and on `g2`
/// at `offset2` (length unit) (`lane::prp`), its two slides (`s0_NAME`,
/// `s1_NAME`) and their rates (`lane::prp_rates` / `lane::prp_accels`).
/// Each block turns with its guide's body. `None` when a guide is not
/// known yet.
fn lane_steps(
    lane: &Lane,
    s: &mut Step,
    g1: &Ident,
    g2: &Ident,
    offset1: &Value,
    offset2: &Value,
) -> Option<()> {
    let (d1, d2) = (lane.guide(g1)?, lane.guide(g2)?);
    let PointLocals {
        px,
        py,
        vx,
        vy,
        ax,
        ay,
    } = s.own.clone();
    let g = s.g.clone();
    let (l1, gv1, ga1) = (&d1.line, &d1.gv, &d1.ga);
    let (l2, gv2, ga2) = (&d2.line, &d2.gv, &d2.ga);
    let (o1, o2) = (offset1.emit(), offset2.emit());
    let (slide1, slide2) = (s.slide_locals(0), s.slide_locals(1));
    let (s1, sd1, sdd1) = (&slide1.s, &slide1.sd, &slide1.sdd);
    let (s2, sd2, sdd2) = (&slide2.s, &slide2.sd, &slide2.sdd);
    s.emit(quote! {
        let #g = ::mechanism::__private::lane::prp(&#l1, #o1, &#l2, #o2);
        ok &= #g.ok;
        let #px = #g.x; let #py = #g.y;
        let #s1 = #g.s1; let #s2 = #g.s2;
    });
    s.check([quote!(#s1), quote!(#s2)]);
    if lane.vel {
        s.emit(quote! {
            let (#sd1, #sd2, #vx, #vy) = ::mechanism::__private::lane::prp_rates(&#g, &#l1, &#l2, #gv1, #gv2);
        });
        s.check([quote!(#sd1), quote!(#sd2)]);
    }
    if lane.acc {
        s.emit(quote! {
            let (#sdd1, #sdd2, #ax, #ay) = ::mechanism::__private::lane::prp_accels(&#g, &#l1, &#l2, #sd1, #sd2, #gv1, #ga1, #gv2, #ga2);
        });
        s.check([quote!(#sdd1), quote!(#sdd2)]);
    }
    s.defines_slide(0, &slide1);
    s.defines_slide(1, &slide2);
    for (k, d) in [d1, d2].into_iter().enumerate() {
        let block = LaneLink::along(line_axis(&d.line), None, d.omega.clone(), d.alpha.clone());
        s.defines_link(k, block)?;
    }
    Some(())
}

impl super::run::RunKind for Prp<'_> {
    fn compile(&self, cx: &Compile<'_>) -> Box<dyn super::run::Step> {
        Box::new(PrpRun {
            me: cx.me(self.stmt),
            g1: cx.guide(self.g1),
            g2: cx.guide(self.g2),
            offset1: cx.num(self.offset1),
            offset2: cx.num(self.offset2),
        })
    }
}

/// A PRP group, compiled: its two guides and the blocks' offsets (L).
struct PrpRun {
    me: Me,
    g1: GuideSlot,
    g2: GuideSlot,
    offset1: f64,
    offset2: f64,
}

impl super::run::Step for PrpRun {
    fn group(&self) -> &'static str {
        self.me.group
    }

    fn walks(&self) -> super::run::Walks {
        super::run::Walks::ALL
    }

    fn position(&self, pose: &mut RunPose) -> Result<Option<f64>, mechanism_core::Error<f64>> {
        let (l1, l2) = (pose.line(self.g1), pose.line(self.g2));
        let p = dyad::prp::position(&l1, self.offset1, &l2, self.offset2)?;
        pose.found(&self.me, p.c, &[l1.dir, l2.dir]);
        pose.keep(&self.me, p);
        Ok(Some(sweep::det_prp(&l1, &l2)))
    }

    fn rates(&self, cx: &mut RunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let me = &self.me;
        let missing = || super::run::missing(mechanism_core::Primitive::Prp);
        let g = cx
            .pose
            .kept::<dyad::prp::PrpPosition<f64>>(me)
            .ok_or_else(missing)?;
        let (l1, l2) = (cx.pose.line(self.g1), cx.pose.line(self.g2));
        let (v1, v2) = (cx.guide_vel(self.g1), cx.guide_vel(self.g2));
        if cx.accel() {
            let gv = cx
                .vel_group::<dyad::prp::PrpVelocity<f64>>(me)
                .ok_or_else(missing)?;
            let (a1, a2) = (cx.guide_acc(self.g1), cx.guide_acc(self.g2));
            let r = dyad::prp::acceleration(
                g,
                &l1,
                &l2,
                gv,
                v1.as_ref(),
                a1.as_ref(),
                v2.as_ref(),
                a2.as_ref(),
            )?;
            cx.set_motion(me, r.ac);
            cx.set_slide(me, 0, r.s1_ddot);
            cx.set_slide(me, 1, r.s2_ddot);
        } else {
            let r = dyad::prp::velocity(g, &l1, &l2, v1.as_ref(), v2.as_ref())?;
            cx.set_motion(me, r.vc);
            cx.set_slide(me, 0, r.s1_dot);
            cx.set_slide(me, 1, r.s2_dot);
            cx.keep(me, r, Some(r.condition));
        }
        Ok(())
    }

    /// `force::prp::reactions` on the links' loads about the joint.
    fn forces(&self, cx: &mut ForceRunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let (me, g1, g2) = (&self.me, self.g1, self.g2);
        let (l1, l2) = cx.loads_about(me, me.point);
        let (d1, d2) = (cx.pose.line(g1).dir, cx.pose.line(g2).dir);
        let rx = mechanism_core::force::prp::reactions(&cx.at(me.point), &d1, &d2, &l1, &l2)?;
        let c1 = cx.body_of_guide(g1);
        let c2 = cx.body_of_guide(g2);
        cx.prismatic_on(c1, &rx.guide1, me.point);
        cx.prismatic_on(c2, &rx.guide2, me.point);
        cx.prismatic(c1, me.links[0], rx.guide1);
        cx.prismatic(c2, me.links[1], rx.guide2);
        cx.inner(me, super::run::ForceValue::Force(rx.c));
        cx.conditions.push(rx.min_pivot_ratio);
        Ok(())
    }

    fn link_dir(&self, index: usize, pose: &RunPose) -> mechanism_core::Vector2<f64> {
        match index {
            0 => pose.line(self.g1).dir,
            _ => pose.line(self.g2).dir,
        }
    }

    fn slide(&self, k: usize, pose: &RunPose) -> Option<f64> {
        pose.kept::<dyad::prp::PrpPosition<f64>>(&self.me)
            .map(|p| if k == 0 { p.s1 } else { p.s2 })
    }
}
