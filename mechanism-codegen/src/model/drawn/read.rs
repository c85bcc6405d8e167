//! Reading the drawn items: each joint's coordinates (as written, and
//! valued at the parameters' defaults), each link's joints, each input's
//! link; malformed entries are reported on their tokens and left out.

use super::{Coordinate, Cylinder, Drawing, Input, Joint, JointId, Link, LinkId, Slider, GROUND};
use crate::diag::{did_you_mean, Diagnostics};
use crate::model::args::NumberScope;
use crate::parse::{Assign, DrawnCylinder, DrawnSlider, Item};
use crate::value::convert;
use proc_macro2::Span;
use syn::{Expr, Ident};

/// Reads the drawn items into a [`Drawing`], reporting malformed entries
/// (left out of it).
pub(super) fn read(items: Vec<Item>, scope: &NumberScope<'_>, errors: &mut Diagnostics) -> Drawing {
    let mut drawing = Drawing {
        joints: Vec::new(),
        links: Vec::new(),
        inputs: Vec::new(),
        sliders: Vec::new(),
        cylinders: Vec::new(),
        gears: Vec::new(),
        span: Span::call_site(),
    };
    let mut cylinders = Vec::new();
    let mut link_lists = Vec::new();
    let mut sliders = Vec::new();
    let mut gears = Vec::new();
    // Every joint written, drawn well or not (a malformed one is reported
    // once, where it is drawn, not again in each link that lists it).
    let mut all_joints = Vec::new();
    for item in items {
        match item {
            Item::Joints(_, list) => {
                all_joints.extend(list.iter().map(|a| a.name.to_string()));
                for a in list {
                    if let Some(j) = read_joint(a, scope, errors) {
                        drawing.joints.push(j);
                    }
                }
            }
            Item::Links(span, list) => {
                drawing.span = span;
                link_lists.extend(list);
            }
            Item::Input(name, value) => {
                if let Some(i) = read_input(name, &value, errors) {
                    drawing.inputs.push(i);
                }
            }
            Item::Slider(s) => sliders.push(s),
            Item::Cylinder(c) => cylinders.push(c),
            Item::Gear(g) => gears.push(g),
            _ => {}
        }
    }
    for a in link_lists {
        if let Some(l) = read_link(a, &drawing.joints, &all_joints, errors) {
            drawing.links.push(l);
        }
    }
    let mut ons = Vec::new();
    for s in sliders {
        if let Some(on) = read_slider(&mut drawing, s, scope, errors) {
            ons.push(on);
        }
    }
    // Blocks may slide on blocks (the sine mechanism's yoke), so what a
    // block slides on is found once every block is a link.
    for (k, on) in ons.into_iter().enumerate() {
        drawing.sliders[k].on = slid_on(&drawing, k, &on, errors);
    }
    for c in cylinders {
        read_cylinder(&mut drawing, c, errors);
    }
    for g in gears {
        if let Some(g) = super::gear::read(&drawing, g, scope, errors) {
            drawing.gears.push(g);
        }
    }
    drawing
}

/// The moving link `on` that the block of `sliders[k]` slides on (`None`:
/// the ground, or an error reported: no such link, or the block's joint
/// pinned to it as well).
fn slid_on(d: &Drawing, k: usize, on: &Ident, errors: &mut Diagnostics) -> Option<LinkId> {
    if on == GROUND {
        return None;
    }
    let s = &d.sliders[k];
    let block = &d.link(s.link).name;
    let Some(link) = d.link_named(on) else {
        let names = d
            .links
            .iter()
            .map(|l| l.name.to_string())
            .collect::<Vec<_>>();
        errors.push(
            on.span(),
            format!(
                "no link named `{on}` for `{block}` to slide on{}",
                did_you_mean(&on.to_string(), names.iter().map(String::as_str))
            ),
        );
        return None;
    };
    let at = &d.joint(s.at).name;
    if link == s.link {
        errors.push(on.span(), format!("`{block}` cannot slide on itself"));
    } else if d.link(link).joints.contains(&s.at) {
        errors.push(
            on.span(),
            format!("`{at}` is a joint of `{on}` (a pin), so `{block}` cannot slide on `{on}` there: leave `{at}` out of `{on} = [..]`, the slot is the block's line"),
        );
    }
    Some(link)
}

