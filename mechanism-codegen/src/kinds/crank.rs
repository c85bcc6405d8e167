//! `crank(PIVOT, r, INPUT) as LINK`: a link turning about a ground pivot by
//! the input angle (rad, counter-clockwise from +x); `crank(PIVOT, r, INPUT,
//! CARRIER) as LINK`: a motor between two links (an elbow, a knee), turning
//! about a point of the moving link `CARRIER` by the input angle measured
//! from the carrier's axis (rad, counter-clockwise), its driving torque the
//! relative one (acting on the link, reacting on the carrier).

use super::closure::{axis_between, f, Residuals};
use super::forces::{drive, revolute, rx, ForceCx, Held};
use super::group::{links_text, GroupKind, LinkShape, Placed, Role, Solve, Turn};
use super::lane::{Lane, LaneLink, PointLocals, Step, Vector};
use super::rates::{vec_ty, RateCx};
use super::reads::Reads;
use super::run::{Compile, ForceRunCx, InputSlot, LinkSlot, Me, PointSlot, RunCx, RunPose};
use super::tokens::{axis, grp, local, tag, unit_field, unit_vector};
use crate::diag::Diagnostics;
use crate::keys::{LinkName, PointName};
use crate::model::Stmt;
use crate::names::Family;
use crate::value::Value;
use mechanism_core::{driver, geometry, link};
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

/// How `crank` is written: its word, usage, arity and links.
pub(crate) const SPEC: super::word::Spec = super::word::Spec {
    word: super::word::KindWord::Crank,
    text: "crank",
    usage: "crank(PIVOT, radius, INPUT[, CARRIER[, zero_angle]]) as LINK",
    arity: super::word::Arity::Range(3, 5),
    links: "the crank, turning about its pivot",
    inputs: &[2],
    mode_at: None,
    mode_words: &[],
    group: Some("crank"),
};

/// A `crank` statement. `cos_sin`: its input is marked `as cos_sin`;
/// `carrier`: the moving link that carries its pivot and its motor (`None`:
/// the ground).
pub(super) struct Crank<'a> {
    pub stmt: &'a Stmt,
    pub pivot: &'a Ident,
    pub radius: &'a Value,
    pub input: &'a Ident,
    pub cos_sin: bool,
    pub carrier: Option<&'a Ident>,
    /// With a carrier: the angle (rad) in the carrier's frame from which the
    /// input is measured (0: its axis).
    pub zero: &'a Value,
}

