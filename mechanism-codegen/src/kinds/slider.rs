//! `slider(GUIDE, INPUT) as BLOCK`: a block driven along a guide by the
//! input displacement (length units, along the guide's direction).

use super::closure::{guide_axis, Residuals};
use super::forces::{drive, prismatic, rx, ForceCx, Held};
use super::group::{links_text, GroupKind, LinkShape, Role, Solve, Turn};
use super::lane::{Lane, LaneLink, PointLocals, Step, Vector};
use super::rates::{vec_ty, RateCx};
use super::reads::Reads;
use super::run::{Compile, ForceRunCx, GuideSlot, InputSlot, Me, RunCx, RunPose};
use super::tokens::{along, grp, local, tag};
use crate::keys::LinkName;
use crate::model::Stmt;
use crate::names::Family;
use crate::value::Value;
use mechanism_core::driver;
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

/// How `slider` is written: its word, usage, arity and links.
pub(crate) const SPEC: super::word::Spec = super::word::Spec {
    word: super::word::KindWord::Slider,
    text: "slider",
    usage: "slider(GUIDE, INPUT[, offset]) as LINK",
    arity: super::word::Arity::Range(2, 3),
    links: "the block, sliding on the guide",
    inputs: &[1],
    mode_at: None,
    mode_words: &[],
    group: Some("slider"),
};

/// A `slider` statement.
pub(super) struct Slider<'a> {
    pub stmt: &'a Stmt,
    pub guide: &'a Ident,
    pub input: &'a Ident,
    pub offset: &'a Value,
}

