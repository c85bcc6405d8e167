//! The drawing decomposed into groups, Assur's way: from the ground and the
//! drivers, repeatedly a dyad (a joint on two links, each with a joint
//! already placed); when none is left, a triad (a link whose three joints
//! each hang on a binary leg from a placed joint); the other joints of
//! every placed link are its points. Before it, the drawing's links, joints
//! and inputs are checked, and Gruebler's count against the inputs. A
//! drawing it cannot decompose is an error naming the links left.

use super::{Axis, Drawing, InputId, JointId, LinkId, GROUND};
use crate::diag::{did_you_mean, Diagnostics};

/// A link's frame: the joint at its origin and the joint its axis points to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Frame {
    pub origin: JointId,
    pub toward: JointId,
}

/// The link that carries a driver's motor: the link, its frame as placed,
/// and the line the input is measured from (its first two joints as listed).
#[derive(Clone, Copy, Debug)]
pub(super) struct Carrier {
    pub link: LinkId,
    pub frame: Frame,
    pub listed: Frame,
}

/// One group statement, in solve order.
pub(super) enum Step {
    /// A joint of the ground.
    Ground(JointId),
    /// A driver: `link` turns by `input` about `frame.origin`, its axis
    /// pointing to `frame.toward` (the joint it places); `carrier`: the link
    /// carrying its motor (`None`: the ground).
    Crank {
        link: LinkId,
        frame: Frame,
        input: InputId,
        carrier: Option<Carrier>,
    },
    /// An RRR dyad: joint `c` at its drawn distances from `a` on link `la`
    /// and from `b` on link `lb`.
    Rrr {
        a: JointId,
        la: LinkId,
        b: JointId,
        lb: LinkId,
        c: JointId,
    },
    /// A triad: the ternary link `t` with joints `joints` (A, B, P), each on
    /// the leg `legs[i]` from the placed joint `known[i]`.
    Triad {
        t: LinkId,
        joints: [JointId; 3],
        legs: [LinkId; 3],
        known: [JointId; 3],
    },
    /// The line a block slides on (the ground's): `sliders[k]`.
    Guide(usize),
    /// A slider driver: the block of `sliders[slider]` at its displacement
    /// `input` along its line.
    Slide { slider: usize, input: InputId },
    /// An RRP dyad: joint `c` at its drawn distance from `a` on link `la`,
    /// and on the block of `sliders[slider]`.
    Rrp {
        a: JointId,
        la: LinkId,
        c: JointId,
        slider: usize,
    },
    /// A target driver: `joint` placed at the inputs `x` and `y`, its
    /// coordinates (inverse kinematics).
    Target {
        joint: JointId,
        x: InputId,
        y: InputId,
    },
    /// A joint fixed on `link`, in the link's frame.
    Point {
        link: LinkId,
        frame: Frame,
        joint: JointId,
    },
}

/// What is placed so far: joints known, links placed with their frames.
struct Placed {
    joint: Vec<bool>,
    frame: Vec<Option<Frame>>,
}

impl Placed {
    fn joint(&self, j: JointId) -> bool {
        self.joint[j.0]
    }

    fn frame(&self, l: LinkId) -> Option<Frame> {
        self.frame[l.0]
    }

    fn place(&mut self, j: JointId) {
        self.joint[j.0] = true;
    }

    fn set_frame(&mut self, l: LinkId, origin: JointId, toward: JointId) {
        self.frame[l.0] = Some(Frame { origin, toward });
    }
}

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
    if !structure_holds(d, errors) || !freedoms_match(d, errors) {
        return None;
    }
    let out = solve_order(d)?;
    for step in &out.steps {
        let ok = match *step {
            Step::Rrr { a, b, c, .. } => off_the_line(d, a, b, c, errors),
            Step::Rrp { a, c, slider, .. } => off_the_normal(d, a, c, slider, errors),
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
                "the links {} form a loop that is not a dyad (a joint on two links, each with a joint already placed) and not a triad (a link with three joints, each on a binary leg from a placed joint): it cannot be decomposed into the supported groups; write it with group statements, or choose inputs on these links",
                left.join(", ")
            ),
        );
    }
    None
}

