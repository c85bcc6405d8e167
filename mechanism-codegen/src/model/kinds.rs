//! One `let` statement's kind and arguments lowered to a [`Kind`]: the kind
//! checked against the vocabulary and its arity, then one function per kind
//! reading the arguments by role ([`Args`]).

use super::args::{Args, NumberScope};
use super::{Gear, Kind, Local, Origin, Triad};
use crate::diag::{did_you_mean, Diagnostics};
use crate::keys::GROUND;
use crate::parse::vocabulary::{kinds, kinds_list, unsupported_driver, KindWord};
use crate::parse::{self, Arg};
use crate::value::convert;
use crate::value::{Scope, Value};
use syn::spanned::Spanned;
use syn::{Expr, Ident};

/// The error for a statement written with fewer arguments than its kind
/// takes, before any argument is read: read in order, the arguments would
/// fill the wrong roles (`rrr(A, 3.5, O4, left)` would read `left` as the
/// second length), and the message would be about a name instead of the
/// count.
fn too_few_arguments(stmt: &parse::Let, kind: KindWord) -> Option<String> {
    let (least, most) =
        kind.arity(|k| matches!(stmt.args.get(k), Some(parse::Arg::Value(Expr::Tuple(_), _))));
    let given = stmt.args.len();
    if given >= least {
        return None;
    }
    let takes = if kind == KindWord::Point {
        "it takes 4 (3 in the `(x, y)` form)".to_string()
    } else if least == most {
        format!("it takes {least}")
    } else {
        format!("it takes at least {least}")
    };
    Some(format!(
        "missing argument(s) for `{kind}`: {given} given, {takes}; usage: `{}`",
        kind.spec().usage
    ))
}

/// Lowers the kind and arguments of the `let` statement `stmt`; `None` when
/// they are rejected (reported).
pub(super) fn lower_kind(
    stmt: &parse::Let,
    scope: &NumberScope<'_>,
    errors: &mut Diagnostics,
) -> Option<Kind> {
    let Some(kind) = stmt.word else {
        let kind = stmt.kind.to_string();
        let hint = match unsupported_driver(&kind) {
            Some(h) => format!("unsupported driver `{kind}`: {h}"),
            None => format!(
                "unknown statement kind `{kind}`; expected one of {}{}",
                kinds_list(),
                did_you_mean(&kind, kinds())
            ),
        };
        errors.push(stmt.kind.span(), hint);
        return None;
    };
    if let Some(message) = too_few_arguments(stmt, kind) {
        errors.push(stmt.args_span, message);
        return None;
    }
    let mut a = Args {
        args: stmt.args.iter(),
        span: stmt.args_span,
        usage: kind.spec().usage,
        kind,
        scope,
        errors,
        failed: false,
    };
    let k = match kind {
        KindWord::Ground => ground(&mut a)?,
        KindWord::Guide => guide(&mut a, stmt)?,
        KindWord::Crank => crank(&mut a)?,
        KindWord::Slider => slider(&mut a)?,
        KindWord::Actuator => actuator(&mut a)?,
        KindWord::Target => target(&mut a)?,
        KindWord::Rrr => rrr(&mut a)?,
        KindWord::Rrp => rrp(&mut a)?,
        KindWord::Rpr => rpr(&mut a)?,
        KindWord::Prp => prp(&mut a)?,
        KindWord::Rpp => rpp(&mut a)?,
        KindWord::Point => point(&mut a, stmt)?,
        KindWord::Triad => triad(&mut a, stmt)?,
        KindWord::Gear => gear(&mut a)?,
    };
    a.finish();
    if a.failed {
        None
    } else {
        Some(k)
    }
}

/// A link name that may be the ground (`ground`: `None`), and where it is
/// written.
fn link_or_ground(a: &mut Args, role: &str) -> Option<(Option<Ident>, proc_macro2::Span)> {
    let name = a.name(role)?;
    let span = name.span();
    Some(((name != GROUND).then_some(name), span))
}

