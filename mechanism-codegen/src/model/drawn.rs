//! The drawn form of a definition: the joints where the drawing has them
//! (the reference pose), the links as sets of joints (the fixed one named
//! `ground`) and the inputs (a link's angle from the ground, or from the link
//! that carries its motor). It is decomposed here into the group statements
//! (`ground`, `crank`, `rrr`, `triad`, `point`) a user would write by hand,
//! in solve order, every length, offset and assembly mode read from the
//! drawing; the rest of the macro sees only those statements.
//!
//! The decomposition is Assur's: from the ground and the drivers, repeatedly
//! take a dyad (a joint on two links, each with a joint already placed); when
//! none is left, a triad (a ternary link whose three joints each hang on a
//! binary leg from a placed joint); the other joints of every placed link are
//! its points. A drawing it cannot so decompose is an error naming the loop.
//! The assembly modes are the drawing's: an RRR's joint on the side of its
//! two known joints' line that the drawing has it on, a triad's assembly the
//! one through the drawn joints at the drawn input.

use super::args::NumberScope;
use crate::diag::{did_you_mean, Diagnostics};
use crate::parse::{Arg, Assign, Item, Let};
use crate::value::convert;
use proc_macro2::{Span, TokenStream};
use quote::{quote, quote_spanned};
use syn::{Expr, Ident};

/// The name of the fixed link.
const GROUND: &str = "ground";

/// A joint of the drawing: its name, its coordinates as written and their
/// values at the parameters' defaults (length units).
struct Joint {
    name: Ident,
    x: Expr,
    y: Expr,
    at: (f64, f64),
}

/// A link of the drawing: its name and its joints, in the order written.
struct Link {
    name: Ident,
    joints: Vec<Ident>,
}

/// An input of the drawing: `angle(link)` or `angle(link, carrier)`.
struct Input {
    name: Ident,
    link: Ident,
    carrier: Option<Ident>,
}

/// The drawing, read.
struct Drawing {
    joints: Vec<Joint>,
    links: Vec<Link>,
    inputs: Vec<Input>,
    /// Where to point a message about the whole drawing (the `links` keyword).
    span: Span,
}

/// Replaces the drawn form's items (`joints`, `links`, `input`) by the group
/// statements they decompose into, placed where the first of them stood;
/// the other items are kept in order. Without a drawn item, `items` comes
/// back as it was.
pub(super) fn expand(
    items: Vec<Item>,
    scope: &NumberScope<'_>,
    errors: &mut Diagnostics,
) -> Vec<Item> {
    let drawn = |i: &Item| matches!(i, Item::Joints(..) | Item::Links(..) | Item::Input(..));
    let Some(first) = items.iter().position(drawn) else {
        return items;
    };
    let (drawing_items, mut rest): (Vec<Item>, Vec<Item>) = items.into_iter().partition(drawn);
    let before = errors.len();
    let Some(drawing) = read(drawing_items, scope, errors) else {
        return rest;
    };
    if errors.len() > before || !structure_holds(&drawing, errors) {
        return rest;
    }
    let Some(steps) = decompose(&drawing, errors) else {
        return rest;
    };
    let lets = steps.iter().map(|s| Item::Let(emit(&drawing, s)));
    let at = first.min(rest.len());
    rest.splice(at..at, lets);
    rest
}

