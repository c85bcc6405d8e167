//! The drawn gear pair, `gear LINK to MESH ratio R [on CARRIER] [pressure
//! ANGLE];`: read (its links named, its ratio neither 0 nor -1), checked
//! (`MESH` and `CARRIER` each the ground or a crank on the ground, `LINK`
//! pivoted on `CARRIER` and driven by nothing else), placed (once its
//! pivot, `MESH` and `CARRIER` are) and written as the `gear` statement of
//! the group form, its pitch-circle radius, pivot and phase read from the
//! drawing (`kinds::gear` is the one implementation).

use super::steps::{next_joint, Frame, Placed, Step};
use super::{Drawing, JointId, LinkId, GROUND};
use crate::diag::{did_you_mean, Diagnostics};
use crate::model::args::NumberScope;
use crate::parse::{Arg, DrawnGear};
use crate::value::convert;
use syn::{Expr, Ident};

/// A gear pair of the drawing: `link` turns about its joint on `carrier`
/// (`None`: the ground), geared to `mesh` (`None`: a fixed gear, the
/// ground) at `ratio` (`MESH`'s pitch radius over `LINK`'s, as written);
/// the names as written, for messages and for the statement.
pub(super) struct Gear {
    pub link: LinkId,
    pub mesh: Option<LinkId>,
    pub carrier: Option<LinkId>,
    pub ratio: Expr,
    pub pressure: Option<(Expr, Option<Ident>)>,
    pub names: DrawnGear,
}

/// Reads `g` once every link (blocks included) is read: its links named,
/// its ratio a number other than 0 and -1 at the parameters' defaults;
/// `None` with an error on the offending token otherwise.
pub(super) fn read(
    d: &Drawing,
    g: DrawnGear,
    scope: &NumberScope<'_>,
    errors: &mut Diagnostics,
) -> Option<Gear> {
    let names: Vec<String> = d.links.iter().map(|l| l.name.to_string()).collect();
    let find = |n: &Ident, errors: &mut Diagnostics| {
        let found = d.link_named(n);
        if found.is_none() {
            errors.push(
                n.span(),
                format!(
                    "no link named `{n}`{}",
                    did_you_mean(&n.to_string(), names.iter().map(String::as_str))
                ),
            );
        }
        found
    };
    let link = find(&g.link, errors)?;
    if g.link == GROUND {
        errors.push(
            g.link.span(),
            "the ground does not turn; a gear is a moving link, geared to another: `gear link5 to link2 ratio 2.0;`",
        );
        return None;
    }
    let mesh = match g.mesh == GROUND {
        true => None,
        false => Some(find(&g.mesh, errors)?),
    };
    let carrier = match g.carrier.as_ref().filter(|c| *c != GROUND) {
        Some(c) => Some(find(c, errors)?),
        None => None,
    };
    let value = match convert(&g.ratio, scope) {
        Ok(v) => v,
        Err(e) => {
            errors.error(e);
            return None;
        }
    };
    let defaults = |p: &Ident| scope.params.iter().find(|(n, _)| n == p).map(|(_, v)| *v);
    let r = value.eval_with(&defaults)?;
    if r == 0.0 || r == -1.0 {
        errors.error(syn::Error::new_spanned(
            &g.ratio,
            format!("a gear ratio of {r} couples nothing (0: no gear; -1: an internal pair of equal gears, which has no center distance); the ratio is the pitch radius of `{}`'s gear over `{}`'s, positive for external gears, negative for an internal pair: `gear {} to {} ratio 2.0;`", g.mesh, g.link, g.link, g.mesh),
        ));
        return None;
    }
    Some(Gear {
        link,
        mesh,
        carrier,
        ratio: g.ratio.clone(),
        pressure: g.pressure.clone(),
        names: g,
    })
}

/// The link of a crank on the ground: an input's `angle(LINK)` from the
/// ground, `LINK` with a joint on the ground.
fn crank_on_ground(d: &Drawing, l: LinkId) -> bool {
    let name = &d.link(l).name;
    let driven = d.inputs.iter().any(|i| {
        &i.link == name && i.carrier.is_none() && !i.slide && !i.length && i.coordinate.is_none()
    });
    let on_ground = d.ground().is_some_and(|g| {
        let fixed = &d.link(g).joints;
        d.link(l).joints.iter().any(|j| fixed.contains(j))
    });
    driven && on_ground && d.slider_of(l).is_none()
}

