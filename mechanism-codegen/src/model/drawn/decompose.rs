//! The drawing decomposed into groups, Assur's way: from the ground and the
//! drivers, repeatedly a dyad (a joint on two links, each with a joint
//! already placed; or a block in a slot: an RPR, an RRP on a carried line,
//! an RPP, a PRP); when none is left, a triad (a link whose three joints
//! each hang on a binary leg from a placed joint); the other joints of
//! every placed link are its points. Before it, the drawing's links, joints
//! and inputs are checked ([`super::rules`]), and Gruebler's count against
//! the inputs. A drawing it cannot decompose is an error naming the links
//! left. The steps it finds are [`super::steps`]; the group finders,
//! [`super::groups`].

use super::groups::{find_dyad, find_triad, place_actuator, place_points, place_slot};
use super::rules::{
    across, off_the_foot, off_the_line, off_the_normal, on_the_slot, structure_holds,
};
use super::steps::{next_joint, Carrier, Frame, Placed, Step};
use super::{Coordinate, Drawing, InputId, JointId, LinkId};
use crate::diag::{counted, is_are, Diagnostics};

/// Where the decomposition got to: the steps found, what they placed, and
/// the inputs it could not place.
struct Outcome {
    steps: Vec<Step>,
    placed: Placed,
    pending: Vec<InputId>,
}

/// Decomposes the drawing into group statements in solve order; `None`
/// (with errors) when its structure is wrong (no ground, a joint on no
/// link, an input on no link, more or fewer inputs than freedoms) or it
/// cannot be decomposed (naming the links left, or the dyad drawn at a dead
/// centre).
pub(super) fn decompose(d: &Drawing, errors: &mut Diagnostics) -> Option<Vec<Step>> {
    if !structure_holds(d, errors)
        || !super::gear::gears_hold(d, errors)
        || !freedoms_match(d, errors)
    {
        return None;
    }
    let out = solve_order(d)?;
    for step in &out.steps {
        let ok = match *step {
            Step::Rrr { a, b, c, .. } => off_the_line(d, a, b, c, errors),
            Step::Rrp { a, c, slider, .. } | Step::RrpCarried { a, c, slider, .. } => {
                off_the_normal(d, a, c, slider, errors)
            }
            Step::Rpr {
                j, pivot, slider, ..
            } => off_the_foot(d, j, pivot, slider, errors),
            Step::Rpp {
                j, slider, yoke, ..
            } => on_the_slot(d, j, slider, yoke, errors),
            Step::Prp { c, sliders, .. } => across(d, c, sliders, errors),
            Step::Actuator { a, b, c, .. } => off_the_line(d, a, b, c, errors),
            _ => true,
        };
        if !ok {
            return None;
        }
    }
    let left = unplaced(d, &out.placed);
    if left.is_empty() {
        return Some(out.steps);
    }
    if let Some(&k) = out.pending.first() {
        let input = d.input(k);
        if input.length || input.slide {
            errors.push(input.link.span(), pending_linear(d, k, &left));
            return None;
        }
        let on = match &input.carrier {
            Some(c) => format!("`{c}`, the link named as its carrier,"),
            None => "the ground".to_string(),
        };
        errors.push(
            input.link.span(),
            format!(
                "the input `{}` turns `{}`, which has no joint with {on} once that is placed, so no motor can drive it there; links left unplaced: {}",
                input.name,
                input.link,
                left.join(", ")
            ),
        );
    } else {
        errors.push(
            d.span,
            format!(
                "the links {} form a loop that is not a dyad (a joint on two links, each with a joint already placed) and not a triad (a link with three joints, each on a binary leg from a placed joint): none of the groups `mechanism` solves, which are the dyads (RRR, RRP, RPR, PRP, RPP) and the triad of three binary revolute legs (class III); groups of class IV or higher, and triads with a sliding pair, are not solved, in a drawing or in group statements; choose inputs on these links so that what is left decomposes into those{}",
                left.join(", "),
                slot_hint(d, &out.placed)
            ),
        );
    }
    None
}

/// The joints whose coordinates are inputs, each with its `x` and `y`
/// inputs (inverse kinematics), in the order of their `x` inputs.
fn targets(d: &Drawing) -> Vec<(JointId, InputId, InputId)> {
    let find = |joint: &syn::Ident, axis: Coordinate| {
        d.input_ids().find(|&k| {
            let i = d.input(k);
            i.coordinate == Some(axis) && &i.link == joint
        })
    };
    d.input_ids()
        .filter(|&k| d.input(k).coordinate == Some(Coordinate::X))
        .filter_map(|k| {
            let joint = &d.input(k).link;
            let j = d.joints.iter().position(|j| &j.name == joint)?;
            Some((JointId(j), k, find(joint, Coordinate::Y)?))
        })
        .collect()
}