/// `cylinder CYL from B to C;`: both joints drawn, and distinct.
fn read_cylinder(d: &mut Drawing, c: DrawnCylinder, errors: &mut Diagnostics) {
    let names = d
        .joints
        .iter()
        .map(|j| j.name.to_string())
        .collect::<Vec<_>>();
    let mut ends = [JointId(0); 2];
    for (k, end) in [&c.from, &c.to].into_iter().enumerate() {
        let Some(id) = d.joints.iter().position(|j| &j.name == end) else {
            errors.push(
                end.span(),
                format!(
                    "no joint named `{end}` is drawn{}",
                    did_you_mean(&end.to_string(), names.iter().map(String::as_str))
                ),
            );
            return;
        };
        ends[k] = JointId(id);
    }
    if ends[0] == ends[1] {
        errors.push(
            c.to.span(),
            format!(
                "a cylinder joins two joints, and `{}` is both its ends",
                c.to
            ),
        );
        return;
    }
    for n in &c.names {
        if d.links.iter().any(|l| &l.name == n) {
            errors.push(
                n.span(),
                format!("`{n}` is a link already; a cylinder's links have names of their own"),
            );
            return;
        }
    }
    d.cylinders.push(Cylinder {
        names: c.names,
        from: ends[0],
        to: ends[1],
    });
}

/// `slider BLOCK at J on LINK along angle;`: the block becomes a link with
/// the one joint `J`, sliding on `LINK` (the ground or a moving link) along
/// the line through `J`'s drawn place; the name `LINK` comes back (found
/// once every block is read), `None` when the statement is rejected.
fn read_slider(
    d: &mut Drawing,
    s: DrawnSlider,
    scope: &NumberScope<'_>,
    errors: &mut Diagnostics,
) -> Option<Ident> {
    if d.links.iter().any(|l| l.name == s.block) {
        errors.push(
            s.block.span(),
            format!("`{}` is a link of `links {{ .. }}` already; a slider's block is a link of its own: give it a name of its own", s.block),
        );
        return None;
    }
    let Some(at) = d.joints.iter().position(|j| j.name == s.at).map(JointId) else {
        let names = d
            .joints
            .iter()
            .map(|j| j.name.to_string())
            .collect::<Vec<_>>();
        errors.push(
            s.at.span(),
            format!(
                "no joint named `{}` is drawn{}",
                s.at,
                did_you_mean(&s.at.to_string(), names.iter().map(String::as_str))
            ),
        );
        return None;
    };
    let angle = match convert(&s.angle, scope) {
        Ok(v) => v,
        Err(e) => {
            errors.error(e);
            return None;
        }
    };
    let defaults = |p: &Ident| scope.params.iter().find(|(n, _)| n == p).map(|(_, v)| *v);
    let mut a = angle.eval_with(&defaults)?;
    if s.unit.as_ref().is_some_and(|u| u == "deg") {
        a = a.to_radians();
    }
    d.links.push(Link {
        name: s.block,
        joints: vec![at],
    });
    d.sliders.push(Slider {
        link: LinkId(d.links.len() - 1),
        at,
        angle: s.angle,
        unit: s.unit,
        dir: (a.cos(), a.sin()),
        on: None,
    });
    Some(s.on)
}

/// `NAME = (x, y)`: a joint at the reference pose.
fn read_joint(a: Assign, scope: &NumberScope<'_>, errors: &mut Diagnostics) -> Option<Joint> {
    let Expr::Tuple(t) = &a.value else {
        errors.push(
            a.name.span(),
            format!("a joint is where the drawing has it, `{} = (x, y)`", a.name),
        );
        return None;
    };
    if t.elems.len() != 2 {
        errors.push(
            a.name.span(),
            format!("a joint has two coordinates, `{} = (x, y)`", a.name),
        );
        return None;
    }
    let (x, y) = (t.elems[0].clone(), t.elems[1].clone());
    let defaults = |p: &Ident| scope.params.iter().find(|(n, _)| n == p).map(|(_, v)| *v);
    let mut at = [0.0; 2];
    for (k, e) in [&x, &y].into_iter().enumerate() {
        match convert(e, scope) {
            Ok(v) => at[k] = v.eval_with(&defaults)?,
            Err(e) => {
                errors.error(e);
                return None;
            }
        }
    }
    Some(Joint {
        name: a.name,
        x,
        y,
        at: (at[0], at[1]),
    })
}

