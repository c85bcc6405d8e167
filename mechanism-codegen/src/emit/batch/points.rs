//! Lane code of the statements that place points and lines without solving
//! a group: ground points, guides, and points fixed on a link.

use super::lane::{Lane, LaneGuide, PointLocals, Step, Vector};
use crate::model::{Local, Origin};
use crate::value::{lit, Value};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::Ident;

/// A ground point at `(x, y)` (length unit): its position locals are the
/// coordinates, its velocity and acceleration locals `zero` (later code
/// reads them like any point's; the compiler folds them). No core call,
/// nothing to check beyond the coordinates (see `Lane::commit`).
pub(super) fn ground(s: &mut Step, x: &Value, y: &Value) {
    let PointLocals {
        px,
        py,
        vx,
        vy,
        ax,
        ay,
    } = s.own.clone();
    let (x, y) = (x.emit(), y.emit());
    s.emit(quote! {
        let #px = #x; let #py = #y;
        let #vx = zero; let #vy = zero;
        let #ax = zero; let #ay = zero;
    });
}

/// A guide line through `origin` at `angle` (radians): fixed, a
/// `mechanism::__private::lane::Line` local `ln_NAME` whose motion is `None`; or
/// carried by the link `carrier`, its direction the link's axis turned by
/// `angle` (`lane::carried`), its motion `LineVelocity` / `LineAcceleration`
/// locals (`gv_NAME`, `ga_NAME`) from the origin's motion and the link's
/// rates. Defines no point. `None` when the origin point or the carrier is
/// not known yet.
pub(super) fn guide(
    lane: &Lane,
    s: &mut Step,
    origin: &Origin,
    angle: &Value,
    carrier: Option<&Ident>,
) -> Option<()> {
    s.defines_no_point();
    let line = format_ident!("ln_{}", s.name);
    let origin = match origin {
        Origin::Point(p) => OriginMotion::point(lane.point(p)?),
        Origin::Coords(x, y) => OriginMotion::fixed(x, y),
    };
    let guide = match carrier {
        None => {
            let Vector { x: ox, y: oy } = &origin.p;
            let Vector { x: dx, y: dy } = s.unit(angle);
            s.emit(quote! {
                let #line = ::mechanism::__private::lane::Line { ox: #ox, oy: #oy, dx: #dx, dy: #dy };
            });
            let none = quote!(::core::option::Option::None);
            LaneGuide {
                line,
                gv: none.clone(),
                ga: none,
                omega: quote!(zero),
                alpha: quote!(zero),
            }
        }
        Some(link) => carried(lane, s, line, &origin, angle, link)?,
    };
    s.defines_guide(guide);
    Some(())
}

/// A guide origin's position, velocity and acceleration as expressions.
struct OriginMotion {
    p: Vector,
    v: Vector,
    a: Vector,
}

impl OriginMotion {
    /// The origin is a point solved before: its locals.
    fn point(p: PointLocals) -> OriginMotion {
        let v = |x: Ident, y: Ident| Vector {
            x: quote!(#x),
            y: quote!(#y),
        };
        OriginMotion {
            p: v(p.px, p.py),
            v: v(p.vx, p.vy),
            a: v(p.ax, p.ay),
        }
    }

    /// The origin is at fixed coordinates `(x, y)`: it does not move.
    fn fixed(x: &Value, y: &Value) -> OriginMotion {
        let still = || Vector {
            x: quote!(zero),
            y: quote!(zero),
        };
        OriginMotion {
            p: Vector {
                x: x.emit(),
                y: y.emit(),
            },
            v: still(),
            a: still(),
        }
    }
}

/// The carried case of [`guide`]: the line through `origin`, its direction
/// the carrier `link`'s axis (angle 0) or that axis turned by `angle`
/// (`lane::carried`), moving with the origin and turning with the link.
fn carried(
    lane: &Lane,
    s: &mut Step,
    line: Ident,
    origin: &OriginMotion,
    angle: &Value,
    link: &Ident,
) -> Option<LaneGuide> {
    let l = lane.link(link)?;
    let Vector { x: ox, y: oy } = &origin.p;
    let Vector { x: axx, y: axy } = &l.axis;
    if angle.fold() == Some(0.0) {
        s.emit(quote! {
            let #line = ::mechanism::__private::lane::Line { ox: #ox, oy: #oy, dx: #axx, dy: #axy };
        });
    } else {
        let Vector { x: lx, y: ly } = s.unit(angle);
        s.emit(quote! {
            let #line = ::mechanism::__private::lane::carried(#ox, #oy, (#axx, #axy), (#lx, #ly));
        });
    }
    let (gv, ga) = (
        format_ident!("gv_{}", s.name),
        format_ident!("ga_{}", s.name),
    );
    let (omega, alpha) = (l.omega.clone(), l.alpha.clone());
    if lane.vel {
        let Vector { x: ovx, y: ovy } = &origin.v;
        s.emit(quote! {
            let #gv = ::mechanism::__private::lane::LineVelocity { vx: #ovx, vy: #ovy, omega: #omega };
        });
    }
    if lane.acc {
        let Vector { x: oax, y: oay } = &origin.a;
        s.emit(quote! {
            let #ga = ::mechanism::__private::lane::LineAcceleration { ax: #oax, ay: #oay, alpha: #alpha };
        });
    }
    Some(LaneGuide {
        line,
        gv: quote!(::core::option::Option::Some(&#gv)),
        ga: quote!(::core::option::Option::Some(&#ga)),
        omega,
        alpha,
    })
}

/// A point fixed on `link` at `local` coordinates from the point `from`
/// (length unit; polar angles in radians from the link's axis): the offset
/// `o_NAME` is the local vector turned by the link's axis, the velocity and
/// acceleration add `lane::rel_vel` / `lane::rel_acc` of that offset with
/// the link's rates. `None` when the link or `from` is not known yet.
pub(super) fn point(
    lane: &Lane,
    s: &mut Step,
    link: &Ident,
    from: &Ident,
    local: &Local,
) -> Option<()> {
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
    let o = super::lane::pv("o", s.name);
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

/// A link point's local coordinates along the link's axis and its left
/// normal: literals when they fold; a polar pair with a run-time distance
/// or angle becomes the local `lp_NAME`, computed once before the loop (as
/// the scalar path does).
fn local_vector(s: &mut Step, local: &Local) -> Vector {
    let (x, y): (TokenStream, TokenStream) = match local {
        Local::Cartesian(x, y) => (x.emit(), y.emit()),
        Local::Polar(d, a) => match (d.fold(), a.fold()) {
            (Some(d), Some(a)) => {
                let (sin, cos) = a.sin_cos();
                (lit(d * cos), lit(d * sin))
            }
            _ => {
                let Vector { x: ux, y: uy } = s.unit(a);
                let d = d.emit();
                let lp = format_ident!("lp_{}", s.name);
                s.before_loop(quote!(let #lp = (#ux * #d, #uy * #d);));
                (quote!(#lp.0), quote!(#lp.1))
            }
        },
    };
    Vector { x, y }
}