/// `gear(PIVOT, radius, MESH, ratio[, phase[, CARRIER[, pressure_angle]]])`:
/// the ratio neither 0 nor -1 (no gear, or an internal pair of equal
/// gears), the pressure angle (20 deg when left out) in (0, 90) deg. Which
/// cranks turn `MESH` and `CARRIER` is resolved after (`lower`).
fn gear(a: &mut Args) -> Option<Kind> {
    let pivot = a.name("pivot point")?;
    let radius = a.length("radius to the point it defines")?;
    let (mesh, mesh_span) = link_or_ground(a, "link it meshes with (or `ground`)")?;
    let ratio = a.number("gear ratio", false)?;
    if let Some(r) = ratio.fold() {
        if r == 0.0 || r == -1.0 {
            a.fail(
                ratio.span,
                format!("a gear ratio of {r} couples nothing (0: no gear; -1: an internal pair of equal gears, which has no center distance); the ratio is the pitch radius of the meshing gear over this one's, positive for external gears, negative for an internal pair, e.g. `2.0`"),
            );
            return None;
        }
    }
    let phase = if a.args.len() > 0 {
        a.number("phase angle", true)?
    } else {
        Value::lit(0.0, a.span)
    };
    let carrier = if a.args.len() > 0 {
        link_or_ground(a, "common link both gears turn on (or `ground`)")?.0
    } else {
        None
    };
    let pressure = if a.args.len() > 0 {
        a.number("pressure angle", true)?
    } else {
        Value::lit(20f64.to_radians(), a.span)
    };
    if let Some(p) = pressure.fold() {
        if !(p > 0.0 && p < std::f64::consts::FRAC_PI_2) {
            a.fail(
                pressure.span,
                format!("a pressure angle is between 0 and 90 deg, got {} deg; gears are commonly cut at `20 deg`", crate::diag::show_num(p.to_degrees())),
            );
            return None;
        }
    }
    Some(Kind::Gear(Box::new(Gear {
        pivot,
        radius,
        mesh,
        mesh_span,
        ratio,
        phase,
        carrier,
        pressure,
        mesh_crank: None,
        carrier_crank: None,
    })))
}

/// `ground(x, y)`.
fn ground(a: &mut Args) -> Option<Kind> {
    Some(Kind::Ground {
        x: a.number("x coordinate", false)?,
        y: a.number("y coordinate", false)?,
    })
}

/// `guide(ORIGIN, angle)` (fixed) or `guide(POINT, LINK, angle?)` (carried);
/// the origin a point or `(x, y)`.
fn guide(a: &mut Args, stmt: &parse::Let) -> Option<Kind> {
    let scope = a.scope;
    let origin = match a.next("origin")? {
        Arg::Value(Expr::Tuple(t), None) if t.elems.len() == 2 => {
            let x = convert(&t.elems[0], scope)
                .map_err(|e| a.errors.error(e))
                .ok()?;
            let y = convert(&t.elems[1], scope)
                .map_err(|e| a.errors.error(e))
                .ok()?;
            Origin::Coords(x, y)
        }
        Arg::Value(Expr::Path(p), None) if p.path.get_ident().is_some() => {
            Origin::Point(p.path.get_ident()?.clone())
        }
        other => {
            let span = match other {
                Arg::From(i) => i.span(),
                Arg::Value(e, _) => e.span(),
            };
            a.fail(
                span,
                "expected the guide's origin: a point name or `(x, y)`".into(),
            );
            return None;
        }
    };
    // Second argument: a link (carried guide) or an angle (fixed guide).
    let carrier = match stmt.args.get(1) {
        Some(Arg::Value(Expr::Path(p), None))
            if p.path.get_ident().is_some()
                && scope.constant(p.path.get_ident()?).is_none()
                && !scope.is_param(p.path.get_ident()?) =>
        {
            a.name("carrying link")
        }
        _ => None,
    };
    let angle = if carrier.is_some() && a.args.len() == 0 {
        Value::lit(0.0, stmt.args_span)
    } else {
        a.number("direction angle", true)?
    };
    Some(Kind::Guide {
        origin,
        angle,
        carrier,
    })
}

/// `crank(PIVOT, radius, INPUT)` or `crank(PIVOT, radius, INPUT as
/// cos_sin)`, then optionally the carrying link: `crank(PIVOT, radius,
/// INPUT, LINK)`.
fn crank(a: &mut Args) -> Option<Kind> {
    let pivot = a.name("pivot point")?;
    let radius = a.length("crank radius")?;
    let (input, cos_sin) = a.crank_input()?;
    let carrier = match a.args.clone().next() {
        None => None,
        Some(Arg::Value(Expr::Path(p), None)) if p.path.get_ident().is_some() => {
            Some(a.name("carrying link")?)
        }
        Some(other) => {
            let span = match other {
                Arg::From(i) => i.span(),
                Arg::Value(e, _) => e.span(),
            };
            a.fail(
                span,
                format!("a crank's fourth argument is the moving link that carries its pivot and its motor (`crank({}, r, {input}, thigh)`: the input is then the angle from `thigh`'s axis); a crank on the ground takes three", pivot),
            );
            return None;
        }
    };
    // After the carrier, the angle in its frame where the input is zero.
    let zero = if carrier.is_some() && a.args.len() > 0 {
        a.number("zero angle in the carrier's frame", true)?
    } else {
        Value::lit(0.0, a.span)
    };
    Some(Kind::Crank {
        pivot,
        radius,
        input,
        cos_sin,
        carrier,
        zero,
    })
}

