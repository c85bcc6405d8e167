//! `point(LINK, from P, d, angle)` and `point(LINK, from P, (x, y))`: a point
//! fixed on a link, given in the link's frame.

use super::closure::{f, Residuals};
use super::group::{GroupKind, Placed, Role, Solve};
use super::lane::{Lane, PointLocals, Step, Vector};
use super::lane_shapes::local_vector;
use super::rates::{vec_ty, RateCx};
use super::run::{Compile, ForceRunCx, LinkSlot, Me, PointSlot, RunCx, RunPose};
use super::tokens::{axis, local, tag, unit_vector};
use crate::diag::Diagnostics;
use crate::keys::{LinkName, PointName};
use crate::model::{Local, Stmt};
use crate::names::Family;
use crate::value::{lit, Value};
use mechanism_core::{geometry, link, Vector2};
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

/// How `point` is written: its word, usage, arity and links.
pub(crate) const SPEC: super::word::Spec = super::word::Spec {
    word: super::word::KindWord::Point,
    text: "point",
    usage: "point(LINK, from POINT, distance, angle) or point(LINK, from POINT, (x, y))",
    arity: super::word::Arity::TupleAt {
        index: 2,
        tuple: (3, 3),
        other: (4, 4),
    },
    links: "",
    inputs: &[],
    mode_at: None,
    mode_words: &[],
    group: Some("link point"),
};

/// A `point` statement.
pub(super) struct Point<'a> {
    pub stmt: &'a Stmt,
    pub link: &'a Ident,
    pub from: &'a Ident,
    pub local: &'a Local,
}