/// `MESH` and `CARRIER` each the ground or a crank on the ground, not the
/// same link; `LINK` neither of them, driven by no input and no other gear,
/// with a joint on its carrier. `false` with errors otherwise.
pub(super) fn gears_hold(d: &Drawing, errors: &mut Diagnostics) -> bool {
    let before = errors.len();
    for (k, g) in d.gears.iter().enumerate() {
        let n = &g.names;
        let on = n
            .carrier
            .clone()
            .unwrap_or_else(|| Ident::new(GROUND, n.link.span()));
        let roles = [
            (
                g.mesh,
                &n.mesh,
                "mesh with",
                "meshes with `ground` (a fixed gear)",
            ),
            (g.carrier, &on, "turn on", "turns on `ground`"),
        ];
        for (l, name, verb, or_ground) in roles {
            if l.is_some_and(|l| !crank_on_ground(d, l)) {
                errors.push(
                    name.span(),
                    format!("`{name}` is not a crank on the ground, so `{}` cannot {verb} it (the gears' center distance would change): a drawn gear {or_ground} or a link with a joint on the ground that an input turns from the ground (`input q = angle({name});`)", n.link),
                );
            }
        }
        if g.mesh == g.carrier {
            errors.push(
                n.mesh.span(),
                format!("`{}` meshes with `{}`, the link it turns on, so it cannot turn on it: mesh it with another link (`ground`, a fixed gear, when it is carried by a crank)", n.link, n.mesh),
            );
        }
        if Some(g.link) == g.mesh || Some(g.link) == g.carrier {
            errors.push(
                n.link.span(),
                format!(
                    "`{}` is geared to itself; a gear pair joins two links",
                    n.link
                ),
            );
        }
        let driven = d.inputs.iter().find(|i| i.link == n.link);
        if let Some(i) = driven {
            errors.push(
                n.link.span(),
                format!("`{}` is turned by the input `{}` already, so its gear would fix it: drop the input or the gear", n.link, i.name),
            );
        } else if d.gears[..k].iter().any(|h| h.link == g.link) {
            errors.push(
                n.link.span(),
                format!("`{}` is geared twice; a link takes one gear pair", n.link),
            );
        } else if d.slider_of(g.link).is_some() {
            errors.push(
                n.link.span(),
                format!("`{}` is a slider's block, which does not turn: a gear is a link that turns about a joint", n.link),
            );
        } else if pivot_joint(d, g).is_none() {
            errors.push(
                n.link.span(),
                format!("`{}` has no joint on `{on}`, the link it turns on: list its pivot in both, or name the carrier, `gear {} to {} ratio .. on CARRIER;`", n.link, n.link, n.mesh),
            );
        }
    }
    errors.len() == before
}

/// The joint of a gear's link on its carrier (its pivot).
fn pivot_joint(d: &Drawing, g: &Gear) -> Option<JointId> {
    let carrier = g.carrier.or(d.ground())?;
    let on = &d.link(carrier).joints;
    d.link(g.link)
        .joints
        .iter()
        .copied()
        .find(|j| on.contains(j))
}

/// Places gear `k` when its pivot, its mesh and its carrier are placed;
/// its axis points from the pivot to the link's next joint as listed.
/// `true` when placed.
pub(super) fn place(d: &Drawing, k: usize, placed: &mut Placed, steps: &mut Vec<Step>) -> bool {
    let g = &d.gears[k];
    let Some(ground) = d.ground() else {
        return false;
    };
    if placed.frame(g.link).is_some() {
        return false;
    }
    let (mesh, carrier) = (g.mesh.unwrap_or(ground), g.carrier.unwrap_or(ground));
    let (Some(mesh_frame), Some(carrier_frame)) = (placed.frame(mesh), placed.frame(carrier))
    else {
        return false;
    };
    let Some(pivot) = pivot_joint(d, g).filter(|&j| placed.joint(j)) else {
        return false;
    };
    let tip = next_joint(&d.link(g.link).joints, pivot);
    let frame = Frame {
        origin: pivot,
        toward: tip,
    };
    steps.push(Step::Gear {
        gear: k,
        frame,
        mesh: g.mesh.map(|_| mesh_frame),
        carrier: g.carrier.map(|_| carrier_frame),
    });
    placed.place(tip);
    placed.set_frame(g.link, pivot, tip);
    true
}

/// The arguments of `gear(PIVOT, r, MESH, ratio, phase, CARRIER[,
/// pressure_angle])` for gear `k` placed in `frame`, its mesh's and
/// carrier's frames as placed (`None`: the ground). The phase is the
/// drawing's: with `a(F)` a frame's drawn angle (rad, from +x, in (-pi,
/// pi], the value of a crank's input as drawn) and the ground's 0,
/// `phase = (a(L) - a(C)) + ratio (a(M) - a(C))`, the gear law
/// `a(L) - a(C) = phase - ratio (a(M) - a(C))` solved at the drawn pose.
/// `a(L) - a(C)` is taken as the turn from the carrier's frame to the
/// link's (`atan2(u x v, u . v)`: whole turns of the link do not matter);
/// the mesh's and carrier's angles each as drawn, since the ratio scales
/// their whole turns.
pub(super) fn args(
    d: &Drawing,
    k: usize,
    frame: Frame,
    mesh: Option<Frame>,
    carrier: Option<Frame>,
) -> Vec<Arg> {
    use super::exprs::{angle_of, distance, name, name_arg, turn, value};
    use quote::quote;
    let g = &d.gears[k];
    let (pivot, tip) = (d.joint(frame.origin), d.joint(frame.toward));
    let own = match carrier {
        Some(c) => turn(d, c, frame),
        None => angle_of(d, frame),
    };
    let ratio = &g.ratio;
    let phase = match (mesh, carrier) {
        (Some(m), Some(c)) => {
            let (m, c) = (angle_of(d, m), angle_of(d, c));
            quote!(#own + (#ratio) * (#m - #c))
        }
        (Some(m), None) => {
            let m = angle_of(d, m);
            quote!(#own + (#ratio) * #m)
        }
        (None, Some(c)) => {
            let c = angle_of(d, c);
            quote!(#own - (#ratio) * #c)
        }
        (None, None) => own,
    };
    let span = tip.name.span();
    let ground = || Ident::new(GROUND, g.names.link.span());
    let mesh_name = g.mesh.map_or_else(ground, |l| d.link(l).name.clone());
    let carrier_name = g.carrier.map_or_else(ground, |l| d.link(l).name.clone());
    let mut out = vec![
        name(pivot),
        value(distance(pivot, tip), span),
        name_arg(&mesh_name),
        Arg::Value(ratio.clone(), None),
        value(phase, span),
        name_arg(&carrier_name),
    ];
    if let Some((angle, unit)) = &g.pressure {
        out.push(Arg::Value(angle.clone(), unit.clone()));
    }
    out
}
