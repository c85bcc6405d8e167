//! `rrr(A, l1, B, l2, mode) as (LINK1, LINK2)`: the RRR dyad, two links of
//! lengths `l1` from `A` and `l2` from `B` pinned at the defined point.

use super::closure::{axis_between, f, Residuals};
use super::forces::{inner, revolute, rx, ForceCx};
use super::group::{links_text, mode_text, GroupKind, LinkShape, Role, Solve, Turn};
use super::lane::{Lane, Step};
use super::lane_shapes::{dyad, SecondSide};
use super::rates::{states, two_links, RateCx};
use super::reads::Reads;
use super::run::{Compile, ForceRunCx, Me, PointSlot, RunCx, RunPose};
use super::tokens::{arm, grp, local, mode_arg};
use crate::diag::show_num;
use crate::keys::LinkName;
use crate::kinds::pose::{mode, num};
use crate::model::{Mode, Stmt};
use crate::value::Value;
use mechanism_core::{dyad, sweep, Fault};
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

/// How `rrr` is written: its word, usage, arity and links.
pub(crate) const SPEC: super::word::Spec = super::word::Spec {
    word: super::word::KindWord::Rrr,
    text: "rrr",
    usage: "rrr(A, l1, B, l2, left|right) as (LINK1, LINK2)",
    arity: super::word::Arity::Range(5, 5),
    links: "L1 from A, L2 from B",
    inputs: &[],
    mode_at: Some(4),
    mode_words: super::word::SIDE_MODES,
    group: Some("RRR"),
};

/// An `rrr` statement.
pub(super) struct Rrr<'a> {
    pub stmt: &'a Stmt,
    pub a: &'a Ident,
    pub l1: &'a Value,
    pub b: &'a Ident,
    pub l2: &'a Value,
    pub mode: Mode,
}

