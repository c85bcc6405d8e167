//! The drawing decomposed into groups, Assur's way: from the ground and the
//! drivers, repeatedly a dyad (a joint on two links, each with a joint
//! already placed; or a block in a slot: an RPR, an RRP on a carried line,
//! an RPP, a PRP); when none is left, a triad (a link whose three joints
//! each hang on a binary leg from a placed joint); the other joints of
//! every placed link are its points. Before it, the drawing's links, joints
//! and inputs are checked, and Gruebler's count against the inputs. A
//! drawing it cannot decompose is an error naming the links left.

use super::{Coordinate, Drawing, InputId, JointId, LinkId, GROUND};
use crate::diag::{did_you_mean, Diagnostics};

/// A link's frame: the joint at its origin and the joint its axis points to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Frame {
    pub origin: JointId,
    pub toward: JointId,
}

/// A placed link's drawn axis: from one of its joints toward another, or
/// from one of its joints along the line of a block sliding on it (the
/// slotted link of an RPR, whose axis is its slot).
#[derive(Clone, Copy, Debug)]
pub(super) enum Axis {
    Joints(Frame),
    Slot { origin: JointId, slider: usize },
}

impl Axis {
    /// The joint at the axis's origin.
    pub fn origin(self) -> JointId {
        match self {
            Axis::Joints(f) => f.origin,
            Axis::Slot { origin, .. } => origin,
        }
    }
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
    /// An RPR dyad: the block of `sliders[slider]`, pinned at the placed
    /// joint `j`, slides in the slot of `link` (its line), which turns about
    /// its placed joint `pivot`.
    Rpr {
        j: JointId,
        pivot: JointId,
        link: LinkId,
        slider: usize,
    },
    /// A joint fixed on the slotted `link` of an RPR, in its frame: at
    /// `pivot`, along the line of `sliders[slider]`.
    SlotPoint {
        link: LinkId,
        pivot: JointId,
        slider: usize,
        joint: JointId,
    },
    /// The line of `sliders[slider]`, carried by the placed link it slides
    /// on (whose drawn axis is `axis`): through the axis's origin, or
    /// (`mark`) through the block's drawn place, the point of [`Step::Mark`].
    CarriedGuide {
        slider: usize,
        axis: Axis,
        mark: bool,
    },
    /// The point `BLOCK_zero` of the link that `sliders[slider]` slides on
    /// (axis `axis`), where the drawing has the block: a carried slide is
    /// measured from it.
    Mark { slider: usize, axis: Axis },
    /// An RRP dyad on a carried line: joint `c` at its drawn distance from
    /// `a` on link `la`, and on the block of `sliders[slider]`, whose line is
    /// carried through `origin`.
    RrpCarried {
        a: JointId,
        la: LinkId,
        c: JointId,
        slider: usize,
        origin: JointId,
    },
    /// An RPP dyad (the sine mechanism's): the block of `sliders[slider]`,
    /// pinned at the placed joint `j`, slides in the slot of the block of
    /// `sliders[yoke]`, which slides on the ground or on a line a placed
    /// link carries through `origin`; defines that block's joint, where its
    /// slot crosses its line.
    Rpp {
        j: JointId,
        slider: usize,
        yoke: usize,
        origin: Option<JointId>,
    },
    /// A PRP dyad: joint `c` on the blocks of `sliders[k]`, each on a line
    /// (the ground's, or one its placed link carries through `origin[k]`).
    Prp {
        c: JointId,
        sliders: [usize; 2],
        origins: [Option<JointId>; 2],
    },
    /// A cylinder driver: `cylinders[cylinder]`, from its placed joint `b`,
    /// of length `input`, reaches joint `c` of `link`, which turns about its
    /// placed joint `a`.
    Actuator {
        a: JointId,
        link: LinkId,
        b: JointId,
        c: JointId,
        cylinder: usize,
        input: InputId,
    },
}

/// What is placed so far: joints known, links placed with their frames.
struct Placed {
    joint: Vec<bool>,
    frame: Vec<Option<Frame>>,
    /// The links whose axis is a slot's line: its origin and the slider.
    slot: Vec<Option<(JointId, usize)>>,
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