/// Gruebler's count of the drawing's freedoms equals its inputs; else an
/// error saying which way it misses: the links left free, or the links that
/// join joints the rest already fixes.
fn freedoms_match(d: &Drawing, errors: &mut Diagnostics) -> bool {
    let moving = d.links.len() as i64 - 1;
    let pairs: i64 = (0..d.joints.len())
        .map(|k| {
            let on = d.links.iter().filter(|l| l.joints.contains(&JointId(k)));
            on.count() as i64 - 1
        })
        .sum();
    // A cylinder: a barrel and a rod (two moving links), pinned at its two
    // joints and sliding in each other (three lower pairs).
    let moving = moving + 2 * d.cylinders.len() as i64;
    let pairs = pairs + d.sliders.len() as i64 + 3 * d.cylinders.len() as i64;
    // A gear pair: a higher pair, one constraint.
    let gears = d.gears.len() as i64;
    let dof = 3 * moving - 2 * pairs - gears;
    let inputs = d.inputs.len() as i64;
    if dof == inputs {
        return true;
    }
    let geared = match gears {
        0 => String::new(),
        n => format!(" - {}", counted(n, "gear pair", "gear pairs")),
    };
    let count = format!(
        "Gruebler: 3 x {moving} moving links - 2 x {pairs} lower pairs{geared} = {}",
        counted(dof, "degree of freedom", "degrees of freedom")
    );
    let message = if dof > inputs {
        let free = solve_order(d)
            .map(|out| unplaced(d, &out.placed))
            .unwrap_or_default();
        format!(
            "the drawing is under-constrained: {count}, and {} {} it, so {} {} free (links left free: {}); add {} `input` (a link's angle), or a link that closes a loop",
            counted(inputs, "input", "inputs"),
            if inputs == 1 { "drives" } else { "drive" },
            counted(dof - inputs, "motion", "motions"),
            is_are(dof - inputs),
            free.join(", "),
            dof - inputs
        )
    } else {
        let braced = braced_links(d);
        let which = if braced.is_empty() {
            String::new()
        } else {
            format!(
                " ({} joins joints the rest already fixes)",
                braced.join(", ")
            )
        };
        format!(
            "the drawing is over-constrained: {count}, and {} {} given{which}; remove {}, or a link that makes a loop rigid",
            counted(inputs, "input", "inputs"),
            is_are(inputs),
            counted(inputs - dof, "input", "inputs")
        )
    };
    errors.push(d.span, message);
    false
}

/// The links not placed, as a list for messages.
fn unplaced(d: &Drawing, placed: &Placed) -> Vec<String> {
    d.link_ids()
        .filter(|&l| placed.frame(l).is_none())
        .map(|l| format!("`{}`", d.link(l).name))
        .collect()
}

/// The links a count of too many constraints points at: links not placed
/// whose joints the rest all placed (each a rigid bar between fixed joints).
fn braced_links(d: &Drawing) -> Vec<String> {
    let Some(out) = solve_order(d) else {
        return Vec::new();
    };
    d.link_ids()
        .filter(|&l| {
            out.placed.frame(l).is_none() && d.link(l).joints.iter().all(|&j| out.placed.joint(j))
        })
        .map(|l| format!("`{}`", d.link(l).name))
        .collect()
}

/// The decomposition proper, without messages: from the ground, the
/// drivers whose carrier is placed, the points of placed links, dyads, then
/// triads (with one input), until nothing more can be placed.
fn solve_order(d: &Drawing) -> Option<Outcome> {
    let ground = d.ground()?;
    let mut placed = Placed {
        joint: vec![false; d.joints.len()],
        frame: vec![None; d.links.len()],
        slot: vec![None; d.links.len()],
    };
    let mut steps = Vec::new();
    let fixed = &d.link(ground).joints;
    for &j in fixed {
        placed.place(j);
        steps.push(Step::Ground(j));
    }
    // The ground's frame marks it placed and is never read (its joints are
    // placed here, its lines are guides). A ground without joints (its
    // blocks' lines only, `ground = []`) is placed all the same.
    let origin = fixed.first().copied().unwrap_or(JointId(0));
    placed.set_frame(ground, origin, origin);
    let on_ground = (0..d.sliders.len()).filter(|&k| d.sliders[k].on.is_none());
    steps.extend(on_ground.map(Step::Guide));
    for (joint, x, y) in targets(d) {
        placed.place(joint);
        steps.push(Step::Target { joint, x, y });
    }
    let mut pending: Vec<InputId> = d
        .input_ids()
        .filter(|&k| d.input(k).coordinate.is_none())
        .collect();
    loop {
        let before = pending.len();
        pending.retain(|&k| !place_driver(d, k, ground, &mut placed, &mut steps));
        let geared = (0..d.gears.len())
            .filter(|&k| super::gear::place(d, k, &mut placed, &mut steps))
            .count();
        let drove = pending.len() < before || geared > 0;
        if place_points(d, &mut placed, &mut steps) || drove {
            continue;
        }
        if let Some(step) = find_dyad(d, &placed, ground) {
            match step {
                Step::Rrr { a, la, b, lb, c } => {
                    placed.place(c);
                    placed.set_frame(la, a, c);
                    placed.set_frame(lb, b, c);
                }
                Step::Rrp { a, la, c, slider } => {
                    placed.place(c);
                    placed.set_frame(la, a, c);
                    placed.set_frame(d.sliders[slider].link, c, c);
                }
                _ => {}
            }
            steps.push(step);
            continue;
        }
        if place_slot(d, &mut placed, &mut steps) {
            continue;
        }
        let triad = (d.inputs.len() == 1)
            .then(|| find_triad(d, &placed, ground))
            .flatten();
        let Some(step) = triad else {
            break;
        };
        if let Step::Triad {
            t,
            joints,
            legs,
            known,
        } = step
        {
            for i in 0..3 {
                placed.place(joints[i]);
                placed.set_frame(legs[i], known[i], joints[i]);
            }
            placed.set_frame(t, joints[0], joints[1]);
        }
        steps.push(step);
    }
    Some(Outcome {
        steps,
        placed,
        pending,
    })
}