/// Reads the drawn items into a [`Drawing`]; `None` (with errors) when an
/// item is malformed.
fn read(items: Vec<Item>, scope: &NumberScope<'_>, errors: &mut Diagnostics) -> Option<Drawing> {
    let mut drawing = Drawing {
        joints: Vec::new(),
        links: Vec::new(),
        inputs: Vec::new(),
        span: Span::call_site(),
    };
    let mut link_lists = Vec::new();
    for item in items {
        match item {
            Item::Joints(_, list) => {
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
            _ => {}
        }
    }
    let joint_names: Vec<String> = drawing.joints.iter().map(|j| j.name.to_string()).collect();
    for a in link_lists {
        if let Some(l) = read_link(a, &joint_names, errors) {
            drawing.links.push(l);
        }
    }
    Some(drawing)
}

/// `NAME = (x, y)`: a joint at the reference pose.
fn read_joint(a: Assign, scope: &NumberScope<'_>, errors: &mut Diagnostics) -> Option<Joint> {
    let Expr::Tuple(t) = &a.value else {
        errors.push(
            a.name.span(),
            format!(
                "a joint is where the drawing has it, `{} = (x, y)`",
                a.name
            ),
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

/// `NAME = [J1, J2, ..]`: a link and its joints.
fn read_link(a: Assign, joints: &[String], errors: &mut Diagnostics) -> Option<Link> {
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
        if !joints.contains(&s) {
            errors.push(
                name.span(),
                format!(
                    "no joint named `{s}` in `joints {{ .. }}`{}; every joint of a link is drawn there, `{s} = (x, y)`",
                    did_you_mean(&s, joints.iter().map(String::as_str))
                ),
            );
            return None;
        }
        if out.iter().any(|o: &Ident| o == name) {
            errors.push(
                name.span(),
                format!("`{s}` is listed twice in link `{}`", a.name),
            );
            return None;
        }
        out.push(name.clone());
    }
    let least = if a.name == GROUND { 1 } else { 2 };
    if out.len() < least {
        errors.push(
            a.name.span(),
            format!(
                "link `{}` has {} joint(s); a moving link joins at least two",
                a.name,
                out.len()
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
        "an input is a link's angle: `input {name} = angle(crank);` (from the ground) or `input {name} = angle(shank, thigh);` (from the link carrying its motor)"
    );
    let ident = |e: &Expr| match e {
        Expr::Path(p) => p.path.get_ident().cloned(),
        _ => None,
    };
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
        }),
        (Some("angle"), [Some(link), Some(carrier)]) => Some(Input {
            name,
            link: link.clone(),
            carrier: (carrier != GROUND).then(|| carrier.clone()),
        }),
        _ => {
            errors.error(syn::Error::new_spanned(value, usage));
            None
        }
    }
}

/// The drawing's structure, before decomposing: a `ground` link, every
/// joint on a link, every input on a link, and Gruebler's count equal to
/// the number of inputs. `false` (with errors) otherwise.
fn structure_holds(d: &Drawing, errors: &mut Diagnostics) -> bool {
    let before = errors.len();
    if !d.links.iter().any(|l| l.name == GROUND) {
        errors.push(
            d.span,
            "the drawing has no fixed link: name it `ground`, with its joints, `ground = [O2, O4]`",
        );
    }
    for j in &d.joints {
        if !d.links.iter().any(|l| l.joints.contains(&j.name)) {
            errors.push(
                j.name.span(),
                format!("joint `{}` is on no link; list it in the links it joins", j.name),
            );
        }
    }
    let link_names: Vec<String> = d.links.iter().map(|l| l.name.to_string()).collect();
    for i in &d.inputs {
        for l in std::iter::once(&i.link).chain(&i.carrier) {
            if !link_names.contains(&l.to_string()) {
                errors.push(
                    l.span(),
                    format!(
                        "no link named `{l}`{}",
                        did_you_mean(&l.to_string(), link_names.iter().map(String::as_str))
                    ),
                );
            }
        }
        if i.link == GROUND {
            errors.push(i.link.span(), "the ground does not turn; an input is the angle of a moving link");
        }
    }
    if errors.len() > before {
        return false;
    }
    let moving = d.links.len() as i64 - 1;
    let pairs: i64 = d
        .joints
        .iter()
        .map(|j| d.links.iter().filter(|l| l.joints.contains(&j.name)).count() as i64 - 1)
        .sum();
    let dof = 3 * moving - 2 * pairs;
    let inputs = d.inputs.len() as i64;
    if dof != inputs {
        let count = format!(
            "Gruebler: 3 x {moving} moving links - 2 x {pairs} pin pairs = {dof} degree(s) of freedom"
        );
        let message = if dof > inputs {
            format!(
                "the drawing is under-constrained: {count}, and {inputs} input(s) drive it, so {} motion(s) are free; add {} `input` (a link's angle) or a link that closes a loop",
                dof - inputs,
                dof - inputs
            )
        } else if dof <= 0 && inputs == 0 {
            format!("the drawing is a structure: {count}; nothing can move")
        } else {
            format!(
                "the drawing is over-constrained: {count}, and {inputs} input(s) are given; remove {} input(s), or a link that makes a loop rigid",
                inputs - dof
            )
        };
        errors.push(d.span, message);
        return false;
    }
    true
}

/// One group statement found by [`decompose`].
enum Step {
    /// A joint of the ground.
    Ground(usize),
    /// A driver: `link` turns about `pivot` by `input`; its axis points to
    /// `tip`; `carrier`: the link carrying its motor (`None`: the ground),
    /// with its frame as placed and the line its input is measured from
    /// (its first two joints as listed), each as (from, toward) joints.
    Crank {
        link: usize,
        pivot: usize,
        tip: usize,
        input: usize,
        carrier: Option<(usize, (usize, usize), (usize, usize))>,
    },
    /// An RRR dyad: joint `c` at its drawn distances from `a` on link `la`
    /// and from `b` on link `lb`.
    Rrr {
        a: usize,
        la: usize,
        b: usize,
        lb: usize,
        c: usize,
    },
    /// A triad: the ternary link `t` with joints `joints` (A, B, P), each on
    /// the leg `legs[i]` from the placed joint `known[i]`, in the assembly
    /// through the drawn joints at the drawn value of the one input.
    Triad {
        t: usize,
        joints: [usize; 3],
        legs: [usize; 3],
        known: [usize; 3],
    },
    /// A joint fixed on `link`, measured from its joint `from` in the frame
    /// whose axis points to its joint `toward`.
    Point {
        link: usize,
        from: usize,
        toward: usize,
        joint: usize,
    },
}

/// What is placed so far while decomposing: joints known, links placed
/// (with the two joints that set their frame: origin and axis).
struct Placed {
    joint: Vec<bool>,
    frame: Vec<Option<(usize, usize)>>,
}

/// Decomposes the drawing into group statements in solve order; `None`
/// (with an error naming the links left) when it cannot.
fn decompose(d: &Drawing, errors: &mut Diagnostics) -> Option<Vec<Step>> {
    let jx = |n: &Ident| d.joints.iter().position(|j| &j.name == n);
    let lx = |n: &Ident| d.links.iter().position(|l| &l.name == n);
    let link_joints: Vec<Vec<usize>> = d
        .links
        .iter()
        .map(|l| l.joints.iter().filter_map(jx).collect())
        .collect();
    let mut placed = Placed {
        joint: vec![false; d.joints.len()],
        frame: vec![None; d.links.len()],
    };
    let mut steps = Vec::new();
    let ground = d.links.iter().position(|l| l.name == GROUND)?;
    for &j in &link_joints[ground] {
        placed.joint[j] = true;
        steps.push(Step::Ground(j));
    }
    placed.frame[ground] = Some((link_joints[ground][0], link_joints[ground][0]));
    let mut pending: Vec<usize> = (0..d.inputs.len()).collect();
    loop {
        let mut progress = false;
        // Drivers whose carrier is placed.
        pending.retain(|&k| {
            let input = &d.inputs[k];
            let (Some(link), carrier) = (lx(&input.link), input.carrier.as_ref().map(|c| lx(c))) else {
                return false;
            };
            let carrier = carrier.flatten();
            let on = carrier.unwrap_or(ground);
            if placed.frame[on].is_none() || placed.frame[link].is_some() {
                return true;
            }
            let shared = link_joints[link]
                .iter()
                .copied()
                .find(|j| link_joints[on].contains(j) && placed.joint[*j]);
            let Some(pivot) = shared else {
                return true;
            };
            let tip = next_joint(&link_joints[link], pivot);
            let carrier = carrier.and_then(|c| {
                let listed = (link_joints[c][0], link_joints[c][1]);
                Some((c, placed.frame[c]?, listed))
            });
            steps.push(Step::Crank {
                link,
                pivot,
                tip,
                input: k,
                carrier,
            });
            placed.joint[tip] = true;
            placed.frame[link] = Some((pivot, tip));
            progress = true;
            false
        });
        progress |= place_points(&link_joints, &mut placed, &mut steps);
        if progress {
            continue;
        }
        if let Some(step) = find_dyad(&link_joints, &placed, ground) {
            if let Step::Rrr { a, la, b, lb, c } = step {
                placed.joint[c] = true;
                placed.frame[la] = Some((a, c));
                placed.frame[lb] = Some((b, c));
            }
            steps.push(step);
            continue;
        }
        if d.inputs.len() == 1 {
            if let Some(step) = find_triad(&link_joints, &placed, ground) {
                if let Step::Triad {
                    t,
                    joints,
                    legs,
                    known,
                } = step
                {
                    for i in 0..3 {
                        placed.joint[joints[i]] = true;
                        placed.frame[legs[i]] = Some((known[i], joints[i]));
                    }
                    placed.frame[t] = Some((joints[0], joints[1]));
                }
                steps.push(step);
                continue;
            }
        }
        break;
    }
    let left: Vec<String> = d
        .links
        .iter()
        .enumerate()
        .filter(|(k, _)| placed.frame[*k].is_none())
        .map(|(_, l)| format!("`{}`", l.name))
        .collect();
    if left.is_empty() {
        return Some(steps);
    }
    let unplaced_inputs: Vec<String> = pending.iter().map(|&k| format!("`{}`", d.inputs[k].name)).collect();
    let message = if !unplaced_inputs.is_empty() {
        format!(
            "the input(s) {} cannot be placed: an input's link must share a joint with the ground (or with the link named as its carrier) once that is placed; links left: {}",
            unplaced_inputs.join(", "),
            left.join(", ")
        )
    } else {
        format!(
            "the links {} form a loop that is not a dyad (a joint on two links, each with a joint already placed) and not a triad: it cannot be decomposed into the supported groups; write it with group statements, or move an input onto one of these links",
            left.join(", ")
        )
    };
    errors.push(d.span, message);
    None
}

/// The joint after `j` in a link's list (wrapping): the one its axis points to.
fn next_joint(list: &[usize], j: usize) -> usize {
    let k = list.iter().position(|&x| x == j).unwrap_or(0);
    list[(k + 1) % list.len()]
}

/// Places, as points, the joints of placed links that are not yet placed.
/// `true` when it placed one.
fn place_points(link_joints: &[Vec<usize>], placed: &mut Placed, steps: &mut Vec<Step>) -> bool {
    let mut progress = false;
    for (link, joints) in link_joints.iter().enumerate() {
        let Some((from, toward)) = placed.frame[link] else {
            continue;
        };
        for &j in joints {
            if !placed.joint[j] {
                placed.joint[j] = true;
                steps.push(Step::Point {
                    link,
                    from,
                    toward,
                    joint: j,
                });
                progress = true;
            }
        }
    }
    progress
}

/// A dyad: an unplaced joint on exactly two unplaced links, each with a
/// placed joint (two different ones).
fn find_dyad(link_joints: &[Vec<usize>], placed: &Placed, ground: usize) -> Option<Step> {
    let n = placed.joint.len();
    for c in (0..n).filter(|&c| !placed.joint[c]) {
        let on: Vec<usize> = (0..link_joints.len())
            .filter(|&l| l != ground && link_joints[l].contains(&c) && placed.frame[l].is_none())
            .collect();
        let [la, lb] = on.as_slice() else {
            continue;
        };
        let known = |l: usize| link_joints[l].iter().copied().find(|&j| placed.joint[j]);
        if let (Some(a), Some(b)) = (known(*la), known(*lb)) {
            if a != b {
                return Some(Step::Rrr {
                    a,
                    la: *la,
                    b,
                    lb: *lb,
                    c,
                });
            }
        }
    }
    None
}

/// A triad: an unplaced link with three unplaced joints, each on one other
/// unplaced link, a binary leg whose other joint is placed, and no other
/// joint on an unplaced link.
fn find_triad(link_joints: &[Vec<usize>], placed: &Placed, ground: usize) -> Option<Step> {
    let unplaced = |l: usize| l != ground && placed.frame[l].is_none();
    for t in (0..link_joints.len()).filter(|&t| unplaced(t) && link_joints[t].len() >= 3) {
        let mut found = Vec::new();
        for &j in &link_joints[t] {
            let others: Vec<usize> = (0..link_joints.len())
                .filter(|&l| l != t && unplaced(l) && link_joints[l].contains(&j))
                .collect();
            match others.as_slice() {
                [] => {}
                [leg] if link_joints[*leg].len() == 2 && !placed.joint[j] => {
                    let k = link_joints[*leg].iter().copied().find(|&x| x != j)?;
                    if !placed.joint[k] {
                        return None;
                    }
                    found.push((j, *leg, k));
                }
                _ => {
                    found.clear();
                    break;
                }
            }
        }
        if let [a, b, p] = found.as_slice() {
            return Some(Step::Triad {
                t,
                joints: [a.0, b.0, p.0],
                legs: [a.1, b.1, p.1],
                known: [a.2, b.2, p.2],
            });
        }
    }
    None
}

/// The `let` statement of one step, its numbers as expressions of the
/// joints' coordinates (folded by the lowering when literal), its spans on
/// the user's names.
fn emit(d: &Drawing, step: &Step) -> Let {
    let j = |k: usize| &d.joints[k];
    let l = |k: usize| &d.links[k].name;
    let value = |t: TokenStream| Arg::Value(syn::parse2(t).expect("a generated expression parses"), None);
    let name = |k: usize| Arg::Value(syn::parse2(ident_tokens(&j(k).name)).expect("a name parses"), None);
    let (defines, kind, args, links): (Ident, &str, Vec<Arg>, Vec<Ident>) = match *step {
        Step::Ground(k) => {
            let (x, y) = (&j(k).x, &j(k).y);
            (j(k).name.clone(), "ground", vec![value(quote!(#x)), value(quote!(#y))], vec![])
        }
        Step::Crank {
            link,
            pivot,
            tip,
            input,
            carrier,
        } => {
            let input = &d.inputs[input].name;
            let mut args = vec![
                name(pivot),
                value(distance(j(pivot), j(tip))),
                value(quote!(#input)),
            ];
            if let Some((c, frame, listed)) = carrier {
                args.push(name_arg(l(c)));
                if frame != listed {
                    args.push(value(turn(
                        (j(frame.0), j(frame.1)),
                        (j(listed.0), j(listed.1)),
                    )));
                }
            }
            (j(tip).name.clone(), "crank", args, vec![l(link).clone()])
        }
        Step::Rrr { a, la, b, lb, c } => {
            let side = side(j(a).at, j(b).at, j(c).at);
            let mode = Ident::new(if side > 0.0 { "left" } else { "right" }, l(la).span());
            (
                j(c).name.clone(),
                "rrr",
                vec![
                    name(a),
                    value(distance(j(a), j(c))),
                    name(b),
                    value(distance(j(b), j(c))),
                    name_arg(&mode),
                ],
                vec![l(la).clone(), l(lb).clone()],
            )
        }
        Step::Triad {
            t,
            joints,
            legs,
            known,
        } => {
            return triad_let(d, t, joints, legs, known);
        }
        Step::Point {
            link,
            from,
            toward,
            joint,
        } => {
            let (x, y) = local(j(from), j(toward), j(joint));
            (
                j(joint).name.clone(),
                "point",
                vec![name_arg(l(link)), Arg::From(j(from).name.clone()), value(quote!((#x, #y)))],
                vec![],
            )
        }
    };
    let span = defines.span();
    Let {
        name: defines,
        joints: Vec::new(),
        kind: Ident::new(kind, span),
        args,
        args_span: span,
        links,
        slides: Vec::new(),
    }
}

/// The triad's `let (A, B, P) = triad(..) as (LEG1, LEG2, LEG3, T)`: the
/// legs' lengths, the side `|AB|` and `P` in the frame `A -> B` from the
/// drawing; the assembly: the drawn joints at the drawn value of the input.
fn triad_let(d: &Drawing, t: usize, joints: [usize; 3], legs: [usize; 3], known: [usize; 3]) -> Let {
    let j = |k: usize| &d.joints[k];
    let value = |t: TokenStream| Arg::Value(syn::parse2(t).expect("a generated expression parses"), None);
    let mut args = Vec::new();
    for i in 0..3 {
        args.push(name_arg(&j(known[i]).name));
        args.push(value(distance(j(known[i]), j(joints[i]))));
    }
    let [a, b, p] = joints.map(j);
    args.push(value(distance(a, b)));
    let (x, y) = local(a, b, p);
    args.push(value(quote!((#x, #y))));
    let input = &d.inputs[0].name;
    let at = input_value(d);
    args.push(value(quote!(#input = #at)));
    for k in joints {
        let (x, y) = (&j(k).x, &j(k).y);
        args.push(value(quote!((#x, #y))));
    }
    let span = a.name.span();
    Let {
        name: a.name.clone(),
        joints: vec![b.name.clone(), p.name.clone()],
        kind: Ident::new("triad", span),
        args,
        args_span: span,
        links: legs
            .iter()
            .chain(std::iter::once(&t))
            .map(|&l| d.links[l].name.clone())
            .collect(),
        slides: Vec::new(),
    }
}

/// The drawn value (rad) of the one input: the angle of its link's line
/// (pivot -> next joint listed) from +x, or from its carrier's first two
/// joints.
fn input_value(d: &Drawing) -> TokenStream {
    let input = &d.inputs[0];
    let link = d.links.iter().find(|l| l.name == input.link).expect("checked");
    let joint = |n: &Ident| d.joints.iter().find(|j| &j.name == n).expect("checked");
    let pivot_of = |carrier: &[Ident]| {
        link.joints
            .iter()
            .position(|j| carrier.contains(j))
            .unwrap_or(0)
    };
    let carrier_joints: Vec<Ident> = match &input.carrier {
        Some(c) => d.links.iter().find(|x| &x.name == c).map(|c| c.joints.clone()).unwrap_or_default(),
        None => d.links.iter().find(|x| x.name == GROUND).map(|g| g.joints.clone()).unwrap_or_default(),
    };
    let k = pivot_of(&carrier_joints);
    let (p, t) = (joint(&link.joints[k]), joint(&link.joints[(k + 1) % link.joints.len()]));
    match &input.carrier {
        None => {
            let (px, py, tx, ty) = (&p.x, &p.y, &t.x, &t.y);
            quote!(atan2((#ty) - (#py), (#tx) - (#px)))
        }
        Some(_) => {
            let (c0, c1) = (joint(&carrier_joints[0]), joint(&carrier_joints[1]));
            turn((c0, c1), (p, t))
        }
    }
}

fn ident_tokens(i: &Ident) -> TokenStream {
    quote!(#i)
}

fn name_arg(i: &Ident) -> Arg {
    Arg::Value(Expr::Path(syn::parse_quote!(#i)), None)
}

/// `hypot(xb - xa, yb - ya)`, spanned on `b`'s name.
fn distance(a: &Joint, b: &Joint) -> TokenStream {
    let (ax, ay, bx, by) = (&a.x, &a.y, &b.x, &b.y);
    quote_spanned!(b.name.span()=> hypot((#bx) - (#ax), (#by) - (#ay)))
}

/// `j`'s coordinates in the frame at `from` whose axis points to `toward`:
/// `(d . u, u x d)` with `d = j - from`, `u` the unit axis.
fn local(from: &Joint, toward: &Joint, j: &Joint) -> (TokenStream, TokenStream) {
    let (fx, fy, tx, ty, x, y) = (&from.x, &from.y, &toward.x, &toward.y, &j.x, &j.y);
    let (ux, uy) = (quote!(((#tx) - (#fx))), quote!(((#ty) - (#fy))));
    let (dx, dy) = (quote!(((#x) - (#fx))), quote!(((#y) - (#fy))));
    let len = quote!(hypot(#ux, #uy));
    (
        quote_spanned!(j.name.span()=> (#dx * #ux + #dy * #uy) / #len),
        quote_spanned!(j.name.span()=> (#ux * #dy - #uy * #dx) / #len),
    )
}

/// The angle (rad) from the direction `a.0 -> a.1` to `b.0 -> b.1`,
/// counter-clockwise: `atan2(a x b, a . b)`.
fn turn(a: (&Joint, &Joint), b: (&Joint, &Joint)) -> TokenStream {
    let v = |(f, t): (&Joint, &Joint)| {
        let (fx, fy, tx, ty) = (&f.x, &f.y, &t.x, &t.y);
        (quote!(((#tx) - (#fx))), quote!(((#ty) - (#fy))))
    };
    let ((ax, ay), (bx, by)) = (v(a), v(b));
    quote!(atan2(#ax * #by - #ay * #bx, #ax * #bx + #ay * #by))
}

/// The side of `c` from the line `a -> b`: positive on the left.
fn side(a: (f64, f64), b: (f64, f64), c: (f64, f64)) -> f64 {
    (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0)
}

