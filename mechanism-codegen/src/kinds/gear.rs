//! `gear(PIVOT, r, MESH, ratio[, phase[, CARRIER[, pressure_angle]]]) as
//! LINK`: a link turning about `PIVOT` on the common link `CARRIER` (the
//! ground when left out), geared to the link `MESH` (or to a fixed gear,
//! `ground`). Measured from the carrier, its angle is
//!
//! ```text
//! theta = phase - ratio * theta_mesh
//! ```
//!
//! (rad, counter-clockwise): `ratio` is the pitch radius of `MESH`'s gear
//! over this one's, positive for external gears (they turn opposite ways),
//! negative for an internal pair (the same way). `MESH` and `CARRIER` are
//! each the ground or a crank's link on the ground, whose angle is that
//! crank's input (over whole turns), so the absolute angle is linear in the
//! inputs, `theta = phase - ratio q_mesh + (1 + ratio) q_carrier`, and so
//! are its rates. The statement defines the point at `r` from the pivot
//! along the link's axis, which turns at `theta`: the crank primitive's
//! position, velocity and acceleration at that angle.
//!
//! Forces (`mechanism::force::gear`): the tooth force along the line of
//! action at the pressure angle (20 deg when left out) holds the link's
//! load; it reacts on `MESH` at the pitch point, the pivot force on the
//! carrier.

use super::closure::{axis_between, f, Residuals};
use super::crank::{lane_steps, LaneTurn};
use super::forces::{body_name, revolute, rx, ForceCx, Held, Reaction};
use super::group::{links_text, GroupKind, LinkShape, Placed, Role, Solve, Turn};
use super::lane::{Lane, Step};
use super::rates::{vec_ty, RateCx};
use super::reads::Reads;
use super::run::{Compile, ForceRunCx, InputSlot, LinkSlot, Me, PointSlot, RunCx, RunPose};
use super::tokens::{grp, local, tag, unit_field};
use crate::diag::Diagnostics;
use crate::keys::GROUND;
use crate::keys::{LinkName, PointName};
use crate::model::{Gear, Stmt};
use crate::names::Family;
use crate::value::Value;
use mechanism_core::{driver, geometry};
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

/// How `gear` is written: its word, usage, arity and links.
pub(crate) const SPEC: super::word::Spec = super::word::Spec {
    word: super::word::KindWord::Gear,
    text: "gear",
    usage: "gear(PIVOT, radius, MESH, ratio[, phase[, CARRIER[, pressure_angle]]]) as LINK",
    arity: super::word::Arity::Range(4, 7),
    links: "the gear's link, turning about its pivot",
    inputs: &[],
    mode_at: None,
    mode_words: &[],
    group: Some("gear"),
};

/// A `gear` statement.
pub(super) struct GearKind<'a> {
    pub stmt: &'a Stmt,
    pub g: &'a Gear,
}

/// The inputs a gear's angle reads and their factors: the meshing link's
/// crank's input times `-ratio`, the carrier's crank's input times
/// `1 + ratio`.
struct Terms<'a> {
    mesh: Option<&'a Ident>,
    carrier: Option<&'a Ident>,
}

