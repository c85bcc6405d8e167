//! Lane code of the drivers: the statements that read the element's inputs
//! (`in_INPUT[k]`, and `rate_INPUT[k]`, `accel_INPUT[k]` at the velocity and
//! acceleration levels).

use super::groups::{self, SecondSide};
use super::lane::{Lane, LaneLink, PointLocals, Step, Vector};
use crate::model::Mode;
use crate::value::Value;
use quote::{format_ident, quote};
use syn::Ident;

/// A crank about `pivot` of length `radius` (length unit) at the input
/// angle `in_INPUT[k]` (radians, counter-clockwise from +x):
/// `lane::crank`, then the tip's velocity and acceleration with
/// `lane::rel_vel` / `lane::rel_acc` from the input's rates (rad/s,
/// rad/s^2), which become the link's `w_LINK` / `al_LINK`. The link's angle
/// is the input wrapped (`lane::wrap_angle`). `None` when the pivot is not
/// known yet.
pub(super) fn crank(
    lane: &Lane,
    s: &mut Step,
    pivot: &Ident,
    radius: &Value,
    input: &Ident,
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
    let th = format_ident!("in_{}", input);
    let rates = s.rates(0)?;
    let (omega, alpha) = (&rates.omega, &rates.alpha);
    s.emit(quote! {
        let #g = ::mechanism::__private::lane::crank(#ppx, #ppy, #r, #th[k]);
        ok &= #g.ok;
        let #px = #g.x; let #py = #g.y;
    });
    if lane.vel {
        let rate = format_ident!("rate_{}", input);
        let (pvx, pvy) = (&p.vx, &p.vy);
        s.emit(quote! {
            let #omega = #rate[k];
            let (tx, ty) = ::mechanism::__private::lane::rel_vel(#g.rx, #g.ry, #omega);
            let #vx = #pvx + tx; let #vy = #pvy + ty;
        });
        s.check([quote!(#omega)]);
    }
    if lane.acc {
        let accel = format_ident!("accel_{}", input);
        let (pax, pay) = (&p.ax, &p.ay);
        s.emit(quote! {
            let #alpha = #accel[k];
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
            angle: quote!(::mechanism::__private::lane::wrap_angle(#th[k])),
            omega: quote!(#omega),
            alpha: quote!(#alpha),
        },
    )
}

/// A slider on `guide` at the input displacement `in_INPUT[k]` (length
/// unit, along the guide's direction) plus `offset` across it:
/// `lane::slider`, `lane::slider_velocity` and `lane::slider_acceleration`
/// (the guide's motion folds away for a fixed guide). The block's link
/// turns with the guide's body. `None` when the guide is not known yet.
pub(super) fn slider(
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
    let input_s = format_ident!("in_{}", input);
    s.emit(quote! {
        let (#px, #py) = ::mechanism::__private::lane::slider(&#line, #o, #input_s[k]);
    });
    s.check([quote!(#input_s[k])]);
    let rate = format_ident!("rate_{}", input);
    if lane.vel {
        s.emit(quote! {
            let (#vx, #vy) = ::mechanism::__private::lane::slider_velocity(&#line, #px, #py, #rate[k], #gv);
        });
        s.check([quote!(#rate[k])]);
    }
    if lane.acc {
        let accel = format_ident!("accel_{}", input);
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

/// A linear actuator between `a` and `b`: an RRR dyad (`lane::rrr`) whose
/// second side is the input length `in_INPUT[k]` (length unit), its rates
/// from `lane::actuator_rates` / `lane::actuator_accels` with the input's
/// rates. See [`groups::rrr`].
pub(super) fn actuator(
    lane: &Lane,
    s: &mut Step,
    a: &Ident,
    l: &Value,
    b: &Ident,
    input: &Ident,
    mode: &Mode,
) -> Option<()> {
    groups::dyad(lane, s, a, l, b, SecondSide::Input(input), mode)
}