/// `slider(GUIDE, INPUT, offset?)`.
fn slider(a: &mut Args) -> Option<Kind> {
    Some(Kind::Slider {
        guide: a.name("guide")?,
        input: a.name("input name")?,
        offset: a.optional_number("offset"),
    })
}

/// `target(X, Y)`: the two inputs, which must differ.
fn target(a: &mut Args) -> Option<Kind> {
    let x = a.name("x input name")?;
    let y = a.name("y input name")?;
    if x == y {
        a.errors.push(
            y.span(),
            format!("a target takes two inputs, its x and its y coordinate, and both are `{x}`; name the second another way, e.g. `target({x}, {x}_y)`"),
        );
        return None;
    }
    Some(Kind::Target { x, y })
}

/// `actuator(A, radius, B, INPUT, mode)`.
fn actuator(a: &mut Args) -> Option<Kind> {
    Some(Kind::Actuator {
        a: a.name("pivot-side point A")?,
        l: a.length("radius |C - A|")?,
        b: a.name("cylinder base point B")?,
        input: a.name("input name")?,
        mode: a.mode()?,
    })
}

/// `rrr(A, l1, B, l2, mode)`.
fn rrr(a: &mut Args) -> Option<Kind> {
    Some(Kind::Rrr {
        a: a.name("first known joint")?,
        l1: a.length("first link length")?,
        b: a.name("second known joint")?,
        l2: a.length("second link length")?,
        mode: a.mode()?,
    })
}

/// `rrp(A, l, GUIDE, mode, offset?)`.
fn rrp(a: &mut Args) -> Option<Kind> {
    Some(Kind::Rrp {
        a: a.name("known joint")?,
        l: a.length("link length")?,
        guide: a.name("guide")?,
        mode: a.mode()?,
        offset: a.optional_number("offset"),
    })
}

/// `rpr(A, B, mode, offset?)`.
fn rpr(a: &mut Args) -> Option<Kind> {
    Some(Kind::Rpr {
        a: a.name("block pin")?,
        b: a.name("rocker pivot")?,
        mode: a.mode()?,
        offset: a.optional_number("offset"),
    })
}

/// `prp(GUIDE1, GUIDE2, offset1?, offset2?)`.
fn prp(a: &mut Args) -> Option<Kind> {
    let g1 = a.name("first guide")?;
    let g2 = a.name("second guide")?;
    let offset1 = a.optional_number("first offset");
    let offset2 = a.optional_number("second offset");
    Some(Kind::Prp {
        g1,
        g2,
        offset1,
        offset2,
    })
}

/// `rpp(A, GUIDE, slot angle, offset?)`.
fn rpp(a: &mut Args) -> Option<Kind> {
    Some(Kind::Rpp {
        a: a.name("block pin")?,
        guide: a.name("guide")?,
        slot: a.number("slot angle", true)?,
        offset: a.optional_number("offset"),
    })
}

/// `point(LINK, from A, distance, angle)` or `point(LINK, from A, (x, y))`.
fn point(a: &mut Args, stmt: &parse::Let) -> Option<Kind> {
    let scope = a.scope;
    let link = a.name("link")?;
    let from = a.from()?;
    let local = match stmt.args.get(2) {
        Some(Arg::Value(Expr::Tuple(t), None)) if t.elems.len() == 2 => {
            a.args.next();
            let x = convert(&t.elems[0], scope)
                .map_err(|e| a.errors.error(e))
                .ok()?;
            let y = convert(&t.elems[1], scope)
                .map_err(|e| a.errors.error(e))
                .ok()?;
            Local::Cartesian(x, y)
        }
        Some(Arg::Value(Expr::Tuple(t), _)) => {
            a.fail(
                t.span(),
                format!(
                    "a point's local coordinates are `(x, y)`, two numbers, not {}; usage: `{}`",
                    t.elems.len(),
                    a.usage
                ),
            );
            return None;
        }
        _ => Local::Polar(a.number("distance", false)?, a.number("angle", true)?),
    };
    Some(Kind::Point { link, from, local })
}