impl<'a> GearKind<'a> {
    fn terms(&self) -> Terms<'a> {
        Terms {
            mesh: self.g.mesh_crank.as_ref().map(|c| &c.input),
            carrier: self.g.carrier_crank.as_ref().map(|c| &c.input),
        }
    }

    /// `1 + ratio` (folded when literal).
    fn one_plus_ratio(&self) -> TokenStream {
        match self.g.ratio.fold() {
            Some(r) => Value::lit(1.0 + r, self.g.ratio.span).emit(),
            None => {
                let r = self.g.ratio.emit();
                quote!((<T as ::mechanism::Real>::lit(1.0) + #r))
            }
        }
    }

    /// Its angle (rad, from +x) or a rate of it (`phase` false: the rates,
    /// whose phase term is 0), from the expressions `input` gives for its
    /// cranks' inputs (their values, rates or accelerations: a field of the
    /// input structs, or an element of a batch's slices).
    fn angle_code(&self, input: impl Fn(&Ident) -> TokenStream, phase: bool) -> TokenStream {
        let t = self.terms();
        let ratio = self.g.ratio.emit();
        let mut sum = if phase {
            let p = self.g.phase.emit();
            quote!(#p)
        } else {
            quote!(<T as ::mechanism::Real>::lit(0.0))
        };
        if let Some(q) = t.mesh {
            let q = input(q);
            sum = quote!(#sum - #ratio * #q);
        }
        if let Some(q) = t.carrier {
            let (q, k) = (input(q), self.one_plus_ratio());
            sum = quote!(#sum + #k * #q);
        }
        sum
    }

    /// [`Self::angle_code`] from the fields of the input struct `src`
    /// (`input`, `rates`, `accels`).
    fn angle_of(&self, src: TokenStream, phase: bool) -> TokenStream {
        self.angle_code(|q| quote!(#src.#q), phase)
    }

    /// [`Self::angle_code`] in a batch's lane step: element `k` of the
    /// inputs' slices of `family` (values, rates or accelerations).
    fn lane_angle(&self, family: Family, phase: bool) -> TokenStream {
        self.angle_code(
            |q| {
                let q = family.of(q);
                quote!(#q[k])
            },
            phase,
        )
    }

    /// The center of the meshing gear: its crank's pivot, or for a fixed
    /// gear (`MESH` the ground) the carrier's crank's pivot.
    fn mesh_center(&self) -> Option<&'a Ident> {
        let g = self.g;
        g.mesh_crank
            .as_ref()
            .or(g.carrier_crank.as_ref())
            .map(|c| &c.pivot)
    }
}

impl<'a> GroupKind<'a> for GearKind<'a> {
    fn references(&self) -> Vec<(&'a Ident, Role)> {
        let g = self.g;
        let mut r = vec![(&g.pivot, Role::Point)];
        r.extend(g.mesh.iter().map(|m| (m, Role::Link)));
        r.extend(g.carrier.iter().map(|c| (c, Role::Link)));
        r
    }

    fn link_shapes(&self) -> Vec<LinkShape> {
        vec![LinkShape::new(
            &[&self.g.pivot, &self.stmt.name],
            Turn::Own,
            None,
        )]
    }

    fn point_owner(&self) -> Option<Option<LinkName>> {
        Some(Some(LinkName::of(&self.stmt.links[0])))
    }

    fn position_values(&self) -> Vec<Value> {
        let g = self.g;
        vec![g.radius.clone(), g.ratio.clone(), g.phase.clone()]
    }

    fn position_type(&self) -> TokenStream {
        quote!(::mechanism::driver::crank::CrankPosition<T>)
    }

    fn position(&self, _cos_sin: bool) -> Solve {
        let (r, pivot) = (self.g.radius.emit(), local(&self.g.pivot));
        let theta = self.angle_of(quote!(input), true);
        Solve::Group {
            call: quote!(::mechanism::driver::crank::position(&#pivot, #r, #theta)),
            joint: Some("tip"),
        }
    }

    fn link_direction(&self, _index: usize) -> (TokenStream, TokenStream) {
        unit_field(self.stmt, "axis")
    }

    fn slide_field(&self, _slot: usize) -> TokenStream {
        quote!(s)
    }

    /// Its angle from the inputs, reduced to (-pi, pi] (no atan2).
    fn link_angle(&self, _cos_sin: bool) -> Option<TokenStream> {
        let theta = self.angle_of(quote!(input), true);
        Some(quote!(::mechanism::geometry::wrap_angle(#theta)))
    }

    fn rates(&self, cx: &mut dyn RateCx) {
        let stmt = self.stmt;
        let (g, pv, t) = (grp(stmt), cx.motion(stmt), tag(stmt));
        let w = cx.own(stmt, 0);
        let m = cx.point_arg(&self.g.pivot);
        let omega = self.angle_of(quote!(rates), false);
        let g = cx.reads().pos(&g);
        let code = if cx.accel() {
            let alpha = self.angle_of(quote!(accels), false);
            quote! {
                let #w = #alpha;
                let #pv = ::mechanism::driver::crank::acceleration(&#g, #m, #omega, #w) #t;
            }
        } else {
            quote! {
                let #w = #omega;
                let #pv = ::mechanism::driver::crank::velocity(&#g, #m, #w) #t;
            }
        };
        cx.code(code);
        cx.field(pv, vec_ty());
        cx.field(w, quote!(T));
    }

    fn rate_system(&self) -> bool {
        false
    }

    /// The point at its radius from the pivot.
    fn residuals(&self, r: &mut Residuals<'_>, _link_axis: &dyn Fn(&Ident) -> TokenStream) {
        r.at_length("|tip - pivot| = radius", &self.g.pivot, f(&self.g.radius));
    }

    fn closure_axis(&self, _index: usize, reads: &Reads) -> TokenStream {
        axis_between(&self.g.pivot, &self.stmt.name, reads)
    }

    fn link_lengths(&self) -> Vec<&'a Value> {
        vec![&self.g.radius]
    }

    /// The crank's lane step at the gear's angle, its rate and
    /// acceleration, each linear in its cranks' inputs at element `k`.
    fn lane(&self, lane: &mut Lane, s: &mut Step<'_>) -> Option<()> {
        let turn = LaneTurn {
            angle: self.lane_angle(Family::In, true),
            rate: self.lane_angle(Family::Rate, false),
            accel: self.lane_angle(Family::Accel, false),
        };
        lane_steps(lane, s, &self.g.pivot, &self.g.radius, &turn)
    }

    fn primitive(&self) -> &'static str {
        "Crank"
    }

    fn det_code(&self, _reads: &Reads) -> TokenStream {
        quote!(1.0)
    }

    fn describe(&self) -> String {
        let g = self.g;
        let (n, links, pivot) = (&self.stmt.name, links_text(self.stmt), &g.pivot);
        let mesh = g.mesh.as_ref().map_or(GROUND.into(), ToString::to_string);
        let on = g
            .carrier
            .as_ref()
            .map_or(GROUND.into(), ToString::to_string);
        let ratio = g.ratio.tokens.to_string();
        format!("gear: `{links}` about `{pivot}` on `{on}`, geared to `{mesh}` at ratio {ratio}, point `{n}`")
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

    fn link_kind(&self, _index: usize) -> &'static str {
        "Crank"
    }

    fn input_is_angle(&self) -> bool {
        false
    }

    /// One link, its pivot (a lower pair) and the mesh (a higher pair).
    fn bodies_and_pairs(&self) -> (i64, i64, i64) {
        (1, 1, 1)
    }

    /// It turns about a ground point, or a point of its carrier.
    fn check_placed(&self, plan: &dyn Placed, errors: &mut Diagnostics) {
        let pivot = &self.g.pivot;
        let p = PointName::of(pivot);
        if !plan.is_defined(pivot) {
            return;
        }
        match &self.g.carrier {
            None if !plan.is_ground_point(&p) => errors.push(
                pivot.span(),
                format!("a gear on the ground turns about a ground point, and `{p}` moves; fix the pivot with `ground(x, y)`, or carry the gear on the crank's link that holds `{p}` (its sixth argument)"),
            ),
            Some(link) => {
                if let Some(points) = plan.link_points(link) {
                    if !points.contains(&p) {
                        errors.push(
                            pivot.span(),
                            format!("a gear carried by `{link}` turns about one of its points, and `{p}` is not on it; its points: {}", points.iter().map(|p| format!("`{p}`")).collect::<Vec<_>>().join(", ")),
                        );
                    }
                }
            }
            None => {}
        }
    }

    fn forces(&self, cx: &mut dyn ForceCx) {
        let (stmt, g) = (self.stmt, self.g);
        let Some(center) = self.mesh_center() else {
            return;
        };
        let (rx, link, pivot) = (rx(stmt), &stmt.links[0], &g.pivot);
        let load = cx.load_about(link, pivot);
        let (ratio, pressure) = (g.ratio.emit(), g.pressure.emit());
        let (pp, pc) = (cx.reads().pos(pivot), cx.reads().pos(center));
        cx.solve(
            stmt,
            quote!(::mechanism::force::gear::reactions(&#load, &#pp, &#pc, #ratio, #pressure)),
        );
        // The pivot force reacts on the carrier (or the body the pivot is
        // on), the tooth force on the meshing link at the pitch point.
        let body = match &g.carrier {
            Some(c) => Some(LinkName::of(c)),
            None => cx.body_of_point(pivot),
        };
        if let Some(b) = &body {
            let r = cx.reads().pos(&cx.reference(b));
            cx.add(
                b,
                quote!(::mechanism::force::Wrench::force_at(&(-#rx.pivot), &#pp, &#r)),
            );
        }
        if let Some(m) = &g.mesh {
            let m = LinkName::of(m);
            let r = cx.reads().pos(&cx.reference(&m));
            cx.add(
                &m,
                quote!(::mechanism::force::Wrench::force_at(&(-#rx.tooth), &#rx.contact, &#r)),
            );
        }
        cx.reaction(revolute(&rx, &body, link, pivot, "pivot"));
        let from = body_name(&g.mesh.as_ref().map(LinkName::of));
        cx.reaction(Reaction {
            name: Family::Reaction.pair(&from, link),
            ty: quote!(::mechanism::Vector2<T>),
            value: quote!(#rx.tooth),
            doc: format!("Tooth force of `{from}`'s gear on `{link}` at the pitch point, along the line of action (force units, global frame)."),
            held: Held::Force,
        });
    }
}

impl super::run::RunKind for GearKind<'_> {
    fn compile(&self, cx: &Compile<'_>) -> Box<dyn super::run::Step> {
        let (g, t) = (self.g, self.terms());
        Box::new(GearRun {
            me: cx.me(self.stmt),
            pivot: cx.point(&g.pivot),
            radius: cx.num(&g.radius),
            ratio: cx.num(&g.ratio),
            phase: cx.num(&g.phase),
            pressure: cx.num(&g.pressure),
            mesh_input: t.mesh.map(|q| cx.input(q)),
            carrier_input: t.carrier.map(|q| cx.input(q)),
            center: self.mesh_center().map(|c| cx.point(c)),
            carrier: g.carrier.as_ref().map(|c| cx.link(c)),
            mesh: g.mesh.as_ref().map(|m| cx.link(m)),
        })
    }
}

/// A gear, compiled: its pivot, radius (L), ratio, phase and pressure
/// angle (rad), the inputs its angle reads, the meshing gear's center, its
/// carrier and the meshing link.
struct GearRun {
    me: Me,
    pivot: PointSlot,
    radius: f64,
    ratio: f64,
    phase: f64,
    pressure: f64,
    mesh_input: Option<InputSlot>,
    carrier_input: Option<InputSlot>,
    center: Option<PointSlot>,
    carrier: Option<LinkSlot>,
    mesh: Option<LinkSlot>,
}

impl GearRun {
    /// Its angle (rad) or a rate of it (`phase` false) from the inputs'
    /// values or rates `value`, as `GearKind::angle_f64`.
    fn angle(&self, value: &dyn Fn(InputSlot) -> f64, phase: bool) -> f64 {
        let mut sum = if phase { self.phase } else { 0.0 };
        if let Some(q) = self.mesh_input {
            sum -= self.ratio * value(q);
        }
        if let Some(q) = self.carrier_input {
            sum += (1.0 + self.ratio) * value(q);
        }
        sum
    }
}

impl super::run::Step for GearRun {
    fn group(&self) -> &'static str {
        self.me.group
    }

    fn walks(&self) -> super::run::Walks {
        super::run::Walks::ALL
    }

    fn position(&self, pose: &mut RunPose) -> Result<Option<f64>, mechanism_core::Error<f64>> {
        let pivot = pose.point(self.pivot);
        let theta = self.angle(&|q| pose.input(q), true);
        let c = driver::crank::position(&pivot, self.radius, theta)?;
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
        let omega = self.angle(&|q| cx.rate(q), false);
        let (pv, w) = if cx.accel() {
            let alpha = self.angle(&|q| cx.accel_of(q), false);
            (
                driver::crank::acceleration(g, m.as_ref(), omega, alpha)?,
                alpha,
            )
        } else {
            (driver::crank::velocity(g, m.as_ref(), omega)?, omega)
        };
        cx.set_motion(&self.me, pv);
        cx.set_own(&self.me, 0, w);
        Ok(())
    }

    /// What its `forces` emits, computed: the same call on the same loads.
    fn forces(&self, cx: &mut ForceRunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let Some(center) = self.center else {
            return Ok(());
        };
        let (link, pivot) = (self.me.links[0], self.pivot);
        let load = cx.load_about(link, pivot);
        let rx = mechanism_core::force::gear::reactions(
            &load,
            &cx.at(pivot),
            &cx.at(center),
            self.ratio,
            self.pressure,
        )?;
        let body = self.carrier.or_else(|| cx.body_of_point(pivot));
        cx.react_on(body, rx.pivot, cx.at(pivot), None);
        cx.react_on(self.mesh, rx.tooth, rx.contact, None);
        cx.revolute(body, link, rx.pivot);
        cx.revolute(self.mesh, link, rx.tooth);
        Ok(())
    }

    fn link_dir(&self, _index: usize, pose: &RunPose) -> mechanism_core::Vector2<f64> {
        pose.kept::<driver::crank::CrankPosition<f64>>(&self.me)
            .map_or(mechanism_core::Vector2::new(f64::NAN, f64::NAN), |c| c.axis)
    }

    fn link_angle(&self, pose: &RunPose) -> Option<f64> {
        Some(geometry::wrap_angle(self.angle(&|q| pose.input(q), true)))
    }
}