impl<'a> GroupKind<'a> for Point<'a> {
    fn references(&self) -> Vec<(&'a Ident, Role)> {
        vec![(self.link, Role::Link), (self.from, Role::Point)]
    }

    fn point_owner(&self) -> Option<Option<LinkName>> {
        Some(Some(LinkName::of(self.link)))
    }

    fn position_values(&self) -> Vec<Value> {
        match self.local {
            Local::Polar(a, b) | Local::Cartesian(a, b) => vec![a.clone(), b.clone()],
        }
    }

    fn position(&self, _cos_sin: bool) -> Solve {
        let (axis, from, t) = (axis(self.link), local(self.from), tag(self.stmt));
        let offset = offset(self.local);
        Solve::Own {
            expr: quote!(::mechanism::link::point_position(&#from, &#axis, &#offset) #t),
            ty: quote!(::mechanism::Point2<T>),
        }
    }

    /// Its base point's motion plus its motion about it.
    fn rates(&self, cx: &mut dyn RateCx) {
        let (stmt, link, from) = (self.stmt, self.link, self.from);
        let name = &stmt.name;
        if !cx.moves(name) {
            return;
        }
        let (pv, t) = (cx.motion(stmt), tag(stmt));
        let base = cx.moves(from).then(|| {
            let b = cx.pfx().of(from);
            quote!(#b)
        });
        // The motion about `from`, as (unchecked, checked) calls; the
        // offset read from `pos` only where a turning link needs it.
        let offset = || {
            let (n, f) = (cx.reads().pos(name), cx.reads().pos(from));
            quote!(&(#n - #f))
        };
        let relative = match (cx.link_rate(link), cx.accel()) {
            (None, _) => None,
            (Some(w), false) => {
                let offset = offset();
                Some((
                    quote!(::mechanism::link::relative_velocity(#offset, #w)),
                    quote!(::mechanism::link::point_velocity(#offset, #w) #t),
                ))
            }
            (Some(alpha), true) => {
                let w = cx.link_omega_in_accel(link).unwrap_or_else(|| lit(0.0));
                let offset = offset();
                Some((
                    quote!(::mechanism::link::relative_acceleration(#offset, #w, #alpha)),
                    quote!(::mechanism::link::point_acceleration(#offset, #w, #alpha) #t),
                ))
            }
        };
        let value = match (base, relative) {
            // One check, of the sum: it overflows or is NaN whenever the
            // motion about `from` is not finite (the base's is finite).
            (Some(b), Some((r, _))) => quote!(::mechanism::link::point_sum(&#b, #r) #t),
            (Some(b), None) => b,
            (None, Some((_, checked))) => checked,
            (None, None) => quote!(::mechanism::Vector2::zeros()),
        };
        cx.code(quote!(let #pv = #value;));
        cx.field(pv, vec_ty());
    }

    /// `from` plus the link's axes times the local offset.
    fn residuals(&self, r: &mut Residuals<'_>, link_axis: &dyn Fn(&Ident) -> TokenStream) {
        let (n, from, axis) = (r.pos(r.n), r.pos(self.from), link_axis(self.link));
        let (x, y) = match self.local {
            Local::Cartesian(x, y) => (f(x), f(y)),
            Local::Polar(d, a) => {
                let (d, a) = (f(d), f(a));
                (quote!(#d * (#a).cos()), quote!(#d * (#a).sin()))
            }
        };
        r.push(
            "P = from + the link's axes times the local offset",
            quote!({
                let u = #axis;
                let (x, y) = (#x, #y);
                norm(sub(sub(pt(&#n), pt(&#from)), [u[0] * x - u[1] * y, u[1] * x + u[0] * y]))
            }),
        );
    }

    fn reads_axis(&self) -> Option<&'a Ident> {
        Some(self.link)
    }

    fn describe(&self) -> String {
        let (n, link, from) = (&self.stmt.name, self.link, self.from);
        format!("point `{n}` on `{link}` (from `{from}`)")
    }

    fn point_kind(&self) -> Option<&'static str> {
        Some("OnLink")
    }

    /// It moves when its link turns or its base point moves.
    fn point_moves(
        &self,
        link_turns: &dyn Fn(&Ident) -> bool,
        moves: &dyn Fn(&Ident) -> bool,
    ) -> bool {
        link_turns(self.link) || moves(self.from)
    }

    /// It is measured from a point of its link.
    fn check_placed(&self, plan: &dyn Placed, errors: &mut Diagnostics) {
        let (link, from) = (self.link, self.from);
        if let Some(points) = plan.link_points(link) {
            let f = PointName::of(from);
            if !points.contains(&f) && plan.is_defined(from) {
                errors.push(
                    from.span(),
                    format!(
                        "`{f}` is not a point of `{link}`; measure from one of its points: {}",
                        points
                            .iter()
                            .filter(|p| **p != self.stmt.name)
                            .map(|p| format!("`{p}`"))
                            .collect::<Vec<_>>()
                            .join(", ")
                    ),
                );
            }
        }
    }

    /// Its lane code in the batch kernel (`None`: an argument the kernel
    /// does not know; the batch then takes the scalar path).
    fn lane(&self, lane: &mut Lane, s: &mut Step<'_>) -> Option<()> {
        lane_steps(lane, s, self.link, self.from, self.local)
    }

    linkless_facets!('a);
}

/// A point's offset in its link's frame, folded when literal.
fn offset(offset: &Local) -> TokenStream {
    match offset {
        Local::Cartesian(x, y) => {
            let (x, y) = (x.emit(), y.emit());
            quote!(::mechanism::Vector2::new(#x, #y))
        }
        Local::Polar(d, a) => match (d.fold(), a.fold()) {
            (Some(d), Some(a)) => {
                let (s, c) = a.sin_cos();
                let (x, y) = (lit(d * c), lit(d * s));
                quote!(::mechanism::Vector2::new(#x, #y))
            }
            _ => {
                let (d, u) = (d.emit(), unit_vector(a));
                quote!((#u * #d))
            }
        },
    }
}

/// A point fixed on `link` at `local` coordinates from the point `from`
/// (length unit; polar angles in radians from the link's axis): the offset
/// `o_NAME` is the local vector turned by the link's axis, the velocity and
/// acceleration add `lane::rel_vel` / `lane::rel_acc` of that offset with
/// the link's rates. `None` when the link or `from` is not known yet.
fn lane_steps(lane: &Lane, s: &mut Step, link: &Ident, from: &Ident, local: &Local) -> Option<()> {
    let l = lane.link(link)?;
    let f = lane.point(from)?;
    let Vector { x: lx, y: ly } = local_vector(s, local);
    let PointLocals {
        px,
        py,
        vx,
        vy,
        ax,
        ay,
    } = s.own.clone();
    let Vector { x: ux, y: uy } = &l.axis;
    let (fpx, fpy) = (&f.px, &f.py);
    let o = super::lane::pv(Family::LaneOffset, s.name);
    let (ox, oy) = (&o.x, &o.y);
    s.emit(quote! {
        let (lx, ly) = (#lx, #ly);
        let #ox = #ux * lx - #uy * ly;
        let #oy = #uy * lx + #ux * ly;
        let #px = #fpx + #ox; let #py = #fpy + #oy;
    });
    let (omega, alpha) = (&l.omega, &l.alpha);
    if lane.vel {
        let (fvx, fvy) = (&f.vx, &f.vy);
        s.emit(quote! {
            let (tx, ty) = ::mechanism::__private::lane::rel_vel(#ox, #oy, #omega);
            let #vx = #fvx + tx; let #vy = #fvy + ty;
        });
    }
    if lane.acc {
        let (fax, fay) = (&f.ax, &f.ay);
        s.emit(quote! {
            let (tx, ty) = ::mechanism::__private::lane::rel_acc(#ox, #oy, #omega, #alpha);
            let #ax = #fax + tx; let #ay = #fay + ty;
        });
    }
    Some(())
}

impl super::run::RunKind for Point<'_> {
    fn compile(&self, cx: &Compile<'_>) -> Box<dyn super::run::Step> {
        let offset = match self.local {
            Local::Cartesian(x, y) => Vector2::new(cx.num(x), cx.num(y)),
            Local::Polar(d, a) => geometry::unit(cx.num(a)) * cx.num(d),
        };
        let (me, from) = (cx.me(self.stmt), cx.point(self.from));
        Box::new(PointRun {
            me,
            link: cx.link(self.link),
            from,
            offset,
            moves: cx.moves(me.point),
            from_moves: cx.moves(from),
        })
    }
}

/// A point on a link, compiled: the link, the point its offset is from
/// and the offset in the link's frame (L).
struct PointRun {
    me: Me,
    link: LinkSlot,
    from: PointSlot,
    offset: Vector2<f64>,
    /// Whether the point moves (its rates are written) and whether `from`
    /// does (its motion is the base of the point's), read once from the
    /// layout when compiled.
    moves: bool,
    from_moves: bool,
}

impl super::run::Step for PointRun {
    fn group(&self) -> &'static str {
        self.me.group
    }

    fn walks(&self) -> super::run::Walks {
        super::run::Walks {
            rates: self.moves,
            forces: false,
        }
    }

    fn position(&self, pose: &mut RunPose) -> Result<Option<f64>, mechanism_core::Error<f64>> {
        let p = link::point_position(&pose.point(self.from), &pose.axis(self.link), &self.offset)?;
        pose.found(&self.me, p, &[]);
        Ok(None)
    }

    /// The motion of a point on a link: its base's plus the motion about
    /// the base, checked as the generated code checks it: the sum alone
    /// when the base moves, the motion about the base otherwise (only the
    /// one used is computed).
    fn rates(&self, cx: &mut RunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        if !self.moves {
            return Ok(());
        }
        let link = self.link;
        let offset = cx.pose.point(self.me.point) - cx.pose.point(self.from);
        let rate = cx.link_rate(link);
        let value = match (self.from_moves, rate, cx.accel()) {
            (true, None, _) => cx.motion_of(self.from),
            (true, Some(w), false) => link::point_sum(
                &cx.motion_of(self.from),
                link::relative_velocity(&offset, w),
            )?,
            (true, Some(alpha), true) => {
                let w = cx.link_omega_in_accel(link).unwrap_or(0.0);
                let r = link::relative_acceleration(&offset, w, alpha);
                link::point_sum(&cx.motion_of(self.from), r)?
            }
            (false, None, _) => Vector2::zeros(),
            (false, Some(w), false) => link::point_velocity(&offset, w)?,
            (false, Some(alpha), true) => {
                let w = cx.link_omega_in_accel(link).unwrap_or(0.0);
                link::point_acceleration(&offset, w, alpha)?
            }
        };
        cx.set_motion(&self.me, value);
        Ok(())
    }

    fn forces(&self, _cx: &mut ForceRunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        Ok(())
    }

    fn link_dir(&self, _index: usize, _pose: &RunPose) -> Vector2<f64> {
        Vector2::x()
    }
}
