//! Lane code of the Assur groups (dyads): RRR (and the linear actuator, an
//! RRR whose second side is an input), RRP, RPR, PRP and RPP. Each calls the
//! `mechanism::__private::lane` function of its kind for the position (a struct with
//! an `ok` flag, stricter than the scalar checks), then its `_rates` and
//! `_accels` functions at the velocity and acceleration levels, and checks
//! every value the scalar path checks.

use super::lane::{sign, Lane, LaneLink, PointLocals, Step, Vector};
use crate::model::Mode;
use crate::value::Value;
use quote::{format_ident, quote};
use syn::Ident;

/// The second side of an RRR dyad: a fixed length, or a linear actuator's
/// input length (`in_INPUT[k]`, read per element and checked).
#[derive(Clone, Copy)]
pub(super) enum SecondSide<'a> {
    Length(&'a Value),
    Input(&'a Ident),
}

/// An RRR group: the joint at distance `l1` from `a` and `l2` from `b`
/// (length unit), on the side `mode` (`lane::rrr`), its rates with
/// `lane::rrr_rates` / `lane::rrr_accels`. See [`dyad`].
pub(super) fn rrr(
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

/// An RRR dyad from `a` (side `l1`) and `b` (side `second`): the joint's
/// position (`lane::rrr`), velocity and acceleration (relative to `a` with
/// `lane::rel_vel` / `lane::rel_acc`), the two links' rates `w_LINK` (rad/s)
/// and `al_LINK` (rad/s^2) from `lane::rrr_rates` / `lane::rrr_accels`, or
/// `lane::actuator_rates` / `lane::actuator_accels` for an actuator. The
/// links lie along the group's `r1` (from `a`) and `r2` (from `b`). `None`
/// when `a` or `b` is not known yet or the statement lacks its two links.
pub(super) fn dyad(
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
            let s_in = format_ident!("in_{}", input);
            s.check([quote!(#s_in[k])]);
            quote!(#s_in[k])
        }
    };
    let sign = sign(mode);
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
                let rate = format_ident!("rate_{}", input);
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
                let (rate, accel) = (
                    format_ident!("rate_{}", input),
                    format_ident!("accel_{}", input),
                );
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
    s.defines_link(0, LaneLink::along(along(&g, "r1"), Some(&l1), w1, al1))?;
    s.defines_link(1, LaneLink::along(along(&g, "r2"), Some(&l2), w2, al2))
}

/// The vector `(g.NAMEx, g.NAMEy)` of the group solution `g`: `r1`, `r2`
/// (the sides from the known joints to the new one, RRR and RRP; length
/// unit), `u` (an RPR's unit slide direction), `w` (an RPP's unit slot
/// direction).
fn along(g: &Ident, name: &str) -> Vector {
    let (x, y) = (format_ident!("{}x", name), format_ident!("{}y", name));
    Vector {
        x: quote!(#g.#x),
        y: quote!(#g.#y),
    }
}

/// The axis of a guide's line local (`line.dx`, `line.dy`).
fn line_axis(line: &Ident) -> Vector {
    Vector {
        x: quote!(#line.dx),
        y: quote!(#line.dy),
    }
}

/// An RRP group: the joint at distance `l` (length unit) from `a` and at
/// `offset` across `guide`, on the side `mode` (`lane::rrp`), its slide
/// along the guide (`s0_NAME`), rates with `lane::rrp_rates` /
/// `lane::rrp_accels`. Link 1 lies along `r1`, link 2 (the block) turns
/// with the guide. `None` when `a` or the guide is not known yet.
pub(super) fn rrp(
    lane: &Lane,
    s: &mut Step,
    a: &Ident,
    l: &Value,
    guide: &Ident,
    mode: &Mode,
    offset: &Value,
) -> Option<()> {
    let pa = lane.point(a)?;
    let gd = lane.guide(guide)?;
    let PointLocals {
        px,
        py,
        vx,
        vy,
        ax,
        ay,
    } = s.own.clone();
    let g = s.g.clone();
    let (line, gv, ga) = (&gd.line, &gd.gv, &gd.ga);
    let (l, o, sign) = (l.emit(), offset.emit(), sign(mode));
    let r1 = s.rates(0)?;
    let (w1, al1) = (&r1.omega, &r1.alpha);
    let slide = s.slide_locals(0);
    let (sl, sd, sdd) = (&slide.s, &slide.sd, &slide.sdd);
    let (apx, apy) = (&pa.px, &pa.py);
    s.emit(quote! {
        let #g = ::mechanism::__private::lane::rrp(#apx, #apy, #l, &#line, #o, #sign);
        ok &= #g.ok;
        let #px = #g.x; let #py = #g.y;
        let #sl = #g.s;
    });
    s.check([quote!(#sl)]);
    if lane.vel {
        let (avx, avy) = (&pa.vx, &pa.vy);
        s.emit(quote! {
            ok &= #g.ok_rate;
            let (#w1, #sd, #vx, #vy) = ::mechanism::__private::lane::rrp_rates(&#g, &#line, #avx, #avy, #gv);
        });
        s.check([quote!(#w1), quote!(#sd)]);
    }
    if lane.acc {
        let (aax, aay) = (&pa.ax, &pa.ay);
        s.emit(quote! {
            let (#al1, #sdd, #ax, #ay) = ::mechanism::__private::lane::rrp_accels(&#g, &#line, #aax, #aay, #w1, #sd, #gv, #ga);
        });
        s.check([quote!(#al1), quote!(#sdd)]);
    }
    s.defines_slide(0, &slide);
    let (w1, al1) = (quote!(#w1), quote!(#al1));
    s.defines_link(0, LaneLink::along(along(&g, "r1"), Some(&l), w1, al1))?;
    let block = LaneLink::along(line_axis(line), None, gd.omega.clone(), gd.alpha.clone());
    s.defines_link(1, block)
}

/// An RPR group: a slide through `a` and `b` at `offset` (length unit)
/// from the line `a`-`b`, on the side `mode` (`lane::rpr`); defines no
/// point, only the slide (`s0_NAME`, named after the statement when the
/// definition gives none) and the rates of its two links, which share the
/// group's direction `u` (`lane::rpr_rates` / `lane::rpr_accels`). `None`
/// when `a` or `b` is not known yet.
pub(super) fn rpr(
    lane: &Lane,
    s: &mut Step,
    a: &Ident,
    b: &Ident,
    mode: &Mode,
    offset: &Value,
) -> Option<()> {
    let (pa, pb) = (lane.point(a)?, lane.point(b)?);
    s.defines_no_point();
    let g = s.g.clone();
    let (o, sign) = (offset.emit(), sign(mode));
    let r = s.rates(0)?;
    let (w, al) = (&r.omega, &r.alpha);
    let slide = s.slide_locals(0);
    let (sl, sd, sdd) = (&slide.s, &slide.sd, &slide.sdd);
    let (apx, apy, bpx, bpy) = (&pa.px, &pa.py, &pb.px, &pb.py);
    s.emit(quote! {
        let #g = ::mechanism::__private::lane::rpr(#apx, #apy, #bpx, #bpy, #o, #sign);
        ok &= #g.ok;
        let #sl = #g.s;
    });
    s.check([quote!(#sl), quote!(#g.ux), quote!(#g.uy)]);
    if lane.vel {
        let (avx, avy, bvx, bvy) = (&pa.vx, &pa.vy, &pb.vx, &pb.vy);
        s.emit(quote! {
            ok &= #g.ok_rate;
            let (#w, #sd) = ::mechanism::__private::lane::rpr_rates(&#g, #avx - #bvx, #avy - #bvy);
        });
        s.check([quote!(#w), quote!(#sd)]);
    }
    if lane.acc {
        let (aax, aay, bax, bay) = (&pa.ax, &pa.ay, &pb.ax, &pb.ay);
        s.emit(quote! {
            let (#al, #sdd) = ::mechanism::__private::lane::rpr_accels(&#g, #aax - #bax, #aay - #bay, #w, #sd);
        });
        s.check([quote!(#al), quote!(#sdd)]);
    }
    s.defines_slide(0, &slide);
    for k in 0..2 {
        s.defines_link(
            k,
            LaneLink::along(along(&g, "u"), None, quote!(#w), quote!(#al)),
        )?;
    }
    Some(())
}

/// A PRP group: the joint of two blocks, on `g1` at `offset1` and on `g2`
/// at `offset2` (length unit) (`lane::prp`), its two slides (`s0_NAME`,
/// `s1_NAME`) and their rates (`lane::prp_rates` / `lane::prp_accels`).
/// Each block turns with its guide's body. `None` when a guide is not
/// known yet.
pub(super) fn prp(
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

/// An RPP group: a block sliding on `guide` (at `offset`, length unit)
/// carrying a slot at `slot` (radians from the guide) through which the
/// point `a` slides (`lane::rpp`), its two slides (`s0_NAME` along the
/// guide, `s1_NAME` along the slot) and their rates (`lane::rpp_rates` /
/// `lane::rpp_accels`). Both links turn with the guide's body: link 1 (the
/// block) along the slot `w`, link 2 (the yoke) along the guide, as in the
/// scalar path. `None` when `a` or the guide is not known yet.
pub(super) fn rpp(
    lane: &Lane,
    s: &mut Step,
    a: &Ident,
    guide: &Ident,
    slot: &Value,
    offset: &Value,
) -> Option<()> {
    let pa = lane.point(a)?;
    let gd = lane.guide(guide)?;
    let PointLocals {
        px,
        py,
        vx,
        vy,
        ax,
        ay,
    } = s.own.clone();
    let g = s.g.clone();
    let (line, gv, ga) = (&gd.line, &gd.gv, &gd.ga);
    let Vector { x: lx, y: ly } = s.unit(slot);
    let o = offset.emit();
    let (slide1, slide2) = (s.slide_locals(0), s.slide_locals(1));
    let (s1, sd1, sdd1) = (&slide1.s, &slide1.sd, &slide1.sdd);
    let (s2, sd2, sdd2) = (&slide2.s, &slide2.sd, &slide2.sdd);
    let (apx, apy) = (&pa.px, &pa.py);
    s.emit(quote! {
        let #g = ::mechanism::__private::lane::rpp(#apx, #apy, &#line, #o, #lx, #ly);
        ok &= #g.ok;
        let #px = #g.x; let #py = #g.y;
        let #s1 = #g.s1; let #s2 = #g.s2;
    });
    s.check([quote!(#s1), quote!(#s2)]);
    if lane.vel {
        let (avx, avy) = (&pa.vx, &pa.vy);
        s.emit(quote! {
            let (#sd1, #sd2, #vx, #vy) = ::mechanism::__private::lane::rpp_rates(&#g, &#line, #apx, #apy, #avx, #avy, #gv);
        });
        s.check([quote!(#sd1), quote!(#sd2)]);
    }
    if lane.acc {
        let (aax, aay) = (&pa.ax, &pa.ay);
        s.emit(quote! {
            let (#sdd1, #sdd2, #ax, #ay) = ::mechanism::__private::lane::rpp_accels(&#g, &#line, #apx, #apy, #aax, #aay, #sd1, #sd2, #gv, #ga);
        });
        s.check([quote!(#sdd1), quote!(#sdd2)]);
    }
    s.defines_slide(0, &slide1);
    s.defines_slide(1, &slide2);
    let turning = |v: Vector| LaneLink::along(v, None, gd.omega.clone(), gd.alpha.clone());
    s.defines_link(0, turning(along(&g, "w")))?;
    s.defines_link(1, turning(line_axis(line)))
}