/// A pair `(x, y)` of numbers (L), in the role `role`.
fn pair(a: &mut Args, role: &str) -> Option<(Value, Value)> {
    let scope = a.scope;
    match a.next(role)? {
        Arg::Value(Expr::Tuple(t), None) if t.elems.len() == 2 => {
            let x = convert(&t.elems[0], scope)
                .map_err(|e| a.errors.error(e))
                .ok()?;
            let y = convert(&t.elems[1], scope)
                .map_err(|e| a.errors.error(e))
                .ok()?;
            Some((x, y))
        }
        other => {
            let span = match other {
                Arg::Value(e, _) => e.span(),
                Arg::From(i) => i.span(),
            };
            a.fail(
                span,
                format!(
                    "expected {role} as `(x, y)`, two numbers; usage: `{}`",
                    a.usage
                ),
            );
            None
        }
    }
}

/// `INPUT = value`: the input at which a triad's pose hint holds (an angle
/// in `deg` or `rad`, or a length).
fn input_at(a: &mut Args) -> Option<(Ident, Value)> {
    let scope = a.scope;
    let role = "input at which the pose holds";
    let arg = a.next(role)?;
    let bad = |a: &mut Args, span: proc_macro2::Span| {
        a.fail(
            span,
            format!(
                "expected the {role}, `INPUT = value` (e.g. `phi = -49.48 deg`); usage: `{}`",
                a.usage
            ),
        );
    };
    let Arg::Value(Expr::Assign(e), unit) = arg else {
        let span = match arg {
            Arg::Value(e, _) => e.span(),
            Arg::From(i) => i.span(),
        };
        bad(a, span);
        return None;
    };
    let name = match &*e.left {
        Expr::Path(p) if p.path.get_ident().is_some() => p.path.get_ident()?.clone(),
        other => {
            bad(a, other.span());
            return None;
        }
    };
    let value = convert(&e.right, scope)
        .map_err(|err| a.errors.error(err))
        .ok()?;
    let value = match unit {
        None => value,
        Some(u) if u == "deg" => value.degrees(),
        Some(u) if u == "rad" => value,
        Some(u) => {
            a.fail(
                u.span(),
                format!(
                    "unknown unit `{u}`; write `deg` or `rad` for an angle, nothing for a length"
                ),
            );
            return None;
        }
    };
    Some((name, value))
}

/// `let (A, B, P) = triad(K1, l1, K2, l2, K3, l3, ab, P's place, INPUT =
/// value, (ax, ay), (bx, by), (px, py))`, P's place `distance, angle` or
/// `(x, y)` in the ternary's frame.
fn triad(a: &mut Args, stmt: &parse::Let) -> Option<Kind> {
    let [b, p] = match &stmt.joints[..] {
        [b, p] => [b.clone(), p.clone()],
        _ => {
            let name = &stmt.name;
            a.fail(
                name.span(),
                format!(
                    "a triad defines three joints: write `let ({name}, B, P) = triad(..)` with the names of the ternary link's other two joints"
                ),
            );
            return None;
        }
    };
    let k1 = a.name("first leg's known point")?;
    let l1 = a.length("first leg's length")?;
    let k2 = a.name("second leg's known point")?;
    let l2 = a.length("second leg's length")?;
    let k3 = a.name("third leg's known point")?;
    let l3 = a.length("third leg's length")?;
    let ab = a.length("ternary link's side |AB|")?;
    let scope = a.scope;
    let p_local = match stmt.args.get(7) {
        Some(Arg::Value(Expr::Tuple(t), None)) if t.elems.len() == 2 => {
            a.args.next();
            let x = convert(&t.elems[0], scope)
                .map_err(|e| a.errors.error(e))
                .ok()?;
            let y = convert(&t.elems[1], scope)
                .map_err(|e| a.errors.error(e))
                .ok()?;
            Local::Cartesian(x, y)
        }
        _ => Local::Polar(
            a.number("distance |AP|", false)?,
            a.number("angle of P from A -> B", true)?,
        ),
    };
    let at = input_at(a)?;
    let near = [
        pair(a, "the approximate position of A")?,
        pair(a, "the approximate position of B")?,
        pair(a, "the approximate position of P")?,
    ];
    Some(Kind::Triad(Box::new(Triad {
        k: [k1, k2, k3],
        l: [l1, l2, l3],
        ab,
        p_local,
        b,
        p,
        at,
        near,
    })))
}