    /// The drawn axis of the placed link `l`: a block's is its line (the
    /// direction of its guide, slot or slide in every group).
    fn axis(&self, d: &Drawing, l: LinkId) -> Option<Axis> {
        self.frame(l)?;
        if let Some(k) = d.sliders.iter().position(|s| s.link == l) {
            let origin = d.sliders[k].at;
            return Some(Axis::Slot { origin, slider: k });
        }
        match self.slot[l.0] {
            Some((origin, slider)) => Some(Axis::Slot { origin, slider }),
            None => self.frame(l).map(Axis::Joints),
        }
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
                "the links {} form a loop that is not a dyad (a joint on two links, each with a joint already placed) and not a triad (a link with three joints, each on a binary leg from a placed joint): it cannot be decomposed into the supported groups; write it with group statements, or choose inputs on these links{}",
                left.join(", "),
                slot_hint(d, &out.placed)
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
        // Blocks on the ground's lines and no pin on it: a trammel's frame.
        let lines_only = d.sliders.iter().any(|s| s.on.is_none());
        errors.push(
            d.span,
            if lines_only {
                "the drawing has no fixed link: name it `ground`, with its joints, `ground = [O2, O4]`, or `ground = []` when it has no pin, only the lines its blocks slide on"
            } else {
                "the drawing has no fixed link: name it `ground`, with its joints, `ground = [O2, O4]`"
            },
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
    cylinders_driven(d, errors);
    for i in d.inputs.iter().filter(|i| i.length) {
        if d.cylinder_named(&i.link).is_none() {
            let names = d.cylinders.iter().map(|c| c.names[0].to_string());
            let names: Vec<String> = names.collect();
            errors.push(
                i.link.span(),
                format!(
                    "no cylinder named `{}`: `length(..)` names a `cylinder` statement's cylinder{}",
                    i.link,
                    did_you_mean(&i.link.to_string(), names.iter().map(String::as_str))
                ),
            );
        }
    }
    for i in d
        .inputs
        .iter()
        .filter(|i| !i.length && i.coordinate.is_none())
    {
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
        let block = |l: &syn::Ident| d.link_named(l).is_some_and(|l| d.slider_of(l).is_some());
        if let Some(c) = i.carrier.as_ref().filter(|c| block(c)) {
            errors.push(
                c.span(),
                format!("`{c}` is a block, whose axis is its line: a motor it carries is not drawn yet; write it with the group statements, `crank(K, r, {}, {c})`", i.name),
            );
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
                Coordinate::X => ("x", "y"),
                Coordinate::Y => ("y", "x"),
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
    // A cylinder: a barrel and a rod (two moving links), pinned at its two
    // joints and sliding in each other (three lower pairs).
    let moving = moving + 2 * d.cylinders.len() as i64;
    let pairs = pairs + d.sliders.len() as i64 + 3 * d.cylinders.len() as i64;
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
                if let Some((pivot, slider)) = placed.slot[link.0] {
                    steps.push(Step::SlotPoint {
                        link,
                        pivot,
                        slider,
                        joint,
                    });
                    progress = true;
                    continue;
                }
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
            .position(|s| s.at == c && s.on.is_none() && placed.frame(s.link).is_none());
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

/// A block on a moving link: an RPR (the block's joint placed, the slotted
/// link turning about a placed joint) or an RRP on the line the placed link
/// carries (the block's joint on a link with a placed joint); the steps
/// pushed, `true` when it placed one.
fn place_slot(d: &Drawing, placed: &mut Placed, steps: &mut Vec<Step>) -> bool {
    for (slider, s) in d.sliders.iter().enumerate() {
        let Some(link) = s.on else {
            continue;
        };
        if placed.frame(s.link).is_some() {
            continue;
        }
        let j = s.at;
        // The yoke: a block on the ground, or on a placed link's line.
        let carried = |y: &super::Slider| y.on.map(|l| placed.axis(d, l));
        let yoke = d.sliders.iter().position(|y| {
            y.link == link && !matches!(carried(y), Some(None)) && !placed.joint(y.at)
        });
        if let Some(yoke) = yoke.filter(|_| placed.joint(j)) {
            let axis = carried(&d.sliders[yoke]).flatten();
            if let Some(axis) = axis {
                steps.push(Step::CarriedGuide {
                    slider: yoke,
                    axis,
                    mark: false,
                });
            }
            let origin = axis.map(Axis::origin);
            steps.push(Step::Rpp {
                j,
                slider,
                yoke,
                origin,
            });
            let q = d.sliders[yoke].at;
            placed.place(q);
            placed.set_frame(link, q, q);
            placed.set_frame(s.link, j, j);
            return true;
        }
        if placed.joint(j) && placed.frame(link).is_none() {
            let Some(pivot) = d
                .link(link)
                .joints
                .iter()
                .copied()
                .find(|&p| placed.joint(p))
            else {
                continue;
            };
            steps.push(Step::Rpr {
                j,
                pivot,
                link,
                slider,
            });
            placed.set_frame(s.link, j, j);
            placed.set_frame(link, pivot, pivot);
            placed.slot[link.0] = Some((pivot, slider));
            return true;
        }
        let Some(axis) = placed.axis(d, link).filter(|_| !placed.joint(j)) else {
            continue;
        };
        let leg = d.link_ids().find_map(|la| {
            let free = la != s.link && placed.frame(la).is_none();
            let joints = &d.link(la).joints;
            let a = joints.iter().copied().find(|&a| placed.joint(a));
            (free && joints.contains(&j)).then_some((la, a?))
        });
        let Some((la, a)) = leg else {
            if let Some(prp) = prp_at(d, placed, slider) {
                place_prp(d, placed, steps, prp);
                return true;
            }
            continue;
        };
        steps.push(Step::CarriedGuide {
            slider,
            axis,
            mark: false,
        });
        steps.push(Step::RrpCarried {
            a,
            la,
            c: j,
            slider,
            origin: axis.origin(),
        });
        placed.place(j);
        placed.set_frame(la, a, j);
        placed.set_frame(s.link, j, j);
        return true;
    }
    false
}

/// Places the cylinder of the length input `k` when its barrel's joint is
/// placed and its rod's joint is on a link turning about a placed joint:
/// an actuator driver. `true` when placed.
fn place_actuator(d: &Drawing, k: InputId, placed: &mut Placed, steps: &mut Vec<Step>) -> bool {
    let Some(cylinder) = d.cylinder_named(&d.input(k).link) else {
        return false;
    };
    let (b, c) = (d.cylinders[cylinder].from, d.cylinders[cylinder].to);
    if !placed.joint(b) || placed.joint(c) {
        return false;
    }
    let ground = d.ground();
    let found = d.link_ids().find_map(|l| {
        let joints = &d.link(l).joints;
        let free = Some(l) != ground && placed.frame(l).is_none() && joints.contains(&c);
        let a = joints.iter().copied().find(|&a| placed.joint(a));
        free.then_some((l, a?))
    });
    let Some((link, a)) = found else {
        return false;
    };
    steps.push(Step::Actuator {
        a,
        link,
        b,
        c,
        cylinder,
        input: k,
    });
    placed.place(c);
    placed.set_frame(link, a, c);
    true
}

/// Every cylinder is driven by one `length(..)` input; an error on the
/// cylinder otherwise (a cylinder left free is not drawn yet).
fn cylinders_driven(d: &Drawing, errors: &mut Diagnostics) {
    for c in &d.cylinders {
        let name = &c.names[0];
        let drives = d.inputs.iter().filter(|i| i.length && &i.link == name);
        match drives.count() {
            1 => {}
            0 => errors.push(
                name.span(),
                format!("cylinder `{name}` has no input: the drawn form drives a cylinder by its length, `input len = length({name});` (a cylinder that moves freely is not drawn yet: write it with the group statements, `rpr`)"),
            ),
            n => errors.push(
                name.span(),
                format!("cylinder `{name}` is driven by {n} inputs; give it one, `input len = length({name});`"),
            ),
        }
    }
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

/// `true` when the drawing has the RPR's pinned joint `j` clearly ahead of
/// or behind the foot of `pivot` on the slot's line (which picks its
/// assembly); else an error on `j` (the pose where the two meet).
fn off_the_foot(
    d: &Drawing,
    j: JointId,
    pivot: JointId,
    slider: usize,
    errors: &mut Diagnostics,
) -> bool {
    let (pj, pp, dir) = (d.joint(j).at, d.joint(pivot).at, d.sliders[slider].dir);
    let (dx, dy) = (pj.0 - pp.0, pj.1 - pp.1);
    let along = dx * dir.0 + dy * dir.1;
    if along.abs() > 1e-9 * dx.hypot(dy) || !along.is_finite() {
        return true;
    }
    let (nj, np) = (&d.joint(j).name, &d.joint(pivot).name);
    let block = &d.link(d.sliders[slider].link).name;
    errors.push(
        nj.span(),
        format!("the drawing has `{block}`'s line square to `{np}`-`{nj}`, with `{nj}` at the foot of `{np}` on it (the pose where its two assemblies meet), so it does not say which is meant: draw the mechanism at a pose where `{nj}` is ahead of or behind that foot along the line"),
    );
    false
}

/// A PRP at the joint of `sliders[first]` (on a placed moving link): a
/// second block at that joint whose line is placed (the ground's, or one a
/// placed link carries), both blocks unplaced.
fn prp_at(d: &Drawing, placed: &Placed, first: usize) -> Option<Step> {
    let c = d.sliders[first].at;
    let origin = |k: usize| {
        d.sliders[k]
            .on
            .and_then(|l| placed.axis(d, l))
            .map(Axis::origin)
    };
    let second = (0..d.sliders.len()).find(|&k| {
        let s = &d.sliders[k];
        let line = s.on.is_none() || origin(k).is_some();
        k != first && s.at == c && line && placed.frame(s.link).is_none()
    })?;
    Some(Step::Prp {
        c,
        sliders: [first, second],
        origins: [origin(first), origin(second)],
    })
}

/// Pushes a PRP and the carried lines it needs, and places its joint.
fn place_prp(d: &Drawing, placed: &mut Placed, steps: &mut Vec<Step>, prp: Step) {
    let Step::Prp { c, sliders, .. } = prp else {
        return;
    };
    for k in sliders {
        if let Some(axis) = d.sliders[k].on.and_then(|l| placed.axis(d, l)) {
            steps.push(Step::CarriedGuide {
                slider: k,
                axis,
                mark: false,
            });
        }
        placed.set_frame(d.sliders[k].link, c, c);
    }
    placed.place(c);
    steps.push(prp);
}

/// `true` when the yoke's joint (the block of `sliders[yoke]`) is drawn on
/// its slot's line, the line of `sliders[slider]` through `j`, and the slot
/// crosses the yoke's line; else an error on the yoke's joint.
fn on_the_slot(
    d: &Drawing,
    j: JointId,
    slider: usize,
    yoke: usize,
    errors: &mut Diagnostics,
) -> bool {
    let (s, y) = (&d.sliders[slider], &d.sliders[yoke]);
    let (pj, pq) = (d.joint(j).at, d.joint(y.at).at);
    let (dx, dy) = (pq.0 - pj.0, pq.1 - pj.1);
    let off = s.dir.0 * dy - s.dir.1 * dx;
    let cross = s.dir.0 * y.dir.1 - s.dir.1 * y.dir.0;
    let (nq, yoke_name) = (&d.joint(y.at).name, &d.link(y.link).name);
    let slot = &d.link(s.link).name;
    if cross.abs() <= 1e-9 {
        errors.push(
            nq.span(),
            format!("`{slot}`'s slot is drawn parallel to the line `{yoke_name}` slides on, so it cannot drive `{yoke_name}` (an RPP with its slot along its guide is singular at every pose): draw the slot across that line"),
        );
        return false;
    }
    // 1e-9: a sine that small is a drawing on the line to its last digits.
    if off.abs() <= 1e-9 * dx.hypot(dy) || !off.is_finite() {
        return true;
    }
    errors.push(
        nq.span(),
        format!("`{nq}` is the reference point of `{yoke_name}`, in whose slot `{slot}` slides (an RPP): draw it where that slot (the line of `{slot}` through `{}`) crosses the line `{yoke_name}` slides on", d.joint(j).name),
    );
    false
}

/// `true` when the two lines of a PRP cross (not parallel as drawn); else
/// an error on its joint.
fn across(d: &Drawing, c: JointId, sliders: [usize; 2], errors: &mut Diagnostics) -> bool {
    let (a, b) = (d.sliders[sliders[0]].dir, d.sliders[sliders[1]].dir);
    if (a.0 * b.1 - a.1 * b.0).abs() > 1e-9 {
        return true;
    }
    let nc = &d.joint(c).name;
    errors.push(
        nc.span(),
        format!("the two blocks at `{nc}` slide on lines drawn parallel, so they do not fix `{nc}` (a PRP with parallel lines is singular): draw them across each other"),
    );
    false
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