impl<'a> GroupKind<'a> for Slider<'a> {
    fn references(&self) -> Vec<(&'a Ident, Role)> {
        vec![(self.guide, Role::Guide)]
    }

    fn link_shapes(&self) -> Vec<LinkShape> {
        vec![LinkShape::new(
            &[&self.stmt.name],
            Turn::None,
            Some(self.guide),
        )]
    }

    fn point_owner(&self) -> Option<Option<LinkName>> {
        Some(Some(LinkName::of(&self.stmt.links[0])))
    }

    fn position_values(&self) -> Vec<Value> {
        vec![self.offset.clone()]
    }

    fn position_type(&self) -> TokenStream {
        quote!(::mechanism::driver::slider::SliderPosition<T>)
    }

    fn position(&self, _cos_sin: bool) -> Solve {
        let (o, guide, input) = (self.offset.emit(), local(self.guide), self.input);
        Solve::Group {
            call: quote!(::mechanism::driver::slider::position(&#guide, #o, input.#input)),
            joint: Some("p"),
        }
    }

    fn link_direction(&self, _index: usize) -> (TokenStream, TokenStream) {
        along(self.guide)
    }

    fn rates(&self, cx: &mut dyn RateCx) {
        let (stmt, guide, input) = (self.stmt, self.guide, self.input);
        let (g, pv, t) = (grp(stmt), cx.motion(stmt), tag(stmt));
        let gvel = cx.guide_vel(guide);
        let r = cx.reads();
        let (pg, pl, pi) = (r.pos(&g), r.pos(guide), r.pos_input());
        let code = if cx.accel() {
            let gacc = cx.guide_acc(guide);
            quote! {
                let #pv = ::mechanism::driver::slider::acceleration(&#pg, &#pl, #pi.#input, rates.#input, accels.#input, #gvel, #gacc) #t;
            }
        } else {
            quote! {
                let #pv = ::mechanism::driver::slider::velocity(&#pg, &#pl, #pi.#input, rates.#input, #gvel) #t;
            }
        };
        cx.code(code);
        cx.field(pv, vec_ty());
    }

    /// The pin on the guide's offset line, at the input displacement.
    fn residuals(&self, r: &mut Residuals<'_>, _link_axis: &dyn Fn(&Ident) -> TokenStream) {
        r.on_offset_line("pin on the offset line", self.guide, self.offset);
        let (n, guide, input) = (r.pos(r.n), r.pos(self.guide), self.input);
        let inputs = r.reads.pos_input();
        r.push(
            "pin at the input displacement",
            quote!(dot(vc(&#guide.dir), sub(pt(&#n), pt(&#guide.origin))) - <T as ::mechanism::Real>::as_f64(#inputs.#input)),
        );
    }

    fn closure_axis(&self, _index: usize, reads: &Reads) -> TokenStream {
        guide_axis(self.guide, reads)
    }

    fn primitive(&self) -> &'static str {
        "Slider"
    }

    fn describe(&self) -> String {
        let (n, links, guide, input) = (
            &self.stmt.name,
            links_text(self.stmt),
            self.guide,
            self.input,
        );
        format!("driver: slider `{links}` on `{guide}`, input `{input}`, pin `{n}`")
    }

    fn forces(&self, cx: &mut dyn ForceCx) {
        let (stmt, guide, input) = (self.stmt, self.guide, self.input);
        let (rx, link, name) = (rx(stmt), &stmt.links[0], &stmt.name);
        let load = cx.load_about(link, name);
        let pl = cx.reads().pos(guide);
        cx.solve(
            stmt,
            quote!(::mechanism::force::slider::reactions(&#pl.dir, &#load)),
        );
        let body = cx.body_of_guide(guide);
        if let Some(b) = &body {
            let r = cx.reference(b);
            let (pn, pr) = (cx.reads().pos(name), cx.reads().pos(&r));
            let w = quote!(::mechanism::force::Wrench::force_at(&(-(#rx.guide.force + #pl.dir * #rx.drive)), &#pn, &#pr).with_couple(-#rx.guide.moment));
            cx.add(b, w);
        }
        cx.reaction(prismatic(&rx, &body, link, name, "guide"));
        let rates = cx.reads().vel_rates();
        cx.power(quote!(#rx.drive * #rates.#input));
        let doc = format!("Driving force on `{link}` along its guide (input `{input}`; force units, positive along the guide's direction).");
        cx.reaction(drive(&rx, input, "drive", Held::Push, doc));
    }

    fn bodies_and_pairs(&self) -> (i64, i64, i64) {
        (1, 1, 0)
    }

    /// Its lane code in the batch kernel (`None`: an argument the kernel
    /// does not know; the batch then takes the scalar path).
    fn lane(&self, lane: &mut Lane, s: &mut Step<'_>) -> Option<()> {
        lane_steps(lane, s, self.guide, self.input, self.offset)
    }

    fn slide_field(&self, _slot: usize) -> TokenStream {
        quote!(s)
    }

    fn rate_system(&self) -> bool {
        false
    }

    fn link_lengths(&self) -> Vec<&'a Value> {
        Vec::new()
    }

    fn det_code(&self, _reads: &Reads) -> TokenStream {
        quote!(1.0)
    }

    moving_joint_facets!();
}

/// A slider on `guide` at the input displacement `in_INPUT[k]` (length
/// unit, along the guide's direction) plus `offset` across it:
/// `lane::slider`, `lane::slider_velocity` and `lane::slider_acceleration`
/// (the guide's motion folds away for a fixed guide). The block's link
/// turns with the guide's body. `None` when the guide is not known yet.
fn lane_steps(
    lane: &Lane,
    s: &mut Step,
    guide: &Ident,
    input: &Ident,
    offset: &Value,
) -> Option<()> {
    let gd = lane.guide(guide)?;
    let PointLocals {
        px,
        py,
        vx,
        vy,
        ax,
        ay,
    } = s.own.clone();
    let (line, gv, ga) = (&gd.line, &gd.gv, &gd.ga);
    let o = offset.emit();
    let input_s = Family::In.of(input);
    s.emit(quote! {
        let (#px, #py) = ::mechanism::__private::lane::slider(&#line, #o, #input_s[k]);
    });
    s.check([quote!(#input_s[k])]);
    let rate = Family::Rate.of(input);
    if lane.vel {
        s.emit(quote! {
            let (#vx, #vy) = ::mechanism::__private::lane::slider_velocity(&#line, #px, #py, #rate[k], #gv);
        });
        s.check([quote!(#rate[k])]);
    }
    if lane.acc {
        let accel = Family::Accel.of(input);
        s.emit(quote! {
            let (#ax, #ay) = ::mechanism::__private::lane::slider_acceleration(&#line, #px, #py, #rate[k], #accel[k], #gv, #ga);
        });
        s.check([quote!(#accel[k])]);
    }
    s.defines_link(
        0,
        LaneLink::along(
            Vector {
                x: quote!(#line.dx),
                y: quote!(#line.dy),
            },
            None,
            gd.omega.clone(),
            gd.alpha.clone(),
        ),
    )
}

impl super::run::RunKind for Slider<'_> {
    fn compile(&self, cx: &Compile<'_>) -> Box<dyn super::run::Step> {
        Box::new(SliderRun {
            me: cx.me(self.stmt),
            guide: cx.guide(self.guide),
            input: cx.input(self.input),
            input_name: super::run::intern(&self.input.to_string()),
            offset: cx.num(self.offset),
        })
    }
}

/// A slider, compiled: its guide, input and the block's offset (L).
struct SliderRun {
    me: Me,
    guide: GuideSlot,
    input: InputSlot,
    input_name: &'static str,
    offset: f64,
}

impl super::run::Step for SliderRun {
    fn group(&self) -> &'static str {
        self.me.group
    }

    fn walks(&self) -> super::run::Walks {
        super::run::Walks::ALL
    }

    fn position(&self, pose: &mut RunPose) -> Result<Option<f64>, mechanism_core::Error<f64>> {
        let g = pose.line(self.guide);
        let s = driver::slider::position(&g, self.offset, pose.input(self.input))?;
        pose.found(&self.me, s.p, &[g.dir]);
        pose.keep(&self.me, s);
        Ok(None)
    }

    fn rates(&self, cx: &mut RunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let g = cx
            .pose
            .kept::<driver::slider::SliderPosition<f64>>(&self.me)
            .ok_or_else(|| super::run::missing(mechanism_core::Primitive::Slider))?;
        let line = cx.pose.line(self.guide);
        let (s, rate) = (cx.value(self.input), cx.rate(self.input));
        let gvel = cx.guide_vel(self.guide);
        let pv = if cx.accel() {
            let gacc = cx.guide_acc(self.guide);
            let acc = cx.accel_of(self.input);
            driver::slider::acceleration(g, &line, s, rate, acc, gvel.as_ref(), gacc.as_ref())?
        } else {
            driver::slider::velocity(g, &line, s, rate, gvel.as_ref())?
        };
        cx.set_motion(&self.me, pv);
        Ok(())
    }

    /// `force::slider::reactions` on its block's load about its point; the
    /// guide's reaction and the drive onto the guide's carrier.
    fn forces(&self, cx: &mut ForceRunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let (me, guide) = (&self.me, self.guide);
        let link = me.links[0];
        let load = cx.load_about(link, me.point);
        let dir = cx.pose.line(guide).dir;
        let rx = mechanism_core::force::slider::reactions(&dir, &load)?;
        let body = cx.body_of_guide(guide);
        let push = rx.guide.force + dir * rx.drive;
        cx.react_on(body, push, cx.at(me.point), Some(rx.guide.moment));
        cx.prismatic(body, link, rx.guide);
        cx.power.push(rx.drive * cx.rate(self.input));
        cx.drive(self.input_name, Held::Push, rx.drive);
        Ok(())
    }

    fn link_dir(&self, _index: usize, pose: &RunPose) -> mechanism_core::Vector2<f64> {
        pose.line(self.guide).dir
    }
}