/// `NAME = [J1, J2, ..]`: a link and its joints. `joints`: the joints
/// drawn; `written`: every joint name written (a malformed joint is
/// reported where it is drawn, and the link is left out silently).
fn read_link(
    a: Assign,
    joints: &[Joint],
    written: &[String],
    errors: &mut Diagnostics,
) -> Option<Link> {
    let usage = format!("a link is the list of its joints, `{} = [A, B]`", a.name);
    let Expr::Array(list) = &a.value else {
        errors.push(a.name.span(), usage);
        return None;
    };
    let mut out = Vec::new();
    for e in &list.elems {
        let Expr::Path(p) = e else {
            errors.error(syn::Error::new_spanned(e, &usage));
            return None;
        };
        let Some(name) = p.path.get_ident() else {
            errors.error(syn::Error::new_spanned(e, &usage));
            return None;
        };
        let s = name.to_string();
        if written.contains(&s) && !joints.iter().any(|j| &j.name == name) {
            return None;
        }
        if !written.contains(&s) {
            errors.push(
                name.span(),
                format!(
                    "no joint named `{s}` is drawn: add it to `joints {{ .. }}`, `{s} = (x, y)`{}",
                    did_you_mean(&s, written.iter().map(String::as_str))
                ),
            );
            return None;
        }
        let id = JointId(joints.iter().position(|j| &j.name == name)?);
        if out.contains(&id) {
            errors.push(
                name.span(),
                format!("`{s}` is listed twice in link `{}`", a.name),
            );
            return None;
        }
        out.push(id);
    }
    // The ground may have no pin at all: a trammel's frame carries only
    // the lines its blocks slide on (`ground = []`).
    if a.name != GROUND && out.len() < 2 {
        errors.push(
            a.name.span(),
            format!(
                "link `{}` has {}; a moving link joins at least two",
                a.name,
                crate::diag::counted(out.len() as i64, "joint", "joints")
            ),
        );
        return None;
    }
    Some(Link {
        name: a.name,
        joints: out,
    })
}

/// `angle(LINK)` or `angle(LINK, CARRIER)`.
fn read_input(name: Ident, value: &Expr, errors: &mut Diagnostics) -> Option<Input> {
    let usage = format!(
        "an input is a link's angle, `input {name} = angle(crank);` (from the ground) or `input {name} = angle(shank, thigh);` (from the link carrying its motor), or a block's slide, `input {name} = slide(block);`, or a cylinder's length, `input {name} = length(cylinder);`, or a joint's coordinate, `input {name} = P.x;` with `P.y` an input too (inverse kinematics)"
    );
    let ident = |e: &Expr| match e {
        Expr::Path(p) => p.path.get_ident().cloned(),
        _ => None,
    };
    if let Expr::Field(f) = value {
        let axis = match &f.member {
            syn::Member::Named(m) if m == "x" => Some(Coordinate::X),
            syn::Member::Named(m) if m == "y" => Some(Coordinate::Y),
            _ => None,
        };
        if let (Some(joint), Some(axis)) = (ident(&f.base), axis) {
            return Some(Input {
                name,
                link: joint,
                carrier: None,
                slide: false,
                length: false,
                coordinate: Some(axis),
            });
        }
    }
    let Expr::Call(call) = value else {
        errors.error(syn::Error::new_spanned(value, usage));
        return None;
    };
    let word = ident(&call.func).map(|i| i.to_string());
    let args: Vec<Option<Ident>> = call.args.iter().map(ident).collect();
    match (word.as_deref(), args.as_slice()) {
        (Some("angle"), [Some(link)]) => Some(Input {
            name,
            link: link.clone(),
            carrier: None,
            slide: false,
            coordinate: None,
            length: false,
        }),
        (Some("angle"), [Some(link), Some(carrier)]) => Some(Input {
            name,
            link: link.clone(),
            carrier: (carrier != GROUND).then(|| carrier.clone()),
            slide: false,
            coordinate: None,
            length: false,
        }),
        (Some("slide"), [Some(block)]) => Some(Input {
            name,
            link: block.clone(),
            carrier: None,
            slide: true,
            coordinate: None,
            length: false,
        }),
        (Some("length"), [Some(cylinder)]) => Some(Input {
            name,
            link: cylinder.clone(),
            carrier: None,
            slide: false,
            length: true,
            coordinate: None,
        }),
        _ => {
            errors.error(syn::Error::new_spanned(value, usage));
            None
        }
    }
}
