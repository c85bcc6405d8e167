//! Each decomposition step as the `let` statement a user would write: its
//! lengths, offsets and angles as expressions of the joints' coordinates
//! (the lowering folds them when literal, and computes them once per call
//! from `params`), its assembly mode from the drawing, its spans on the
//! user's names.

use super::exprs::{distance, name, name_arg, turn, value};
use super::steps::{side, Axis, Frame, Step};
use super::{Drawing, Joint, JointId, LinkId, Slider};
use crate::parse::vocabulary::KindWord;
use crate::parse::{Arg, Let};
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

/// The `let` statement of one step.
pub(super) fn statement(d: &Drawing, step: &Step) -> Let {
    let j = |k: JointId| d.joint(k);
    let l = |k: LinkId| &d.link(k).name;
    let (defines, kind, args, links): (&Joint, KindWord, Vec<Arg>, Vec<Ident>) = match *step {
        Step::Ground(k) => {
            // The user's own coordinates, with their spans.
            let (x, y) = (j(k).x.clone(), j(k).y.clone());
            (
                j(k),
                KindWord::Ground,
                vec![Arg::Value(x, None), Arg::Value(y, None)],
                vec![],
            )
        }
        Step::Crank {
            link,
            frame,
            input,
            carrier,
        } => {
            let input = &d.input(input).name;
            let (pivot, tip) = (j(frame.origin), j(frame.toward));
            let mut args = vec![
                name(pivot),
                value(distance(pivot, tip), tip.name.span()),
                name_arg(input),
            ];
            if let Some(c) = carrier {
                args.push(name_arg(l(c.link)));
                if c.frame != c.listed {
                    args.push(value(turn(d, c.frame, c.listed), input.span()));
                }
            }
            (tip, KindWord::Crank, args, vec![l(link).clone()])
        }
        Step::Rrr { a, la, b, lb, c } => {
            let (a, b, c) = (j(a), j(b), j(c));
            let word = if side(a.at, b.at, c.at) > 0.0 {
                "left"
            } else {
                "right"
            };
            let mode = Ident::new(word, c.name.span());
            let args = vec![
                name(a),
                value(distance(a, c), c.name.span()),
                name(b),
                value(distance(b, c), c.name.span()),
                name_arg(&mode),
            ];
            (c, KindWord::Rrr, args, vec![l(la).clone(), l(lb).clone()])
        }
        Step::Triad { .. } => return triad(d, step),
        Step::Rpr { .. } | Step::CarriedGuide { .. } | Step::Mark { .. } => {
            return slot_statement(d, step)
        }
        Step::SlotPoint { .. }
        | Step::RrpCarried { .. }
        | Step::Rpp { .. }
        | Step::Prp { .. }
        | Step::Actuator { .. } => slot_joint(d, step),
        Step::Guide(k) => return guide(d, k),
        Step::Slide { slider, input } => {
            let s = &d.sliders[slider];
            let args = vec![
                name_arg(&line_name(d, slider)),
                name_arg(&d.input(input).name),
            ];
            (j(s.at), KindWord::Slider, args, vec![l(s.link).clone()])
        }
        Step::Rrp { a, la, c, slider } => {
            let s = &d.sliders[slider];
            let args = rrp_args(d, j(a), j(c), slider);
            (
                j(c),
                KindWord::Rrp,
                args,
                vec![l(la).clone(), l(s.link).clone()],
            )
        }
        Step::Target { joint, x, y } => {
            let args = vec![name_arg(&d.input(x).name), name_arg(&d.input(y).name)];
            (j(joint), KindWord::Target, args, vec![effector(j(joint))])
        }
        Step::Gear {
            gear,
            frame,
            mesh,
            carrier,
        } => {
            let args = super::gear::args(d, gear, frame, mesh, carrier);
            let link = l(d.gears[gear].link).clone();
            (j(frame.toward), KindWord::Gear, args, vec![link])
        }
        Step::Point { link, frame, joint } => {
            let (x, y) = local(j(frame.origin), j(frame.toward), j(joint));
            let args = vec![
                name_arg(l(link)),
                Arg::From(j(frame.origin).name.clone()),
                value(quote!((#x, #y)), j(joint).name.span()),
            ];
            (j(joint), KindWord::Point, args, vec![])
        }
    };
    let span = defines.name.span();
    let slides = block_slides(kind, &links);
    Let {
        name: defines.name.clone(),
        joints: Vec::new(),
        word: Some(kind),
        kind: kind.ident(span),
        args,
        args_span: span,
        links,
        slides,
    }
}

/// The names of the slides a group with blocks has, each `BLOCK_slide` as
/// an RPR's is (`links`: the group's, in its statement's order): an RRP's
/// block along its line (its second link); a PRP's two blocks, each along
/// its own line; an RPP's block along the slot, then the yoke along its
/// line. Each is measured from its line's origin (`assembly-modes.md`).
fn block_slides(kind: KindWord, links: &[Ident]) -> Vec<Ident> {
    let slide = |l: &Ident| Ident::new(&format!("{l}_slide"), l.span());
    match kind {
        KindWord::Rrp => links.get(1).map(slide).into_iter().collect(),
        KindWord::Prp | KindWord::Rpp => links.iter().take(2).map(slide).collect(),
        _ => Vec::new(),
    }
}

/// The effector of a target joint `J`, the body that moves with it and
/// does not turn: `J_effector`.
pub(super) fn effector(j: &Joint) -> Ident {
    Ident::new(&format!("{}_effector", j.name), j.name.span())
}

/// What a step of a block on a moving link or of a cylinder that defines a
/// joint writes: the joint, its kind, its arguments, its links.
fn slot_joint<'d>(d: &'d Drawing, step: &Step) -> (&'d Joint, KindWord, Vec<Arg>, Vec<Ident>) {
    let j = |k: JointId| d.joint(k);
    let l = |k: LinkId| &d.link(k).name;
    match *step {
        Step::SlotPoint {
            link,
            pivot,
            slider,
            joint,
        } => {
            let (p, at) = (j(pivot), j(joint));
            let (x, y) = local_along(p, &d.sliders[slider], at);
            let args = vec![
                name_arg(l(link)),
                Arg::From(p.name.clone()),
                value(quote!((#x, #y)), at.name.span()),
            ];
            (at, KindWord::Point, args, vec![])
        }
        Step::RrpCarried {
            a,
            la,
            c,
            slider,
            origin,
        } => {
            let s = &d.sliders[slider];
            let (a, c) = (j(a), j(c));
            let mut args = rrp_args(d, a, c, slider);
            args.push(value(offset(j(origin), s, c), c.name.span()));
            (
                c,
                KindWord::Rrp,
                args,
                vec![l(la).clone(), l(s.link).clone()],
            )
        }
        Step::Rpp {
            j: pin,
            slider,
            yoke,
            origin,
        } => {
            let (s, y) = (&d.sliders[slider], &d.sliders[yoke]);
            let (a, b) = (radians(s), radians(y));
            let mut args = vec![
                name(j(pin)),
                name_arg(&line_name(d, yoke)),
                value(quote!(#a - #b), l(s.link).span()),
            ];
            if let Some(o) = origin {
                args.push(value(offset(j(o), y, j(y.at)), j(y.at).name.span()));
            }
            let links = vec![l(s.link).clone(), l(y.link).clone()];
            (j(y.at), KindWord::Rpp, args, links)
        }
        Step::Prp {
            c,
            sliders,
            origins,
        } => {
            let c = j(c);
            let mut args: Vec<Arg> = sliders
                .iter()
                .map(|&k| name_arg(&line_name(d, k)))
                .collect();
            if origins.iter().any(Option::is_some) {
                for (k, o) in sliders.into_iter().zip(origins) {
                    let e = match o {
                        Some(o) => offset(j(o), &d.sliders[k], c),
                        None => quote!(0.0),
                    };
                    args.push(value(e, c.name.span()));
                }
            }
            let links = sliders.iter().map(|&k| l(d.sliders[k].link).clone());
            (c, KindWord::Prp, args, links.collect())
        }
        Step::Actuator {
            a,
            link,
            b,
            c,
            cylinder,
            input,
        } => {
            let (a, b, c) = (j(a), j(b), j(c));
            let word = if side(a.at, b.at, c.at) > 0.0 {
                "left"
            } else {
                "right"
            };
            let args = vec![
                name(a),
                value(distance(a, c), c.name.span()),
                name(b),
                name_arg(&d.input(input).name),
                name_arg(&Ident::new(word, c.name.span())),
            ];
            let mut links = vec![l(link).clone()];
            links.extend(d.cylinders[cylinder].names.iter().cloned());
            (c, KindWord::Actuator, args, links)
        }
        _ => unreachable!("slot_joint() is called on the steps it matches"),
    }
}

/// An RRP's first four arguments: the known joint `a`, its drawn distance
/// to `c`, the line of `sliders[slider]` and the mode `c` is drawn in.
fn rrp_args(d: &Drawing, a: &Joint, c: &Joint, slider: usize) -> Vec<Arg> {
    vec![
        name(a),
        value(distance(a, c), c.name.span()),
        name_arg(&line_name(d, slider)),
        name_arg(&ahead(a, c, &d.sliders[slider])),
    ]
}

/// The mode a block's line gives a group: `plus` when the drawing has `to`
/// ahead of `from` along the line's direction (`dot(to - from, dir) > 0`),
/// `minus` behind it; spanned on `to`.
fn ahead(from: &Joint, to: &Joint, s: &Slider) -> Ident {
    let along = (to.at.0 - from.at.0) * s.dir.0 + (to.at.1 - from.at.1) * s.dir.1;
    Ident::new(if along > 0.0 { "plus" } else { "minus" }, to.name.span())
}

/// The name of the line the block of `sliders[k]` slides on: `BLOCK_line`.
fn line_name(d: &Drawing, k: usize) -> Ident {
    let block = &d.link(d.sliders[k].link).name;
    Ident::new(&format!("{block}_line"), block.span())
}

/// `let BLOCK_line = guide((x, y), angle);`: the ground's line through the
/// block's joint as drawn.
fn guide(d: &Drawing, k: usize) -> Let {
    let s = &d.sliders[k];
    let (x, y) = (&d.joint(s.at).x, &d.joint(s.at).y);
    let name = line_name(d, k);
    let span = name.span();
    Let {
        name,
        joints: Vec::new(),
        word: Some(KindWord::Guide),
        kind: KindWord::Guide.ident(span),
        args: vec![
            value(quote!((#x, #y)), d.joint(s.at).name.span()),
            Arg::Value(s.angle.clone(), s.unit.clone()),
        ],
        args_span: span,
        links: Vec::new(),
        slides: Vec::new(),
    }
}

/// The triad's `let (A, B, P) = triad(..) as (LEG1, LEG2, LEG3, T)`: the
/// legs' lengths, the side `|AB|` and `P` in the frame `A -> B` from the
/// drawing; its assembly: the drawn joints at the drawn value of the input.
fn triad(d: &Drawing, step: &Step) -> Let {
    let Step::Triad {
        t,
        joints,
        legs,
        known,
    } = *step
    else {
        unreachable!("triad() is called on a triad step");
    };
    let j = |k: JointId| d.joint(k);
    let mut args = Vec::new();
    for i in 0..3 {
        args.push(name(j(known[i])));
        args.push(value(
            distance(j(known[i]), j(joints[i])),
            j(joints[i]).name.span(),
        ));
    }
    let [a, b, p] = joints.map(j);
    args.push(value(distance(a, b), b.name.span()));
    let (x, y) = local(a, b, p);
    args.push(value(quote!((#x, #y)), p.name.span()));
    let input = &d.inputs[0].name;
    let at = drawn_input(d);
    args.push(value(quote!(#input = #at), input.span()));
    for k in joints {
        let (x, y) = (&j(k).x, &j(k).y);
        args.push(value(quote!((#x, #y)), j(k).name.span()));
    }
    let span = a.name.span();
    let links = legs.iter().chain([&t]).map(|&l| d.link(l).name.clone());
    Let {
        name: a.name.clone(),
        joints: vec![b.name.clone(), p.name.clone()],
        word: Some(KindWord::Triad),
        kind: KindWord::Triad.ident(span),
        args,
        args_span: span,
        links: links.collect(),
        slides: Vec::new(),
    }
}

/// The drawn value (rad) of the one input: the angle of its link's line
/// (the pivot, its joint on what carries it, to the next joint listed) from
/// +x, or from its carrier's first two joints as listed.
fn drawn_input(d: &Drawing) -> TokenStream {
    let input = &d.inputs[0];
    if input.slide {
        // A slide is measured from the block's drawn place.
        return quote!(0.0);
    }
    if let Some(c) = input
        .length
        .then(|| d.cylinder_named(&input.link))
        .flatten()
    {
        let c = &d.cylinders[c];
        return distance(d.joint(c.from), d.joint(c.to));
    }
    let links = (
        d.link_named(&input.link),
        match &input.carrier {
            Some(c) => d.link_named(c),
            None => d.ground(),
        },
    );
    let (Some(link), Some(on)) = links else {
        unreachable!("the decomposition placed this input's link and carrier");
    };
    let (joints, carried_by) = (&d.link(link).joints, &d.link(on).joints);
    let k = joints
        .iter()
        .position(|j| carried_by.contains(j))
        .unwrap_or(0);
    let line = Frame {
        origin: joints[k],
        toward: joints[(k + 1) % joints.len()],
    };
    match input.carrier {
        None => {
            let (p, t) = (d.joint(line.origin), d.joint(line.toward));
            let (px, py, tx, ty) = (&p.x, &p.y, &t.x, &t.y);
            quote!(atan2((#ty) - (#py), (#tx) - (#px)))
        }
        Some(_) => {
            let listed = Frame {
                origin: carried_by[0],
                toward: carried_by[1],
            };
            turn(d, listed, line)
        }
    }
}

/// `j`'s coordinates in the frame at `from` whose axis points to `toward`:
/// `(d . u, u x d) / |u|` with `d = j - from`, `u = toward - from`.
fn local(from: &Joint, toward: &Joint, j: &Joint) -> (TokenStream, TokenStream) {
    let (fx, fy, tx, ty, x, y) = (&from.x, &from.y, &toward.x, &toward.y, &j.x, &j.y);
    let (ux, uy) = (quote!(((#tx) - (#fx))), quote!(((#ty) - (#fy))));
    let (dx, dy) = (quote!(((#x) - (#fx))), quote!(((#y) - (#fy))));
    let len = quote!(hypot(#ux, #uy));
    (
        quote!((#dx * #ux + #dy * #uy) / #len),
        quote!((#ux * #dy - #uy * #dx) / #len),
    )
}

/// The statements of a block on a moving link that define no joint: the
/// RPR (`let BLOCK_slide = rpr(J, PIVOT, mode, offset) as (BLOCK, LINK)`),
/// the carried line (`let BLOCK_line = guide(P, LINK, angle)`) and the
/// point a carried slide is measured from (`let BLOCK_zero = point(..)`).
fn slot_statement(d: &Drawing, step: &Step) -> Let {
    let j = |k: JointId| d.joint(k);
    let (name, kind, args, links) = match *step {
        Step::Rpr {
            j: pin,
            pivot,
            link,
            slider,
        } => {
            let s = &d.sliders[slider];
            let (pin, pivot) = (j(pin), j(pivot));
            let mode = ahead(pivot, pin, s);
            let args = vec![
                name(pin),
                name(pivot),
                name_arg(&mode),
                value(offset(pivot, s, pin), pin.name.span()),
            ];
            let links = vec![d.link(s.link).name.clone(), d.link(link).name.clone()];
            (suffixed(d, slider, "slide"), KindWord::Rpr, args, links)
        }
        Step::CarriedGuide { slider, axis, mark } => {
            let s = &d.sliders[slider];
            let on = s.on.map(|l| d.link(l).name.clone());
            let on = on.expect("a carried guide's slider is on a link");
            let through = if mark {
                suffixed(d, slider, "zero")
            } else {
                j(axis.origin()).name.clone()
            };
            let span = d.link(s.link).name.span();
            let args = vec![
                name_arg(&through),
                name_arg(&on),
                value(turn_to(d, axis, s), span),
            ];
            (line_name(d, slider), KindWord::Guide, args, vec![])
        }
        Step::Mark { slider, axis } => {
            let s = &d.sliders[slider];
            let on = s.on.map(|l| d.link(l).name.clone());
            let on = on.expect("a carried slide's slider is on a link");
            let (x, y) = local_on(d, axis, j(s.at));
            let args = vec![
                name_arg(&on),
                Arg::From(j(axis.origin()).name.clone()),
                value(quote!((#x, #y)), j(s.at).name.span()),
            ];
            (suffixed(d, slider, "zero"), KindWord::Point, args, vec![])
        }
        _ => unreachable!("slot_statement() is called on an RPR, a carried guide or a mark"),
    };
    let span = name.span();
    Let {
        name,
        joints: Vec::new(),
        word: Some(kind),
        kind: kind.ident(span),
        args,
        args_span: span,
        links,
        slides: Vec::new(),
    }
}

/// `BLOCK_word`, spanned on the block of `sliders[k]`.
fn suffixed(d: &Drawing, k: usize, word: &str) -> Ident {
    let block = &d.link(d.sliders[k].link).name;
    Ident::new(&format!("{block}_{word}"), block.span())
}

/// The direction of a slider's line (rad): its angle as written, turned
/// into radians when written in degrees.
fn radians(s: &Slider) -> TokenStream {
    let a = &s.angle;
    if s.unit.as_ref().is_some_and(|u| u == "deg") {
        quote!(((#a) * 0.017453292519943295))
    } else {
        quote!((#a))
    }
}

/// The signed distance (length units) of the line of `s` through `j`'s
/// drawn place from `from`, positive when the line passes to the left of
/// `from` along its direction: `dir x (j - from) = dot(j - from,
/// perp(dir))`, with `a x b = a.x b.y - a.y b.x`. It is the offset of a
/// group whose line's origin or pivot is `from`.
fn offset(from: &Joint, s: &Slider, j: &Joint) -> TokenStream {
    let (fx, fy, x, y) = (&from.x, &from.y, &j.x, &j.y);
    let a = radians(s);
    quote!(((#y) - (#fy)) * cos(#a) - ((#x) - (#fx)) * sin(#a))
}

/// `j`'s coordinates in the frame at `from` whose axis is the line of `s`.
fn local_along(from: &Joint, s: &Slider, j: &Joint) -> (TokenStream, TokenStream) {
    let (fx, fy, x, y) = (&from.x, &from.y, &j.x, &j.y);
    let a = radians(s);
    let (dx, dy) = (quote!(((#x) - (#fx))), quote!(((#y) - (#fy))));
    (
        quote!(#dx * cos(#a) + #dy * sin(#a)),
        quote!(#dy * cos(#a) - #dx * sin(#a)),
    )
}

/// `j`'s coordinates in the frame of a placed link's drawn axis.
fn local_on(d: &Drawing, axis: Axis, j: &Joint) -> (TokenStream, TokenStream) {
    match axis {
        Axis::Joints(f) => local(d.joint(f.origin), d.joint(f.toward), j),
        Axis::Slot { origin, slider } => local_along(d.joint(origin), &d.sliders[slider], j),
    }
}

/// The angle (rad, counter-clockwise) from a placed link's drawn axis to
/// the line of `s`.
fn turn_to(d: &Drawing, axis: Axis, s: &Slider) -> TokenStream {
    let a = radians(s);
    match axis {
        Axis::Joints(f) => {
            let (o, t) = (d.joint(f.origin), d.joint(f.toward));
            let (ox, oy, tx, ty) = (&o.x, &o.y, &t.x, &t.y);
            let (ux, uy) = (quote!(((#tx) - (#ox))), quote!(((#ty) - (#oy))));
            quote!(atan2(#ux * sin(#a) - #uy * cos(#a), #ux * cos(#a) + #uy * sin(#a)))
        }
        Axis::Slot { slider, .. } => {
            let b = radians(&d.sliders[slider]);
            quote!(#a - #b)
        }
    }
}
