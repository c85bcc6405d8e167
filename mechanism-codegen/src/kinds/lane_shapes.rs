//! Lane code shapes shared by several kinds: the RRR-shaped dyad (the RRR
//! and the actuator), unit vectors along guides, carried guide lines and
//! points' offsets in their link's frame.

use super::lane::{Lane, LaneGuide, LaneLink, PointLocals, Step, Vector};
use crate::model::{Local, Mode};
use crate::names::Family;
use crate::value::{lit, Value};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::Ident;

/// The second side of an RRR dyad: a fixed length, or a linear actuator's
/// input length (`in_INPUT[k]`, read per element and checked).
#[derive(Clone, Copy)]
pub(crate) enum SecondSide<'a> {
    Length(&'a Value),
    Input(&'a Ident),
}

/// An RRR dyad from `a` (side `l1`) and `b` (side `second`): the joint's
/// position (`lane::rrr`), velocity and acceleration (relative to `a` with
/// `lane::rel_vel` / `lane::rel_acc`), the two links' rates `w_LINK` (rad/s)
/// and `al_LINK` (rad/s^2) from `lane::rrr_rates` / `lane::rrr_accels`, or
/// `lane::actuator_rates` / `lane::actuator_accels` for an actuator. The
/// links lie along the group's `r1` (from `a`) and `r2` (from `b`). `None`
/// when `a` or `b` is not known yet or the statement lacks its two links.
pub(crate) fn dyad(
    lane: &Lane,
    s: &mut Step,
    a: &Ident,
    l1: &Value,
    b: &Ident,
    second: SecondSide,
    mode: &Mode,
) -> Option<()> {
    let (pa, pb) = (lane.point(a)?, lane.point(b)?);
    if s.link_count() != 2 {
        return None;
    }
    let PointLocals {
        px,
        py,
        vx,
        vy,
        ax,
        ay,
    } = s.own.clone();
    let g = s.g.clone();
    let l1 = l1.emit();
    let l2 = match second {
        SecondSide::Length(l2) => l2.emit(),
        SecondSide::Input(input) => {
            let s_in = Family::In.of(input);
            s.check([quote!(#s_in[k])]);
            quote!(#s_in[k])
        }
    };
    let sign = s.sign(mode);
    let (r1, r2) = (s.rates(0)?, s.rates(1)?);
    let (w1, al1, w2, al2) = (&r1.omega, &r1.alpha, &r2.omega, &r2.alpha);
    let (apx, apy, bpx, bpy) = (&pa.px, &pa.py, &pb.px, &pb.py);
    s.emit(quote! {
        let #g = ::mechanism::__private::lane::rrr(#apx, #apy, #l1, #bpx, #bpy, #l2, #sign);
        ok &= #g.ok;
        let #px = #g.x; let #py = #g.y;
    });
    if lane.vel {
        let (avx, avy, bvx, bvy) = (&pa.vx, &pa.vy, &pb.vx, &pb.vy);
        let rates = match second {
            SecondSide::Length(_) => {
                quote!(::mechanism::__private::lane::rrr_rates(&#g, #bvx - #avx, #bvy - #avy))
            }
            SecondSide::Input(input) => {
                let rate = Family::Rate.of(input);
                s.check([quote!(#rate[k])]);
                quote!(::mechanism::__private::lane::actuator_rates(&#g, #bvx - #avx, #bvy - #avy, #l2, #rate[k]))
            }
        };
        s.emit(quote! {
            ok &= #g.ok_rate;
            let (#w1, #w2) = #rates;
            let (tx, ty) = ::mechanism::__private::lane::rel_vel(#g.r1x, #g.r1y, #w1);
            let #vx = #avx + tx; let #vy = #avy + ty;
        });
        s.check([quote!(#w1), quote!(#w2)]);
    }
    if lane.acc {
        let (aax, aay, bax, bay) = (&pa.ax, &pa.ay, &pb.ax, &pb.ay);
        let accels = match second {
            SecondSide::Length(_) => {
                quote!(::mechanism::__private::lane::rrr_accels(&#g, #bax - #aax, #bay - #aay, #w1, #w2))
            }
            SecondSide::Input(input) => {
                let (rate, accel) = (Family::Rate.of(input), Family::Accel.of(input));
                s.check([quote!(#accel[k])]);
                quote!(::mechanism::__private::lane::actuator_accels(&#g, #bax - #aax, #bay - #aay, #l2, #rate[k], #accel[k], #w1, #w2))
            }
        };
        s.emit(quote! {
            let (#al1, #al2) = #accels;
            let (tx, ty) = ::mechanism::__private::lane::rel_acc(#g.r1x, #g.r1y, #w1, #al1);
            let #ax = #aax + tx; let #ay = #aay + ty;
        });
        s.check([quote!(#al1), quote!(#al2)]);
    }
    let (w1, al1, w2, al2) = (quote!(#w1), quote!(#al1), quote!(#w2), quote!(#al2));
    s.defines_link(0, LaneLink::along(along_line(&g, "r1"), Some(&l1), w1, al1))?;
    s.defines_link(1, LaneLink::along(along_line(&g, "r2"), Some(&l2), w2, al2))
}

/// The vector `(g.NAMEx, g.NAMEy)` of the group solution `g`: `r1`, `r2`
/// (the sides from the known joints to the new one, RRR and RRP; length
/// unit), `u` (an RPR's unit slide direction), `w` (an RPP's unit slot
/// direction).
pub(crate) fn along_line(g: &Ident, name: &str) -> Vector {
    let (x, y) = (format_ident!("{}x", name), format_ident!("{}y", name));
    Vector {
        x: quote!(#g.#x),
        y: quote!(#g.#y),
    }
}

/// The axis of a guide's line local (`line.dx`, `line.dy`).
pub(crate) fn line_axis(line: &Ident) -> Vector {
    Vector {
        x: quote!(#line.dx),
        y: quote!(#line.dy),
    }
}

/// A guide origin's position, velocity and acceleration as expressions.
pub(crate) struct OriginMotion {
    pub(crate) p: Vector,
    pub(crate) v: Vector,
    pub(crate) a: Vector,
}

impl OriginMotion {
    /// The origin is a point solved before: its locals.
    pub(crate) fn point(p: PointLocals) -> OriginMotion {
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
    pub(crate) fn fixed(x: &Value, y: &Value) -> OriginMotion {
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
pub(crate) fn carried(
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
        Family::LaneGuideVel.of(s.name),
        Family::LaneGuideAcc.of(s.name),
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

/// A link point's local coordinates along the link's axis and its left
/// normal: literals when they fold; a polar pair with a run-time distance
/// or angle becomes the local `lp_NAME`, computed once before the loop (as
/// the scalar path does).
pub(crate) fn local_vector(s: &mut Step, local: &Local) -> Vector {
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
                let lp = Family::LaneLinkPoint.of(s.name);
                s.before_loop(quote!(let #lp = (#ux * #d, #uy * #d);));
                (quote!(#lp.0), quote!(#lp.1))
            }
        },
    };
    Vector { x, y }
}
