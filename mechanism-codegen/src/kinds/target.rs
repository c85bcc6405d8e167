//! `target(X, Y) as EFFECTOR`: a point placed by two inputs, its
//! coordinates (length units, global frame). It is how inverse kinematics
//! is written: the groups hanging on the point solve the motors' links from
//! it. The effector is a body of its own that moves with the point and
//! does not turn; its driving effort is the force (and couple) a positioner
//! must apply to it, `drive_X` and `drive_Y` its components.

use super::forces::{body_name, rx, ForceCx, Held, Reaction};
use super::group::{links_text, GroupKind, LinkShape, Role, Solve, Turn};
use super::lane::{Lane, LaneLink, PointLocals, Step, Vector};
use super::rates::{vec_ty, RateCx};
use super::reads::Reads;
use super::run::{Compile, ForceRunCx, InputSlot, Me, RunCx, RunPose};
use super::tokens::tag;
use crate::keys::LinkName;
use crate::model::Stmt;
use crate::names::Family;
use crate::value::Value;
use mechanism_core::driver;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::Ident;

/// How `target` is written: its word, usage, arity and links.
pub(crate) const SPEC: super::word::Spec = super::word::Spec {
    word: super::word::KindWord::Target,
    text: "target",
    usage: "target(X_INPUT, Y_INPUT) as EFFECTOR",
    arity: super::word::Arity::Range(2, 2),
    links: "the effector, moving with the point and not turning",
    inputs: &[0, 1],
    mode_at: None,
    mode_words: &[],
    group: Some("target"),
};

/// A `target` statement.
pub(super) struct Target<'a> {
    pub stmt: &'a Stmt,
    pub x: &'a Ident,
    pub y: &'a Ident,
}