/// A `ground` link, every joint on a link, every input on a moving link.
/// `false` with errors otherwise.
fn structure_holds(d: &Drawing, errors: &mut Diagnostics) -> bool {
    let before = errors.len();
    if d.ground().is_none() {
        errors.push(
            d.span,
            "the drawing has no fixed link: name it `ground`, with its joints, `ground = [O2, O4]`",
        );
    }
    for (k, j) in d.joints.iter().enumerate() {
        if !d.links.iter().any(|l| l.joints.contains(&JointId(k))) {
            errors.push(
                j.name.span(),
                format!(
                    "joint `{}` is on no link; list it in the links it joins",
                    j.name
                ),
            );
        }
    }
    let link_names: Vec<String> = d.links.iter().map(|l| l.name.to_string()).collect();
    coordinates_hold(d, errors);
    for i in d.inputs.iter().filter(|i| i.coordinate.is_none()) {
        for l in std::iter::once(&i.link).chain(&i.carrier) {
            if d.link_named(l).is_none() {
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
            errors.push(
                i.link.span(),
                "the ground does not turn; an input is the angle of a moving link",
            );
        }
        let block = d.link_named(&i.link).map(|l| d.slider_of(l).is_some());
        match (i.slide, block) {
            (true, Some(false)) => errors.push(
                i.link.span(),
                format!("`{}` is no slider's block: `slide(..)` names a block of a `slider` statement", i.link),
            ),
            (false, Some(true)) => errors.push(
                i.link.span(),
                format!("`{}` is a slider's block, which does not turn: its input is its slide, `input {} = slide({});`", i.link, i.name, i.link),
            ),
            _ => {}
        }
    }
    errors.len() == before
}

/// The joints whose coordinates are inputs, each with its `x` and `y`
/// inputs (inverse kinematics), in the order of their `x` inputs.
fn targets(d: &Drawing) -> Vec<(JointId, InputId, InputId)> {
    let find = |joint: &syn::Ident, axis: Axis| {
        d.input_ids().find(|&k| {
            let i = d.input(k);
            i.coordinate == Some(axis) && &i.link == joint
        })
    };
    d.input_ids()
        .filter(|&k| d.input(k).coordinate == Some(Axis::X))
        .filter_map(|k| {
            let joint = &d.input(k).link;
            let j = d.joints.iter().position(|j| &j.name == joint)?;
            Some((JointId(j), k, find(joint, Axis::Y)?))
        })
        .collect()
}

/// Every coordinate input names a moving joint, once, with its other
/// coordinate an input too; errors otherwise.
fn coordinates_hold(d: &Drawing, errors: &mut Diagnostics) {
    let joint_names: Vec<String> = d.joints.iter().map(|j| j.name.to_string()).collect();
    let fixed = d.ground().map(|g| &d.link(g).joints);
    for (n, i) in d.inputs.iter().enumerate() {
        let Some(axis) = i.coordinate else { continue };
        let (joint, (this, other)) = (
            &i.link,
            match axis {
                Axis::X => ("x", "y"),
                Axis::Y => ("y", "x"),
            },
        );
        let Some(j) = d.joints.iter().position(|j| &j.name == joint) else {
            errors.push(
                joint.span(),
                format!(
                    "no joint named `{joint}` (a coordinate input, `input {} = P.{this};`, names a joint of `joints`){}",
                    i.name,
                    did_you_mean(&joint.to_string(), joint_names.iter().map(String::as_str)),
                ),
            );
            continue;
        };
        if fixed.is_some_and(|f| f.contains(&JointId(j))) {
            errors.push(
                joint.span(),
                format!("`{joint}` is a joint of the ground, which does not move; a coordinate input places a moving joint (an end point, a foot)"),
            );
            continue;
        }
        let same = |k: &super::Input| k.coordinate == i.coordinate && &k.link == joint;
        if d.inputs[..n].iter().any(same) {
            errors.push(
                i.name.span(),
                format!("`{joint}.{this}` is already an input; remove this one"),
            );
        }
        // A partner on an unknown joint is reported there (a misspelt name).
        let partner = d.inputs.iter().any(|k| {
            k.coordinate.is_some()
                && k.coordinate != i.coordinate
                && (&k.link == joint || !d.joints.iter().any(|j| j.name == k.link))
        });
        if !partner {
            errors.push(
                i.name.span(),
                format!("`{joint}.{this}` is an input, so `{joint}.{other}` must be one too: a joint is placed by both its coordinates (inverse kinematics); add `input {joint}_{other} = {joint}.{other};`"),
            );
        }
    }
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
    let pairs = pairs + d.sliders.len() as i64;
    let dof = 3 * moving - 2 * pairs;
    let inputs = d.inputs.len() as i64;
    if dof == inputs {
        return true;
    }
    let count = format!(
        "Gruebler: 3 x {moving} moving links - 2 x {pairs} lower pairs = {dof} degree(s) of freedom"
    );
    let message = if dof > inputs {
        let free = solve_order(d)
            .map(|out| unplaced(d, &out.placed))
            .unwrap_or_default();
        format!(
            "the drawing is under-constrained: {count}, and {inputs} input(s) drive it, so {} motion(s) are free (links left free: {}); add {} `input` (a link's angle), or a link that closes a loop",
            dof - inputs,
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
            "the drawing is over-constrained: {count}, and {inputs} input(s) are given{which}; remove {} input(s), or a link that makes a loop rigid",
            inputs - dof
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
    };
    let mut steps = Vec::new();
    let fixed = &d.link(ground).joints;
    for &j in fixed {
        placed.place(j);
        steps.push(Step::Ground(j));
    }
    placed.set_frame(ground, fixed[0], fixed[0]);
    steps.extend((0..d.sliders.len()).map(Step::Guide));
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
        let drove = pending.len() < before;
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

/// `true` when the drawing has the dyad's joint `c` clearly on one side of
/// the line through its known joints `a`, `b` (the side that picks its
/// assembly); else an error on `c` (a drawing at a dead centre, or with `c`
/// on that line, does not say which).
fn off_the_line(d: &Drawing, a: JointId, b: JointId, c: JointId, errors: &mut Diagnostics) -> bool {
    let (pa, pb, pc) = (d.joint(a).at, d.joint(b).at, d.joint(c).at);
    let scale = (pb.0 - pa.0).hypot(pb.1 - pa.1) * (pc.0 - pa.0).hypot(pc.1 - pa.1);
    let cross = side(pa, pb, pc);
    // 1e-9: a sine that small is a drawing on the line to its last digits.
    // A drawing too large for an f64 is not judged here: its lengths
    // overflow, which the lowering reports on the joint.
    if cross.abs() > 1e-9 * scale || !(cross.is_finite() && scale.is_finite()) {
        return true;
    }
    let (na, nb, nc) = (&d.joint(a).name, &d.joint(b).name, &d.joint(c).name);
    errors.push(
        nc.span(),
        format!("the drawing has `{nc}` on the line through `{na}` and `{nb}`, which it is solved from (a dead centre), so it does not say on which side `{nc}` assembles: draw the mechanism at a pose where `{nc}` is off that line"),
    );
    false
}

/// `true` when the drawing has the RRP's joint `c` clearly ahead of or
/// behind the foot of `a` on the block's line (which picks its assembly);
/// else an error on `c`: the link drawn square to the line (the tangent
/// pose, where the two assemblies meet).
fn off_the_normal(
    d: &Drawing,
    a: JointId,
    c: JointId,
    slider: usize,
    errors: &mut Diagnostics,
) -> bool {
    let (pa, pc, dir) = (d.joint(a).at, d.joint(c).at, d.sliders[slider].dir);
    let (dx, dy) = (pc.0 - pa.0, pc.1 - pa.1);
    let along = dx * dir.0 + dy * dir.1;
    if along.abs() > 1e-9 * dx.hypot(dy) || !along.is_finite() {
        return true;
    }
    let (na, nc) = (&d.joint(a).name, &d.joint(c).name);
    errors.push(
        nc.span(),
        format!("the drawing has `{na}`-`{nc}` square to the line `{nc}`'s block slides on (the pose where its two assemblies meet), so it does not say which is meant: draw the mechanism at a pose where `{nc}` is ahead of or behind the foot of `{na}` on that line"),
    );
    false
}

/// The side of `c` from the line `a -> b` (twice the signed area of the
/// triangle): positive on the left.
pub(super) fn side(a: (f64, f64), b: (f64, f64), c: (f64, f64)) -> f64 {
    (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0)
}

/// The joint after `j` in a link's list (wrapping): the one its axis points to.
fn next_joint(list: &[JointId], j: JointId) -> JointId {
    let k = list.iter().position(|&x| x == j).unwrap_or(0);
    list[(k + 1) % list.len()]
}

/// Places, as points, the joints of placed links that are not yet placed.
/// `true` when it placed one.
fn place_points(d: &Drawing, placed: &mut Placed, steps: &mut Vec<Step>) -> bool {
    let mut progress = false;
    for link in d.link_ids() {
        let Some(frame) = placed.frame(link) else {
            continue;
        };
        for &joint in &d.link(link).joints {
            if !placed.joint(joint) {
                placed.place(joint);
                steps.push(Step::Point { link, frame, joint });
                progress = true;
            }
        }
    }
    progress
}

/// A dyad: an unplaced joint on two unplaced links that each have a placed
/// joint (two different ones). Other unplaced links at the joint wait: they
/// gain it as a placed joint.
fn find_dyad(d: &Drawing, placed: &Placed, ground: LinkId) -> Option<Step> {
    let known = |l: LinkId| d.link(l).joints.iter().copied().find(|&j| placed.joint(j));
    for c in (0..d.joints.len())
        .map(JointId)
        .filter(|&c| !placed.joint(c))
    {
        let on: Vec<(LinkId, JointId)> = d
            .link_ids()
            .filter(|&l| l != ground && placed.frame(l).is_none() && d.link(l).joints.contains(&c))
            .filter_map(|l| Some((l, known(l)?)))
            .collect();
        for (i, &(la, a)) in on.iter().enumerate() {
            if let Some(&(lb, b)) = on[i + 1..].iter().find(|(_, b)| *b != a) {
                return Some(Step::Rrr { a, la, b, lb, c });
            }
        }
        // A link with a placed joint and a block at `c` on its line.
        let block = d
            .sliders
            .iter()
            .position(|s| s.at == c && placed.frame(s.link).is_none());
        if let (Some(&(la, a)), Some(slider)) = (on.first(), block) {
            return Some(Step::Rrp { a, la, c, slider });
        }
    }
    None
}

/// A triad: an unplaced link with three unplaced joints, each on one other
/// unplaced link, a binary leg whose other joint is placed, and no other
/// joint on an unplaced link.
fn find_triad(d: &Drawing, placed: &Placed, ground: LinkId) -> Option<Step> {
    let free = |l: LinkId| l != ground && placed.frame(l).is_none();
    for t in d
        .link_ids()
        .filter(|&t| free(t) && d.link(t).joints.len() >= 3)
    {
        if let Some([a, b, p]) = triad_legs(d, placed, t, &free) {
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

/// The three legs of a triad on the ternary link `t`, each `(joint on t,
/// leg, the leg's placed joint)`, or `None` when `t` is not such a link.
fn triad_legs(
    d: &Drawing,
    placed: &Placed,
    t: LinkId,
    free: &dyn Fn(LinkId) -> bool,
) -> Option<[(JointId, LinkId, JointId); 3]> {
    let mut found = Vec::new();
    for &j in &d.link(t).joints {
        let others: Vec<LinkId> = d
            .link_ids()
            .filter(|&l| l != t && free(l) && d.link(l).joints.contains(&j))
            .collect();
        match others[..] {
            [] => {}
            [leg] if d.link(leg).joints.len() == 2 && !placed.joint(j) => {
                let k = d.link(leg).joints.iter().copied().find(|&x| x != j)?;
                if !placed.joint(k) {
                    return None;
                }
                found.push((j, leg, k));
            }
            _ => return None,
        }
    }
    found.try_into().ok()
}