impl<'a> GroupKind<'a> for Rrr<'a> {
    fn references(&self) -> Vec<(&'a Ident, Role)> {
        vec![(self.a, Role::Point), (self.b, Role::Point)]
    }

    fn link_shapes(&self) -> Vec<LinkShape> {
        let n = &self.stmt.name;
        vec![
            LinkShape::new(&[self.a, n], Turn::Own, None),
            LinkShape::new(&[self.b, n], Turn::Own, None),
        ]
    }

    fn point_owner(&self) -> Option<Option<LinkName>> {
        Some(Some(LinkName::of(&self.stmt.links[0])))
    }

    fn position_values(&self) -> Vec<Value> {
        vec![self.l1.clone(), self.l2.clone()]
    }

    fn position_type(&self) -> TokenStream {
        quote!(::mechanism::dyad::rrr::RrrPosition<T>)
    }

    fn position(&self, _cos_sin: bool) -> Solve {
        let (l1, l2, m) = (
            self.l1.emit(),
            self.l2.emit(),
            mode_arg(self.stmt, self.mode),
        );
        let (a, b) = (local(self.a), local(self.b));
        Solve::Group {
            call: quote!(::mechanism::dyad::rrr::position(&#a, #l1, &#b, #l2, #m)),
            joint: Some("c"),
        }
    }

    fn link_direction(&self, index: usize) -> (TokenStream, TokenStream) {
        match index {
            0 => arm(self.stmt, "r1", self.l1.emit()),
            _ => arm(self.stmt, "r2", self.l2.emit()),
        }
    }

    fn rates(&self, cx: &mut dyn RateCx) {
        let (g, gv) = states(self.stmt);
        let (ma, mb) = (cx.point_arg(self.a), cx.point_arg(self.b));
        let g = cx.reads().pos(&g);
        let call = if cx.accel() {
            let gv = cx.reads().vel(&gv);
            quote!(::mechanism::dyad::rrr::acceleration(&#g, &#gv, #ma, #mb))
        } else {
            // The link lengths are the determinant's scale: no square root.
            let (l1, l2) = (self.l1.emit(), self.l2.emit());
            quote!(::mechanism::dyad::rrr::velocity_lengths(&#g, #l1, #l2, #ma, #mb))
        };
        let gr = cx.group(self.stmt, call, quote!(dyad::rrr), "Rrr");
        two_links(cx, self.stmt, &gr);
    }

    fn rate_system(&self) -> bool {
        true
    }

    /// `C` at `l1` from `A` and `l2` from `B`, on its branch.
    fn residuals(&self, r: &mut Residuals<'_>, _link_axis: &dyn Fn(&Ident) -> TokenStream) {
        r.at_length("|C - A| = l1", self.a, f(self.l1));
        r.at_length("|C - B| = l2", self.b, f(self.l2));
        r.dyad_branch(self.a, self.b, self.mode);
    }

    fn closure_axis(&self, index: usize, reads: &Reads) -> TokenStream {
        let from = if index == 0 { self.a } else { self.b };
        axis_between(from, &self.stmt.name, reads)
    }

    fn link_lengths(&self) -> Vec<&'a Value> {
        vec![self.l1, self.l2]
    }

    /// Too far apart (beyond `l1 + l2`) or too close (within `|l1 - l2|`).
    fn explain_fault(&self, fault: &Fault, at: &str) -> Option<String> {
        let (a, b) = (self.a, self.b);
        let Fault::CannotAssemble { miss, reach } = fault else {
            return None;
        };
        let (l1, l2) = (num(self.l1), num(self.l2));
        Some(
            if (reach - (l1 + l2)).abs() <= 1e-9 * reach.abs().max(1.0) {
                format!(
                "at {at}, `{a}` and `{b}` are {} apart, {} more than the links reach ({} + {} = {})",
                show_num(reach + miss),
                show_num(*miss),
                show_num(l1),
                show_num(l2),
                show_num(*reach)
            )
            } else {
                format!(
                "at {at}, `{a}` and `{b}` are {} apart, {} less than the links' difference (|{} - {}| = {})",
                show_num(reach - miss),
                show_num(*miss),
                show_num(l1),
                show_num(l2),
                show_num(*reach)
            )
            },
        )
    }

    /// Three RRR pinned outside their cycle: the class III group, written
    /// as one `triad` statement.
    fn cycle_hint(&self, cycle: &[&Stmt]) -> Option<String> {
        super::triad::cycle_hint(cycle)
    }

    fn singular_meaning(&self) -> Option<String> {
        let l = &self.stmt.links;
        Some(format!(
            "links `{}` and `{}` are aligned (toggle)",
            l[0], l[1]
        ))
    }

    fn primitive(&self) -> &'static str {
        "Rrr"
    }

    fn det_code(&self, reads: &Reads) -> TokenStream {
        let g = reads.pos(&grp(self.stmt));
        quote!(::mechanism::__private::det_rrr(&#g))
    }

    fn describe(&self) -> String {
        let (n, links, a, b) = (&self.stmt.name, links_text(self.stmt), self.a, self.b);
        format!(
            "RRR group `{links}`: `{a}`, `{b}` -> `{n}`, {}",
            mode_text(self.stmt, self.mode)
        )
    }

    fn forces(&self, cx: &mut dyn ForceCx) {
        let (stmt, a, b) = (self.stmt, self.a, self.b);
        let (rx, links, name) = (rx(stmt), &stmt.links, &stmt.name);
        let (l1, l2) = cx.loads_about(stmt, name);
        let r = cx.reads();
        let (pa, pb, pn) = (r.pos(a), r.pos(b), r.pos(name));
        cx.solve(
            stmt,
            quote!(::mechanism::force::rrr::reactions(&#pa, &#pb, &#pn, &#l1, &#l2)),
        );
        let ba = cx.pass_revolute(a, &rx, "a");
        let bb = cx.pass_revolute(b, &rx, "b");
        cx.reaction(revolute(&rx, &ba, &links[0], a, "a"));
        cx.reaction(revolute(&rx, &bb, &links[1], b, "b"));
        cx.reaction(inner(&rx, links, name, "c", false));
        cx.condition(quote!(#rx.min_pivot_ratio));
    }

    fn bodies_and_pairs(&self) -> (i64, i64, i64) {
        (2, 3, 0)
    }

    fn distinct_pair(&self) -> Option<(&'a Ident, &'a Ident, &'static str)> {
        Some((self.a, self.b, "known joints"))
    }

    /// Driven by a crank onto a ground point, it closes a four-bar: its
    /// Grashof condition, in numbers.
    fn full_turn_hint(&self, find: &dyn Fn(&Ident) -> Option<&'a Stmt>) -> Option<String> {
        let arm =
            |n: &Ident| find(n).and_then(|s| super::accessors::crank_arm(s).map(|arm| (s, arm)));
        let ground = |n: &Ident| find(n).and_then(super::accessors::ground_at);
        let ((crank, (pivot, radius)), other) = match (arm(self.a), arm(self.b)) {
            (Some(c), _) => (c, self.b),
            (_, Some(c)) => (c, self.a),
            _ => return None,
        };
        let (o, g) = (ground(pivot)?, ground(other)?);
        let four_bar = FourBar {
            names: [pivot, &crank.name, &self.stmt.name, other],
            crank: num(radius),
            coupler: num(self.l1),
            rocker: num(self.l2),
            ground: (o.0 - g.0).hypot(o.1 - g.1),
        };
        four_bar.grashof()
    }

    /// Its lane code in the batch kernel (`None`: an argument the kernel
    /// does not know; the batch then takes the scalar path).
    fn lane(&self, lane: &mut Lane, s: &mut Step<'_>) -> Option<()> {
        lane_steps(lane, s, self.a, self.l1, self.b, self.l2, &self.mode)
    }

    fn slide_field(&self, _slot: usize) -> TokenStream {
        quote!(s)
    }

    moving_joint_facets!();
}

/// An RRR group: the joint at distance `l1` from `a` and `l2` from `b`
/// (length unit), on the side `mode` (`lane::rrr`), its rates with
/// `lane::rrr_rates` / `lane::rrr_accels`. See [`dyad`].
fn lane_steps(
    lane: &Lane,
    s: &mut Step,
    a: &Ident,
    l1: &Value,
    b: &Ident,
    l2: &Value,
    mode: &Mode,
) -> Option<()> {
    dyad(lane, s, a, l1, b, SecondSide::Length(l2), mode)
}

/// A four-bar closed by a crank and an RRR: its joints' names (pivot, crank
/// tip, RRR joint, other ground point) and its link lengths.
struct FourBar<'n> {
    names: [&'n Ident; 4],
    crank: f64,
    coupler: f64,
    rocker: f64,
    ground: f64,
}

impl FourBar<'_> {
    /// Why no full turn: not Grashof, or the crank not the shortest link;
    /// `None` when the crank can turn fully.
    fn grashof(&self) -> Option<String> {
        let r = self.crank;
        let mut links = [
            (r, format!("crank {}", show_num(r))),
            (self.coupler, show_num(self.coupler)),
            (self.rocker, show_num(self.rocker)),
            (self.ground, format!("ground {}", show_num(self.ground))),
        ];
        links.sort_by(|x, y| x.0.total_cmp(&y.0));
        let (s, p, q, l) = (&links[0], &links[1], &links[2], &links[3]);
        let text = format!(
            "s + l = {} + {} = {}, p + q = {} + {} = {}",
            s.1,
            l.1,
            show_num(s.0 + l.0),
            p.1,
            q.1,
            show_num(p.0 + q.0)
        );
        let [pivot, tip, joint, other] = self.names;
        Some(if s.0 + l.0 > p.0 + q.0 {
            format!("the four-bar `{pivot}`-`{tip}`-`{joint}`-`{other}` is not Grashof ({text}): no link turns fully")
        } else if s.0 < r {
            format!("the four-bar `{pivot}`-`{tip}`-`{joint}`-`{other}` is Grashof ({text}), but the crank is not its shortest link: only the shortest link turns fully")
        } else {
            return None;
        })
    }
}

impl super::run::RunKind for Rrr<'_> {
    fn compile(&self, cx: &Compile<'_>) -> Box<dyn super::run::Step> {
        Box::new(RrrRun {
            me: cx.me(self.stmt),
            a: cx.point(self.a),
            b: cx.point(self.b),
            l1: cx.num(self.l1),
            l2: cx.num(self.l2),
            mode: mode(self.mode),
        })
    }
}

/// An RRR group, compiled: its known joints, link lengths (L) and mode.
struct RrrRun {
    me: Me,
    a: PointSlot,
    b: PointSlot,
    l1: f64,
    l2: f64,
    mode: mechanism_core::Mode,
}

impl super::run::Step for RrrRun {
    fn group(&self) -> &'static str {
        self.me.group
    }

    fn walks(&self) -> super::run::Walks {
        super::run::Walks::ALL
    }

    fn position(&self, pose: &mut RunPose) -> Result<Option<f64>, mechanism_core::Error<f64>> {
        let (pa, pb) = (pose.point(self.a), pose.point(self.b));
        let (l1, l2) = (self.l1, self.l2);
        let p = dyad::rrr::position(&pa, l1, &pb, l2, self.mode)?;
        pose.found(&self.me, p.c, &[p.r1 / l1, p.r2 / l2]);
        pose.keep(&self.me, p);
        Ok(Some(sweep::det_rrr(&p)))
    }

    fn rates(&self, cx: &mut RunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let me = &self.me;
        let missing = || super::run::missing(mechanism_core::Primitive::Rrr);
        let g = cx
            .pose
            .kept::<dyad::rrr::RrrPosition<f64>>(me)
            .ok_or_else(missing)?;
        let (ma, mb) = (cx.point_arg(self.a), cx.point_arg(self.b));
        if cx.accel() {
            let gv = cx
                .vel_group::<dyad::rrr::RrrVelocity<f64>>(me)
                .ok_or_else(missing)?;
            let r = dyad::rrr::acceleration(g, gv, ma.as_ref(), mb.as_ref())?;
            cx.set_motion(me, r.ac);
            cx.set_own(me, 0, r.alpha1);
            cx.set_own(me, 1, r.alpha2);
        } else {
            // The link lengths are the determinant's scale, as emitted.
            let r = dyad::rrr::velocity_lengths(g, self.l1, self.l2, ma.as_ref(), mb.as_ref())?;
            cx.set_motion(me, r.vc);
            cx.set_own(me, 0, r.omega1);
            cx.set_own(me, 1, r.omega2);
            cx.keep(me, r, Some(r.condition));
        }
        Ok(())
    }

    /// `force::rrr::reactions` on the links' loads about the joint.
    fn forces(&self, cx: &mut ForceRunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let (me, a, b) = (&self.me, self.a, self.b);
        let (l1, l2) = cx.loads_about(me, me.point);
        let rx = mechanism_core::force::rrr::reactions(
            &cx.at(a),
            &cx.at(b),
            &cx.at(me.point),
            &l1,
            &l2,
        )?;
        let ba = cx.pass_revolute(a, rx.a);
        let bb = cx.pass_revolute(b, rx.b);
        cx.revolute(ba, me.links[0], rx.a);
        cx.revolute(bb, me.links[1], rx.b);
        cx.inner(me, super::run::ForceValue::Force(rx.c));
        cx.conditions.push(rx.min_pivot_ratio);
        Ok(())
    }

    fn link_dir(&self, index: usize, pose: &RunPose) -> mechanism_core::Vector2<f64> {
        let nan = mechanism_core::Vector2::new(f64::NAN, f64::NAN);
        pose.kept::<dyad::rrr::RrrPosition<f64>>(&self.me)
            .map_or(nan, |p| if index == 0 { p.r1 } else { p.r2 })
    }
}