impl<'a> GroupKind<'a> for Target<'a> {
    fn references(&self) -> Vec<(&'a Ident, Role)> {
        vec![]
    }

    fn link_shapes(&self) -> Vec<LinkShape> {
        vec![LinkShape::new(&[&self.stmt.name], Turn::None, None)]
    }

    fn point_owner(&self) -> Option<Option<LinkName>> {
        Some(Some(LinkName::of(&self.stmt.links[0])))
    }

    fn position_values(&self) -> Vec<Value> {
        Vec::new()
    }

    fn position(&self, _cos_sin: bool) -> Solve {
        let (x, y, t) = (self.x, self.y, tag(self.stmt));
        Solve::Own {
            expr: quote!(::mechanism::driver::target::position(input.#x, input.#y) #t),
            ty: quote!(::mechanism::Point2<T>),
        }
    }

    fn rates(&self, cx: &mut dyn RateCx) {
        let (x, y, t) = (self.x, self.y, tag(self.stmt));
        let pv = cx.motion(self.stmt);
        cx.code(if cx.accel() {
            quote!(let #pv = ::mechanism::driver::target::acceleration(accels.#x, accels.#y) #t;)
        } else {
            quote!(let #pv = ::mechanism::driver::target::velocity(rates.#x, rates.#y) #t;)
        });
        cx.field(pv, vec_ty());
    }

    /// The point at its two inputs.
    fn residuals(
        &self,
        r: &mut super::closure::Residuals<'_>,
        _link_axis: &dyn Fn(&Ident) -> TokenStream,
    ) {
        let (n, inputs, x, y) = (r.pos(r.n), r.reads.pos_input(), self.x, self.y);
        r.push(
            "x at its input",
            quote!(<T as ::mechanism::Real>::as_f64(#n.x) - <T as ::mechanism::Real>::as_f64(#inputs.#x)),
        );
        r.push(
            "y at its input",
            quote!(<T as ::mechanism::Real>::as_f64(#n.y) - <T as ::mechanism::Real>::as_f64(#inputs.#y)),
        );
    }

    fn primitive(&self) -> &'static str {
        "Target"
    }

    fn describe(&self) -> String {
        let (n, links, x, y) = (&self.stmt.name, links_text(self.stmt), self.x, self.y);
        format!("driver: target `{n}` at inputs (`{x}`, `{y}`), effector `{links}`")
    }

    fn link_kind(&self, _index: usize) -> &'static str {
        "Block"
    }

    fn forces(&self, cx: &mut dyn ForceCx) {
        let (stmt, x, y) = (self.stmt, self.x, self.y);
        let (rx, link, name) = (rx(stmt), &stmt.links[0], &stmt.name);
        let load = cx.load_about(link, name);
        cx.solve(stmt, quote!(::mechanism::force::target::reactions(&#load)));
        let rates = cx.reads().vel_rates();
        cx.power(quote!(#rx.drive.x * #rates.#x + #rx.drive.y * #rates.#y));
        for (input, axis) in [(x, "x"), (y, "y")] {
            let a = format_ident!("{}", axis);
            cx.reaction(Reaction {
                name: Family::Drive.of(input),
                ty: quote!(T),
                value: quote!(#rx.drive.#a),
                doc: format!("Driving force on `{link}` along +{axis} (input `{input}`; force units): the {axis} component of the force a positioner applies at `{name}` to hold it on its path."),
                held: Held::Push,
            });
        }
        let ground = body_name(&None);
        cx.reaction(Reaction {
            name: Family::Mount.pair(ground, link),
            ty: quote!(T),
            value: quote!(#rx.couple),
            doc: format!("Couple of the positioner on `{link}` (force x length units, counter-clockwise positive): zero unless loads act on `{link}` away from `{name}`."),
            held: Held::Torque,
        });
    }

    /// A carriage and the effector, on two sliding pairs: two freedoms.
    fn bodies_and_pairs(&self) -> (i64, i64, i64) {
        (2, 2, 0)
    }

    /// The point is its inputs `in_X[k]`, `in_Y[k]`; its motion their
    /// rates and accelerations; the effector never turns (axis +x).
    fn lane(&self, lane: &mut Lane, s: &mut Step<'_>) -> Option<()> {
        let PointLocals {
            px,
            py,
            vx,
            vy,
            ax,
            ay,
        } = s.own.clone();
        let at = |family: Family| {
            let (x, y) = (family.of(self.x), family.of(self.y));
            (quote!(#x[k]), quote!(#y[k]))
        };
        let (x, y) = at(Family::In);
        s.emit(quote!(let #px = #x; let #py = #y;));
        s.check([x, y]);
        if lane.vel {
            let (x, y) = at(Family::Rate);
            s.emit(quote!(let #vx = #x; let #vy = #y;));
            s.check([x, y]);
        }
        if lane.acc {
            let (x, y) = at(Family::Accel);
            s.emit(quote!(let #ax = #x; let #ay = #y;));
            s.check([x, y]);
        }
        s.defines_link(
            0,
            LaneLink {
                axis: Vector {
                    x: quote!(<T as ::mechanism::Real>::lit(1.0)),
                    y: quote!(zero),
                },
                angle: quote!(zero),
                omega: quote!(zero),
                alpha: quote!(zero),
            },
        )
    }

    fn position_type(&self) -> TokenStream {
        quote!(())
    }

    fn link_direction(&self, _index: usize) -> (TokenStream, TokenStream) {
        (
            quote!(::mechanism::Vector2::x()),
            quote!(::mechanism::Vector2::x()),
        )
    }

    fn slide_field(&self, _slot: usize) -> TokenStream {
        quote!(s)
    }

    fn rate_system(&self) -> bool {
        false
    }

    fn closure_axis(&self, _index: usize, _reads: &Reads) -> TokenStream {
        quote!([1.0, 0.0])
    }

    fn link_lengths(&self) -> Vec<&'a Value> {
        Vec::new()
    }

    fn det_code(&self, _reads: &Reads) -> TokenStream {
        quote!(1.0)
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

impl super::run::RunKind for Target<'_> {
    fn compile(&self, cx: &Compile<'_>) -> Box<dyn super::run::Step> {
        Box::new(TargetRun {
            me: cx.me(self.stmt),
            x: cx.input(self.x),
            y: cx.input(self.y),
            names: [
                super::run::intern(&self.x.to_string()),
                super::run::intern(&self.y.to_string()),
            ],
        })
    }
}

/// A target, compiled: its two inputs (L) and their names.
struct TargetRun {
    me: Me,
    x: InputSlot,
    y: InputSlot,
    names: [&'static str; 2],
}

impl super::run::Step for TargetRun {
    fn group(&self) -> &'static str {
        self.me.group
    }

    fn walks(&self) -> super::run::Walks {
        super::run::Walks::ALL
    }

    fn position(&self, pose: &mut RunPose) -> Result<Option<f64>, mechanism_core::Error<f64>> {
        let p = driver::target::position(pose.input(self.x), pose.input(self.y))?;
        pose.found(&self.me, p, &[mechanism_core::Vector2::x()]);
        Ok(None)
    }

    fn rates(&self, cx: &mut RunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let v = if cx.accel() {
            driver::target::acceleration(cx.accel_of(self.x), cx.accel_of(self.y))?
        } else {
            driver::target::velocity(cx.rate(self.x), cx.rate(self.y))?
        };
        cx.set_motion(&self.me, v);
        Ok(())
    }

    /// `force::target::reactions` on the effector's load about its point:
    /// the positioner's force components and couple.
    fn forces(&self, cx: &mut ForceRunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let link = self.me.links[0];
        let load = cx.load_about(link, self.me.point);
        let rx = mechanism_core::force::target::reactions(&load)?;
        cx.power
            .push(rx.drive.x * cx.rate(self.x) + rx.drive.y * cx.rate(self.y));
        cx.drive(self.names[0], Held::Push, rx.drive.x);
        cx.drive(self.names[1], Held::Push, rx.drive.y);
        let ground = body_name(&None);
        cx.scalar(
            |l| Family::Mount.pair_text(ground, l.link_name(Some(link))),
            Held::Torque,
            rx.couple,
        );
        Ok(())
    }

    fn link_dir(&self, _index: usize, _pose: &RunPose) -> mechanism_core::Vector2<f64> {
        mechanism_core::Vector2::x()
    }
}