impl Crank<'_> {
    /// The direction the input is measured from: the carrier's axis, turned
    /// by the zero angle when there is one (folded when literal).
    fn zero_axis(&self, carrier: &Ident) -> TokenStream {
        let ax = axis(carrier);
        if self.zero.fold() == Some(0.0) {
            quote!(#ax)
        } else {
            let u = unit_vector(self.zero);
            quote!(::mechanism::link::local_offset(&#ax, &#u))
        }
    }
}

impl<'a> GroupKind<'a> for Crank<'a> {
    fn references(&self) -> Vec<(&'a Ident, Role)> {
        let mut r = vec![(self.pivot, Role::Point)];
        r.extend(self.carrier.map(|c| (c, Role::Link)));
        r
    }

    fn link_shapes(&self) -> Vec<LinkShape> {
        vec![LinkShape::new(
            &[self.pivot, &self.stmt.name],
            Turn::Own,
            None,
        )]
    }

    fn point_owner(&self) -> Option<Option<LinkName>> {
        Some(Some(LinkName::of(&self.stmt.links[0])))
    }

    fn position_values(&self) -> Vec<Value> {
        vec![self.radius.clone(), self.zero.clone()]
    }

    fn position_type(&self) -> TokenStream {
        quote!(::mechanism::driver::crank::CrankPosition<T>)
    }

    fn position(&self, cos_sin: bool) -> Solve {
        let (r, pivot, input) = (self.radius.emit(), local(self.pivot), self.input);
        let call = match (self.cos_sin && cos_sin, self.carrier) {
            (true, None) => {
                quote!(::mechanism::driver::crank::position_cos_sin(&#pivot, #r, input_cs.#input.cos, input_cs.#input.sin))
            }
            (false, None) => {
                quote!(::mechanism::driver::crank::position(&#pivot, #r, input.#input))
            }
            (true, Some(l)) => {
                let ax = self.zero_axis(l);
                quote!(::mechanism::driver::crank::position_cos_sin_on(&#pivot, #r, &#ax, input_cs.#input.cos, input_cs.#input.sin))
            }
            (false, Some(l)) => {
                let ax = self.zero_axis(l);
                quote!(::mechanism::driver::crank::position_on(&#pivot, #r, &#ax, input.#input))
            }
        };
        Solve::Group {
            call,
            joint: Some("tip"),
        }
    }

    fn link_direction(&self, _index: usize) -> (TokenStream, TokenStream) {
        unit_field(self.stmt, "axis")
    }

    /// Its input, reduced to (-pi, pi] (no atan2), except in
    /// `position_cos_sin` for a crank marked `as cos_sin` and for a crank on
    /// a moving link (its input is relative: its angle is its axis's).
    fn link_angle(&self, cos_sin: bool) -> Option<TokenStream> {
        let input = self.input;
        (!(cos_sin && self.cos_sin) && self.carrier.is_none())
            .then(|| quote!(::mechanism::geometry::wrap_angle(input.#input)))
    }

    fn rates(&self, cx: &mut dyn RateCx) {
        let (stmt, pivot, input) = (self.stmt, self.pivot, self.input);
        let (g, pv, t) = (grp(stmt), cx.motion(stmt), tag(stmt));
        let w = cx.own(stmt, 0);
        let m = cx.point_arg(pivot);
        let carrier = self.carrier.and_then(|l| cx.link_rate(l).map(|w| (l, w)));
        let g = cx.reads().pos(&g);
        let code = match (cx.accel(), carrier) {
            (true, None) => quote! {
                let #pv = ::mechanism::driver::crank::acceleration(&#g, #m, rates.#input, accels.#input) #t;
                let #w = accels.#input;
            },
            (false, None) => quote! {
                let #pv = ::mechanism::driver::crank::velocity(&#g, #m, rates.#input) #t;
                let #w = rates.#input;
            },
            // On a turning carrier the link's rates are the carrier's plus
            // the input's (relative) ones.
            (true, Some((l, alpha_c))) => {
                let omega_c = cx.link_omega_in_accel(l);
                quote! {
                    let #w = #alpha_c + accels.#input;
                    let #pv = ::mechanism::driver::crank::acceleration(&#g, #m, #omega_c + rates.#input, #w) #t;
                }
            }
            (false, Some((_, omega_c))) => quote! {
                let #w = #omega_c + rates.#input;
                let #pv = ::mechanism::driver::crank::velocity(&#g, #m, #w) #t;
            },
        };
        cx.code(code);
        cx.field(pv, vec_ty());
        cx.field(w, quote!(T));
    }

    /// The tip at its radius from the pivot.
    fn residuals(&self, r: &mut Residuals<'_>, _link_axis: &dyn Fn(&Ident) -> TokenStream) {
        r.at_length("|tip - pivot| = radius", self.pivot, f(self.radius));
    }

    fn closure_axis(&self, _index: usize, reads: &Reads) -> TokenStream {
        axis_between(self.pivot, &self.stmt.name, reads)
    }

    fn link_lengths(&self) -> Vec<&'a Value> {
        vec![self.radius]
    }

    fn primitive(&self) -> &'static str {
        "Crank"
    }

    fn describe(&self) -> String {
        let (n, links, pivot, input) = (
            &self.stmt.name,
            links_text(self.stmt),
            self.pivot,
            self.input,
        );
        match self.carrier {
            None => format!("driver: crank `{links}` about `{pivot}`, input `{input}`, tip `{n}`"),
            Some(c) => format!("driver: crank `{links}` about `{pivot}` on `{c}`, input `{input}` (angle from `{c}`'s axis), tip `{n}`"),
        }
    }

    fn link_kind(&self, _index: usize) -> &'static str {
        "Crank"
    }

    fn input_is_angle(&self) -> bool {
        true
    }

    /// The crank's link: its angle is the input, its rates the input's
    /// (not on a moving carrier: the input is relative there).
    fn given_by_caller(&self, output: &Ident) -> bool {
        self.carrier.is_none() && self.stmt.links.first() == Some(output)
    }

    fn forces(&self, cx: &mut dyn ForceCx) {
        let (stmt, pivot, input) = (self.stmt, self.pivot, self.input);
        let (rx, link) = (rx(stmt), &stmt.links[0]);
        let load = cx.load_about(link, pivot);
        cx.solve(stmt, quote!(::mechanism::force::crank::reactions(&#load)));
        // The motor's reaction (force and torque) goes to the carrier, or to
        // the body the pivot is on.
        let body = match self.carrier {
            Some(c) => Some(LinkName::of(c)),
            None => cx.body_of_point(pivot),
        };
        if let Some(b) = &body {
            let r = cx.reference(b);
            let (pp, pr) = (cx.reads().pos(pivot), cx.reads().pos(&r));
            let w = quote!(::mechanism::force::Wrench::force_at(&(-#rx.pivot), &#pp, &#pr).with_couple(-#rx.torque));
            cx.add(b, w);
        }
        cx.reaction(revolute(&rx, &body, link, pivot, "pivot"));
        let rates = cx.reads().vel_rates();
        cx.power(quote!(#rx.torque * #rates.#input));
        let doc = format!("Driving torque on `{link}` (input `{input}`; force x length units, counter-clockwise positive): the balancing moment.");
        cx.reaction(drive(&rx, input, "torque", Held::Torque, doc));
    }

    fn bodies_and_pairs(&self) -> (i64, i64, i64) {
        (1, 1, 0)
    }

    /// It turns about a ground point, or about a point of its carrier.
    fn check_placed(&self, plan: &dyn Placed, errors: &mut Diagnostics) {
        let pivot = self.pivot;
        let p = PointName::of(pivot);
        match self.carrier {
            None if plan.is_defined(pivot) && !plan.is_ground_point(&p) => {
                let (r, input) = (self.radius.tokens.to_string(), self.input);
                let own = &self.stmt.links;
                let carriers = plan.links_with_point(&p);
                let link = carriers
                    .iter()
                    .find(|l| !own.iter().any(|o| **l == *o))
                    .map_or("LINK", LinkName::as_str);
                errors.push(
                    pivot.span(),
                    format!("a crank without a carrier turns about a ground point, and `{p}` moves; for a motor on the moving link that carries `{p}` (an elbow, a knee), name that link: `crank({p}, {r}, {input}, {link})`, the input then being the angle from `{link}`'s axis; or fix the pivot with `ground(x, y)`"),
                );
            }
            Some(link) => {
                let l = link.to_string();
                if let Some(points) = plan.link_points(link) {
                    if plan.is_defined(pivot) && !points.contains(&p) {
                        errors.push(
                            pivot.span(),
                            format!("a crank carried by `{l}` turns about one of its points, and `{p}` is not on it; its points: {}", points.iter().map(|p| format!("`{p}`")).collect::<Vec<_>>().join(", ")),
                        );
                    }
                }
            }
            None => {}
        }
    }

    fn reads_axis(&self) -> Option<&'a Ident> {
        self.carrier
    }

    /// Its lane code in the batch kernel (`None`: an argument the kernel
    /// does not know; the batch then takes the scalar path).
    fn lane(&self, lane: &mut Lane, s: &mut Step<'_>) -> Option<()> {
        if self.carrier.is_some() {
            return None;
        }
        let (th, rate, accel) = (
            Family::In.of(self.input),
            Family::Rate.of(self.input),
            Family::Accel.of(self.input),
        );
        let turn = LaneTurn {
            angle: quote!(#th[k]),
            rate: quote!(#rate[k]),
            accel: quote!(#accel[k]),
        };
        lane_steps(lane, s, self.pivot, self.radius, &turn)
    }

    fn slide_field(&self, _slot: usize) -> TokenStream {
        quote!(s)
    }

    fn rate_system(&self) -> bool {
        false
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
}

/// The angle a turned link's lane step reads, as expressions of element
/// `k` of the batch: the angle (rad, counter-clockwise from +x), its rate
/// (rad/s) and acceleration (rad/s^2). A crank's are its input's slices; a
/// gear's are linear in its cranks' inputs.
pub(super) struct LaneTurn {
    pub angle: TokenStream,
    pub rate: TokenStream,
    pub accel: TokenStream,
}

/// A link turned about `pivot` with its point at `radius` (length unit) at
/// the angle `turn.angle`: `lane::crank`, then the point's velocity and
/// acceleration with `lane::rel_vel` / `lane::rel_acc` from `turn`'s rate
/// and acceleration, which become the link's `w_LINK` / `al_LINK`. The
/// link's angle is `turn.angle` wrapped (`lane::wrap_angle`). `None` when
/// the pivot is not known yet.
pub(super) fn lane_steps(
    lane: &Lane,
    s: &mut Step,
    pivot: &Ident,
    radius: &Value,
    turn: &LaneTurn,
) -> Option<()> {
    let p = lane.point(pivot)?;
    let PointLocals {
        px,
        py,
        vx,
        vy,
        ax,
        ay,
    } = s.own.clone();
    let g = s.g.clone();
    let (ppx, ppy) = (&p.px, &p.py);
    let r = radius.emit();
    let th = &turn.angle;
    let rates = s.rates(0)?;
    let (omega, alpha) = (&rates.omega, &rates.alpha);
    s.emit(quote! {
        let #g = ::mechanism::__private::lane::crank(#ppx, #ppy, #r, #th);
        ok &= #g.ok;
        let #px = #g.x; let #py = #g.y;
    });
    if lane.vel {
        let rate = &turn.rate;
        let (pvx, pvy) = (&p.vx, &p.vy);
        s.emit(quote! {
            let #omega = #rate;
            let (tx, ty) = ::mechanism::__private::lane::rel_vel(#g.rx, #g.ry, #omega);
            let #vx = #pvx + tx; let #vy = #pvy + ty;
        });
        s.check([quote!(#omega)]);
    }
    if lane.acc {
        let accel = &turn.accel;
        let (pax, pay) = (&p.ax, &p.ay);
        s.emit(quote! {
            let #alpha = #accel;
            let (tx, ty) = ::mechanism::__private::lane::rel_acc(#g.rx, #g.ry, #omega, #alpha);
            let #ax = #pax + tx; let #ay = #pay + ty;
        });
        s.check([quote!(#alpha)]);
    }
    s.defines_link(
        0,
        LaneLink {
            axis: Vector {
                x: quote!(#g.ux),
                y: quote!(#g.uy),
            },
            angle: quote!(::mechanism::__private::lane::wrap_angle(#th)),
            omega: quote!(#omega),
            alpha: quote!(#alpha),
        },
    )
}

impl super::run::RunKind for Crank<'_> {
    fn compile(&self, cx: &Compile<'_>) -> Box<dyn super::run::Step> {
        Box::new(CrankRun {
            me: cx.me(self.stmt),
            pivot: cx.point(self.pivot),
            radius: cx.num(self.radius),
            input: cx.input(self.input),
            input_name: super::run::intern(&self.input.to_string()),
            carrier: self.carrier.map(|l| cx.link(l)),
            zero: geometry::unit(cx.num(self.zero)),
        })
    }
}

/// A crank, compiled: its pivot, radius (L), input, carrier and the unit
/// direction its input is measured from in the carrier's frame.
struct CrankRun {
    me: Me,
    pivot: PointSlot,
    radius: f64,
    input: InputSlot,
    input_name: &'static str,
    carrier: Option<LinkSlot>,
    zero: mechanism_core::Vector2<f64>,
}

impl super::run::Step for CrankRun {
    fn group(&self) -> &'static str {
        self.me.group
    }

    fn walks(&self) -> super::run::Walks {
        super::run::Walks::ALL
    }

    fn position(&self, pose: &mut RunPose) -> Result<Option<f64>, mechanism_core::Error<f64>> {
        let pivot = pose.point(self.pivot);
        let (r, q) = (self.radius, pose.input(self.input));
        let c = match self.carrier {
            None => driver::crank::position(&pivot, r, q)?,
            Some(l) => {
                let axis = link::local_offset(&pose.axis(l), &self.zero);
                driver::crank::position_on(&pivot, r, &axis, q)?
            }
        };
        pose.found(&self.me, c.tip, &[c.axis]);
        pose.keep(&self.me, c);
        Ok(None)
    }

    fn rates(&self, cx: &mut RunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let g = cx
            .pose
            .kept::<driver::crank::CrankPosition<f64>>(&self.me)
            .ok_or_else(|| super::run::missing(mechanism_core::Primitive::Crank))?;
        let m = cx.point_arg(self.pivot);
        let (rate, acc) = (cx.rate(self.input), cx.accel_of(self.input));
        let carrier = self.carrier.and_then(|l| cx.link_rate(l).map(|w| (l, w)));
        let (pv, w) = match (cx.accel(), carrier) {
            (true, None) => (driver::crank::acceleration(g, m.as_ref(), rate, acc)?, acc),
            (false, None) => (driver::crank::velocity(g, m.as_ref(), rate)?, rate),
            (true, Some((l, alpha_c))) => {
                let omega_c = cx.link_omega_in_accel(l).unwrap_or(f64::NAN);
                let w = alpha_c + acc;
                (
                    driver::crank::acceleration(g, m.as_ref(), omega_c + rate, w)?,
                    w,
                )
            }
            (false, Some((_, omega_c))) => {
                let w = omega_c + rate;
                (driver::crank::velocity(g, m.as_ref(), w)?, w)
            }
        };
        cx.set_motion(&self.me, pv);
        cx.set_own(&self.me, 0, w);
        Ok(())
    }

    /// `force::crank::reactions` on its link's load about the pivot; the
    /// motor's reaction (pivot force and torque) onto the carrier or the
    /// pivot's body.
    fn forces(&self, cx: &mut ForceRunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let (pivot, link) = (self.pivot, self.me.links[0]);
        let load = cx.load_about(link, pivot);
        let rx = mechanism_core::force::crank::reactions(&load)?;
        let body = self.carrier.or_else(|| cx.body_of_point(pivot));
        cx.react_on(body, rx.pivot, cx.at(pivot), Some(rx.torque));
        cx.revolute(body, link, rx.pivot);
        cx.power.push(rx.torque * cx.rate(self.input));
        cx.drive(self.input_name, Held::Torque, rx.torque);
        Ok(())
    }

    fn link_dir(&self, _index: usize, pose: &RunPose) -> mechanism_core::Vector2<f64> {
        pose.kept::<driver::crank::CrankPosition<f64>>(&self.me)
            .map_or(mechanism_core::Vector2::new(f64::NAN, f64::NAN), |c| c.axis)
    }

    fn link_angle(&self, pose: &RunPose) -> Option<f64> {
        self.carrier
            .is_none()
            .then(|| geometry::wrap_angle(pose.input(self.input)))
    }
}