/// Places input `k`'s crank when what carries it is placed and its link
/// shares a placed joint with it (the pivot); its axis points to the link's
/// next joint as listed. `true` when placed.
fn place_driver(
    d: &Drawing,
    k: InputId,
    ground: LinkId,
    placed: &mut Placed,
    steps: &mut Vec<Step>,
) -> bool {
    let input = d.input(k);
    if input.length {
        return place_actuator(d, k, placed, steps);
    }
    let Some(link) = d.link_named(&input.link) else {
        return false;
    };
    if input.slide {
        let Some(slider) = d.sliders.iter().position(|s| s.link == link) else {
            return false;
        };
        let at = d.sliders[slider].at;
        if placed.frame(link).is_some() || placed.joint(at) {
            return false;
        }
        if let Some(on) = d.sliders[slider].on {
            let Some(axis) = placed.axis(d, on) else {
                return false;
            };
            steps.push(Step::Mark { slider, axis });
            steps.push(Step::CarriedGuide {
                slider,
                axis,
                mark: true,
            });
        }
        steps.push(Step::Slide { slider, input: k });
        placed.place(at);
        placed.set_frame(link, at, at);
        return true;
    }
    let carrier = input.carrier.as_ref().and_then(|c| d.link_named(c));
    let on = carrier.unwrap_or(ground);
    if placed.frame(on).is_none() || placed.frame(link).is_some() {
        return false;
    }
    // A motor on a slotted link (whose axis is its slot) is not drawn yet.
    if placed.slot[on.0].is_some() {
        return false;
    }
    let joints = &d.link(link).joints;
    let shared = joints
        .iter()
        .copied()
        .find(|&j| d.link(on).joints.contains(&j) && placed.joint(j));
    let Some(pivot) = shared else {
        return false;
    };
    let tip = next_joint(joints, pivot);
    let carrier = carrier.and_then(|c| {
        let listed = &d.link(c).joints;
        Some(Carrier {
            link: c,
            frame: placed.frame(c)?,
            listed: Frame {
                origin: listed[0],
                toward: listed[1],
            },
        })
    });
    let frame = Frame {
        origin: pivot,
        toward: tip,
    };
    steps.push(Step::Crank {
        link,
        frame,
        input: k,
        carrier,
    });
    placed.place(tip);
    placed.set_frame(link, pivot, tip);
    true
}

/// The message for a slide or length input that could not be placed: its
/// block's or cylinder's joints, what they wait for.
fn pending_linear(d: &Drawing, k: InputId, left: &[String]) -> String {
    let input = d.input(k);
    let (name, left) = (&input.name, left.join(", "));
    if let Some(c) = d.cylinder_named(&input.link) {
        let c = &d.cylinders[c];
        let (b, cj) = (&d.joint(c.from).name, &d.joint(c.to).name);
        return format!(
            "the input `{name}` is the length of `{}`, which is driven from `{b}` (its barrel's joint, on the ground or on a link placed before it) to `{cj}` (a joint of a link turning about a joint placed before it); the drawing does not place it that way (links left unplaced: {left}): swap `from` and `to`, or choose another input",
            input.link
        );
    }
    format!(
        "the input `{name}` slides `{}` along a line that is never placed (the link it slides on is not placed before it; links left unplaced: {left})",
        input.link
    )
}

/// What the decomposition needs of a block left on a moving link, for the
/// message about an undecomposable drawing (empty when there is none).
fn slot_hint(d: &Drawing, placed: &Placed) -> String {
    let Some(s) = d
        .sliders
        .iter()
        .find(|s| s.on.is_some() && placed.frame(s.link).is_none())
    else {
        return String::new();
    };
    let (block, at) = (&d.link(s.link).name, &d.joint(s.at).name);
    let on = s.on.map(|l| d.link(l).name.to_string()).unwrap_or_default();
    format!(". A block on a moving link, as `{block}` on `{on}`, is solved when `{at}` is placed and `{on}` turns about a placed joint (an RPR) or slides on the ground or on a placed link (an RPP), or when `{on}` is placed and `{at}` is on a link with a placed joint (an RRP) or on another block whose line is placed (a PRP)")
}
